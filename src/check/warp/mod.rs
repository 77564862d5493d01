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
//! samples where the claimed pdf is zero or not finite, negative pdfs, samples in cells
//! where the pdf integrates to zero, and pdfs whose integral is not 1. On a chi-squared failure it writes observed, expected and
//! difference images a student can open.
//!
//! Called like every checker, `check(&warp, &options)` with the common
//! [`Options`] (samples, seed, level); the grid and the Jacobian points
//! follow from the number of samples ([`WarpOptions`]). The planted bugs it must reject
//! are in [`planted`].

mod cells;
mod images;
pub mod planted;

use glam::{DVec2, DVec3};

use super::{Finding, Options, Verdict};
use crate::numeric::tuple_text;
use crate::rng::{self, Rng};
use crate::stats::{StatsError, chi2};
use cells::{cell_of, cell_probabilities, grid, outside, worst_cells};
use images::{remove_stale_images, write_failure_images};

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

impl Domain {
    /// The domain in words, for messages: "the sphere", "the disc", "the square",
    /// "the interval [lo, hi]".
    pub fn words(self) -> String {
        match self {
            Domain::Interval { lo, hi } => format!("the interval [{lo}, {hi}]"),
            Domain::Square => "the square".into(),
            Domain::Disc => "the disc".into(),
            Domain::Sphere => "the sphere".into(),
        }
    }
}

/// A sampler and the density it claims. Implement this for your own sampler to check it.
pub trait Warp: Sync {
    /// A name for reports and failure images.
    fn name(&self) -> String;
    /// The domain of the samples.
    fn domain(&self) -> Domain;
    /// The domain in the words of the density sampled, for messages ("outside the
    /// hemisphere" for a hemisphere sampler, whose domain is the sphere); by default
    /// [`Domain::words`].
    fn domain_words(&self) -> String {
        self.domain().words()
    }
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
/// `fn(DVec2) -> DVec3` sampler with its `fn(DVec3) -> f64` pdf
/// (`SquareWarp::new(name, domain, sample, pdf)`, with [`inverse`](SquareWarp::inverse)
/// for the round trip).
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

impl<S, P> SquareWarp<S, P> {
    /// The warp `sample` with the claimed density `pdf` on `domain`, and no inverse.
    pub fn new(name: impl Into<String>, domain: Domain, sample: S, pdf: P) -> Self {
        Self {
            name: name.into(),
            domain,
            sample,
            pdf,
            invert: None,
        }
    }

