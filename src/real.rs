//! One harness for both precisions: the trait that lets the ray-sphere checker (and the
//! chapter's figures and tests) run the same cases on `f32` and `f64` routines.
//! Chapter: *Ray-sphere intersection*.
//!
//! The routines themselves are plain functions of plain types, written once and compiled
//! twice (see [`crate::precision`]); only a harness that must *choose* a precision needs
//! a trait. [`Real`] ties each scalar to its `V3`, [`Ray`](Real::Ray) and
//! [`Sphere`](Real::Sphere), and to the conversions a checker needs: cases are built in
//! `f64` and rounded to the routine's precision, answers are widened (exactly) back to
//! `f64` and measured there.

use std::fmt::{Debug, Display};

use glam::{DVec3, Vec3};

use crate::{geometry, single};

/// A floating-point scalar with its 3-vector, ray and sphere: `f32` (the types of
/// [`crate::single::geometry`]) or `f64` (those of [`crate::geometry`]).
pub trait Real: Copy + PartialOrd + Debug + Display + Send + Sync + 'static {
    /// The 3-vector of this precision (`Vec3` for `f32`, `DVec3` for `f64`).
    type V3: Copy + Debug + PartialEq + Send + Sync;
    /// The ray of this precision.
    type Ray: Copy + Debug + Send + Sync;
    /// The sphere of this precision.
    type Sphere: Copy + Debug + Send + Sync;

    /// `"f32"` or `"f64"`, for reports.
    const NAME: &'static str;
    /// Zero.
    const ZERO: Self;
    /// The machine epsilon (`2^-23` or `2^-52`).
    const EPSILON: Self;

    /// Converts an `f64` literal or value (rounding to nearest for `f32`).
    fn lit(x: f64) -> Self;
    /// Widens to `f64` (exact for both precisions).
    fn wide(self) -> f64;
    /// Widens a vector to `f64` (exact).
    fn wide3(v: Self::V3) -> DVec3;
    /// Rounds an `f64` vector to this precision.
    fn narrow3(v: DVec3) -> Self::V3;

    /// The ray from `origin` along `dir`, rounded to this precision.
    fn ray(origin: DVec3, dir: DVec3) -> Self::Ray;
    /// The sphere of centre `center` and radius `radius`, rounded to this precision.
    fn sphere(center: DVec3, radius: f64) -> Self::Sphere;
    /// A ray's origin `O`.
    fn origin(ray: &Self::Ray) -> Self::V3;
    /// A ray's direction `D`.
    fn dir(ray: &Self::Ray) -> Self::V3;
    /// The point `O + t D` of a ray, in this precision.
    fn at(ray: &Self::Ray, t: Self) -> Self::V3;
    /// A sphere's centre `C`.
    fn center(sphere: &Self::Sphere) -> Self::V3;
    /// A sphere's radius `r`.
    fn radius(sphere: &Self::Sphere) -> Self;
}

impl Real for f32 {
    type V3 = Vec3;
    type Ray = single::geometry::Ray;
    type Sphere = single::geometry::Sphere;
    const NAME: &'static str = "f32";
    const ZERO: f32 = 0.0;
    const EPSILON: f32 = f32::EPSILON;
    fn lit(x: f64) -> f32 {
        x as f32
    }
    fn wide(self) -> f64 {
        f64::from(self)
    }
    fn wide3(v: Vec3) -> DVec3 {
        v.as_dvec3()
    }
    fn narrow3(v: DVec3) -> Vec3 {
        v.as_vec3()
    }
    fn ray(origin: DVec3, dir: DVec3) -> Self::Ray {
        Self::Ray::new(origin.as_vec3(), dir.as_vec3())
    }
    fn sphere(center: DVec3, radius: f64) -> Self::Sphere {
        Self::Sphere::new(center.as_vec3(), radius as f32)
    }
    fn origin(ray: &Self::Ray) -> Vec3 {
        ray.origin
    }
    fn dir(ray: &Self::Ray) -> Vec3 {
        ray.dir
    }
    fn at(ray: &Self::Ray, t: f32) -> Vec3 {
        ray.at(t)
    }
    fn center(sphere: &Self::Sphere) -> Vec3 {
        sphere.center
    }
    fn radius(sphere: &Self::Sphere) -> f32 {
        sphere.radius
    }
}

impl Real for f64 {
    type V3 = DVec3;
    type Ray = geometry::Ray;
    type Sphere = geometry::Sphere;
    const NAME: &'static str = "f64";
    const ZERO: f64 = 0.0;
    const EPSILON: f64 = f64::EPSILON;
    fn lit(x: f64) -> f64 {
        x
    }
    fn wide(self) -> f64 {
        self
    }
    fn wide3(v: DVec3) -> DVec3 {
        v
    }
    fn narrow3(v: DVec3) -> DVec3 {
        v
    }
    fn ray(origin: DVec3, dir: DVec3) -> Self::Ray {
        Self::Ray::new(origin, dir)
    }
    fn sphere(center: DVec3, radius: f64) -> Self::Sphere {
        Self::Sphere::new(center, radius)
    }
    fn origin(ray: &Self::Ray) -> DVec3 {
        ray.origin
    }
    fn dir(ray: &Self::Ray) -> DVec3 {
        ray.dir
    }
    fn at(ray: &Self::Ray, t: f64) -> DVec3 {
        ray.at(t)
    }
    fn center(sphere: &Self::Sphere) -> DVec3 {
        sphere.center
    }
    fn radius(sphere: &Self::Sphere) -> f64 {
        sphere.radius
    }
}
