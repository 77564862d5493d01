//! Tests of the chapter *Importance-sampled emission spectra* (`src/spectral/emission.rs`).
//!
//! Statistical tests that correct code must pass, each at `raylemma::stats::test_alpha()`
//! with a fixed seed: 12. Kolmogorov–Smirnov of every lamp's sampler against the exact
//! CDF of its table (5), chi-squared with one cell per table segment for the fluorescent
//! lamp and the amber LED (2), and a t-test of the luminance estimator of every lamp
//! against the exact `Y` of its table (5). Every reference (CDF, segment masses, `Y`) is
//! computed here from the table by a different method than the code under test.
//!
//! Planted bugs that must be rejected: the table read as piecewise constant; the source's
//! 450 columns stretched over 380-830 nm; an unnormalised pdf; the spectrum counted
//! twice in the weight.

use glam::DVec3;
use rand::RngExt;
use raylemma::rng;
use raylemma::sampling::tabulated::{ONE_MINUS_EPSILON, Piecewise1D};
use raylemma::spectral::cie;
use raylemma::spectral::emission::*;
use raylemma::spectral::spectrum::Table;
use raylemma::stats::ttest::{self, Summary};
use raylemma::stats::{chi2, ks, test_alpha};

/// Samples per statistical test.
const N: usize = 100_000;

fn lamp(name: &str) -> Lamp {
    lamps()
        .into_iter()
        .find(|l| l.name.starts_with(name))
        .unwrap_or_else(|| panic!("no lamp {name}"))
}

fn sampler(t: &Table) -> EmissionSampler {
    EmissionSampler::new(t).unwrap_or_else(|e| panic!("{e}"))
}

/// `n` uniform numbers in [0, 1) from `seed`.
fn uniforms(seed: u64, n: usize) -> Vec<f64> {
    let mut r = rng::seeded(seed);
    (0..n).map(|_| r.random::<f64>()).collect()
}

// ---------------------------------------------------------------------------------------
// The exact distribution of a table, computed from its knots by trapezoids.

/// Cumulative trapezoid areas at the knots (not normalised).
fn areas(t: &Table) -> Vec<f64> {
    let (x, v) = (t.wavelengths(), t.values());
    let mut a = vec![0.0];
    for i in 1..x.len() {
        a.push(a[i - 1] + 0.5 * (v[i - 1] + v[i]) * (x[i] - x[i - 1]));
    }
    a
}

/// The exact CDF of the piecewise-linear density through the knots of `t`: the area to
/// the left of `x` (whole trapezoids, then the part-trapezoid up to `x`) over the total.
fn exact_cdf(t: &Table, areas: &[f64], x: f64) -> f64 {
    let knots = t.wavelengths();
    let total = areas[areas.len() - 1];
    if x <= knots[0] {
        return 0.0;
    }
    if x >= knots[knots.len() - 1] {
        return 1.0;
    }
    let i = knots.partition_point(|&k| k <= x) - 1;
    let part = 0.5 * (t.values()[i] + t.eval(x)) * (x - knots[i]);
    ((areas[i] + part) / total).min(1.0)
}

fn ks_p(t: &Table, xs: &[f64]) -> f64 {
    let a = areas(t);
    ks::one_sample(xs, |x| exact_cdf(t, &a, x))
        .unwrap_or_else(|e| panic!("{e}"))
        .p_value
}

/// Chi-squared with one cell per segment of `t`, expected counts from the trapezoids.
fn chi2_p(t: &Table, xs: &[f64]) -> f64 {
    let a = areas(t);
    let total = a[a.len() - 1];
    let n = xs.len() as f64;
    let expected: Vec<f64> = a.windows(2).map(|w| n * (w[1] - w[0]) / total).collect();
    let knots = t.wavelengths();
    let mut observed = vec![0u64; expected.len()];
    for &x in xs {
        let i = knots.partition_point(|&k| k <= x) - 1;
        observed[i.min(expected.len() - 1)] += 1;
    }
    chi2::pearson(&observed, &expected, 5.0)
        .unwrap_or_else(|e| panic!("{e}"))
        .p_value
}

