//! Geometry: rays and the shapes they hit. Chapter: *Geometry*.

pub mod parallelogram;
pub mod ray;
pub mod sphere;

pub use parallelogram::Parallelogram;
pub use ray::Ray;
pub use sphere::Sphere;
