//! Figures and tables of the chapter *Importance-sampled emission spectra*.

use std::fmt::Write as _;

use glam::DVec3;
use rand::RngExt;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, BoxError, Panel, Series};
use raylemma::rng;
use raylemma::spectral::cie;
use raylemma::spectral::emission::*;
use raylemma::spectral::spectrum::Table;
use raylemma::stats::ttest::Summary;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "emission_histograms.svg",
            what: "each lamp's pdf and a histogram of its samples",
            make: histograms_svg,
        },
        Output {
            file: "emission_swatches.png",
            what: "the colour of each lamp",
            make: swatches_png,
        },
        Output {
            file: "emission_colour.md",
            what: "chromaticity, CCT, Duv and linear sRGB per lamp",
            make: colour_md,
        },
        Output {
            file: "emission_gain.md",
            what: "variance gain of importance sampling per lamp",
            make: gain_md,
        },
        Output {
            file: "emission_drawing.md",
            what: "what drawing a spectrum as an image changes",
            make: drawing_md,
        },
        Output {
            file: "emission_speed.md",
            what: "ns per wavelength sample per lamp",
            make: speed_md,
        },
    ]
}

fn sampler(t: &Table) -> Result<EmissionSampler, BoxError> {
    EmissionSampler::new(t).map_err(|e| e.to_string().into())
}

fn histograms_svg(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let n: usize = if settings.quick { 100_000 } else { 1_000_000 };
    let mut panels = Vec::new();
    for (k, lamp) in lamps().iter().enumerate() {
        let s = sampler(&lamp.spectrum)?;
        // 1 nm histogram bins over 380-830 nm: density = count / (n * 1 nm).
        let mut counts = vec![0u64; 450];
        let mut r = rng::seeded(0xE1 + k as u64);
        for _ in 0..n {
            let nm = s.sample(r.random::<f64>()).nm;
            counts[((nm - IMAGE_FIRST_NM) as usize).min(449)] += 1;
        }
        let edges: Vec<f64> = (0..=450).map(|i| 380.0 + f64::from(i)).collect();
        let heights: Vec<f64> = counts.iter().map(|&c| c as f64 / n as f64).collect();
        let pdf: Vec<(f64, f64)> = (0..=4500)
            .map(|i| {
                let nm = 380.0 + 0.1 * f64::from(i);
                (nm, s.pdf(nm))
            })
            .collect();
        let ymax = pdf.iter().map(|p| p.1).fold(0.0, f64::max) * 1.1;
        panels.push(
            Panel::new(
                lamp.name,
                "wavelength (nm)",
                "density (1/nm)",
                vec![
                    Series::bars(format!("{n} samples, 1 nm bins"), &edges, &heights),
                    Series::line("the pdf L(λ)/∫L", pdf),
                ],
            )
            .x_range((380.0, 830.0))
            .y_range((0.0, ymax)),
        );
    }
    plot::chart(&panels, 2)
}

fn swatches_png(_: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    use plotters::prelude::*;
    let lamps = lamps();
    let (side, gap, label) = (200i32, 24i32, 70i32);
    let width = (lamps.len() as i32 * (side + gap) + gap) as u32;
    let height = (side + 2 * gap + label) as u32;
    plot::draw_png(width, height, |root| {
        for (k, lamp) in lamps.iter().enumerate() {
            let x0 = gap + k as i32 * (side + gap);
            let [r, g, b] = swatch_rgb8(&lamp.spectrum);
            root.draw(&Rectangle::new(
                [(x0, gap), (x0 + side, gap + side)],
                RGBColor(r, g, b).filled(),
            ))?;
            let xy = cie::chromaticity(xyz_unit(&lamp.spectrum)).ok_or("black lamp")?;
            root.draw(&Text::new(
                lamp.name.to_string(),
                (x0, gap + side + 12),
                ("sans-serif", 17),
            ))?;
            root.draw(&Text::new(
                format!("x = {:.4}, y = {:.4}", xy.x, xy.y),
                (x0, gap + side + 36),
                ("sans-serif", 15),
            ))?;
        }
        Ok(())
    })
}

/// Variance of the one-sample X, Y, Z estimators with `n` samples drawn by `draw`.
fn variances(t: &Table, n: usize, seed: u64, draw: impl Fn(f64) -> WavelengthSample) -> DVec3 {
    let mut r = rng::seeded(seed);
    let (mut x, mut y, mut z) = (Summary::default(), Summary::default(), Summary::default());
    for _ in 0..n {
        let w = draw(r.random::<f64>());
        let e = xyz_estimate(t, w.nm, w.pdf);
        x.push(e.x);
        y.push(e.y);
        z.push(e.z);
    }
    DVec3::new(x.variance(), y.variance(), z.variance())
}

