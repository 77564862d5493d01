//! Tests of the chapter *Tabulated distributions* (`src/sampling/tabulated.rs`).
//!
//! Statistical tests (Kolmogorov–Smirnov against the exact CDF, chi-squared with one cell
//! per bin) run at `raylemma::stats::test_alpha()` with fixed seeds; every reference
//! distribution is computed here from the table itself, never by the code under test.
//! Planted bugs, including the ones the source notes invite, must be rejected.
//!
//! Statistical tests that correct code must pass (each a chance of a false failure at
//! the suite's level): 19. Piecewise constant: KS and chi-squared on three tables, KS on
//! the single bin (7); piecewise linear: both on four tables (8); the textbook inverse's
//! equality in distribution (2); the unbiased importance-sampling estimator (1); the
//! chi-squared test that cannot see a linear table sampled as constant (1).

use glam::{DVec2, DVec3};
use rand::RngExt;
use raylemma::check::Options;
use raylemma::check::max_abs;
use raylemma::check::warp::{self, Domain, RngWarp};
use raylemma::rng::{self, Rng};
use raylemma::sampling::tabulated::{
    ONE_MINUS_EPSILON, Piecewise1D, PiecewiseLinear1D, Sample, TableError, segment_cdf,
    segment_inverse,
};
use raylemma::stats::chi2::{self, Chi2};
use raylemma::stats::ks;
use raylemma::stats::ttest::{self, Summary};
use raylemma::stats::{StatsError, test_alpha};

/// Samples per statistical test.
const N: usize = 200_000;

// ---------------------------------------------------------------------------------------
// Tables, and their exact distributions computed independently of the code under test.

/// A table: `edges.len() == values.len() + 1` (piecewise constant) or
/// `edges.len() == values.len()` (piecewise linear, edges are knots).
#[derive(Clone, Debug)]
struct Table {
    name: &'static str,
    edges: Vec<f64>,
    values: Vec<f64>,
}

/// Smooth, on non-uniform bins, integral far from 1.
fn smooth() -> Table {
    let edges: Vec<f64> = (0..=48)
        .map(|k| {
            let k = f64::from(k);
            2.0 * k + 0.6 * (0.7 * k).sin()
        })
        .collect();
    let values = (0..48)
        .map(|k| 3.0 + 2.5 * (f64::from(k) / 7.0).cos())
        .collect();
    Table {
        name: "smooth",
        edges,
        values,
    }
}

/// A narrow emission line, 400 times the background, on 380–780 nm in 2 nm bins.
fn spiky() -> Table {
    let edges: Vec<f64> = (0..=200).map(|k| 380.0 + 2.0 * f64::from(k)).collect();
    let mut values = vec![1.0; 200];
    values[83] = 400.0; // 546–548 nm
    values[84] = 40.0;
    Table {
        name: "spiky",
        edges,
        values,
    }
}

/// Leading, interior and trailing runs of zero bins, and a lone zero bin.
fn with_zeros() -> Table {
    let edges: Vec<f64> = (0..=40).map(|k| f64::from(k) * 0.25 - 3.0).collect();
    let values = (0..40)
        .map(|k| match k {
            0..=4 | 12..=17 | 25 | 34..=39 => 0.0,
            _ => 1.0 + f64::from(k % 5),
        })
        .collect();
    Table {
        name: "with_zeros",
        edges,
        values,
    }
}

/// One bin with mass among zeros.
fn single_bin() -> Table {
    Table {
        name: "single_bin",
        edges: vec![0.0, 1.0, 2.0, 3.5, 4.0],
        values: vec![0.0, 0.0, 5.0, 0.0],
    }
}

