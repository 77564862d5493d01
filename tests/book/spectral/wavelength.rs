//! Tests of the chapter *Wavelength sampling and hero wavelengths*
//! (`src/spectral/wavelength.rs`).
//!
//! The t-tests run at `raylemma::stats::test_alpha()` (Šidák across the suite) with fixed
//! seeds. The exact values come from `cie::xyz` (Gauss-Legendre quadrature, a different
//! method from Monte Carlo), the visible pdf's constants from pbrt-v4's source. Every
//! estimator test has planted-bug twins, run on the same samples, that must be rejected.
//! Statistical tests in this file (correct code that must pass): 13.

use glam::DVec3;
use raylemma::check::Options;
use raylemma::check::warp::{self, Domain, SquareWarp, WarpOptions, planted};
use raylemma::rng;
use raylemma::spectral::spectrum::{Table, builtin, planck_normalised};
use raylemma::spectral::wavelength::*;
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN, cie};
use raylemma::stats::ttest::{self, Summary};
use raylemma::stats::{ks, test_alpha};

fn p_value(s: &Summary, mu: f64) -> f64 {
    ttest::one_sample(s, mu).unwrap().p_value
}

/// Asserts that `s` is consistent with `mu` (the correct estimator).
fn assert_unbiased(what: &str, s: &Summary, mu: f64) {
    let p = p_value(s, mu);
    eprintln!(
        "{what}: t = {:.2}, p = {p:.3e}",
        ttest::one_sample(s, mu).unwrap().t
    );
    assert!(
        p >= test_alpha(),
        "{what}: mean {} vs exact {mu} (relative {:+.2e}, p = {p:.3e})",
        s.mean,
        s.mean / mu - 1.0
    );
}

/// Asserts that a planted bug is rejected.
fn assert_rejected(what: &str, s: &Summary, mu: f64) {
    let p = p_value(s, mu);
    eprintln!(
        "planted bug {what}: t = {:.2}, p = {p:.3e}",
        ttest::one_sample(s, mu).unwrap().t
    );
    assert!(
        p < test_alpha(),
        "planted bug {what} was not detected: mean {} vs exact {mu} (p = {p:.3e})",
        s.mean
    );
}

/// `X + Y + Z`: the fixed linear combination each t-test uses (one test per estimator).
fn sum(v: DVec3) -> f64 {
    v.x + v.y + v.z
}

/// `n` estimates of `X + Y + Z` of spectrum `s`, one path per uniform number.
fn estimates(
    n: usize,
    seed: u64,
    lanes: impl Fn(f64) -> Wavelengths,
    s: impl Fn(f64) -> f64,
) -> Summary {
    let mut r = rng::seeded(seed);
    Summary::of((0..n).map(|_| sum(lanes(rng::uniform(&mut r, 0.0, 1.0)).xyz(&s))))
}

fn d65() -> Table {
    builtin("cie_illuminant_D65.csv")
}

fn blackbody(nm: f64) -> f64 {
    planck_normalised(nm, 5000.0)
}

// ---------------------------------------------------------------------------------------
// The visible pdf: against pbrt-v4's constants, its normalisation, its sampler.

/// pbrt-v4 (`SampleVisibleWavelengths`, `VisibleWavelengthsPDF`) prints the constants of
/// the same pdf on the same 360–830 nm range: `0.0039398042 / cosh²(0.0072 (λ − 538))` and
/// `λ = 538 − 138.888889 atanh(0.85691062 − 1.82750197 u)`. Our derived forms must agree
/// to the digits printed.
#[test]
fn visible_pdf_matches_pbrt_constants() {
    for nm in [360.0_f64, 400.0, 538.0, 600.0, 829.0, 830.0] {
        let pbrt = 0.003_939_804_2 / (0.0072 * (nm - 538.0)).cosh().powi(2);
        let err = (visible_pdf(nm) / pbrt - 1.0).abs();
        assert!(
            err <= 3e-8,
            "pdf at {nm} nm: {} vs pbrt {pbrt}",
            visible_pdf(nm)
        );
    }
    for u in [0.0_f64, 0.1, 0.5, 0.9, 0.999_999] {
        let pbrt = 538.0 - 138.888_889 * (0.856_910_62 - 1.827_501_97 * u).atanh();
        let err = (sample_visible(u) - pbrt).abs();
        assert!(
            err <= 1e-4,
            "λ(u = {u}): {} vs pbrt {pbrt}",
            sample_visible(u)
        );
    }
}

