//! Planted bugs of the Sellmeier checker. Chapter: *Dispersion*.

use crate::optics::dispersion::Sellmeier;

/// The wavelength squared in nm while `C` is in µm²: `n²` is about `1 + ΣB`, flat.
pub fn nanometres(m: &Sellmeier, nm: f64) -> f64 {
    let nm2 = nm * nm;
    (1.0 + m
        .terms
        .iter()
        .map(|&(b, c)| b * nm2 / (nm2 - c))
        .sum::<f64>())
    .sqrt()
}

/// Returns `n²`, forgetting the square root.
pub fn n_squared(m: &Sellmeier, nm: f64) -> f64 {
    let um2 = (nm / 1000.0) * (nm / 1000.0);
    1.0 + m
        .terms
        .iter()
        .map(|&(b, c)| b * um2 / (um2 - c))
        .sum::<f64>()
}