/// Knot tables for the piecewise-linear density.
fn linear_tables() -> Vec<Table> {
    let smooth_knots: Vec<f64> = (0..=12)
        .map(|k| f64::from(k) * f64::from(k) / 4.0)
        .collect();
    let smooth_values = (0..=12)
        .map(|k| 1.0 + 0.9 * (f64::from(k) * 0.8).sin())
        .collect();
    let spiky_knots: Vec<f64> = (0..=80).map(|k| 380.0 + 5.0 * f64::from(k)).collect();
    let mut spiky_values = vec![0.5; 81];
    spiky_values[33] = 60.0; // a line at 545 nm, zero width at the knots
    let zero_knots: Vec<f64> = (0..=20).map(f64::from).collect();
    let zero_values = (0..=20)
        .map(|k| match k {
            0..=3 | 8..=10 | 17..=20 => 0.0,
            _ => f64::from(k % 4) + 1.0,
        })
        .collect();
    vec![
        Table {
            name: "linear_smooth",
            edges: smooth_knots,
            values: smooth_values,
        },
        Table {
            name: "linear_spiky",
            edges: spiky_knots,
            values: spiky_values,
        },
        Table {
            name: "linear_zeros",
            edges: zero_knots,
            values: zero_values,
        },
    ]
}

/// A single triangle among zero knots.
fn triangle() -> Table {
    Table {
        name: "triangle",
        edges: vec![0.0, 1.0, 2.0, 3.0],
        values: vec![0.0, 0.0, 2.0, 0.0],
    }
}

impl Table {
    fn constant(&self) -> Piecewise1D {
        Piecewise1D::new(&self.edges, &self.values).unwrap()
    }

    fn linear(&self) -> PiecewiseLinear1D {
        PiecewiseLinear1D::new(&self.edges, &self.values).unwrap()
    }

    /// Unnormalised mass of each cell (bin or segment).
    fn masses(&self, linear: bool) -> Vec<f64> {
        self.edges
            .windows(2)
            .enumerate()
            .map(|(i, e)| {
                let w = e[1] - e[0];
                if linear {
                    0.5 * w * (self.values[i] + self.values[i + 1])
                } else {
                    w * self.values[i]
                }
            })
            .collect()
    }

    /// Probability of each cell.
    fn probabilities(&self, linear: bool) -> Vec<f64> {
        let m = self.masses(linear);
        let total: f64 = m.iter().sum();
        m.iter().map(|x| x / total).collect()
    }

    /// The exact CDF.
    fn cdf(&self, linear: bool, x: f64) -> f64 {
        let m = self.masses(linear);
        let total: f64 = m.iter().sum();
        let mut below = 0.0;
        for (i, e) in self.edges.windows(2).enumerate() {
            if x >= e[1] {
                below += m[i];
                continue;
            }
            if x > e[0] {
                let s = x - e[0];
                below += if linear {
                    let slope = (self.values[i + 1] - self.values[i]) / (e[1] - e[0]);
                    self.values[i] * s + 0.5 * slope * s * s
                } else {
                    self.values[i] * s
                };
            }
            break;
        }
        (below / total).clamp(0.0, 1.0)
    }

    /// The exact normalised density.
    fn density(&self, linear: bool, x: f64) -> f64 {
        let total: f64 = self.masses(linear).iter().sum();
        match self.edges.windows(2).position(|e| x >= e[0] && x < e[1]) {
            None => 0.0,
            Some(i) if linear => {
                let (lo, hi) = (self.edges[i], self.edges[i + 1]);
                let s = (x - lo) / (hi - lo);
                ((1.0 - s) * self.values[i] + s * self.values[i + 1]) / total
            }
            Some(i) => self.values[i] / total,
        }
    }

    /// Counts of `xs` per cell; panics on a sample outside the table.
    fn counts(&self, xs: &[f64]) -> Vec<u64> {
        let mut counts = vec![0u64; self.edges.len() - 1];
        for &x in xs {
            let i = self
                .edges
                .windows(2)
                .position(|e| x >= e[0] && x < e[1])
                .unwrap_or_else(|| panic!("{}: sample {x} outside the table", self.name));
            counts[i] += 1;
        }
        counts
    }
}

fn draw(seed: u64, n: usize, sample: impl Fn(f64) -> f64) -> Vec<f64> {
    let mut rng: Rng = rng::seeded(seed);
    (0..n).map(|_| sample(rng.random::<f64>())).collect()
}

