//! The fixed inputs that the book's speed tables (`cargo run --release`, the figures job)
//! and the criterion benches (`cargo bench -p raylemma-bench`) both time, so that the two measure the same
//! work. Each is drawn from its own fixed seed.

use crate::sampling::sphere::sphere_uniform;
use glam::DVec3;
use rand::RngExt as _;

use crate::real::Real;
use crate::rng;
use crate::sampling::tabulated::{Piecewise1D, PiecewiseLinear1D};

/// `n` uniform numbers in `[0, 1)` from a fixed seed: the inputs of the speed tables and
/// benches that time a function of one uniform number (tabulated, wavelength, emission).
pub fn uniform_inputs(n: usize) -> Vec<f64> {
    let mut rng = rng::seeded(0x7157);
    (0..n).map(|_| rng.random::<f64>()).collect()
}

/// Rays for timing: from 5 radii away towards random points within 1.4 radii of a unit
/// sphere's centre, so that about half of them hit.
pub fn timing_rays<R: Real>(n: usize) -> (Vec<R::Ray>, R::Sphere) {
    let mut rng = rng::seeded(0x7157);
    let rays = (0..n)
        .map(|_| {
            let origin = sphere_uniform(&mut rng) * 5.0;
            let target = sphere_uniform(&mut rng) * 1.4 * rng::uniform(&mut rng, 0.0, 1.0).cbrt();
            R::ray(origin, target - origin)
        })
        .collect();
    (rays, R::sphere(DVec3::ZERO, 1.0))
}

/// Cosines for timing: 4096 uniform in `[0, 1]`, seeded.
pub fn timing_cosines(n: usize) -> Vec<f64> {
    let mut rng = rng::seeded(0xf7e5);
    (0..n).map(|_| rng::uniform(&mut rng, 0.0, 1.0)).collect()
}

/// `n` random unit normals for timing (fixed seed).
pub fn timing_normals(n: usize) -> Vec<DVec3> {
    let mut r = rng::seeded(0xf4a);
    (0..n).map(|_| sphere_uniform(&mut r)).collect()
}

/// Table sizes of the speed table and the benchmark.
pub const TIMING_BINS: [usize; 4] = [16, 256, 4096, 65536];

/// A random table of `bins` bins on `[0, 1]`, in both forms (the linear one with
/// `bins + 1` knots), for timing.
pub fn timing_tables(bins: usize) -> (Piecewise1D, PiecewiseLinear1D) {
    let mut rng = rng::seeded(0x71b + bins as u64);
    let values: Vec<f64> = (0..=bins).map(|_| 0.1 + rng.random::<f64>()).collect();
    let constant = Piecewise1D::uniform(0.0, 1.0, &values[..bins]);
    let linear = PiecewiseLinear1D::uniform(0.0, 1.0, &values);
    match (constant, linear) {
        (Ok(c), Ok(l)) => (c, l),
        _ => unreachable!("positive random values on a valid grid"),
    }
}
