//! Light transport: Lambertian reflectance, Russian roulette, shadow-ray pdfs.
//! Chapters: *Light transport*.

pub mod lambert;
pub mod roulette;
pub mod shadow;
