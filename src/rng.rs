//! The project's one pseudo-random generator: PCG-64 with a fixed seed.
//!
//! Every test, check and figure draws from [`seeded`], so a failure reproduces exactly
//! from the seed printed in its message.

use glam::DVec3;
use rand::{RngExt, SeedableRng};

/// PCG-64 (O'Neill 2014): small, fast, statistically strong, seedable.
pub type Rng = rand_pcg::Pcg64;

/// A generator seeded with `seed`.
pub fn seeded(seed: u64) -> Rng {
    Rng::seed_from_u64(seed)
}

/// A uniform `f64` in `[lo, hi)`.
pub fn uniform(rng: &mut Rng, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * rng.random::<f64>()
}

/// A standard normal deviate from two uniforms, by Box and Muller's transform
/// `sqrt(-2 ln(1 - u1)) cos(2 pi u2)` (`1 - u1` is in `(0, 1]`, so the logarithm is
/// finite): the statistics chapter's experiments and the tests draw their normal data
/// here, so that they depend on no sampler of the book (the sphere chapter derives the
/// transform, `sampling::sphere::box_muller`, and checks it).
pub fn standard_normal(rng: &mut Rng) -> f64 {
    let (u1, u2): (f64, f64) = (rng.random(), rng.random());
    (-2.0 * (1.0 - u1).ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

/// A log-uniform `f64` in `[lo, hi)` (`lo > 0`): every decade equally likely.
pub fn log_uniform(rng: &mut Rng, lo: f64, hi: f64) -> f64 {
    (uniform(rng, lo.ln(), hi.ln())).exp()
}

/// A unit vector perpendicular to the unit vector `n` (any one, chosen stably).
pub fn perpendicular(n: DVec3) -> DVec3 {
    n.any_orthonormal_vector()
}
