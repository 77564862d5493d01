//! Russian roulette. Chapter: *Russian roulette* (`chapters/transport/roulette.md`).
//!
//! An estimator `F` is replaced by `F' = F / p` with probability `p`, else 0. Then
//! `E[F'] = E[F]` and `Var[F'] = E[F^2] / p - E[F]^2`. Applied at every vertex of a path,
//! it ends paths in finite expected time without bias; here on a furnace whose answer is
//! known, `L = L_e + a L = L_e / (1 - a)`.

use glam::DVec2;

use crate::rng::{self, Rng};
use crate::transport::lambert::{
    furnace_bounce_uniform, furnace_uniform_variance, tail_index, uniform_weight_moment,
};

// ANCHOR: roulette
// EXERCISE transport/roulette roulette: Russian roulette on one value, unbiased, with p = 0 never surviving
/// Russian roulette on one value: `f / p` if `u < p`, else 0, for `u` uniform in `[0, 1)`.
/// `u < p` (not the source notes' `u <= p`) so that `p = 0` never survives (and never divides by 0)
/// and `p = 1` always does.
pub fn roulette(f: f64, p: f64, u: f64) -> f64 {
    if u < p { f / p } else { 0.0 }
}
// END EXERCISE
// ANCHOR_END: roulette

/// The source notes' rule, `u <= p`: identical except at `u = p`, which for `p = 0` and
/// `u = 0` (a value the `rand` crate's `[0, 1)` floats, 53 random bits, do produce, with
/// probability `2^-53`) gives `0 / 0`.
pub fn roulette_seed(f: f64, p: f64, u: f64) -> f64 {
    if u <= p { f / p } else { 0.0 }
}

// ANCHOR: single_variance
/// `Var[F'] = E[F'^2] - E[F']^2 = p E[F^2] / p^2 - E[F]^2 = E[F^2] / p - E[F]^2`.
pub fn roulette_variance(mean: f64, second_moment: f64, p: f64) -> f64 {
    second_moment / p - mean * mean
}
// ANCHOR_END: single_variance

/// How a furnace path decides to continue after each bounce.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Survival {
    /// No roulette: exactly `depth` bounces, then stop (biased by the missing tail).
    Depth(u32),
    /// Fixed survival probability `q` at every bounce.
    Fixed(f64),
    /// `p = min(1, T)` with `T` the path throughput (after earlier divisions).
    Throughput,
}

/// The furnace of the chapter: emission `L_e`, albedo `a`.
#[derive(Clone, Copy, Debug)]
pub struct Furnace {
    /// Emitted radiance `L_e` of every surface.
    pub emission: f64,
    /// Albedo `a < 1` of every surface.
    pub albedo: f64,
}

impl Furnace {
    /// The exact radiance `L_e / (1 - a)`.
    pub fn radiance(&self) -> f64 {
        self.emission / (1.0 - self.albedo)
    }

    /// The expectation of the path cut after `depth` bounces: `L_e (1 - a^(depth+1)) / (1 - a)`.
    pub fn truncated(&self, depth: u32) -> f64 {
        self.radiance() * (1.0 - self.albedo.powi(depth as i32 + 1))
    }

    /// `E[w^2]` of one bounce's weight `w = 2 a cos(theta)`, `cos(theta)` uniform on
    /// `[0, 1]` (uniform hemisphere directions): `4 a^2 / 3`.
    pub fn weight_second_moment(&self) -> f64 {
        4.0 * self.albedo * self.albedo / 3.0
    }
}

