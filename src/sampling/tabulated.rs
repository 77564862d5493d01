//! Tabulated 1D distributions, sampled by inverting their CDF. Chapter: *Tabulated
//! distributions* (`chapters/sampling/tabulated.md`).
//!
//! A measured emission spectrum is a table: values at wavelengths. [`Piecewise1D`] reads
//! the table as a piecewise-constant density over bins (`n + 1` edges, `n` values);
//! [`PiecewiseLinear1D`] as a density that is linear between knots (`n` knots, `n`
//! values), which is how measured spectra are usually interpolated. Both normalise the
//! table, build its CDF once, and then map a uniform `u` in `[0, 1)` to a sample by a
//! binary search and an inversion within one bin.
//!
//! Both guarantee, for every `u` in `[0, 1]` (1 is treated as the largest `f64` below it):
//! the sample `x` lies in `[x_0, x_n)`, its returned pdf equals [`Piecewise1D::pdf`]`(x)`
//! exactly and is positive, so `x` never lies in a bin of zero density, not even at the
//! `u` of a plateau of the CDF.

use std::error::Error;
use std::fmt;

/// Why a table cannot be turned into a distribution. Every variant names the offending
/// entry (its index and value) or the two lengths that disagree.
#[derive(Clone, Debug, PartialEq)]
pub enum TableError {
    /// Fewer than two edges (or knots): there is no interval to sample.
    TooFewEdges {
        /// `"edges"` or `"knots"`.
        what: &'static str,
        /// How many were given.
        len: usize,
    },
    /// The number of values does not fit the number of edges (or knots).
    LengthMismatch {
        /// `"edges"` or `"knots"`.
        what: &'static str,
        /// How many edges or knots were given.
        edges: usize,
        /// How many values were given.
        values: usize,
        /// How many values those edges or knots need.
        needed: usize,
    },
    /// An edge or knot is NaN or infinite.
    NonFiniteEdge {
        /// `"edges"` or `"knots"`.
        what: &'static str,
        /// Its index.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// An edge or knot is not greater than the one before it.
    EdgesNotIncreasing {
        /// `"edges"` or `"knots"`.
        what: &'static str,
        /// Index of the edge that is not greater than its predecessor.
        index: usize,
        /// The predecessor, at `index - 1`.
        previous: f64,
        /// The edge itself.
        value: f64,
    },
    /// Two edges are so far apart that their distance overflows.
    BinTooWide {
        /// The bin (between edges `index` and `index + 1`).
        index: usize,
        /// Its left edge.
        lo: f64,
        /// Its right edge.
        hi: f64,
    },
    /// A value is negative, NaN or infinite: a density must be finite and non-negative.
    InvalidValue {
        /// Its index.
        index: usize,
        /// The value.
        value: f64,
    },
    /// Every value is zero: there is nothing to sample.
    AllZero {
        /// How many values were given.
        values: usize,
    },
    /// The values are finite but their integral overflows.
    IntegralOverflow {
        /// The bin at which the running sum first became infinite.
        index: usize,
    },
}

impl fmt::Display for TableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::TooFewEdges { what, len } => {
                write!(f, "{len} {what} given: a table needs at least 2")
            }
            Self::LengthMismatch {
                what,
                edges,
                values,
                needed,
            } => write!(
                f,
                "{values} values for {edges} {what}: {edges} {what} need exactly {needed} values"
            ),
            Self::NonFiniteEdge { what, index, value } => {
                write!(f, "{what}[{index}] = {value} is not finite")
            }
            Self::EdgesNotIncreasing {
                what,
                index,
                previous,
                value,
            } => write!(
                f,
                "{what}[{index}] = {value} is not greater than {what}[{}] = {previous}: {what} must increase strictly",
                index - 1
            ),
            Self::BinTooWide { index, lo, hi } => write!(
                f,
                "bin {index} from {lo:e} to {hi:e} is wider than the largest f64"
            ),
            Self::InvalidValue { index, value } => {
                let why = if value.is_nan() {
                    "NaN"
                } else if value.is_infinite() {
                    "infinite"
                } else {
                    "negative"
                };
                write!(
                    f,
                    "values[{index}] = {value} is {why}: a density must be finite and non-negative"
                )
            }
            Self::AllZero { values } => {
                write!(
                    f,
                    "all {values} values are zero: there is nothing to sample"
                )
            }
            Self::IntegralOverflow { index } => write!(
                f,
                "the integral of the table overflows f64 at bin {index}: scale the values down"
            ),
        }
    }
}

