//! Planted bugs of the warp checker: samplers with the classic mistakes, each paired with
//! the density it wrongly claims. Chapter: *Checking a sampler*
//! (`chapters/checking/warps.md`).
//!
//! The checker's own tests, the sampling, spectral and transport chapters' tests and the
//! power figure all use these one copies: every check of a sampler must reject each of
//! them.
//!
//! * the classic four, with the densities they claim ([`all`]): the power table's rows;
//! * wrong samplers of a correct pdf: samples outside the domain or NaN, a cosine sampler
//!   leaking samples just below the horizon, a concentric map
//!   with the wrong wedge angle, the visible-wavelength sampler with another range's
//!   constants, a linear density without its square root;
//! * wrong pdfs of a correct sampler: twice too large, negative, zero where samples land,
//!   the cosine without `1/pi`, a hemisphere at the sphere's density, a density along the
//!   wrong axis; an inverse that returns NaN;
//! * a [`Cone`] claiming the pdf of a narrower cone (a jump that cuts cells);
//! * the wrong conversions of a light's area pdf to solid angle ([`LIGHT_PDFS`]).

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use glam::{DVec2, DVec3};

use super::{Domain, SquareWarp, Warp, square_point};
use crate::rng::Rng;
use crate::sampling::cosine::{cosine_pdf, cosine_seed_cartesian};
use crate::sampling::disc::{disc_concentric, disc_pdf, disc_polar, disc_polar_invert};
use crate::sampling::frame::Frame;
use crate::sampling::sphere::{SPHERE_PDF, hemisphere_flip, sphere_inverse_cdf, sphere_pdf};
use crate::spectral::wavelength::{VISIBLE_A, VISIBLE_C};

// ANCHOR: planted
/// The polar map with `r = u1` instead of `sqrt(u1)`: the radial CDF `r^2` forgotten, so
/// the samples crowd the centre (density `1 / (2 pi r)` instead of `1 / pi`).
pub fn disc_r_equals_u(u: DVec2) -> DVec3 {
    disc_polar(DVec2::new(u.x * u.x, u.y))
}

/// `theta` uniform in `[0, pi]`: the `sin(theta)` of the solid-angle element forgotten,
/// so the samples crowd the poles.
pub fn sphere_theta_uniform(u: DVec2) -> DVec3 {
    let (theta, phi) = (PI * u.x, TAU * u.y);
    DVec3::new(
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    )
}

/// Samples of the lobe `cos^1.1` (exponent `n`: `z = u^(1/(n+1))`), which is close to but
/// not the cosine-weighted density.
pub fn cosine_power_lobe(u: DVec2) -> DVec3 {
    let z = (1.0 - u.x).powf(1.0 / 2.1);
    let r = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(r * (TAU * u.y).cos(), r * (TAU * u.y).sin(), z)
}

/// A uniform hemisphere sample (density `1 / (2 pi)`).
pub fn hemisphere_uniform(u: DVec2) -> DVec3 {
    hemisphere_flip(sphere_inverse_cdf(u), DVec3::Z)
}
// ANCHOR_END: planted

/// A planted sampler: a plain warp from the square and the pdf it claims.
pub type Planted = SquareWarp<fn(DVec2) -> DVec3, fn(DVec3) -> f64>;

fn planted(
    name: &str,
    domain: Domain,
    sample: fn(DVec2) -> DVec3,
    pdf: fn(DVec3) -> f64,
) -> Planted {
    SquareWarp {
        name: name.into(),
        domain,
        sample,
        pdf,
        invert: None,
    }
}

// ANCHOR: claims
/// Every planted bug, each with the density it wrongly claims: every sampler check must
/// reject all of them.
pub fn all() -> Vec<Planted> {
    vec![
        planted("disc, r = u", Domain::Disc, disc_r_equals_u, disc_pdf),
        planted(
            "sphere, theta uniform (missing sin theta)",
            Domain::Sphere,
            sphere_theta_uniform,
            sphere_pdf,
        ),
        planted(
            "cosine^1.1 lobe claimed as cosine",
            Domain::Sphere,
            cosine_power_lobe,
            cosine_pdf,
        ),
        planted(
            "uniform hemisphere claimed as cosine",
            Domain::Sphere,
            hemisphere_uniform,
            cosine_pdf,
        ),
    ]
}
// ANCHOR_END: claims

