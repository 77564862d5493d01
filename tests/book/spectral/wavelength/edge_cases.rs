//! Edge cases.

use super::*;

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
    for s in WavelengthStrategy::ALL {
        for u in [0.0, 0.25, 0.75, below] {
            let w = s.sample(u);
            for (l, p) in w.lambda.iter().zip(&w.pdf) {
                assert!(p.is_finite() && *p >= 0.0, "{}: u = {u}: pdf {p}", s.name());
                if s != WavelengthStrategy::SeedBand {
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
