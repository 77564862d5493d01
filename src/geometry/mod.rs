//! Geometry: rays and the shapes they hit. Chapter: *Geometry*.

pub mod ray;
pub mod sphere;

pub use ray::Ray;
pub use sphere::Sphere;
