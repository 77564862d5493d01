//! The checker of sampling a tabulated density by its inverse CDF: any routine with the
//! signature of [`crate::sampling::tabulated::Piecewise1D::sample`] ([`sampler`]) or
//! [`crate::sampling::tabulated::PiecewiseLinear1D::sample`] ([`linear_sampler`])
//! (`f(&table, u) -> Sample`) can be checked against the claims of the chapter *Tabulated
//! distributions* (`chapters/sampling/tabulated.md`), on three tables: a smooth one, a
//! spiky one with uneven bins, and one with bins (or knots) of zero value.
//!
//! * `bins`: the samples fall in each bin in proportion to its mass (Pearson chi-squared
//!   at the options' level, divided among the tables);
//! * `within_bins`: the samples follow the table's CDF, uniform within each bin
//!   (Kolmogorov-Smirnov, same level);
//! * `pdf`: the sample's `pdf` is the table's density at `x`, and `bin` the bin of `x`;
//! * `zero_bins`: no `u` lands in a bin of zero value, not even `u` at the CDF's levels;
//! * `range`: `x` lies in `[x_0, x_n)` for every `u` in `[0, 1)`, `u = 0` and `u → 1`
//!   included;
//! * `monotone`: `x` does not decrease as `u` grows (an inverse CDF).
//!
//! Planted bugs that it must reject are in [`planted`].

pub mod planted;

use super::{Finding, Options, Verdict};
use crate::rng;
use crate::sampling::tabulated::{Piecewise1D, PiecewiseLinear1D, Sample};
use crate::stats::{chi2, ks};

/// Default number of samples per table.
pub const SAMPLES: usize = 100_000;
/// Default seed.
pub const SEED: u64 = 0x7ab1;

/// What the claims read of a table (not of the sampler under test).
pub(crate) trait TabulatedPdf {
    /// The bin edges (or knots).
    fn grid(&self) -> &[f64];
    /// The normalised density.
    fn density(&self, x: f64) -> f64;
    /// The CDF.
    fn cdf_at(&self, x: f64) -> f64;
    /// The probability of bin (or segment) `i`.
    fn probability(&self, i: usize) -> f64;
    /// The CDF at the edges (or knots).
    fn levels(&self) -> &[f64];
}

impl TabulatedPdf for Piecewise1D {
    fn grid(&self) -> &[f64] {
        self.edges()
    }
    fn density(&self, x: f64) -> f64 {
        self.pdf(x)
    }
    fn cdf_at(&self, x: f64) -> f64 {
        self.cdf(x)
    }
    fn probability(&self, i: usize) -> f64 {
        self.bin_probability(i)
    }
    fn levels(&self) -> &[f64] {
        self.cdf_table()
    }
}

impl TabulatedPdf for PiecewiseLinear1D {
    fn grid(&self) -> &[f64] {
        self.knots()
    }
    fn density(&self, x: f64) -> f64 {
        self.pdf(x)
    }
    fn cdf_at(&self, x: f64) -> f64 {
        self.cdf(x)
    }
    fn probability(&self, i: usize) -> f64 {
        self.segment_probability(i)
    }
    fn levels(&self) -> &[f64] {
        self.cdf_table()
    }
}

/// The three piecewise-linear tables the claims run on: values at the knots, a smooth
/// one, a spiky one, and one with zero values at knots and over whole segments.
pub fn linear_tables() -> Vec<(&'static str, PiecewiseLinear1D)> {
    let smooth = PiecewiseLinear1D::uniform(
        0.0,
        2.0,
        &(0..=40)
            .map(|k| 1.0 + (0.15 * k as f64).sin().powi(2))
            .collect::<Vec<_>>(),
    )
    .expect("a valid table");
    let spiky = PiecewiseLinear1D::new(
        &[0.0, 0.1, 0.15, 0.5, 0.52, 1.0, 3.0],
        &[1.0, 40.0, 0.5, 200.0, 0.1, 0.01, 2.0],
    )
    .expect("a valid table");
    let zeros = PiecewiseLinear1D::new(
        &[-1.0, -0.5, 0.0, 0.25, 0.5, 1.0, 1.5, 2.0],
        &[0.0, 2.0, 0.0, 0.0, 1.0, 0.0, 3.0, 0.0],
    )
    .expect("a valid table");
    vec![("smooth", smooth), ("spiky", spiky), ("with zeros", zeros)]
}

/// The three piecewise-constant tables the claims run on, with their names.
pub fn tables() -> Vec<(&'static str, Piecewise1D)> {
    let smooth = Piecewise1D::from_fn(0.0, 2.0, 40, |x| 1.0 + (3.0 * x).sin().powi(2))
        .expect("a valid table");
    let spiky = Piecewise1D::new(
        &[0.0, 0.1, 0.15, 0.5, 0.52, 1.0, 3.0],
        &[1.0, 40.0, 0.5, 200.0, 0.1, 0.01],
    )
    .expect("a valid table");
    let zeros = Piecewise1D::new(
        &[-1.0, -0.5, 0.0, 0.25, 0.5, 1.0, 1.5, 2.0],
        &[0.0, 2.0, 0.0, 0.0, 1.0, 0.0, 3.0],
    )
    .expect("a valid table");
    vec![
        ("smooth", smooth),
        ("spiky", spiky),
        ("with zero bins", zeros),
    ]
}

