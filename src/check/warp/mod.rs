//! The warp checker: one harness for every sampler. Chapter: *Checking a sampler*.
//!
//! Modelled on Nori's `warptest`: a sampler states the density it claims to draw from,
//! and the checker tests the claim three ways.
//!
//! 1. **Chi-squared.** Draw `n` samples, bin them into cells of the domain, and compare
//!    the counts with `n` times the integral of the claimed pdf over each cell (by
//!    Gauss-Legendre quadrature, not a point value), with Pearson's test
//!    ([`crate::stats::chi2::pearson`]) at the suite's Šidák-corrected level.
//! 2. **Jacobian.** For a warp `T` from the unit square, a correct pdf satisfies
//!    `p(T(u)) |det dT/du| = 1` (on the sphere, `|dT/du1 x dT/du2|` is the area element),
//!    checked by central differences at many points. This is the derivation itself.
//! 3. **Round trip.** Where the warp has an inverse, `T^-1(T(u)) = u`.
//!
//! It fails loudly, saying why, on NaN or infinite samples, samples outside the domain,
//! negative pdfs, samples in cells where the pdf integrates to zero, and pdfs whose
//! integral is not 1. On a chi-squared failure it writes observed, expected and
//! difference images a student can open.

pub mod planted;

use std::f64::consts::TAU;
use std::path::PathBuf;

use glam::{DVec2, DVec3};

use super::{Finding, Verdict};
use crate::rng::{self, Rng};
use crate::stats::{self, chi2};

// ANCHOR: interface
/// The domain a sampler draws from, and the measure its pdf is a density for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Domain {
    /// The interval `[lo, hi]` (points `(x, 0, 0)`; pdf per unit length).
    Interval {
        /// Lower end.
        lo: f64,
        /// Upper end.
        hi: f64,
    },
    /// The unit square `[0, 1]^2` (points `(x, y, 0)`; pdf per unit area).
    Square,
    /// The unit disc (points `(x, y, 0)`; pdf per unit area).
    Disc,
    /// The unit sphere (points are unit vectors; pdf per steradian). Hemisphere samplers
    /// use this domain too, with a pdf of zero on the other side.
    Sphere,
}

/// A sampler and the density it claims. Implement this for your own sampler to check it.
pub trait Warp: Sync {
    /// A name for reports and failure images.
    fn name(&self) -> String;
    /// The domain of the samples.
    fn domain(&self) -> Domain;
    /// Draws one sample (may consume any number of random numbers).
    fn sample(&self, rng: &mut Rng) -> DVec3;
    /// The claimed density at `p` (zero outside the support).
    fn pdf(&self, p: DVec3) -> f64;
    /// The warp from the unit square, if the sampler is one (enables the Jacobian check).
    fn warp(&self, _u: DVec2) -> Option<DVec3> {
        None
    }
    /// The inverse warp, if known (enables the round-trip check).
    fn invert(&self, _p: DVec3) -> Option<DVec2> {
        None
    }
}
// ANCHOR_END: interface

/// A warp from the unit square built from two plain functions: the usual way to check a
/// `fn(DVec2) -> DVec3` sampler with its `fn(DVec3) -> f64` pdf.
pub struct SquareWarp<S, P> {
    /// Name for reports.
    pub name: String,
    /// Domain of the samples.
    pub domain: Domain,
    /// The warp.
    pub sample: S,
    /// The claimed pdf.
    pub pdf: P,
    /// The inverse warp, if any.
    pub invert: Option<fn(DVec3) -> DVec2>,
}