impl Error for TableError {}

/// The largest `f64` below 1: `1 - 2^-53`, the largest value a `[0, 1)` generator returns.
pub const ONE_MINUS_EPSILON: f64 = 1.0 - f64::EPSILON / 2.0;

// ANCHOR: validate
/// Checks `edges` (`what` names them in errors): at least two, finite, strictly
/// increasing, with every difference finite.
fn validate_edges(edges: &[f64], what: &'static str) -> Result<(), TableError> {
    if edges.len() < 2 {
        return Err(TableError::TooFewEdges {
            what,
            len: edges.len(),
        });
    }
    if let Some((index, &value)) = edges.iter().enumerate().find(|(_, e)| !e.is_finite()) {
        return Err(TableError::NonFiniteEdge { what, index, value });
    }
    for (index, pair) in edges.windows(2).enumerate() {
        if pair[0] >= pair[1] {
            return Err(TableError::EdgesNotIncreasing {
                what,
                index: index + 1,
                previous: pair[0],
                value: pair[1],
            });
        }
        if !(pair[1] - pair[0]).is_finite() {
            return Err(TableError::BinTooWide {
                index,
                lo: pair[0],
                hi: pair[1],
            });
        }
    }
    Ok(())
}

/// Checks that every value is finite and non-negative, and that one is positive.
fn validate_values(values: &[f64]) -> Result<(), TableError> {
    // `!(v >= 0)` rejects NaN as well as negative values; -0.0 is accepted as zero.
    if let Some((index, &value)) = values
        .iter()
        .enumerate()
        .find(|(_, v)| !(**v >= 0.0 && v.is_finite()))
    {
        return Err(TableError::InvalidValue { index, value });
    }
    if values.iter().all(|&v| v == 0.0) {
        return Err(TableError::AllZero {
            values: values.len(),
        });
    }
    Ok(())
}
// ANCHOR_END: validate

// ANCHOR: build_cdf
/// The normalised CDF at the edges from the masses of the bins, and the total mass.
///
/// `cdf[0] = 0`, `cdf[n] = 1` exactly, and `cdf` is non-decreasing: partial sums of
/// non-negative numbers never decrease in floating point (rounding is monotone), and
/// neither does dividing them by the same positive total. A bin of zero mass gives two
/// *equal* entries, a plateau, which [`bin_of`] never selects.
fn build_cdf(masses: impl Iterator<Item = f64>) -> Result<(Vec<f64>, f64), TableError> {
    let mut cdf = vec![0.0];
    let mut sum = 0.0;
    for (index, m) in masses.enumerate() {
        sum += m;
        if !sum.is_finite() {
            return Err(TableError::IntegralOverflow { index });
        }
        cdf.push(sum);
    }
    let total = sum;
    for c in &mut cdf {
        *c /= total;
    }
    Ok((cdf, total))
}
// ANCHOR_END: build_cdf

// ANCHOR: bin_of
/// The bin `i` with `cdf[i] <= u < cdf[i + 1]`, by binary search.
///
/// This is the *largest* `i` with `cdf[i] <= u`. On a plateau (`cdf[i] = cdf[i + 1]`, a
/// bin of zero mass) no `u` satisfies both inequalities, so a bin of zero mass is never
/// returned: at the plateau's own level `u = cdf[i]` the search moves on to the first
/// bin after it that has mass. `u >= 1` returns the last bin with mass.
fn bin_of(cdf: &[f64], last: usize, u: f64) -> usize {
    // Number of entries cdf[1..] that are <= u, i.e. the largest j with cdf[j] <= u,
    // since cdf[0] = 0 <= u.
    let i = cdf[1..].partition_point(|&c| c <= u);
    i.min(last)
}
// ANCHOR_END: bin_of

