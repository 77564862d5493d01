//! The probes of the spectral chapters' exercises (see [`super`]).

use crate::spectral::wavelength::Wavelengths;

/// Probe inputs of hero wavelengths: seven points `u` in `[0, 1)`; the outputs are, for
/// each, the lanes, their densities and the hero's density.
pub fn heroes(f: fn(f64) -> Wavelengths) -> Vec<f64> {
    [0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 0.999]
        .into_iter()
        .flat_map(|u| {
            let w = f(u);
            w.lambda.into_iter().chain(w.pdf).chain([w.hero_pdf])
        })
        .collect()
}

/// Probe inputs of an encoding: a negative value, 0, both sides of the breakpoint and the
/// breakpoint itself, the grey card and 1; the outputs are `f`'s values.
pub fn encodings(f: fn(f64) -> f64) -> Vec<f64> {
    [-0.5, 0.0, 0.001, 0.003_130_8, 0.02, 0.1, 0.18, 0.5, 1.0]
        .into_iter()
        .map(f)
        .collect()
}

/// Probe inputs of a decoding: a negative value, 0, both sides of the breakpoint and the
/// breakpoint itself, code 188 and 1; the outputs are `f`'s values.
pub fn decodings(f: fn(f64) -> f64) -> Vec<f64> {
    [-0.5, 0.0, 0.002, 0.02, 0.040_45, 0.1, 0.25, 0.5, 0.735, 1.0]
        .into_iter()
        .map(f)
        .collect()
}
