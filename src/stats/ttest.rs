//! Student's and Welch's t-tests of means, on running summaries.
//!
//! A Monte Carlo estimator is checked through its mean: is the average of `n` estimates
//! consistent with the known answer `mu0` (Student's one-sample test), or with the
//! average of another estimator (Welch's test)? By the central limit theorem the sample
//! mean is close to normal with standard error `s / sqrt(n)`; dividing the difference by
//! the *estimated* standard error gives Student's t distribution instead of the normal,
//! which matters when `n` is small.

use statrs::function::beta::checked_beta_reg;

use super::{StatsError, welford};

// ANCHOR: summary
/// Running count, mean and sum of squared deviations of a stream of values (Welford's
/// algorithm), so that means and variances of millions of samples need no storage.
///
/// Each push updates `mean += (x - mean) / n` and `m2 += (x - mean_old)(x - mean_new)`
/// ([`welford::update`], the project's one accumulator); unlike `Σx² - (Σx)²/n` this never
/// subtracts two large nearly equal sums.
///
/// NaN-safe: a NaN or infinite value is counted in `n` but poisons the summary (the mean
/// and variance become NaN) and is remembered, so that a test on the summary returns
/// [`StatsError::NonFiniteSample`] naming the first bad value's index instead of a
/// meaningless p-value.
#[derive(Clone, Copy, Debug, Default)]
pub struct Summary {
    /// Number of values pushed.
    pub n: u64,
    /// Their mean (NaN once a non-finite value was pushed).
    pub mean: f64,
    /// Sum of squared deviations from the mean.
    m2: f64,
    /// Index and value of the first non-finite value pushed, if any.
    first_non_finite: Option<(u64, f64)>,
}
// ANCHOR_END: summary

impl Summary {
    // ANCHOR: push
    /// Adds one value.
    pub fn push(&mut self, x: f64) {
        if self.first_non_finite.is_none() && !x.is_finite() {
            self.first_non_finite = Some((self.n, x));
        }
        if self.first_non_finite.is_some() {
            self.n += 1;
            self.mean = f64::NAN;
            self.m2 = f64::NAN;
            return;
        }
        welford::update(&mut self.n, &mut self.mean, &mut self.m2, x);
    }
    // ANCHOR_END: push

    /// The summary of `xs`.
    pub fn of(xs: impl IntoIterator<Item = f64>) -> Self {
        let mut s = Self::default();
        for x in xs {
            s.push(x);
        }
        s
    }

    /// Sample variance `m2 / (n - 1)` (unbiased); NaN for `n < 2` or after a non-finite value.
    pub fn variance(&self) -> f64 {
        if self.n < 2 {
            return f64::NAN;
        }
        self.m2 / (self.n - 1) as f64
    }

    /// Estimated standard error of the mean, `sqrt(variance / n)`.
    pub fn std_error(&self) -> f64 {
        (self.variance() / self.n as f64).sqrt()
    }

    /// Index and value of the first non-finite value pushed, if any.
    pub fn first_non_finite(&self) -> Option<(u64, f64)> {
        self.first_non_finite
    }

    // ANCHOR: merge
    /// The summary of both streams together (Chan, Golub & LeVeque 1979): with
    /// `δ = mean_b - mean_a` and `n = n_a + n_b`,
    /// `mean = mean_a + δ n_b / n` and `m2 = m2_a + m2_b + δ² n_a n_b / n`.
    /// Lets threads summarise separately and combine at the end.
    pub fn merge(&self, other: &Summary) -> Summary {
        let n = self.n + other.n;
        let first_non_finite = self
            .first_non_finite
            .or(other.first_non_finite.map(|(i, x)| (i + self.n, x)));
        if first_non_finite.is_some() {
            return Summary {
                n,
                mean: f64::NAN,
                m2: f64::NAN,
                first_non_finite,
            };
        }
        let (n, mean, m2) = welford::combine(
            (self.n, self.mean, self.m2),
            (other.n, other.mean, other.m2),
        );
        Summary {
            n,
            mean,
            m2,
            first_non_finite: None,
        }
    }
    // ANCHOR_END: merge

    /// Checks that the summary can be tested: no non-finite value and `n >= 2`.
    fn check(&self, what: &'static str) -> Result<(), StatsError> {
        if let Some((index, value)) = self.first_non_finite {
            return Err(StatsError::NonFiniteSample { what, index, value });
        }
        if self.n < 2 {
            return Err(StatsError::TooFewSamples {
                what,
                n: self.n,
                needed: 2,
            });
        }
        Ok(())
    }
}