impl<S, P> Warp for SquareWarp<S, P>
where
    S: Fn(DVec2) -> DVec3 + Sync,
    P: Fn(DVec3) -> f64 + Sync,
{
    fn name(&self) -> String {
        self.name.clone()
    }
    fn domain(&self) -> Domain {
        self.domain
    }
    fn sample(&self, rng: &mut Rng) -> DVec3 {
        (self.sample)(square_point(rng))
    }
    fn pdf(&self, p: DVec3) -> f64 {
        (self.pdf)(p)
    }
    fn warp(&self, u: DVec2) -> Option<DVec3> {
        Some((self.sample)(u))
    }
    fn invert(&self, p: DVec3) -> Option<DVec2> {
        self.invert.map(|f| f(p))
    }
}

/// A sampler that draws from a generator (rejection, Gaussian, ...) rather than warping
/// the unit square; only the chi-squared test applies to it.
pub struct RngWarp<S, P> {
    /// Name for reports.
    pub name: String,
    /// Domain of the samples.
    pub domain: Domain,
    /// The sampler.
    pub sample: S,
    /// The claimed pdf.
    pub pdf: P,
}

impl<S, P> Warp for RngWarp<S, P>
where
    S: Fn(&mut Rng) -> DVec3 + Sync,
    P: Fn(DVec3) -> f64 + Sync,
{
    fn name(&self) -> String {
        self.name.clone()
    }
    fn domain(&self) -> Domain {
        self.domain
    }
    fn sample(&self, rng: &mut Rng) -> DVec3 {
        (self.sample)(rng)
    }
    fn pdf(&self, p: DVec3) -> f64 {
        (self.pdf)(p)
    }
}

/// A uniform point of `[0, 1)^2`.
pub fn square_point(rng: &mut Rng) -> DVec2 {
    DVec2::new(rng::uniform(rng, 0.0, 1.0), rng::uniform(rng, 0.0, 1.0))
}

/// How thoroughly to check.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    /// Samples for the chi-squared test.
    pub samples: usize,
    /// Cells along each axis of the domain (odd on the sphere: the cell rows of
    /// `cos(theta)` then straddle the equator, and no hemisphere edge is a cell boundary).
    pub resolution: usize,
    /// Points for the Jacobian and round-trip checks.
    pub points: usize,
    /// Seed of the random numbers.
    pub seed: u64,
    /// Significance level of the chi-squared test.
    pub alpha: f64,
}

impl Options {
    /// The settings of the book's sampler tests: 400 000 samples, 21 rows of cells,
    /// 5 000 Jacobian and round-trip points, the default seed and the suite's level.
    pub fn tests() -> Self {
        Self {
            samples: 400_000,
            resolution: 21,
            points: 5_000,
            ..Self::default()
        }
    }
}

impl Default for Options {
    fn default() -> Self {
        Self {
            samples: 1_000_000,
            resolution: 51,
            points: 10_000,
            seed: 0xC41,
            alpha: stats::test_alpha(),
        }
    }
}

// ANCHOR: cells
/// The cells of a domain: `(rows, cols)` and, for a point, its cell index.
/// Sphere cells are equal-area: rows in `z = cos(theta)`, columns in `phi`.
/// Disc cells are equal-area: rows in `r^2`, columns in `phi`.
fn cell_of(domain: Domain, p: DVec3, rows: usize, cols: usize) -> usize {
    let clamp = |v: f64, n: usize| ((v * n as f64) as usize).min(n - 1);
    let (a, b) = match domain {
        Domain::Interval { lo, hi } => ((p.x - lo) / (hi - lo), 0.0),
        Domain::Square => (p.y, p.x),
        Domain::Disc => (p.x * p.x + p.y * p.y, phi01(p.x, p.y)),
        Domain::Sphere => ((p.z + 1.0) / 2.0, phi01(p.x, p.y)),
    };
    clamp(a, rows) * cols + clamp(b, cols)
}
// ANCHOR_END: cells

