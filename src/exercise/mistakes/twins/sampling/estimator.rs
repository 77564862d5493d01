//! Twins and alternatives of `estimate`.

use crate::rng::{self, Rng};
use crate::sampling::importance::Proposal;
use crate::stats::ttest::Summary;

/// `n` terms `term(f, q, X)` of draws `X ~ q`.
fn terms(
    f: &dyn Fn(f64) -> f64,
    q: &Proposal,
    n: usize,
    r: &mut Rng,
    term: fn(&dyn Fn(f64) -> f64, &Proposal, f64) -> f64,
) -> Summary {
    Summary::of((0..n).map(|_| term(f, q, (q.sample)(rng::uniform(r, 0.0, 1.0)))))
}

pub fn times_density(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
    terms(f, q, n, r, |f, q, x| f(x) * (q.pdf)(x))
}

pub fn unguarded(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
    terms(f, q, n, r, |f, q, x| f(x) / (q.pdf)(x))
}

pub fn uniform_draws(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
    Summary::of((0..n).map(|_| {
        let x = rng::uniform(r, 0.0, 1.0);
        let q_x = (q.pdf)(x);
        if q_x > 0.0 { f(x) / q_x } else { 0.0 }
    }))
}

pub fn one_more_term(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
    terms(f, q, n + 1, r, |f, q, x| {
        let q_x = (q.pdf)(x);
        if q_x > 0.0 { f(x) / q_x } else { 0.0 }
    })
}

pub fn by_iterator(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
    Summary::of((0..n).map(|_| {
        let x = (q.sample)(rng::uniform(r, 0.0, 1.0));
        let q_x = (q.pdf)(x);
        if q_x == 0.0 { 0.0 } else { f(x) / q_x }
    }))
}

pub fn by_reciprocal(f: &dyn Fn(f64) -> f64, q: &Proposal, n: usize, r: &mut Rng) -> Summary {
    let mut summary = Summary::default();
    for _ in 0..n {
        let x = (q.sample)(rng::uniform(r, 0.0, 1.0));
        summary.push(match (q.pdf)(x) {
            density if density > 0.0 => f(x) * density.recip(),
            _ => 0.0,
        });
    }
    summary
}