/// ∫ p dλ = 1 over 360–830 nm by composite Simpson on 47 000 intervals (independent of the
/// closed-form CDF), `P(P⁻¹(u)) = u`, and the sampler's `a (1 − t²) / (t₁ − t₀)` is `p(λ)`.
#[test]
fn visible_pdf_integrates_to_one_and_inverts() {
    let m = 47_000;
    let h = RANGE / m as f64;
    let simpson: f64 = (0..=m)
        .map(|i| {
            let w = if i == 0 || i == m {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * visible_pdf(LAMBDA_MIN + i as f64 * h)
        })
        .sum::<f64>()
        * h
        / 3.0;
    assert!((simpson - 1.0).abs() <= 1e-12, "∫ p = {simpson}");
    for i in 0..=1000 {
        let u = f64::from(i) / 1000.0 * (1.0 - f64::EPSILON);
        let (l, p) = sample_visible_pdf(u);
        let back = visible_cdf(l);
        assert!((back - u).abs() <= 1e-12, "P(P⁻¹({u})) = {back}");
        assert!(
            (p / visible_pdf(l) - 1.0).abs() <= 1e-9,
            "pdf at {l}: {p} vs {}",
            visible_pdf(l)
        );
    }
}

/// The inverse CDF's `½ ln((1 + t) / (1 − t))` is `atanh t` to within `1e-9` nm of `λ`,
/// on a fine grid of `u` that includes `u = 0`, `u → 1` and the `u` where `t = 0` (there
/// the logarithm's form loses relative accuracy); the reference is `f64::atanh`, a
/// different formula (`½ log1p(2t / (1 − t))`).
#[test]
fn inverse_cdf_by_logarithm_agrees_with_atanh() {
    let (t0, t1) = (
        (VISIBLE_A * (LAMBDA_MIN - VISIBLE_C)).tanh(),
        (VISIBLE_A * (LAMBDA_MAX - VISIBLE_C)).tanh(),
    );
    let zero = -t0 / (t1 - t0);
    let near_zero = (-50..=50).map(|i| zero + f64::from(i) * 1e-12);
    let grid = (0..=100_000).map(|i| f64::from(i) / 100_000.0 * (1.0 - f64::EPSILON));
    let mut worst = 0.0_f64;
    for u in grid.chain(near_zero) {
        let t = t0 + u * (t1 - t0);
        let by_atanh = (VISIBLE_C + t.atanh() / VISIBLE_A).clamp(LAMBDA_MIN, LAMBDA_MAX);
        let (l, _) = sample_visible_pdf(u);
        let err = (l - by_atanh).abs();
        assert!(err <= 1e-9, "u = {u}: {l} nm against atanh's {by_atanh} nm");
        worst = worst.max(err);
    }
    eprintln!("largest difference: {worst:.1e} nm");
}

/// The warp checker on the interval: chi-squared (statistical test 1) and the Jacobian
/// `p(P⁻¹(u)) dP⁻¹/du = 1`. Planted bug: the same formula normalised over 380–780 nm (the
/// constants copied for another range), claimed with our pdf: rejected by both checks.
#[test]
fn visible_sampler_draws_its_pdf() {
    // 400 000 samples on 47 x 47 cells of the interval, 10 000 Jacobian points.
    let options = WarpOptions {
        resolution: 47,
        points: 10_000,
        ..WarpOptions::from(Options::default().cases(400_000))
    };
    let domain = Domain::Interval {
        lo: LAMBDA_MIN,
        hi: LAMBDA_MAX,
    };
    let ok = SquareWarp::new(
        "visible pdf",
        domain,
        |u: glam::DVec2| DVec3::new(sample_visible(u.x), 0.0, 0.0),
        |p: DVec3| visible_pdf(p.x),
    );
    let v = warp::check(&ok, &options);
    assert!(v.passed(), "{v}");
    let bad = SquareWarp::new(
        "visible pdf, other range",
        domain,
        planted::visible_other_range,
        |p: DVec3| visible_pdf(p.x),
    );
    let v = warp::check(&bad, &options);
    assert!(
        v.failed("chi_squared") && v.failed("jacobian"),
        "the planted bug passed: {v}"
    );
}

/// KS of the hero's secondary lanes (statistical test 2): with the rotation in sample
/// space, lane 2 alone has the visible pdf. Planted bug: the rotation in wavelength space
/// (Wilkie's placement), whose lane 2 does not, is rejected.
#[test]
fn sample_space_lanes_each_have_the_pdf() {
    let mut r = rng::seeded(0x4A);
    let us: Vec<f64> = (0..20_000)
        .map(|_| rng::uniform(&mut r, 0.0, 1.0))
        .collect();
    let lane =
        |f: fn(f64) -> Wavelengths| -> Vec<f64> { us.iter().map(|&u| f(u).lambda[2]).collect() };
    let ok = ks::one_sample(&lane(hero_visible), visible_cdf).unwrap();
    assert!(ok.p_value >= test_alpha(), "sample-space lane 2: {ok:?}");
    let bad = ks::one_sample(&lane(hero_balance), visible_cdf).unwrap();
    assert!(
        bad.p_value < test_alpha(),
        "wavelength-space lane 2 passed: {bad:?}"
    );
}

/// Rotating in wavelength space a hero from the visible pdf places the lanes as an equally
/// spaced rule whose offset `s ∈ [0, 1/N)` has the folded density `R Σ_k p(λ_min + (s + k/N) R)`
/// (per unit `s`, against `N` for `hero_uniform`'s uniform offset). The visible pdf varies by
/// more than 17 times over the range, but the folded density stays within 7 % of uniform:
/// between 0.93 and 1.03 of `N`.
#[test]
fn wavelength_space_offset_is_nearly_uniform() {
    let m = 10_000;
    let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
    for i in 0..=m {
        let s = f64::from(i) / f64::from(m) / N as f64;
        let q: f64 = (0..N)
            .map(|k| RANGE * visible_pdf(LAMBDA_MIN + (s + k as f64 / N as f64) * RANGE))
            .sum::<f64>()
            / N as f64;
        lo = lo.min(q);
        hi = hi.max(q);
    }
    eprintln!("folded density / uniform: {lo:.4} to {hi:.4}");
    assert!(
        lo >= 0.93 && hi <= 1.03,
        "folded density from {lo} to {hi} of uniform"
    );
    let spread = visible_pdf(VISIBLE_C) / visible_pdf(LAMBDA_MAX);
    assert!(spread > 17.0, "the visible pdf varies by {spread}");
}

/// A named spectrum.
type Named = (&'static str, Box<dyn Fn(f64) -> f64>);

/// The spectra of the efficiency table (`figures/wavelength_efficiency.md`).
fn efficiency_spectra() -> Vec<Named> {
    let table = |file: &'static str| {
        let t = builtin(file);
        Box::new(move |nm: f64| t.eval(nm)) as Box<dyn Fn(f64) -> f64>
    };
    vec![
        ("incandescent", table("lamp_incandescent.csv")),
        ("cool white fl.", table("lamp_cool_white_fluorescent.csv")),
        ("LED (YAG)", table("lamp_phosphor_led_yag.csv")),
        ("high-pr. sodium", table("lamp_high_pressure_sodium.csv")),
        ("low-pr. sodium", table("lamp_low_pressure_sodium.csv")),
        ("D65", table("cie_illuminant_D65.csv")),
        ("A", table("cie_illuminant_A.csv")),
        ("blackbody 5000 K", Box::new(blackbody)),
    ]
}

/// The exact relative variances per path of a strategy's X, Y and Z (`Var / exact²` of each):
/// each strategy is a deterministic function of `u`, so the variance is an integral over `u`,
/// here by the midpoint rule on `m` points.
fn exact_relative_variances(
    lanes: &dyn Fn(f64) -> Wavelengths,
    s: &dyn Fn(f64) -> f64,
    m: u32,
) -> DVec3 {
    let exact = cie::xyz(s);
    let (mut first, mut second) = (DVec3::ZERO, DVec3::ZERO);
    for i in 0..m {
        let e = lanes((f64::from(i) + 0.5) / f64::from(m)).xyz(s);
        first += e;
        second += e * e;
    }
    let (first, second) = (first / f64::from(m), second / f64::from(m));
    let mean_err = ((first - exact) / exact).abs().max_element();
    assert!(mean_err <= 1e-4, "the grid's mean is off by {mean_err:.1e}");
    (second - first * first) / (exact * exact)
}

/// The mean over X, Y, Z of [`exact_relative_variances`]: the measure of the efficiency table.
fn exact_relative_variance(lanes: fn(f64) -> Wavelengths, s: &dyn Fn(f64) -> f64, m: u32) -> f64 {
    exact_relative_variances(&lanes, s, m).element_sum() / 3.0
}

/// The balance heuristic over the rotations of the visible pdf is no better than uniform hero
/// lanes: its exact relative variance per path is larger on every spectrum of the
/// efficiency table (its lanes are the same equally spaced rule, with weights reshuffled by a
/// folded density within 7 % of uniform). Computed by quadrature over `u`, not measured.
#[test]
fn wavelength_space_balance_is_no_better_than_hero_uniform() {
    for (name, s) in efficiency_spectra() {
        let uniform = exact_relative_variance(hero_uniform, &s, 200_000);
        let balance = exact_relative_variance(hero_balance, &s, 200_000);
        let sample_space = exact_relative_variance(hero_visible, &s, 200_000);
        eprintln!(
            "{name}: relative variance, hero uniform {uniform:.4}, wavelength-space balance \
             {balance:.4}, sample space {sample_space:.4}"
        );
        assert!(
            balance > uniform,
            "{name}: balance {balance} vs uniform {uniform}"
        );
        assert!(
            sample_space < uniform,
            "{name}: sample space {sample_space} vs uniform {uniform}"
        );
    }
}

// ---------------------------------------------------------------------------------------
// Edge cases.

#[test]
fn ends_of_the_range_and_nan() {
    let below = 1.0 - f64::EPSILON;
    assert_eq!(sample_visible(0.0), LAMBDA_MIN);
    assert_eq!(sample_uniform(0.0), LAMBDA_MIN);
    assert!((sample_visible(below) - LAMBDA_MAX).abs() <= 1e-9);
    for f in [visible_pdf, uniform_pdf] {
        assert!(f(LAMBDA_MIN) > 0.0 && f(LAMBDA_MAX) > 0.0);
        for nm in [
            LAMBDA_MIN - 1e-9,
            LAMBDA_MAX + 1e-9,
            -1.0,
            f64::NAN,
            f64::INFINITY,
        ] {
            assert_eq!(f(nm), 0.0, "pdf at {nm}");
        }
    }
    for s in Strategy::ALL {
        for u in [0.0, 0.25, 0.75, below] {
            let w = s.sample(u);
            for (l, p) in w.lambda.iter().zip(&w.pdf) {
                assert!(p.is_finite() && *p >= 0.0, "{}: u = {u}: pdf {p}", s.name());
                if s != Strategy::SeedBand {
                    assert!(
                        (LAMBDA_MIN..=LAMBDA_MAX).contains(l),
                        "{}: u = {u}: λ = {l}",
                        s.name()
                    );
                }
            }
            assert!(w.pdf[0] > 0.0, "{}: u = {u}: dead hero", s.name());
        }
        // A NaN random number gives a NaN estimate, never a silent zero.
        let e = s.sample(f64::NAN).xyz(|_| 1.0);
        assert!(e.is_nan(), "{}: NaN u gave {e}", s.name());
    }
    // Hero lanes are a quarter of the range apart, wrapped: at u -> 1 lane 1 is near 360 + 117.5.
    let w = hero_uniform(below);
    assert!(
        (w.lambda[1] - (LAMBDA_MIN + 0.25 * RANGE)).abs() <= 1e-9,
        "{w:?}"
    );
    assert_eq!(wrap01(-1e-300), 0.0);
}

#[test]
fn terminated_lanes_contribute_nothing() {
    let mut w = hero_visible(0.3);
    let once = {
        w.terminate_secondary();
        w
    };
    w.terminate_secondary();
    assert_eq!(w, once, "terminating twice changed the lanes");
    let e = w.estimate(|_| DVec3::ONE);
    assert!(
        (e.x - 1.0 / w.hero_pdf).abs() <= 1e-12 / w.hero_pdf,
        "terminated estimate {e} vs 1/p(λ0) = {}",
        1.0 / w.hero_pdf
    );
}

// ---------------------------------------------------------------------------------------
// Unbiasedness of the estimators, with their planted bugs.

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
    let single = |s: Strategy| move |u| s.sample(u);
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
        &estimates(n, 4, single(Strategy::Uniform), |l| d.eval(l)),
        exact,
    );
    let uniform = |u| Strategy::Uniform.sample(u);
    assert_rejected(
        "uniform single, density of 380-780 nm",
        &estimates(n, 4, reweighted(uniform, 1.0 / 400.0), |l| d.eval(l)),
        exact,
    );
    let exact = sum(cie::xyz(blackbody));
    assert_unbiased(
        "visible single",
        &estimates(n, 5, single(Strategy::Visible), blackbody),
        exact,
    );
    let visible = |u| Strategy::Visible.sample(u);
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

