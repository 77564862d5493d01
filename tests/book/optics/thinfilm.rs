//! Tests of the chapter *Thin-film interference* (`chapters/optics/thinfilm.md`).
//!
//! The reference is a transfer-matrix computation written here, independently of the
//! library: Macleod's characteristic matrix of a film (*Thin-Film Optical Filters*, ch. 2)
//! with tilted admittances, in Macleod's own conventions (time dependence `exp(+iωt)`,
//! evanescent cosines `−i·sqrt(sin²θ − 1)`, `r_p` with the opposite sign to Born & Wolf's).
//! The library uses the Airy sum in Born & Wolf's conventions; only the measurable powers
//! R and T must agree. Planted bugs (and the seed's formula) must be rejected.
//! Everything is deterministic (fixed seeds); no statistics are involved.

use std::f64::consts::{FRAC_PI_2, PI};

use num_complex::Complex64;
use raylemma::optics::thinfilm::{
    Film, airy_r, cos_theta, incoherent_reflectance, interface, phase, quarter_wave_reflectance,
    seed_reflectance,
};
use raylemma::rng;

// ---------------------------------------------------------------------------------------
// The independent reference: Macleod's characteristic matrix.

/// `cos θ` in a medium of index `n` for light arriving from index `n1` at `cos θ1`, in
/// Macleod's convention: real, or `−i·sqrt(sin²θ − 1)` (fourth quadrant). From
/// `cos²θ = 1 − ρ² sin²θ1 = (1 − ρ²) + ρ² cos²θ1`, `ρ = n1/n`, so that a medium of the
/// ambient's index gets the ambient's cosine even at grazing incidence.
fn macleod_cos(n1: f64, cos1: f64, n: f64) -> Complex64 {
    let rho2 = (n1 / n).powi(2);
    let c2 = (1.0 - rho2) + rho2 * cos1 * cos1;
    if c2 >= 0.0 {
        Complex64::new(c2.sqrt(), 0.0)
    } else {
        Complex64::new(0.0, -(-c2).sqrt())
    }
}

/// `(cos δ, sin δ / δ)` times `e^{−|Im δ|}`, and `|Im δ|`: the matrix of a thick
/// evanescent layer overflows otherwise. `sin δ / δ` is taken by its series near 0, so
/// that a film exactly at its critical angle (`δ = 0`) needs no special case.
fn scaled_cos_sinc(delta: Complex64) -> (Complex64, Complex64, f64) {
    let y = delta.im.abs();
    let e = (-2.0 * y).exp();
    let (sx, cx) = delta.re.sin_cos();
    let (cosh, sinh) = (0.5 * (1.0 + e), 0.5 * (1.0 - e) * delta.im.signum());
    let cos = Complex64::new(cx * cosh, -sx * sinh);
    let sin = Complex64::new(sx * cosh, cx * sinh);
    let sinc = if delta.norm() < 1e-6 {
        (1.0 - delta * delta / 6.0) * (-y).exp()
    } else {
        sin / delta
    };
    (cos, sinc, y)
}

/// `(R_s, R_p, T_s, T_p)` by the transfer matrix.
fn tmm(film: &Film, wavelength_nm: f64, theta1: f64) -> [f64; 4] {
    tmm_cos(film, wavelength_nm, theta1.cos())
}

fn tmm_cos(film: &Film, wavelength_nm: f64, cos1: f64) -> [f64; 4] {
    let (n1, n2, n3, d) = (film.n1, film.n2, film.n3, film.thickness_nm);
    let c1 = Complex64::new(cos1, 0.0);
    let c2 = macleod_cos(n1, cos1, n2);
    let c3 = macleod_cos(n1, cos1, n3);
    let k = 2.0 * PI / wavelength_nm;
    let delta = c2 * (k * n2 * d);
    let (cos, sinc, y) = scaled_cos_sinc(delta);
    let i = Complex64::i();
    let mut out = [0.0; 4];
    // s: tilted admittances (in units of the free-space admittance) η = n cos θ; the
    // film's matrix entries i sin δ / η2 and i η2 sin δ are written with sin δ = δ·sinc δ,
    // so that no cosine is divided by. [B, C] = M [1, η3], scaled by e^{−|Im δ|}.
    {
        let (eta1, eta3) = (c1 * n1, c3 * n3);
        let (m12, m21) = (i * k * d * sinc, i * k * d * (c2 * n2) * (c2 * n2) * sinc);
        let b = cos + m12 * eta3;
        let c = m21 + cos * eta3;
        let den = eta1 * b + c;
        out[0] = ((eta1 * b - c) / den).norm_sqr();
        out[2] = 4.0 * eta1.re * eta3.re * (-2.0 * y).exp() / den.norm_sqr();
    }
    // p: η = n / cos θ. Multiplying B and C by cos θ3, and r's numerator and denominator
    // by cos θ1, keeps grazing and critical cosines (0) out of every denominator:
    // B' = c3 B, C' = c3 C, r = (n1 B' − c1 C') / (n1 B' + c1 C'),
    // T = 4 n1 c1 Re(n3 c3*) / |n1 B' + c1 C'|².
    {
        let (m12, m21) = (i * k * d * c2 * c2 * sinc, i * k * n2 * n2 * d * sinc);
        let b = cos * c3 + m12 * n3;
        let c = m21 * c3 + cos * n3;
        let den = b * n1 + c * c1;
        out[1] = ((b * n1 - c * c1) / den).norm_sqr();
        out[3] = 4.0 * n1 * c1.re * (c3.conj() * n3).re * (-2.0 * y).exp() / den.norm_sqr();
    }
    out
}

/// The bare interface `n1 | n3`, from the Fresnel equations written out here (the test's
/// own, in Macleod's admittance form).
fn bare(n1: f64, n3: f64, theta1: f64) -> [f64; 2] {
    let c1 = Complex64::new(theta1.cos(), 0.0);
    let c3 = macleod_cos(n1, theta1.cos(), n3);
    let rs = (c1 * n1 - c3 * n3) / (c1 * n1 + c3 * n3);
    let rp = (n1 / c1 - n3 / c3) / (n1 / c1 + n3 / c3);
    [rs.norm_sqr(), rp.norm_sqr()]
}

fn library(film: &Film, wavelength_nm: f64, theta1: f64) -> [f64; 4] {
    let r = film.response(wavelength_nm, theta1);
    [
        r.reflectance_s,
        r.reflectance_p,
        r.transmittance_s,
        r.transmittance_p,
    ]
}

