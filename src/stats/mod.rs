//! Statistical tests. Chapter: *Statistical tests* (`chapters/checking/statistics.md`).
//!
//! A sampling routine cannot be checked case by case: any single sample is possible. It
//! is checked by drawing many samples and asking whether what came out is *plausible*
//! under the claim ("the null hypothesis"). Each test here turns the samples into one
//! number, the p-value: the probability, if the claim is true, of a result at least as
//! extreme as the one observed. The claim is rejected when the p-value falls below a
//! significance level chosen in advance.
//!
//! * [`chi2::pearson`]: Pearson's chi-squared goodness of fit of binned counts against
//!   the counts a pdf predicts, with pooling of sparse cells.
//! * [`ks::one_sample`], [`ks::two_sample`]: Kolmogorov–Smirnov, unbinned, against a CDF
//!   or another sample; exact p-values for `n <= 1000` (Marsaglia, Tsang & Wang 2003).
//! * [`ttest::one_sample`], [`ttest::welch`]: Student's and Welch's t-tests of means, on
//!   running [`ttest::Summary`] values (Welford).
//! * [`welford`]: running means and variances (every accumulator of the project).
//! * [`binomial::wilson`]: the Wilson interval of a rate (false alarms, power).
//! * [`null`]: experiments in which each test's null is true, for its calibration.
//!
//! Every test returns `Result<_, StatsError>`: malformed input (a NaN sample, samples
//! where the pdf is zero, a pdf that does not integrate to 1) is an error that names the
//! offending cell or sample, never a panic and never a silent pass.
//!
//! ## The suite's significance level
//!
//! The project runs many statistical tests, and each one, at level `a`, fails by chance
//! with probability `a` even when the code is right. With `m` independent tests at
//! level `a`, the probability that *none* fails by chance is `(1 - a)^m`. Šidák's
//! correction chooses `a` so that this is `1 - SUITE_ALPHA`:
//!
//! `a = 1 - (1 - SUITE_ALPHA)^(1/m)`.
//!
//! [`SUITE_TESTS`] is a budget, not a count: as long as the suite holds at most that many
//! statistical tests, its family-wise false-failure rate is at most [`SUITE_ALPHA`]. Nothing
//! counts them automatically: a test file that holds many states its count in its opening
//! comment, and a test whose real false-failure rate is above its nominal level (Pearson's
//! test with cells expecting 5 to 10 samples is about twice as likely to fail at
//! [`test_alpha`]) uses up more than one test of the budget. (For
//! dependent tests Šidák's level is still valid for the usual positively dependent cases,
//! and Bonferroni's `SUITE_ALPHA / m`, smaller still, is valid always.)

pub mod binomial;
pub mod chi2;
pub mod error;
pub mod ks;
pub mod null;
pub mod ttest;
pub mod welford;

pub use error::StatsError;

// ANCHOR: suite
/// Significance level of the whole suite of statistical tests (family-wise): the
/// probability that a correct implementation fails *any* of them by chance.
pub const SUITE_ALPHA: f64 = 0.01;

/// Budget of statistical tests in the suite. Šidák with a larger `m` than the number of
/// tests actually run is conservative, so the budget may be generous.
pub const SUITE_TESTS: u32 = 200;

/// Šidák's per-test level for `m` independent tests with family-wise level `alpha`:
/// `1 - (1 - alpha)^(1/m)`.
///
/// Computed as `-expm1(ln1p(-alpha) / m)`: the naive form subtracts from 1 a number
/// within about `alpha / m` of it, losing about `-log10(alpha / m)` of its 16 digits.
///
/// # Panics
/// If `alpha` is not in `[0, 1]` or `m == 0`: both are programming errors in a
/// constant, and a NaN level would make every test silently pass.
pub fn sidak(alpha: f64, m: u32) -> f64 {
    assert!(
        (0.0..=1.0).contains(&alpha),
        "sidak: alpha = {alpha} is not a probability"
    );
    assert!(m > 0, "sidak: the number of tests m must be at least 1");
    -(f64::ln_1p(-alpha) / f64::from(m)).exp_m1()
}

/// The two-sided critical value `z` with `P(|Z| > z) = level` for a standard normal `Z`:
/// `sqrt(2) erfc^-1(level)` (the pooled tests of the renderer's checks and `compare`'s).
pub fn two_sided_critical(level: f64) -> f64 {
    std::f64::consts::SQRT_2 * statrs::function::erf::erfc_inv(level)
}

/// The per-test level every statistical test of the suite uses:
/// `sidak(SUITE_ALPHA, SUITE_TESTS)`, about `5.03e-5`.
pub fn test_alpha() -> f64 {
    sidak(SUITE_ALPHA, SUITE_TESTS)
}
// ANCHOR_END: suite