/// The two statistical tests against `table`'s exact distribution.
fn fit(table: &Table, linear: bool, xs: &[f64]) -> (ks::Ks, Result<Chi2, StatsError>) {
    let ks = ks::one_sample(xs, |x| table.cdf(linear, x)).unwrap();
    let expected: Vec<f64> = table
        .probabilities(linear)
        .iter()
        .map(|p| p * xs.len() as f64)
        .collect();
    let observed = table.counts_clamped(xs);
    (ks, chi2::pearson(&observed, &expected, 5.0))
}

impl Table {
    /// Counts per cell; samples outside the table go to the nearest end cell (planted
    /// bugs may produce them; the tests must then reject, not panic).
    fn counts_clamped(&self, xs: &[f64]) -> Vec<u64> {
        let inside: Vec<f64> = xs
            .iter()
            .map(|&x| x.clamp(self.edges[0], self.edges[self.edges.len() - 1].next_down()))
            .collect();
        self.counts(&inside)
    }
}

/// Chi-squared rejects: a p-value below the level, or samples where the table is zero.
fn chi2_rejects(result: &Result<Chi2, StatsError>) -> bool {
    match result {
        Ok(c) => c.p_value < test_alpha(),
        Err(StatsError::SamplesWherePdfIsZero { .. }) => true,
        Err(e) => panic!("chi-squared could not run: {e}"),
    }
}

fn assert_fits(table: &Table, linear: bool, xs: &[f64]) {
    let (ks, chi) = fit(table, linear, xs);
    assert!(
        ks.p_value >= test_alpha(),
        "{}: KS rejects, D = {} p = {:e}",
        table.name,
        ks.statistic,
        ks.p_value
    );
    match chi {
        Ok(c) => assert!(
            c.p_value >= test_alpha(),
            "{}: chi2 rejects {c:?}",
            table.name
        ),
        // A single cell with mass: the chi-squared test has no degree of freedom.
        Err(StatsError::TooFewCells { .. }) => {}
        Err(e) => panic!("{}: chi2 could not run: {e}", table.name),
    }
}

fn assert_rejected(table: &Table, linear: bool, xs: &[f64], what: &str) {
    let (ks, chi) = fit(table, linear, xs);
    assert!(
        ks.p_value < test_alpha() && chi2_rejects(&chi),
        "{what} on {}: not rejected (KS p = {:e}, chi2 {chi:?})",
        table.name,
        ks.p_value
    );
}

mod errors;
mod fits;
mod importance;
mod pdf;
mod planted;
mod round_trip;
mod segment_inverse;

// ---------------------------------------------------------------------------------------
// Hard cases: plateaus of the CDF, u = 0 and u -> 1.

/// The u values most likely to break a sampler: 0, the largest value below 1, 1 itself,
/// every CDF entry (the levels of the plateaus) and its neighbouring floats.
fn hard_us(cdf: &[f64]) -> Vec<f64> {
    let mut us = vec![0.0, f64::MIN_POSITIVE, ONE_MINUS_EPSILON, 1.0];
    for &c in cdf {
        us.extend([c, c.next_up(), c.next_down().max(0.0)]);
    }
    us.retain(|u| (0.0..=1.0).contains(u));
    us
}

/// A sample is sound if it lies in [x_0, x_n), its pdf is positive and equals `pdf(x)`,
/// and it lies in its bin, whose table value is positive.
fn unsound(t: &Table, linear: bool, u: f64, s: Sample, pdf: impl Fn(f64) -> f64) -> Option<String> {
    let (lo, hi) = (t.edges[0], t.edges[t.edges.len() - 1]);
    let in_bin = s.bin + 1 < t.edges.len() && s.x >= t.edges[s.bin] && s.x < t.edges[s.bin + 1];
    let positive_bin = in_bin
        && if linear {
            t.values[s.bin] + t.values[s.bin + 1] > 0.0
        } else {
            t.values[s.bin] > 0.0
        };
    let ok = s.x >= lo
        && s.x < hi
        && s.pdf > 0.0
        && s.pdf == pdf(s.x)
        && t.density(linear, s.x) > 0.0
        && positive_bin;
    (!ok).then(|| {
        format!(
            "{}: u = {u:e} gave {s:?}, pdf(x) = {}, exact density {}",
            t.name,
            pdf(s.x),
            t.density(linear, s.x)
        )
    })
}

