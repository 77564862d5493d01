//! Illuminants.

use super::*;

/// The CIE's own rule (CIE 015:2018 §7.1): sum the 5 nm samples of the spectrum times the
/// colour-matching functions at the same wavelengths, 380-780 nm (the range of the published
/// illuminant chromaticities; A's and D65's tables start lower, and summing from 360 nm misses
/// their published values by one and two units of the fifth decimal). Only the ratio matters
/// for chromaticity, so the normaliser is left out.
fn cie_summation(t: &Table) -> DVec3 {
    t.wavelengths()
        .iter()
        .zip(t.values())
        .filter(|(nm, _)| (380.0..=780.0).contains(*nm))
        .map(|(&nm, &v)| v * cmf(nm))
        .sum()
}

#[test]
fn illuminant_chromaticities_by_the_cie_rule_match_published_values() {
    for (file, name, x, y, decimals) in PUBLISHED {
        let c = chromaticity(cie_summation(&builtin(file))).unwrap();
        // Half a unit of the last printed decimal (and 1e-7 for A, whose sum lies 4.98e-6
        // from its published value).
        let tol = 0.5 * 10f64.powi(-decimals) + 1e-7;
        let err = (c - DVec2::new(x, y)).max_abs();
        assert!(
            err <= tol,
            "{name}: ({:.6}, {:.6}) vs published ({x}, {y}), error {err:.2e} > {tol:.1e}",
            c.x,
            c.y
        );
    }
}

/// The renderer's rule: the spectrum is piecewise linear between its 5 nm samples and the
/// integral is exact. For smooth spectra it agrees with the published values to 3e-5; for
/// lamps with features only a few samples wide (the mercury lines of FL2 and FL11, HP1's
/// sodium lines, the 20 nm blue peak of LED-B3) the two readings of the same samples differ
/// in the fourth decimal, and 3e-4 is the tolerance there (the chapter shows the numbers,
/// `figures/colour_illuminants.md`).
#[test]
fn illuminant_chromaticities_by_quadrature_match_published_values() {
    for (file, name, x, y, decimals) in PUBLISHED {
        let t = builtin(file);
        let c = xy(|nm| t.eval(nm));
        let tol = if decimals == 5 { 3e-5 } else { 3e-4 };
        let err = (c - DVec2::new(x, y)).max_abs();
        assert!(
            err <= tol,
            "{name}: ({:.6}, {:.6}) vs published ({x}, {y}), error {err:.2e} > {tol:.0e}",
            c.x,
            c.y
        );
    }
}

#[test]
fn d65_maps_to_equal_linear_srgb() {
    let t = builtin("cie_illuminant_D65.csv");
    let w = xyz(|nm| t.eval(nm));
    let rgb = xyz_to_linear_srgb(w / w.y);
    // sRGB's white is D65 rounded to four decimals, (0.3127, 0.3290); the true D65 is
    // (0.31272, 0.32903). The tolerance is the largest RGB deviation that a white point
    // moved by up to 5e-5 in x and y produces: the rounding of the standard itself.
    let mut tol: f64 = 0.0;
    for dx in [-5e-5, 5e-5] {
        for dy in [-5e-5, 5e-5] {
            let p = SRGB_WHITE + DVec2::new(dx, dy);
            let moved = xyz_to_linear_srgb(DVec3::new(p.x / p.y, 1.0, (1.0 - p.x - p.y) / p.y));
            tol = nan_max_abs([tol, (moved - DVec3::ONE).max_abs()]);
        }
    }
    let err = (rgb - DVec3::ONE).max_abs();
    assert!(err <= tol, "D65 -> {rgb}, error {err:.2e} > {tol:.2e}");
    assert!(tol < 1e-3, "the tolerance itself is small: {tol}");
}

/// Planted bug: the transposed matrix. D65 is no longer white, and the matrix no longer
/// matches the standard.
#[test]
fn srgb_rejects_the_transposed_matrix() {
    let t = builtin("cie_illuminant_D65.csv");
    let w = xyz(|nm| t.eval(nm));
    let rgb = xyz_to_linear_srgb_matrix().transpose() * (w / w.y);
    assert!(
        (rgb - DVec3::ONE).max_abs() > 0.01,
        "transposed matrix still maps D65 to white: {rgb}"
    );
    let err = max_abs_diff(xyz_to_linear_srgb_matrix().transpose(), mat(IEC_XYZ_TO_RGB));
    assert!(err > 0.1, "transposed matrix matches IEC: {err}");
}

#[test]
fn srgb_matrix_derived_from_primaries_matches_iec_61966_2_1() {
    let forward = rgb_to_xyz_matrix(SRGB_PRIMARIES, SRGB_WHITE);
    let err = max_abs_diff(forward, mat(IEC_RGB_TO_XYZ));
    assert!(err <= 5e-5, "RGB->XYZ differs from IEC by {err:.2e}");
    // The standard's inverse is the inverse of its *rounded* forward matrix, rounded again
    // (3.2406 where the exact derivation gives 3.24097). The tolerance propagates the
    // forward rounding, |M⁻¹| |ΔM| |M⁻¹| with |ΔM| ≤ 5e-5 entrywise, plus the final half unit.
    let inv = xyz_to_linear_srgb_matrix();
    let abs = DMat3::from_cols(inv.x_axis.abs(), inv.y_axis.abs(), inv.z_axis.abs());
    let bound = abs * DMat3::from_cols_array(&[5e-5; 9]) * abs;
    for (r, row) in IEC_XYZ_TO_RGB.iter().enumerate() {
        for (c, published) in row.iter().enumerate() {
            let d = (inv.col(c)[r] - published).abs();
            let tol = bound.col(c)[r] + 5e-5;
            assert!(d <= tol, "XYZ->RGB [{r}][{c}]: {d:.2e} > {tol:.2e}");
        }
    }
    // The exact derivation's corner is 3.24097, not the printed 3.2406: computed independently
    // of the crate (Cramer's rule on the primaries and the white, in double precision, outside
    // the crate): 3.2409699419045226.
    let corner = inv.col(0)[0];
    assert!(
        (corner - 3.240_969_941_904_522_6).abs() <= 1e-12,
        "XYZ->RGB [0][0] = {corner}"
    );
    assert!(
        (corner - 3.2406).abs() > 3e-4,
        "the corner is the printed one"
    );
    // And the inverse really inverts.
    let id = max_abs_diff(inv * forward, DMat3::IDENTITY);
    assert!(id <= 1e-14, "M⁻¹ M differs from I by {id:.1e}");
}