/// `u` as the samplers use it: NaN and negative values (which a correct generator never
/// produces) become 0, and values `>= 1` become [`ONE_MINUS_EPSILON`].
fn clamp_u(u: f64) -> f64 {
    debug_assert!(
        (0.0..=1.0).contains(&u),
        "u = {u} is not in [0, 1]: the generator is broken"
    );
    if u >= 1.0 {
        ONE_MINUS_EPSILON
    } else if u > 0.0 {
        u
    } else {
        0.0
    }
}

/// The last bin of positive probability (`cdf[i] < cdf[i + 1]`); one exists because the
/// table is not all zero and `cdf[n] = 1`.
fn last_bin(cdf: &[f64]) -> usize {
    (0..cdf.len() - 1)
        .rev()
        .find(|&i| cdf[i] < cdf[i + 1])
        .unwrap_or(0)
}

/// Index of the bin `[edges[i], edges[i + 1])` that holds `x`, if `x` is in
/// `[edges[0], edges[n])`.
fn bin_containing(edges: &[f64], x: f64) -> Option<usize> {
    if !(x >= edges[0] && x < edges[edges.len() - 1]) {
        return None;
    }
    Some(edges[1..].partition_point(|&e| e <= x))
}

/// A sample drawn from a tabulated distribution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// The sampled point, in `[x_0, x_n)`.
    pub x: f64,
    /// The density at `x`, positive and equal to `pdf(x)`.
    pub pdf: f64,
    /// The bin (or segment) of `x`.
    pub bin: usize,
}

/// A piecewise-constant density: bin `i` spans `[edges[i], edges[i + 1])` and has density
/// proportional to `values[i]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Piecewise1D {
    edges: Vec<f64>,
    /// `values[i] / integral`: the normalised density of bin `i`.
    density: Vec<f64>,
    /// The CDF at the edges, `cdf[0] = 0`, `cdf[n] = 1`.
    cdf: Vec<f64>,
    integral: f64,
    last: usize,
}

impl Piecewise1D {
    /// A density over `edges.len() - 1` bins with the given (unnormalised) bin values.
    ///
    /// # Errors
    /// A [`TableError`] naming the entry, if there are fewer than 2 edges, if
    /// `values.len() != edges.len() - 1`, if an edge is not finite or not greater than
    /// the previous one, if a value is negative, NaN or infinite, if all values are zero,
    /// or if the integral overflows.
    pub fn new(edges: &[f64], values: &[f64]) -> Result<Self, TableError> {
        validate_edges(edges, "edges")?;
        if values.len() != edges.len() - 1 {
            return Err(TableError::LengthMismatch {
                what: "edges",
                edges: edges.len(),
                values: values.len(),
                needed: edges.len() - 1,
            });
        }
        validate_values(values)?;
        // ANCHOR: constant_new
        let masses = values
            .iter()
            .zip(edges.windows(2))
            .map(|(v, e)| v * (e[1] - e[0]));
        let (cdf, integral) = build_cdf(masses)?;
        let density = values.iter().map(|v| v / integral).collect();
        // ANCHOR_END: constant_new
        let last = last_bin(&cdf);
        Ok(Self {
            edges: edges.to_vec(),
            density,
            cdf,
            integral,
            last,
        })
    }

    /// `values.len()` bins of equal width over `[lo, hi]`; the last edge is exactly `hi`.
    ///
    /// # Errors
    /// As [`Piecewise1D::new`].
    pub fn uniform(lo: f64, hi: f64, values: &[f64]) -> Result<Self, TableError> {
        Self::new(&uniform_grid(lo, hi, values.len() + 1), values)
    }

    /// `bins` bins of equal width over `[lo, hi]`, with `f` evaluated at each bin's centre.
    ///
    /// # Errors
    /// As [`Piecewise1D::new`].
    pub fn from_fn(
        lo: f64,
        hi: f64,
        bins: usize,
        f: impl Fn(f64) -> f64,
    ) -> Result<Self, TableError> {
        let edges = uniform_grid(lo, hi, bins + 1);
        let values: Vec<f64> = edges.windows(2).map(|e| f(0.5 * (e[0] + e[1]))).collect();
        Self::new(&edges, &values)
    }

