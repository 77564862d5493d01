//! The cells of the warp checker's chi-squared test: the equal-area grid of each domain,
//! where a sample falls, and how much probability the claimed pdf puts in each cell
//! (adaptive Gauss-Legendre integrals). Chapter: *Checking a sampler*.

use std::f64::consts::TAU;

use glam::DVec3;

use super::{Domain, Warp};
use crate::stats::StatsError;

// ANCHOR: cells
/// The cells of a domain: `(rows, cols)` and, for a point, its cell index.
/// Sphere cells are equal-area: rows in `z = cos(theta)`, columns in `phi`.
/// Disc cells are equal-area: rows in `r^2`, columns in `phi`.
pub(super) fn cell_of(domain: Domain, p: DVec3, rows: usize, cols: usize) -> usize {
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
pub(super) fn worst_cells(
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

/// The `(rows, cols)` of a domain's grid at `resolution`. On the sphere the number of rows
/// is odd (an even `resolution` is rounded up), so that the equator is never a cell
/// boundary: a correct hemisphere sampler whose `z` rounds to `-1e-17` then lands in the
/// straddling row, whose upper half has mass, instead of a row of `E = 0`.
pub(super) fn grid(domain: Domain, resolution: usize) -> (usize, usize) {
    match domain {
        Domain::Interval { .. } => (resolution * resolution, 1),
        Domain::Square | Domain::Disc => (resolution, resolution),
        Domain::Sphere => {
            let rows = resolution | 1;
            (rows, 2 * rows)
        }
    }
}

/// Why a sample is not in the domain, if it is not, naming the domain in `words` (the
/// density's own: "the hemisphere" for a hemisphere sampler on [`Domain::Sphere`]) and
/// saying which condition the sample breaks, its numbers written plainly.
pub(super) fn outside(domain: Domain, words: &str, p: DVec3) -> Option<String> {
    if !p.is_finite() {
        return Some("the sample is not finite".into());
    }
    let tol = 1e-9;
    let flat = |why: String| {
        if p.z == 0.0 {
            why
        } else {
            format!("its z is {:?}, not 0", p.z)
        }
    };
    let why = match domain {
        Domain::Interval { lo, hi } => (p.x < lo || p.x > hi || p.y != 0.0 || p.z != 0.0)
            .then(|| format!("it is not a point (x, 0, 0) with x in [{lo}, {hi}]")),
        Domain::Square => (p.x < 0.0 || p.x > 1.0 || p.y < 0.0 || p.y > 1.0 || p.z != 0.0)
            .then(|| flat("x and y must lie in [0, 1]".into())),
        Domain::Disc => {
            let r2 = p.x * p.x + p.y * p.y;
            (r2 > 1.0 + tol || p.z != 0.0).then(|| flat(format!("x^2 + y^2 = {r2:?} > 1")))
        }
        Domain::Sphere => {
            let length = p.length();
            ((length - 1.0).abs() > tol)
                .then(|| format!("its length is {length:?}, not 1 (to 1e-9)"))
        }
    };
    why.map(|why| format!("the sample lies outside {words}: {why}"))
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
pub(super) fn cell_probabilities(
    warp: &dyn Warp,
    rows: usize,
    cols: usize,
) -> Result<Vec<f64>, StatsError> {
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
            let p = integral.map_err(|(s, t, value)| StatsError::InvalidPdf {
                cell: (i, j),
                at: (s, t),
                value,
            })?;
            probs.push(p);
        }
    }
    Ok(probs)
}
// ANCHOR_END: expected