/// Cell `index` of `(rows, cols)` in the domain's own coordinates, for messages: the
/// interval `x`, the square's `x, y`, the disc's `r^2` (and `r`) and azimuth, the sphere's
/// `z = cos(theta)` (and `theta`) and azimuth.
fn describe_cell(domain: Domain, index: usize, rows: usize, cols: usize) -> String {
    let (i, j) = (index / cols, index % cols);
    let span = |k: usize, n: usize| (k as f64 / n as f64, (k + 1) as f64 / n as f64);
    let (a0, a1) = span(i, rows);
    let (b0, b1) = span(j, cols);
    let phi = format!("phi in [{:.0}, {:.0}] deg", 360.0 * b0, 360.0 * b1);
    match domain {
        Domain::Interval { lo, hi } => {
            format!(
                "x in [{:.4}, {:.4}]",
                lo + a0 * (hi - lo),
                lo + a1 * (hi - lo)
            )
        }
        Domain::Square => format!("u1 in [{b0:.3}, {b1:.3}], u2 in [{a0:.3}, {a1:.3}]"),
        Domain::Disc => format!(
            "r^2 in [{a0:.3}, {a1:.3}] (r in [{:.3}, {:.3}]), {phi}",
            a0.sqrt(),
            a1.sqrt()
        ),
        Domain::Sphere => {
            let (z0, z1) = (2.0 * a0 - 1.0, 2.0 * a1 - 1.0);
            format!(
                "z = cos(theta) in [{z0:.3}, {z1:.3}] (theta in [{:.1}, {:.1}] deg), {phi}",
                z1.clamp(-1.0, 1.0).acos().to_degrees(),
                z0.clamp(-1.0, 1.0).acos().to_degrees()
            )
        }
    }
}

/// The `k` cells whose counts are furthest from the pdf's prediction, in standard
/// deviations `(observed - expected) / sqrt(expected)`, described in the domain's terms.
fn worst_cells(
    domain: Domain,
    observed: &[u64],
    expected: &[f64],
    cols: usize,
    k: usize,
) -> String {
    let rows = observed.len() / cols;
    let mut cells: Vec<(usize, f64)> = expected
        .iter()
        .zip(observed)
        .enumerate()
        .map(|(i, (&e, &o))| {
            let z = if e > 0.0 {
                (o as f64 - e) / e.sqrt()
            } else if o > 0 {
                f64::INFINITY
            } else {
                0.0
            };
            (i, z)
        })
        .collect();
    cells.sort_by(|a, b| b.1.abs().total_cmp(&a.1.abs()));
    cells
        .iter()
        .take(k)
        .map(|&(i, z)| {
            let (o, e) = (observed[i], expected[i]);
            format!(
                "\n      {}: {o} samples where the pdf predicts {e:.1} ({:.2}x, {z:+.1} sd)",
                describe_cell(domain, i, rows, cols),
                o as f64 / e
            )
        })
        .collect()
}

/// Azimuth scaled to `[0, 1)`.
fn phi01(x: f64, y: f64) -> f64 {
    let phi = y.atan2(x);
    (if phi < 0.0 { phi + TAU } else { phi }) / TAU
}

fn grid(domain: Domain, resolution: usize) -> (usize, usize) {
    match domain {
        Domain::Interval { .. } => (resolution * resolution, 1),
        Domain::Square | Domain::Disc => (resolution, resolution),
        Domain::Sphere => (resolution, 2 * resolution),
    }
}

/// Why a sample is not in the domain, if it is not.
fn outside(domain: Domain, p: DVec3) -> Option<String> {
    if !p.is_finite() {
        return Some("the sample is not finite".into());
    }
    let tol = 1e-9;
    let bad = match domain {
        Domain::Interval { lo, hi } => p.x < lo || p.x > hi || p.y != 0.0 || p.z != 0.0,
        Domain::Square => p.x < 0.0 || p.x > 1.0 || p.y < 0.0 || p.y > 1.0 || p.z != 0.0,
        Domain::Disc => p.x * p.x + p.y * p.y > 1.0 + tol || p.z != 0.0,
        Domain::Sphere => (p.length() - 1.0).abs() > tol,
    };
    bad.then(|| format!("the sample lies outside the domain {domain:?}"))
}

