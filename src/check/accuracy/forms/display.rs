//! The forms answering `data/corpus/display.txt`: [`crate::spectral::display`], the sRGB
//! transfer function and its inverse, the power law and the gamut fit.

use super::{out3, v3};
use crate::check::accuracy::{Answer, Form};
use crate::spectral::display::{fit_to_gamut, gamma_encode, srgb_decode, srgb_encode};

fn encode(a: &[f64]) -> Answer {
    Some(vec![srgb_encode(a[0])])
}

fn decode(a: &[f64]) -> Answer {
    Some(vec![srgb_decode(a[0])])
}

fn gamma(a: &[f64]) -> Answer {
    Some(vec![gamma_encode(a[0], a[1])])
}

fn fit(a: &[f64]) -> Answer {
    out3(fit_to_gamut(v3(a)))
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::stable;
    vec![
        f("srgb_encode", encode),
        f("srgb_decode", decode),
        f("gamma_encode", gamma),
        f("fit_to_gamut", fit),
    ]
}