fn draw(s: &EmissionSampler, seed: u64) -> Vec<f64> {
    uniforms(seed, N)
        .into_iter()
        .map(|u| s.sample(u).nm)
        .collect()
}

fn data_dir() -> std::path::PathBuf {
    crate::support::root().join("data")
}

/// Var of the one-sample estimator of each of X, Y, Z, by quadrature (0.01 nm midpoint
/// rule): `∫ f²/p - (∫ f)²` with `f = L c̄ / ∫ȳ`.
fn predicted_variance(t: &Table, pdf: impl Fn(f64) -> f64) -> DVec3 {
    let (mut m1, mut m2) = (DVec3::ZERO, DVec3::ZERO);
    let h = 0.01;
    for i in 0..45_000 {
        let nm = 380.0 + (f64::from(i) + 0.5) * h;
        let f = t.eval(nm) * cie::cmf(nm) / cie::y_integral();
        let p = pdf(nm);
        if p > 0.0 {
            m1 += f * h;
            m2 += f * f / p * h;
        }
    }
    m2 - m1 * m1
}

/// A sample of `t`: inside the table, where the spectrum is positive, with a positive pdf
/// equal (bit for bit) to `pdf(nm)`, and a weight `L / p` equal to `∫L` within 1e-12.
fn unsound(t: &Table, s: &EmissionSampler, u: f64) -> Option<String> {
    let w = s.sample(u);
    let k = t.wavelengths();
    let (lo, hi) = (k[0], k[k.len() - 1]);
    let weight = t.eval(w.nm) / w.pdf;
    let ok = w.nm >= lo
        && w.nm < hi
        && t.eval(w.nm) > 0.0
        && w.pdf > 0.0
        && w.pdf == s.pdf(w.nm)
        && (weight / t.integral() - 1.0).abs() <= 1e-12;
    (!ok).then(|| format!("u = {u:e}: {w:?}, L = {}, weight {weight}", t.eval(w.nm)))
}

fn y_of(t: &Table) -> f64 {
    cie::xyz(|nm| t.eval(nm)).y
}

mod amber;
mod estimator;
mod fits;
mod found_by_mutation;
mod image_format;
mod lamp_colour;
mod soundness;

// ---------------------------------------------------------------------------------------
// Exercises (ignored until the student fills in the scaffolds; each test fails on the stub).

/// Exercise 1 of *Importance-sampled emission spectra*: the path of your drawing, the
/// low-pressure sodium lamp with a faint second line near 819 nm (relative to the crate's
/// root, e.g. `"target/lamp_lps_doublet.png"`).
const YOUR_DRAWING: Option<&str> = None;

/// Exercise 1's answer: the distance (the larger of |Δx| and |Δy|) between the chromaticity of
/// your drawing and that of the shipped drawing `data/lamp_low_pressure_sodium.png`.
const YOUR_SHIFT: Option<f64> = None;

/// Checks exercise 1: the drawing has light between 814 and 824 nm that the shipped one does
/// not, the shift is below 1e-4 (the eye does not notice: ȳ at 819 nm is about 1e-5 of its
/// value at 589 nm), and your shift agrees with the one computed here to 10 %.
#[test]
#[ignore = "exercise 1 of Importance-sampled emission spectra: draw the line, fill in YOUR_DRAWING and YOUR_SHIFT, then run it"]
fn exercise_1_sodium_doublet() {
    let root = crate::support::root();
    let yours = load_image(&root.join(YOUR_DRAWING.expect("fill in YOUR_DRAWING"))).unwrap();
    let shipped = load_image(&data_dir().join("lamp_low_pressure_sodium.png")).unwrap();
    let near_819 = |t: &Table| (814..=824).map(|nm| t.eval(f64::from(nm))).sum::<f64>();
    assert!(
        near_819(&yours) > near_819(&shipped),
        "no light added near 819 nm"
    );
    let xy = |t: &Table| cie::chromaticity(cie::xyz(|nm| t.eval(nm))).unwrap();
    let shift = (xy(&yours) - xy(&shipped)).abs().max_element();
    eprintln!("chromaticity shift {shift:.2e}");
    assert!(shift < 1e-4, "the doublet moved the colour by {shift}");
    let answer = YOUR_SHIFT.expect("fill in YOUR_SHIFT");
    assert!((answer / shift - 1.0).abs() <= 0.1, "{answer} vs {shift}");
}

