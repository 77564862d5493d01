//! Geometry: rays and the shapes they hit. Chapter: *Geometry*.
//!
//! Written once for both precisions (see [`crate::precision`]): this is the `f64`
//! instantiation, and [`crate::single::geometry`] the `f32` twin of the same files.

use crate::precision::double as precision;

pub mod parallelogram;
pub mod ray;
pub mod sphere;

pub use parallelogram::Parallelogram;
pub use ray::Ray;
pub use sphere::Sphere;