// ---------------------------------------------------------------------------------------
// Dispersion: terminating the secondary lanes.

// ANCHOR: prism
/// A toy pixel with a dispersive event: half of it shows a grey wall (albedo 0.8) lit by
/// D65, half a prism. A camera ray through a uniform point of the pixel (`coin`) hits the
/// wall with probability 1/2: no dispersion, all lanes carry on. Otherwise it passes
/// through the prism, which sends towards the D65 light only the wavelengths 480–520 nm (for
/// the others the refracted ray misses it): the refraction angle depends on λ, so only the
/// hero lane can follow it and the secondaries are terminated. `terminate` is the rule.
/// Returns the estimate of `X + Y + Z` of the pixel, `0.5 · 0.8 · D65 + 0.5 · D65 · 1[480, 520]`.
fn prism_path(mut w: Wavelengths, coin: f64, d65: &Table, terminate: fn(&mut Wavelengths)) -> f64 {
    let xyz = if coin < 0.5 {
        w.xyz(|l| 0.8 * d65.eval(l))
    } else {
        terminate(&mut w);
        w.xyz(|l| {
            if (480.0..=520.0).contains(&l) {
                d65.eval(l)
            } else {
                0.0
            }
        })
    };
    sum(xyz)
}
// ANCHOR_END: prism

