//! Pearson's chi-squared goodness-of-fit test.
//!
//! `N` samples are sorted into cells; cell `i` receives `O_i` of them. If the samples
//! follow a pdf `p`, each one lands in cell `i` with probability `P_i = ∫_cell_i p`, so
//! the counts are multinomial with expectations `E_i = N P_i`. Pearson's statistic
//!
//! `X² = Σ_i (O_i - E_i)² / E_i`
//!
//! is, for large expectations, distributed as chi-squared with `k - 1` degrees of freedom
//! (`k` cells; one is lost because the counts must add up to `N`). The approximation is
//! poor for cells expecting few samples, so cells expecting fewer than `min_expected`
//! (5 by convention) are *pooled* into one cell before the statistic is formed.

use statrs::function::gamma::{checked_gamma_lr, checked_gamma_ur, ln_gamma};

use super::StatsError;

/// The outcome of [`pearson`].
#[derive(Clone, Debug, PartialEq)]
pub struct Chi2 {
    /// Pearson's statistic `X²` over the cells after pooling.
    pub statistic: f64,
    /// Degrees of freedom, `cells - 1`.
    pub dof: usize,
    /// `P(X² >= statistic)` under the null hypothesis.
    pub p_value: f64,
    /// Cells the statistic was summed over, after pooling (the pooled cell counts as one).
    pub cells: usize,
    /// How many of the original cells were merged into the pooled cell (0 if none).
    pub pooled_cells: usize,
}

// ANCHOR: upper_tail
/// Upper tail of the chi-squared distribution with `dof` degrees of freedom:
/// `P(X >= statistic) = Q(dof / 2, statistic / 2)`, the regularised upper incomplete
/// gamma function.
///
/// `Q` is evaluated directly (by its continued fraction when `statistic / 2 > dof / 2`),
/// not as `1 - P`, so a p-value of `1e-200` is returned as such instead of rounding to
/// 0 at `1e-16`. Returns 1 for `statistic <= 0`, 0 for `+inf`, NaN for NaN or `dof == 0`.
pub fn upper_tail(statistic: f64, dof: usize) -> f64 {
    if statistic.is_nan() || dof == 0 {
        return f64::NAN;
    }
    if statistic <= 0.0 {
        return 1.0;
    }
    if statistic == f64::INFINITY {
        return 0.0;
    }
    // Both arguments are finite and positive here, so the checked form cannot fail.
    checked_gamma_ur(dof as f64 / 2.0, statistic / 2.0).unwrap_or(f64::NAN)
}
// ANCHOR_END: upper_tail