    /// The same warp with the inverse `invert` (enables the round-trip check).
    pub fn inverse(self, invert: fn(DVec3) -> DVec2) -> Self {
        Self {
            invert: Some(invert),
            ..self
        }
    }
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

/// The default number of samples of the chi-squared test.
pub const SAMPLES: usize = 1_000_000;
/// The samples of the book's sampler tests (with 21 rows and 5 000 points, by the rule of
/// [`WarpOptions`]).
pub const TEST_SAMPLES: usize = 400_000;
/// The default seed of the samples (the Jacobian and round-trip points are drawn from
/// seeds derived from it).
pub const SEED: u64 = 0xC41;

// ANCHOR: rule
/// From this many samples on, the checker bins on the fine grid.
pub const FINE_SAMPLES: usize = 1_000_000;
/// Rows of cells and Jacobian points below [`FINE_SAMPLES`] (the sampler tests' grid).
pub const COARSE_GRID: (usize, usize) = (21, 5_000);
/// Rows of cells and Jacobian points from [`FINE_SAMPLES`] on (the default's grid).
pub const FINE_GRID: (usize, usize) = (51, 10_000);

/// The warp checker's settings: the samples, seed and level of the common
/// [`Options`], and the two knobs of its own that follow from the samples by a rule.
///
/// **The rule.** Below [`FINE_SAMPLES`] samples the chi-squared test bins on 21 rows of
/// cells and the Jacobian and round-trip checks use 5 000 points ([`COARSE_GRID`]): the
/// sampler tests' 400 000 samples then fill each of the sphere's 21 x 42 cells with about
/// 450. From [`FINE_SAMPLES`] on it bins on 51 rows and uses 10 000 points
/// ([`FINE_GRID`]): the default's 1 000 000 samples fill each of 51 x 102 cells with about
/// 190. A check that needs another grid (a light's silhouette, an interval's cells) sets
/// the field itself: `WarpOptions { resolution: 41, ..WarpOptions::from(&options) }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WarpOptions {
    /// Samples for the chi-squared test (the cases of [`Options`]).
    pub samples: usize,
    /// Cells along each axis of the domain. On the sphere the rows of `cos(theta)` are made
    /// odd (an even value is rounded up), so that a row straddles the equator and no
    /// hemisphere's edge is a cell boundary.
    pub resolution: usize,
    /// Points for the Jacobian and round-trip checks.
    pub points: usize,
    /// Seed of the random numbers.
    pub seed: u64,
    /// Significance level of the chi-squared test.
    pub alpha: f64,
}

impl From<&Options> for WarpOptions {
    fn from(options: &Options) -> Self {
        let samples = options.cases_or(SAMPLES);
        let (resolution, points) = if samples < FINE_SAMPLES {
            COARSE_GRID
        } else {
            FINE_GRID
        };
        Self {
            samples,
            resolution,
            points,
            seed: options.seed_or(SEED),
            alpha: options.level(),
        }
    }
}
// ANCHOR_END: rule

impl From<Options> for WarpOptions {
    fn from(options: Options) -> Self {
        Self::from(&options)
    }
}

/// What the warp checker's functions take: the common [`Options`] (read by the rule of
/// [`WarpOptions`]) or a [`WarpOptions`] with its own grid. Both are passed by reference,
/// `check(&warp, &options)`, like every checker's options.
pub trait ToWarpOptions {
    /// The settings to check with.
    fn to_warp_options(&self) -> WarpOptions;
}

impl ToWarpOptions for Options {
    fn to_warp_options(&self) -> WarpOptions {
        WarpOptions::from(self)
    }
}

impl ToWarpOptions for WarpOptions {
    fn to_warp_options(&self) -> WarpOptions {
        *self
    }
}

impl Default for WarpOptions {
    /// [`Options::default`] by the rule: 1 000 000 samples, 51 rows, 10 000 points, seed
    /// [`SEED`], the suite's level.
    fn default() -> Self {
        Self::from(&Options::default())
    }
}

/// The hint for a hemisphere sampler's sample below the horizon: the checker's axes
/// (`+z` up), and how many of the `rest` samples still to draw are below it too (about
/// half for a sampler written with another axis up, which is then named as the likely
/// cause).
fn below_horizon(warp: &dyn Warp, rng: &mut Rng, rest: usize) -> String {
    let below = (0..rest).filter(|_| warp.sample(rng).z < 0.0).count() + 1;
    let total = rest + 1;
    let mut hint = format!(
        ". The hemisphere here is z >= 0 (+z is up, the normal); {below} of the {total} \
         samples from this one on have z < 0"
    );
    if below * 4 > total {
        hint += ": a sampler written with y (or another axis) up must map its up axis to z";
    }
    hint
}

/// Draws the samples, bins them, and runs Pearson's test.
///
/// # Errors
/// A [`StatsError`] naming the first invalid sample (not finite, outside the domain, or
/// where the claimed pdf is not positive and finite), a negative pdf, or what `pearson`
/// rejects (samples in zero-probability cells, a pdf that does not integrate to 1).
pub fn chi_squared(
    warp: &dyn Warp,
    options: &impl ToWarpOptions,
) -> Result<(chi2::Chi2, Vec<u64>, Vec<f64>), StatsError> {
    let options = options.to_warp_options();
    let domain = warp.domain();
    let (rows, cols) = grid(domain, options.resolution);
    let mut rng = rng::seeded(options.seed);
    let mut observed = vec![0u64; rows * cols];
    // ANCHOR: support
    for k in 0..options.samples {
        let p = warp.sample(&mut rng);
        let invalid = |problem: String| StatsError::InvalidSample {
            index: k as u64,
            sample: p,
            problem,
        };
        if let Some(why) = outside(domain, &warp.domain_words(), p) {
            return Err(invalid(why));
        }
        // Every sample must lie where the claimed pdf is positive: a renderer divides by it.
        // A cell's integral cannot see a few samples leaked just past a jump of the pdf,
        // such as a hemisphere's horizon, which crosses the cells of its row.
        let pdf = warp.pdf(p);
        if !(pdf > 0.0 && pdf.is_finite()) {
            let why = if !pdf.is_finite() {
                "not finite"
            } else if pdf < 0.0 {
                "negative"
            } else {
                "zero"
            };
            let mut problem =
                format!("the claimed pdf is {pdf} there ({why}), and a renderer divides by it");
            if domain == Domain::Sphere && p.z < 0.0 && pdf == 0.0 {
                problem += &below_horizon(warp, &mut rng, options.samples - k - 1);
            }
            return Err(invalid(problem));
        }
        observed[cell_of(domain, p, rows, cols)] += 1;
    }
    // ANCHOR_END: support
    let expected: Vec<f64> = cell_probabilities(warp, rows, cols)?
        .into_iter()
        .map(|p| p * options.samples as f64)
        .collect();
    let result = chi2::pearson(&observed, &expected, 5.0)?;
    Ok((result, observed, expected))
}

/// The chi-squared finding, writing images on failure.
fn chi_squared_finding(warp: &dyn Warp, options: &WarpOptions) -> Finding {
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
            if ok {
                remove_stale_images(warp);
            }
            let dir = (!ok)
                .then(|| write_failure_images(warp, options, &observed, &expected))
                .flatten();
            finding.picture = dir
                .as_ref()
                .map(|d| format!("{}", d.join("difference.png").display()));
            finding.record(ok, || {
                let images = dir
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
        Err(why) => finding.record(false, || why.to_string()),
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
/// square (kept `1e-3` away from its edges, where warps may fold or be singular), to a
/// relative error of `1e-4`. Central differences with step `1e-6` are accurate to about
/// `1e-7` even `1e-3` from the edges, where warps like `sqrt(u1)` are steep (their
/// truncation error grows like `u1^-2` there; rounding adds about `eps / h = 2e-10`), so
/// the bound has margin.
pub fn jacobian(warp: &dyn Warp, options: &impl ToWarpOptions) -> Option<Finding> {
    let options = options.to_warp_options();
    warp.warp(DVec2::splat(0.5))?;
    let mut finding = Finding::new(
        "jacobian",
        "p(T(u)) |det dT/du| = 1 to a relative error of 1e-4",
    )
    .in_unit("relative error");
    let mut rng = rng::seeded(options.seed ^ 0x1AC0);
    for _ in 0..options.points {
        let u = DVec2::new(
            rng::uniform(&mut rng, 1e-3, 1.0 - 1e-3),
            rng::uniform(&mut rng, 1e-3, 1.0 - 1e-3),
        );
        let (Some(p), Some(area)) = (warp.warp(u), area_element(warp, u, 1e-6)) else {
            finding.record(false, || {
                format!(
                    "the warp is undefined near u = {}",
                    tuple_text(u.to_array())
                )
            });
            continue;
        };
        let product = warp.pdf(p) * area;
        finding.measure((product - 1.0).abs(), 1e-4, || {
            format!(
                "at u = {}: T(u) = {}, pdf = {:.6e}, |dT/du| = {area:.6e}, product {product:.6e}",
                tuple_text(u.to_array()),
                tuple_text(p.to_array()),
                warp.pdf(p)
            )
        });
    }
    Some(finding)
}
// ANCHOR_END: jacobian

/// The round-trip check `T^-1(T(u)) = u`, to `1e-9`.
pub fn round_trip(warp: &dyn Warp, options: &impl ToWarpOptions) -> Option<Finding> {
    let options = options.to_warp_options();
    warp.invert(warp.warp(DVec2::splat(0.5))?)?;
    let mut finding = Finding::new("round_trip", "T^-1(T(u)) = u within 1e-9")
        .in_unit("distance in the unit square");
    let mut rng = rng::seeded(options.seed ^ 0x2077);
    for _ in 0..options.points {
        let u = square_point(&mut rng);
        let back = warp.warp(u).and_then(|p| warp.invert(p));
        // `max_abs`, not glam's `max_element`, which drops a NaN in the first component.
        let err = back.map_or(f64::INFINITY, |b| {
            crate::numeric::max_abs((b - u).to_array())
        });
        finding.measure(err, 1e-9, || {
            let back = back.map_or("nothing (the inverse is undefined there)".into(), |b| {
                tuple_text(b.to_array())
            });
            format!("u = {} came back as {back}", tuple_text(u.to_array()))
        });
    }
    Some(finding)
}

/// Every check that applies to `warp`: chi-squared, and the Jacobian and the round trip
/// where the warp provides them. `options` is the common [`Options`] (the samples,
/// default [`SAMPLES`]; the seed, default [`SEED`]; the level), or a [`WarpOptions`] with
/// its own grid.
pub fn check(warp: &dyn Warp, options: &impl ToWarpOptions) -> Verdict {
    let options = options.to_warp_options();
    let mut verdict = Verdict::new(format!("sampler {}", warp.name()));
    verdict.findings.push(chi_squared_finding(warp, &options));
    verdict.findings.extend(jacobian(warp, &options));
    verdict.findings.extend(round_trip(warp, &options));
    verdict
}
