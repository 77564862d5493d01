//! Importance sampling. Chapter: *Importance sampling* (`chapters/sampling/importance.md`).
//!
//! To estimate `I = int f(x) dx`, draw `X_i` from a density `q` and average `f(X_i) / q(X_i)`.
//! The estimator is unbiased when `q > 0` wherever `f != 0` (and, for an `f` of one sign,
//! only then, up to a set of zero length: it misses the integral of `f` over the set where
//! `q = 0`); its variance is `int f^2 / q dx - I^2`, zero when `q` is proportional to `|f|`
//! (and `f` has one sign).

use crate::rng::{self, Rng};
use crate::stats::ttest::Summary;

/// A density on `[0, 1]` that can be sampled by inverting its CDF.
#[derive(Clone, Copy)]
pub struct Proposal {
    /// Name for tables.
    pub name: &'static str,
    /// The inverse CDF: `u` uniform in `[0, 1)` gives `x` distributed as `pdf`.
    pub sample: fn(f64) -> f64,
    /// The density.
    pub pdf: fn(f64) -> f64,
}

// ANCHOR: estimator
// EXERCISE sampling/importance estimate: the importance-sampling estimator: the terms f(X)/q(X) of n draws X ~ q, 0 where q(X) = 0
/// The importance-sampling estimator's terms `f(X) / q(X)` for `n` draws `X ~ q`,
/// summarised (mean = the estimate; its variance and standard error come with it).
/// A draw where `q(X) = 0` contributes 0 (a set of probability zero in exact arithmetic,
/// not always in floating point: `q = 3x²` draws `x = 0` when its uniform is 0).
pub fn estimate(f: impl Fn(f64) -> f64, q: &Proposal, n: usize, rng: &mut Rng) -> Summary {
    let mut terms = Summary::default();
    for _ in 0..n {
        let x = (q.sample)(rng::uniform(rng, 0.0, 1.0));
        let density = (q.pdf)(x);
        terms.push(if density > 0.0 { f(x) / density } else { 0.0 });
    }
    terms
}
// END EXERCISE
// ANCHOR_END: estimator

// ANCHOR: proposals
/// The chapter's integrand: `f(x) = x^2` on `[0, 1]`, `I = 1/3`.
pub fn square(x: f64) -> f64 {
    x * x
}

/// Uniform: `q = 1`. Variance of `f/q`: `1/5 - 1/9 = 4/45`.
pub const UNIFORM: Proposal = Proposal {
    name: "uniform, q = 1",
    sample: |u| u,
    pdf: |_| 1.0,
};

/// Linear: `q = 2x`, `x = sqrt(u)`. Variance: `int x^4 / (2x) - 1/9 = 1/8 - 1/9 = 1/72`.
pub const LINEAR: Proposal = Proposal {
    name: "linear, q = 2x",
    sample: f64::sqrt,
    pdf: |x| {
        if (0.0..=1.0).contains(&x) {
            2.0 * x
        } else {
            0.0
        }
    },
};

/// Matched: `q = 3x^2 = f / I`, `x = u^(1/3)`. Variance 0: every term equals `I`.
pub const MATCHED: Proposal = Proposal {
    name: "matched, q = 3x^2",
    sample: f64::cbrt,
    pdf: |x| {
        if (0.0..=1.0).contains(&x) {
            3.0 * x * x
        } else {
            0.0
        }
    },
};

/// Half support: `q = 2` on `[0, 1/2]`, zero on `(1/2, 1]` where `f` is not: the estimator
/// converges to `int_0^(1/2) x^2 dx = 1/24`, not `1/3`.
pub const HALF_SUPPORT: Proposal = Proposal {
    name: "half support, q = 2 on [0, 1/2]",
    sample: |u| u / 2.0,
    pdf: |x| if (0.0..=0.5).contains(&x) { 2.0 } else { 0.0 },
};
// ANCHOR_END: proposals

/// Exact variance of one term `f(X)/q(X)` for the proposals above (from the formulas in
/// their documentation); `None` for a proposal without a closed form here.
pub fn exact_variance(q: &Proposal) -> Option<f64> {
    match q.name {
        n if n == UNIFORM.name => Some(4.0 / 45.0),
        n if n == LINEAR.name => Some(1.0 / 72.0),
        n if n == MATCHED.name => Some(0.0),
        _ => None,
    }
}
