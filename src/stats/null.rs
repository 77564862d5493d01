//! Experiments in which the null hypothesis of a test is true by construction. Chapter:
//! *Statistical tests* (`chapters/checking/statistics.md`).
//!
//! A test is calibrated when, with the null true, its p-value is uniform on `[0, 1]`. Each
//! [`NullCase`] draws such data with its own seed; the test suite checks that the p-values
//! of many runs are uniform, and the book's calibration table counts how often each test
//! rejects at the suite's level.

use rayon::prelude::*;

use crate::rng::{self, Rng, standard_normal};
use crate::stats::{StatsError, chi2, ks, ttest};

/// One experiment in which the null hypothesis of a test is true by construction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NullCase {
    /// Pearson's chi-squared: 1000 draws into 16 cells of geometric probabilities
    /// `∝ 0.7^i` (the sparsest cells are pooled), against their exact expectations.
    Chi2,
    /// One-sample KS, exact p-value: 100 uniform samples against the uniform CDF.
    KsExact,
    /// One-sample KS, asymptotic p-value: 2000 exponential samples (above
    /// [`ks::EXACT_MAX_N`], so the limit law is used) against the
    /// exponential CDF.
    KsAsymptotic,
    /// Two-sample KS: 200 and 301 standard normal samples.
    KsTwoSample,
    /// Student's one-sample t-test: 10 standard normal samples against mean 0.
    StudentT,
    /// Welch's t-test: 10 and 40 standard normal samples.
    Welch,
}

/// Every experiment, in the order of the figure and the table.
pub const NULL_CASES: [NullCase; 6] = [
    NullCase::Chi2,
    NullCase::KsExact,
    NullCase::KsAsymptotic,
    NullCase::KsTwoSample,
    NullCase::StudentT,
    NullCase::Welch,
];

/// Cells and draws of the [`NullCase::Chi2`] experiment.
const CHI2_CELLS: usize = 16;
const CHI2_DRAWS: u64 = 1000;

impl NullCase {
    /// Short name of the test.
    pub fn test(self) -> &'static str {
        match self {
            Self::Chi2 => "Pearson χ²",
            Self::KsExact => "KS, exact p",
            Self::KsAsymptotic => "KS, asymptotic p",
            Self::KsTwoSample => "KS, two samples",
            Self::StudentT => "Student t",
            Self::Welch => "Welch t",
        }
    }

    /// The experiment, in words.
    pub fn experiment(self) -> &'static str {
        match self {
            Self::Chi2 => "1000 draws into 16 cells with P ∝ 0.7^i, against N·P",
            Self::KsExact => "100 uniform samples against the uniform CDF",
            Self::KsAsymptotic => "2000 exponential samples against the exponential CDF",
            Self::KsTwoSample => "200 against 301 normal samples",
            Self::StudentT => "mean of 10 normal samples against 0",
            Self::Welch => "mean of 10 against mean of 40 normal samples",
        }
    }

    fn index(self) -> u64 {
        NULL_CASES.iter().position(|&c| c == self).unwrap_or(0) as u64
    }

    /// The p-value of one run of the experiment, with its own seed.
    ///
    /// # Errors
    /// Only if a test rejects its input, which for these well-formed inputs is a bug.
    pub fn p_value(self, seed: u64) -> Result<f64, StatsError> {
        let mut rng = self.rng(seed);
        Ok(match self {
            // Cells expecting fewer than 5 samples pooled, as everywhere in the project.
            Self::Chi2 => chi2_p_value(seed, 5.0)?,
            Self::KsExact => {
                let xs: Vec<f64> = (0..100).map(|_| rng::uniform(&mut rng, 0.0, 1.0)).collect();
                ks::one_sample(&xs, |x| x.clamp(0.0, 1.0))?.p_value
            }
            Self::KsAsymptotic => {
                let xs: Vec<f64> = (0..2000)
                    .map(|_| -(1.0 - rng::uniform(&mut rng, 0.0, 1.0)).ln())
                    .collect();
                ks::one_sample(&xs, |x| -(-x.max(0.0)).exp_m1())?.p_value
            }
            Self::KsTwoSample => {
                let (a, b) = two_samples(&mut rng);
                ks::two_sample(&a, &b)?.p_value
            }
            Self::StudentT => {
                let s = ttest::Summary::of(normals(&mut rng, 10));
                ttest::one_sample(&s, 0.0)?.p_value
            }
            Self::Welch => {
                let a = ttest::Summary::of(normals(&mut rng, 10));
                let b = ttest::Summary::of(normals(&mut rng, 40));
                ttest::welch(&a, &b)?.p_value
            }
        })
    }

    /// The generator of run `seed` of this experiment.
    fn rng(self, seed: u64) -> Rng {
        rng::seeded(0x5747_0000_0000 + (self.index() << 32) + seed)
    }

    /// The p-values of runs `0..runs`, in parallel.
    ///
    /// # Errors
    /// As [`NullCase::p_value`].
    pub fn p_values(self, runs: u64) -> Result<Vec<f64>, StatsError> {
        if self == Self::KsTwoSample {
            return two_sample_p_values(runs);
        }
        (0..runs).into_par_iter().map(|s| self.p_value(s)).collect()
    }
}

