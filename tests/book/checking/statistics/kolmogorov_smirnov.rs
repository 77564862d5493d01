//! Kolmogorov-Smirnov: published values and closed forms.

use super::*;

#[test]
fn kolmogorov_matches_marsaglia_tsang_wang_example() {
    // Marsaglia, Tsang & Wang (2003), J. Stat. Softw. 8(18), section 2: K(10, 0.274).
    assert_rel(kolmogorov_cdf(10, 0.274), 0.628_479_615_456_504_3, 1e-13);
}

#[test]
fn kolmogorov_matches_fergusons_example() {
    // T. S. Ferguson's KS calculator (UCLA, "The Kolmogorov-Smirnov Goodness-of-Fit
    // Test"): P(D_100 <= 0.1) = .74731.
    assert!((kolmogorov_cdf(100, 0.1) - 0.74731).abs() < 5e-6);
    assert!((1.0 - ks::p_value(100, 0.1) - 0.74731).abs() < 5e-6);
}

#[test]
fn kolmogorov_closed_forms() {
    for n in [1usize, 2, 3, 7, 20, 100] {
        let nf = n as f64;
        let factorial: f64 = (1..=n).map(|i| i as f64).product();
        for t in [0.1, 0.5, 0.9] {
            // For 1/(2n) < d <= 1/n: P(D_n < d) = n! (2d - 1/n)^n.
            let d = (0.5 + 0.5 * t) / nf;
            assert_rel(
                kolmogorov_cdf(n, d),
                factorial * (2.0 * d - 1.0 / nf).powi(n as i32),
                1e-11,
            );
            // For max(1 - 1/n, 1/2) <= d < 1: P(D_n >= d) = 2 (1 - d)^n.
            let d = 1.0 - t * (1.0 / nf).min(0.5);
            assert_rel(ks::p_value(n, d), 2.0 * (1.0 - d).powi(n as i32), 1e-11);
        }
        assert_eq!(kolmogorov_cdf(n, 0.5 / nf), 0.0);
        assert_eq!(kolmogorov_cdf(n, 1.0), 1.0);
    }
}

#[test]
fn ks_critical_values_bracket_the_tables() {
    // Two-sided critical values of D_n (L. H. Miller, "Table of percentage points of
    // Kolmogorov statistics", JASA 51, 1956), as printed to 3 decimals in the usual
    // tables: (n, alpha, D). The exact p-value must cross alpha within +-0.001 of D.
    for (n, alpha, d) in [
        (10, 0.05, 0.409),
        (10, 0.01, 0.489),
        (20, 0.05, 0.294),
        (20, 0.01, 0.352),
    ] {
        let (above, below) = (ks::p_value(n, d - 0.001), ks::p_value(n, d + 0.001));
        assert!(
            above > alpha && alpha > below,
            "n = {n}: p({d} -+ 0.001) = {above}, {below}"
        );
    }
    // Upper percentage points of Kolmogorov's limit law for sqrt(n) D, as printed to 3
    // decimals by Stephens ("EDF statistics for goodness of fit", JASA 69, 1974, table
    // 1A, case 0): 1.224 (10 %), 1.358 (5 %), 1.628 (1 %).
    for (lambda, alpha) in [(1.224, 0.10), (1.358, 0.05), (1.628, 0.01)] {
        let (above, below) = (kolmogorov_sf(lambda - 0.001), kolmogorov_sf(lambda + 0.001));
        assert!(
            above > alpha && alpha > below,
            "Q({lambda} -+ 0.001) = {above}, {below}"
        );
    }
}

#[test]
fn ks_tail_formula_agrees_with_the_matrix() {
    // Where p_value switches from 1 - K (matrix) to 2 P(D+ >= d) (n d² = 3), and beyond,
    // the two agree to 1e-7 relative, and the doubled tail is never below the truth.
    for n in [5usize, 10, 50, 99, 100, 200, 500, 1000] {
        for s in [3.0, 4.0, 6.0] {
            let d = (s / n as f64).sqrt();
            if d >= 1.0 {
                continue;
            }
            let matrix = 1.0 - kolmogorov_cdf(n, d);
            let tail = 2.0 * smirnov_upper_tail(n, d);
            assert_rel(tail, matrix, 1e-7);
            assert!(tail >= matrix * (1.0 - 1e-9), "n {n} s {s}");
        }
    }
    // Above d = 1/2 the events D+ >= d and D- >= d exclude each other: exactly equal.
    assert_rel(
        2.0 * smirnov_upper_tail(10, 0.6),
        1.0 - kolmogorov_cdf(10, 0.6),
        1e-12,
    );
}

#[test]
fn ks_p_value_is_a_tail_function() {
    // For every n, p_value(n, .) is a non-increasing map of [0, 1] onto [0, 1]: no NaN,
    // no jump up where the method changes (matrix, Smirnov tail, limit law).
    for n in [1usize, 2, 3, 10, 99, 100, 999, 1000, 1001, 5000] {
        let mut previous = 1.0;
        for i in 0..=4000 {
            let d = f64::from(i) / 4000.0;
            let p = ks::p_value(n, d);
            assert!((0.0..=1.0).contains(&p), "n {n} d {d}: p = {p}");
            assert!(
                p <= previous * (1.0 + 1e-9),
                "n {n}: p rises at d = {d}: {previous} -> {p}"
            );
            previous = p;
        }
        assert_eq!(ks::p_value(n, 0.0), 1.0);
        assert!(ks::p_value(n, 1.0) < 1e-300);
    }
    // P(D+ >= d) -> 1 as d -> 0, without NaN from rounding at j = n (1 - d).
    assert_rel(smirnov_upper_tail(10, 1e-18), 1.0, 1e-12);
}

#[test]
fn ks_exact_and_asymptotic_meet_at_n_1000() {
    // At the switch from exact to asymptotic, the two agree to 5 % down to p = 1e-6.
    let n = ks::EXACT_MAX_N;
    for s in [0.5f64, 1.0, 2.0, 3.0, 5.0, 6.5, 7.0] {
        let d = (s / n as f64).sqrt();
        let exact = ks::p_value(n, d);
        let asymptotic = ks::p_value(n + 1, d);
        assert!(exact > 1e-6);
        assert_rel(asymptotic, exact, 5e-2);
    }
}
