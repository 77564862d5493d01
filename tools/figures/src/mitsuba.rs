//! The renderer chapter's account of Mitsuba 3's own colour conversion: what its `hdrfilm`
//! would make of the light of every canonical scene, against raylemma's convention, from
//! Mitsuba's published constants (no Mitsuba is run here). `raylemma export` writes a
//! `specfilm` with raylemma's own colour-matching functions instead, so none of this
//! difference reaches the comparison of `tools/mitsuba/compare_all.sh`; the table says how
//! large it would be, and why.
//!
//! Mitsuba 3.9.1's `hdrfilm`, in a spectral variant (`src/render/integrator.cpp`,
//! `include/mitsuba/core/spectrum.h`; `tools/mitsuba/NOTES.md`, section 6), integrates each
//! sample against the CIE 1931 table at 5 nm (95 entries, 360-830 nm, linear in between:
//! the 1 nm table's rows at every fifth nanometre, checked), multiplies by
//! `MI_CIE_Y_NORMALIZATION = 1 / 106.7502594`, and converts with a matrix rounded to six
//! decimals. raylemma integrates against the 1 nm table, divides by its integral of `ȳ`
//! (106.857) and converts with the exact inverse of the sRGB primaries' matrix.

use std::fmt::Write as _;

use glam::{DMat3, DVec3};

use super::{Output, Record, Settings};
use raylemma::render;
use raylemma::render::scene::Environment;
use raylemma::spectral::cie;
use raylemma::spectral::spectrum::Spectrum;

/// The outputs of this module.
pub fn outputs() -> Vec<Output> {
    vec![Output {
        file: "mitsuba_colour.md",
        what: "Mitsuba's hdrfilm colour conversion against raylemma's, per canonical light",
        make: colour_md,
    }]
}

/// `MI_CIE_Y_NORMALIZATION` of Mitsuba 3.9.1 (`include/mitsuba/core/spectrum.h`).
const MITSUBA_Y_NORMALIZATION: f64 = 1.0 / 106.750_259_4;

/// Mitsuba's `xyz_to_srgb` (`include/mitsuba/core/spectrum.h`), rows.
const MITSUBA_XYZ_TO_SRGB: [[f64; 3]; 3] = [
    [3.240_479, -1.537_150, -0.498_535],
    [-0.969_256, 1.875_991, 0.041_556],
    [0.055_648, -0.204_043, 1.057_311],
];

/// Three-point Gauss-Legendre on [0, 1]: exact for the product of two functions linear on
/// each whole nanometre (a table with whole-nanometre knots times the 5 nm table).
const GAUSS3: [(f64, f64); 3] = [
    (0.112_701_665_379_258_3, 5.0 / 18.0),
    (0.5, 8.0 / 18.0),
    (0.887_298_334_620_741_7, 5.0 / 18.0),
];

/// The CIE 1931 functions as Mitsuba holds them: the 1 nm table's rows at 360, 365, ...,
/// 830 nm, linear in between.
fn cmf_5nm(nm: f64) -> DVec3 {
    let s = (nm - 360.0) / 5.0;
    if !(0.0..=94.0).contains(&s) {
        return DVec3::ZERO;
    }
    let i = (s as usize).min(93);
    let t = s - i as f64;
    cie::cmf_row(5 * i).lerp(cie::cmf_row(5 * (i + 1)), t)
}

/// Mitsuba's `hdrfilm` linear sRGB of the spectrum `s` (its expectation: the exact
/// integral of its estimator).
fn mitsuba_rgb(s: &Spectrum) -> DVec3 {
    let mut sum = DVec3::ZERO;
    for l in 360..830 {
        for (t, w) in GAUSS3 {
            let nm = f64::from(l) + t;
            sum += w * s.eval(nm) * cmf_5nm(nm);
        }
    }
    let m = DMat3::from_cols_array_2d(&MITSUBA_XYZ_TO_SRGB).transpose();
    m * (sum * MITSUBA_Y_NORMALIZATION)
}

fn colour_md(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let scenes = [
        "cornell",
        "lamps/amber-led",
        "lamps/incandescent",
        "lamps/cool-white-fluorescent",
        "lamps/low-pressure-sodium",
        "lamps/high-pressure-sodium",
        "furnace-grey",
    ];
    let mut rows: Vec<(String, Spectrum)> = vec![("a constant 1".into(), Spectrum::Constant(1.0))];
    for name in scenes {
        let s = render::load(&settings.root.join("scenes").join(format!("{name}.toml")))?;
        let (what, spectrum) = match (&s.lights[..], &s.environment) {
            ([light, ..], _) => ("light", light.emission.clone()),
            ([], Some(Environment::Constant(e))) => ("environment", e.clone()),
            _ => continue,
        };
        rows.push((format!("`{name}`, its {what}"), spectrum));
    }
    // Mitsuba's own ∫ȳ, of its 5 nm table (trapezoids: exact for the linear interpolant).
    let y5: f64 = (0..94)
        .map(|i| 2.5 * (cie::cmf_row(5 * i).y + cie::cmf_row(5 * i + 5).y))
        .sum();
    let y_fix = y5 * MITSUBA_Y_NORMALIZATION;
    let mut md = String::from(
        "| spectrum | Mitsuba's hdrfilm / raylemma − 1: R, G, B | with Mitsuba's Y normalisation corrected |\n|---|---:|---:|\n",
    );
    for (name, s) in &rows {
        let ours = cie::xyz_to_linear_srgb(cie::xyz(|nm| s.eval(nm)));
        let theirs = mitsuba_rgb(s);
        let pct = |v: DVec3| {
            format!(
                "{:+.3} %, {:+.3} %, {:+.3} %",
                100.0 * v.x,
                100.0 * v.y,
                100.0 * v.z
            )
        };
        writeln!(
            md,
            "| {name} | {} | {} |",
            pct(theirs / ours - DVec3::ONE),
            pct(theirs / (ours * y_fix) - DVec3::ONE)
        )?;
    }
    writeln!(
        md,
        "\n*The exact expectation of each film's estimator for the spectrum seen directly: raylemma's (the 1 nm CIE 1931 table, ÷ its ∫ȳ = {:.6}, the exact sRGB matrix) and Mitsuba 3.9.1's `hdrfilm` (the same table at 5 nm, × `MI_CIE_Y_NORMALIZATION` = 1/106.7502594, its six-decimal matrix), from their published constants. The last column divides Mitsuba's by {:.8}, its table's ∫ȳ = {:.6} times its constant, so that a constant 1 has Y = 1 in its own table too; what is left is the 5 nm table and the rounded matrix. `raylemma export` writes a `specfilm` with raylemma's own functions instead, which makes this difference zero.*",
        cie::y_integral(),
        y_fix,
        y5
    )?;
    Ok(md.into_bytes())
}
