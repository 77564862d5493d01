//! Monochromatic light and the gamut.

use super::*;

/// Is `p` inside the triangle of sRGB primaries (closed)?
fn in_srgb_triangle(p: DVec2) -> bool {
    let [a, b, c] = SRGB_PRIMARIES;
    let side = |u: DVec2, v: DVec2| (v - u).perp_dot(p - u);
    let s = [side(a, b), side(b, c), side(c, a)];
    s.iter().all(|&x| x >= 0.0) || s.iter().all(|&x| x <= 0.0)
}

#[test]
fn monochromatic_lines_land_on_the_spectral_locus_outside_the_gamut() {
    for k in 0..31 {
        let l0 = 400.0 + 10.0 * f64::from(k);
        let locus = chromaticity(cmf(l0)).unwrap();
        // A table spike: 1 at l0, 0 one nanometre either side.
        let spike = Table::new(vec![l0 - 1.0, l0, l0 + 1.0], vec![0.0, 1.0, 0.0]).unwrap();
        // A narrow Gaussian, σ = 0.5 nm.
        let gauss = |nm: f64| (-0.5 * ((nm - l0) / 0.5).powi(2)).exp();
        for (what, c) in [
            ("spike", xyz(|nm| spike.eval(nm))),
            ("gaussian", xyz(gauss)),
        ] {
            let p = chromaticity(c).unwrap();
            // Within 2 nm of l0 the locus moves by at most 0.025 per nm (near 500 nm); the
            // lines' widths average it over ±1 nm: 2e-3 bounds the curvature effect.
            let d = (p - locus).length();
            assert!(
                d <= 2e-3,
                "{what} at {l0} nm: {p} is {d:.1e} from the locus {locus}"
            );
            let rgb = xyz_to_linear_srgb(c);
            // Every spectral colour lies outside the sRGB triangle, so some component is
            // negative, and stays negative: no clamp before display.
            assert!(!in_srgb_triangle(p), "{what} at {l0} nm inside sRGB: {p}");
            assert!(rgb.min_element() < 0.0, "{what} at {l0} nm: {rgb}");
            let back = linear_srgb_to_xyz(rgb);
            let err = ((back - c) / c.max_element()).max_abs();
            assert!(
                err <= 1e-13,
                "{what} at {l0} nm: round trip error {err:.1e}"
            );
        }
    }
    // And the white points are inside.
    assert!(in_srgb_triangle(SRGB_WHITE));
    let a = builtin("cie_illuminant_A.csv");
    let rgb_a = xyz_to_linear_srgb(xyz(|nm| a.eval(nm)));
    assert!(rgb_a.min_element() > 0.0, "A is inside sRGB: {rgb_a}");
}

/// Planted bug: clamping negative components at conversion time. The colour then does not
/// survive the round trip (the 520 nm green becomes a different, duller colour).
#[test]
fn out_of_gamut_rejects_clamping() {
    let c = cmf(520.0);
    let clamped = xyz_to_linear_srgb(c).max(DVec3::ZERO);
    let back = linear_srgb_to_xyz(clamped);
    let err = ((back - c) / c.max_element()).max_abs();
    assert!(err > 0.01, "clamping went unnoticed: {err:.1e}");
    let p = chromaticity(back).unwrap();
    assert!(in_srgb_triangle(p), "the clamped colour is in gamut: {p}");
}

/// The source notes convert to colour at every surface (in the BSDF) and multiply colours
/// along the path. Colour matching is a linear functional of the *final* spectrum: the
/// colour of a product of spectra is not the product of their colours. Two green filters
/// with disjoint pass bands (500-520 nm and 540-560 nm) in series pass nothing; the product
/// of their linear sRGB colours is a bright green.
#[test]
fn colour_of_a_product_is_not_the_product_of_colours() {
    let band = |lo: f64, hi: f64| move |nm: f64| if (lo..=hi).contains(&nm) { 1.0 } else { 0.0 };
    let (f1, f2) = (band(500.0, 520.0), band(540.0, 560.0));
    let through_both = xyz(|nm| f1(nm) * f2(nm));
    assert!(through_both == DVec3::ZERO, "{through_both}");
    let seed = xyz_to_linear_srgb(xyz(f1)) * xyz_to_linear_srgb(xyz(f2));
    assert!(seed.y > 0.01, "per-bounce colours multiplied: {seed}");
}
