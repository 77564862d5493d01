//! Cosine-weighted hemisphere sampling. Chapter: *Cosine-weighted hemisphere*
//! (`chapters/sampling/cosine.md`).
//!
//! Density `p(w) = cos(theta) / pi` on the hemisphere `z >= 0`. Three constructions, shown
//! to be the same distribution: the source's inverse CDF in angles, its Cartesian form, and
//! Malley's method (lift a uniform disc sample onto the hemisphere), here with the
//! concentric disc map.
//!
//! Written once for both precisions (see [`crate::precision`]): `Float`, `V2`, `V3` are
//! `f64`, `DVec2`, `DVec3` in `raylemma::sampling::cosine` and `f32`, `Vec2`, `Vec3` in its
//! twin `raylemma::single::sampling::cosine`.

use super::disc::disc_concentric;
use super::precision::{Float, V2, V3, consts};

// ANCHOR: seed_angles
/// The source's inverse CDF in angles: `F(theta) = (1 - cos 2 theta) / 2`, so
/// `theta = acos(1 - 2 u1) / 2`, and `phi = 2 pi u2`.
pub fn cosine_seed_angles(u: V2) -> V3 {
    let theta = (1.0 - 2.0 * u.x).acos() / 2.0;
    let phi = u.y * consts::TAU;
    V3::new(
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    )
}
// ANCHOR_END: seed_angles

// ANCHOR: seed_cartesian
/// The source's Cartesian form, from the half-angle identities: `sin theta = sqrt(u1)`,
/// `cos theta = sqrt(1 - u1)`. For `u1 < 1`, `z > 0`.
pub fn cosine_seed_cartesian(u: V2) -> V3 {
    let (s, phi) = (u.x.sqrt(), consts::TAU * u.y);
    V3::new(s * phi.cos(), s * phi.sin(), (1.0 - u.x).sqrt())
}
// ANCHOR_END: seed_cartesian

// ANCHOR: malley
// EXERCISE sampling/cosine cosine_malley: a cosine-weighted direction by Malley's method, accurate near the rim
/// Malley's method: a uniform point `(x, y)` of the disc lifted to `z = sqrt(1 - r^2)`.
///
/// Near the rim, `1 - x^2 - y^2` loses every digit (and can round below zero: NaN). The
/// concentric map's radius is `r = max(|2u1 - 1|, |2u2 - 1|)`, so the distance to the rim
/// is known exactly from `u`: `1 - r = 2 min(u1, 1 - u1, u2, 1 - u2)`, and
/// `z = sqrt((1 - r)(1 + r))` stays positive for every `u` inside the square.
pub fn cosine_malley(u: V2) -> V3 {
    let disc = disc_concentric(u);
    let to_rim = 2.0 * u.x.min(1.0 - u.x).min(u.y).min(1.0 - u.y);
    let z = (to_rim * (2.0 - to_rim)).max(0.0).sqrt();
    V3::new(disc.x, disc.y, z)
}
// END EXERCISE
// ANCHOR_END: malley

// EXERCISE sampling/cosine cosine_pdf: the cosine-weighted density per steradian
/// The cosine-weighted density `max(z, 0) / pi`, per steradian.
pub fn cosine_pdf(w: V3) -> Float {
    w.z.max(0.0) * consts::FRAC_1_PI
}
// END EXERCISE
