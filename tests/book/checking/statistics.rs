//! Tests of the chapter *Statistical tests* (`chapters/checking/statistics.md`).
//!
//! Three kinds: the p-value machinery against published tables and closed forms; every
//! error path (malformed input must be an error naming what is wrong, never a panic and
//! never a pass); and power: each test rejects an obviously false null at `test_alpha()`
//! and accepts the true one at the same seed. The power and acceptance tests are
//! themselves statistical tests of the suite, at the suite's per-test level. Those that
//! correct code must pass (each a chance of a false failure): 26, of which the calibration
//! test makes 18; the acceptances of the KS, chi-squared and t power tests make 7, and the
//! thousand rounded uniforms 1.

use raylemma::rng;
use raylemma::rng::standard_normal;
use raylemma::stats::chi2::{pearson, upper_tail};
use raylemma::stats::ks::{self, kolmogorov_cdf, kolmogorov_sf, smirnov_upper_tail};
use raylemma::stats::null::{NULL_CASES, NullCase};
use raylemma::stats::ttest::{self, Summary, two_sided_p, welch};
use raylemma::stats::{SUITE_ALPHA, SUITE_TESTS, StatsError, sidak, test_alpha};

/// Asserts `|got / want - 1| <= rel`.
#[track_caller]
fn assert_rel(got: f64, want: f64, rel: f64) {
    assert!(
        (got / want - 1.0).abs() <= rel,
        "got {got:e}, want {want:e} (relative error {:e} > {rel:e})",
        got / want - 1.0
    );
}

// ---------------------------------------------------------------------------------------
// Šidák

#[test]
fn sidak_levels() {
    // One test: no correction.
    assert_rel(sidak(0.05, 1), 0.05, 1e-15);
    // 1 - 0.99^(1/100) = 1.004983e-4 (not the first-order -ln(0.99)/100 = 1.005034e-4).
    // References: 1 - exp(ln(0.99) / m) in 50-digit decimal arithmetic.
    assert_rel(sidak(0.01, 100), 1.004_983_082_416_679e-4, 1e-15);
    assert_rel(-(-0.01f64).ln_1p() / 100.0, 1.005_03e-4, 1e-5);
    // The suite's budget of 200: 1 - 0.99^(1/200) = 5.025042e-5, first-order 5.025168e-5.
    assert_rel(sidak(0.01, 200), 5.025_041_667_302_186e-5, 1e-15);
    assert_rel(-(-0.01f64).ln_1p() / 200.0, 5.025_168e-5, 1e-6);
    // The naive form 1 - (1 - alpha)^(1/m) subtracts from 1 a number within 1e-4 of it
    // and loses three to four of its sixteen digits.
    for (m, reference, lost) in [
        (100.0, 1.004_983_082_416_679e-4, 3e-14),
        (200.0, 5.025_041_667_302_186e-5, 3e-13),
    ] {
        let naive = 1.0 - 0.99f64.powf(1.0 / m);
        assert!(
            (naive / reference - 1.0).abs() > lost,
            "m = {m}: naive {naive:e}"
        );
    }
    assert_eq!(test_alpha(), sidak(SUITE_ALPHA, SUITE_TESTS));
    // Šidák lies between Bonferroni's alpha/m and -ln(1 - alpha)/m, for every m.
    for m in [1, 2, 10, 100, 1000, 1_000_000] {
        let a = sidak(SUITE_ALPHA, m);
        let mf = f64::from(m);
        assert!(
            SUITE_ALPHA / mf <= a && a <= -(-SUITE_ALPHA).ln_1p() / mf,
            "m = {m}: {a}"
        );
        // and it does what it claims: m tests at level a have family-wise level alpha.
        assert_rel(-(mf * (-a).ln_1p()).exp_m1(), SUITE_ALPHA, 1e-12);
    }
}

// ---------------------------------------------------------------------------------------
// Chi-squared: published values

/// Upper-tail critical values of the chi-squared distribution, from the NIST/SEMATECH
/// e-Handbook of Statistical Methods, section 1.3.6.7.4, "Critical Values of the
/// Chi-Square Distribution": `(dof, alpha, critical value)`.
const CHI2_CRITICAL: [(usize, f64, f64); 6] = [
    (1, 0.05, 3.841),
    (1, 0.01, 6.635),
    (10, 0.05, 18.307),
    (10, 0.01, 23.209),
    (100, 0.05, 124.342),
    (100, 0.01, 135.807),
];

#[test]
fn chi2_upper_tail_matches_nist_critical_values() {
    for (dof, alpha, critical) in CHI2_CRITICAL {
        // The table rounds to 3 decimals: a relative error of 1e-3 in p covers that.
        assert_rel(upper_tail(critical, dof), alpha, 1e-3);
    }
}

