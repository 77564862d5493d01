//! Spectral rendering: spectra and CIE colour, wavelength sampling (hero wavelengths),
//! importance-sampled emission spectra, display transforms and RGB-to-spectrum upsampling.
//! Chapters: *Spectral*.

pub mod cie;
pub mod display;
pub mod emission;
pub mod spectrum;
pub mod upsample;
pub mod wavelength;

/// The shortest wavelength the renderer carries, nm: the start of the CIE 1931 table.
pub const LAMBDA_MIN: f64 = 360.0;
/// The longest wavelength the renderer carries, nm: the end of the CIE 1931 table.
pub const LAMBDA_MAX: f64 = 830.0;