#[test]
fn hard_u_values_give_sound_samples() {
    assert_eq!(ONE_MINUS_EPSILON, f64::from_bits(0x3FEF_FFFF_FFFF_FFFF));
    for t in [smooth(), spiky(), with_zeros(), single_bin()] {
        let d = t.constant();
        let mut rng = rng::seeded(30);
        let random = (0..10_000).map(|_| rng.random::<f64>());
        for u in hard_us(d.cdf_table()).into_iter().chain(random) {
            assert_eq!(unsound(&t, false, u, d.sample(u), |x| d.pdf(x)), None);
        }
    }
    for t in linear_tables().into_iter().chain([triangle()]) {
        let d = t.linear();
        let cdf: Vec<f64> = t.edges.iter().map(|&x| d.cdf(x)).collect();
        let mut rng = rng::seeded(31);
        let random = (0..10_000).map(|_| rng.random::<f64>());
        for u in hard_us(&cdf).into_iter().chain(random) {
            assert_eq!(unsound(&t, true, u, d.sample(u), |x| d.pdf(x)), None);
        }
    }
}

/// Zero bins are never sampled, not even at the exact level of their plateau.
#[test]
fn plateau_levels_skip_zero_bins() {
    let t = with_zeros();
    let d = t.constant();
    let cdf = d.cdf_table();
    for (i, &v) in t.values.iter().enumerate() {
        if v == 0.0 {
            // The plateau's level maps to the first bin with mass after it (or, at the
            // top, to the last bin with mass before it).
            let s = d.sample(cdf[i]);
            assert!(t.values[s.bin] > 0.0, "bin {i}: {s:?}");
        }
    }
    let s = d.sample(0.0);
    assert_eq!((s.bin, s.x), (5, t.edges[5]));
    let s = d.sample(ONE_MINUS_EPSILON);
    assert_eq!(s.bin, 33);
    assert!(s.x < t.edges[34] && s.x > t.edges[33]);
}

// ANCHOR: plateau
/// The textbook generalised inverse, `F^-1(u) = inf { x : F(x) >= u }`, read off a table
/// (the first bin with `cdf[i + 1] >= u`): equal in distribution, but at the level of a
/// plateau it lands on the left end of the zero bin, and at u = 0 with a leading zero bin
/// it divides 0 by 0.
fn generalised_inverse(d: &Piecewise1D, u: f64) -> Sample {
    let (cdf, edges) = (d.cdf_table(), d.edges());
    let i = cdf[1..].partition_point(|&c| c < u).min(d.bins() - 1);
    let t = (u - cdf[i]) / (cdf[i + 1] - cdf[i]);
    let x = edges[i] + t * (edges[i + 1] - edges[i]);
    Sample {
        x,
        pdf: d.pdf(x),
        bin: i,
    }
}

/// The source's premise "the PDF must always have a positive result" excludes the tables
/// spectra give; with zero bins the inverse CDF is not single-valued, and the textbook
/// choice of inverse returns points of zero density.
#[test]
fn seed_premise_textbook_inverse_lands_in_zero_bins() {
    let t = with_zeros();
    let d = t.constant();
    let s = generalised_inverse(&d, 0.0);
    assert!(s.x.is_nan(), "u = 0: {s:?}");
    let bad = hard_us(d.cdf_table())
        .into_iter()
        .filter(|&u| unsound(&t, false, u, generalised_inverse(&d, u), |x| d.pdf(x)).is_some())
        .count();
    // u = 0 and the level of each interior plateau (3 runs of zeros between bins with mass).
    assert!(bad >= 4, "only {bad} unsound samples");
    // Equal in distribution: the plateau levels have probability 0.
    assert_fits(
        &t,
        false,
        &draw(32, N / 4, |u| generalised_inverse(&d, u).x),
    );
}
// ANCHOR_END: plateau

