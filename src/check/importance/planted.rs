//! Planted bugs of the importance-sampling checker. Chapter: *Importance sampling*.

use crate::rng::{self, Rng};
use crate::sampling::importance::Proposal;
use crate::stats::ttest::Summary;

/// Averages `f(X)` and forgets to divide by the density: estimates `E_q[f]`, not `∫ f`.
pub fn forgets_the_density(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
    Summary::of((0..n).map(|_| f((q.sample)(rng::uniform(r, 0.0, 1.0)))))
}

/// Divides by the density of the wrong point: `f(X) / q(U)` with `U` the uniform number
/// rather than the sample.
pub fn density_of_u(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
    Summary::of((0..n).map(|_| {
        let u = rng::uniform(r, 0.0, 1.0);
        let density = (q.pdf)(u);
        if density > 0.0 {
            f((q.sample)(u)) / density
        } else {
            0.0
        }
    }))
}

/// Skips a draw where `q(X) = 0` instead of adding a term of 0: fewer than `n` terms, and
/// their mean is `int f` over the set where `q > 0` divided by the share of draws there.
pub fn skips_zero_density(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
    let mut summary = Summary::default();
    for _ in 0..n {
        let x = (q.sample)(rng::uniform(r, 0.0, 1.0));
        let q_x = (q.pdf)(x);
        if q_x > 0.0 {
            summary.push(f(x) / q_x);
        }
    }
    summary
}