fn prism_estimates(
    n: usize,
    seed: u64,
    lanes: fn(f64) -> Wavelengths,
    terminate: fn(&mut Wavelengths),
) -> Summary {
    let d = d65();
    let mut r = rng::seeded(seed);
    Summary::of((0..n).map(|_| {
        let u = rng::uniform(&mut r, 0.0, 1.0);
        prism_path(lanes(u), rng::uniform(&mut r, 0.0, 1.0), &d, terminate)
    }))
}

/// The exact pixel, by quadrature: the band's edges are whole nanometres, where
/// `cie::xyz` places its interval ends, so the step is integrated exactly.
fn prism_exact() -> f64 {
    let d = d65();
    0.5 * sum(cie::xyz(|l| 0.8 * d.eval(l)))
        + 0.5
            * sum(cie::xyz(|l| {
                if (480.0..=520.0).contains(&l) {
                    d.eval(l)
                } else {
                    0.0
                }
            }))
}

/// Termination keeps the hero unbiased: with sample-space lanes (statistical test 9) and
/// with Wilkie's balance lanes (statistical test 10). Planted bugs: terminating without
/// reweighting the hero (the prism branch is `N` times too dark), and pbrt-v4's rule
/// `pdf[0] /= N` applied to balance-heuristic lanes (right only when `pdf[0]` is the hero's
/// own density).
#[test]
fn terminating_secondaries_stays_unbiased() {
    let exact = prism_exact();
    let n = 100_000;
    let rule: fn(&mut Wavelengths) = Wavelengths::terminate_secondary;
    assert_unbiased(
        "prism, sample space",
        &prism_estimates(n, 7, hero_visible, rule),
        exact,
    );
    assert_unbiased(
        "prism, balance",
        &prism_estimates(n, 8, hero_balance, rule),
        exact,
    );
    let no_reweight: fn(&mut Wavelengths) = |w| {
        for p in &mut w.pdf[1..] {
            *p = 0.0;
        }
    };
    assert_rejected(
        "no reweighting",
        &prism_estimates(n, 7, hero_visible, no_reweight),
        exact,
    );
    let pbrt_rule: fn(&mut Wavelengths) = |w| {
        for p in &mut w.pdf[1..] {
            *p = 0.0;
        }
        w.pdf[0] /= N as f64;
    };
    // The same rule is right for sample-space lanes, where pdf[0] = p(λ0) ...
    let same = prism_estimates(n, 7, hero_visible, pbrt_rule);
    let ours = prism_estimates(n, 7, hero_visible, rule);
    assert!(same.mean == ours.mean, "{} vs {}", same.mean, ours.mean);
    // ... and wrong for balance lanes, where pdf[0] is the lanes' mean density.
    assert_rejected(
        "pbrt's rule on balance lanes",
        &prism_estimates(n, 8, hero_balance, pbrt_rule),
        exact,
    );
}

// ---------------------------------------------------------------------------------------
// A rough dispersive interface: Wilkie et al.'s weights over which lane was the hero.

/// The refraction angle into N-BK7 of light arriving at 60°, radians: `asin(sin 60° / n(λ))`.
fn refracted(nm: f64) -> f64 {
    let n = raylemma::optics::dispersion::material(raylemma::optics::dispersion::N_BK7).index(nm);
    (60f64.to_radians().sin() / n).asin()
}

/// The spread of the refraction angles over the range, `θ_t(830) − θ_t(360)` (about 0.7°).
fn dispersion_spread() -> f64 {
    refracted(LAMBDA_MAX) - refracted(LAMBDA_MIN)
}

/// The normal density of `x` with mean `m` and standard deviation `s`.
fn gauss(x: f64, m: f64, s: f64) -> f64 {
    (-0.5 * ((x - m) / s).powi(2)).exp() / (s * (2.0 * std::f64::consts::PI).sqrt())
}

/// What a rough dispersive vertex does with the secondary lanes.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Secondaries {
    /// Terminate them, as at a delta event (pbrt-v4 does so at every dispersive dielectric).
    Terminate,
    /// Keep them, each lane's throughput divided by the hero's path density.
    HeroPathPdf,
    /// Keep them, with Wilkie et al.'s balance heuristic over which lane was the hero.
    Wilkie,
    /// Planted bug: each lane divided by its *own* path density, though the path was drawn
    /// with the hero's.
    OwnPathPdf,
}