/// Runs the chapter's claims on a piecewise-constant sampler `f`; `options` sets the
/// samples per table (default [`SAMPLES`]), their seed (default [`SEED`]) and the level of
/// the statistical claims.
pub fn sampler(f: &dyn Fn(&Piecewise1D, f64) -> Sample, options: &Options) -> Verdict {
    claims(
        "tabulated inverse CDF (piecewise constant)",
        &tables(),
        f,
        options,
    )
}

/// The same claims on a piecewise-linear sampler `f`, on [`linear_tables`].
pub fn linear_sampler(f: &dyn Fn(&PiecewiseLinear1D, f64) -> Sample, options: &Options) -> Verdict {
    claims(
        "tabulated inverse CDF (piecewise linear)",
        &linear_tables(),
        f,
        options,
    )
}

fn claims<T: TabulatedPdf>(
    subject: &str,
    all: &[(&'static str, T)],
    f: &dyn Fn(&T, f64) -> Sample,
    options: &Options,
) -> Verdict {
    let n = options.cases_or(SAMPLES).max(100);
    let mut rng = rng::seeded(options.seed_or(SEED));
    let level = options.level() / all.len() as f64;
    let mut bins = Finding::new(
        "bins",
        "each bin receives its share of the mass (chi-squared)",
    );
    let mut within = Finding::new("within_bins", "the samples follow the table's CDF (KS)");
    let mut pdf = Finding::new(
        "pdf",
        "sample.pdf = the density at x, sample.bin = the bin of x",
    );
    let mut zero = Finding::new("zero_bins", "no u lands in a bin of zero value");
    let mut range = Finding::new("range", "x in [x_0, x_n) for every u in [0, 1)");
    let mut monotone = Finding::new("monotone", "x does not decrease as u grows");
    for (name, table) in all {
        let edges = table.grid();
        let pieces = edges.len() - 1;
        let (lo, hi) = (edges[0], edges[edges.len() - 1]);
        let mut counts = vec![0u64; pieces];
        let mut xs = Vec::with_capacity(n);
        let mut hard: Vec<f64> = table.levels().to_vec();
        hard.extend([0.0, 1.0 - f64::EPSILON / 2.0]);
        let random: Vec<f64> = (0..n).map(|_| rng::uniform(&mut rng, 0.0, 1.0)).collect();
        for (k, &u) in random.iter().chain(&hard).enumerate() {
            let u = u.min(1.0 - f64::EPSILON / 2.0);
            let s = f(table, u);
            let inside = s.x >= lo && s.x < hi;
            range.record(inside, || {
                format!("{name} table, u = {u}: x = {} outside [{lo}, {hi})", s.x)
            });
            let bin_ok = s.bin < pieces && edges[s.bin] <= s.x && s.x < edges[s.bin + 1];
            pdf.record(bin_ok && s.pdf == table.density(s.x), || {
                format!(
                    "{name} table, u = {u}: x = {}, bin {}, pdf {} (the density at x is {})",
                    s.x,
                    s.bin,
                    s.pdf,
                    table.density(s.x)
                )
            });
            zero.record(!inside || table.density(s.x) > 0.0, || {
                format!(
                    "{name} table, u = {u}: x = {} is in a bin of zero value",
                    s.x
                )
            });
            if k < n && inside {
                xs.push(s.x);
                let bin = edges[1..].partition_point(|&e| e <= s.x);
                counts[bin] += 1;
            }
        }
        let expected: Vec<f64> = (0..pieces)
            .map(|i| table.probability(i) * xs.len() as f64)
            .collect();
        let p = chi2::pearson(&counts, &expected, 5.0).map_or(0.0, |c| c.p_value);
        bins.record(p >= level, || {
            format!("{name} table: chi-squared p = {p:.3e}; counts {counts:?}")
        });
        let p = ks::one_sample(&xs, |x| table.cdf_at(x)).map_or(0.0, |k| k.p_value);
        within.record(p >= level, || format!("{name} table: KS p = {p:.3e}"));
        let mut previous = f64::NEG_INFINITY;
        for k in 0..=1000 {
            let u = (k as f64 / 1000.0).min(1.0 - f64::EPSILON / 2.0);
            let x = f(table, u).x;
            monotone.record(x >= previous, || {
                format!("{name} table: x({u}) = {x} < {previous} at the u before")
            });
            previous = x;
        }
    }
    let mut verdict = Verdict::new(subject);
    verdict
        .findings
        .extend([bins, within, pdf, zero, range, monotone]);
    verdict
}

/// A hard linear segment for the round trip of `segment_inverse` (chapter *Tabulated
/// distributions*): `a = 0` in a tenth of draws, else log-uniform on `[1e-300, 1e300]`; `b =
/// a` in a quarter, `b = a (1 + 1e-12 u)` in a quarter (the nearly constant segments the
/// stable form is for), else independent. `None` for a segment without mass, which is never
/// sampled. The test `segment_inverse_round_trips` and the precision table draw from it.
pub fn hard_segment(rng: &mut rng::Rng) -> Option<(f64, f64)> {
    use rand::RngExt as _;
    let a = if rng.random::<f64>() < 0.1 {
        0.0
    } else {
        rng::log_uniform(rng, 1e-300, 1e300)
    };
    let b = match rng.random::<u8>() % 4 {
        0 => a,
        1 => a * (1.0 + 1e-12 * rng.random::<f64>()),
        _ => rng::log_uniform(rng, 1e-300, 1e300),
    };
    (a != 0.0 || b != 0.0).then_some((a, b))
}
