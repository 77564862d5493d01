//! Figures and tables of the chapter *From RGB to spectrum*.

use std::fmt::Write as _;

use anyhow::Context;
use glam::DVec3;

use super::{Output, Record, Settings, timing};
use crate::plot::Legend;
use crate::plot::{self, Panel, Series};
use raylemma::rng;
use raylemma::spectral::display::delta_e;
use raylemma::spectral::upsample::*;
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN, cie};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "upsample_spectra.svg",
            what: "upsampled reflectances of primaries, everyday colours and greys",
            make: spectra_svg,
        },
        Output {
            file: "upsample_roundtrip.md",
            what: "round-trip errors sRGB -> spectrum -> sRGB under D65, and planted bugs",
            make: roundtrip_md,
        },
        Output {
            file: "upsample_speed.md",
            what: "solve time per colour",
            make: speed_md,
        },
    ]
}

fn curve(label: &str, rgb: DVec3) -> anyhow::Result<Series> {
    let fit = upsample(rgb)?;
    Ok(Series::line(
        format!("{label} ({}, {}, {})", rgb.x, rgb.y, rgb.z),
        (0..=94)
            .map(|i| {
                let nm = LAMBDA_MIN + 5.0 * f64::from(i);
                (nm, fit.reflectance.eval(nm))
            })
            .collect(),
    ))
}

fn spectra_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let corners = Panel::new(
        "gamut corners (linear sRGB)",
        "wavelength, nm",
        "reflectance",
        vec![
            curve("red", DVec3::new(1.0, 0.0, 0.0))?,
            curve("green", DVec3::new(0.0, 1.0, 0.0))?,
            curve("blue", DVec3::new(0.0, 0.0, 1.0))?,
            curve("yellow", DVec3::new(1.0, 1.0, 0.0))?,
            curve("cyan", DVec3::new(0.0, 1.0, 1.0))?,
            curve("magenta", DVec3::new(1.0, 0.0, 1.0))?,
        ],
    );
    let everyday = Panel::new(
        "everyday colours and greys (linear sRGB)",
        "wavelength, nm",
        "reflectance",
        vec![
            curve("brick", DVec3::new(0.4, 0.08, 0.05))?,
            curve("leaf", DVec3::new(0.1, 0.3, 0.05))?,
            curve("sky", DVec3::new(0.2, 0.3, 0.6))?,
            curve("skin", DVec3::new(0.6, 0.35, 0.25))?,
            curve("grey", DVec3::splat(0.18))?,
            curve("grey", DVec3::splat(0.5))?,
        ],
    );
    let range = (LAMBDA_MIN, LAMBDA_MAX);
    plot::ranged_chart(&[
        (corners, range, (-0.02, 1.02), Legend::Below),
        (everyday, range, (-0.02, 1.02), Legend::Below),
    ])
}

fn grid() -> Vec<DVec3> {
    let mut v = Vec::new();
    for r in 0..=10 {
        for g in 0..=10 {
            for b in 0..=10 {
                v.push(DVec3::new(f64::from(r), f64::from(g), f64::from(b)) / 10.0);
            }
        }
    }
    v
}

fn random(n: usize) -> Vec<DVec3> {
    let mut r = rng::seeded(0x5EC7);
    (0..n)
        .map(|_| {
            DVec3::new(
                rng::uniform(&mut r, 0.0, 1.0),
                rng::uniform(&mut r, 0.0, 1.0),
                rng::uniform(&mut r, 0.0, 1.0),
            )
        })
        .collect()
}

fn logistic(r: &Reflectance, nm: f64) -> f64 {
    match *r {
        Reflectance::Constant(v) => v,
        Reflectance::Sigmoid(c) => {
            let t = unit_wavelength(nm);
            1.0 / (1.0 + (-((c[0] * t + c[1]) * t + c[2])).exp())
        }
    }
}

/// The worst errors of one row of the round-trip table.
struct Worst {
    /// The largest linear sRGB error, and the colour it is at.
    linear: (f64, DVec3),
    /// The largest ΔE, and the colour it is at.
    delta_e: (f64, DVec3),
}

fn row(
    md: &mut String,
    name: &str,
    colours: &[DVec3],
    fitter: &Fitter,
    eval: fn(&Reflectance, f64) -> f64,
) -> anyhow::Result<Worst> {
    let (mut lin, mut de_max, mut de_sum, mut at, mut its, mut lo, mut hi) =
        (0.0f64, 0.0f64, 0.0, DVec3::ZERO, 0u32, 1.0f64, 0.0f64);
    let mut lin_at = DVec3::ZERO;
    for &c in colours {
        let fit = fitter.fit(c)?;
        its = its.max(fit.iterations);
        let back = srgb_under_d65(|nm| eval(&fit.reflectance, nm));
        let e = (back - c).abs().max_element();
        if e > lin {
            (lin, lin_at) = (e, c);
        }
        let de = delta_e(back, c);
        de_sum += de;
        if de > de_max {
            (de_max, at) = (de, c);
        }
        for nm in (3600..=8300).map(|i| f64::from(i) / 10.0) {
            let v = eval(&fit.reflectance, nm);
            (lo, hi) = (lo.min(v), hi.max(v));
        }
    }
    writeln!(
        md,
        "| {name} | {} | {lin:.2e} | {de_max:.2e} | ({:.2}, {:.2}, {:.2}) | {:.2e} | {its} | [{lo:.3}, {hi:.3}] |",
        colours.len(),
        at.x,
        at.y,
        at.z,
        de_sum / colours.len() as f64,
    )?;
    Ok(Worst {
        linear: (lin, lin_at),
        delta_e: (de_max, at),
    })
}

