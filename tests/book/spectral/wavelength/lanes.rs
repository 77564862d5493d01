//! Lane placement (found by mutation testing: with every lane on the hero the estimators
//! stay unbiased, so only the placement itself can show the mistake).

use super::*;

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