/// The outcome of a t-test.
#[derive(Clone, Debug, PartialEq)]
pub struct TTest {
    /// `difference / std_error`.
    pub t: f64,
    /// Degrees of freedom of the t distribution the statistic is compared with.
    pub dof: f64,
    /// Two-sided p-value, `P(|T| >= |t|)`.
    pub p_value: f64,
    /// The difference tested: `mean - mu0`, or `mean_a - mean_b`.
    pub difference: f64,
    /// Its estimated standard error.
    pub std_error: f64,
}

// ANCHOR: two_sided
/// Two-sided tail of Student's t distribution with `dof` degrees of freedom:
/// `P(|T| >= |t|) = I_x(dof/2, 1/2)` with `x = dof / (dof + t²)`, the regularised
/// incomplete beta function. Evaluated directly, not as `1 - cdf`, so small p-values keep
/// their relative accuracy. 1 for `t = 0`, 0 for infinite `t`, NaN for NaN input or
/// `dof <= 0`.
pub fn two_sided_p(t: f64, dof: f64) -> f64 {
    if t.is_nan() || dof.is_nan() || dof <= 0.0 {
        return f64::NAN;
    }
    if t.is_infinite() {
        return 0.0;
    }
    let x = dof / (dof + t * t);
    checked_beta_reg(dof / 2.0, 0.5, x).unwrap_or(f64::NAN)
}
// ANCHOR_END: two_sided

/// Assembles a [`TTest`]; zero standard error is resolved without dividing by it.
fn finish(difference: f64, std_error: f64, dof: f64) -> TTest {
    let (t, p_value) = if std_error > 0.0 {
        let t = difference / std_error;
        (t, two_sided_p(t, dof))
    } else if difference == 0.0 {
        (0.0, 1.0)
    } else {
        (difference.signum() * f64::INFINITY, 0.0)
    };
    TTest {
        t,
        dof,
        p_value,
        difference,
        std_error,
    }
}

// ANCHOR: one_sample
/// Student's one-sample t-test of the mean of `s` against `mu0`:
/// `t = (mean - mu0) / (sd / sqrt(n))`, compared with Student's t with `n - 1` degrees
/// of freedom (exact for normal data, and by the central limit theorem a good
/// approximation for the means of many Monte Carlo samples).
///
/// Zero variance is not an error: all values are equal, so the mean is known exactly; the
/// p-value is 1 if it equals `mu0` and 0 otherwise (`t = ±inf`).
///
/// # Errors
/// [`StatsError::NonFiniteSample`] if a NaN or infinite value was pushed (its index),
/// [`StatsError::TooFewSamples`] for `n < 2`, [`StatsError::InvalidArgument`] for a
/// non-finite `mu0`.
pub fn one_sample(s: &Summary, mu0: f64) -> Result<TTest, StatsError> {
    s.check("summary")?;
    if !mu0.is_finite() {
        return Err(StatsError::InvalidArgument {
            what: "mu0 must be finite",
            value: mu0,
        });
    }
    Ok(finish(s.mean - mu0, s.std_error(), (s.n - 1) as f64))
}
// ANCHOR_END: one_sample

// ANCHOR: welch
/// Welch's t-test of `mean(a) - mean(b)`, not assuming equal variances:
/// with `v_a = s_a² / n_a` and `v_b = s_b² / n_b`, `t = (mean_a - mean_b) / sqrt(v_a + v_b)`,
/// compared with Student's t with the Welch–Satterthwaite degrees of freedom
///
/// `ν = (v_a + v_b)² / (v_a² / (n_a - 1) + v_b² / (n_b - 1))`,
///
/// which lie between `min(n_a, n_b) - 1` and `n_a + n_b - 2`.
///
/// If both variances are zero, `ν = n_a + n_b - 2` and the p-value is 1 for equal means,
/// 0 otherwise.
///
/// # Errors
/// As [`one_sample`], naming `"summary a"` or `"summary b"`.
pub fn welch(a: &Summary, b: &Summary) -> Result<TTest, StatsError> {
    a.check("summary a")?;
    b.check("summary b")?;
    let va = a.variance() / a.n as f64;
    let vb = b.variance() / b.n as f64;
    let v = va + vb;
    let dof = if v > 0.0 {
        // The same formula with the shares ra = va / v, rb = vb / v, so that tiny
        // variances cannot underflow when squared.
        let (ra, rb) = (va / v, vb / v);
        1.0 / (ra * ra / (a.n - 1) as f64 + rb * rb / (b.n - 1) as f64)
    } else {
        (a.n + b.n - 2) as f64
    };
    Ok(finish(a.mean - b.mean, v.sqrt(), dof))
}
// ANCHOR_END: welch
