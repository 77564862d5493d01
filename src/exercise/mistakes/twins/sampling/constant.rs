//! Twins and alternatives of `Piecewise1D::sample`.

use crate::sampling::tabulated::{Piecewise1D, Sample};

/// The bin of `u`: the first with `cdf[i + 1] > u`, never one of zero mass.
fn bin(t: &Piecewise1D, u: f64) -> usize {
    t.cdf_table()[1..]
        .partition_point(|&c| c <= u)
        .min(t.bins() - 1)
}

/// The point of bin `i` at the fraction `s` of its width, kept below its upper edge.
fn at(t: &Piecewise1D, i: usize, s: f64) -> f64 {
    let e = t.edges();
    (e[i] + s * (e[i + 1] - e[i])).min(e[i + 1].next_down())
}

/// The fraction of bin `i`'s share of `[0, 1)` below `u`.
fn fraction(t: &Piecewise1D, i: usize, u: f64) -> f64 {
    let c = t.cdf_table();
    (u - c[i]) / (c[i + 1] - c[i])
}

pub fn probability_as_pdf(t: &Piecewise1D, u: f64) -> Sample {
    let i = bin(t, u);
    let x = at(t, i, fraction(t, i, u));
    Sample {
        x,
        pdf: t.bin_probability(i),
        bin: i,
    }
}

pub fn position_from_u(t: &Piecewise1D, u: f64) -> Sample {
    let i = bin(t, u);
    let x = at(t, i, u);
    Sample {
        x,
        pdf: t.pdf(x),
        bin: i,
    }
}

pub fn reversed_in_bin(t: &Piecewise1D, u: f64) -> Sample {
    let i = bin(t, u);
    let x = at(t, i, 1.0 - fraction(t, i, u));
    Sample {
        x,
        pdf: t.pdf(x),
        bin: i,
    }
}

pub fn by_partition_point(t: &Piecewise1D, u: f64) -> Sample {
    let i = bin(t, u);
    let x = at(t, i, fraction(t, i, u));
    Sample {
        x,
        pdf: t.pdf(x),
        bin: i,
    }
}

pub fn by_scan(t: &Piecewise1D, u: f64) -> Sample {
    let c = t.cdf_table();
    let mut i = 0;
    while i + 1 < t.bins() && c[i + 1] <= u {
        i += 1;
    }
    let x = at(t, i, fraction(t, i, u));
    Sample {
        x,
        pdf: t.pdf(x),
        bin: i,
    }
}