// ANCHOR: rough
/// A toy rough dispersive interface. Light arriving at 60° refracts into N-BK7 at
/// `θ_t(λ)`, and the rough surface spreads it into a normal lobe of directions
/// `g(θ; θ_t(λ), σ)`. The path draws `θ = θ_t(λ_0) + σ z` from the hero's lobe, `z` standard
/// normal; the light (D65) is seen in the directions `W` refracted for 450–650 nm. So
/// `f(θ, λ) = D65(λ) g(θ; θ_t(λ), σ) 1[θ ∈ W]`, and each lane's throughput is
/// `f(θ, λ_j) / g(θ; θ_t(λ_0), σ)`. Returns the estimate of `X + Y + Z`.
fn rough_path(mut w: Wavelengths, z: f64, sigma: f64, how: Secondaries, d65: &Table) -> f64 {
    let theta = refracted(w.lambda[0]) + sigma * z;
    let seen = (refracted(450.0)..=refracted(650.0)).contains(&theta);
    // p(θ | λ_k) for every lane: the lobe the path would have been drawn from had lane k
    // been the hero.
    let path_pdf = w.lambda.map(|l| gauss(theta, refracted(l), sigma));
    match how {
        Secondaries::Terminate => w.terminate_secondary(),
        Secondaries::Wilkie => w.balance_path_pdfs(path_pdf),
        Secondaries::HeroPathPdf | Secondaries::OwnPathPdf => {}
    }
    let lobe = |l: f64| match how {
        Secondaries::OwnPathPdf => 1.0,
        _ => gauss(theta, refracted(l), sigma) / path_pdf[0],
    };
    sum(w.xyz(|l| if seen { d65.eval(l) * lobe(l) } else { 0.0 }))
}
// ANCHOR_END: rough

/// The exact pixel of the toy, by quadrature over λ of D65 times the lobe's mass in `W`.
fn rough_exact(sigma: f64, d65: &Table) -> f64 {
    use statrs::function::erf::erfc;
    let phi = |x: f64| 0.5 * erfc(-x / std::f64::consts::SQRT_2);
    let (a, b) = (refracted(450.0), refracted(650.0));
    sum(cie::xyz(|l| {
        let t = refracted(l);
        d65.eval(l) * (phi((b - t) / sigma) - phi((a - t) / sigma))
    }))
}

/// `n` estimates of the toy, the same random numbers for every choice (`u` for the lanes,
/// `z` for the direction).
fn rough_estimates(
    n: usize,
    seed: u64,
    lanes: fn(f64) -> Wavelengths,
    sigma: f64,
    how: Secondaries,
    d65: &Table,
) -> Summary {
    let mut r = rng::seeded(seed);
    Summary::of((0..n).map(|_| {
        let u = rng::uniform(&mut r, 0.0, 1.0);
        let z = raylemma::rng::standard_normal(&mut r);
        rough_path(lanes(u), z, sigma, how, d65)
    }))
}

/// Wilkie et al.'s weights keep the estimate unbiased on Wilkie's own uniform lanes
/// (statistical test 12) and on sample-space lanes (statistical test 13), with a lobe 0.3
/// times the spread of the refraction angles. Planted bugs: each lane divided by its own
/// path density, and the same weights on wavelength-space balance lanes (`hero_balance`,
/// whose techniques have the densities `p(λ_k)`, not one common density).
#[test]
fn rough_dispersion_wilkie_weights_are_unbiased() {
    let d = d65();
    let sigma = 0.3 * dispersion_spread();
    let exact = rough_exact(sigma, &d);
    let n = 200_000;
    assert_unbiased(
        "rough interface, uniform lanes, Wilkie",
        &rough_estimates(n, 13, hero_uniform, sigma, Secondaries::Wilkie, &d),
        exact,
    );
    assert_unbiased(
        "rough interface, sample-space lanes, Wilkie",
        &rough_estimates(n, 14, hero_visible, sigma, Secondaries::Wilkie, &d),
        exact,
    );
    assert_rejected(
        "own path pdf per lane",
        &rough_estimates(n, 13, hero_uniform, sigma, Secondaries::OwnPathPdf, &d),
        exact,
    );
    assert_rejected(
        "Wilkie's weights on wavelength-space balance lanes",
        &rough_estimates(n, 15, hero_balance, sigma, Secondaries::Wilkie, &d),
        exact,
    );
}

/// Where Wilkie et al.'s multiple importance sampling helps. With the lobe much narrower
/// than the spread of the refraction angles (σ = 0.01 of it) the other lanes' lobes miss the
/// path and the weights give what termination gives (variance within 2 %); with a lobe ten
/// times wider than the spread the lanes' lobes overlap, the weights tend to 1/N, and
/// Wilkie's weights and the hero's path density agree (within 2 %). In between (σ = 0.1 and
/// 0.3 of the spread) Wilkie's variance is below both: termination wastes the secondaries,
/// and the hero's density for every lane makes fireflies where a lane's lobe is far from the
/// hero's. The same random numbers for every choice; uniform lanes, as in Wilkie et al.
#[test]
fn rough_dispersion_wilkie_weights_beat_termination_and_the_hero_pdf() {
    let d = d65();
    let n = 200_000;
    // The spread of the refraction angles, about 0.7° (the chapter's figure).
    let spread = dispersion_spread().to_degrees();
    assert!((0.65..=0.75).contains(&spread), "spread {spread}°");
    for ratio in [0.01, 0.1, 0.3, 10.0] {
        let sigma = ratio * dispersion_spread();
        let exact = rough_exact(sigma, &d);
        let var =
            |how| rough_estimates(n, 16, hero_uniform, sigma, how, &d).variance() / (exact * exact);
        let (terminate, hero_pdf, wilkie) = (
            var(Secondaries::Terminate),
            var(Secondaries::HeroPathPdf),
            var(Secondaries::Wilkie),
        );
        eprintln!(
            "σ = {ratio} × spread: relative variance, terminate {terminate:.4}, \
             hero pdf {hero_pdf:.4}, Wilkie {wilkie:.4}"
        );
        if ratio < 0.05 {
            assert!(
                (wilkie / terminate - 1.0).abs() <= 0.02,
                "{wilkie} vs {terminate}"
            );
        } else if ratio > 5.0 {
            assert!(
                (wilkie / hero_pdf - 1.0).abs() <= 0.02,
                "{wilkie} vs {hero_pdf}"
            );
        } else {
            assert!(
                wilkie < 0.9 * terminate && wilkie < 0.9 * hero_pdf,
                "σ = {ratio} × spread: Wilkie {wilkie}, terminate {terminate}, hero pdf {hero_pdf}"
            );
        }
    }
    // The delta limit: at a smooth interface only the hero's lobe contains the path, and
    // Wilkie's weights give lane 0 what termination gives it, `p(λ_0) / N`.
    let mut w = hero_visible(0.3);
    let mut t = w;
    w.balance_path_pdfs([2.0, 0.0, 0.0, 0.0]);
    t.terminate_secondary();
    assert!((w.pdf[0] / t.pdf[0] - 1.0).abs() <= 1e-15, "{w:?} vs {t:?}");
    // A path density that is not positive for the hero is a broken sampler: NaN, not 0.
    let mut w = hero_uniform(0.3);
    w.balance_path_pdfs([0.0, 1.0, 1.0, 1.0]);
    assert!(w.estimate(|_| DVec3::ONE).is_nan());
}

