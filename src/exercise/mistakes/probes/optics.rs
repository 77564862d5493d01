//! The probes of the optics chapters' exercises (see [`super`]).

use glam::DVec3;
use num_complex::Complex64;

use crate::check::dispersion::{fused_silica, material, n_bk7};
use crate::optics::dispersion::Sellmeier;
use crate::optics::fresnel::{Amplitudes, Polarized};
use crate::optics::reflect::Refraction;

/// Unit directions of incidence `(w_i, n)`: at 0, 30, 45, 60, 75 and 89.9 degrees and
/// grazing, about the normal `+z` and a tilted one, with the normal facing the light and
/// facing away.
pub fn incidences() -> Vec<(DVec3, DVec3)> {
    let tilted = DVec3::new(0.3, -0.5, 0.8).normalize();
    let mut cases = Vec::new();
    for m in [DVec3::Z, tilted] {
        let t = m.any_orthonormal_vector();
        for degrees in [0.0_f64, 30.0, 45.0, 60.0, 75.0, 89.9, 90.0] {
            let (sin, cos) = degrees.to_radians().sin_cos();
            let w_i = t * sin - m * cos;
            cases.push((w_i, m));
            cases.push((w_i, -m));
        }
    }
    cases
}

/// `f` on [`incidences`]: every coordinate of every direction.
pub fn reflect_probe(f: fn(DVec3, DVec3) -> DVec3) -> Vec<f64> {
    incidences()
        .into_iter()
        .flat_map(|(w_i, n)| f(w_i, n).to_array())
        .collect()
}

/// Index pairs of the refraction probe: into and out of glass and diamond (past their
/// critical angles at 45 degrees and beyond), water to air, matched.
pub const REFRACT_PAIRS: [(f64, f64); 6] = [
    (1.0, 1.5),
    (1.5, 1.0),
    (1.0, 2.4),
    (2.4, 1.0),
    (1.33, 1.0),
    (1.2, 1.2),
];

/// `f` on [`incidences`] and [`REFRACT_PAIRS`]: per case `1` and the direction when
/// transmitted, `0` and three NaNs under total internal reflection.
pub fn refract_probe(f: fn(DVec3, DVec3, f64, f64) -> Refraction) -> Vec<f64> {
    let mut out = Vec::new();
    for (w_i, n) in incidences() {
        for (n1, n2) in REFRACT_PAIRS {
            match f(w_i, n, n1, n2) {
                Refraction::Transmitted(w) => out.extend([1.0, w.x, w.y, w.z]),
                Refraction::TotalInternalReflection => {
                    out.extend([0.0, f64::NAN, f64::NAN, f64::NAN])
                }
            }
        }
    }
    out
}

/// Cosines of the Fresnel probes: normal, 30, 45, 60 and 80 degrees, near grazing,
/// grazing, and a negative cosine.
pub fn probe_cosines() -> Vec<f64> {
    let mut c: Vec<f64> = [0.0_f64, 30.0, 45.0, 60.0, 80.0]
        .iter()
        .map(|d| d.to_radians().cos())
        .collect();
    c.extend([0.01, 0.0, -0.5]);
    c
}

/// Index pairs of the Fresnel probes: into and out of glass (critical angle 41.8
/// degrees), water, glass under water, out of diamond, matched.
pub const FRESNEL_PAIRS: [(f64, f64); 7] = [
    (1.0, 1.5),
    (1.5, 1.0),
    (1.0, 1.33),
    (1.33, 1.5),
    (1.5, 1.33),
    (2.4, 1.0),
    (1.5, 1.5),
];

/// Every input `(cos_i, n1, n2)` of the Fresnel probes.
pub fn fresnel_inputs() -> impl Iterator<Item = (f64, f64, f64)> {
    FRESNEL_PAIRS
        .into_iter()
        .flat_map(|(n1, n2)| probe_cosines().into_iter().map(move |c| (c, n1, n2)))
}

