//! Twins and alternatives of `Sellmeier::index`.

use crate::optics::dispersion::Sellmeier;

pub fn lambda_not_squared(m: &Sellmeier, nm: f64) -> f64 {
    let um = nm / 1000.0;
    let sum: f64 = m.terms.iter().map(|&(b, c)| b * um / (um - c)).sum();
    (1.0 + sum).sqrt()
}

pub fn converted_once(m: &Sellmeier, nm: f64) -> f64 {
    let l2 = nm * nm / 1000.0;
    let sum: f64 = m.terms.iter().map(|&(b, c)| b * l2 / (l2 - c)).sum();
    (1.0 + sum).sqrt()
}

pub fn b_c_swapped(m: &Sellmeier, nm: f64) -> f64 {
    let l2 = (nm / 1000.0).powi(2);
    let sum: f64 = m.terms.iter().map(|&(b, c)| c * l2 / (l2 - b)).sum();
    (1.0 + sum).sqrt()
}

pub fn without_one(m: &Sellmeier, nm: f64) -> f64 {
    let l2 = (nm / 1000.0).powi(2);
    let sum: f64 = m.terms.iter().map(|&(b, c)| b * l2 / (l2 - c)).sum();
    sum.sqrt()
}

pub fn as_written(m: &Sellmeier, nm: f64) -> f64 {
    let um = nm / 1000.0;
    let l2 = um * um;
    let mut n2 = 1.0;
    for &(b, c) in &m.terms {
        n2 += b * l2 / (l2 - c);
    }
    n2.sqrt()
}

pub fn in_nanometres(m: &Sellmeier, nm: f64) -> f64 {
    let l2 = nm * nm;
    m.terms
        .iter()
        .fold(1.0, |n2, &(b, c)| n2 + b * l2 / (l2 - c * 1e6))
        .sqrt()
}