    // ANCHOR: constant_sample
    // EXERCISE sampling/tabulated Piecewise1D::sample: sample the piecewise-constant table by its inverse CDF, never landing in a bin of zero mass
    /// Maps `u` in `[0, 1)` to a sample: the bin by binary search on the CDF, then the
    /// position within the bin by inverting the CDF there, which is linear.
    pub fn sample(&self, u: f64) -> Sample {
        let u = clamp_u(u);
        let i = bin_of(&self.cdf, self.last, u);
        let (c0, c1) = (self.cdf[i], self.cdf[i + 1]);
        let (x0, x1) = (self.edges[i], self.edges[i + 1]);
        // t in [0, 1) in exact arithmetic; rounding can give t = 1, or x = x1, which
        // lies in the *next* bin (perhaps one of zero density): keep x below x1.
        let t = (u - c0) / (c1 - c0);
        let x = (x0 + t * (x1 - x0)).min(x1.next_down());
        Sample {
            x,
            pdf: self.density[i],
            bin: i,
        }
    }
    // END EXERCISE
    // ANCHOR_END: constant_sample

    /// The normalised density at `x`: `values[i] / integral` in bin `i`, 0 outside
    /// `[x_0, x_n)`.
    pub fn pdf(&self, x: f64) -> f64 {
        bin_containing(&self.edges, x).map_or(0.0, |i| self.density[i])
    }

    /// The CDF at `x`: 0 below `x_0`, 1 from `x_n` on, linear within each bin (NaN for
    /// NaN).
    pub fn cdf(&self, x: f64) -> f64 {
        if x.is_nan() {
            return f64::NAN;
        }
        if x < self.edges[0] {
            return 0.0;
        }
        let Some(i) = bin_containing(&self.edges, x) else {
            return 1.0;
        };
        let (lo, hi) = (self.edges[i], self.edges[i + 1]);
        let (c_lo, c_hi) = (self.cdf[i], self.cdf[i + 1]);
        (c_lo + (x - lo) / (hi - lo) * (c_hi - c_lo)).min(c_hi)
    }

    /// The inverse of [`Piecewise1D::sample`]: the `u` that maps to `x`. It is the CDF
    /// (the sampler is `F^-1`, so its inverse is `F`).
    pub fn invert(&self, x: f64) -> f64 {
        self.cdf(x)
    }

    /// The integral of the table as given (before normalisation): `sum values[i] w_i`.
    pub fn integral(&self) -> f64 {
        self.integral
    }

    /// The edges `x_0 < ... < x_n`.
    pub fn edges(&self) -> &[f64] {
        &self.edges
    }

    /// The normalised CDF at the edges.
    pub fn cdf_table(&self) -> &[f64] {
        &self.cdf
    }

    /// Number of bins.
    pub fn bins(&self) -> usize {
        self.density.len()
    }

    /// Probability of bin `i`, `cdf[i + 1] - cdf[i]`.
    pub fn bin_probability(&self, i: usize) -> f64 {
        self.cdf[i + 1] - self.cdf[i]
    }
}

/// `points` equally spaced points from `lo` to `hi` inclusive (`hi` exactly).
pub(crate) fn uniform_grid(lo: f64, hi: f64, points: usize) -> Vec<f64> {
    let steps = points.saturating_sub(1).max(1) as f64;
    (0..points)
        .map(|k| {
            if k + 1 == points {
                hi
            } else {
                lo + (hi - lo) * (k as f64 / steps)
            }
        })
        .collect()
}

/// A piecewise-linear density: proportional to `values[i]` at `knots[i]`, linear between.
#[derive(Clone, Debug, PartialEq)]
pub struct PiecewiseLinear1D {
    knots: Vec<f64>,
    /// `values[i] / integral`: the normalised density at knot `i`.
    density: Vec<f64>,
    /// The CDF at the knots, `cdf[0] = 0`, `cdf[n - 1] = 1`.
    cdf: Vec<f64>,
    integral: f64,
    last: usize,
}

