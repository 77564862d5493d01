//! # raylemma
//!
//! The derivations of a physically based, spectral path tracer, turned into code that is
//! checked numerically. Each module is one concept and one chapter of the book
//! (`chapters/`), and has one test file (`tests/`).
//!
//! * [`precision`]: the two precisions (`f64`, `f32`) the geometry, samplers and frames
//!   are written for; [`single`] holds their `f32` twins, and [`real`] the trait that lets
//!   one harness choose between them.
//! * [`geometry`]: rays and spheres (*Ray-sphere intersection*).
//! * [`check`]: the checkers a student runs on their own implementation.
//! * [`conformance`]: the tools for implementers of other renderers, beside the renderer:
//!   export to Mitsuba, pbrt and JSON, the conformance ladder, merging renders, comparing
//!   a candidate with a reference, the diagnosis of a disagreement.
//! * [`data`]: errors of data files (file, line, problem).
//! * [`exercise`]: coursework: the exercises marked in the source, the student edition
//!   made from them (`raylemma exercises DIR`) and its report card.
//! * [`image`]: a render's image (per-pixel means and variances) and its files: OpenEXR
//!   written and read, EXR headers checked, PNG encoded and decoded; below every module
//!   that reads or writes an image.
//! * [`numeric`]: small numerical helpers (`max_abs`, a maximum that keeps a NaN).
//! * [`output`]: the one writer of every file the library writes: atomic files, sets of
//!   files that land together or not at all, staged folders.
//! * [`rng`]: the seeded generator every test and figure uses.
//! * [`stats`]: chi-squared, Kolmogorov-Smirnov and t-tests, with Šidák correction.
//! * [`sampling`]: warps and tabulated distributions (*Sampling*).
//! * [`optics`]: reflection, refraction, Fresnel, specular deltas, dispersion, thin films.
//! * [`spectral`]: spectra, CIE colour, wavelength sampling, emission spectra, display,
//!   RGB-to-spectrum upsampling.
//! * [`transport`]: Lambertian reflectance, Russian roulette, shadow-ray pdfs.
//! * [`render`]: the reference renderer: scenes, the spectral path tracer, what a render writes.
//! * [`workload`]: the fixed inputs that the speed tables and the benches both time.
//!
//! The code that draws the book's figures is its own crate (`tools/figures/`), which this
//! library never depends on.

pub mod check;
pub mod conformance;
pub mod data;
pub mod exercise;
pub mod geometry;
pub mod image;
pub mod numeric;
pub mod optics;
pub use raylemma_output as output;
pub mod precision;
pub mod real;
pub mod render;
pub mod rng;
pub mod sampling;
pub mod single;
pub mod spectral;
pub mod stats;
pub mod transport;
pub mod workload;
