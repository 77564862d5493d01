//! Planted bugs of the warp checker: samplers with the classic mistakes, each paired with
//! the density it wrongly claims. Chapter: *Checking a sampler*
//! (`chapters/checking/warps.md`).
//!
//! The checker's own tests, the sampling chapters' tests and the calibration figures all
//! use these one copies: every check of a sampler must reject each of them.

use std::f64::consts::{PI, TAU};

use glam::{DVec2, DVec3};

use super::{Domain, SquareWarp};
use crate::sampling::cosine::cosine_pdf;
use crate::sampling::disc::{disc_pdf, disc_polar};
use crate::sampling::sphere::{hemisphere_flip, sphere_inverse_cdf, sphere_pdf};

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
