//! The forms answering `data/corpus/tabulated.txt`: [`crate::sampling::tabulated`]. A
//! case's table is its trailing arguments: the `n + 1` edges, then the `n` values.

use crate::check::accuracy::{Answer, Form};
use crate::sampling::tabulated::{Piecewise1D, PiecewiseLinear1D, segment_cdf, segment_inverse};

/// The table of a case's trailing arguments (`None` if the crate refuses it).
fn table(t: &[f64]) -> Option<Piecewise1D> {
    let n = (t.len() - 1) / 2;
    Piecewise1D::new(&t[..=n], &t[n + 1..]).ok()
}

fn sample(a: &[f64]) -> Answer {
    table(&a[1..]).map(|t| vec![t.sample(a[0]).x])
}

/// The textbook generalised inverse `inf {x : F(x) >= u}`: the first bin whose upper CDF
/// level reaches `u`, then the linear inverse within it (the left end of a plateau, and
/// `0 / 0` at `u = 0` with a leading zero bin).
fn sample_generalised(a: &[f64]) -> Answer {
    let t = table(&a[1..])?;
    let (levels, edges) = (t.cdf_table(), t.edges());
    let u = a[0];
    let k = levels[1..].partition_point(|&c| c < u).min(t.bins() - 1);
    let (lo_level, hi_level) = (levels[k], levels[k + 1]);
    let frac = (u - lo_level) / (hi_level - lo_level);
    Some(vec![edges[k] + frac * (edges[k + 1] - edges[k])])
}

fn linear_sample(a: &[f64]) -> Answer {
    let t = &a[1..];
    let n = t.len() / 2;
    PiecewiseLinear1D::new(&t[..n], &t[n..])
        .ok()
        .map(|table| vec![table.sample(a[0]).x])
}

fn pdf(a: &[f64]) -> Answer {
    table(&a[1..]).map(|t| vec![t.pdf(a[0])])
}

fn cdf(a: &[f64]) -> Answer {
    table(&a[1..]).map(|t| vec![t.invert(a[0])])
}

/// The quadratic formula for the segment's root,
/// `t = (sqrt(a^2 + (b - a) xi (a + b)) - a) / (b - a)`, `t = xi` for `a = b` (with `a`,
/// `b` scaled by their maximum as the crate's form is).
fn segment_inverse_quadratic(v: &[f64]) -> Answer {
    let top = v[0].max(v[1]);
    let (lo, hi, xi) = (v[0] / top, v[1] / top, v[2]);
    if lo == hi {
        return Some(vec![xi]);
    }
    let root = (lo * lo + (hi - lo) * xi * (lo + hi)).sqrt();
    Some(vec![((root - lo) / (hi - lo)).clamp(0.0, 1.0)])
}

/// Every form of every verb of the corpus.
pub fn forms() -> Vec<Form> {
    let f = Form::stable;
    let textbook = Form::textbook;
    vec![
        f("tabulated_sample", sample),
        textbook(f("tabulated_sample", sample_generalised)),
        f("tabulated_pdf", pdf),
        f("tabulated_cdf", cdf),
        f("linear_sample", linear_sample),
        f("segment_inverse", |a| {
            Some(vec![segment_inverse(a[0], a[1], a[2])])
        }),
        textbook(f("segment_inverse", segment_inverse_quadratic)),
        f("segment_cdf", |a| Some(vec![segment_cdf(a[0], a[1], a[2])])),
    ]
}
