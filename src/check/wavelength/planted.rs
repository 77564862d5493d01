//! Planted bugs of the hero-wavelength checker. Chapter: *Wavelength sampling and hero
//! wavelengths*.

use crate::spectral::wavelength::{N, Wavelengths};
use crate::spectral::{LAMBDA_MAX, LAMBDA_MIN};

/// Rotates without wrapping: lanes past 830 nm leave the range.
pub fn without_wrap(u: f64) -> Wavelengths {
    let range = LAMBDA_MAX - LAMBDA_MIN;
    Wavelengths {
        lambda: std::array::from_fn(|j| LAMBDA_MIN + (u + j as f64 / N as f64) * range),
        pdf: [1.0 / range; N],
        hero_pdf: 1.0 / range,
    }
}

/// Each lane weighted as if the N lanes shared one density: `1 / (N × 470)`.
pub fn pdf_shared(u: f64) -> Wavelengths {
    let range = LAMBDA_MAX - LAMBDA_MIN;
    let lambda = std::array::from_fn(|j| LAMBDA_MIN + ((u + j as f64 / N as f64) % 1.0) * range);
    Wavelengths {
        lambda,
        pdf: [1.0 / (N as f64 * range); N],
        hero_pdf: 1.0 / range,
    }
}
