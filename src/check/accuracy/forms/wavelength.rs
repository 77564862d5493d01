//! The forms answering `data/corpus/wavelength.txt`: [`crate::spectral::wavelength`], the
//! hero wavelengths and the visible-range importance density.

use crate::check::accuracy::{Answer, Expect, Form, Precision};
use crate::spectral::wavelength::{
    N, VISIBLE_A, VISIBLE_C, hero_uniform, sample_uniform, sample_visible_pdf, visible_cdf,
    visible_pdf, wrap01,
};
use crate::spectral::{LAMBDA_MAX, LAMBDA_MIN};

fn hero(a: &[f64]) -> Answer {
    Some(hero_uniform(a[0]).lambda.to_vec())
}

/// The rotation as the crate first wrote it: `wrap01` of the rounded sum `u + j/N`, which
/// sends a sum just below 1 that rounds to 1.0 to 0 (830 nm becomes 360 nm).
fn hero_textbook(a: &[f64]) -> Answer {
    let lanes: [f64; N] =
        std::array::from_fn(|k| sample_uniform(wrap01(a[0] + k as f64 / N as f64)));
    Some(lanes.to_vec())
}

fn sample(a: &[f64]) -> Answer {
    let (l, p) = sample_visible_pdf(a[0]);
    Some(vec![l, p])
}

/// The inverse CDF as the density's derivation writes it: `λ = c + atanh(t) / a` with
/// `f64::atanh`, and the density from `cosh` at that `λ` ([`visible_pdf`]).
fn sample_textbook(a: &[f64]) -> Answer {
    let lo = (VISIBLE_A * (LAMBDA_MIN - VISIBLE_C)).tanh();
    let hi = (VISIBLE_A * (LAMBDA_MAX - VISIBLE_C)).tanh();
    let t = lo + a[0] * (hi - lo);
    let nm = (VISIBLE_C + t.atanh() / VISIBLE_A).clamp(LAMBDA_MIN, LAMBDA_MAX);
    Some(vec![nm, visible_pdf(nm)])
}

fn pdf(a: &[f64]) -> Answer {
    Some(vec![visible_pdf(a[0])])
}

fn cdf(a: &[f64]) -> Answer {
    Some(vec![visible_cdf(a[0])])
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::stable;
    vec![
        f("hero_uniform", hero),
        f("hero_uniform", hero_textbook).textbook(),
        f("visible_sample", sample),
        Form::new(
            "visible_sample",
            "textbook",
            Precision::Double,
            Expect::Within,
            sample_textbook,
        ),
        f("visible_pdf", pdf),
        f("visible_cdf", cdf),
    ]
}