/// CIE 1960 (u, v) of a chromaticity.
fn uv(xy: glam::DVec2) -> glam::DVec2 {
    let d = -2.0 * xy.x + 12.0 * xy.y + 3.0;
    glam::DVec2::new(4.0 * xy.x / d, 6.0 * xy.y / d)
}

/// The Planckian locus in CIE 1960 (u, v), from 1 to 1000 mired (1000 K to 10⁶ K) in
/// steps of 1 mired, each point from Planck's law and the colour-matching functions.
fn planckian_locus() -> Vec<(f64, glam::DVec2)> {
    (1..=1000)
        .rev()
        .map(|mired| {
            let kelvin = 1e6 / f64::from(mired);
            let xyz = cie::xyz(|nm| raylemma::spectral::spectrum::planck(nm, kelvin));
            (
                kelvin,
                uv(glam::DVec2::new(xyz.x, xyz.y) / xyz.element_sum()),
            )
        })
        .collect()
}

/// Correlated colour temperature and `Duv` of a chromaticity: the nearest point of the
/// Planckian locus in (u, v) (projected onto the polyline), and the signed distance to
/// it, positive above the locus (towards green), negative below (towards magenta).
fn cct_duv(xy: glam::DVec2, locus: &[(f64, glam::DVec2)]) -> (f64, f64) {
    let p = uv(xy);
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for w in locus.windows(2) {
        let ((t0, a), (t1, b)) = (w[0], w[1]);
        let s = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
        let q = a + s * (b - a);
        let d = (p - q).length();
        if d < best.0 {
            // Above the locus is larger v (the locus is a graph over u here).
            let side = (p.y - q.y).signum();
            best = (d, t0 + s * (t1 - t0), side);
        }
    }
    (best.1, best.2 * best.0)
}

fn colour_md(_: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let locus = planckian_locus();
    let mut md = String::new();
    writeln!(
        md,
        "| lamp | x | y | CCT (K) | Duv | linear sRGB at Y = 1 | swatch (sRGB, 8 bit) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---|---|")?;
    for lamp in lamps() {
        let xyz = xyz_unit(&lamp.spectrum);
        let xy = cie::chromaticity(xyz).ok_or("black lamp")?;
        let (cct, duv) = cct_duv(xy, &locus);
        let rgb = cie::xyz_to_linear_srgb(xyz);
        let [r, g, b] = swatch_rgb8(&lamp.spectrum);
        writeln!(
            md,
            "| {} | {:.4} | {:.4} | {cct:.0} | {duv:+.4} | ({:.3}, {:.3}, {:.3}) | ({r}, {g}, {b}) |",
            lamp.name, xy.x, xy.y, rgb.x, rgb.y, rgb.z
        )?;
    }
    writeln!(
        md,
        "\n*Chromaticity, correlated colour temperature, Duv (distance from the Planckian \
         locus in CIE 1960 (u, v), positive towards green) and linear sRGB from the exact XYZ \
         of each table (CIE 1931 2°). A negative sRGB component is a colour outside the sRGB \
         gamut; the swatch clips it to 0.*"
    )?;
    Ok(md.into_bytes())
}

/// A lamp's name as a value name: its drawing's stem without `lamp_` (`amber_led`).
fn lamp_key(lamp: &Lamp) -> &'static str {
    lamp.stem.trim_start_matches("lamp_")
}

/// One lamp's variance gains over uniform wavelengths, for X, Y and Z.
struct Gain {
    name: &'static str,
    key: &'static str,
    /// With `p ∝ L`, the lamp's own spectrum.
    own: DVec3,
    /// With the colour proposal `p ∝ L (x̄ + ȳ + z̄)`.
    colour: DVec3,
}

/// The gains, measured once per run (with fixed seeds): the gain table and the speed table's
/// efficiencies read the same measurement.
fn gains(settings: &Settings) -> Result<&'static [Gain], BoxError> {
    static GAINS: std::sync::OnceLock<Result<Vec<Gain>, String>> = std::sync::OnceLock::new();
    GAINS
        .get_or_init(|| measure_gains(settings).map_err(|e| e.to_string()))
        .as_deref()
        .map_err(|e| e.clone().into())
}

fn measure_gains(settings: &Settings) -> Result<Vec<Gain>, BoxError> {
    let n = gain_samples(settings);
    lamps()
        .iter()
        .enumerate()
        .map(|(k, lamp)| {
            let t = &lamp.spectrum;
            let own = sampler(t)?;
            let colour = sampler(&colour_proposal(t))?;
            let un = variances(t, n, 0xE20 + k as u64, uniform_wavelength);
            Ok(Gain {
                name: lamp.name,
                key: lamp_key(lamp),
                own: un / variances(t, n, 0xE10 + k as u64, |u| own.sample(u)),
                colour: un / variances(t, n, 0xE30 + k as u64, |u| colour.sample(u)),
            })
        })
        .collect()
}