// ANCHOR: segment_inverse
/// Within a segment whose density goes linearly from `a` at `t = 0` to `b` at `t = 1`
/// (`a, b >= 0`, not both 0), the `t` in `[0, 1]` below which a fraction `xi` of the
/// segment's mass lies: the root of `(b - a) t^2 / 2 + a t = xi (a + b) / 2`.
///
/// Written as `t = xi (a + b) / (a + sqrt((1 - xi) a^2 + xi b^2))`, the root of the
/// quadratic that involves no cancellation (every term is non-negative), is exact for
/// `a = b` (`t = xi`, bit for bit), gives `sqrt(xi)` to one ulp for `a = 0` (`xi / sqrt(xi)`
/// rounds twice: 0.7071067811865475 at `xi = 0.5`), and needs no special case for a
/// constant segment. `a` and `b` are first scaled by their maximum so that their squares
/// neither overflow nor underflow.
pub fn segment_inverse(a: f64, b: f64, xi: f64) -> f64 {
    let m = a.max(b);
    let (a, b) = (a / m, b / m);
    let denominator = a + ((1.0 - xi) * a * a + xi * b * b).sqrt();
    if denominator == 0.0 {
        return 0.0; // a = 0 and xi = 0
    }
    (xi * (a + b) / denominator).min(1.0)
}
// ANCHOR_END: segment_inverse

// ANCHOR: segment_cdf
/// The fraction of a segment's mass below `s` in `[0, 1]` (inverse of
/// [`segment_inverse`]): `s (a (2 - s) + b s) / (a + b)`, every term non-negative.
pub fn segment_cdf(a: f64, b: f64, s: f64) -> f64 {
    let m = a.max(b);
    let (a, b) = (a / m, b / m);
    (s * (a * (2.0 - s) + b * s) / (a + b)).min(1.0)
}
// ANCHOR_END: segment_cdf

impl PiecewiseLinear1D {
    /// A density through `(knots[i], values[i])`, linear between knots.
    ///
    /// # Errors
    /// As [`Piecewise1D::new`], with `values.len() == knots.len()`.
    pub fn new(knots: &[f64], values: &[f64]) -> Result<Self, TableError> {
        validate_edges(knots, "knots")?;
        if values.len() != knots.len() {
            return Err(TableError::LengthMismatch {
                what: "knots",
                edges: knots.len(),
                values: values.len(),
                needed: knots.len(),
            });
        }
        validate_values(values)?;
        // Trapezoids: exact for a linear density. A segment between two zero values has
        // no mass; one with a single zero end has mass but a density of 0 at that end.
        let masses = values
            .windows(2)
            .zip(knots.windows(2))
            .map(|(v, k)| 0.5 * (v[0] + v[1]) * (k[1] - k[0]));
        let (cdf, integral) = build_cdf(masses)?;
        let density = values.iter().map(|v| v / integral).collect();
        let last = last_bin(&cdf);
        Ok(Self {
            knots: knots.to_vec(),
            density,
            cdf,
            integral,
            last,
        })
    }

    /// `values.len()` equally spaced knots from `lo` to `hi` inclusive.
    ///
    /// # Errors
    /// As [`PiecewiseLinear1D::new`].
    pub fn uniform(lo: f64, hi: f64, values: &[f64]) -> Result<Self, TableError> {
        Self::new(&uniform_grid(lo, hi, values.len()), values)
    }

    /// The density within segment `i` at `x`, linear between the knot densities:
    /// `(1 - s) a + s b`, never negative, exact at both ends.
    fn density_in(&self, i: usize, x: f64) -> f64 {
        let (lo, hi) = (self.knots[i], self.knots[i + 1]);
        let s = ((x - lo) / (hi - lo)).clamp(0.0, 1.0);
        (1.0 - s) * self.density[i] + s * self.density[i + 1]
    }