/// An amplitude routine `f` on the Fresnel probes: `1, r_s, r_p, t_s, t_p, cos_t`, or `0`
/// and five NaNs for `None`.
pub fn amplitude_probe(f: fn(f64, f64, f64) -> Option<Amplitudes>) -> Vec<f64> {
    fresnel_inputs()
        .flat_map(|(c, n1, n2)| match f(c, n1, n2) {
            Some(a) => [1.0, a.r_s, a.r_p, a.t_s, a.t_p, a.cos_t],
            None => [0.0, f64::NAN, f64::NAN, f64::NAN, f64::NAN, f64::NAN],
        })
        .collect()
}

/// A transmittance routine `f` on the Fresnel probes: `T_s, T_p`.
pub fn transmittance_probe(f: fn(f64, f64, f64) -> Polarized) -> Vec<f64> {
    fresnel_inputs()
        .flat_map(|(c, n1, n2)| {
            let t = f(c, n1, n2);
            [t.s, t.p]
        })
        .collect()
}

/// A reflectance routine `f` on the Fresnel probes.
pub fn scalar_probe(f: fn(f64, f64, f64) -> f64) -> Vec<f64> {
    fresnel_inputs().map(|(c, n1, n2)| f(c, n1, n2)).collect()
}

/// A lobe BRDF `f` (its `divide_by_cos` set) at two albedos, two lobe densities and the
/// directions: normal, 60 degrees, near grazing, grazing and below the surface.
pub fn lobe_probe(f: fn(f64, f64, DVec3, bool) -> f64) -> Vec<f64> {
    let (s, c) = 60f64.to_radians().sin_cos();
    let directions = [
        DVec3::Z,
        DVec3::new(s, 0.0, c),
        DVec3::new(0.0, (1.0 - 1e-6f64).sqrt(), 1e-3),
        DVec3::X,
        DVec3::new(0.6, 0.0, -0.8),
    ];
    let mut out = Vec::new();
    for rho in [0.3, 0.9] {
        for pdf in [0.5, 1e3] {
            out.extend(directions.iter().map(|&w| f(rho, pdf, w, true)));
        }
    }
    out
}

/// An index routine `f` on N-BK7, fused silica and a pole at 500 nm, from 360 to 1500 nm.
pub fn sellmeier_probe(f: fn(&Sellmeier, f64) -> f64) -> Vec<f64> {
    let glasses = [
        n_bk7(),
        fused_silica(),
        material("pole at 500 nm", &[(1.0, 0.25)]),
    ];
    let nms = [360.0, 486.1, 550.0, 656.3, 830.0, 1000.0, 1500.0];
    glasses
        .iter()
        .flat_map(|g| nms.iter().map(move |&nm| f(g, nm)))
        .collect()
}

/// An Airy sum `f` on real and complex coefficients and on real and evanescent (complex)
/// phases: the real and imaginary parts.
pub fn airy_probe(f: fn(Complex64, Complex64, Complex64) -> Complex64) -> Vec<f64> {
    let coefficients = [
        (Complex64::new(0.2, 0.0), Complex64::new(-0.3, 0.0)),
        (Complex64::new(-0.5, 0.0), Complex64::new(0.4, 0.0)),
        (Complex64::new(0.3, 0.0), Complex64::new(0.0, 0.0)),
        (Complex64::new(0.0, 0.0), Complex64::new(0.6, 0.0)),
        (
            Complex64::from_polar(0.4, 0.7),
            Complex64::from_polar(0.7, -1.9),
        ),
    ];
    let deltas = [
        Complex64::new(0.0, 0.0),
        Complex64::new(0.3, 0.0),
        Complex64::new(std::f64::consts::FRAC_PI_2, 0.0),
        Complex64::new(2.0, 0.0),
        Complex64::new(0.5, 0.7),
    ];
    let mut out = Vec::new();
    for (r12, r23) in coefficients {
        for delta in deltas {
            let r = f(r12, r23, delta);
            out.extend([r.re, r.im]);
        }
    }
    out
}