/// The lower `p` quantile of the chi-squared distribution with `dof` degrees of freedom:
/// the `x` with `P(dof / 2, x / 2) = p`, `P` the regularised lower incomplete gamma
/// function, found by bisection on `ln x` to a relative `1e-12` (`ln_lower_gamma` keeps
/// `ln P` exact where `P` is far below the smallest double, so however small `p` is:
/// statrs' `inverse_cdf` stops at an absolute tolerance and returns 0 below about `1e-9`,
/// and its `gamma_lr` returns 0 below `x = 2.2e-15`). NaN unless `0 < p < 1` and `dof` is
/// positive and finite.
pub fn lower_quantile(p: f64, dof: f64) -> f64 {
    if !(p > 0.0 && p < 1.0 && dof > 0.0 && dof < 1e300) {
        return f64::NAN;
    }
    let a = dof / 2.0;
    let below = |ln_x: f64| ln_lower_gamma(a, ln_x - std::f64::consts::LN_2) < p.ln();
    // Bounds in ln x: the quantile is above e^-1e7 for any p >= 1e-300 and dof >= 2e-4
    // (P(a, y) <= y^a / Γ(a + 1)), and for most p below 2 dof + 100 + 40 sqrt(dof), which
    // grows until it is not.
    let (mut lo, mut hi) = (-1e7_f64, (2.0 * dof + 100.0 + 40.0 * dof.sqrt()).ln());
    for _ in 0..60 {
        if !below(hi) {
            break;
        }
        hi += 1.0;
    }
    for _ in 0..200 {
        if hi - lo <= 1e-12 {
            break;
        }
        let mid = 0.5 * (lo + hi);
        if below(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (0.5 * (lo + hi)).exp()
}

/// `ln P(a, y)` for `y = e^ln_y`: by the series `P = y^a e^-y / Γ(a + 1) Σ_n y^n / ((a + 1)
/// … (a + n))` in logarithms below `y = a + 1`, where `P` can be far below the smallest
/// double; from statrs' `gamma_lr` above, where it is not small.
fn ln_lower_gamma(a: f64, ln_y: f64) -> f64 {
    let y = ln_y.exp();
    if y < a + 1.0 {
        let (mut term, mut sum) = (1.0_f64, 1.0_f64);
        for n in 1..10_000 {
            term *= y / (a + f64::from(n));
            sum += term;
            if term <= 1e-17 * sum {
                break;
            }
        }
        a * ln_y - y - ln_gamma(a + 1.0) + sum.ln()
    } else {
        checked_gamma_lr(a, y).map_or(f64::NAN, f64::ln)
    }
}

// ANCHOR: validate
/// Checks the input of [`pearson`]; returns `sum(observed)`.
fn validate(observed: &[u64], expected: &[f64], min_expected: f64) -> Result<u64, StatsError> {
    if observed.len() != expected.len() {
        return Err(StatsError::LengthMismatch {
            what: "observed and expected counts",
            left: observed.len(),
            right: expected.len(),
        });
    }
    if observed.is_empty() {
        return Err(StatsError::Empty { what: "cells" });
    }
    if !(min_expected.is_finite() && min_expected >= 0.0) {
        return Err(StatsError::InvalidArgument {
            what: "min_expected must be finite and non-negative",
            value: min_expected,
        });
    }
    if let Some((cell, &value)) = expected
        .iter()
        .enumerate()
        .find(|(_, e)| !(e.is_finite() && **e >= 0.0))
    {
        return Err(StatsError::InvalidExpected { cell, value });
    }
    if let Some((cell, (&count, _))) = observed
        .iter()
        .zip(expected)
        .enumerate()
        .find(|(_, (o, e))| **o > 0 && **e == 0.0)
    {
        return Err(StatsError::SamplesWherePdfIsZero { cell, count });
    }
    let observed_total = observed.iter().fold(0u64, |s, &o| s.saturating_add(o));
    if observed_total == 0 {
        return Err(StatsError::Empty {
            what: "samples (all observed counts are 0)",
        });
    }
    let expected_total: f64 = expected.iter().sum();
    let n = observed_total as f64;
    if (expected_total - n).abs() > 1e-3 * n + 1.0 {
        return Err(StatsError::NotNormalised {
            integral: expected_total / n,
            expected_total,
            observed_total,
        });
    }
    Ok(observed_total)
}
// ANCHOR_END: validate

// ANCHOR: pearson
/// Pearson's chi-squared goodness of fit of `observed` counts against `expected` counts.
///
/// `expected[i]` must be `N ∫_cell_i p`, the sample count times the integral of the pdf
/// over the cell, so that `sum(expected) ≈ sum(observed) = N`.
///
/// Pooling (as in Nori's `warptest`): cells are sorted by ascending expected count; those
/// expecting fewer than `min_expected` are merged into one pooled cell, and while the
/// pooled cell itself expects fewer than `min_expected` the next-smallest ordinary cell
/// is merged into it too. Cells with `expected == 0` and no samples carry no information
/// and are left out. Then `X² = Σ (O - E)² / E` over the remaining cells, with
/// `cells - 1` degrees of freedom, and the p-value is [`upper_tail`]`(X², cells - 1)`.
///
/// # Errors
/// * [`StatsError::LengthMismatch`] if the slices differ in length, [`StatsError::Empty`]
///   if they are empty or hold no samples;
/// * [`StatsError::InvalidExpected`] for a negative or non-finite expected count;
/// * [`StatsError::SamplesWherePdfIsZero`] if a cell with `expected == 0` holds samples;
/// * [`StatsError::NotNormalised`] if `|sum(expected) - N| > 1e-3 N + 1`;
/// * [`StatsError::TooFewCells`] if fewer than 2 cells remain after pooling;
/// * [`StatsError::InvalidArgument`] if `min_expected` is negative or not finite.
pub fn pearson(observed: &[u64], expected: &[f64], min_expected: f64) -> Result<Chi2, StatsError> {
    validate(observed, expected, min_expected)?;
    let mut cells: Vec<(f64, f64)> = expected
        .iter()
        .zip(observed)
        .filter(|(e, _)| **e > 0.0)
        .map(|(&e, &o)| (e, o as f64))
        .collect();
    cells.sort_by(|a, b| a.0.total_cmp(&b.0));

    let (mut pooled_e, mut pooled_o, mut pooled_cells) = (0.0, 0.0, 0usize);
    let (mut statistic, mut count) = (0.0, 0usize);
    for (e, o) in cells {
        let pooling = pooled_cells > 0 && pooled_e < min_expected;
        if e < min_expected || pooling {
            pooled_e += e;
            pooled_o += o;
            pooled_cells += 1;
        } else {
            statistic += (o - e) * (o - e) / e;
            count += 1;
        }
    }
    if pooled_cells > 0 {
        statistic += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e;
        count += 1;
    }
    if count < 2 {
        return Err(StatsError::TooFewCells {
            cells: count,
            min_expected,
        });
    }
    let dof = count - 1;
    Ok(Chi2 {
        statistic,
        dof,
        p_value: upper_tail(statistic, dof),
        cells: count,
        pooled_cells,
    })
}
// ANCHOR_END: pearson
