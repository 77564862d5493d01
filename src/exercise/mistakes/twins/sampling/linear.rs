//! Twins and alternatives of `PiecewiseLinear1D::sample`.

use crate::sampling::tabulated::{PiecewiseLinear1D, Sample, segment_inverse};

/// A piecewise-linear sampler with the position within the segment from `inverse(a, b,
/// s)` (`a`, `b` the end densities, `s` the fraction of the segment's mass), stepping
/// off a zero-valued end when `step`.
fn sample_with(
    t: &PiecewiseLinear1D,
    u: f64,
    inverse: impl Fn(f64, f64, f64) -> f64,
    step: bool,
) -> Sample {
    let (c, k) = (t.cdf_table(), t.knots());
    let i = c[1..].partition_point(|&c| c <= u).min(t.segments() - 1);
    // The density at the left knot is the table's; at the right one, from the mass.
    let a = t.pdf(k[i]);
    let b = (2.0 * (c[i + 1] - c[i]) / (k[i + 1] - k[i]) - a).max(0.0);
    let s = (u - c[i]) / (c[i + 1] - c[i]);
    let mut x = (k[i] + inverse(a, b, s) * (k[i + 1] - k[i])).min(k[i + 1].next_down());
    let mut pdf = t.pdf(x);
    let mut steps = 0;
    while step && pdf == 0.0 && steps < 64 {
        x = if a == 0.0 {
            x.next_up().min(k[i + 1].next_down())
        } else {
            x.next_down().max(k[i])
        };
        pdf = t.pdf(x);
        steps += 1;
    }
    Sample { bin: i, x, pdf }
}

pub fn uniform_within(t: &PiecewiseLinear1D, u: f64) -> Sample {
    sample_with(t, u, |_, _, s| s, true)
}

pub fn ramp_root(t: &PiecewiseLinear1D, u: f64) -> Sample {
    sample_with(t, u, |_, _, s| s.sqrt(), true)
}

pub fn ends_swapped(t: &PiecewiseLinear1D, u: f64) -> Sample {
    sample_with(t, u, |a, b, s| segment_inverse(b, a, s), true)
}

pub fn no_step(t: &PiecewiseLinear1D, u: f64) -> Sample {
    sample_with(t, u, segment_inverse, false)
}

pub fn mean_density(t: &PiecewiseLinear1D, u: f64) -> Sample {
    let sample = sample_with(t, u, segment_inverse, true);
    let (c, k, i) = (t.cdf_table(), t.knots(), sample.bin);
    Sample {
        pdf: (c[i + 1] - c[i]) / (k[i + 1] - k[i]),
        ..sample
    }
}

pub fn by_partition_point(t: &PiecewiseLinear1D, u: f64) -> Sample {
    let solve = |a: f64, b: f64, s: f64| {
        let m = a.max(b);
        let (a, b) = (a / m, b / m);
        let denominator = a + (a * a + s * (b * b - a * a)).max(0.0).sqrt();
        if denominator == 0.0 {
            0.0
        } else {
            (s * (a + b) / denominator).min(1.0)
        }
    };
    sample_with(t, u, solve, true)
}
