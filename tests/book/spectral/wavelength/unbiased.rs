//! Unbiasedness of the estimators, with their planted bugs.

use super::*;

/// Hero lanes, uniform, on D65 (statistical test 3). Planted bugs: lanes not wrapped
/// (`u + j/N` past 1 leaves the range) and lanes summed without the `1/N`.
#[test]
fn hero_uniform_is_unbiased() {
    let d = d65();
    let exact = sum(cie::xyz(|l| d.eval(l)));
    let n = 100_000;
    assert_unbiased(
        "hero uniform",
        &estimates(n, 1, hero_uniform, |l| d.eval(l)),
        exact,
    );
    let unwrapped = |u: f64| {
        let mut w = hero_uniform(u);
        w.lambda = std::array::from_fn(|j| sample_uniform(u + j as f64 / N as f64));
        w
    };
    assert_rejected(
        "not wrapped",
        &estimates(n, 1, unwrapped, |l| d.eval(l)),
        exact,
    );
    let no_mean = |u: f64| {
        let mut w = hero_uniform(u);
        w.pdf = w.pdf.map(|p| p / N as f64);
        w
    };
    assert_rejected("no 1/N", &estimates(n, 1, no_mean, |l| d.eval(l)), exact);
}

/// Hero lanes from the visible pdf, rotated in sample space, on illuminant A (statistical
/// test 4). Planted bugs: the uniform weight `1/470` on importance-sampled lanes, and
/// Wilkie's balance weight `Σ_k p(λ_k)` on sample-space lanes (correct only for lanes
/// rotated in wavelength space).
#[test]
fn hero_visible_is_unbiased() {
    let a = builtin("cie_illuminant_A.csv");
    let exact = sum(cie::xyz(|l| a.eval(l)));
    let n = 100_000;
    assert_unbiased(
        "hero visible",
        &estimates(n, 2, hero_visible, |l| a.eval(l)),
        exact,
    );
    let uniform_weight = |u: f64| {
        let mut w = hero_visible(u);
        w.pdf = [1.0 / RANGE; N];
        w
    };
    assert_rejected(
        "uniform weight",
        &estimates(n, 2, uniform_weight, |l| a.eval(l)),
        exact,
    );
    let balance_weight = |u: f64| {
        let mut w = hero_visible(u);
        let mean = w.pdf.iter().sum::<f64>() / N as f64;
        w.pdf = [mean; N];
        w
    };
    assert_rejected(
        "balance weight",
        &estimates(n, 2, balance_weight, |l| a.eval(l)),
        exact,
    );
}

/// Wilkie's hero wavelengths with the balance heuristic, on a 5000 K blackbody
/// (statistical test 5). Planted bugs: lanes spaced by `1/(N+1)` of the range (the
/// rotations then no longer form a cycle, and `Σ_k p(λ_k)` is not the sum over the
/// techniques that could have made each lane), and each lane weighted by its own pdf.
#[test]
fn hero_balance_is_unbiased() {
    let exact = sum(cie::xyz(blackbody));
    let n = 100_000;
    assert_unbiased(
        "hero balance",
        &estimates(n, 3, hero_balance, blackbody),
        exact,
    );
    let spaced = |u: f64| {
        let mut w = hero_balance(u);
        let s = (w.lambda[0] - LAMBDA_MIN) / RANGE;
        w.lambda = std::array::from_fn(|j| sample_uniform(wrap01(s + j as f64 / (N + 1) as f64)));
        let mean = w.lambda.iter().map(|&l| visible_pdf(l)).sum::<f64>() / N as f64;
        w.pdf = [mean; N];
        w
    };
    assert_rejected(
        "spaced by 1/(N+1)",
        &estimates(n, 3, spaced, blackbody),
        exact,
    );
    let own_pdf = |u: f64| {
        let mut w = hero_balance(u);
        w.pdf = w.lambda.map(visible_pdf);
        w
    };
    assert_rejected(
        "own pdf per lane",
        &estimates(n, 3, own_pdf, blackbody),
        exact,
    );
}

/// Single wavelengths: uniform on D65 and visible on the blackbody (statistical tests 6, 7);
/// hero lanes on the low-pressure sodium lamp, whose light is one line at 589 nm
/// (statistical test 8: the hardest case, relative standard deviation ≈ 3 per path).
/// Planted bugs, one per estimator, on the same samples: the uniform density of the source's
/// 380–780 nm (`1/400`) claimed for wavelengths uniform on 360–830 nm; the uniform weight
/// `1/470` on a wavelength drawn from the visible pdf; and the same uniform weight on the
/// hero lanes that meet the sodium line.
#[test]
fn single_wavelengths_and_a_line_spectrum_are_unbiased() {
    let d = d65();
    let exact = sum(cie::xyz(|l| d.eval(l)));
    let single = |s: WavelengthStrategy| move |u| s.sample(u);
    let reweighted = |s: fn(f64) -> Wavelengths, pdf: f64| {
        move |u| {
            let mut w = s(u);
            for p in w.pdf.iter_mut().filter(|p| **p > 0.0) {
                *p = pdf;
            }
            w
        }
    };
    let n = 100_000;
    assert_unbiased(
        "uniform single",
        &estimates(n, 4, single(WavelengthStrategy::Uniform), |l| d.eval(l)),
        exact,
    );
    let uniform = |u| WavelengthStrategy::Uniform.sample(u);
    assert_rejected(
        "uniform single, density of 380-780 nm",
        &estimates(n, 4, reweighted(uniform, 1.0 / 400.0), |l| d.eval(l)),
        exact,
    );
    let exact = sum(cie::xyz(blackbody));
    assert_unbiased(
        "visible single",
        &estimates(n, 5, single(WavelengthStrategy::Visible), blackbody),
        exact,
    );
    let visible = |u| WavelengthStrategy::Visible.sample(u);
    assert_rejected(
        "visible single, uniform weight",
        &estimates(n, 5, reweighted(visible, 1.0 / RANGE), blackbody),
        exact,
    );
    let lps = builtin("lamp_low_pressure_sodium.csv");
    let exact = sum(cie::xyz(|l| lps.eval(l)));
    let s = estimates(400_000, 6, hero_visible, |l| lps.eval(l));
    assert_unbiased("hero visible, sodium line", &s, exact);
    let s = estimates(400_000, 6, reweighted(hero_visible, 1.0 / RANGE), |l| {
        lps.eval(l)
    });
    assert_rejected("hero visible on the sodium line, uniform weight", &s, exact);
}
