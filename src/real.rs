//! The two floating-point precisions the geometry is written for.
//!
//! Every geometric routine in raylemma is written once, generic over [`Real`], and
//! instantiated for `f32` (with [`glam::Vec3`]) and `f64` (with [`glam::DVec3`]). This
//! lets the book compare the *same* formula at both precisions, which is how the
//! ray-sphere chapter shows where the textbook quadratic breaks down.

use std::fmt::{Debug, Display};
use std::ops::{Add, Mul, Neg, Sub};

use glam::{DVec3, Vec3};

/// A floating-point scalar together with its 3-vector type.
pub trait Real: num_traits::Float + Debug + Display + Default + Send + Sync + 'static {
    /// The 3-vector of this precision (`Vec3` for `f32`, `DVec3` for `f64`).
    type V3: Copy
        + Debug
        + PartialEq
        + Send
        + Sync
        + Add<Output = Self::V3>
        + Sub<Output = Self::V3>
        + Neg<Output = Self::V3>
        + Mul<Self, Output = Self::V3>;

    /// `"f32"` or `"f64"`, for reports.
    const NAME: &'static str;

    /// Builds a vector from three scalars.
    fn v3(x: Self, y: Self, z: Self) -> Self::V3;
    /// Dot product.
    fn dot(a: Self::V3, b: Self::V3) -> Self;
    /// Converts an `f64` literal or value (rounding to nearest for `f32`).
    fn lit(x: f64) -> Self;
    /// Widens to `f64` (exact for both precisions).
    fn wide(self) -> f64;
    /// Widens a vector to `f64` (exact).
    fn wide3(v: Self::V3) -> DVec3;
    /// Rounds an `f64` vector to this precision.
    fn narrow3(v: DVec3) -> Self::V3;
}

impl Real for f32 {
    type V3 = Vec3;
    const NAME: &'static str = "f32";
    fn v3(x: f32, y: f32, z: f32) -> Vec3 {
        Vec3::new(x, y, z)
    }
    fn dot(a: Vec3, b: Vec3) -> f32 {
        a.dot(b)
    }
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
}

impl Real for f64 {
    type V3 = DVec3;
    const NAME: &'static str = "f64";
    fn v3(x: f64, y: f64, z: f64) -> DVec3 {
        DVec3::new(x, y, z)
    }
    fn dot(a: DVec3, b: DVec3) -> f64 {
        a.dot(b)
    }
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
}
