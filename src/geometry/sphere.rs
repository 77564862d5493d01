//! Ray-sphere intersection, two ways. Chapter: *Ray-sphere intersection*
//! (`chapters/geometry/sphere.md`).
//!
//! Substituting the ray `P(t) = O + tD` into the sphere `|P - C|^2 = r^2` gives, with
//! `f = O - C`, the quadratic `(D.D) t^2 + 2 (D.f) t + (f.f - r^2) = 0`.
//!
//! * [`intersect_textbook`] solves it with the school formula, as the source notes do.
//! * [`intersect_stable`] is the rewrite of Haines, Günther and Akenine-Möller
//!   (*Ray Tracing Gems*, 2019, ch. 7), which avoids both cancellations of the school
//!   formula: the discriminant from the distance of the centre to the ray, and the
//!   smaller root from Vieta's formula instead of a difference of nearly equal numbers
//!   (which gains relative accuracy only where `c` itself is exact: `c = f.f - r^2`
//!   cancels near the surface too).
//!
//! Both return the smallest root strictly greater than the caller's `t_min`, or `None`.
//! Neither ever returns NaN: a NaN discriminant or root counts as a miss.
//!
//! Written once for both precisions (see [`crate::precision`]): `Float` and `V3` are
//! `f64` and `DVec3` in `raylemma::geometry::sphere`, `f32` and `Vec3` in its twin
//! `raylemma::single::geometry::sphere`.

use super::Ray;
use super::precision::{Float, V3};

/// A sphere with centre `center` and radius `radius` (> 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// The centre `C`.
    pub center: V3,
    /// The radius `r`.
    pub radius: Float,
}

impl Sphere {
    /// A sphere of centre `center` and radius `radius`.
    pub fn new(center: V3, radius: Float) -> Self {
        Self { center, radius }
    }
}

// ANCHOR: textbook
/// The source notes' quadratic, solved by the school formula.
///
/// With `f = O - C`, `a = D.D`, `b = D.f` (half the linear coefficient) and
/// `c = f.f - r^2`, the roots are `t = (-b -+ sqrt(b^2 - a c)) / a`.
/// The ray hits iff the discriminant `b^2 - a c >= 0`.
pub fn intersect_textbook(ray: &Ray, sphere: &Sphere, t_min: Float) -> Option<Float> {
    let f = ray.origin - sphere.center;
    let a = ray.dir.dot(ray.dir);
    let b = ray.dir.dot(f);
    let c = f.dot(f) - sphere.radius * sphere.radius;
    let discriminant = b * b - a * c;
    if discriminant.is_nan() || discriminant < 0.0 {
        return None; // a miss (or a NaN discriminant)
    }
    let root = discriminant.sqrt();
    let t_near = (-b - root) / a;
    let t_far = (-b + root) / a;
    nearest_root_above(t_near, t_far, t_min)
}
// ANCHOR_END: textbook

// ANCHOR: stable
// EXERCISE geometry/sphere intersect_stable: the first hit of a ray with a sphere beyond t_min, the quadratic solved without cancellation
/// The numerically stable form (*Ray Tracing Gems*, ch. 7).
///
/// With `f = O - C`, `a = D.D`, `b' = -D.f` and `c = f.f - r^2`:
/// * the point of the ray's line closest to the centre is `C + l` with
///   `l = f + (b'/a) D`, so `a (r^2 - l.l) = b'^2 - a c` is the discriminant, computed
///   from a squared *distance* instead of a difference of two huge squares;
/// * `q = b' + sign(b') sqrt(a (r^2 - l.l))` adds two numbers of the same sign, and the
///   roots are `t = c / q` and `t = q / a` (their product is `c / a`, Vieta).
pub fn intersect_stable(ray: &Ray, sphere: &Sphere, t_min: Float) -> Option<Float> {
    let (a, f) = (ray.dir.dot(ray.dir), ray.origin - sphere.center);
    let b = -f.dot(ray.dir);
    let r2 = sphere.radius * sphere.radius;
    let l = f + ray.dir * (b / a);
    let delta = r2 - l.dot(l);
    if delta.is_nan() || delta < 0.0 {
        return None; // the line passes farther than r from the centre (or NaN)
    }
    let c = f.dot(f) - r2;
    let q = b + (a * delta).sqrt().copysign(b);
    let (t0, t1) = (c / q, q / a);
    let (near, far) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    nearest_root_above(near, far, t_min)
}
// END EXERCISE
// ANCHOR_END: stable

// ANCHOR: nearest_root
/// The first intersection along the ray: the smaller root if it lies beyond `t_min`,
/// else the larger one, else none. NaN roots fail every comparison and are skipped.
pub fn nearest_root_above(t_near: Float, t_far: Float, t_min: Float) -> Option<Float> {
    if t_near > t_min {
        Some(t_near)
    } else if t_far > t_min {
        Some(t_far)
    } else {
        None
    }
}
// ANCHOR_END: nearest_root
