//! The checker of Russian roulette on one value: any routine with the signature of
//! [`crate::transport::roulette::roulette`] (`f(value, p, u)`) can be checked against the
//! claims of the chapter *Russian roulette* (`chapters/transport/roulette.md`).
//!
//! * `unbiased`: `∫₀¹ F'(f, p, u) du = f` (midpoint rule in `u`, exact up to rounding);
//! * `survivors`: a survivor (`u < p`) carries `f / p`;
//! * `killed`: `u ≥ p` gives exactly 0;
//! * `never`: `p = 0` never survives, not even at `u = 0` (no `0 / 0`);
//! * `always`: `p = 1` always survives and returns `f`.
//!
//! Planted bugs that it must reject are in [`planted`], beside the source notes' own rule
//! ([`crate::transport::roulette::roulette_seed`]).

pub mod planted;

use super::{Finding, Options, Verdict};
use crate::rng;

/// Default number of points `u` per claim (the midpoint rule's too).
pub const CASES: usize = 10_000;
/// Default seed.
pub const SEED: u64 = 0x2011;
/// Bound of the relative errors, in units of `f64::EPSILON` (the midpoint sum rounds).
pub const BOUND: f64 = 64.0;

const VALUES: [f64; 3] = [1.0, 0.3, 7.5];
const PROBABILITIES: [f64; 4] = [0.1, 0.25, 0.5, 0.8];

/// Runs the chapter's claims on `f`; `options` sets the number of points `u` (default
/// [`CASES`]) and the seed of the random ones (default [`SEED`]).
pub fn roulette(f: &dyn Fn(f64, f64, f64) -> f64, options: &Options) -> Verdict {
    let m = options.cases_or(CASES).max(10);
    let mut rng = rng::seeded(options.seed_or(SEED));
    let eps = f64::EPSILON;
    let mut unbiased = Finding::new("unbiased", "int_0^1 F'(f, p, u) du = f (midpoint rule)")
        .in_unit("relative error in machine epsilons");
    for value in VALUES {
        for p in PROBABILITIES {
            // p m is a whole number for every p above and m a multiple of 20: the midpoints
            // below p are exactly p m of the m.
            let m = m - m % 20;
            let mean = compensated_sum((0..m).map(|k| f(value, p, (k as f64 + 0.5) / m as f64)))
                / m as f64;
            unbiased.measure((mean / value - 1.0).abs() / eps, BOUND, || {
                format!("f = {value}, p = {p}: the mean over u is {mean}")
            });
        }
    }
    let mut survivors = Finding::new("survivors", "u < p gives f / p")
        .in_unit("relative error in machine epsilons");
    let mut killed = Finding::new("killed", "u >= p gives 0");
    for _ in 0..m {
        let value = rng::log_uniform(&mut rng, 1e-3, 1e3);
        let p = rng::uniform(&mut rng, 0.01, 1.0);
        let u = rng::uniform(&mut rng, 0.0, 1.0);
        let got = f(value, p, u);
        if u < p {
            let want = value / p;
            survivors.measure((got / want - 1.0).abs() / eps, 4.0, || {
                format!("f = {value}, p = {p}, u = {u}: got {got}, want f / p = {want}")
            });
        } else {
            killed.record(got == 0.0, || {
                format!("f = {value}, p = {p}, u = {u}: got {got}, want 0")
            });
        }
    }
    let mut never = Finding::new("never", "p = 0 never survives, even at u = 0");
    let mut always = Finding::new("always", "p = 1 always survives and returns f");
    for u in [0.0, 1e-300, 0.5, 1.0 - eps / 2.0] {
        for value in VALUES {
            let got = f(value, 0.0, u);
            never.record(got == 0.0, || {
                format!("f = {value}, p = 0, u = {u:e}: got {got}, want 0")
            });
            let got = f(value, 1.0, u);
            always.record(got == value, || {
                format!("f = {value}, p = 1, u = {u:e}: got {got}, want {value}")
            });
        }
    }
    let mut verdict = Verdict::new("Russian roulette");
    verdict
        .findings
        .extend([unbiased, survivors, killed, never, always]);
    verdict
}

/// The sum of `xs` with Neumaier's compensation: exact to a few rounding errors whatever
/// the number of terms.
fn compensated_sum(xs: impl Iterator<Item = f64>) -> f64 {
    let (mut sum, mut compensation) = (0.0_f64, 0.0_f64);
    for x in xs {
        let t = sum + x;
        compensation += if sum.abs() >= x.abs() {
            (sum - t) + x
        } else {
            (x - t) + sum
        };
        sum = t;
    }
    sum + compensation
}