// ---------------------------------------------------------------------------------------
// Exercises: each scaffold is yours to fill in; its test is ignored until you do
// (`cargo test --test book sampling::tabulated::exercise_ -- --ignored`).

/// Exercise 1 of *Tabulated distributions*: Walker's alias method over the bins of a
/// piecewise-constant table (`edges.len() == values.len() + 1`), then a position uniform
/// within the bin drawn.
struct YourAlias {}

impl YourAlias {
    fn new(edges: &[f64], values: &[f64]) -> Self {
        let _ = (edges, values);
        unimplemented!("exercise 1 of Tabulated distributions: build the alias table")
    }

    /// A sample `x` of the table from one uniform `u` in `[0, 1)`.
    fn sample(&self, u: f64) -> f64 {
        let _ = u;
        unimplemented!("exercise 1 of Tabulated distributions: draw a bin in constant time")
    }
}

#[test]
#[ignore = "exercise 1 of Tabulated distributions: fill in YourAlias, then run it"]
fn exercise_1_alias_fits_every_table() {
    for (k, t) in [smooth(), spiky(), with_zeros(), single_bin()]
        .iter()
        .enumerate()
    {
        let alias = YourAlias::new(&t.edges, &t.values);
        assert_fits(t, false, &draw(70 + k as u64, N, |u| alias.sample(u)));
    }
    // Why there is no `invert`: x is not a monotone function of u, so no u is "the" u of
    // an x, and stratified or low-discrepancy u lose their structure on the way to x.
    let t = smooth();
    let alias = YourAlias::new(&t.edges, &t.values);
    let xs: Vec<f64> = (0..100_000)
        .map(|k| alias.sample(f64::from(k) / 1e5))
        .collect();
    assert!(
        xs.windows(2).any(|w| w[1] < w[0]),
        "x is monotone in u: that is an inverse CDF, not the alias method"
    );
}

/// Exercise 2 of *Tabulated distributions*: a guide table over the CDF of `d`.
struct YourGuide {}

impl YourGuide {
    /// For each of `slices` equal slices of `[0, 1)`, the first bin whose CDF range meets it.
    fn new(d: &Piecewise1D, slices: usize) -> Self {
        let _ = (d, slices);
        unimplemented!("exercise 2 of Tabulated distributions: build the guide table")
    }

    /// `d.sample(u)`, bit for bit, with the binary search limited to the bins between two
    /// guides.
    fn sample(&self, d: &Piecewise1D, u: f64) -> Sample {
        let _ = (d, u);
        unimplemented!("exercise 2 of Tabulated distributions: search between two guides")
    }
}

#[test]
#[ignore = "exercise 2 of Tabulated distributions: fill in YourGuide, then run it"]
fn exercise_2_guide_table_gives_the_same_samples() {
    // 65 536 bins, as in the speed table, with runs of zero bins.
    let mut rng = rng::seeded(80);
    let values: Vec<f64> = (0..65_536)
        .map(|k| {
            if (k / 1000) % 7 == 3 {
                0.0
            } else {
                rng.random::<f64>()
            }
        })
        .collect();
    let d = Piecewise1D::uniform(380.0, 780.0, &values).unwrap();
    let guide = YourGuide::new(&d, 65_536);
    let random: Vec<f64> = (0..100_000).map(|_| rng.random::<f64>()).collect();
    for u in hard_us(d.cdf_table()).into_iter().chain(random) {
        assert_eq!(guide.sample(&d, u), d.sample(u), "u = {u:e}");
    }
}

