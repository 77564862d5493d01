//! The visible pdf: against pbrt-v4's constants, its normalisation, its sampler.

use super::*;

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