// ANCHOR: path
/// One path in the furnace, directions uniform on the hemisphere (bounce weight
/// `w = 2 a cos`, mean `a`). `divide = false` plants the bug of not dividing by `p`.
/// Returns the estimate and the number of vertices.
pub fn furnace_path(
    furnace: &Furnace,
    survival: Survival,
    divide: bool,
    rng: &mut Rng,
) -> (f64, u32) {
    let (mut radiance, mut throughput, mut vertices) = (0.0, 1.0, 0u32);
    loop {
        radiance += throughput * furnace.emission;
        vertices += 1;
        let u = DVec2::new(rng::uniform(rng, 0.0, 1.0), rng::uniform(rng, 0.0, 1.0));
        throughput *= furnace_bounce_uniform(furnace.albedo, u);
        let p = match survival {
            Survival::Depth(d) => {
                if vertices > d {
                    return (radiance, vertices);
                }
                1.0
            }
            Survival::Fixed(q) => q,
            Survival::Throughput => throughput.min(1.0),
        };
        if rng::uniform(rng, 0.0, 1.0) >= p {
            return (radiance, vertices);
        }
        if divide {
            throughput /= p;
        }
    }
}
// ANCHOR_END: path

// ANCHOR: path_variance
/// The exact variance of [`furnace_path`] with fixed survival `q`, from the recursion
/// `X = L_e + B (w / q) X'` (`B` Bernoulli(`q`), `w` the bounce weight, all independent):
/// `E[X] = L_e / (1 - a)`, and `E[X^2] = L_e^2 + 2 a L_e E[X] + (E[w^2] / q) E[X^2]`, so
/// `E[X^2] = L_e^2 (1 + a) / ((1 - a)(1 - E[w^2] / q))`, finite only for `q > E[w^2]`.
/// Returns infinity for `q <= E[w^2]`.
pub fn path_variance(furnace: &Furnace, q: f64) -> f64 {
    let (le, a, w2) = (
        furnace.emission,
        furnace.albedo,
        furnace.weight_second_moment(),
    );
    if q <= w2 {
        return f64::INFINITY;
    }
    let mean = furnace.radiance();
    le * le * (1.0 + a) / ((1.0 - a) * (1.0 - w2 / q)) - mean * mean
}

/// The tail index of [`furnace_path`] with fixed survival `q`: the path is
/// `X = L_e + A X'` with the random factor `A = B w / q`, and its moments `E[X^s]` are
/// finite exactly for `s` below the root `kappa` of
/// `E[A^kappa] = q^(1 - kappa) (2a)^kappa / (kappa + 1) = 1` (Kesten 1973, Goldie 1991).
/// `kappa > 2` exactly when `q > E[w^2]` (finite variance); the sample variance is itself a
/// reliable estimate only for `kappa > 4`.
pub fn fixed_survival_tail_index(furnace: &Furnace, q: f64) -> f64 {
    let a = furnace.albedo;
    tail_index(|s| q.powf(1.0 - s) * uniform_weight_moment(a, s))
}

/// The exact variance of [`furnace_path`] with the throughput rule `p = min(1, T)`: the
/// walk of `lambert::furnace_walk` with uniform bounces, whose variance is
/// [`furnace_uniform_variance`] (times `L_e^2`): `a / (1 - a)^2` for `a <= 1/2`, infinite
/// for `a >= sqrt(3)/2`.
pub fn throughput_rule_variance(furnace: &Furnace) -> f64 {
    furnace.emission * furnace.emission * furnace_uniform_variance(furnace.albedo)
}

/// Expected number of vertices of a path with fixed survival `q`: `1 / (1 - q)`.
pub fn expected_vertices(q: f64) -> f64 {
    1.0 / (1.0 - q)
}

/// The predicted efficiency `1 / (Var x time)` with time `ns_per_vertex / (1 - q)`.
pub fn predicted_efficiency(furnace: &Furnace, q: f64, ns_per_vertex: f64) -> f64 {
    1.0 / (path_variance(furnace, q) * ns_per_vertex * expected_vertices(q))
}

/// The `q` maximising [`predicted_efficiency`] (independent of the time per vertex), on a
/// grid of step `1e-4` over `(E[w^2], 1)`.
pub fn optimal_survival(furnace: &Furnace) -> f64 {
    let lo = furnace.weight_second_moment();
    (1..10_000)
        .map(|i| lo + (1.0 - lo) * f64::from(i) / 10_000.0)
        .max_by(|&x, &y| {
            predicted_efficiency(furnace, x, 1.0).total_cmp(&predicted_efficiency(furnace, y, 1.0))
        })
        .unwrap_or(1.0)
}
// ANCHOR_END: path_variance