/// Exercise 3 of *Tabulated distributions*: predicted from the CDF `cdf` alone (without
/// calling a sampler), every `u` among the hard ones (0, 1 − 2⁻⁵³, 1, each CDF entry and its
/// two neighbouring doubles) at which `Piecewise1D::sample` with
/// `partition_point(|&c| c < u)` in `bin_of` returns a sample that is not sound (outside
/// its bin, or in a bin of zero mass, or with a pdf of 0).
fn your_failing_us(cdf: &[f64]) -> Vec<f64> {
    let _ = cdf;
    unimplemented!("exercise 3 of Tabulated distributions: which u break the other inequality?")
}

/// `Piecewise1D::sample` with the other inequality in `bin_of`: the same arithmetic,
/// including the clamping of `u` and of `x` below the bin's right edge.
fn sample_with_the_other_inequality(d: &Piecewise1D, u: f64) -> Sample {
    let (cdf, edges) = (d.cdf_table(), d.edges());
    let u = if u >= 1.0 {
        ONE_MINUS_EPSILON
    } else {
        u.max(0.0)
    };
    let last = (0..d.bins()).rev().find(|&i| cdf[i] < cdf[i + 1]).unwrap();
    let i = cdf[1..].partition_point(|&c| c < u).min(last);
    let t = (u - cdf[i]) / (cdf[i + 1] - cdf[i]);
    let x = (edges[i] + t * (edges[i + 1] - edges[i])).min(edges[i + 1].next_down());
    Sample {
        x,
        pdf: d.pdf(x),
        bin: i,
    }
}

#[test]
#[ignore = "exercise 3 of Tabulated distributions: fill in your_failing_us, then run it"]
fn exercise_3_the_other_inequality_fails_where_you_predict() {
    for t in [smooth(), spiky(), with_zeros(), single_bin()] {
        let d = t.constant();
        let sorted = |mut v: Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v.dedup();
            v
        };
        let failing = sorted(
            hard_us(d.cdf_table())
                .into_iter()
                .filter(|&u| {
                    let s = sample_with_the_other_inequality(&d, u);
                    unsound(&t, false, u, s, |x| d.pdf(x)).is_some()
                })
                .collect(),
        );
        assert_eq!(
            sorted(your_failing_us(d.cdf_table())),
            failing,
            "{}",
            t.name
        );
    }
}

/// Exercise 4 of *Tabulated distributions*: the position `t` in `[0, 1)` within a segment
/// whose density goes linearly from `a` (at `t = 0`) to `b` (at `t = 1`), by drawing
/// uniformly under the constant envelope `max(a, b)` and rejecting; and the number of tries
/// it took (1 if the first was accepted).
fn your_rejection_in_a_segment(a: f64, b: f64, rng: &mut Rng) -> (f64, u32) {
    let _ = (a, b, rng);
    unimplemented!("exercise 4 of Tabulated distributions: sample a segment by rejection")
}

#[test]
#[ignore = "exercise 4 of Tabulated distributions: fill in your_rejection_in_a_segment, then run it"]
fn exercise_4_rejection_inside_a_segment() {
    let mut tables = linear_tables();
    tables.push(triangle());
    for (k, t) in tables.iter().enumerate() {
        let d = t.linear();
        let mut rng = rng::seeded(90 + k as u64);
        let xs: Vec<f64> = (0..N)
            .map(|_| {
                // The segment by its CDF, then the position within it by rejection.
                let i = d.sample(rng.random::<f64>()).bin;
                let (s, _) = your_rejection_in_a_segment(t.values[i], t.values[i + 1], &mut rng);
                t.edges[i] + s * (t.edges[i + 1] - t.edges[i])
            })
            .collect();
        assert_fits(t, true, &xs);
    }
    // The mean number of tries is 2 max(a, b) / (a + b), to 1 % over 100 000 segments
    // (4.5 standard errors at the worst case a = 0, where it is 2).
    let mut rng = rng::seeded(99);
    for (a, b) in [(1.0f64, 1.0f64), (0.0, 2.0), (3.0, 1.0), (0.2, 5.0)] {
        let n = 100_000;
        let tries: u64 = (0..n)
            .map(|_| u64::from(your_rejection_in_a_segment(a, b, &mut rng).1))
            .sum();
        let (mean, want) = (tries as f64 / f64::from(n), 2.0 * a.max(b) / (a + b));
        assert!(
            (mean / want - 1.0).abs() <= 0.01,
            "a = {a}, b = {b}: {mean} tries on average, expected {want}"
        );
    }
}

