//! Single-precision accuracy of a warp: how far its `f32` result is from a unit vector, and
//! how far its `cos θ` (the `z` component, which the pdf of a hemisphere sampler is built
//! from) is from the same formula evaluated in `f64`. Chapters: *Uniform sphere and
//! hemisphere*, *Cosine-weighted hemisphere* (the f32 columns of their tables).
//!
//! Errors are in units of `f32::EPSILON` (2⁻²³) and are computed in `f64` from the `f32`
//! results, so the measurement itself adds no rounding. A NaN or infinite result makes the
//! worst error NaN (see [`crate::numeric::max_abs`]), which fails any `err <= bound` check.
//!
//! The points are [`square_points`]`(&options)`: as many random points as the
//! [`Options`] say (default [`POINTS`]), from their seed (default [`SEED`]), then the
//! square's hard cases. The planted twin every measurement must catch is in
//! [`planted`].

use glam::{DVec2, DVec3, Vec2, Vec3};
use rand::RngExt as _;

use super::Options;

/// The default number of random points of [`square_points`].
pub const POINTS: usize = 200_000;
/// The default seed of [`square_points`] (the sampling chapters' tests and the f32
/// columns of their tables use it).
pub const SEED: u64 = 0xF32;

/// Random points of the unit square in `f32` (as many as `options` says, default
/// [`POINTS`], from its seed, default [`SEED`]), then its hard cases: every pair of `0`,
/// `1/2` and the largest `f32` below 1.
pub fn square_points(options: &Options) -> Vec<Vec2> {
    let (n, seed) = (options.cases_or(POINTS), options.seed_or(SEED));
    let below_one = 1.0 - f32::EPSILON / 2.0;
    let edges = [0.0, 0.5, below_one];
    let mut rng = crate::rng::seeded(seed);
    let mut v: Vec<Vec2> = (0..n)
        .map(|_| Vec2::new(rng.random::<f32>(), rng.random::<f32>()))
        .collect();
    for a in edges {
        for b in edges {
            v.push(Vec2::new(a, b));
        }
    }
    v
}

/// Worst `| |w| − 1 |` over `points`, in units of `f32::EPSILON`.
pub fn norm_error(warp: impl Fn(Vec2) -> Vec3, points: &[Vec2]) -> f64 {
    crate::numeric::max_abs(
        points
            .iter()
            .map(|&u| (warp(u).as_dvec3().length() - 1.0) / f64::from(f32::EPSILON)),
    )
}

/// Worst relative error of `z` over `points`, against `exact` (the same construction in
/// `f64`, from the same `u`), in units of `f32::EPSILON`; where the exact `z` is 0 the
/// error is `z` itself in those units.
pub fn z_error(
    warp: impl Fn(Vec2) -> Vec3,
    exact: impl Fn(DVec2) -> DVec3,
    points: &[Vec2],
) -> f64 {
    crate::numeric::max_abs(points.iter().map(|&u| {
        let (z, z64) = (f64::from(warp(u).z), exact(u.as_dvec2()).z);
        let err = if z64 != 0.0 { z / z64 - 1.0 } else { z };
        err / f64::from(f32::EPSILON)
    }))
}

/// Planted bugs of the single-precision measurements: each must show an error far above
/// the bound the correct constructions keep.
pub mod planted {
    use glam::{Vec2, Vec3};

    use crate::single::sampling::disc::disc_concentric;

    /// Malley's lift written `z = sqrt(1 - x^2 - y^2)`: in `f32` the difference cancels at
    /// the rim, so [`super::z_error`] against the `f64` Malley map is NaN or thousands of
    /// ε (chapter *Cosine-weighted hemisphere*).
    pub fn malley_naive_lift(u: Vec2) -> Vec3 {
        let p = disc_concentric(u);
        Vec3::new(p.x, p.y, (1.0 - p.x * p.x - p.y * p.y).max(0.0).sqrt())
    }
}