// ---------------------------------------------------------------------------------------
// Wrong samplers of a correct pdf.

/// The polar disc scaled by 1.01: samples outside the domain.
pub fn disc_outside(u: DVec2) -> DVec3 {
    disc_polar(u) * 1.01
}

// ANCHOR: leak
/// The Cartesian cosine sampler (`cosine_seed_cartesian`, `z = sqrt(1 - u1)`) with `z`
/// negated for `u1 > 0.9999`, as a sign slip in a frame might do: one sample in 10 000
/// leaks to just below the horizon (`-0.01 < z < 0`), inside the sphere's row of cells that
/// straddles it, where the cosine pdf it claims is 0. Chi-squared alone misses the few
/// dozen such samples among 400 000, and the Jacobian's points never reach `u1 > 0.999`.
pub fn cosine_leaking_below_horizon(u: DVec2) -> DVec3 {
    let w = cosine_seed_cartesian(u);
    if u.x > 0.9999 {
        DVec3::new(w.x, w.y, -w.z)
    } else {
        w
    }
}
// ANCHOR_END: leak

/// The polar disc with NaN samples for `u1 < 1e-3`.
pub fn disc_nan(u: DVec2) -> DVec3 {
    if u.x < 1e-3 {
        DVec3::NAN
    } else {
        disc_polar(u)
    }
}

/// The concentric map with `pi/2` instead of `pi/4` in the first wedge: it folds the disc
/// over itself.
pub fn concentric_wrong_wedge(u: DVec2) -> DVec3 {
    let a = 2.0 * u - DVec2::ONE;
    if a.x.abs() > a.y.abs() {
        let phi = FRAC_PI_2 * (a.y / a.x);
        DVec3::new(a.x * phi.cos(), a.x * phi.sin(), 0.0)
    } else {
        disc_concentric(u)
    }
}

/// The visible-wavelength sampler with the constants of another range: normalised over
/// 380-780 nm (points `(lambda, 0, 0)`), to be claimed with the visible pdf on
/// 360-830 nm (chapter *Wavelength sampling*).
pub fn visible_other_range(u: DVec2) -> DVec3 {
    let t = |l: f64| (VISIBLE_A * (l - VISIBLE_C)).tanh();
    let (t0, t1) = (t(380.0), t(780.0));
    DVec3::new(
        VISIBLE_C + (t0 + u.x * (t1 - t0)).atanh() / VISIBLE_A,
        0.0,
        0.0,
    )
}

/// `x = u1`, uniform on `[0, 1]` (points `(x, 0, 0)`): the square root of the linear
/// density `2x`'s sampler `x = sqrt(u1)` forgotten.
pub fn linear_without_sqrt(u: DVec2) -> DVec3 {
    DVec3::new(u.x, 0.0, 0.0)
}

// ---------------------------------------------------------------------------------------
// Wrong pdfs of a correct sampler, and a wrong inverse.

/// The disc's pdf twice too large: it integrates to 2.
pub fn disc_pdf_doubled(p: DVec3) -> f64 {
    2.0 * disc_pdf(p)
}

/// The disc's pdf, negative for `x > 0.9`.
pub fn disc_pdf_negative(p: DVec3) -> f64 {
    if p.x > 0.9 { -1.0 } else { disc_pdf(p) }
}

/// The pdf of the upper half disc (`y >= 0`), claimed for samples of the whole disc:
/// samples land where the pdf is zero.
pub fn disc_pdf_upper_half(p: DVec3) -> f64 {
    if p.y >= 0.0 { 2.0 * disc_pdf(p) } else { 0.0 }
}

/// The cosine-weighted pdf without its `1/pi`: `cos(theta)`, which integrates to `pi`.
pub fn cosine_pdf_without_1_over_pi(w: DVec3) -> f64 {
    w.z.max(0.0)
}

/// The hemisphere around `+z` claimed at the sphere's density `1/(4 pi)`: flipping without
/// doubling the pdf, which then integrates to 1/2.
pub fn hemisphere_pdf_not_doubled(w: DVec3) -> f64 {
    if w.z >= 0.0 { SPHERE_PDF } else { 0.0 }
}