/// 8-point Gauss-Legendre nodes and weights on `[-1, 1]`.
const GAUSS8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
];

// ANCHOR: adaptive
/// Integral of `f` over `[a0, a1] x [b0, b1]`, adaptively: the 8x8 Gauss rule on the
/// rectangle is compared with the sum of the rule on its four quarters; where they differ
/// by more than [`CELL_TOLERANCE`] (a jump of the pdf, such as a light's silhouette or a
/// cone's rim, crosses the rectangle) each quarter is integrated the same way, down to
/// [`CELL_DEPTH`] levels. A smooth pdf stops at the first level. Returns `Err` with the
/// point if `f` is negative or not finite at a node.
fn integrate2(
    f: &impl Fn(f64, f64) -> f64,
    a: (f64, f64),
    b: (f64, f64),
) -> Result<f64, (f64, f64, f64)> {
    refine(f, a, b, gauss2(f, a, b)?, CELL_DEPTH)
}

/// Largest difference, relative to the cell's probability scale, between one Gauss rule
/// and the sum over its quarters that counts as converged. Expected counts are then right
/// to about `1e-9 N`, far below their Poisson noise `sqrt(N p)`.
const CELL_TOLERANCE: f64 = 1e-10;
/// Deepest subdivision of a cell: `4^6` quarters in the limit, though only the quarters
/// that a jump crosses are refined (about `2^k` of them at level `k`).
const CELL_DEPTH: u32 = 6;

fn refine(
    f: &impl Fn(f64, f64) -> f64,
    a: (f64, f64),
    b: (f64, f64),
    whole: f64,
    depth: u32,
) -> Result<f64, (f64, f64, f64)> {
    let (am, bm) = (0.5 * (a.0 + a.1), 0.5 * (b.0 + b.1));
    let quarters = [
        ((a.0, am), (b.0, bm)),
        ((am, a.1), (b.0, bm)),
        ((a.0, am), (bm, b.1)),
        ((am, a.1), (bm, b.1)),
    ];
    let mut parts = [0.0; 4];
    for (part, &(qa, qb)) in parts.iter_mut().zip(&quarters) {
        *part = gauss2(f, qa, qb)?;
    }
    let sum: f64 = parts.iter().sum();
    // The scale is the rectangle's area: the pdf is O(1) on the unit domains checked here.
    let area = (a.1 - a.0) * (b.1 - b.0);
    if depth == 0 || (sum - whole).abs() <= CELL_TOLERANCE * area.max(f64::MIN_POSITIVE) {
        return Ok(sum);
    }
    let mut total = 0.0;
    for (part, &(qa, qb)) in parts.iter().zip(&quarters) {
        total += refine(f, qa, qb, *part, depth - 1)?;
    }
    Ok(total)
}

// ANCHOR_END: adaptive

/// Integral of `f` over `[a0, a1] x [b0, b1]` by a tensor 8x8 Gauss-Legendre rule.
/// Returns `Err` with the point if `f` is negative or not finite at a node.
fn gauss2(
    f: &impl Fn(f64, f64) -> f64,
    a: (f64, f64),
    b: (f64, f64),
) -> Result<f64, (f64, f64, f64)> {
    let (ha, ma) = ((a.1 - a.0) / 2.0, (a.1 + a.0) / 2.0);
    let (hb, mb) = ((b.1 - b.0) / 2.0, (b.1 + b.0) / 2.0);
    let mut sum = 0.0;
    for &(xa, wa) in &GAUSS8 {
        for &(xb, wb) in &GAUSS8 {
            let (s, t) = (ma + ha * xa, mb + hb * xb);
            let v = f(s, t);
            if v.is_nan() || v < 0.0 || v.is_infinite() {
                return Err((s, t, v));
            }
            sum += wa * wb * v;
        }
    }
    Ok(sum * ha * hb)
}

