//! The one error type of the statistical tests.
//!
//! A statistical test that is fed malformed input must neither panic nor pass: each
//! variant names what is wrong, where (the cell or the sample index) and with what value,
//! so that the message alone locates the bug in the code under test.

use std::fmt;

/// What the chi-squared test's message says when every cell expects too few samples to
/// test (the remedy is more samples, not another sampler); `raylemma check` reads it as bad
/// input.
pub(crate) const DRAW_MORE: &str = "draw more samples";

/// Why a statistical test could not be carried out.
#[derive(Debug, Clone, PartialEq)]
pub enum StatsError {
    /// Two inputs that must have the same length do not.
    LengthMismatch {
        /// What the two inputs are, e.g. `"observed and expected counts"`.
        what: &'static str,
        /// Length of the first input.
        left: usize,
        /// Length of the second input.
        right: usize,
    },
    /// There is no data at all.
    Empty {
        /// What is empty, e.g. `"samples"`.
        what: &'static str,
    },
    /// There is some data, but too little for the test.
    TooFewSamples {
        /// What was counted, e.g. `"summary"`.
        what: &'static str,
        /// How many values there are.
        n: u64,
        /// How many the test needs.
        needed: u64,
    },
    /// A sample is NaN or infinite.
    NonFiniteSample {
        /// Which input holds it, e.g. `"samples"`, `"sample a"`, `"summary"`.
        what: &'static str,
        /// Its index in that input, in the order given (0-based).
        index: u64,
        /// The value.
        value: f64,
    },
    /// An expected count is negative, NaN or infinite.
    InvalidExpected {
        /// The cell (index into the slices given).
        cell: usize,
        /// The expected count.
        value: f64,
    },
    /// Samples fell into a cell over which the pdf integrates to exactly 0.
    SamplesWherePdfIsZero {
        /// The cell.
        cell: usize,
        /// How many samples it holds.
        count: u64,
    },
    /// The expected counts do not add up to the number of samples: the pdf does not
    /// integrate to 1 (or the expected counts were not scaled by the sample count).
    NotNormalised {
        /// `sum(expected) / sum(observed)`: what the pdf integrates to.
        integral: f64,
        /// `sum(expected)`.
        expected_total: f64,
        /// `sum(observed)`.
        observed_total: u64,
    },
    /// Fewer than two cells remain after pooling: the test has no degree of freedom.
    TooFewCells {
        /// Cells left after pooling.
        cells: usize,
        /// The pooling threshold that was used.
        min_expected: f64,
    },
    /// The CDF returned NaN or a value outside `[0, 1]`.
    CdfOutOfRange {
        /// Where it was evaluated.
        x: f64,
        /// What it returned.
        value: f64,
    },
    /// The CDF decreased between two samples `x0 < x1`.
    CdfNotMonotone {
        /// The smaller sample.
        x0: f64,
        /// `cdf(x0)`.
        f0: f64,
        /// The larger sample.
        x1: f64,
        /// `cdf(x1)`, smaller than `f0`.
        f1: f64,
    },
    /// A sample of the sampler under test cannot be binned: not finite, outside its
    /// domain, or where the claimed pdf is not positive and finite (a renderer divides by
    /// it).
    InvalidSample {
        /// Its index, in the order drawn.
        index: u64,
        /// The sample.
        sample: glam::DVec3,
        /// What is wrong with it, in words.
        problem: String,
    },
    /// The claimed pdf is negative or not finite at a point where a cell's probability is
    /// integrated.
    InvalidPdf {
        /// The cell: its row and column.
        cell: (usize, usize),
        /// The point, in the cell's coordinates.
        at: (f64, f64),
        /// The pdf there.
        value: f64,
    },
    /// A parameter of the test itself (not the data) is invalid.
    InvalidArgument {
        /// Which parameter and what it must be.
        what: &'static str,
        /// Its value.
        value: f64,
    },
}

impl fmt::Display for StatsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::LengthMismatch { what, left, right } => {
                write!(f, "{what} differ in length: {left} and {right}")
            }
            Self::Empty { what } => write!(f, "no {what}: a test needs data"),
            Self::TooFewSamples { what, n, needed } => {
                write!(
                    f,
                    "{what} holds {n} values; the test needs at least {needed}"
                )
            }
            Self::NonFiniteSample { what, index, value } => {
                write!(f, "{what}[{index}] is {value}: every sample must be finite")
            }
            Self::InvalidExpected { cell, value } => write!(
                f,
                "the expected count of cell {cell} is {value}: expected counts must be finite and non-negative"
            ),
            Self::SamplesWherePdfIsZero { cell, count } => write!(
                f,
                "{count} samples in cell {cell} where the pdf integrates to 0"
            ),
            Self::NotNormalised {
                integral,
                expected_total,
                observed_total,
            } => write!(
                f,
                "the pdf integrates to {integral:.6}, not 1 (expected counts sum to {expected_total} for {observed_total} samples)"
            ),
            Self::TooFewCells {
                cells,
                min_expected,
            } => write!(
                f,
                "{cells} cell(s) left after pooling cells expecting fewer than {min_expected}: the test needs at least 2 ({DRAW_MORE})"
            ),
            Self::CdfOutOfRange { x, value } => {
                write!(f, "cdf({x}) = {value}: a CDF takes values in [0, 1]")
            }
            Self::CdfNotMonotone { x0, f0, x1, f1 } => write!(
                f,
                "the cdf decreases: cdf({x0}) = {f0} but cdf({x1}) = {f1}, although {x0} < {x1}"
            ),
            Self::InvalidSample {
                index,
                sample,
                ref problem,
            } => write!(
                f,
                "sample {index} = {}: {problem}",
                crate::numeric::tuple_text(sample.to_array())
            ),
            Self::InvalidPdf {
                cell: (i, j),
                at: (s, t),
                value,
            } => write!(
                f,
                "the pdf is {value} (negative or not finite) in cell ({i}, {j}) at cell coordinates ({s:.6}, {t:.6})"
            ),
            Self::InvalidArgument { what, value } => {
                write!(f, "invalid argument: {what} (got {value})")
            }
        }
    }
}

impl std::error::Error for StatsError {}