// ---------------------------------------------------------------------------------------
// The sweep: random films over the whole domain, including the awkward corners.

#[derive(Clone, Copy, Debug)]
struct Case {
    film: Film,
    wavelength_nm: f64,
    theta1: f64,
}

/// `count` random cases: indices 1–2.5 in every order (so films and substrates both
/// denser and rarer than the ambient, total internal reflection at either interface and
/// evanescent films), one in ten with two equal indices, thicknesses 0 or 0.01 nm to
/// 100 µm, wavelengths 360–830 nm, angles 0 to exactly 90°.
fn sweep(count: usize, seed: u64) -> Vec<Case> {
    let mut g = rng::seeded(seed);
    (0..count)
        .map(|_| {
            let mut n = [0.0; 3];
            for x in &mut n {
                *x = rng::uniform(&mut g, 1.0, 2.5);
            }
            match (rng::uniform(&mut g, 0.0, 1.0) * 30.0) as u32 {
                0 => n[1] = n[0],
                1 => n[2] = n[1],
                2 => n[2] = n[0],
                _ => {}
            }
            let thickness_nm = if rng::uniform(&mut g, 0.0, 1.0) < 0.1 {
                0.0
            } else {
                rng::log_uniform(&mut g, 1e-2, 1e5)
            };
            let u = rng::uniform(&mut g, 0.0, 1.0);
            let theta1 = if u < 0.03 {
                0.0
            } else if u < 0.06 {
                FRAC_PI_2
            } else {
                rng::uniform(&mut g, 0.0, FRAC_PI_2)
            };
            Case {
                film: Film::new(n[0], n[1], n[2], thickness_nm),
                wavelength_nm: rng::uniform(&mut g, 360.0, 830.0),
                theta1,
            }
        })
        .collect()
}

/// The worst disagreement of `f` (unpolarised reflectance) with the transfer matrix over
/// `cases`, and the case where it occurs. NaN counts as infinitely wrong.
fn worst_unpolarised(cases: &[Case], f: impl Fn(&Case) -> f64) -> (f64, Option<Case>) {
    let mut worst = (0.0, None);
    for case in cases {
        let [rs, rp, ..] = tmm(&case.film, case.wavelength_nm, case.theta1);
        let got = f(case);
        let err = if got.is_finite() {
            (got - 0.5 * (rs + rp)).abs()
        } else {
            f64::INFINITY
        };
        if err > worst.0 {
            worst = (err, Some(*case));
        }
    }
    worst
}

const SWEEP_SEED: u64 = 0x7f11;
const SWEEP_CASES: usize = 20_000;

// ANCHOR: tmm_test
/// The Airy sum agrees with the transfer matrix to 1e-12 in R_s, R_p, T_s and T_p over
/// 20 000 random films: every order of indices, total internal reflection at either
/// interface, evanescent films, thicknesses from 0 to 100 µm, angles up to exactly 90°.
#[test]
fn airy_sum_agrees_with_the_transfer_matrix() {
    let cases = sweep(SWEEP_CASES, SWEEP_SEED);
    let mut worst = (0.0f64, String::new());
    for case in &cases {
        let want = tmm(&case.film, case.wavelength_nm, case.theta1);
        let got = library(&case.film, case.wavelength_nm, case.theta1);
        for (k, name) in ["R_s", "R_p", "T_s", "T_p"].iter().enumerate() {
            let err = (got[k] - want[k]).abs();
            if (err.is_nan() || err > worst.0) && !worst.0.is_nan() {
                worst = (
                    err,
                    format!("{name}: {} vs {} for {case:?}", got[k], want[k]),
                );
            }
        }
    }
    assert!(worst.0 <= 1e-12, "worst error {:e}: {}", worst.0, worst.1);
}
// ANCHOR_END: tmm_test

// ---------------------------------------------------------------------------------------
// Limits that must reduce to a single interface.

/// Angles 0..90° and index pairs including total internal reflection (n1 > n3).
fn interface_cases() -> impl Iterator<Item = (f64, f64, f64)> {
    let pairs = [
        (1.0, 1.33),
        (1.0, 1.5),
        (1.33, 1.5),
        (1.5, 1.0),
        (1.52, 1.33),
        (2.4, 1.0),
    ];
    pairs
        .into_iter()
        .flat_map(|(n1, n3)| (0..=90).map(move |a| (n1, n3, FRAC_PI_2 * f64::from(a) / 90.0)))
}

#[track_caller]
fn assert_bare(film: Film, n1: f64, n3: f64, theta1: f64, tol: f64) {
    let r = film.response(550.0, theta1);
    let [bs, bp] = bare(n1, n3, theta1);
    assert!(
        (r.reflectance_s - bs).abs() <= tol && (r.reflectance_p - bp).abs() <= tol,
        "{film:?} at {theta1}: ({}, {}) vs bare ({bs}, {bp})",
        r.reflectance_s,
        r.reflectance_p
    );
}

/// d = 0: the film vanishes, leaving the bare n1 | n3 interface, for any film index.
#[test]
fn zero_thickness_is_the_bare_interface() {
    for (n1, n3, t) in interface_cases() {
        for n2 in [1.2, 1.38, 2.0, 3.0] {
            assert_bare(Film::new(n1, n2, n3, 0.0), n1, n3, t, 1e-14);
        }
    }
}

/// n2 = n1: the film is part of the ambient and only its far interface (n1 | n3) remains,
/// at any thickness; n2 = n3: it is part of the substrate and only the near one remains.
#[test]
fn film_matching_either_neighbour_leaves_one_interface() {
    for (n1, n3, t) in interface_cases() {
        for d in [10.0, 123.4, 5000.0] {
            assert_bare(Film::new(n1, n1, n3, d), n1, n3, t, 1e-14);
            assert_bare(Film::new(n1, n3, n3, d), n1, n3, t, 1e-14);
        }
    }
}