/// Observed and expected counts over `dof + 1` cells whose Pearson statistic is
/// `target`: every cell observes `N`, and expects `N (1 + s c_i)` with `sum c_i = 0`, so
/// `X² = N s² sum c_i² / (1 + s c_i)`, increasing in `s`; `s` is found by bisection.
fn counts_with_statistic(dof: usize, target: f64) -> (Vec<u64>, Vec<f64>) {
    const N: u64 = 10_000;
    let cells = dof + 1;
    let c: Vec<f64> = (0..cells)
        .map(|i| match (i == cells - 1, cells % 2 == 1, i % 2 == 0) {
            (true, true, _) => 0.0, // odd number of cells: the last one balances nothing
            (_, _, true) => 1.0,
            _ => -1.0,
        })
        .collect();
    let expected = |s: f64| -> Vec<f64> { c.iter().map(|ci| N as f64 * (1.0 + s * ci)).collect() };
    let statistic =
        |s: f64| -> f64 { expected(s).iter().map(|e| (N as f64 - e).powi(2) / e).sum() };
    let (mut lo, mut hi) = (0.0, 0.5);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if statistic(mid) < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (vec![N; cells], expected(0.5 * (lo + hi)))
}

#[test]
fn pearson_p_value_at_nist_critical_values() {
    for (dof, alpha, critical) in CHI2_CRITICAL {
        let (observed, expected) = counts_with_statistic(dof, critical);
        let r = pearson(&observed, &expected, 5.0).unwrap();
        assert_eq!((r.dof, r.cells, r.pooled_cells), (dof, dof + 1, 0));
        assert_rel(r.statistic, critical, 1e-9);
        assert_rel(r.p_value, alpha, 1e-3);
    }
}

#[test]
fn chi2_tiny_p_values_keep_their_digits() {
    // For even dof = 2k, P(X >= x) = exp(-x/2) sum_{j<k} (x/2)^j / j!  (a Poisson tail).
    for (dof, x) in [(2usize, 50.0f64), (10, 400.0), (10, 1000.0), (4, 1400.0)] {
        let half = x / 2.0;
        let mut term = 1.0;
        let mut sum = 0.0;
        for j in 0..dof / 2 {
            if j > 0 {
                term *= half / j as f64;
            }
            sum += term;
        }
        let exact = (-half).exp() * sum;
        assert!(exact > 0.0 && exact < 1e-10);
        assert_rel(upper_tail(x, dof), exact, 1e-9);
    }
    assert_eq!(upper_tail(0.0, 3), 1.0);
    assert_eq!(upper_tail(f64::INFINITY, 3), 0.0);
    assert!(upper_tail(f64::NAN, 3).is_nan());
}

#[test]
fn pearson_statistic_by_hand() {
    // A die rolled 60 times: X² = (4 + 1 + 0 + 1 + 9 + 1) / 10 = 1.6 with 5 dof.
    let r = pearson(&[12, 9, 10, 11, 7, 11], &[10.0; 6], 5.0).unwrap();
    assert_rel(r.statistic, 1.6, 1e-14);
    assert_eq!((r.dof, r.cells, r.pooled_cells), (5, 6, 0));
    assert_rel(r.p_value, upper_tail(1.6, 5), 1e-15);
}

#[test]
fn pearson_pools_sparse_cells() {
    // Expected 1, 2, 3, 4, 90, 100: 1+2+3 = 6 >= 5 after three cells; 4 < 5 joins as
    // well because every cell expecting fewer than 5 is pooled.
    let expected = [90.0, 1.0, 4.0, 100.0, 3.0, 2.0];
    let observed = [88, 2, 5, 101, 2, 2];
    let r = pearson(&observed, &expected, 5.0).unwrap();
    assert_eq!((r.cells, r.pooled_cells, r.dof), (3, 4, 2));
    let want = 4.0 / 90.0 + 1.0 / 100.0 + 1.0 / 10.0;
    assert_rel(r.statistic, want, 1e-14);

    // Expected 1, 1, 6, 92: the two small cells (2 < 5) pull in the next-smallest, 6.
    let r = pearson(&[1, 3, 5, 91], &[1.0, 1.0, 6.0, 92.0], 5.0).unwrap();
    assert_eq!((r.cells, r.pooled_cells), (2, 3));
    assert_rel(r.statistic, 1.0 / 8.0 + 1.0 / 92.0, 1e-14);

    // Cells expecting exactly 0 with no samples carry no information and are left out.
    let r = pearson(&[50, 0, 50], &[50.0, 0.0, 50.0], 5.0).unwrap();
    assert_eq!((r.cells, r.pooled_cells, r.dof), (2, 0, 1));
}