/// Exercise 2 of *Importance-sampled emission spectra*: the exact density proportional to
/// `L(λ) (x̄ + ȳ + z̄)(λ)`, normalised over 380–830 nm (the product itself, not a table of it).
fn your_exact_product_pdf(t: &Table) -> Box<dyn Fn(f64) -> f64> {
    let _ = t;
    unimplemented!("exercise 2 of Importance-sampled emission spectra: the exact product pdf")
}

/// Exercise 2's answer: the largest relative difference, over X, Y and Z, between the
/// variance of the incandescent lamp's estimator with the tabulated colour proposal and with
/// the exact product.
const YOUR_PRODUCT_COST: Option<f64> = None;

/// Checks exercise 2: your density integrates to 1 and is proportional to the product (to
/// 1e-9 on a 0.01 nm grid); the tabulated proposal costs less than 1 % of variance on every
/// channel; your answer agrees with the cost computed here to 10 % (or to 1e-5, if smaller).
#[test]
#[ignore = "exercise 2 of Importance-sampled emission spectra: fill in your_exact_product_pdf and YOUR_PRODUCT_COST, then run it"]
fn exercise_2_exact_product_proposal() {
    let t = lamp("incandescent").spectrum;
    let pdf = your_exact_product_pdf(&t);
    let grid = (0..45_000).map(|i| 380.0 + (f64::from(i) + 0.5) * 0.01);
    let integral: f64 = grid.clone().map(|nm| pdf(nm) * 0.01).sum();
    assert!((integral - 1.0).abs() <= 1e-6, "∫ p = {integral}");
    let product = |nm: f64| t.eval(nm) * cie::cmf(nm).element_sum();
    let k = pdf(600.0) / product(600.0);
    for nm in grid {
        assert!(
            (pdf(nm) - k * product(nm)).abs() <= 1e-9 * k * product(nm).max(1e-300),
            "{nm} nm: {} is not proportional to the product",
            pdf(nm)
        );
    }
    let tabulated = sampler(&colour_proposal(&t));
    let (v_tab, v_exact) = (
        predicted_variance(&t, |nm| tabulated.pdf(nm)),
        predicted_variance(&t, &*pdf),
    );
    let cost = (v_tab / v_exact - DVec3::ONE).abs().max_element();
    eprintln!("variances: tabulated {v_tab}, exact {v_exact}, cost {cost:.2e}");
    assert!(cost < 0.01, "the tabulated proposal costs {cost}");
    let answer = YOUR_PRODUCT_COST.expect("fill in YOUR_PRODUCT_COST");
    assert!(
        (answer - cost).abs() <= (0.1 * cost).max(1e-5),
        "{answer} vs {cost}"
    );
}

/// Exercise 3 of *Importance-sampled emission spectra*: the luminance proposal, the table
/// of `L(λ) ȳ(λ)` at every whole nanometre of 380–830 nm, linear in between (as
/// `colour_proposal` does for `x̄ + ȳ + z̄`).
fn your_luminance_proposal(t: &Table) -> Table {
    let _ = t;
    unimplemented!("exercise 3 of Importance-sampled emission spectra: the L ȳ proposal")
}

/// Exercise 3's answer: the names of the lamps (as `lamps()` names them) for which sampling
/// `L ȳ` makes the estimator of Z worse than uniform sampling.
const YOUR_BAD_FOR_Z: Option<&[&str]> = None;