// ---------------------------------------------------------------------------------------
// The source's band.

/// The source's estimator converges to `∫ w f` with the weight [`seed_band_weight`], not to
/// `∫ f`. Read with the range 400–700 nm, its Z of D65 is measurably low: rejected against
/// the exact Z, accepted against `∫ w f` (statistical test 11: this checks the derivation
/// of what the source's band computes). Quadrature gives the bias for every reading
/// (`figures/wavelength_seed_bias.md`).
#[test]
fn seed_band_is_biased() {
    let d = d65();
    let band = SeedBand {
        lo: 400.0,
        hi: 700.0,
        spacing: 5.0,
    };
    let n = 2_500_000;
    let mut r = rng::seeded(9);
    let s = Summary::of((0..n).map(|_| {
        seed_band(rng::uniform(&mut r, 0.0, 1.0), &band)
            .xyz(|l| d.eval(l))
            .z
    }));
    let exact = cie::xyz(|l| d.eval(l)).z;
    let converges_to = cie::xyz(|l| d.eval(l) * seed_band_weight(l, &band)).z;
    assert_unbiased("seed band against ∫ w f", &s, converges_to);
    assert_rejected("seed band against the exact Z", &s, exact);
}

/// The source notes claim their band "decreases noise". Its lanes lie within 15 nm of each other,
/// so they see almost the same integrand: per path, the variance of Y of D65 is within a
/// factor 2 of one uniform wavelength's, while hero lanes spread over the range cut it by
/// more than 20 (both measured on 200 000 paths; the figure tables give the numbers).
#[test]
fn seed_band_barely_reduces_variance() {
    let d = d65();
    let var = |s: Strategy| {
        let mut r = rng::seeded(10);
        Summary::of((0..200_000).map(|_| {
            s.sample(rng::uniform(&mut r, 0.0, 1.0))
                .xyz(|l| d.eval(l))
                .y
        }))
        .variance()
    };
    let (single, band, hero) = (
        var(Strategy::Uniform),
        var(Strategy::SeedBand),
        var(Strategy::HeroUniform),
    );
    assert!(band >= single / 2.0, "band {band} vs single {single}");
    assert!(hero <= single / 20.0, "hero {hero} vs single {single}");
}

// ---------------------------------------------------------------------------------------
// Lane placement (found by mutation testing: with every lane on the hero the estimators
// stay unbiased, so only the placement itself can show the mistake).

/// Sorted positions on the unit circle, and their gaps (including the wrap-around).
fn gaps(mut xs: [f64; N]) -> Vec<f64> {
    xs.sort_by(f64::total_cmp);
    let mut g: Vec<f64> = xs.windows(2).map(|w| w[1] - w[0]).collect();
    g.push(xs[0] + 1.0 - xs[N - 1]);
    g
}

/// Hero lanes are `1/N` apart: in wavelength for the uniform and balance forms, in the
/// visible CDF for the sample-space form. One lane per quarter is what stratifies.
#[test]
fn hero_lanes_are_spread_one_nth_apart() {
    let mut r = rng::seeded(0x1A5E);
    for _ in 0..1000 {
        let u = rng::uniform(&mut r, 0.0, 1.0);
        let in_range = |w: &Wavelengths| w.lambda.map(|l| (l - LAMBDA_MIN) / RANGE);
        let cases = [
            ("hero uniform", in_range(&hero_uniform(u))),
            ("hero balance", in_range(&hero_balance(u))),
            ("hero visible", hero_visible(u).lambda.map(visible_cdf)),
        ];
        for (name, xs) in cases {
            for g in gaps(xs) {
                assert!(
                    (g - 1.0 / N as f64).abs() <= 1e-9,
                    "{name}: u = {u}: lanes {xs:?}"
                );
            }
        }
    }
    // The planted twin: every lane on the hero (j N instead of j / N) has gaps 0 and 1.
    let xs = [0.3; N];
    assert!(gaps(xs).iter().any(|g| (g - 0.25).abs() > 0.1));
}

/// `uniform_pdf` integrates to 1 over the range by the trapezoid rule (exact for a
/// constant), and termination is visible to `is_terminated`.
#[test]
fn uniform_pdf_is_normalised_and_termination_is_reported() {
    let m = 4700;
    let h = RANGE / m as f64;
    let trapezoid: f64 = (0..m)
        .map(|i| {
            0.5 * h
                * (uniform_pdf(LAMBDA_MIN + i as f64 * h)
                    + uniform_pdf(LAMBDA_MIN + (i + 1) as f64 * h))
        })
        .sum();
    assert!((trapezoid - 1.0).abs() <= 1e-12, "∫ p = {trapezoid}");
    let mut w = hero_uniform(0.3);
    assert!(!w.is_terminated());
    w.terminate_secondary();
    assert!(w.is_terminated());
    assert!(Wavelengths::single(500.0, 1.0 / RANGE).is_terminated());
}

