//! The single-precision (`f32`) twins of the dual-precision derivations.
//!
//! The modules below are the source files of `crate::geometry::{ray, sphere}` and
//! `crate::sampling::{sphere, disc, cosine, frame, trig}`, compiled a second time: each parent
//! module here brings [`crate::precision::single`] into scope as `precision`, so inside
//! those files `Float` is `f32` and `V2`, `V3` are `Vec2`, `Vec3` (see
//! [`crate::precision`]). The book measures the same formulas in both precisions with
//! them, and a renderer written in `f32` can use them.
//!
//! `#[path = "geometry"]` on an inline module makes `src/geometry/` the directory its
//! `mod` declarations read from, so `pub mod ray;` below is `src/geometry/ray.rs`. Clippy's
//! `duplicate_mod` warns against loading a file twice, which is the point here; it is
//! expected, with its reason, on these two modules only.

/// `f32` rays and spheres: `Ray`, `Sphere`, `sphere::intersect_stable`, … Chapter:
/// *Ray-sphere intersection*.
#[path = "geometry"]
#[expect(
    clippy::duplicate_mod,
    reason = "the f32 twins: the files of crate::geometry, compiled with precision::single"
)]
pub mod geometry {
    use crate::precision::single as precision;

    pub mod ray; // src/geometry/ray.rs
    pub mod sphere; // src/geometry/sphere.rs

    pub use ray::Ray;
    pub use sphere::Sphere;
}

/// `f32` samplers and tangent frames. Chapters: *Sampling*.
#[path = "sampling"]
#[expect(
    clippy::duplicate_mod,
    reason = "the f32 twins: the files of crate::sampling, compiled with precision::single"
)]
pub mod sampling {
    use crate::precision::single as precision;

    pub mod cosine; // src/sampling/cosine.rs
    pub mod disc; // src/sampling/disc.rs
    pub mod frame; // src/sampling/frame.rs
    pub mod sphere; // src/sampling/sphere.rs
    pub mod trig; // src/sampling/trig.rs
}