fn gain_samples(settings: &Settings) -> usize {
    if settings.quick { 100_000 } else { 1_000_000 }
}

/// The names of the lamps whose gains satisfy `pred`.
fn lamps_where(rows: &[Gain], pred: impl Fn(&Gain) -> bool) -> Vec<String> {
    rows.iter()
        .filter(|g| pred(g))
        .map(|g| g.name.to_string())
        .collect()
}

fn gain_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let n = gain_samples(settings);
    let rows = gains(settings)?;
    let mut md = String::new();
    writeln!(
        md,
        "| lamp | p ∝ L: gain X | gain Y | gain Z | p ∝ L (x̄+ȳ+z̄): gain X | gain Y | gain Z |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|---:|")?;
    for g in rows {
        let mut cells = Vec::new();
        for (proposal, gain) in [("own", g.own), ("colour", g.colour)] {
            for (axis, x) in [("x", gain.x), ("y", gain.y), ("z", gain.z)] {
                cells.push(r.number(&format!("{}.{proposal}.gain_{axis}", g.key), x, ".2"));
            }
            // The Y gain as the prose rounds a large one, to a whole number.
            r.number(&format!("{}.{proposal}.gain_y_int", g.key), gain.y, "int");
        }
        writeln!(md, "| {} | {} |", g.name, cells.join(" | "))?;
    }
    let list = |v: &[String]| {
        if v.is_empty() {
            "none".to_string()
        } else {
            v.join(", ")
        }
    };
    // The colour proposal against p ∝ L, and against uniform, on each of X, Y and Z.
    let below_own_y = lamps_where(rows, |g| g.colour.y <= g.own.y);
    let below_uniform_y = lamps_where(rows, |g| g.colour.y <= 1.0);
    let below_own_xyz = lamps_where(rows, |g| g.colour.cmple(g.own).any());
    let below_uniform_xyz = lamps_where(rows, |g| g.colour.cmple(DVec3::ONE).any());
    r.claim(
        "colour_beats_own_on_y_every_lamp",
        below_own_y.is_empty(),
        format!(
            "lamps whose Y gain with the colour proposal is not above that of p ∝ L: {}",
            list(&below_own_y)
        ),
    );
    r.claim(
        "colour_beats_own_and_uniform_on_y_every_lamp",
        below_own_y.is_empty() && below_uniform_y.is_empty(),
        format!(
            "lamps whose Y gain with the colour proposal is not above that of p ∝ L: {}; not above 1: {}",
            list(&below_own_y),
            list(&below_uniform_y)
        ),
    );
    r.claim(
        "colour_beats_own_on_xyz_every_lamp",
        below_own_xyz.is_empty(),
        format!(
            "lamps where the colour proposal's gain on X, Y or Z is not above that of p ∝ L: {}",
            list(&below_own_xyz)
        ),
    );
    r.claim(
        "colour_beats_uniform_on_xyz_every_lamp",
        below_uniform_xyz.is_empty(),
        format!(
            "lamps where the colour proposal's gain on X, Y or Z is not above 1: {}",
            list(&below_uniform_xyz)
        ),
    );
    let inc = rows
        .iter()
        .find(|g| g.key == "incandescent")
        .ok_or("no incandescent lamp")?;
    r.claim(
        "incandescent_own_gains_nothing_on_y_loses_on_z",
        0.9 < inc.own.y && inc.own.y <= 1.0 && inc.own.z < 1.0,
        format!(
            "incandescent, p ∝ L: 0.9 < gain Y {:.4} <= 1 and gain Z {:.4} < 1",
            inc.own.y, inc.own.z
        ),
    );
    writeln!(
        md,
        "\n*Gain: variance of the one-sample estimator of X, Y or Z with λ uniform on \
         380–830 nm, divided by its variance with λ drawn from the proposal p; above 1, the \
         proposal is better. {n} samples per estimator and lamp (fixed seeds).*"
    )?;
    Ok(md.into_bytes())
}

