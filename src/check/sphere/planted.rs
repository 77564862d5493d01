//! Planted bugs of the ray-sphere checker: intersection routines with the classic
//! mistakes, each of which [`super::intersection`] or [`super::far`] must reject on the
//! claim it breaks. Chapter: *Ray-sphere intersection* (`chapters/geometry/sphere.md`).
//!
//! The chapter's tests (`tests/book/geometry/sphere.rs`) use these same copies. The source
//! notes' own quadratic, [`crate::geometry::sphere::intersect_textbook`], is not here: it is
//! a derivation of the chapter, measured there, not a mistake made up for the checker. The
//! two half-fixes of it that the chapter's exercises discuss are:
//! [`discriminant_only_in_f64`] and [`textbook_normalised`].

use crate::geometry::sphere::{intersect_stable, nearest_root_above};
use crate::geometry::{Ray, Sphere};
use crate::single::geometry::{Ray as Ray32, Sphere as Sphere32};

/// The source notes' rule, "the smallest value that is still greater than 0": `t_min` is
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

/// The textbook form (`f32`) with only its discriminant `b^2 - a c` computed in `f64`, from
/// `b` and `c` already rounded to `f32`: the half-fix of the chapter's exercise on mixed
/// precision. The error is already in `b` and `c` (each about `eps_32 d^2` for `c`), so it
/// still fails [`super::far`] from `1e3` radii on.
pub fn discriminant_only_in_f64(ray: &Ray32, sphere: &Sphere32, t_min: f32) -> Option<f32> {
    let f = ray.origin - sphere.center;
    let a = ray.dir.dot(ray.dir);
    let b = ray.dir.dot(f);
    let c = f.dot(f) - sphere.radius * sphere.radius;
    let discriminant = f64::from(b) * f64::from(b) - f64::from(a) * f64::from(c);
    if discriminant.is_nan() || discriminant < 0.0 {
        return None;
    }
    let root = discriminant.sqrt() as f32;
    crate::single::geometry::sphere::nearest_root_above((-b - root) / a, (-b + root) / a, t_min)
}

/// The textbook form (`f32`) with the direction normalised first, so that `a = 1`, and `t`
/// divided by `|D|` at the end. The discriminant `b^2 - c` still subtracts two numbers of
/// about `d^2`, so it still fails [`super::far`].
pub fn textbook_normalised(ray: &Ray32, sphere: &Sphere32, t_min: f32) -> Option<f32> {
    let length = ray.dir.length();
    let unit = ray.dir / length;
    let f = ray.origin - sphere.center;
    let b = unit.dot(f);
    let c = f.dot(f) - sphere.radius * sphere.radius;
    let discriminant = b * b - c;
    if discriminant.is_nan() || discriminant < 0.0 {
        return None;
    }
    let root = discriminant.sqrt();
    crate::single::geometry::sphere::nearest_root_above(
        (-b - root) / length,
        (-b + root) / length,
        t_min,
    )
}
