//! # raylemma
//!
//! The derivations of a physically based, spectral path tracer, turned into code that is
//! checked numerically. Each module is one concept and one chapter of the book
//! (`chapters/`), and has one test file (`tests/`).
//!
//! * [`real`]: the two precisions the geometry is written for.
//! * [`geometry`]: rays and spheres (*Ray-sphere intersection*).
//! * [`check`]: the checkers a student runs on their own implementation.
//! * [`data`]: errors of data files (file, line, problem).
//! * [`output`]: the one writer of every file the library writes: atomic files, sets of
//!   files that land together or not at all, staged folders.
//! * [`rng`]: the seeded generator every test and figure uses.
//! * [`stats`]: chi-squared, Kolmogorov-Smirnov and t-tests, with Šidák correction.
//! * [`sampling`]: warps and tabulated distributions (*Sampling*).
//! * [`optics`]: reflection, refraction, Fresnel, specular deltas, dispersion, thin films.
//! * [`spectral`]: spectra, CIE colour, wavelength sampling, emission spectra, display,
//!   RGB-to-spectrum upsampling.
//! * [`transport`]: Lambertian reflectance, Russian roulette, shadow-ray pdfs.
//! * [`render`]: the reference renderer: scenes, the spectral path tracer, images, compare.
//! * [`figures`]: the code that draws the book's figures and tables.

pub mod check;
pub mod data;
pub mod figures;
pub mod geometry;
pub mod optics;
pub mod output;
pub mod plot;
pub mod real;
pub mod render;
pub mod rng;
pub mod sampling;
pub mod spectral;
pub mod stats;
pub mod transport;