/// A half-wave film (2δ = 2π, so e^{2iδ} = 1) is absent at its own wavelength and angle:
/// r = (r12 + r23)/(1 + r12 r23) = r13, for any film index.
#[test]
fn half_wave_film_is_absent() {
    for (n1, n3, t) in interface_cases() {
        for n2 in [n1 + 0.3, n1 + 0.9, n1 + 1.5] {
            // Films denser than the ambient, so cos θ2 is real.
            let c2 = cos_theta(n1, t.cos(), n2).re;
            let d = 550.0 / (2.0 * n2 * c2);
            assert_bare(Film::new(n1, n2, n3, d), n1, n3, t, 1e-12);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Energy, range, the soap film, thin and thick films, grazing and total reflection.

/// R in [0, 1] and R + T = 1 (lossless media) for each polarisation, to 1e-12, over the
/// random sweep.
#[test]
fn energy_is_conserved_and_reflectance_is_in_range() {
    for case in sweep(SWEEP_CASES, SWEEP_SEED + 1) {
        let r = case.film.response(case.wavelength_nm, case.theta1);
        for (rr, tt) in [
            (r.reflectance_s, r.transmittance_s),
            (r.reflectance_p, r.transmittance_p),
        ] {
            assert!(
                (0.0..=1.0 + 1e-12).contains(&rr) && tt >= -1e-12 && (rr + tt - 1.0).abs() <= 1e-12,
                "R = {rr}, T = {tt} for {case:?}"
            );
        }
    }
}

// ANCHOR: soap_test
/// A quarter-wave film at normal incidence (n2 d = λ/4, e^{2iδ} = −1) reflects
/// ((n1 n3 − n2²)/(n1 n3 + n2²))²: for a soap film (n2 = 1.33) in air, ((1 − n2²)/(1 + n2²))²
/// = 0.0771. For a film denser (or rarer) than both neighbours, r12 r23 < 0 and that is the
/// largest R over all thicknesses; for a film between them, as an anti-reflection coating
/// (MgF2, 1.38, on glass, 1.52), the smallest: 0.0126, against 0.0426 for bare glass.
#[test]
fn quarter_wave_soap_film_reflects_most() {
    let lambda = 550.0;
    let soap = quarter_wave_reflectance(1.0, 1.33, 1.0);
    assert!((soap - 0.0771).abs() < 5e-5, "{soap}");
    let coating = quarter_wave_reflectance(1.0, 1.38, 1.52);
    assert!((coating - 0.0126).abs() < 5e-5, "{coating}");
    let glass = Film::new(1.0, 1.52, 1.52, 0.0).reflectance(lambda, 0.0);
    assert!((glass - 0.0426).abs() < 5e-5, "{glass}");
    for (n1, n2, n3) in [
        (1.0, 1.33, 1.0),
        (1.0, 1.5, 1.33),
        (1.0, 1.38, 1.52),
        (1.33, 2.0, 1.5),
    ] {
        let quarter = lambda / (4.0 * n2);
        let r = Film::new(n1, n2, n3, quarter).reflectance(lambda, 0.0);
        let want = quarter_wave_reflectance(n1, n2, n3);
        assert!((r - want).abs() <= 1e-14, "{n1}/{n2}/{n3}: {r} vs {want}");
        // Over one period of thickness (0 to λ/(2 n2)) the quarter wave is the extreme.
        let mut others = (0..=400).map(|k| {
            Film::new(n1, n2, n3, 2.0 * quarter * f64::from(k) / 400.0).reflectance(lambda, 0.0)
        });
        if (n2 - n1) * (n3 - n2) < 0.0 {
            assert!(others.all(|x| x <= r + 1e-15));
        } else {
            assert!(others.all(|x| x >= r - 1e-15));
        }
    }
}
// ANCHOR_END: soap_test

/// A film much thinner than the wavelength barely changes the interface, and only to
/// second order: with real cosines the first-order change of r is in quadrature with r, so
/// R(d) − R(0) ∝ d² (doubling d quadruples the change; |R(1e-6 nm) − R(0)| < 1e-9).
#[test]
fn very_thin_films_tend_to_the_bare_interface() {
    for (n1, n2, n3) in [(1.0, 1.33, 1.0), (1.0, 1.5, 1.33), (1.52, 1.38, 1.0)] {
        for t in [0.0, 0.5] {
            let r0 = Film::new(n1, n2, n3, 0.0).reflectance(550.0, t);
            let r = |d: f64| Film::new(n1, n2, n3, d).reflectance(550.0, t);
            assert!((r(1e-6) - r0).abs() < 1e-9);
            let (a, b) = (r(2.0) - r0, r(1.0) - r0);
            assert!(a.abs() < 1e-2 && (a / b - 4.0).abs() <= 1e-2, "{a} {b}");
        }
    }
}

/// A thick film's fringes, averaged over one period of the phase, leave the incoherent
/// sum of the multiple reflections, (R12 + R23 − 2 R12 R23)/(1 − R12 R23), per polarisation:
/// 100 µm of oil on water at 30°, sampled at 64 points per fringe over ten fringes (uniform
/// in 1/λ, where the phase is uniform), agrees to 1e-9.
#[test]
fn thick_film_fringes_average_to_the_incoherent_sum() {
    let film = Film::new(1.0, 1.5, 1.33, 1e5);
    let theta1 = 30f64.to_radians();
    let c2 = cos_theta(1.0, theta1.cos(), 1.5).re;
    // 2δ = 4π n2 d c2 / λ advances by 2π when 1/λ advances by 1/(2 n2 d c2).
    let step = 1.0 / (2.0 * 1.5 * 1e5 * c2) / 64.0;
    let (mut s, mut p) = (0.0, 0.0);
    let count = 640;
    for k in 0..count {
        let lambda = 1.0 / (1.0 / 550.0 + step * f64::from(k));
        let r = film.response(lambda, theta1);
        s += r.reflectance_s / f64::from(count);
        p += r.reflectance_p / f64::from(count);
    }
    let [r12s, r12p] = bare(1.0, 1.5, theta1);
    let theta2 = (theta1.sin() / 1.5).asin();
    let [r23s, r23p] = bare(1.5, 1.33, theta2);
    let want_s = incoherent_reflectance(r12s, r23s);
    let want_p = incoherent_reflectance(r12p, r23p);
    assert!((s - want_s).abs() < 1e-9, "{s} vs {want_s}");
    assert!((p - want_p).abs() < 1e-9, "{p} vs {want_p}");
}

/// Grazing incidence reflects everything: R = 1 and T = 0 at exactly 90°, and R → 1
/// continuously as the angle approaches it (1 − R within 10 times the angle to grazing).
#[test]
fn grazing_incidence_reflects_everything() {
    for (n1, n2, n3) in [
        (1.0, 1.33, 1.0),
        (1.0, 1.5, 1.33),
        (1.52, 1.38, 1.0),
        (1.0, 1.0, 1.5),
    ] {
        let film = Film::new(n1, n2, n3, 300.0);
        let r = film.response(550.0, FRAC_PI_2);
        assert!((r.reflectance() - 1.0).abs() <= 1e-12 && r.transmittance().abs() <= 1e-12);
        for k in 1..=8 {
            let gap = 10f64.powi(-k);
            let near = film.reflectance(550.0, FRAC_PI_2 - gap);
            assert!(
                near <= 1.0 + 1e-12 && 1.0 - near <= 10.0 * gap,
                "{gap}: {near}"
            );
        }
    }
}

/// Seen from inside glass (1.52) through an MgF2 film (1.38) into air, every angle beyond
/// the glass–air critical angle (41.1°) is totally reflected: R = 1, T = 0, with no NaN,
/// although the wave in the air (and, beyond 65.2°, in the film too) is evanescent.
#[test]
fn total_internal_reflection_through_a_film() {
    let film = Film::new(1.52, 1.38, 1.0, 100.0);
    let critical = (1.0f64 / 1.52).asin();
    assert!((critical.to_degrees() - 41.14).abs() < 0.01);
    let film_critical = (1.38f64 / 1.52).asin();
    assert!((film_critical.to_degrees() - 65.2).abs() < 0.05);
    for k in 0..=200 {
        let t = critical + (FRAC_PI_2 - critical) * f64::from(k) / 200.0 + 1e-12;
        let t = t.min(FRAC_PI_2);
        let r = film.response(550.0, t);
        assert!(
            (r.reflectance_s - 1.0).abs() <= 1e-12 && (r.reflectance_p - 1.0).abs() <= 1e-12,
            "{t}: {r:?}"
        );
        assert!(r.transmittance() == 0.0, "{t}: {r:?}");
    }
}

/// Frustrated total internal reflection: an air gap (n2 = 1) between two glass blocks
/// (1.5) at 60°, beyond the critical angle. Light tunnels through a thin gap, T falls by
/// e^{−2 k κ Δd} for each added Δd of thickness (κ = n2 |cos θ2|), and the sum stays 1.
#[test]
fn frustrated_total_internal_reflection_tunnels_and_decays() {
    let theta1 = 60f64.to_radians();
    let kappa = cos_theta(1.5, theta1.cos(), 1.0).im;
    assert!(kappa > 0.0);
    let k = 2.0 * PI / 550.0;
    let t = |d: f64| Film::new(1.5, 1.0, 1.5, d).response(550.0, theta1);
    assert!(t(10.0).transmittance() > 0.5);
    for d in [600.0, 1200.0, 2400.0] {
        let ratio = t(d + 50.0).transmittance_s / t(d).transmittance_s;
        let want = (-2.0 * k * kappa * 50.0).exp();
        assert!((ratio / want - 1.0).abs() < 1e-3, "{ratio} vs {want}");
        let r = t(d);
        assert!((r.reflectance() + r.transmittance() - 1.0).abs() <= 1e-12);
    }
}

/// The film exactly at its critical angle: n1 = 1.25, n2 = 1, cos θ1 = 0.6, so that
/// cos²θ2 = (1 − 1.25²) + (1.25 · 0.6)² = 0 exactly in floating point. The plain Airy sum
/// is 0/0 there (r12 = 1, r23 = −1, z = 1); the rearranged form needs no special case and
/// agrees with the transfer matrix to 1e-12, conserving energy.
#[test]
fn film_exactly_at_its_critical_angle() {
    let (n1, n2, n3, cos1) = (1.25, 1.0, 1.5, 0.6);
    assert_eq!(cos_theta(n1, cos1, n2).norm_sqr(), 0.0);
    for d in [0.0, 1.0, 100.0, 5000.0] {
        let film = Film::new(n1, n2, n3, d);
        let r = film.response_cos(550.0, cos1);
        let got = [
            r.reflectance_s,
            r.reflectance_p,
            r.transmittance_s,
            r.transmittance_p,
        ];
        let want = tmm_cos(&film, 550.0, cos1);
        for k in 0..4 {
            assert!(
                got[k].is_finite() && (got[k] - want[k]).abs() <= 1e-12,
                "d = {d}: {got:?} vs {want:?}"
            );
        }
        assert!((got[0] + got[2] - 1.0).abs() <= 1e-12 && (got[1] + got[3] - 1.0).abs() <= 1e-12);
    }
}

/// The plain Airy sum `(r12 + r23 z)/(1 + r12 r23 z)`, assembled from the library's
/// pieces, is right away from two corners: 1e-12 against the transfer matrix wherever
/// |cos θ1| and |cos θ2| exceed 1e-3. In the corners its denominator is a difference of
/// nearly equal numbers:
/// * near the film's critical angle r12 → 1, r23 → −1, z → 1. At 30° in glass of
///   n1 = 2.4 under a film of n2 = 1.2 (n1 sin θ1 = n2 but for rounding, |cos θ2| < 1e-7)
///   with d = 0 it is wrong by more than 1e-10;
/// * within 1e-12 rad of grazing incidence over a sub-picometre film whose far side has
///   the ambient's index, r12 → −1, r23 → 1: n1 = n3 = 1, n2 = 1.33, d = 1e-9 nm, it is
///   wrong by more than 1e-7 (a corner no real scene reaches).
///
/// The library's rearranged form stays within 1e-13 in both.
#[test]
fn plain_airy_sum_loses_digits_in_two_corners() {
    let cases = sweep(SWEEP_CASES, SWEEP_SEED);
    let away: Vec<Case> = cases
        .into_iter()
        .filter(|c| {
            let cos1 = c.theta1.cos();
            cos1 > 1e-3 && cos_theta(c.film.n1, cos1, c.film.n2).norm() > 1e-3
        })
        .collect();
    assert!(away.len() > SWEEP_CASES / 2);
    let (worst, at) = worst_unpolarised(&away, |c| assembled(c, phase, false));
    assert!(worst <= 1e-12, "{worst} at {at:?}");

    for (film, t, threshold) in [
        (Film::new(2.4, 1.2, 1.0, 0.0), 30f64.to_radians(), 1e-10),
        (Film::new(1.0, 1.33, 1.0, 1e-9), FRAC_PI_2 - 1e-12, 1e-7),
    ] {
        let case = Case {
            film,
            wavelength_nm: 550.0,
            theta1: t,
        };
        let [rs, rp, ..] = tmm(&film, 550.0, t);
        let reference = 0.5 * (rs + rp);
        let plain = assembled(&case, phase, false);
        let plain_error = (plain - reference).abs();
        let stable_error = (film.reflectance(550.0, t) - reference).abs();
        assert!(
            plain_error.is_nan() || plain_error > threshold,
            "plain sum error {plain_error} for {film:?}"
        );
        assert!(
            stable_error <= 1e-13,
            "stable error {stable_error} for {film:?}"
        );
    }
    // The first reference is known exactly: the bare interface totally reflects.
    assert_eq!(bare(2.4, 1.0, 30f64.to_radians()), [1.0, 1.0]);
}

/// No NaN, R and T in [0, 1], R + T = 1 on a grid over the whole domain: indices 1, 1.33,
/// 1.5, 2.4 in every combination, thicknesses 0 to 100 µm, the ends of the render range,
/// and angles 0 to exactly 90° plus each exact critical angle.
#[test]
fn no_nan_anywhere_in_the_domain() {
    let indices = [1.0f64, 1.33, 1.5, 2.4];
    let mut count = 0;
    for &n1 in &indices {
        for &n2 in &indices {
            for &n3 in &indices {
                let mut angles: Vec<f64> =
                    (0..=90).map(|a| FRAC_PI_2 * f64::from(a) / 90.0).collect();
                for n in [n2, n3] {
                    if n < n1 {
                        angles.push((n / n1).asin());
                    }
                }
                for d in [0.0, 1e-3, 1.0, 100.0, 1e3, 1e5] {
                    for lambda in [360.0, 550.0, 830.0] {
                        for &t in &angles {
                            let r = Film::new(n1, n2, n3, d).response(lambda, t);
                            for (rr, tt) in [
                                (r.reflectance_s, r.transmittance_s),
                                (r.reflectance_p, r.transmittance_p),
                            ] {
                                assert!(
                                    rr.is_finite()
                                        && tt.is_finite()
                                        && (-1e-12..=1.0 + 1e-12).contains(&rr)
                                        && (-1e-12..=1.0 + 1e-12).contains(&tt)
                                        && (rr + tt - 1.0).abs() <= 1e-10,
                                    "{n1}/{n2}/{n3}, d {d}, λ {lambda}, θ {t}: {r:?}"
                                );
                            }
                            count += 1;
                        }
                    }
                }
            }
        }
    }
    assert!(count > 100_000);
}

// ---------------------------------------------------------------------------------------
// Planted bugs: each must disagree with the transfer matrix.

/// A reflectance built from the library's pieces, with one piece swapped.
fn assembled(
    case: &Case,
    phase_of: impl Fn(f64, f64, Complex64, f64) -> Complex64,
    flip_r12_p: bool,
) -> f64 {
    let Film { n1, n2, n3, .. } = case.film;
    let cos1 = case.theta1.cos();
    let c1 = Complex64::new(cos1, 0.0);
    let (c2, c3) = (cos_theta(n1, cos1, n2), cos_theta(n1, cos1, n3));
    let (i12, i23) = (interface(n1, c1, n2, c2), interface(n2, c2, n3, c3));
    let delta = phase_of(n2, case.film.thickness_nm, c2, case.wavelength_nm);
    let r12_p = if flip_r12_p { -i12.r_p } else { i12.r_p };
    let rs = airy_r(i12.r_s, i23.r_s, delta).norm_sqr();
    let rp = airy_r(r12_p, i23.r_p, delta).norm_sqr();
    0.5 * (rs + rp)
}

#[test]
fn rejects_a_missing_factor_2_in_the_phase() {
    // e^{iδ} for the round trip instead of e^{2iδ}.
    let cases = sweep(2_000, SWEEP_SEED);
    let (worst, _) = worst_unpolarised(&cases, |c| {
        assembled(c, |n, d, c2, l| 0.5 * phase(n, d, c2, l), false)
    });
    assert!(worst > 0.05, "{worst}");
}

#[test]
fn rejects_the_wrong_sign_of_r12_for_p() {
    // Mixing the two sign conventions of r_p between the two interfaces.
    let cases = sweep(2_000, SWEEP_SEED);
    let (worst, _) = worst_unpolarised(&cases, |c| assembled(c, phase, true));
    assert!(worst > 0.05, "{worst}");
}

#[test]
fn rejects_a_missing_cos_theta2_in_the_phase() {
    // δ = 2π n2 d / λ: right at normal incidence only.
    let cases = sweep(2_000, SWEEP_SEED);
    let (worst, _) = worst_unpolarised(&cases, |c| {
        assembled(
            c,
            |n, d, _c2, l| phase(n, d, Complex64::new(1.0, 0.0), l),
            false,
        )
    });
    assert!(worst > 0.05, "{worst}");
    // ...and at normal incidence it is right, which is why it survives casual testing.
    let normal: Vec<Case> = cases.iter().map(|c| Case { theta1: 0.0, ..*c }).collect();
    let (worst, _) = worst_unpolarised(&normal, |c| {
        assembled(
            c,
            |n, d, _c2, l| phase(n, d, Complex64::new(1.0, 0.0), l),
            false,
        )
    });
    assert!(worst <= 1e-12, "{worst}");
}

#[test]
fn rejects_the_wrong_branch_of_the_evanescent_cosine() {
    // cos θ = −i sqrt(sin²θ − 1) in Born & Wolf's convention: a growing wave. A thick
    // evanescent film then overflows e^{2iδ} to infinity and the sum to NaN.
    let cases = sweep(2_000, SWEEP_SEED);
    let wrong_branch = |n1: f64, cos1: f64, n: f64| cos_theta(n1, cos1, n).conj();
    let (worst, _) = worst_unpolarised(&cases, |c| {
        let Film { n1, n2, n3, .. } = c.film;
        let cos1 = c.theta1.cos();
        let c1 = Complex64::new(cos1, 0.0);
        let (c2, c3) = (wrong_branch(n1, cos1, n2), wrong_branch(n1, cos1, n3));
        let (i12, i23) = (interface(n1, c1, n2, c2), interface(n2, c2, n3, c3));
        let delta = phase(n2, c.film.thickness_nm, c2, c.wavelength_nm);
        0.5 * (airy_r(i12.r_s, i23.r_s, delta).norm_sqr()
            + airy_r(i12.r_p, i23.r_p, delta).norm_sqr())
    });
    assert!(worst > 0.05, "{worst}");
}

// ---------------------------------------------------------------------------------------
// The seed's formula.

/// The seed's denominator has −2 r12 r23 cos φ where the Airy sum gives +2 r12 r23 cos φ
/// (|1 + r12 r23 e^{iφ}|² = 1 + r12² r23² + 2 r12 r23 cos φ). For the quarter-wave soap film
/// at normal incidence it gives 0.0836 instead of 0.0771 (so R + T = 1.0064 > 1), and near
/// grazing incidence it exceeds 1: 2.83 at 89°.
#[test]
fn seed_airy_denominator_has_the_wrong_sign() {
    let soap = Film::new(1.0, 1.33, 1.0, 550.0 / (4.0 * 1.33));
    let seed = seed_reflectance(&soap, 550.0, 0.0);
    let right = soap.response(550.0, 0.0);
    assert!((seed - 0.0836).abs() < 5e-5, "{seed}");
    assert!((right.reflectance() - 0.0771).abs() < 5e-5);
    assert!((seed + right.transmittance() - 1.0064).abs() < 5e-5);
    let grazing = seed_reflectance(&soap, 550.0, 89f64.to_radians());
    assert!((grazing - 2.83).abs() < 5e-3, "{grazing}");
    assert!(soap.reflectance(550.0, 89f64.to_radians()) <= 1.0);
    // With the sign corrected (and the seed's other choices kept: s only, real cosines)
    // the formula is the library's s reflectance wherever the cosines are real (short of
    // exactly grazing, where its real cosines give 0/0).
    let fixed = |f: &Film, l: f64, t: f64| {
        let (n1, n2, n3, d) = (f.n1, f.n2, f.n3, f.thickness_nm);
        let c1 = t.cos();
        let c2 = (1.0 - (n1 / n2 * t.sin()).powi(2)).sqrt();
        let c3 = (1.0 - (n1 / n3 * t.sin()).powi(2)).sqrt();
        let r12 = (n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2);
        let r23 = (n2 * c2 - n3 * c3) / (n2 * c2 + n3 * c3);
        let phi = 4.0 * PI * n2 * d * c2 / l;
        (r12 * r12 + r23 * r23 + 2.0 * r12 * r23 * phi.cos())
            / (1.0 + r12 * r12 * r23 * r23 + 2.0 * r12 * r23 * phi.cos())
    };
    for case in sweep(2_000, SWEEP_SEED) {
        let f = case.film;
        if f.n2 >= f.n1 && f.n3 >= f.n1 && case.theta1 < 1.5 {
            let want = f.response(case.wavelength_nm, case.theta1).reflectance_s;
            let got = fixed(&f, case.wavelength_nm, case.theta1);
            assert!((got - want).abs() <= 1e-12, "{got} vs {want} for {case:?}");
        }
    }
}

/// The seed's cosines are real, sqrt(1 − sin²θ): beyond a critical angle they are NaN, and
/// so is its reflectance. Glass (1.52) | MgF2 (1.38) | air beyond 41.1°: every angle NaN,
/// where the true reflectance is 1.
#[test]
fn seed_real_cosines_give_nan_beyond_the_critical_angle() {
    let film = Film::new(1.52, 1.38, 1.0, 100.0);
    for a in [42, 50, 60, 70, 80, 89] {
        let t = f64::from(a).to_radians();
        assert!(seed_reflectance(&film, 550.0, t).is_nan(), "{a}°");
        assert!((film.reflectance(550.0, t) - 1.0).abs() <= 1e-12);
    }
    let cases = sweep(2_000, SWEEP_SEED);
    let (worst, _) = worst_unpolarised(&cases, |c| {
        seed_reflectance(&c.film, c.wavelength_nm, c.theta1)
    });
    assert!(worst.is_infinite());
}

/// The seed uses the s-polarised coefficients for all light. Unpolarised light is the mean
/// of s and p, and they differ away from normal incidence: for the 300 nm soap film at
/// 550 nm and 60°, R_s = 0.0536 and R_p = 0.0017, so the seed's choice (even with its sign
/// fixed) reports 0.0536 where unpolarised light sees 0.0277, almost twice as much.
#[test]
fn seed_uses_s_polarisation_for_unpolarised_light() {
    let soap = Film::new(1.0, 1.33, 1.0, 300.0);
    let r = soap.response(550.0, 60f64.to_radians());
    assert!(
        (r.reflectance_s - 0.0536).abs() < 5e-5,
        "{}",
        r.reflectance_s
    );
    assert!(
        (r.reflectance_p - 0.0017).abs() < 5e-5,
        "{}",
        r.reflectance_p
    );
    assert!(
        (r.reflectance() - 0.0277).abs() < 5e-5,
        "{}",
        r.reflectance()
    );
    // At normal incidence s and p agree, so the seed's choice is harmless there.
    let r0 = soap.response(550.0, 0.0);
    assert!((r0.reflectance_s - r0.reflectance_p).abs() <= 1e-15);
}

/// Sanity of the building blocks' conventions (Born & Wolf): r_p = −r_s at normal
/// incidence; r_p = 0 at Brewster's angle; the evanescent cosine has Im > 0.
#[test]
fn building_block_conventions() {
    let one = Complex64::new(1.0, 0.0);
    let i = interface(1.0, one, 1.5, one);
    assert!((i.r_s + i.r_p).norm() <= 1e-15 && (i.r_s.re + 0.2).abs() <= 1e-15);
    let brewster = 1.5f64.atan();
    let c1 = Complex64::new(brewster.cos(), 0.0);
    let c2 = cos_theta(1.0, brewster.cos(), 1.5);
    assert!(interface(1.0, c1, 1.5, c2).r_p.norm() <= 1e-15);
    let ev = cos_theta(1.5, 0.6, 1.0); // n1 sin θ1 = 1.2 > 1
    assert!(ev.re == 0.0 && ev.im > 0.0);
}

// ---------------------------------------------------------------------------------------
// Exercises. Each scaffold is the student's to fill in; each ignored test checks it, and
// fails until it is done: `cargo test --test book optics::thinfilm::exercise_ -- --ignored`.

/// Two films by Macleod's characteristic matrices (his conventions, as in [`tmm_cos`]),
/// `n = [ambient, upper film, lower film, substrate]`: `[R_s, R_p]`. Unscaled, so for
/// films up to a few micrometres only.
fn tmm_two_layers(n: [f64; 4], d_nm: [f64; 2], wavelength_nm: f64, cos1: f64) -> [f64; 2] {
    let k = 2.0 * PI / wavelength_nm;
    let i = Complex64::i();
    let c: Vec<Complex64> = n.iter().map(|&nj| macleod_cos(n[0], cos1, nj)).collect();
    let mut out = [0.0; 2];
    for (pol, slot) in out.iter_mut().enumerate() {
        // Tilted admittances: n cos θ for s, n / cos θ for p.
        let eta = |j: usize| if pol == 0 { c[j] * n[j] } else { n[j] / c[j] };
        let (mut m11, mut m12, mut m21, mut m22) = (
            Complex64::new(1.0, 0.0),
            Complex64::new(0.0, 0.0),
            Complex64::new(0.0, 0.0),
            Complex64::new(1.0, 0.0),
        );
        for layer in 1..=2 {
            let delta = c[layer] * (k * n[layer] * d_nm[layer - 1]);
            let (cos, sin) = (delta.cos(), delta.sin());
            let (a11, a12, a21, a22) = (cos, i * sin / eta(layer), i * eta(layer) * sin, cos);
            (m11, m12, m21, m22) = (
                m11 * a11 + m12 * a21,
                m11 * a12 + m12 * a22,
                m21 * a11 + m22 * a21,
                m21 * a12 + m22 * a22,
            );
        }
        let b = m11 + m12 * eta(3);
        let cc = m21 + m22 * eta(3);
        *slot = ((eta(0) * b - cc) / (eta(0) * b + cc)).norm_sqr();
    }
    out
}

/// Exercise 1 of *Thin-film interference*: `[R_s, R_p]` of two films on a substrate,
/// `n = [ambient, upper film, lower film, substrate]` with thicknesses `d_nm = [upper,
/// lower]`, by the Airy sum applied twice.
#[allow(unused_variables)]
fn your_two_layer_reflectance(
    n: [f64; 4],
    d_nm: [f64; 2],
    wavelength_nm: f64,
    cos1: f64,
) -> [f64; 2] {
    unimplemented!("exercise 1 of Thin-film interference: apply the Airy sum twice")
}

#[test]
#[ignore = "exercise 1 of Thin-film interference: fill in your_two_layer_reflectance, then run it"]
fn exercise_1_two_layers() {
    let mut g = rng::seeded(0x2f11);
    let mut worst: f64 = 0.0;
    for _ in 0..20_000 {
        let mut n = [0.0; 4];
        for x in &mut n {
            *x = rng::uniform(&mut g, 1.0, 2.5);
        }
        let d = [
            rng::uniform(&mut g, 0.0, 1000.0),
            rng::uniform(&mut g, 0.0, 1000.0),
        ];
        let wavelength = rng::uniform(&mut g, 360.0, 830.0);
        let cos1 = rng::uniform(&mut g, 0.01, 1.0);
        let (yours, reference) = (
            your_two_layer_reflectance(n, d, wavelength, cos1),
            tmm_two_layers(n, d, wavelength, cos1),
        );
        for (y, r) in yours.iter().zip(reference) {
            assert!(
                (y - r).abs() <= 1e-10,
                "{n:?}, {d:?} nm at {wavelength} nm, cos {cos1}: {yours:?}, matrices give {reference:?}"
            );
            worst = worst.max((y - r).abs());
        }
    }
    // One film with the other of zero thickness is the library's one film.
    let one = Film::new(1.0, 1.38, 1.52, 100.0).response_cos(550.0, 0.8);
    let two = your_two_layer_reflectance([1.0, 1.38, 2.0, 1.52], [100.0, 0.0], 550.0, 0.8);
    assert!(
        (two[0] - one.reflectance_s).abs() <= 1e-12 && (two[1] - one.reflectance_p).abs() <= 1e-12
    );
    assert!(worst <= 1e-10);
}

/// The unpolarised reflectance of the film of MgF2 (1.38, no dispersion) on glass (1.52)
/// in air, averaged over 400..=700 nm in steps of 1 nm, at `theta1`.
fn mean_coating_reflectance(thickness_nm: f64, theta1: f64) -> f64 {
    let film = Film::new(1.0, 1.38, 1.52, thickness_nm);
    (400..=700)
        .map(|l| film.reflectance(f64::from(l), theta1))
        .sum::<f64>()
        / 301.0
}

/// Exercise 2 of *Thin-film interference*: the MgF2 thickness (nm) that minimises
/// `mean_coating_reflectance` at normal incidence and at 45°.
const YOUR_COATING_NM_AT_0_AND_45: Option<(f64, f64)> = None;

#[test]
#[ignore = "exercise 2 of Thin-film interference: set YOUR_COATING_NM_AT_0_AND_45, then run it"]
fn exercise_2_broadband_coating() {
    let optimum = |theta1: f64| {
        (500..=2000)
            .map(|k| f64::from(k) * 0.1)
            .min_by(|a, b| {
                mean_coating_reflectance(*a, theta1)
                    .total_cmp(&mean_coating_reflectance(*b, theta1))
            })
            .unwrap()
    };
    let expected = (optimum(0.0), optimum(45f64.to_radians()));
    let yours = YOUR_COATING_NM_AT_0_AND_45.expect("exercise 2: set YOUR_COATING_NM_AT_0_AND_45");
    assert!(
        (yours.0 - expected.0).abs() <= 0.5 && (yours.1 - expected.1).abs() <= 0.5,
        "{yours:?} nm, but the optima are {expected:?} nm"
    );
}

/// Exercise 3 of *Thin-film interference*: the unpolarised reflectance of a film (index
/// `n2`, `d_nm` thick) on a metal of complex index `n3 = n + ik`, for light from the
/// ambient `n1` at `cos θ1 = cos1`.
#[allow(unused_variables)]
fn your_film_on_metal_reflectance(
    n1: f64,
    n2: f64,
    n3: Complex64,
    d_nm: f64,
    wavelength_nm: f64,
    cos1: f64,
) -> f64 {
    unimplemented!("exercise 3 of Thin-film interference: a film on a metal substrate")
}

/// The bare interface from `n1` onto a conductor `n3`, as pbrt-v4 writes it (`FrComplex`).
fn bare_conductor(n1: f64, n3: Complex64, cos1: f64) -> f64 {
    let eta = n3 / n1;
    let sin2_t = (1.0 - cos1 * cos1) / (eta * eta);
    let cos_t = (1.0 - sin2_t).sqrt();
    let r_parl = (eta * cos1 - cos_t) / (eta * cos1 + cos_t);
    let r_perp = (cos1 - eta * cos_t) / (cos1 + eta * cos_t);
    0.5 * (r_parl.norm_sqr() + r_perp.norm_sqr())
}

#[test]
#[ignore = "exercise 3 of Thin-film interference: fill in your_film_on_metal_reflectance, then run it"]
fn exercise_3_metal_substrate() {
    let metals = [
        Complex64::new(0.96, 6.69),
        Complex64::new(0.06, 3.59),
        Complex64::new(0.2, 3.0),
    ];
    for m in metals {
        for k in 0..90 {
            let c = f64::to_radians(f64::from(k)).cos();
            // No film: the bare conductor, from air and from glass.
            for n1 in [1.0, 1.5] {
                let (got, want) = (
                    your_film_on_metal_reflectance(n1, 1.38, m, 0.0, 550.0, c),
                    bare_conductor(n1, m, c),
                );
                assert!(
                    (got - want).abs() <= 1e-12,
                    "{m} from {n1} at {k} deg, no film: {got}, expected {want}"
                );
            }
            let r = your_film_on_metal_reflectance(1.0, 1.38, m, 120.0, 550.0, c);
            assert!(
                (0.0..1.0).contains(&r),
                "{m} at {k} deg: R = {r}, but the metal absorbs"
            );
        }
        // A half-wave film is absent at normal incidence, on a metal too.
        let half = 550.0 / (2.0 * 1.38);
        let (got, want) = (
            your_film_on_metal_reflectance(1.0, 1.38, m, half, 550.0, 1.0),
            bare_conductor(1.0, m, 1.0),
        );
        assert!(
            (got - want).abs() <= 1e-12,
            "{m}, half-wave film: {got}, expected {want}"
        );
    }
    // A real substrate index is the library's dielectric film, total reflection included.
    for case in sweep(2_000, 0x3e7a) {
        let Film {
            n1,
            n2,
            n3,
            thickness_nm,
        } = case.film;
        let c = case.theta1.cos();
        // Where the plain Airy sum keeps its digits (see "Where the plain sum loses digits").
        if c < 1e-3 || cos_theta(n1, c, n2).norm() < 1e-3 || thickness_nm > 5_000.0 {
            continue;
        }
        let got = your_film_on_metal_reflectance(
            n1,
            n2,
            Complex64::new(n3, 0.0),
            thickness_nm,
            case.wavelength_nm,
            c,
        );
        let want = case.film.response_cos(case.wavelength_nm, c).reflectance();
        assert!(
            (got - want).abs() <= 1e-9,
            "{case:?}: {got}, expected {want}"
        );
    }
}

/// Exercise 4 of *Thin-film interference*: for the 300 nm soap film (1.33) in air at
/// 550 nm, the hemispherical means weighted by cos θ, `2 ∫ R(θ) cos θ sin θ dθ` over
/// `[0, π/2]`, of the s-only reflectance `R_s` and of the true unpolarised `R`.
const YOUR_MEANS_S_ONLY_AND_TRUE: Option<(f64, f64)> = None;

#[test]
#[ignore = "exercise 4 of Thin-film interference: set YOUR_MEANS_S_ONLY_AND_TRUE, then run it"]
fn exercise_4_s_only_on_average() {
    let film = Film::new(1.0, 1.33, 1.0, 300.0);
    let steps = 20_000;
    let h = FRAC_PI_2 / f64::from(steps);
    let (mut s_only, mut truth) = (0.0, 0.0);
    for k in 0..steps {
        let theta = (f64::from(k) + 0.5) * h;
        let r = film.response(550.0, theta);
        let w = 2.0 * theta.cos() * theta.sin() * h;
        s_only += w * r.reflectance_s;
        truth += w * r.reflectance();
    }
    let yours = YOUR_MEANS_S_ONLY_AND_TRUE.expect("exercise 4: set YOUR_MEANS_S_ONLY_AND_TRUE");
    assert!(
        (yours.0 / s_only - 1.0).abs() <= 0.01 && (yours.1 / truth - 1.0).abs() <= 0.01,
        "{yours:?}, but the means are ({s_only}, {truth})"
    );
}

/// Exercise 5 of *Thin-film interference*: a film and a wavelength for which the rule
/// "dark when 2 n2 d = m λ" predicts darkness at normal incidence (m a whole number, at
/// least 1), but the reflectance there is a maximum over the thickness.
fn your_counterexample() -> (Film, f64) {
    unimplemented!("exercise 5 of Thin-film interference: a film where the pi rule is wrong")
}

#[test]
#[ignore = "exercise 5 of Thin-film interference: fill in your_counterexample, then run it"]
fn exercise_5_the_pi_rule() {
    let (film, wavelength) = your_counterexample();
    let m = 2.0 * film.n2 * film.thickness_nm / wavelength;
    assert!(
        m >= 0.5 && (m - m.round()).abs() <= 1e-9,
        "2 n2 d / λ = {m}: not a whole number"
    );
    let r = |d: f64| {
        Film {
            thickness_nm: d,
            ..film
        }
        .response(wavelength, 0.0)
        .reflectance()
    };
    let (at, quarter) = (r(film.thickness_nm), wavelength / (4.0 * film.n2));
    for shift in [0.1 * quarter, 0.5 * quarter, quarter] {
        assert!(
            at > r(film.thickness_nm + shift) && at > r(film.thickness_nm - shift),
            "R = {at} at the rule's dark thickness is not a maximum"
        );
    }
}

// ---------------------------------------------------------------------------------------
// Accuracy against exact arithmetic (data/corpus/thinfilm.txt, tools/exact).

/// At a subnormal `cos θ1` the transmittance used to be `(Re(n3 cos θ3)/(n1 cos θ1)) |t|²`
/// = ∞ · 0 = NaN; the exact answer (the corpus's, mpmath at 256 bits) is a few subnormals,
/// and the ratio taken last gives 0, within one unit of the scale 1.
#[test]
fn transmittance_at_a_subnormal_cosine_is_not_nan() {
    let root = crate::support::root();
    let corpus = raylemma::check::accuracy::corpus::load(&root.join("data/corpus/thinfilm.txt"))
        .expect("the corpus reads");
    let question = "film 1.0 1.38 1.52 100.0 550.0 5e-324";
    let case = corpus
        .cases
        .iter()
        .find(|c| c.question == question)
        .expect("the case is in the corpus");
    let exact = case.exact.as_ref().expect("an answer");
    let r = Film::new(1.0, 1.38, 1.52, 100.0).response_cos(550.0, 5e-324);
    let got = [
        r.reflectance_s,
        r.reflectance_p,
        r.transmittance_s,
        r.transmittance_p,
    ];
    for (g, e) in got.iter().zip(exact) {
        assert!(
            (g - e.double).abs() <= f64::EPSILON,
            "{got:?}, exact {}",
            e.text
        );
    }
}
