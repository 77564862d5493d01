//! Planted bugs: each must be rejected.

use super::*;

/// Samples uniformly over [x_0, x_n], ignoring the table.
#[test]
fn uniform_ignoring_the_table_is_rejected() {
    for t in [smooth(), spiky(), with_zeros()] {
        let (lo, hi) = (t.edges[0], t.edges[t.edges.len() - 1]);
        assert_rejected(&t, false, &draw(20, N, |u| lo + u * (hi - lo)), "uniform");
    }
}

/// The CDF as running sums of the masses, not divided by their total.
#[test]
fn unnormalised_cdf_is_rejected() {
    let t = smooth();
    let mut cdf = vec![0.0];
    for m in t.masses(false) {
        cdf.push(cdf.last().unwrap() + m);
    }
    assert!(
        cdf[cdf.len() - 1] > 10.0,
        "the table must not integrate to 1"
    );
    let bad = |u: f64| {
        let i = cdf[1..]
            .partition_point(|&c| c <= u)
            .min(t.values.len() - 1);
        let s = (u - cdf[i]) / (cdf[i + 1] - cdf[i]);
        t.edges[i] + s.min(1.0) * (t.edges[i + 1] - t.edges[i])
    };
    assert_rejected(&t, false, &draw(21, N, bad), "unnormalised CDF");
}

/// Off by one: the bin after the right one.
#[test]
fn off_by_one_bin_is_rejected() {
    for t in [smooth(), spiky(), with_zeros()] {
        let d = t.constant();
        let bad = |u: f64| {
            let s = d.sample(u);
            let j = (s.bin + 1).min(t.values.len() - 1);
            let f = (s.x - t.edges[s.bin]) / (t.edges[s.bin + 1] - t.edges[s.bin]);
            t.edges[j] + f * (t.edges[j + 1] - t.edges[j])
        };
        assert_rejected(&t, false, &draw(22, N, bad), "off by one");
    }
}

/// Treating a piecewise-linear table as piecewise constant within each segment.
#[test]
fn linear_table_sampled_as_constant_is_rejected() {
    let t = &linear_tables()[0];
    let d = t.linear();
    let bad = |u: f64| {
        let s = d.sample(u);
        let (x0, x1) = (t.edges[s.bin], t.edges[s.bin + 1]);
        let (c0, c1) = (d.cdf(x0), d.cdf(x1));
        x0 + (u - c0) / (c1 - c0) * (x1 - x0)
    };
    // One chi-squared cell per segment cannot see the shape within a segment (the
    // segment probabilities are right); the unbinned KS test can.
    let (ks, chi) = fit(t, true, &draw(23, N, bad));
    assert!(ks.p_value < test_alpha(), "not rejected: {ks:?}");
    // ... and chi-squared cannot: with the right segment probabilities it is a test whose
    // null hypothesis holds, so it must pass.
    assert!(
        chi.as_ref().is_ok_and(|c| c.p_value >= test_alpha()),
        "chi-squared saw the shape within a segment: {chi:?}"
    );
}
