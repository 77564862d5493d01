//! Running means and variances, one sample at a time (Welford 1962), and the combination of
//! two such summaries (Chan, Golub & LeVeque 1979). Chapter: *Statistical tests*
//! (`chapters/checking/statistics.md`); the renderer accumulates every pixel with it
//! (*The reference renderer*).
//!
//! One implementation for every accumulator of the project: [`Welford`] for any value that
//! adds, subtracts, multiplies componentwise and scales (`f64`, `DVec3`), used by the
//! renderer's pixels, and the t-tests' [`crate::stats::ttest::Summary`], which adds NaN
//! bookkeeping to the same recurrence ([`update`], [`combine`]).

use std::ops::{Add, Div, Mul, Sub};

/// A value Welford's recurrence can accumulate: `f64`, or a vector of them (componentwise).
pub trait Value:
    Copy
    + Default
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Mul<f64, Output = Self>
    + Div<f64, Output = Self>
{
}

impl<T> Value for T where
    T: Copy
        + Default
        + Add<Output = T>
        + Sub<Output = T>
        + Mul<Output = T>
        + Mul<f64, Output = T>
        + Div<f64, Output = T>
{
}

// ANCHOR: update
/// Adds the sample `x` to a summary of `n` samples with mean `mean` and sum of squared
/// deviations `m2`: the mean moves by `(x - mean) / (n + 1)` and the sum of squares by
/// `(x - mean_old)(x - mean_new)`, without the cancellation of `sum x^2 - n mean^2`.
pub fn update<T: Value>(n: &mut u64, mean: &mut T, m2: &mut T, x: T) {
    *n += 1;
    let delta = x - *mean;
    *mean = *mean + delta / *n as f64;
    *m2 = *m2 + delta * (x - *mean);
}
// ANCHOR_END: update

// ANCHOR: combine
/// The summary `(n, mean, m2)` of two streams together: with `δ = mean_b - mean_a` and
/// `n = n_a + n_b`, `mean = mean_a + δ n_b / n` and `m2 = m2_a + m2_b + δ² n_a n_b / n`.
/// Lets threads summarise separately and combine at the end.
pub fn combine<T: Value>(a: (u64, T, T), b: (u64, T, T)) -> (u64, T, T) {
    let ((na, ma, m2a), (nb, mb, m2b)) = (a, b);
    if na == 0 || nb == 0 {
        return if na == 0 { b } else { a };
    }
    let n = na + nb;
    let (fa, fb, f) = (na as f64, nb as f64, n as f64);
    let delta = mb - ma;
    (
        n,
        ma + delta * (fb / f),
        m2a + m2b + delta * delta * (fa * fb / f),
    )
}
// ANCHOR_END: combine

// ANCHOR: welford
/// A running count, mean and sum of squared deviations of a stream of values.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Welford<T> {
    n: u64,
    mean: T,
    m2: T,
}

impl<T: Value> Welford<T> {
    /// Adds one sample.
    pub fn push(&mut self, x: T) {
        update(&mut self.n, &mut self.mean, &mut self.m2, x);
    }

    /// The number of samples.
    pub fn count(&self) -> u64 {
        self.n
    }

    /// The mean of the samples (0 for none).
    pub fn mean(&self) -> T {
        self.mean
    }

    /// The sample variance `m2 / (n - 1)`; NaN for fewer than two samples.
    pub fn variance(&self) -> T {
        if self.n < 2 {
            return self.m2 / 0.0; // 0 / 0: NaN in every component
        }
        self.m2 / (self.n - 1) as f64
    }

    /// The variance of the mean, `s^2 / n = m2 / ((n - 1) n)`; NaN for fewer than two
    /// samples.
    pub fn var_of_mean(&self) -> T {
        if self.n < 2 {
            return self.m2 / 0.0;
        }
        let n = self.n as f64;
        self.m2 / ((n - 1.0) * n)
    }

    /// Both streams together ([`combine`]).
    pub fn merge(&self, other: &Self) -> Self {
        let (n, mean, m2) = combine(
            (self.n, self.mean, self.m2),
            (other.n, other.mean, other.m2),
        );
        Welford { n, mean, m2 }
    }
}
// ANCHOR_END: welford