// ---------------------------------------------------------------------------------------
// Kolmogorov-Smirnov: published values and closed forms

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

// ---------------------------------------------------------------------------------------
// Student t: published values

#[test]
fn student_t_matches_nist_critical_values() {
    // NIST/SEMATECH e-Handbook, section 1.3.6.7.2, "Critical Values of the Student's t
    // Distribution" (upper-tail 0.025 and 0.005, i.e. two-sided 0.05 and 0.01).
    for (dof, alpha, critical) in [
        (10.0, 0.05, 2.228),
        (10.0, 0.01, 3.169),
        (30.0, 0.05, 2.042),
        (30.0, 0.01, 2.750),
        (100.0, 0.05, 1.984),
    ] {
        assert_rel(two_sided_p(critical, dof), alpha, 2e-3);
        assert_rel(two_sided_p(-critical, dof), alpha, 2e-3);
    }
}

#[test]
fn student_t_closed_forms_in_the_far_tail() {
    // dof 1 (Cauchy): p = (2/pi) atan(1/|t|); dof 2: p = 1 - |t| / sqrt(t² + 2).
    for t in [0.5f64, 3.0, 1e3, 1e6] {
        assert_rel(
            two_sided_p(t, 1.0),
            2.0 / std::f64::consts::PI * (1.0 / t).atan(),
            1e-10,
        );
        let s = (t * t + 2.0).sqrt();
        assert_rel(two_sided_p(t, 2.0), 2.0 / (s * (s + t)), 1e-10);
    }
    assert_eq!(two_sided_p(0.0, 5.0), 1.0);
    assert_eq!(two_sided_p(f64::INFINITY, 5.0), 0.0);
}

#[test]
fn one_sample_t_test_at_a_critical_value() {
    // Eleven values; choose mu0 so that t = 2.228 exactly with 10 dof.
    let xs: Vec<f64> = (0..11).map(|i| f64::from(i * i) / 7.0).collect();
    let s = Summary::of(xs.iter().copied());
    let mu0 = s.mean - 2.228 * s.std_error();
    let r = ttest::one_sample(&s, mu0).unwrap();
    assert_rel(r.t, 2.228, 1e-12);
    assert_eq!(r.dof, 10.0);
    assert_rel(r.p_value, 0.05, 2e-3);
}

#[test]
fn welch_by_hand() {
    // a = 1..=5 (mean 3, var 2.5), b = 2, 4, 6, 8 (mean 5, var 20/3).
    let a = Summary::of((1..=5).map(f64::from));
    let b = Summary::of([2.0, 4.0, 6.0, 8.0]);
    let r = welch(&a, &b).unwrap();
    let (va, vb): (f64, f64) = (2.5 / 5.0, 20.0 / 3.0 / 4.0);
    let dof = (va + vb) * (va + vb) / (va * va / 4.0 + vb * vb / 3.0);
    assert_rel(r.difference, -2.0, 1e-14);
    assert_rel(r.std_error, (va + vb).sqrt(), 1e-14);
    assert_rel(r.dof, dof, 1e-14);
    assert_rel(r.p_value, two_sided_p(-2.0 / (va + vb).sqrt(), dof), 1e-14);
}

#[test]
fn summary_is_welford_and_merges() {
    // Values near 1e9 with spread 1: the naive sum of squares would lose every digit.
    let xs: Vec<f64> = (0..1000).map(|i| 1e9 + f64::from(i % 10)).collect();
    let s = Summary::of(xs.iter().copied());
    assert_eq!(s.n, 1000);
    assert_rel(s.mean, 1e9 + 4.5, 1e-15);
    assert_rel(s.variance(), 8.25 * 1000.0 / 999.0, 1e-7);
    // The textbook one-pass formula (sum x² - n mean²) / (n - 1) is off by orders of magnitude.
    let naive = (xs.iter().map(|x| x * x).sum::<f64>() - 1000.0 * s.mean * s.mean) / 999.0;
    assert!(
        (naive / s.variance() - 1.0).abs() > 1.0,
        "naive variance {naive}"
    );
    // Merging two halves gives the summary of the whole.
    let (left, right) = xs.split_at(377);
    let merged = Summary::of(left.iter().copied()).merge(&Summary::of(right.iter().copied()));
    assert_eq!(merged.n, s.n);
    assert_rel(merged.mean, s.mean, 1e-15);
    assert_rel(merged.variance(), s.variance(), 1e-7);
    assert_eq!(Summary::default().merge(&s).n, s.n);
}