/// The band's weight has the shape its derivation gives: lane `j` covers
/// `[lo + 5j, hi + 5j]`, so `w` steps up by `1/N` at 380, 385, 390, 395 nm, is 1 up to
/// 780 nm, and steps down by `1/N` after 780, 785, 790, 795 nm (found by mutation
/// testing: the bias t-test alone cannot tell lanes 5 nm apart from lanes 1 nm apart).
#[test]
fn seed_band_weight_ramps_by_quarters() {
    let w = |nm: f64| seed_band_weight(nm, &SEED_BAND);
    let expected = [
        (379.5, 0.0),
        (382.5, 0.25),
        (387.5, 0.5),
        (392.5, 0.75),
        (397.5, 1.0),
        (600.0, 1.0),
        (782.5, 0.75),
        (787.5, 0.5),
        (792.5, 0.25),
        (795.5, 0.0),
    ];
    for (nm, want) in expected {
        assert_eq!(w(nm), want, "w({nm})");
    }
}

// ---------------------------------------------------------------------------------------
// Exercises (ignored until the student fills in the scaffolds; each test fails on the stub).

/// Exercise 1 of *Wavelength sampling*: hero lanes rotated in sample space through the CDF of
/// the lamp's spectrum times ȳ (tabulate `S ȳ` at every whole nanometre of 360–830 nm and draw
/// from it with the piecewise-linear sampler of *Tabulated distributions*,
/// `raylemma::spectral::emission::EmissionSampler`); every lane weighted by its own density.
fn your_light_lanes(spectrum: &Table) -> Box<dyn Fn(f64) -> Wavelengths> {
    let _ = spectrum;
    unimplemented!("exercise 1 of Wavelength sampling: hero lanes through the CDF of S ȳ")
}

/// Checks exercise 1: sampling `S ȳ` makes the low-pressure sodium lamp almost noise-free
/// (exact relative variance per path of its XYZ below 1e-3, against about 8.7 for the
/// visible pdf), and makes the Z of the incandescent lamp worse than the visible pdf does
/// (`S ȳ` starves the blue, where z̄ lives). Exact variances, by quadrature over `u`.
#[test]
#[ignore = "exercise 1 of Wavelength sampling: fill in your_light_lanes, then run it"]
fn exercise_1_light_sampling_lanes() {
    let lps = builtin("lamp_low_pressure_sodium.csv");
    let lanes = your_light_lanes(&lps);
    let v = exact_relative_variances(&*lanes, &|nm| lps.eval(nm), 200_000);
    eprintln!("low-pressure sodium, light sampling: relative variances {v}");
    assert!(v.element_sum() / 3.0 < 1e-3, "low-pressure sodium: {v}");
    let inc = builtin("lamp_incandescent.csv");
    let lanes = your_light_lanes(&inc);
    let v = exact_relative_variances(&*lanes, &|nm| inc.eval(nm), 200_000);
    let visible = exact_relative_variances(&hero_visible, &|nm| inc.eval(nm), 200_000);
    eprintln!("incandescent: light sampling {v}, visible pdf {visible}");
    assert!(
        v.z > visible.z,
        "incandescent Z: light sampling {} vs visible {}",
        v.z,
        visible.z
    );
    assert!(
        v.y < visible.y,
        "incandescent Y: light sampling {} vs visible {}",
        v.y,
        visible.y
    );
}

/// Exercise 2 of *Wavelength sampling*: `n` values of `u` stratified over `[0, 1)`, one
/// uniform point in each of the strata `[i/n, (i + 1)/n)`, in a random order (a shuffled
/// grid), so that the pixels of an image each get one.
fn your_shuffled_grid(n: usize, r: &mut rng::Rng) -> Vec<f64> {
    let _ = (n, r);
    unimplemented!("exercise 2 of Wavelength sampling: a shuffled stratified grid of u")
}

/// Checks exercise 2 on a flat field of 64 pixels lit by D65, 4000 images per case: the
/// grid has one point per stratum; the variance of each pixel is unchanged (each pixel still
/// has one uniform `u`: within 10 %); the variance of the image's mean falls by more than 4
/// times for one uniform wavelength, and by less for uniform hero lanes, whose four lanes are
/// already stratified.
#[test]
#[ignore = "exercise 2 of Wavelength sampling: fill in your_shuffled_grid, then run it"]
fn exercise_2_stratified_hero() {
    let mut r = rng::seeded(0x57A7);
    let g = your_shuffled_grid(64, &mut r);
    let mut strata: Vec<usize> = g.iter().map(|&u| (u * 64.0) as usize).collect();
    strata.sort_unstable();
    assert_eq!(
        strata,
        (0..64).collect::<Vec<_>>(),
        "one u per stratum: {g:?}"
    );
    assert!(
        g.windows(2).any(|w| w[0] > w[1]),
        "the grid is not shuffled"
    );
    let d = d65();
    let images = 4000;
    // (variance of a pixel, variance of the image's mean) for independent or stratified u.
    let measure = |s: Strategy, stratified: bool| {
        let mut r = rng::seeded(0xF1A7);
        let (mut pixels, mut means) = (Vec::new(), Vec::new());
        for _ in 0..images {
            let us: Vec<f64> = if stratified {
                your_shuffled_grid(64, &mut r)
            } else {
                (0..64).map(|_| rng::uniform(&mut r, 0.0, 1.0)).collect()
            };
            let image: Vec<f64> = us
                .iter()
                .map(|&u| sum(s.sample(u).xyz(|l| d.eval(l))))
                .collect();
            pixels.push(image[17]);
            means.push(image.iter().sum::<f64>() / 64.0);
        }
        (
            Summary::of(pixels).variance(),
            Summary::of(means).variance(),
        )
    };
    let mut gains = Vec::new();
    for s in [Strategy::Uniform, Strategy::HeroUniform] {
        let (pixel, mean) = measure(s, false);
        let (pixel_s, mean_s) = measure(s, true);
        eprintln!(
            "{}: pixel variance {pixel:.4e} -> {pixel_s:.4e}, image-mean variance {mean:.4e} -> {mean_s:.4e}",
            s.name()
        );
        assert!(
            (pixel_s / pixel - 1.0).abs() <= 0.1,
            "{}: pixel variance changed",
            s.name()
        );
        gains.push(mean / mean_s);
    }
    assert!(
        gains[0] > 4.0,
        "one uniform wavelength gains only {}",
        gains[0]
    );
    assert!(
        gains[1] < gains[0],
        "hero lanes gain {} against {}",
        gains[1],
        gains[0]
    );
}

