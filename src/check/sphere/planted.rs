//! Planted bugs of the ray-sphere checker: intersection routines with the classic
//! mistakes, each of which [`super::intersection`] or [`super::far`] must reject on the
//! claim it breaks. Chapter: *Ray-sphere intersection* (`chapters/geometry/sphere.md`).
//!
//! The chapter's tests (`tests/book/geometry/sphere.rs`) use these one copies. The seed's
//! own quadratic, [`crate::geometry::sphere::intersect_textbook`], is not here: it is a
//! derivation of the chapter, measured there, not a mistake made up for the checker.

use crate::geometry::sphere::{intersect_stable, nearest_root_above};
use crate::geometry::{Ray, Sphere};
use crate::single::geometry::{Ray as Ray32, Sphere as Sphere32};

/// The seed's rule, "the smallest value that is still greater than 0": `t_min` is
/// ignored and 0 used instead. Fails `surface_origin` and `nearest_root`.
pub fn t_greater_than_zero(ray: &Ray, sphere: &Sphere, _t_min: f64) -> Option<f64> {
    intersect_stable(ray, sphere, 0.0)
}

/// Always the far root `(-b + sqrt(b^2 - ac)) / a`, the exit. Fails `hits` and
/// `nearest_root`.
pub fn always_far_root(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
    let (f, a) = (ray.origin - sphere.center, ray.dir.dot(ray.dir));
    let (b, c) = (ray.dir.dot(f), f.dot(f) - sphere.radius * sphere.radius);
    let disc = b * b - a * c;
    (disc >= 0.0)
        .then(|| (-b + disc.sqrt()) / a)
        .filter(|&t| t > t_min)
}

/// Every root counts, behind the origin too: `t_min = -infinity`. Fails `nearest_root`.
pub fn ignoring_t_min(ray: &Ray, sphere: &Sphere, _t_min: f64) -> Option<f64> {
    intersect_stable(ray, sphere, f64::NEG_INFINITY)
}

/// `a = D.D` replaced by 1: right only for normalised directions. Fails
/// `direction_scale` and `hits`.
pub fn assuming_unit_direction(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
    let f = ray.origin - sphere.center;
    let (b, c) = (ray.dir.dot(f), f.dot(f) - sphere.radius * sphere.radius);
    let disc = b * b - c;
    if disc < 0.0 {
        return None;
    }
    nearest_root_above(-b - disc.sqrt(), -b + disc.sqrt(), t_min)
}

/// Near misses counted as hits (a discriminant down to `-1 %` of `a r^2`), clamped to a
/// real root. Fails `misses`.
pub fn loose_discriminant(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
    let f = ray.origin - sphere.center;
    let (a, b, c) = (
        ray.dir.dot(ray.dir),
        ray.dir.dot(f),
        f.dot(f) - sphere.radius * sphere.radius,
    );
    let disc = b * b - a * c;
    if disc < -0.01 * a * sphere.radius * sphere.radius {
        return None;
    }
    let root = disc.max(0.0).sqrt();
    nearest_root_above((-b - root) / a, (-b + root) / a, t_min)
}

/// A NaN for every ray (`f32`). Fails `hits` and `misses`.
pub fn always_nan(_ray: &Ray32, _sphere: &Sphere32, _t_min: f32) -> Option<f32> {
    Some(f32::NAN)
}

/// No ray ever hits (`f32`). Fails the far-sphere checker.
pub fn never_hits(_ray: &Ray32, _sphere: &Sphere32, _t_min: f32) -> Option<f32> {
    None
}
