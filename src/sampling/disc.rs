//! Uniformly sampling the unit disc. Chapter: *The unit disc* (`chapters/sampling/disc.md`).
//!
//! Both maps are area-preserving warps from the unit square with pdf `1 / pi`; they differ
//! in how much they stretch the square's cells, which matters for stratified samples.
//!
//! Written once for both precisions (see [`crate::precision`]): `Float`, `V2`, `V3` are
//! `f64`, `DVec2`, `DVec3` in `raylemma::sampling::disc` and `f32`, `Vec2`, `Vec3` in its
//! twin `raylemma::single::sampling::disc`.

use glam::{DVec2, DVec3};

use super::precision::{Float, V2, V3, consts};

/// Density of a uniform point on the unit disc, per unit area.
pub(crate) const DISC_PDF: Float = 1.0 / consts::PI;

// ANCHOR: polar
// EXERCISE sampling/disc disc_polar: map the unit square to the disc with r = sqrt(u1), phi = 2 pi u2
/// The polar map: `r = sqrt(u1)` (the inverse of the radial CDF `r^2`), `phi = 2 pi u2`.
pub fn disc_polar(u: V2) -> V3 {
    let r = u.x.sqrt();
    let phi = consts::TAU * u.y;
    V3::new(r * phi.cos(), r * phi.sin(), 0.0)
}
// END EXERCISE
// ANCHOR_END: polar

// ANCHOR: concentric
// EXERCISE sampling/disc disc_concentric: Shirley and Chiu's concentric map from the unit square to the disc
/// Shirley and Chiu's concentric map (*A Low Distortion Map Between Disk and Square*,
/// JGT 1997): concentric squares of `[-1, 1]^2` go to concentric circles, each square's
/// wedge to a sector of equal angle. Written in the two-wedge form with negative radii
/// that Shirley posted in 2011 (crediting Dave Cline), as pbrt has it; with the second
/// wedge's angle written `pi/2 - psi` it is the same map as the paper's four regions.
/// With `a = 2u - 1`: if `|a.x| > |a.y|`, `r = a.x` and `phi = (pi/4) a.y / a.x`; otherwise
/// `r = a.y` and `phi = pi/2 - (pi/4) a.x / a.y`, whose cosine and sine are the sine and
/// cosine of `psi = (pi/4) a.x / a.y`. Either way the angle to take the sine and cosine of
/// lies in `[-pi/4, pi/4]`, where [`super::trig::sin_cos_quarter`] (a speed trick measured
/// to pay, kept beside the samplers) needs no range reduction.
pub fn disc_concentric(u: V2) -> V3 {
    let a = 2.0 * u - V2::ONE;
    if a == V2::ZERO {
        return V3::ZERO;
    }
    if a.y.abs() < a.x.abs() {
        let (sin, cos) = super::trig::sin_cos_quarter(consts::FRAC_PI_4 * (a.y / a.x));
        V3::new(a.x * cos, a.x * sin, 0.0)
    } else {
        let (sin, cos) = super::trig::sin_cos_quarter(consts::FRAC_PI_4 * (a.x / a.y));
        V3::new(a.y * sin, a.y * cos, 0.0)
    }
}
// END EXERCISE
// ANCHOR_END: concentric

/// The inverse of [`disc_polar`].
pub fn disc_polar_invert(p: V3) -> V2 {
    let phi = p.y.atan2(p.x);
    let phi = if phi < 0.0 { phi + consts::TAU } else { phi };
    V2::new(p.x * p.x + p.y * p.y, phi / consts::TAU)
}

/// The inverse of [`disc_concentric`], wedge by wedge.
pub fn disc_concentric_invert(p: V3) -> V2 {
    let radius = (p.x * p.x + p.y * p.y).sqrt();
    if radius == 0.0 {
        return V2::splat(0.5);
    }
    let a = if p.x.abs() >= p.y.abs() {
        let ax = radius.copysign(p.x);
        V2::new(ax, ax * (p.y / p.x).atan() / consts::FRAC_PI_4)
    } else {
        let ay = radius.copysign(p.y);
        V2::new(ay * (p.x / p.y).atan() / consts::FRAC_PI_4, ay)
    };
    (a + V2::ONE) / 2.0
}

/// The uniform disc density: `1 / pi` inside, 0 outside.
pub fn disc_pdf(p: V3) -> Float {
    if p.x * p.x + p.y * p.y <= 1.0 {
        DISC_PDF
    } else {
        0.0
    }
}

/// Anisotropy of a warp at `u`: the ratio of the larger to the smaller singular value of
/// its Jacobian (1 = cells keep their shape), by central differences.
///
/// A measurement of `f64` maps, in `f64` in both twins: its step `h = 1e-6` would leave
/// nothing but rounding in `f32`.
pub fn anisotropy(warp: impl Fn(DVec2) -> DVec3, u: DVec2) -> f64 {
    let h = 1e-6;
    let du = (warp(u + DVec2::new(h, 0.0)) - warp(u - DVec2::new(h, 0.0))) / (2.0 * h);
    let dv = (warp(u + DVec2::new(0.0, h)) - warp(u - DVec2::new(0.0, h))) / (2.0 * h);
    // Singular values of [du dv] from its Gram matrix [[a, b], [b, c]].
    let (a, b, c) = (du.length_squared(), du.dot(dv), dv.length_squared());
    let mean = (a + c) / 2.0;
    let spread = (((a - c) / 2.0).powi(2) + b * b).sqrt();
    ((mean + spread) / (mean - spread).max(f64::MIN_POSITIVE)).sqrt()
}
