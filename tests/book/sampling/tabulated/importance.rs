//! Importance sampling with a table (the source's estimator and its support condition).

use super::*;

/// The estimator `(1/N) sum f(x_i) / q(x_i)` with `x_i` drawn from `q`.
fn estimate(seed: u64, n: usize, q: &Piecewise1D, f: impl Fn(f64) -> f64) -> Summary {
    let mut rng = rng::seeded(seed);
    Summary::of((0..n).map(|_| {
        let s = q.sample(rng.random::<f64>());
        f(s.x) / s.pdf
    }))
}

/// With `q` proportional to `f`, every term equals the integral: zero variance.
#[test]
fn table_proportional_to_integrand_gives_zero_variance() {
    let t = spiky();
    let q = t.constant();
    let f = |x: f64| 7.0 * q.pdf(x);
    let mut rng = rng::seeded(60);
    for _ in 0..10_000 {
        let s = q.sample(rng.random::<f64>());
        let term = f(s.x) / s.pdf;
        assert!(
            (term - 7.0).abs() <= 4.0 * f64::EPSILON * 7.0,
            "{s:?}: {term}"
        );
    }
}

/// The source requires `q` nonzero "wherever f(x) p_X(x) is nonzero". When `p` vanishes
/// where `f` does not, that allows a `q` which misses part of `f`, and the estimate of
/// `∫ f` is biased. What is needed is `q > 0` wherever `f != 0`.
#[test]
fn seed_support_condition_is_not_sufficient() {
    // f = 1 on [0, 1]; p and q vanish on [0.4, 0.6); so does f p, as the source allows.
    let edges = [0.0, 0.4, 0.6, 1.0];
    let p = Piecewise1D::new(&edges, &[1.0, 0.0, 1.0]).unwrap();
    let f = |x: f64| if (0.0..1.0).contains(&x) { 1.0 } else { 0.0 };
    let seed_ok = p.pdf(0.5) == 0.0 && f(0.5) * p.pdf(0.5) == 0.0;
    assert!(seed_ok);
    let biased = estimate(61, 100_000, &p, f);
    let test = ttest::one_sample(&biased, 1.0).unwrap();
    assert!(test.p_value < test_alpha(), "{test:?}");
    assert!((biased.mean - 0.8).abs() < 1e-9, "{}", biased.mean); // misses 0.2 exactly
    // q > 0 wherever f != 0: unbiased.
    let q = Piecewise1D::new(&edges, &[1.0, 0.1, 1.0]).unwrap();
    let fair = estimate(62, 100_000, &q, f);
    let test = ttest::one_sample(&fair, 1.0).unwrap();
    assert!(test.p_value >= test_alpha(), "{test:?}");
}

#[test]
fn uniform_constructors_place_the_last_edge_exactly() {
    let d = Piecewise1D::uniform(380.0, 780.0, &[1.0; 7]).unwrap();
    assert_eq!(d.edges().len(), 8);
    assert_eq!(d.edges()[7], 780.0);
    let d = Piecewise1D::from_fn(0.0, 1.0, 10, |x| x).unwrap();
    assert!((d.pdf(0.95) - 1.9).abs() < 1e-12);
    let l = PiecewiseLinear1D::uniform(380.0, 780.0, &[1.0; 81]).unwrap();
    assert_eq!((l.segments(), l.knots()[80]), (80, 780.0));
    assert!((l.integral() - 400.0).abs() < 1e-9);
}
