//! Rays, `P(t) = O + t D`.

use crate::real::Real;

/// A ray `P(t) = origin + t * dir` for real `t`.
///
/// `dir` need not be unit length: every intersection routine in raylemma accepts any
/// non-zero direction, and `t` is then measured in units of `|dir|`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<R: Real> {
    /// The origin `O`.
    pub origin: R::V3,
    /// The direction `D` (any non-zero length).
    pub dir: R::V3,
}

impl<R: Real> Ray<R> {
    /// A ray from `origin` along `dir`.
    pub fn new(origin: R::V3, dir: R::V3) -> Self {
        Self { origin, dir }
    }

    /// The point `O + t D`.
    pub fn at(&self, t: R) -> R::V3 {
        self.origin + self.dir * t
    }
}