// ANCHOR: expected
/// Probability of each cell under the claimed pdf: the integral of the pdf over the cell,
/// in the cell's own coordinates with the measure's Jacobian:
/// square `dx dy`; disc `dA = (1/2) d(r^2) dphi`; sphere `dOmega = dz dphi`.
/// A sphere row containing the equator is integrated as two halves, so a hemisphere pdf's
/// jump at `z = 0` is integrated exactly.
fn cell_probabilities(warp: &dyn Warp, rows: usize, cols: usize) -> Result<Vec<f64>, String> {
    let domain = warp.domain();
    let mut probs = Vec::with_capacity(rows * cols);
    for i in 0..rows {
        for j in 0..cols {
            let (a0, a1) = (i as f64 / rows as f64, (i + 1) as f64 / rows as f64);
            let (b0, b1) = (j as f64 / cols as f64, (j + 1) as f64 / cols as f64);
            let integral = match domain {
                Domain::Interval { lo, hi } => {
                    let f =
                        |s: f64, _| warp.pdf(DVec3::new(lo + s * (hi - lo), 0.0, 0.0)) * (hi - lo);
                    integrate2(&f, (a0, a1), (0.0, 1.0))
                }
                Domain::Square => {
                    integrate2(&|s, t| warp.pdf(DVec3::new(t, s, 0.0)), (a0, a1), (b0, b1))
                }
                Domain::Disc => {
                    let f = |s: f64, t: f64| {
                        let (r, phi) = (s.sqrt(), t * TAU);
                        warp.pdf(DVec3::new(r * phi.cos(), r * phi.sin(), 0.0)) * 0.5 * TAU
                    };
                    integrate2(&f, (a0, a1), (b0, b1))
                }
                Domain::Sphere => {
                    let f = |s: f64, t: f64| {
                        let (z, phi) = (2.0 * s - 1.0, t * TAU);
                        let r = (1.0 - z * z).max(0.0).sqrt();
                        warp.pdf(DVec3::new(r * phi.cos(), r * phi.sin(), z)) * 2.0 * TAU
                    };
                    if a0 < 0.5 && a1 > 0.5 {
                        integrate2(&f, (a0, 0.5), (b0, b1))
                            .and_then(|x| Ok(x + integrate2(&f, (0.5, a1), (b0, b1))?))
                    } else {
                        integrate2(&f, (a0, a1), (b0, b1))
                    }
                }
            };
            let p = integral.map_err(|(s, t, v)| {
                format!("the pdf is {v} (negative or not finite) in cell ({i}, {j}) at cell coordinates ({s:.6}, {t:.6})")
            })?;
            probs.push(p);
        }
    }
    Ok(probs)
}
// ANCHOR_END: expected

/// Draws the samples, bins them, and runs Pearson's test.
///
/// # Errors
/// A message naming the first invalid sample, a negative pdf, or what `pearson` rejects
/// (samples in zero-probability cells, a pdf that does not integrate to 1).
pub fn chi_squared(
    warp: &dyn Warp,
    options: &Options,
) -> Result<(chi2::Chi2, Vec<u64>, Vec<f64>), String> {
    let domain = warp.domain();
    let (rows, cols) = grid(domain, options.resolution);
    let mut rng = rng::seeded(options.seed);
    let mut observed = vec![0u64; rows * cols];
    for k in 0..options.samples {
        let p = warp.sample(&mut rng);
        if let Some(why) = outside(domain, p) {
            return Err(format!("sample {k} = {p:?}: {why}"));
        }
        observed[cell_of(domain, p, rows, cols)] += 1;
    }
    let expected: Vec<f64> = cell_probabilities(warp, rows, cols)?
        .into_iter()
        .map(|p| p * options.samples as f64)
        .collect();
    let result = chi2::pearson(&observed, &expected, 5.0).map_err(|e| e.to_string())?;
    Ok((result, observed, expected))
}