/// Checks exercise 3: your table is `L ȳ` at every whole nanometre (to 1e-12, relative), and
/// your list is the set of lamps whose Z gain with it, by quadrature, is below 1.
#[test]
#[ignore = "exercise 3 of Importance-sampled emission spectra: fill in your_luminance_proposal and YOUR_BAD_FOR_Z, then run it"]
fn exercise_3_one_proposal_for_three_estimators() {
    let mut bad = Vec::new();
    for l in lamps() {
        let p = your_luminance_proposal(&l.spectrum);
        for nm in image_wavelengths() {
            let want = l.spectrum.eval(nm) * cie::cmf(nm).y;
            assert!(
                (p.eval(nm) - want).abs() <= 1e-12 * want.abs(),
                "{} at {nm}: {} vs {want}",
                l.name,
                p.eval(nm)
            );
        }
        let s = sampler(&p);
        let gain = predicted_variance(&l.spectrum, |_| 1.0 / 450.0)
            / predicted_variance(&l.spectrum, |nm| s.pdf(nm));
        eprintln!("{}: gains with L ȳ {gain}", l.name);
        if gain.z < 1.0 {
            bad.push(l.name);
        }
    }
    let mut answer = YOUR_BAD_FOR_Z.expect("fill in YOUR_BAD_FOR_Z").to_vec();
    answer.sort_unstable();
    bad.sort_unstable();
    assert_eq!(
        answer, bad,
        "the lamps for which L ȳ is worse than uniform on Z"
    );
}

/// Exercise 4 of *Importance-sampled emission spectra*: the mean of `n` estimates of the `Y`
/// of `t`, each from a wavelength drawn from `t`'s own spectrum (`EmissionSampler`), with the
/// uniform numbers stratified: one in each of `[i/n, (i + 1)/n)`.
fn your_stratified_y(t: &Table, n: usize, r: &mut rng::Rng) -> f64 {
    let _ = (t, n, r);
    unimplemented!("exercise 4 of Importance-sampled emission spectra: stratified estimates of Y")
}

/// Exercise 4's answer: the slope of log Var(Ŷ) against log N for the fluorescent lamp.
const YOUR_STRATIFIED_SLOPE: Option<f64> = None;

/// Checks exercise 4 on the fluorescent lamp: over 2000 repetitions at N = 4, 8, …, 256, the
/// mean is unbiased (within five standard errors of the exact Y at every N), the least-squares
/// slope of log Var against log N lies between −3.3 and −2.7 (one sample per stratum of a
/// Lipschitz integrand: N⁻³, against N⁻¹ for independent samples), and your slope agrees with
/// the measured one to 0.15.
#[test]
#[ignore = "exercise 4 of Importance-sampled emission spectra: fill in your_stratified_y and YOUR_STRATIFIED_SLOPE, then run it"]
fn exercise_4_stratified_wavelengths() {
    let t = lamp("fluorescent").spectrum;
    let exact = y_of(&t);
    let mut r = rng::seeded(0x57A4);
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    for k in 2..=8 {
        let n = 1usize << k;
        let s = Summary::of((0..2000).map(|_| your_stratified_y(&t, n, &mut r)));
        let se = (s.variance() / 2000.0).sqrt();
        assert!(
            (s.mean - exact).abs() <= 5.0 * se,
            "N = {n}: mean {} vs {exact}",
            s.mean
        );
        xs.push((n as f64).ln());
        ys.push(s.variance().ln());
    }
    let (mx, my) = (
        xs.iter().sum::<f64>() / xs.len() as f64,
        ys.iter().sum::<f64>() / ys.len() as f64,
    );
    let slope = xs
        .iter()
        .zip(&ys)
        .map(|(x, y)| (x - mx) * (y - my))
        .sum::<f64>()
        / xs.iter().map(|x| (x - mx).powi(2)).sum::<f64>();
    eprintln!("slope of log Var against log N: {slope:.3}");
    assert!((-3.3..=-2.7).contains(&slope), "slope {slope}");
    let answer = YOUR_STRATIFIED_SLOPE.expect("fill in YOUR_STRATIFIED_SLOPE");
    assert!((answer - slope).abs() <= 0.15, "{answer} vs {slope}");
}