fn roundtrip_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::new();
    writeln!(
        md,
        "| fit, seen under D65 | colours | max error, linear sRGB | max ΔE | at | mean ΔE | max iterations | reflectance range |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---|---:|---:|---|")?;
    let d65 = Fitter::d65();
    let n_random = if settings.quick { 200 } else { 2000 };
    let on_grid = row(
        &mut md,
        "D65, grid 0, 0.1, ..., 1",
        &grid(),
        d65,
        Reflectance::eval,
    )?;
    let at = on_grid.delta_e.1;
    r.text(
        "grid.worst_delta_e_at",
        format!("({:.2}, {:.2}, {:.2})", at.x, at.y, at.z),
    );
    // The largest error on the grid, ΔE and linear, is at white.
    r.claim(
        "grid_worst_error_at_white",
        on_grid.delta_e.1 == DVec3::ONE && on_grid.linear.1 == DVec3::ONE,
        format!(
            "largest ΔE {:.2e} at {:?}, largest linear error {:.2e} at {:?}; white is (1, 1, 1)",
            on_grid.delta_e.0, on_grid.delta_e.1, on_grid.linear.0, on_grid.linear.1
        ),
    );
    let at_random = row(
        &mut md,
        "D65, random (seeded)",
        &random(n_random),
        d65,
        Reflectance::eval,
    )?;
    // The tests' bounds hold on the table's D65 rows: linear error below 1e-3, ΔE below
    // 0.02.
    r.claim(
        "d65_rows_within_test_bounds",
        [&on_grid, &at_random]
            .iter()
            .all(|w| w.linear.0 < 1e-3 && w.delta_e.0 < 0.02),
        format!(
            "D65 rows, largest linear error < 1e-3 and largest ΔE < 0.02: grid {:.2e}, {:.2e}; random {:.2e}, {:.2e}",
            on_grid.linear.0, on_grid.delta_e.0, at_random.linear.0, at_random.delta_e.0
        ),
    );
    let under_e = row(
        &mut md,
        "planted: fitted under illuminant E",
        &grid(),
        &Fitter::new(|_| 1.0),
        Reflectance::eval,
    )?;
    let logistic = row(&mut md, "planted: logistic sigmoid", &grid(), d65, logistic)?;
    // Both planted bugs miss by tens of ΔE: at least 10, below 100.
    r.number("planted_under_e.max_delta_e", under_e.delta_e.0, ".0");
    r.number("planted_logistic.max_delta_e", logistic.delta_e.0, ".0");
    r.claim(
        "planted_tens_of_de",
        [&under_e, &logistic]
            .iter()
            .all(|w| (10.0..100.0).contains(&w.delta_e.0)),
        format!(
            "largest ΔE, each in [10, 100): fitted under E {:.2}, logistic sigmoid {:.2}",
            under_e.delta_e.0, logistic.delta_e.0
        ),
    );
    writeln!(
        md,
        "\n*Round trip: linear sRGB → reflectance (fit on a 1 nm trapezoid grid) → XYZ under \
         D65 by 4-point Gauss-Legendre per nm (`cie::xyz`) → linear sRGB. ΔE is CIE 1976 \
         (CIELAB, white = sRGB (1, 1, 1)). Reflectance range over 360-830 nm in 0.1 nm steps.*"
    )?;
    let white = srgb_under_d65(|_| 1.0);
    let xy = cie::chromaticity(cie::linear_srgb_to_xyz(white)).context("white is black")?;
    r.text(
        "white.d65_chromaticity",
        format!("({:.5}, {:.5})", xy.x, xy.y),
    );
    writeln!(
        md,
        "\n*White, the constant reflectance 1, comes back as ({:.5}, {:.5}, {:.5}): the CIE D65 \
         table's chromaticity is ({:.5}, {:.5}), sRGB's white is ({}, {}).*",
        white.x,
        white.y,
        white.z,
        xy.x,
        xy.y,
        cie::SRGB_WHITE.x,
        cie::SRGB_WHITE.y
    )?;
    Ok(md.into_bytes())
}

fn speed_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let colours = if settings.quick { random(100) } else { grid() };
    let reps = if settings.quick { 3 } else { 11 };
    let d65 = Fitter::d65();
    let ns_fit = timing::median_ns_per_item(colours.len(), reps, || {
        colours
            .iter()
            .map(|&c| d65.fit(c).map_or(0, |f| u64::from(f.iterations)))
            .sum()
    });
    let iterations: u64 = colours
        .iter()
        .map(|&c| d65.fit(c).map_or(0, |f| u64::from(f.iterations)))
        .sum();
    let fit = upsample(DVec3::new(0.7, 0.2, 0.1))?.reflectance;
    let n = 100_000;
    let ns_eval = timing::median_ns_per_item(n, reps, || {
        (0..n)
            .map(|i| fit.eval(LAMBDA_MIN + (LAMBDA_MAX - LAMBDA_MIN) * i as f64 / n as f64))
            .sum::<f64>()
            .to_bits()
    });
    let mut md = String::new();
    writeln!(md, "| operation | time |")?;
    writeln!(md, "|---|---:|")?;
    let us = r.number("fit_one_colour.us", ns_fit / 1000.0, ".1");
    writeln!(
        md,
        "| fit one colour (average over {} colours) | {} |",
        colours.len(),
        r.text("fit_one_colour.time", format!("{us} µs")),
    )?;
    r.number("thousand_colours_s", ns_fit * 1000.0 / 1e9, "s2");
    writeln!(
        md,
        "| mean Levenberg-Marquardt iterations per colour | {:.1} |",
        iterations as f64 / colours.len() as f64
    )?;
    writeln!(md, "| evaluate r(λ) once | {ns_eval:.1} ns |")?;
    writeln!(md, "\n*{}.*", timing::machine())?;
    Ok(md.into_bytes())
}
