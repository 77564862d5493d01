//! Uniformly sampling the unit sphere and hemisphere. Chapter: *Uniform sphere and
//! hemisphere* (`chapters/sampling/sphere.md`).
//!
//! Three ways to draw a uniformly distributed direction (pdf `1 / (4 pi)` per steradian):
//! the inverse CDF in `(z = cos theta, phi)`, a normalised Gaussian vector, and rejection
//! from the cube. A hemisphere sample is a sphere sample flipped into the normal's side
//! (pdf `1 / (2 pi)`).
//!
//! Written once for both precisions (see [`crate::precision`]): `Float`, `V2`, `V3` are
//! `f64`, `DVec2`, `DVec3` in `raylemma::sampling::sphere` and `f32`, `Vec2`, `Vec3` in its
//! twin `raylemma::single::sampling::sphere`.

use rand::RngExt as _;

use super::precision::{Float, V2, V3, consts};
use crate::rng::Rng;

/// Density of a uniform direction on the sphere, per steradian.
pub const SPHERE_PDF: Float = 1.0 / (4.0 * consts::PI);
/// Density of a uniform direction on a hemisphere, per steradian.
pub(crate) const HEMISPHERE_PDF: Float = 1.0 / (2.0 * consts::PI);

// ANCHOR: inverse_cdf
/// Inverse-CDF sampling: `z = cos(theta) = 1 - 2 u1`, `phi = 2 pi u2`.
///
/// The source notes write `sqrt(1 - z^2)` for the radius of the circle at height `z`; near the
/// poles that subtracts two nearly equal numbers. Since `1 - (1 - 2u)^2 = 4 u (1 - u)`,
/// the radius is computed as `2 sqrt(u (1 - u))`, accurate everywhere.
pub fn sphere_inverse_cdf(u: V2) -> V3 {
    let z = 1.0 - 2.0 * u.x;
    let r = 2.0 * (u.x * (1.0 - u.x)).max(0.0).sqrt();
    let phi = u.y * consts::TAU;
    V3::new(r * phi.cos(), r * phi.sin(), z)
}
// ANCHOR_END: inverse_cdf

// ANCHOR: normalize
/// `v / |v|`, robust for tiny vectors: `v` is first scaled by its largest component
/// (exact for powers of two, and never underflowing), so a vector as short as `1e-300`
/// still normalises correctly. Returns `None` for a zero or non-finite vector.
pub fn normalize_robust(v: V3) -> Option<V3> {
    // `is_finite` first: glam's `max_element` drops a NaN in all but the last
    // component, so `m` alone would let `(NaN, 1, 0)` through.
    let m = v.abs().max_element();
    if !(v.is_finite() && m > 0.0) {
        return None;
    }
    let s = v / m;
    Some(s / s.length())
}
// ANCHOR_END: normalize

/// The inverse of [`sphere_inverse_cdf`]: `u1 = (1 - z) / 2`, `u2 = phi / (2 pi)`.
pub fn sphere_inverse_cdf_invert(w: V3) -> V2 {
    let phi = w.y.atan2(w.x);
    let phi = if phi < 0.0 { phi + consts::TAU } else { phi };
    V2::new((1.0 - w.z) / 2.0, phi / consts::TAU)
}

/// A uniform direction drawn with `rng`: [`sphere_inverse_cdf`] of two uniform numbers. The
/// project's one way to draw a random direction (checks, tests and timing inputs use it).
pub fn sphere_uniform(rng: &mut Rng) -> V3 {
    sphere_inverse_cdf(V2::new(rng.random(), rng.random()))
}

// ANCHOR: gaussian
/// Two independent standard normal numbers from two uniforms (Box-Muller). `1 - u1` is
/// in `(0, 1]`, so the logarithm is finite.
pub fn box_muller(u: V2) -> (Float, Float) {
    let r = (-2.0 * (1.0 - u.x).ln()).sqrt();
    let phi = u.y * consts::TAU;
    (r * phi.cos(), r * phi.sin())
}

/// A normalised vector of three standard normal numbers: uniform on the sphere because
/// the joint Gaussian density depends only on `|v|`. A zero vector (probability zero, but
/// representable) is redrawn.
pub fn sphere_gaussian(rng: &mut Rng) -> V3 {
    loop {
        let (x, y) = box_muller(V2::new(rng.random(), rng.random()));
        let (z, _) = box_muller(V2::new(rng.random(), rng.random()));
        if let Some(w) = normalize_robust(V3::new(x, y, z)) {
            return w;
        }
    }
}
// ANCHOR_END: gaussian

// ANCHOR: rejection
// EXERCISE sampling/sphere sphere_rejection: a uniform direction by rejection from the cube, with the number of draws it took
/// Rejection: draw `v` uniformly in the cube `[-1, 1]^3` until it lies in the unit ball
/// (and is not zero), then normalise. Returns the direction and the number of draws; the
/// acceptance probability is the ball's share of the cube, `(4 pi / 3) / 8 = pi / 6`.
pub fn sphere_rejection(rng: &mut Rng) -> (V3, u32) {
    let mut tries = 0;
    loop {
        tries += 1;
        let mut coordinate = || -1.0 + 2.0 * rng.random::<Float>(); // uniform in [-1, 1)
        let v = V3::new(coordinate(), coordinate(), coordinate());
        if v.length_squared() <= 1.0
            && let Some(w) = normalize_robust(v)
        {
            return (w, tries);
        }
    }
}
// END EXERCISE
// ANCHOR_END: rejection

// ANCHOR: hemisphere
// EXERCISE sampling/sphere hemisphere_flip: a uniform direction on the hemisphere around n: a sphere sample flipped to n's side
/// A uniform direction on the hemisphere around `n`: a sphere sample flipped to `n`'s
/// side. Flipping maps the sphere two-to-one onto the hemisphere, doubling the density to
/// `1 / (2 pi)`.
pub fn hemisphere_flip(w: V3, n: V3) -> V3 {
    if w.dot(n) < 0.0 { -w } else { w }
}
// END EXERCISE
// ANCHOR_END: hemisphere

/// The uniform sphere density (constant).
pub fn sphere_pdf(_w: V3) -> Float {
    SPHERE_PDF
}

/// The uniform hemisphere density around `n`: `1 / (2 pi)` where `w . n >= 0`, else 0.
pub fn hemisphere_pdf(w: V3, n: V3) -> Float {
    if w.dot(n) >= 0.0 { HEMISPHERE_PDF } else { 0.0 }
}