/// `n` standard normal samples.
fn normals(rng: &mut Rng, n: usize) -> Vec<f64> {
    (0..n).map(|_| standard_normal(rng)).collect()
}

/// The sizes of the two samples of [`NullCase::KsTwoSample`].
const TWO_SAMPLE_SIZES: (usize, usize) = (200, 301);

/// The samples of one run of [`NullCase::KsTwoSample`]: [`TWO_SAMPLE_SIZES`] normal values.
fn two_samples(rng: &mut Rng) -> (Vec<f64>, Vec<f64>) {
    let a = normals(rng, TWO_SAMPLE_SIZES.0);
    let b = normals(rng, TWO_SAMPLE_SIZES.1);
    (a, b)
}

/// [`NullCase::p_values`] of [`NullCase::KsTwoSample`], the same p-values as
/// [`NullCase::p_value`]'s. The p-value ([`ks::two_sample_p_value`], most of a run's cost)
/// is a function of the statistic `n_a n_b D` alone, an integer that takes far fewer
/// values than there are runs: each value's p-value is counted once.
fn two_sample_p_values(runs: u64) -> Result<Vec<f64>, StatsError> {
    let gaps: Vec<u128> = (0..runs)
        .into_par_iter()
        .map(|seed| {
            let (a, b) = two_samples(&mut NullCase::KsTwoSample.rng(seed));
            ks::two_sample_gap(&a, &b)
        })
        .collect::<Result<_, _>>()?;
    let mut distinct = gaps.clone();
    distinct.sort_unstable();
    distinct.dedup();
    let ps: Vec<f64> = distinct
        .par_iter()
        .map(|&gap| ks::two_sample_p_value(TWO_SAMPLE_SIZES.0, TWO_SAMPLE_SIZES.1, gap))
        .collect();
    Ok(gaps
        .iter()
        .map(|gap| ps[distinct.partition_point(|d| d < gap)])
        .collect())
}

/// The p-value of run `seed` of the [`NullCase::Chi2`] experiment, with the cells that
/// expect fewer than `min_expected` samples pooled ([`NullCase::p_value`] pools at 5; 0
/// pools nothing).
///
/// # Errors
/// As [`chi2::pearson`], which for these well-formed counts is a bug.
pub fn chi2_p_value(seed: u64, min_expected: f64) -> Result<f64, StatsError> {
    let (observed, expected) = geometric_counts(&mut NullCase::Chi2.rng(seed));
    Ok(chi2::pearson(&observed, &expected, min_expected)?.p_value)
}

/// [`chi2_p_value`] of runs `0..runs`, in parallel.
///
/// # Errors
/// As [`chi2_p_value`].
pub fn chi2_p_values(runs: u64, min_expected: f64) -> Result<Vec<f64>, StatsError> {
    Ok(chi2_p_values_pooled(runs, [min_expected])?
        .into_iter()
        .map(|[p]| p)
        .collect())
}

/// [`chi2_p_value`] of runs `0..runs` at each of the poolings `min_expected`, in
/// parallel: `result[seed][k]` is `chi2_p_value(seed, min_expected[k])`, with each run's
/// counts drawn once for all the poolings.
///
/// # Errors
/// As [`chi2_p_value`].
pub fn chi2_p_values_pooled<const K: usize>(
    runs: u64,
    min_expected: [f64; K],
) -> Result<Vec<[f64; K]>, StatsError> {
    (0..runs)
        .into_par_iter()
        .map(|seed| {
            let (observed, expected) = geometric_counts(&mut NullCase::Chi2.rng(seed));
            let mut ps = [0.0; K];
            for (p, &pool) in ps.iter_mut().zip(&min_expected) {
                *p = chi2::pearson(&observed, &expected, pool)?.p_value;
            }
            Ok(ps)
        })
        .collect()
}

/// Counts of [`NullCase::Chi2`]: `CHI2_DRAWS` draws by inversion into cells with
/// probabilities `∝ 0.7^i`, and the expected counts `N P_i`.
fn geometric_counts(rng: &mut Rng) -> (Vec<u64>, Vec<f64>) {
    let weights: Vec<f64> = (0..CHI2_CELLS).map(|i| 0.7f64.powi(i as i32)).collect();
    let total: f64 = weights.iter().sum();
    let mut cumulative = Vec::with_capacity(CHI2_CELLS);
    let mut acc = 0.0;
    for w in &weights {
        acc += w / total;
        cumulative.push(acc);
    }
    let mut observed = vec![0u64; CHI2_CELLS];
    for _ in 0..CHI2_DRAWS {
        let u = rng::uniform(rng, 0.0, 1.0);
        let cell = cumulative.partition_point(|&c| c <= u).min(CHI2_CELLS - 1);
        observed[cell] += 1;
    }
    let expected = weights
        .iter()
        .map(|w| CHI2_DRAWS as f64 * w / total)
        .collect();
    (observed, expected)
}