/// The prism toy with the prism covering a fraction `q` of the pixel (the chapter's toy has
/// `q = 1/2`): the estimate of `X + Y + Z` of `(1 − q) 0.8 D65 + q D65 1[480, 520]`.
fn prism_path_covering(w: Wavelengths, coin: f64, q: f64, d65: &Table) -> f64 {
    // `prism_path` takes the wall below 0.5 and the prism above.
    let branch = if coin < q { 0.75 } else { 0.25 };
    prism_path(w, branch, d65, Wavelengths::terminate_secondary)
}

/// Exercise 3 of *Wavelength sampling*: the variance per path of the prism toy's estimate
/// when the prism covers a fraction `q` of the pixel, predicted (not measured) from the two
/// branches: `(1 − q) E[w²] + q E[p²] − ((1 − q) W + q P)²`, with `w` the wall's estimate
/// (all lanes live), `p` the prism's (the hero alone), `W`, `P` their means, and the second
/// moments by quadrature over `u` (each branch is a deterministic function of `u`).
fn your_prism_variance(q: f64, lanes: fn(f64) -> Wavelengths) -> f64 {
    let _ = (q, lanes);
    unimplemented!("exercise 3 of Wavelength sampling: the prism toy's variance as a function of q")
}

/// Checks exercise 3: the predicted variance against the measured one (400 000 paths, within
/// four standard errors of the sample variance) at q = 0.25, 0.5, 0.75, for sample-space hero
/// lanes and for one wavelength from the visible pdf; and at q = 1, where both are the
/// one-wavelength estimator, a variance ratio of 1.
#[test]
#[ignore = "exercise 3 of Wavelength sampling: fill in your_prism_variance, then run it"]
fn exercise_3_mixed_terminations() {
    let d = d65();
    let single = |u: f64| Strategy::Visible.sample(u);
    for (name, lanes) in [
        ("hero visible", hero_visible as fn(f64) -> Wavelengths),
        ("visible, 1 λ", single),
    ] {
        for q in [0.25, 0.5, 0.75] {
            let mut r = rng::seeded(0x9215);
            let xs: Vec<f64> = (0..400_000)
                .map(|_| {
                    let u = rng::uniform(&mut r, 0.0, 1.0);
                    prism_path_covering(lanes(u), rng::uniform(&mut r, 0.0, 1.0), q, &d)
                })
                .collect();
            let n = xs.len() as f64;
            let mean = xs.iter().sum::<f64>() / n;
            let m2 = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n;
            let m4 = xs.iter().map(|x| (x - mean).powi(4)).sum::<f64>() / n;
            let se = ((m4 - m2 * m2) / n).sqrt();
            let predicted = your_prism_variance(q, lanes);
            eprintln!("{name}, q = {q}: measured {m2:.5} ± {se:.5}, predicted {predicted:.5}");
            assert!(
                (predicted - m2).abs() <= 4.0 * se,
                "{name}, q = {q}: {predicted} vs {m2} ± {se}"
            );
        }
    }
    let ratio = your_prism_variance(1.0, hero_visible) / your_prism_variance(1.0, single);
    assert!(
        (ratio - 1.0).abs() <= 1e-9,
        "at q = 1 the variance ratio is {ratio}"
    );
}

// ---------------------------------------------------------------------------------------
// Accuracy against exact arithmetic (data/corpus/wavelength.txt, tools/exact).

/// The rotation `(u + j/N) mod 1` used to wrap the *rounded* sum: at `u = 1/4 − 2⁻⁵⁵`,
/// `u + 3/4` rounds to 1.0 and lane 3 went to 360 nm, while the exact lane is
/// 830 − 1.3e-14 nm (the corpus's answer, mpmath at 256 bits). The wrap is now decided
/// exactly ([`rotate01`]).
#[test]
fn hero_rotation_does_not_wrap_a_sum_that_rounds_to_one() {
    let root = crate::support::root();
    let corpus = raylemma::check::accuracy::corpus::load(&root.join("data/corpus/wavelength.txt"))
        .expect("the corpus reads");
    for question in [
        "hero_uniform 0.24999999999999997",
        "hero_uniform 0.49999999999999994",
    ] {
        let case = corpus
            .cases
            .iter()
            .find(|c| c.question == question)
            .expect("the case is in the corpus");
        let got = hero_uniform(case.args[0]).lambda;
        for (g, e) in got.iter().zip(case.exact.as_ref().expect("an answer")) {
            assert!(
                (g - e.double).abs() <= 2.0 * f64::EPSILON * e.double,
                "{question}: {got:?}, exact {}",
                e.text
            );
        }
    }
    assert_eq!(rotate01(0.25 - 2f64.powi(-55), 0.75), 1.0);
    assert_eq!(rotate01(0.75, 0.25), 0.0);
}