fn drawing_md(_: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let mut md = String::new();
    writeln!(
        md,
        "| lamp | height (px) | largest column error (of the peak) | columns with light lost | share of ∫L lost there | Δ(x, y) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|")?;
    let mut worst_shift_256 = 0.0f64;
    let mut lost_at_32 = Vec::new();
    for lamp in lamps() {
        let t = &lamp.spectrum;
        let key = lamp_key(&lamp);
        let xy_table = cie::chromaticity(xyz_unit(t)).ok_or("black lamp")?;
        let nm = image_wavelengths();
        let max = nm.iter().map(|&l| t.eval(l)).fold(0.0, f64::max);
        let total: f64 = nm.iter().map(|&l| t.eval(l)).sum();
        for height in [32, IMAGE_HEIGHT] {
            let png = write_image(t, height)?;
            let drawn = parse_image(&png, lamp.stem)?;
            let err = nm
                .iter()
                .map(|&l| (drawn.eval(l) - t.eval(l) / max).abs())
                .fold(0.0, f64::max);
            let lost: Vec<f64> = nm
                .iter()
                .filter(|&&l| t.eval(l) > 0.0 && drawn.eval(l) == 0.0)
                .map(|&l| t.eval(l))
                .collect();
            let xy = cie::chromaticity(xyz_unit(&drawn)).ok_or("black drawing")?;
            let shift = (xy - xy_table).length();
            if height == IMAGE_HEIGHT {
                worst_shift_256 = worst_shift_256.max(shift);
            }
            if height == 32 {
                lost_at_32.push((key, lamp.name, lost.len()));
            }
            writeln!(
                md,
                "| {} | {height} | {err:.2e} | {} | {} | {shift:.1e} |",
                lamp.name,
                r.number(
                    &format!("{key}.h{height}.lost_columns"),
                    lost.len() as f64,
                    "int"
                ),
                if lost.is_empty() {
                    "0".to_string()
                } else {
                    format!("{:.2e}", lost.iter().sum::<f64>() / total)
                },
            )?;
        }
    }
    r.number(
        &format!("worst_xy_shift_h{IMAGE_HEIGHT}"),
        worst_shift_256,
        "x1",
    );
    // "Dozens of columns": two dozen or more, and fewer than a hundred.
    let tails: Vec<(&str, usize)> = lost_at_32
        .iter()
        .filter(|(key, ..)| ["cool_white_fluorescent", "high_pressure_sodium"].contains(key))
        .map(|&(_, name, n)| (name, n))
        .collect();
    r.claim(
        "fluorescent_and_high_pressure_sodium_lose_dozens_of_columns_h32",
        tails.len() == 2 && tails.iter().all(|&(_, n)| (24..100).contains(&n)),
        format!(
            "columns with light lost at 32 px: {}",
            tails
                .iter()
                .map(|(name, n)| format!("{name}: 24 <= {n} < 100"))
                .collect::<Vec<_>>()
                .join("; ")
        ),
    );
    writeln!(
        md,
        "\n*Each lamp drawn with `write_image` and read back with `parse_image`; the error of \
         a column is at most half a pixel, 1/(2 height) of the peak. \"Lost\": columns where \
         the lamp emits but the drawing has no dark pixel. Δ(x, y): distance between the \
         chromaticities of the drawing and of the table.*"
    )?;
    Ok(md.into_bytes())
}

fn speed_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let reps = if settings.quick { 5 } else { 101 };
    let us = raylemma::workload::uniform_inputs(4096);
    let gains = gains(settings)?;
    let mut md = String::new();
    writeln!(
        md,
        "| lamp | knots | importance (ns per sample) | uniform (ns per sample) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|")?;
    for lamp in lamps() {
        let key = lamp_key(&lamp);
        let s = sampler(&lamp.spectrum)?;
        let imp = timing::median_ns_per_input(&us, reps, |u| {
            let w = s.sample(u);
            w.nm + w.pdf
        });
        let uni = timing::median_ns_per_input(&us, reps, |u| {
            let w = uniform_wavelength(u);
            w.nm + w.pdf
        });
        // A draw from the table costs this many uniform draws; the gains per unit cost (the
        // colour proposal is a table sampled the same way, so it is given the same cost).
        let cost = imp / uni;
        r.number(&format!("{key}.cost_ratio"), cost, "s2");
        let gain = gains
            .iter()
            .find(|g| g.key == key)
            .ok_or("a lamp without gains")?;
        for (axis, g) in [
            ("x", gain.colour.x),
            ("y", gain.colour.y),
            ("z", gain.colour.z),
        ] {
            r.number(
                &format!("{key}.colour_gain_per_cost.{axis}"),
                g / cost,
                "s2",
            );
        }
        if key == "incandescent" {
            r.claim(
                "incandescent_uniform_no_worse_on_y_and_cheaper",
                gain.own.y <= 1.0 && uni < imp,
                format!(
                    "incandescent: gain on Y of p ∝ L {:.4} <= 1, uniform {uni:.2} ns < importance {imp:.2} ns",
                    gain.own.y
                ),
            );
        }
        writeln!(
            md,
            "| {} | {} | {} | {} |",
            lamp.name,
            lamp.spectrum.wavelengths().len(),
            // Three significant digits each: the ratio of the two, which the book quotes,
            // then does not depend on how a sub-nanosecond time was rounded.
            r.number(&format!("{key}.importance_ns"), imp, "s3"),
            r.number(&format!("{key}.uniform_ns"), uni, "s3"),
        )?;
    }
    writeln!(
        md,
        "\n*{}; 4096 random u per batch, median of {reps} batches{}. Each sample includes \
         its pdf.*",
        timing::machine(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
