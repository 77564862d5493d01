//! Planted bugs of the tabulated sampler's checker. Chapter: *Tabulated distributions*.

use crate::sampling::tabulated::{Piecewise1D, Sample};

/// Picks the bin `floor(u n)` as if every bin had the same mass.
pub fn equal_bins(t: &Piecewise1D, u: f64) -> Sample {
    let e = t.edges();
    let n = t.bins();
    let scaled = u * n as f64;
    let bin = (scaled as usize).min(n - 1);
    let x = e[bin] + (scaled - bin as f64) * (e[bin + 1] - e[bin]);
    Sample {
        x,
        pdf: t.pdf(x),
        bin,
    }
}

/// The textbook search, the first bin with `cdf[i + 1] >= u`: at a plateau's level it
/// lands on the bin of zero mass before it.
pub fn first_bin_reaching_u(t: &Piecewise1D, u: f64) -> Sample {
    let (c, e) = (t.cdf_table(), t.edges());
    let bin = (0..t.bins())
        .find(|&i| c[i + 1] >= u)
        .unwrap_or(t.bins() - 1);
    let width = c[bin + 1] - c[bin];
    let s = if width > 0.0 {
        (u - c[bin]) / width
    } else {
        0.0
    };
    let x = (e[bin] + s * (e[bin + 1] - e[bin])).min(e[bin + 1].next_down());
    Sample {
        x,
        pdf: t.pdf(x),
        bin,
    }
}
