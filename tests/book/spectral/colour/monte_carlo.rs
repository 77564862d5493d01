//! Monte Carlo colour: what the source notes do.

use super::*;

/// Estimates of the Y of D65 (as `xyz` normalises it) by uniform wavelengths: each sample is S(λ) ȳ(λ) / (p(λ) ∫ȳ) with p = 1/(830 − 360). `seed_average` drops
/// the 1/p and the 1/∫ȳ and averages S(λ) ȳ(λ) as the spectral-rendering source notes do.
fn y_estimates(seed_average: bool, n: usize, seed: u64) -> Summary {
    let t = builtin("cie_illuminant_D65.csv");
    let mut r = rng::seeded(seed);
    let range = LAMBDA_MAX - LAMBDA_MIN;
    Summary::of((0..n).map(|_| {
        let nm = rng::uniform(&mut r, LAMBDA_MIN, LAMBDA_MAX);
        let f = t.eval(nm) * cmf(nm).y;
        if seed_average {
            f
        } else {
            f * range / y_integral()
        }
    }))
}

#[test]
fn uniform_wavelength_estimate_of_y_is_unbiased() {
    let t = builtin("cie_illuminant_D65.csv");
    let exact = xyz(|nm| t.eval(nm)).y;
    let s = y_estimates(false, 200_000, 11);
    let p = ttest::one_sample(&s, exact).unwrap().p_value;
    assert!(p >= test_alpha(), "mean {} vs {exact}: p = {p:.2e}", s.mean);
}

/// Planted bug (the source's "averaging their RGB contributions"): without the pdf and the
/// ∫ȳ normaliser the estimate is off by the factor ∫ȳ / (830 − 360) ≈ 0.23.
#[test]
fn uniform_wavelength_estimate_rejects_the_seed_average() {
    let t = builtin("cie_illuminant_D65.csv");
    let exact = xyz(|nm| t.eval(nm)).y;
    let s = y_estimates(true, 200_000, 12);
    let p = ttest::one_sample(&s, exact).unwrap().p_value;
    assert!(
        p < test_alpha(),
        "the seed's average passed: mean {} vs {exact}",
        s.mean
    );
    // The factor the chapter quotes, ∫ȳ / 470 ≈ 0.23.
    let factor = raylemma::spectral::cie::y_integral() / (830.0 - 360.0);
    assert!((factor - 0.23).abs() <= 0.005, "∫ȳ / 470 = {factor}");
}