/// The density `2y` on the unit square, claimed for samples of `2x`: the wrong axis.
pub fn square_linear_pdf_wrong_axis(p: DVec3) -> f64 {
    2.0 * p.y
}

/// The polar disc's inverse with its first coordinate lost to NaN (glam's `max_element`
/// would drop it and pass the round trip).
pub fn disc_polar_invert_nan(p: DVec3) -> DVec2 {
    DVec2::new(f64::NAN, disc_polar_invert(p).y)
}

// ---------------------------------------------------------------------------------------
// A jump that cuts cells.

/// Uniform directions in the cone of `cos_max` around the unit `axis`, claiming the pdf of
/// the cone of `claimed_cos_max`. With the two equal it is a correct sampler whose pdf
/// jumps at the cone's rim, across the checker's cells, as a light's silhouette does; a
/// cone wider than its claim (`cos_max < claimed_cos_max`) is a planted bug that puts
/// samples where the pdf is 0.
#[derive(Clone, Copy, Debug)]
pub struct Cone {
    /// The cone's axis (unit).
    pub axis: DVec3,
    /// `cos` of the half-angle of the cone sampled.
    pub cos_max: f64,
    /// `cos` of the half-angle of the cone whose pdf is claimed.
    pub claimed_cos_max: f64,
}

impl Warp for Cone {
    fn name(&self) -> String {
        if self.cos_max == self.claimed_cos_max {
            format!("uniform cone, cos_max = {}", self.cos_max)
        } else {
            format!(
                "cone of cos_max = {} with the pdf of cos_max = {}",
                self.cos_max, self.claimed_cos_max
            )
        }
    }
    fn domain(&self) -> Domain {
        Domain::Sphere
    }
    fn sample(&self, rng: &mut Rng) -> DVec3 {
        let u = square_point(rng);
        let z = 1.0 - u.x * (1.0 - self.cos_max);
        let r = (1.0 - z * z).max(0.0).sqrt();
        let local = DVec3::new(r * (TAU * u.y).cos(), r * (TAU * u.y).sin(), z);
        Frame::from_normal(self.axis).to_world(local)
    }
    fn pdf(&self, p: DVec3) -> f64 {
        if p.dot(self.axis) >= self.claimed_cos_max {
            1.0 / (TAU * (1.0 - self.claimed_cos_max))
        } else {
            0.0
        }
    }
}

// ---------------------------------------------------------------------------------------
// Lights: the wrong conversions of an area pdf to solid angle.

/// A conversion of a light sample's area pdf to a solid-angle pdf, from the area pdf, the
/// distance to the sample and the cosine at the light (chapter *Shadow-ray pdfs*; the
/// correct one is [`crate::transport::shadow::area_to_solid_angle`]).
pub type AreaToSolidAngle = fn(pdf_area: f64, dist: f64, cos_light: f64) -> f64;

/// The `r^2` forgotten: `p_A / |cos|`.
pub fn missing_r2(pdf_area: f64, _dist: f64, cos_light: f64) -> f64 {
    pdf_area / cos_light.abs()
}

/// The cosine forgotten: `p_A r^2`.
pub fn missing_cos(pdf_area: f64, dist: f64, _cos_light: f64) -> f64 {
    pdf_area * dist * dist
}

/// The seed's formula, `p_A r^2 / (n . r)`, without the absolute value: negative for a
/// light facing the point.
pub fn signed_cos(pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
    pdf_area * dist * dist / cos_light
}

/// The area pdf taken as 1 instead of `1 / area`: `r^2 / |cos|`.
pub fn unnormalised(_pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
    dist * dist / cos_light.abs()
}

/// The planted conversions of a light's area pdf, with their names: every test of a light's
/// solid-angle pdf must reject each of them.
pub const LIGHT_PDFS: [(&str, AreaToSolidAngle); 4] = [
    ("missing r^2", missing_r2),
    ("missing cosine", missing_cos),
    ("signed cosine", signed_cos),
    ("area pdf = 1", unnormalised),
];
