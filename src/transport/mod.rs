//! Light transport: Lambertian reflectance, Russian roulette, shadow-ray pdfs, sampling a
//! rectangle by solid angle.
//! Chapters: *Light transport*.

pub mod lambert;
pub mod rectangle;
pub mod roulette;
pub mod shadow;
