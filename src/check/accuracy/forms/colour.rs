//! The forms answering `data/corpus/colour.txt`: Planck's law
//! ([`crate::spectral::spectrum::planck`]), the analytic colour-matching functions
//! ([`crate::spectral::cie::cmf_fit`]) and XYZ to linear sRGB
//! ([`crate::spectral::cie::xyz_to_linear_srgb`]).

use super::{out3, v3};
use crate::check::accuracy::{Answer, Expect, Form, Precision};
use crate::spectral::cie::{cmf_fit, xyz_to_linear_srgb};
use crate::spectral::spectrum::{BOLTZMANN_K, LIGHT_C, PLANCK_H, planck};

fn planck_form(a: &[f64]) -> Answer {
    Some(vec![planck(a[0], a[1])])
}

/// Planck's law with `e^x − 1` written out instead of `exp_m1`, and the quotient by a huge
/// `e^x` taken directly (the crate's before the corpus: 0 once `e^x` overflows, at
/// `x > 709.78`, though the radiance is still a normal double up to `x ≈ 1490`).
fn planck_textbook(a: &[f64]) -> Answer {
    let (nm, temperature) = (a[0], a[1]);
    if !(nm > 0.0 && temperature > 0.0) {
        return Some(vec![0.0]);
    }
    let metres = nm * 1e-9;
    let exponent = PLANCK_H * LIGHT_C / (metres * BOLTZMANN_K * temperature);
    let numerator = 2.0 * PLANCK_H * LIGHT_C * LIGHT_C / metres.powi(5);
    Some(vec![numerator / (exponent.exp() - 1.0) * 1e-9])
}

/// The same with `exp_m1`, as the crate had it: right in the red, 0 past `e^x`'s overflow.
fn planck_expm1_only(a: &[f64]) -> Answer {
    let (nm, temperature) = (a[0], a[1]);
    if !(nm > 0.0 && temperature > 0.0) {
        return Some(vec![0.0]);
    }
    let metres = nm * 1e-9;
    let exponent = PLANCK_H * LIGHT_C / (metres * BOLTZMANN_K * temperature);
    let numerator = 2.0 * PLANCK_H * LIGHT_C * LIGHT_C / metres.powi(5);
    Some(vec![numerator / exponent.exp_m1() * 1e-9])
}

fn fit(a: &[f64]) -> Answer {
    let c = cmf_fit(a[0]);
    Some(vec![c.x, c.y, c.z])
}

fn to_srgb(a: &[f64]) -> Answer {
    out3(xyz_to_linear_srgb(v3(a)))
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::stable;
    vec![
        f("planck", planck_form),
        f("planck", planck_textbook).textbook(),
        Form::new(
            "planck",
            "exp_m1 only",
            Precision::Double,
            Expect::Exceeds,
            planck_expm1_only,
        ),
        f("cmf_fit", fit),
        f("xyz_to_srgb", to_srgb),
    ]
}