/// The chi-squared finding, writing images on failure.
fn chi_squared_finding(warp: &dyn Warp, options: &Options) -> Finding {
    let mut finding = Finding::new(
        "chi_squared",
        format!(
            "{} samples binned into cells of the domain match the integral of the pdf over each cell \
             (Pearson, p >= {:.3e})",
            options.samples, options.alpha
        ),
    );
    match chi_squared(warp, options) {
        Ok((result, observed, expected)) => {
            let ok = result.p_value >= options.alpha;
            finding.record(ok, || {
                let images = write_failure_images(warp, options, &observed, &expected)
                    .map(|dir| format!("; images in {}", dir.display()))
                    .unwrap_or_default();
                let (_, cols) = grid(warp.domain(), options.resolution);
                format!(
                    "chi^2 = {:.1} with {} degrees of freedom, p = {:.3e}; the cells furthest from the pdf:{}{images}",
                    result.statistic,
                    result.dof,
                    result.p_value,
                    worst_cells(warp.domain(), &observed, &expected, cols, 3)
                )
            });
        }
        Err(why) => finding.record(false, || why),
    }
    finding
}

/// Central-difference area element of `warp` at `u`, on its domain.
fn area_element(warp: &dyn Warp, u: DVec2, h: f64) -> Option<f64> {
    let du = (warp.warp(u + DVec2::new(h, 0.0))? - warp.warp(u - DVec2::new(h, 0.0))?) / (2.0 * h);
    let dv = (warp.warp(u + DVec2::new(0.0, h))? - warp.warp(u - DVec2::new(0.0, h))?) / (2.0 * h);
    Some(match warp.domain() {
        Domain::Interval { .. } => du.x.abs(),
        Domain::Square | Domain::Disc => (du.x * dv.y - du.y * dv.x).abs(),
        Domain::Sphere => du.cross(dv).length(),
    })
}

// ANCHOR: jacobian
/// The Jacobian check: `p(T(u)) |dT/du| = 1` at `options.points` random points of the
/// square (kept `1e-3` away from its edges, where warps may fold), to a relative error of
/// `1e-4` (central differences with step `1e-6` are accurate to about `1e-8` for smooth
/// warps, so the bound has margin).
pub fn jacobian(warp: &dyn Warp, options: &Options) -> Option<Finding> {
    warp.warp(DVec2::splat(0.5))?;
    let mut finding = Finding::new(
        "jacobian",
        "p(T(u)) |det dT/du| = 1 to a relative error of 1e-4",
    );
    let mut rng = rng::seeded(options.seed ^ 0x1AC0);
    for _ in 0..options.points {
        let u = DVec2::new(
            rng::uniform(&mut rng, 1e-3, 1.0 - 1e-3),
            rng::uniform(&mut rng, 1e-3, 1.0 - 1e-3),
        );
        let (Some(p), Some(area)) = (warp.warp(u), area_element(warp, u, 1e-6)) else {
            finding.record(false, || format!("the warp is undefined near u = {u:?}"));
            continue;
        };
        let product = warp.pdf(p) * area;
        finding.measure((product - 1.0).abs(), 1e-4, || {
            format!("at u = {u:?}: T(u) = {p:?}, pdf = {:.6e}, |dT/du| = {area:.6e}, product {product:.6e}", warp.pdf(p))
        });
    }
    Some(finding)
}
// ANCHOR_END: jacobian

/// The round-trip check `T^-1(T(u)) = u`, to `1e-9`.
pub fn round_trip(warp: &dyn Warp, options: &Options) -> Option<Finding> {
    warp.invert(warp.warp(DVec2::splat(0.5))?)?;
    let mut finding = Finding::new("round_trip", "T^-1(T(u)) = u within 1e-9");
    let mut rng = rng::seeded(options.seed ^ 0x2077);
    for _ in 0..options.points {
        let u = square_point(&mut rng);
        let back = warp.warp(u).and_then(|p| warp.invert(p));
        // `max_abs`, not glam's `max_element`, which drops a NaN in the first component.
        let err = back.map_or(f64::INFINITY, |b| crate::numeric::max_abs((b - u).to_array()));
        finding.measure(err, 1e-9, || format!("u = {u:?} came back as {back:?}"));
    }
    Some(finding)
}

