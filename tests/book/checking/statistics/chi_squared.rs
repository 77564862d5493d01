//! Chi-squared: published values.

use super::*;

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