#[test]
fn zero_variance_is_decided_not_an_error() {
    let s = Summary::of([2.0; 5]);
    let same = ttest::one_sample(&s, 2.0).unwrap();
    assert_eq!((same.t, same.p_value), (0.0, 1.0));
    let other = ttest::one_sample(&s, 1.0).unwrap();
    assert_eq!((other.t, other.p_value), (f64::INFINITY, 0.0));
    let r = welch(&s, &Summary::of([3.0; 4])).unwrap();
    assert_eq!((r.t, r.p_value, r.dof), (f64::NEG_INFINITY, 0.0, 7.0));
    assert_eq!(welch(&s, &s).unwrap().p_value, 1.0);
}

// ---------------------------------------------------------------------------------------
// Error paths: each returns the right error, whose message says what is wrong.

#[test]
fn pearson_errors() {
    let e = pearson(&[1, 2], &[1.5], 5.0).unwrap_err();
    assert!(
        matches!(
            e,
            StatsError::LengthMismatch {
                left: 2,
                right: 1,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(matches!(
        pearson(&[], &[], 5.0),
        Err(StatsError::Empty { .. })
    ));
    assert!(matches!(
        pearson(&[0, 0], &[0.0, 0.0], 5.0),
        Err(StatsError::Empty { .. })
    ));

    let e = pearson(&[10, 10, 10], &[15.0, -1.0, 16.0], 5.0).unwrap_err();
    assert_eq!(
        e,
        StatsError::InvalidExpected {
            cell: 1,
            value: -1.0
        }
    );
    assert!(e.to_string().contains("cell 1"), "{e}");
    for bad in [f64::NAN, f64::INFINITY] {
        let e = pearson(&[10, 10], &[10.0, bad], 5.0).unwrap_err();
        assert!(
            matches!(e, StatsError::InvalidExpected { cell: 1, .. }),
            "{e:?}"
        );
    }

    // Samples in a cell where the pdf integrates to 0: a sampler leaking out of its domain.
    let e = pearson(&[50, 3, 47], &[50.0, 0.0, 50.0], 5.0).unwrap_err();
    assert_eq!(e, StatsError::SamplesWherePdfIsZero { cell: 1, count: 3 });
    assert_eq!(
        e.to_string(),
        "3 samples in cell 1 where the pdf integrates to 0"
    );

    // A pdf integrating to 2: expected counts twice the sample count.
    let e = pearson(&[50, 50], &[100.0, 100.0], 5.0).unwrap_err();
    match e {
        StatsError::NotNormalised { integral, .. } => assert_rel(integral, 2.0, 1e-15),
        _ => panic!("{e:?}"),
    }
    assert!(
        e.to_string().contains("integrates to 2.000000, not 1"),
        "{e}"
    );
    // Within 1e-3 N + 1 it is accepted (binning round-off); just outside it is not.
    assert!(pearson(&[500, 500], &[500.9, 500.0], 5.0).is_ok());
    assert!(pearson(&[500, 500], &[501.0, 501.1], 5.0).is_err());

    // Everything pooled into one cell: no degree of freedom left.
    let e = pearson(&[2, 1], &[1.5, 1.5], 5.0).unwrap_err();
    assert_eq!(
        e,
        StatsError::TooFewCells {
            cells: 1,
            min_expected: 5.0
        }
    );
    assert!(matches!(
        pearson(&[5, 5], &[5.0, 5.0], f64::NAN),
        Err(StatsError::InvalidArgument { .. })
    ));
}

#[test]
fn ks_errors() {
    let e = ks::one_sample(&[0.1, f64::NAN, 0.3], |x| x).unwrap_err();
    assert!(
        matches!(e, StatsError::NonFiniteSample { index: 1, .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("samples[1] is NaN"), "{e}");
    let e = ks::one_sample(&[0.1, 0.2, f64::INFINITY], |x| x).unwrap_err();
    assert!(
        matches!(e, StatsError::NonFiniteSample { index: 2, .. }),
        "{e:?}"
    );
    assert_eq!(
        ks::one_sample(&[], |x| x).unwrap_err(),
        StatsError::Empty { what: "samples" }
    );

    let e = ks::one_sample(&[0.5, 2.0], |x| x).unwrap_err();
    assert_eq!(e, StatsError::CdfOutOfRange { x: 2.0, value: 2.0 });
    let e = ks::one_sample(&[0.5], |_| f64::NAN).unwrap_err();
    assert!(
        matches!(e, StatsError::CdfOutOfRange { x: 0.5, .. }),
        "{e:?}"
    );
    let e = ks::one_sample(&[0.2, 0.1, 0.3], |x| 1.0 - x).unwrap_err();
    let (f0, f1) = (1.0 - 0.1, 1.0 - 0.2);
    assert_eq!(
        e,
        StatsError::CdfNotMonotone {
            x0: 0.1,
            f0,
            x1: 0.2,
            f1
        }
    );
    assert!(e.to_string().contains("decreases"), "{e}");

    let e = ks::two_sample(&[0.1, 0.2], &[0.3, f64::NEG_INFINITY]).unwrap_err();
    assert!(
        matches!(
            e,
            StatsError::NonFiniteSample {
                what: "sample b",
                index: 1,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(matches!(
        ks::two_sample(&[], &[1.0]),
        Err(StatsError::Empty { what: "sample a" })
    ));
}

#[test]
fn t_test_errors() {
    let mut s = Summary::of([1.0, 2.0, 3.0]);
    s.push(f64::NAN);
    s.push(4.0);
    assert_eq!(s.n, 5);
    assert!(s.mean.is_nan() && s.variance().is_nan());
    let e = ttest::one_sample(&s, 2.0).unwrap_err();
    assert!(
        matches!(e, StatsError::NonFiniteSample { index: 3, .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("summary[3] is NaN"), "{e}");

    let good = Summary::of([1.0, 2.0, 3.0]);
    let e = welch(&good, &s).unwrap_err();
    assert!(
        matches!(
            e,
            StatsError::NonFiniteSample {
                what: "summary b",
                index: 3,
                ..
            }
        ),
        "{e:?}"
    );
    // Merging keeps the index of the first bad value, counted in the merged stream.
    let e = ttest::one_sample(&good.merge(&s), 0.0).unwrap_err();
    assert!(
        matches!(e, StatsError::NonFiniteSample { index: 6, .. }),
        "{e:?}"
    );

    let one = Summary::of([1.0]);
    let e = ttest::one_sample(&one, 0.0).unwrap_err();
    assert_eq!(
        e,
        StatsError::TooFewSamples {
            what: "summary",
            n: 1,
            needed: 2
        }
    );
    assert!(matches!(
        welch(&one, &good),
        Err(StatsError::TooFewSamples {
            what: "summary a",
            ..
        })
    ));
    assert!(matches!(
        ttest::one_sample(&Summary::default(), 0.0),
        Err(StatsError::TooFewSamples { n: 0, .. })
    ));
    assert!(matches!(
        ttest::one_sample(&good, f64::NAN),
        Err(StatsError::InvalidArgument { .. })
    ));
}

// ---------------------------------------------------------------------------------------
// Power and acceptance: at test_alpha(), with fixed seeds.

fn uniforms(seed: u64, n: usize) -> Vec<f64> {
    let mut rng = rng::seeded(seed);
    (0..n).map(|_| rng::uniform(&mut rng, 0.0, 1.0)).collect()
}

#[test]
fn ks_rejects_a_wrong_distribution_and_accepts_the_right_one() {
    // u^1.1 is not uniform: its CDF is x^(1/1.1), at most 0.036 away from x.
    let us = uniforms(0xC0FFEE, 100_000);
    let warped: Vec<f64> = us.iter().map(|u| u.powf(1.1)).collect();
    let wrong = ks::one_sample(&warped, |x| x.clamp(0.0, 1.0)).unwrap();
    assert!(wrong.p_value < test_alpha(), "{wrong:?}");
    let right = ks::one_sample(&us, |x| x.clamp(0.0, 1.0)).unwrap();
    assert!(right.p_value > test_alpha(), "{right:?}");
    // The same pair against the warped CDF: the roles swap.
    let swapped = ks::one_sample(&warped, |x| x.clamp(0.0, 1.0).powf(1.0 / 1.1)).unwrap();
    assert!(swapped.p_value > test_alpha(), "{swapped:?}");

    // Exact p-values (n = 1000): u^1.3 rejected, u accepted.
    let us = &us[..1000];
    let warped: Vec<f64> = us.iter().map(|u| u.powf(1.3)).collect();
    assert!(
        ks::one_sample(&warped, |x| x.clamp(0.0, 1.0))
            .unwrap()
            .p_value
            < test_alpha()
    );
    assert!(ks::one_sample(us, |x| x.clamp(0.0, 1.0)).unwrap().p_value > test_alpha());

    // Two samples: 20 000 uniforms against 20 000 u^1.1, and against 20 000 more uniforms.
    let a = uniforms(1, 20_000);
    let b = uniforms(2, 20_000);
    let b_warped: Vec<f64> = b.iter().map(|u| u.powf(1.1)).collect();
    assert!(ks::two_sample(&a, &b_warped).unwrap().p_value < test_alpha());
    assert!(ks::two_sample(&a, &b).unwrap().p_value > test_alpha());
}

// ANCHOR: die
/// Rolls of a die whose face 0 has probability `(1 + bias) / 6` (the others share the rest).
fn die_counts(seed: u64, rolls: u64, bias: f64) -> [u64; 6] {
    let mut rng = rng::seeded(seed);
    let p0 = (1.0 + bias) / 6.0;
    let mut counts = [0u64; 6];
    for _ in 0..rolls {
        let u = rng::uniform(&mut rng, 0.0, 1.0);
        let face = if u < p0 {
            0
        } else {
            1 + (((u - p0) / (1.0 - p0) * 5.0) as usize).min(4)
        };
        counts[face] += 1;
    }
    counts
}

#[test]
fn pearson_rejects_a_biased_die_and_accepts_a_fair_one() {
    let rolls = 1_000_000;
    let fair = [rolls as f64 / 6.0; 6];
    let biased = pearson(&die_counts(0xD1CE, rolls, 0.02), &fair, 5.0).unwrap();
    assert!(biased.p_value < test_alpha(), "{biased:?}");
    let honest = pearson(&die_counts(0xD1CE, rolls, 0.0), &fair, 5.0).unwrap();
    assert!(honest.p_value > test_alpha(), "{honest:?}");
}
// ANCHOR_END: die

#[test]
fn t_tests_reject_a_shifted_mean_and_accept_the_true_one() {
    let normals = |seed: u64, n: usize, shift: f64| -> Summary {
        let mut rng = rng::seeded(seed);
        Summary::of((0..n).map(|_| standard_normal(&mut rng) + shift))
    };
    // Welch: means 0.1 sd apart, 1e5 samples each (t about 22).
    let a = normals(0xA, 100_000, 0.0);
    let shifted = welch(&a, &normals(0xB, 100_000, 0.1)).unwrap();
    assert!(shifted.p_value < test_alpha(), "{shifted:?}");
    let same = welch(&a, &normals(0xB, 100_000, 0.0)).unwrap();
    assert!(same.p_value > test_alpha(), "{same:?}");

    // Student: the mean of 1e6 uniforms is 0.5, not 0.502 (t about 7).
    let u = Summary::of(uniforms(0xE, 1_000_000));
    assert!(ttest::one_sample(&u, 0.502).unwrap().p_value < test_alpha());
    assert!(ttest::one_sample(&u, 0.5).unwrap().p_value > test_alpha());
}

/// Runs per experiment of `p_values_are_uniform_under_the_null`, as many as the
/// calibration table's: the uniformity test then sees a p-value off by about
/// `2.3 / sqrt(RUNS) = 0.016` anywhere.
const RUNS: u64 = 20_000;

#[test]
fn p_values_are_uniform_under_the_null() {
    // The experiments of the chapter's calibration figure: their p-values must pass a KS
    // test against the uniform distribution, and their rejection rates at 0.05 and 0.01
    // must lie within 4.5 binomial standard errors of the level (a two-sided normal tail
    // of 7e-6, below test_alpha()). Three statistical tests per experiment, 18 in all.
    for case in NULL_CASES {
        let ps = case.p_values(RUNS).unwrap();
        let r = ks::one_sample(&ps, |x| x.clamp(0.0, 1.0)).unwrap();
        assert!(r.p_value > test_alpha(), "{case:?}: {r:?}");
        for level in [0.05, 0.01] {
            let rejected = ps.iter().filter(|&&p| p < level).count() as f64;
            let (expected, sd) = (
                level * RUNS as f64,
                (level * (1.0 - level) * RUNS as f64).sqrt(),
            );
            assert!(
                (rejected - expected).abs() <= 4.5 * sd,
                "{case:?}: {rejected} rejected at {level}, expected {expected} +- {sd:.1}"
            );
        }
    }
    assert_eq!(NullCase::Chi2.p_value(7), NullCase::Chi2.p_value(7)); // reproducible
}

/// The exact two-sample p-value against an enumeration of every path of 5 and 7 samples,
/// and against an independent implementation (SciPy 1.17's exact two-sided method,
/// `scipy.stats._stats_py._attempt_exact_2kssamp`) for 200 and 301.
#[test]
fn ks_two_sample_exact_matches_the_paths() {
    use raylemma::stats::ks::two_sample_exact_p;
    // Every arrangement of 5 a's and 7 b's, as a bit mask of the positions of the a's.
    let (na, nb) = (5usize, 7usize);
    let mut gaps = Vec::new();
    for mask in 0u32..1 << (na + nb) {
        if mask.count_ones() as usize != na {
            continue;
        }
        let (mut i, mut j, mut gap) = (0i64, 0i64, 0i64);
        for k in 0..na + nb {
            if mask >> k & 1 == 1 {
                i += 1;
            } else {
                j += 1;
            }
            gap = gap.max((i * nb as i64 - j * na as i64).abs());
        }
        gaps.push(gap);
    }
    assert_eq!(gaps.len(), 792);
    for g in 1..=35i64 {
        let share = gaps.iter().filter(|&&x| x >= g).count() as f64 / 792.0;
        assert_rel(two_sample_exact_p(na, nb, g as u128), share, 1e-13);
    }
    for (gap, p) in [
        (3000u128, 0.906_320_053_631_967),
        (6020, 0.165_961_327_490_820_7),
        (8000, 0.025_530_171_911_849_62),
        (12000, 0.000_116_812_375_991_769_52),
        (15000, 4.847_868_099_475_522e-7),
    ] {
        assert_rel(two_sample_exact_p(200, 301, gap), p, 1e-9);
    }
    // D = 0 (identical samples) is certain.
    assert_eq!(two_sample_exact_p(200, 301, 0), 1.0);
    // The statistic two_sample reports is the gap over n_a n_b, and its p-value the count's.
    let a: Vec<f64> = (0..5).map(f64::from).collect();
    let b: Vec<f64> = (0..7).map(|k| f64::from(k) + 0.5).collect();
    let r = ks::two_sample(&a, &b).unwrap();
    let gap = (r.statistic * 35.0).round() as u128;
    assert_eq!(r.p_value, two_sample_exact_p(5, 7, gap));
}

/// Exercise 3's answer: without pooling, cells expecting one to four samples give X² a
/// tail heavier than chi-squared's, and the experiment of the calibration table rejects
/// more often than its level, most of all in the far tail: at 1e-4, over 100 000 runs,
/// more than 2.5 times as often as nominal, and more often than with the cells pooled.
#[test]
fn unpooled_cells_reject_too_often() {
    use raylemma::stats::null::chi2_p_values;
    let runs = 100_000u64;
    let rejected = |min_expected: f64| {
        chi2_p_values(runs, min_expected)
            .unwrap()
            .iter()
            .filter(|&&p| p < 1e-4)
            .count()
    };
    let (pooled, unpooled, nominal) = (rejected(5.0), rejected(0.0), runs as f64 * 1e-4);
    assert!(
        unpooled as f64 > 2.5 * nominal && unpooled > pooled,
        "at 1e-4: {unpooled} rejections unpooled, {pooled} pooled, {nominal} nominal"
    );
}

/// Exercise 5's answer: rounding uniforms to two decimals moves their empirical CDF by at
/// most 0.005, which the one-sample test sees with a million samples and not with a
/// thousand.
#[test]
fn ks_sees_rounding_only_with_many_samples() {
    let rounded = |n: usize| -> Vec<f64> {
        uniforms(0x71E5, n)
            .into_iter()
            .map(|u| (u * 100.0).round() / 100.0)
            .collect()
    };
    let uniform = |x: f64| x.clamp(0.0, 1.0);
    let many = ks::one_sample(&rounded(1_000_000), uniform).unwrap();
    assert!(many.p_value < test_alpha(), "{many:?}");
    let few = ks::one_sample(&rounded(1000), uniform).unwrap();
    assert!(few.p_value >= test_alpha(), "{few:?}");
}

// ---------------------------------------------------------------------------------------
// Exercises: each is ignored until you fill in its scaffold or answer
// (`cargo test --test book checking::statistics::exercise_ -- --ignored`).

/// Exercise 1 of *Statistical tests*: the integral `pearson` reports for the midpoint
/// expected counts.
const YOUR_ANSWER_1: Option<f64> = None;
/// Exercise 1: do the rescaled midpoint counts still reject the correct sampler?
const YOUR_ANSWER_1_RESCALED: Option<bool> = None;

#[test]
#[ignore = "exercise 1 of Statistical tests: fill in YOUR_ANSWER_1 and YOUR_ANSWER_1_RESCALED, then run it"]
fn exercise_1_midpoints_are_not_expected_counts() {
    let n = 1_000_000u64;
    let mut counts = vec![0u64; 10];
    for u in uniforms(0x3D, n as usize) {
        counts[((u.cbrt() * 10.0) as usize).min(9)] += 1;
    }
    let nf = n as f64;
    let cells = |k: usize| (k as f64 / 10.0, (k + 1) as f64 / 10.0);
    let exact: Vec<f64> = (0..10)
        .map(|k| {
            let (a, b) = cells(k);
            nf * (b * b * b - a * a * a)
        })
        .collect();
    let midpoint: Vec<f64> = (0..10)
        .map(|k| {
            let (a, b) = cells(k);
            let m = 0.5 * (a + b);
            nf * 3.0 * m * m * (b - a)
        })
        .collect();
    let right = pearson(&counts, &exact, 5.0).unwrap();
    assert!(right.p_value >= test_alpha(), "{right:?}");
    let integral = match pearson(&counts, &midpoint, 5.0) {
        Err(StatsError::NotNormalised { integral, .. }) => integral,
        other => panic!("the midpoint counts were not refused as unnormalised: {other:?}"),
    };
    let total: f64 = midpoint.iter().sum();
    let rescaled: Vec<f64> = midpoint.iter().map(|e| e * nf / total).collect();
    let rejects = pearson(&counts, &rescaled, 5.0).unwrap().p_value < test_alpha();
    let yours =
        YOUR_ANSWER_1.expect("exercise 1 of Statistical tests: YOUR_ANSWER_1 is still None");
    assert!(
        (yours - integral).abs() <= 1e-4,
        "pearson reports the integral {integral}, you predict {yours}"
    );
    assert_eq!(
        YOUR_ANSWER_1_RESCALED,
        Some(rejects),
        "rescaled to N, the midpoint counts reject the correct sampler: {rejects}"
    );
}

/// Exercise 2 of *Statistical tests*: the number of rolls at which a die with `b = 2 %` is
/// rejected at `test_alpha()` about half the time.
const YOUR_ANSWER_2: Option<u64> = None;

#[test]
#[ignore = "exercise 2 of Statistical tests: fill in YOUR_ANSWER_2, then run it"]
fn exercise_2_die_power_is_half_at_your_rolls() {
    let rolls =
        YOUR_ANSWER_2.expect("exercise 2 of Statistical tests: YOUR_ANSWER_2 is still None");
    let fair = [rolls as f64 / 6.0; 6];
    let rejected = (0..50u64)
        .filter(|&seed| {
            let counts = die_counts(0xD1CE_0000 + seed, rolls, 0.02);
            pearson(&counts, &fair, 5.0).unwrap().p_value < test_alpha()
        })
        .count();
    assert!(
        (13..=37).contains(&rejected),
        "{rejected} of 50 seeds rejected at {rolls} rolls: not about half"
    );
}

/// Exercise 4 of *Statistical tests*: the two-sided p-value of the classical two-sample
/// t-test with a pooled variance (`n_a + n_b - 2` degrees of freedom; `two_sided_p` gives
/// the tail).
fn your_pooled_t(a: &Summary, b: &Summary) -> f64 {
    let _ = (a, b);
    unimplemented!("exercise 4 of Statistical tests: the pooled-variance t-test")
}

#[test]
#[ignore = "exercise 4 of Statistical tests: fill in your_pooled_t, then run it"]
fn exercise_4_pooled_t_is_miscalibrated_for_unequal_variances() {
    let normals = |rng: &mut raylemma::rng::Rng, n: usize, sd: f64| -> Summary {
        Summary::of((0..n).map(|_| sd * standard_normal(rng)))
    };
    let (mut pooled, mut welchs) = (0u32, 0u32);
    let runs = 2000u32;
    for seed in 0..u64::from(runs) {
        let mut rng = rng::seeded(0x9001_0000 + seed);
        let (a, b) = (normals(&mut rng, 10, 3.0), normals(&mut rng, 40, 1.0));
        pooled += u32::from(your_pooled_t(&a, &b) < 0.05);
        welchs += u32::from(welch(&a, &b).unwrap().p_value < 0.05);
    }
    let rate = |k: u32| f64::from(k) / f64::from(runs);
    assert!(
        rate(pooled) > 0.15,
        "the pooled test rejects only {}",
        rate(pooled)
    );
    assert!(
        (rate(welchs) - 0.05).abs() <= 0.015,
        "Welch rejects {}",
        rate(welchs)
    );
}

/// Exercise 5 of *Statistical tests*: `(D, p)` of `ks::two_sample(&a, &a)`.
const YOUR_ANSWER_5: Option<(f64, f64)> = None;

#[test]
#[ignore = "exercise 5 of Statistical tests: fill in YOUR_ANSWER_5, then run it"]
fn exercise_5_two_sample_of_identical_samples() {
    let a = uniforms(0x5A, 1000);
    let r = ks::two_sample(&a, &a).unwrap();
    let yours =
        YOUR_ANSWER_5.expect("exercise 5 of Statistical tests: YOUR_ANSWER_5 is still None");
    assert_eq!(yours, (r.statistic, r.p_value));
}

#[test]
fn errors_are_std_errors() {
    fn takes(_: &dyn std::error::Error) {}
    takes(&StatsError::Empty { what: "samples" });
}
