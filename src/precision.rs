//! The two floating-point precisions the derivations are written for.
//!
//! The geometry (`geometry::{ray, sphere}`) and the samplers and frames
//! (`sampling::{sphere, disc, cosine, frame}`) are written once, in plain Rust, with these
//! names:
//!
//! * `Float`: the scalar, `f64` or `f32`;
//! * `V2`, `V3`: its glam vectors, `DVec2`, `DVec3` or `Vec2`, `Vec3`;
//! * `consts`: its mathematical constants, `std::f64::consts` or `std::f32::consts`
//!   (so `consts::TAU` is `τ` rounded to the module's precision);
//! * `widen`: a `V3` converted to `DVec3`, exactly, for errors measured in `f64`.
//!
//! Each of those files begins with `use super::precision::{Float, V2, V3, consts};` (or
//! the names it needs): it
//! takes the names from its parent module, which brings one of the two modules below into
//! scope as `precision`. A literal such as `1.0` takes the type of `Float` from its
//! context, so no line of a derivation names a precision. The files are compiled twice:
//!
//! * with [`double`], at their usual paths: `crate::geometry`, `crate::sampling::sphere`,
//!   …, which the renderer and most of the book use;
//! * with [`single`], as the `f32` twins under [`crate::single`]:
//!   `crate::single::geometry`, `crate::single::sampling::sphere`, …, declared in
//!   `src/single.rs` with `#[path]` pointing at the same files.
//!
//! A dual file refers to another one relatively (`super::disc::disc_concentric`), so each
//! twin calls its own twin. The sphere checker compares the two precisions through the
//! trait [`crate::real::Real`].

/// Double precision: `f64`, `DVec2`, `DVec3`. The precision of `crate::geometry` and
/// `crate::sampling`.
pub mod double {
    /// The scalar.
    pub type Float = f64;
    pub use glam::{DVec2 as V2, DVec3 as V3};
    pub use std::f64::consts;

    /// `v` as a `DVec3`: the identity.
    pub(crate) fn widen(v: V3) -> glam::DVec3 {
        v
    }
}

/// Single precision: `f32`, `Vec2`, `Vec3`. The precision of the twins in
/// [`crate::single`].
pub mod single {
    /// The scalar.
    pub type Float = f32;
    pub use glam::{Vec2 as V2, Vec3 as V3};
    pub use std::f32::consts;

    /// `v` widened to a `DVec3` (exact: every `f32` is an `f64`).
    pub(crate) fn widen(v: V3) -> glam::DVec3 {
        v.as_dvec3()
    }
}
