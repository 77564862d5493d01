//! Twins and alternatives of `intersect_stable` (`f64`).

use crate::geometry::sphere::nearest_root_above;
use crate::geometry::{Ray, Sphere};

pub fn t_greater_than_zero(ray: &Ray, sphere: &Sphere, _t_min: f64) -> Option<f64> {
    explicit_sign(ray, sphere, 0.0)
}

pub fn ignoring_t_min(ray: &Ray, sphere: &Sphere, _t_min: f64) -> Option<f64> {
    explicit_sign(ray, sphere, f64::NEG_INFINITY)
}

/// `c = f.f - r`: the correct routine on the sphere of radius `sqrt(r)`, which it squares.
pub fn radius_not_squared(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
    explicit_sign(
        ray,
        &Sphere::new(sphere.center, sphere.radius.sqrt()),
        t_min,
    )
}

/// `f = C - O`: the correct routine from the origin `2C - O`, whose `O - C` is `C - O`.
pub fn centre_minus_origin(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
    let mirrored = Ray::new(2.0 * sphere.center - ray.origin, ray.dir);
    explicit_sign(&mirrored, sphere, t_min)
}

pub fn explicit_sign(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
    let f = ray.origin - sphere.center;
    let a = ray.dir.length_squared();
    let b = -ray.dir.dot(f);
    let r2 = sphere.radius.powi(2);
    let closest = f + (b / a) * ray.dir;
    let delta = r2 - closest.length_squared();
    if delta < 0.0 || delta.is_nan() {
        return None;
    }
    let root = (a * delta).sqrt();
    let q = if b < 0.0 { b - root } else { b + root };
    let c = f.length_squared() - r2;
    let (by_vieta, by_q) = (c / q, q / a);
    let near = if by_vieta < by_q { by_vieta } else { by_q };
    let far = if by_vieta < by_q { by_q } else { by_vieta };
    if near > t_min {
        Some(near)
    } else if far > t_min {
        Some(far)
    } else {
        None
    }
}

pub fn min_max(ray: &Ray, sphere: &Sphere, t_min: f64) -> Option<f64> {
    let f = ray.origin - sphere.center;
    let a = ray.dir.dot(ray.dir);
    let half_b = ray.dir.dot(f);
    let r2 = sphere.radius.powi(2);
    let l = f - ray.dir * (half_b / a);
    let delta = r2 - l.length_squared();
    if delta < 0.0 || delta.is_nan() {
        return None;
    }
    let q = -(half_b + (a * delta).sqrt().copysign(half_b));
    let by_q = q / a;
    let by_vieta = (f.dot(f) - r2) / q;
    nearest_root_above(by_q.min(by_vieta), by_q.max(by_vieta), t_min)
}