    // ANCHOR: linear_sample
    // EXERCISE sampling/tabulated PiecewiseLinear1D::sample: sample the piecewise-linear table: the segment by its CDF, then the quadratic's inverse within it
    /// Maps `u` in `[0, 1)` to a sample: the segment by binary search on the CDF, then
    /// the position within the segment by [`segment_inverse`].
    pub fn sample(&self, u: f64) -> Sample {
        let u = clamp_u(u);
        let i = bin_of(&self.cdf, self.last, u);
        let (c0, c1) = (self.cdf[i], self.cdf[i + 1]);
        let (x0, x1) = (self.knots[i], self.knots[i + 1]);
        let (a, b) = (self.density[i], self.density[i + 1]);
        let t = segment_inverse(a, b, (u - c0) / (c1 - c0));
        let mut x = (x0 + t * (x1 - x0)).min(x1.next_down());
        let mut pdf = self.density_in(i, x);
        // The density is 0 only at a zero-valued end of the segment, which x reaches for
        // u at (or rounding to) the end of the segment's share of [0, 1). Step away from
        // that end, one float at a time, until the density is positive.
        let mut steps = 0;
        while pdf == 0.0 && steps < 64 {
            x = if a == 0.0 {
                x.next_up().min(x1.next_down())
            } else {
                x.next_down().max(x0)
            };
            pdf = self.density_in(i, x);
            steps += 1;
        }
        if pdf == 0.0 {
            // Unreachable for segments wider than a few floats; the midpoint is safe.
            x = 0.5 * (x0 + x1);
            pdf = self.density_in(i, x);
        }
        Sample { x, pdf, bin: i }
    }
    // END EXERCISE
    // ANCHOR_END: linear_sample

    /// The normalised density at `x`, 0 outside `[x_0, x_n)`.
    pub fn pdf(&self, x: f64) -> f64 {
        bin_containing(&self.knots, x).map_or(0.0, |i| self.density_in(i, x))
    }

    /// The CDF at `x`: 0 below `x_0`, 1 from `x_n` on, quadratic within each segment
    /// (NaN for NaN).
    pub fn cdf(&self, x: f64) -> f64 {
        if x.is_nan() {
            return f64::NAN;
        }
        if x < self.knots[0] {
            return 0.0;
        }
        let Some(i) = bin_containing(&self.knots, x) else {
            return 1.0;
        };
        let (c_lo, c_hi) = (self.cdf[i], self.cdf[i + 1]);
        if c_hi == c_lo {
            return c_lo;
        }
        let (lo, hi) = (self.knots[i], self.knots[i + 1]);
        let s = ((x - lo) / (hi - lo)).clamp(0.0, 1.0);
        let f = segment_cdf(self.density[i], self.density[i + 1], s);
        (c_lo + f * (c_hi - c_lo)).min(c_hi)
    }

    /// The inverse of [`PiecewiseLinear1D::sample`]: the CDF.
    pub fn invert(&self, x: f64) -> f64 {
        self.cdf(x)
    }

    /// The integral of the table as given, by the trapezoid rule (exact here).
    pub fn integral(&self) -> f64 {
        self.integral
    }

    /// The knots.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The normalised CDF at the knots.
    pub fn cdf_table(&self) -> &[f64] {
        &self.cdf
    }

    /// Number of segments (`knots - 1`).
    pub fn segments(&self) -> usize {
        self.knots.len() - 1
    }

    /// Probability of segment `i`.
    pub(crate) fn segment_probability(&self, i: usize) -> f64 {
        self.cdf[i + 1] - self.cdf[i]
    }
}

// ANCHOR: emission
/// A made-up fluorescent-lamp spectrum on 380–780 nm in 1 nm bins: a broad phosphor
/// continuum, three narrow lines (436, 546 and 611 nm), nothing below 400 nm or from
/// 720 nm on (a filter), and a notch filter that blocks 575–590 nm.
pub fn emission_values() -> Vec<f64> {
    (380..780)
        .map(|nm| {
            let l = f64::from(nm) + 0.5; // bin centre
            if !(400.0..720.0).contains(&l) || (575.0..590.0).contains(&l) {
                return 0.0;
            }
            let continuum = 0.6 * (-((l - 600.0) / 90.0).powi(2)).exp();
            let line = |centre: f64, width: f64, height: f64| {
                height * (-((l - centre) / width).powi(2)).exp()
            };
            continuum + line(436.0, 0.8, 8.0) + line(546.0, 1.2, 20.0) + line(611.0, 1.5, 10.0)
        })
        .collect()
}
// ANCHOR_END: emission

/// The table of [`emission_values`], 380–780 nm.
pub fn emission_table() -> Piecewise1D {
    Piecewise1D::uniform(380.0, 780.0, &emission_values())
        .unwrap_or_else(|e| panic!("the emission table is valid: {e}"))
}
