//! Sampling: warps from uniform random numbers to the distributions a path tracer needs.
//! Chapters: *Sampling*.
//!
//! `sphere`, `disc`, `cosine` and `frame` are written once for both precisions (see
//! [`crate::precision`]): these are the `f64` instantiations, and
//! [`crate::single::sampling`] holds the `f32` twins of the same files.

use crate::precision::double as precision;

pub mod cosine;
pub mod disc;
pub mod frame;
pub mod importance;
pub mod sphere;
pub mod tabulated;
pub mod trig;
