//! The piecewise-linear segment inverse: stable, exact in the limits.

use super::*;

/// The textbook root `(-a + sqrt(a^2 + xi (b^2 - a^2))) / (b - a)`.
fn segment_inverse_textbook(a: f64, b: f64, xi: f64) -> f64 {
    (-a + (a * a + xi * (b * b - a * a)).sqrt()) / (b - a)
}

#[test]
fn segment_inverse_is_exact_in_the_limits() {
    for xi in [0.0, 1e-300, 0.25, 0.5, 0.7, ONE_MINUS_EPSILON] {
        assert_eq!(segment_inverse(3.0, 3.0, xi), xi, "constant segment");
        assert_eq!(
            segment_inverse(1e-300, 1e-300, xi),
            xi,
            "tiny constant segment"
        );
        let ramp = segment_inverse(0.0, 2.0, xi);
        assert!(
            (ramp - xi.sqrt()).abs() <= f64::EPSILON * xi.sqrt(),
            "ramp: {ramp}"
        );
    }
    assert_eq!(segment_inverse(0.0, 1.0, 0.0), 0.0);
}

#[test]
fn segment_inverse_round_trips() {
    let mut rng = rng::seeded(41);
    let mut worst: f64 = 0.0;
    for _ in 0..200_000 {
        // A segment without mass is never sampled.
        let Some((a, b)) = raylemma::check::tabulated::hard_segment(&mut rng) else {
            continue;
        };
        let xi = rng.random::<f64>();
        let t = segment_inverse(a, b, xi);
        assert!(
            (0.0..=1.0).contains(&t),
            "a = {a:e}, b = {b:e}, xi = {xi}: t = {t}"
        );
        let err = (segment_cdf(a, b, t) - xi).abs() / f64::EPSILON;
        worst = max_abs([worst, err]);
        assert!(
            err <= 6.0,
            "a = {a:e}, b = {b:e}, xi = {xi}: error {err} units"
        );
    }
    println!("worst segment round trip: {worst:.2} units");
}

/// The textbook root is undefined for constant segments and loses most digits for
/// nearly constant ones: this is why the sampler uses the other form.
#[test]
fn textbook_quadratic_fails_on_nearly_constant_segments() {
    assert!(segment_inverse_textbook(2.0, 2.0, 0.5).is_nan());
    let (a, b) = (1.0, 1.0 + 1e-13);
    let (mut textbook, mut stable) = (0.0f64, 0.0f64);
    for k in 1..1000 {
        let xi = f64::from(k) / 1000.0 + 1e-7;
        let exact = xi + 0.5 * (b - a) * xi * (1.0 - xi); // to first order in b - a
        textbook = max_abs([textbook, segment_inverse_textbook(a, b, xi) - exact]);
        stable = max_abs([stable, segment_inverse(a, b, xi) - exact]);
    }
    assert!(stable <= 2.0 * f64::EPSILON, "stable {stable:e}");
    assert!(textbook >= 1e-4, "textbook {textbook:e}");
    println!("worst error for b - a = 1e-13: textbook {textbook:.1e}, stable {stable:.1e}");
}
