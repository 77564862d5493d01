//! Tests of the chapter *Wavelength sampling and hero wavelengths*
//! (`src/spectral/wavelength.rs`).
//!
//! The t-tests run at `raylemma::stats::test_alpha()` (Šidák across the suite) with fixed
//! seeds. The exact values come from `cie::xyz` (Gauss-Legendre quadrature, a different
//! method from Monte Carlo), the visible pdf's constants from pbrt-v4's source. Every
//! estimator test has planted-bug twins, run on the same samples, that must be rejected.
//! Statistical tests in this file (correct code that must pass): 11.

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
/// Planted bugs, one per estimator, on the same samples: the uniform density of the seed's
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
// The seed's band.

/// The seed's estimator converges to `∫ w f` with the weight [`seed_band_weight`], not to
/// `∫ f`. Read with the range 400–700 nm, its Z of D65 is measurably low: rejected against
/// the exact Z, accepted against `∫ w f` (statistical test 11: this checks the derivation
/// of what the seed computes). Quadrature gives the bias for every reading
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

/// The seed claims its band "decreases noise". Its lanes lie within 15 nm of each other,
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

/// The seed band's weight has the shape its derivation gives: lane `j` covers
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
