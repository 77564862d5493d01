//! The samplers fit their tables.

use super::*;

#[test]
fn every_lamp_sampler_fits_its_table_ks() {
    for (k, l) in lamps().iter().enumerate() {
        let p = ks_p(&l.spectrum, &draw(&sampler(&l.spectrum), 100 + k as u64));
        assert!(p >= test_alpha(), "{}: KS p = {p:.3e}", l.name);
    }
}

#[test]
fn fluorescent_and_amber_fit_their_segments_chi2() {
    for (name, seed) in [("fluorescent", 110), ("amber", 111)] {
        let t = lamp(name).spectrum;
        let p = chi2_p(&t, &draw(&sampler(&t), seed));
        assert!(p >= test_alpha(), "{name}: chi-squared p = {p:.3e}");
    }
}

/// Planted bug: the table read as piecewise constant, knot `i`'s value held over
/// `[λ_i, λ_{i+1})` (a drawing's columns read as bins). Every segment gets the wrong mass
/// and shape; KS and the per-segment chi-squared both reject it on the fluorescent lamp.
#[test]
fn planted_piecewise_constant_reading_is_rejected() {
    let t = lamp("fluorescent").spectrum;
    let v = t.values();
    let wrong = Piecewise1D::new(t.wavelengths(), &v[..v.len() - 1]).unwrap();
    let xs: Vec<f64> = uniforms(120, N)
        .into_iter()
        .map(|u| wrong.sample(u).x)
        .collect();
    let p = ks_p(&t, &xs);
    assert!(p < test_alpha(), "not rejected: KS p = {p:.3e}");
    let p = chi2_p(&t, &xs);
    assert!(p < test_alpha(), "not rejected: chi-squared p = {p:.3e}");
}

/// Planted bug: the source's 450-pixel-wide drawing, its columns (380..=829 nm) spread
/// evenly over 380-830 nm. At the amber LED's peak the stretch is half a nanometre; KS
/// sees it.
#[test]
fn planted_450_columns_stretched_over_the_range_are_rejected() {
    let t = lamp("amber").spectrum;
    let knots: Vec<f64> = (0..450)
        .map(|c| 380.0 + 450.0 * f64::from(c) / 449.0)
        .collect();
    let values: Vec<f64> = (0..450).map(|c| t.eval(380.0 + f64::from(c))).collect();
    let stretched = Table::new(knots, values).unwrap();
    let p = ks_p(&t, &draw(&sampler(&stretched), 121));
    assert!(p < test_alpha(), "not rejected: KS p = {p:.3e}");
}
