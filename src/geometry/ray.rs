//! Rays, `P(t) = O + t D`. Chapter: *Ray-sphere intersection* (`chapters/geometry/sphere.md`).
//! Written once for both precisions (see [`crate::precision`]).

use super::precision::{Float, V3};

/// A ray `P(t) = origin + t * dir` for real `t`.
///
/// `dir` need not be unit length: every intersection routine in raylemma accepts any
/// non-zero direction, and `t` is then measured in units of `|dir|`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// The origin `O`.
    pub origin: V3,
    /// The direction `D` (any non-zero length).
    pub dir: V3,
}

impl Ray {
    /// A ray from `origin` along `dir`.
    pub fn new(origin: V3, dir: V3) -> Self {
        Self { origin, dir }
    }

    /// The point `O + t D`.
    pub fn at(&self, t: Float) -> V3 {
        self.origin + self.dir * t
    }
}