/// Checks a warp of the unit square given as plain functions, with [`Options::tests`].
pub fn check_square(
    name: &str,
    domain: Domain,
    sample: fn(DVec2) -> DVec3,
    pdf: fn(DVec3) -> f64,
    invert: Option<fn(DVec3) -> DVec2>,
) -> Verdict {
    check(
        &SquareWarp {
            name: name.into(),
            domain,
            sample,
            pdf,
            invert,
        },
        &Options::tests(),
    )
}

/// Every check that applies to `warp`.
pub fn check(warp: &dyn Warp, options: &Options) -> Verdict {
    let mut verdict = Verdict::new(format!("sampler {}", warp.name()));
    verdict.findings.push(chi_squared_finding(warp, options));
    verdict.findings.extend(jacobian(warp, options));
    verdict.findings.extend(round_trip(warp, options));
    verdict
}

/// Writes `observed`, `expected` and `difference` PNGs (one pixel block per cell) into
/// `warp-failures/<name>/` of the target directory (`CARGO_TARGET_DIR` if set, else the
/// project's `target/`) and returns that directory. Rows are the cells' first coordinate
/// (the interval's `x`, the square's `u2`, the disc's `r^2`, the sphere's `z`), increasing
/// upwards; columns the second (the square's `u1`, the azimuth), increasing to the right.
fn write_failure_images(
    warp: &dyn Warp,
    options: &Options,
    observed: &[u64],
    expected: &[f64],
) -> Option<PathBuf> {
    let (rows, cols) = grid(warp.domain(), options.resolution);
    let safe: String = warp
        .name()
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    let target = std::env::var_os("CARGO_TARGET_DIR").map_or_else(
        || PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target"),
        PathBuf::from,
    );
    let dir = target.join("warp-failures").join(safe);
    std::fs::create_dir_all(&dir).ok()?;
    let max = expected
        .iter()
        .copied()
        .fold(0.0, f64::max)
        .max(observed.iter().copied().max().unwrap_or(0) as f64);
    let scale = 4;
    let image = |value: &dyn Fn(usize) -> [u8; 3]| {
        image::RgbImage::from_fn((cols * scale) as u32, (rows * scale) as u32, |x, y| {
            let (i, j) = (rows - 1 - y as usize / scale, x as usize / scale);
            image::Rgb(value(i * cols + j))
        })
    };
    let grey = |v: f64| {
        let g = (255.0 * (v / max).clamp(0.0, 1.0)) as u8;
        [g, g, g]
    };
    // The three images land together (the project's one writer), never half of them.
    let mut files = crate::output::FileSet::new();
    let mut stage = |name: &str, img: image::RgbImage| {
        let png = crate::spectral::display::encode_png(img.width(), img.height(), img.as_raw());
        png.ok()
            .and_then(|bytes| files.write(&dir.join(name), &bytes).ok())
    };
    stage("observed.png", image(&|k| grey(observed[k] as f64)))?;
    stage("expected.png", image(&|k| grey(expected[k])))?;
    let difference = image(&|k| {
        // Red: more samples than expected; blue: fewer; in standard deviations, saturating at 5.
        let z = (observed[k] as f64 - expected[k]) / expected[k].max(1.0).sqrt();
        let c = (255.0 * (z.abs() / 5.0).min(1.0)) as u8;
        if z > 0.0 {
            [255, 255 - c, 255 - c]
        } else {
            [255 - c, 255 - c, 255]
        }
    });
    stage("difference.png", difference)?;
    files.commit().ok()?;
    Some(dir)
}
