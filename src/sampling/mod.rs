//! Sampling: warps from uniform random numbers to the distributions a path tracer needs.
//! Chapters: *Sampling*.

pub mod cosine;
pub mod disc;
pub mod frame;
pub mod importance;
pub mod sphere;
pub mod tabulated;