/// Exercise 5 of *Tabulated distributions*: an environment map, a piecewise-constant table
/// over `width × height` equal cells of the unit square, `values[j * width + i]` in column
/// `i` (along `x`) and row `j` (along `y`).
struct YourEnvironmentMap {}

impl YourEnvironmentMap {
    fn new(width: usize, height: usize, values: &[f64]) -> Self {
        let _ = (width, height, values);
        unimplemented!(
            "exercise 5 of Tabulated distributions: the marginal over rows and one Piecewise1D per row"
        )
    }

    /// A point of `[0, 1)²` from `u` (the row from `u.y` by the marginal, the column from
    /// `u.x` by the row's conditional table) and its density per unit area.
    fn sample(&self, u: DVec2) -> (DVec2, f64) {
        let _ = u;
        unimplemented!("exercise 5 of Tabulated distributions: sample the map")
    }

    /// The density per unit area at `p`.
    fn pdf(&self, p: DVec2) -> f64 {
        let _ = p;
        unimplemented!("exercise 5 of Tabulated distributions: the map's density")
    }
}

#[test]
#[ignore = "exercise 5 of Tabulated distributions: fill in YourEnvironmentMap, then run it"]
fn exercise_5_two_dimensions() {
    let (w, h) = (64usize, 32usize);
    // A bright sun, a dim sky and a band of zero rows on one side (a horizon).
    let values: Vec<f64> = (0..w * h)
        .map(|k| {
            let (i, j) = ((k % w) as f64, (k / w) as f64);
            if (10.0..14.0).contains(&j) && i > 40.0 {
                0.0
            } else {
                1.0 + 50.0 * (-((i - 20.0) / 3.0).powi(2) - ((j - 8.0) / 2.0).powi(2)).exp()
            }
        })
        .collect();
    // The exact density of cell (i, j): v_ij / I, with I = sum v_ij w_i w_j.
    let integral: f64 = values.iter().sum::<f64>() / (w * h) as f64;
    let map = YourEnvironmentMap::new(w, h, &values);
    let mut rng = rng::seeded(100);
    let mut observed = vec![0u64; w * h];
    for _ in 0..N {
        let u = DVec2::new(rng.random::<f64>(), rng.random::<f64>());
        let (p, pdf) = map.sample(u);
        assert!(
            (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y),
            "u = {u}: {p}"
        );
        let cell =
            ((p.y * h as f64) as usize).min(h - 1) * w + ((p.x * w as f64) as usize).min(w - 1);
        let exact = values[cell] / integral;
        assert!(exact > 0.0, "u = {u}: {p} lies in a cell of zero value");
        for (what, got) in [("sample", pdf), ("pdf", map.pdf(p))] {
            assert!(
                (got / exact - 1.0).abs() <= 1e-12,
                "u = {u}: {what} gives the density {got} at {p}, exactly {exact}"
            );
        }
        observed[cell] += 1;
    }
    let expected: Vec<f64> = values
        .iter()
        .map(|v| N as f64 * v / (integral * (w * h) as f64))
        .collect();
    let r = chi2::pearson(&observed, &expected, 5.0).unwrap();
    assert!(r.p_value >= test_alpha(), "{r:?}");
    // And on the warp checker's own grid of the square (chapter *Checking a sampler*).
    let sampler = RngWarp {
        name: "your environment map".into(),
        domain: Domain::Square,
        sample: |rng: &mut Rng| {
            let (p, _) = map.sample(warp::square_point(rng));
            DVec3::new(p.x, p.y, 0.0)
        },
        pdf: |p: DVec3| map.pdf(DVec2::new(p.x, p.y)),
    };
    warp::check(&sampler, &Options::default().cases(warp::TEST_SAMPLES)).assert_pass();
}
