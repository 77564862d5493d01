//! Figures and tables of the chapter *Importance-sampled emission spectra*.

use std::fmt::Write as _;

use anyhow::{Context, anyhow};
use glam::DVec3;
use rand::RngExt;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, Panel, Series};
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

fn sampler(t: &Table) -> anyhow::Result<EmissionSampler> {
    Ok(EmissionSampler::new(t)?)
}

fn histograms_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
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

fn swatches_png(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
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
            let xy = cie::chromaticity(xyz_unit(&lamp.spectrum)).context("black lamp")?;
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

fn colour_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let locus = planckian_locus();
    let mut md = String::new();
    writeln!(
        md,
        "| lamp | x | y | CCT (K) | Duv | linear sRGB at Y = 1 | swatch (sRGB, 8 bit) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---|---|")?;
    for lamp in lamps() {
        let xyz = xyz_unit(&lamp.spectrum);
        let xy = cie::chromaticity(xyz).context("black lamp")?;
        let (cct, duv) = cct_duv(xy, &locus);
        let rgb = cie::xyz_to_linear_srgb(xyz);
        let [red, green, blue] = swatch_rgb8(&lamp.spectrum);
        let key = lamp_key(&lamp);
        let cct_text = r.number(&format!("{key}.cct"), cct, "int");
        let duv_text = r.text(&format!("{key}.duv"), format!("{duv:+.4}"));
        if key == "cool_white_fluorescent" {
            // ANSI C78.377's 4500 K band: CCT 4503 ± 243 K, Duv 0.001 ± 0.006. The lamp is
            // on the green side of the locus, and well inside the tolerance: within half of
            // it from the band's centre.
            r.claim(
                "fluorescent_in_4500_band",
                (4503.0 - 243.0..=4503.0 + 243.0).contains(&cct),
                format!("cool white fluorescent: 4260 K <= CCT {cct:.1} K <= 4746 K"),
            );
            r.claim(
                "fluorescent_green_side",
                duv > 0.0,
                format!("cool white fluorescent: Duv {duv:+.5} > 0"),
            );
            r.claim(
                "fluorescent_well_inside",
                (duv - 0.001).abs() < 0.003,
                format!(
                    "cool white fluorescent: |Duv {duv:+.5} − 0.001| < 0.003 (half the tolerance 0.006)"
                ),
            );
        }
        writeln!(
            md,
            "| {} | {:.4} | {:.4} | {cct_text} | {duv_text} | ({:.3}, {:.3}, {:.3}) | ({red}, {green}, {blue}) |",
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
    /// With the channel-balanced proposal `p ∝ L (x̄/X + ȳ/Y + z̄/Z)`.
    balanced: DVec3,
    /// The mean over X, Y and Z of `Var / exact²`, with λ uniform and with each proposal:
    /// `[uniform, own, colour, balanced]`.
    relative_variance: [f64; 4],
}

/// The gains, measured once per run (with fixed seeds): the gain table and the speed table's
/// efficiencies read the same measurement.
fn gains(settings: &Settings) -> anyhow::Result<&'static [Gain]> {
    static GAINS: std::sync::OnceLock<Result<Vec<Gain>, String>> = std::sync::OnceLock::new();
    GAINS
        .get_or_init(|| measure_gains(settings).map_err(|e| crate::job::message(&e)))
        .as_deref()
        .map_err(|e| anyhow!("{e}"))
}

fn measure_gains(settings: &Settings) -> anyhow::Result<Vec<Gain>> {
    let n = gain_samples(settings);
    lamps()
        .iter()
        .enumerate()
        .map(|(k, lamp)| {
            let t = &lamp.spectrum;
            let own = sampler(t)?;
            let colour = sampler(&colour_proposal(t))?;
            let balanced = sampler(&balanced_proposal(t))?;
            let un = variances(t, n, 0xE20 + k as u64, uniform_wavelength);
            let own = variances(t, n, 0xE10 + k as u64, |u| own.sample(u));
            let colour = variances(t, n, 0xE30 + k as u64, |u| colour.sample(u));
            let balanced = variances(t, n, 0xE40 + k as u64, |u| balanced.sample(u));
            let exact = cie::xyz(|nm| t.eval(nm));
            let relative = |v: DVec3| (v / (exact * exact)).element_sum() / 3.0;
            Ok(Gain {
                name: lamp.name,
                key: lamp_key(lamp),
                own: un / own,
                colour: un / colour,
                balanced: un / balanced,
                relative_variance: [un, own, colour, balanced].map(relative),
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

fn gain_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n = gain_samples(settings);
    let rows = gains(settings)?;
    let mut md = String::new();
    writeln!(
        md,
        "| lamp | p ∝ L: gain X | gain Y | gain Z | p ∝ L (x̄+ȳ+z̄): gain X | gain Y | gain Z | p ∝ L (x̄/X+ȳ/Y+z̄/Z): gain X | gain Y | gain Z |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")?;
    for g in rows {
        let mut cells = Vec::new();
        for (proposal, gain) in [
            ("own", g.own),
            ("colour", g.colour),
            ("balanced", g.balanced),
        ] {
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
    // The colour proposal loses to p ∝ L on X for exactly the two narrowest lamps, and
    // stays below uniform sampling on Z for the incandescent and high-pressure sodium lamps.
    let below_own_x = lamps_where(rows, |g| g.colour.x < g.own.x);
    r.claim(
        "colour_loses_x_twice",
        below_own_x == ["amber LED", "low-pressure sodium"],
        format!(
            "lamps whose X gain with the colour proposal is below that of p ∝ L (want: amber LED, low-pressure sodium): {}",
            list(&below_own_x)
        ),
    );
    let lamp = |key: &str| {
        rows.iter()
            .find(|g| g.key == key)
            .with_context(|| format!("no lamp {key}"))
    };
    let (inc, hps) = (lamp("incandescent")?, lamp("high_pressure_sodium")?);
    r.claim(
        "colour_loses_z_warm",
        inc.colour.z < 1.0 && hps.colour.z < 1.0,
        format!(
            "gain Z with the colour proposal: incandescent {:.4} < 1, high-pressure sodium {:.4} < 1",
            inc.colour.z, hps.colour.z
        ),
    );
    r.claim(
        "incandescent_colour_gain_y_above_2",
        inc.colour.y > 2.0,
        format!(
            "incandescent, colour proposal: gain Y {:.4} > 2",
            inc.colour.y
        ),
    );
    // The channel-balanced proposal gains over uniform sampling on every channel of every
    // lamp, and has the lowest mean relative variance of the four choices for every lamp; it
    // pays with a smaller gain on Y than the colour proposal's for the broad lamps.
    let balanced_not_above = lamps_where(rows, |g| g.balanced.cmple(DVec3::ONE).any());
    r.claim(
        "balanced_gains_everywhere",
        balanced_not_above.is_empty(),
        format!(
            "lamps where the balanced proposal's gain on X, Y or Z is not above 1: {}",
            list(&balanced_not_above)
        ),
    );
    let broad = [
        "incandescent",
        "cool_white_fluorescent",
        "high_pressure_sodium",
    ];
    let broad_rows: Vec<&Gain> = rows.iter().filter(|g| broad.contains(&g.key)).collect();
    r.claim(
        "balanced_y_below_colour_y_broad",
        broad_rows.len() == broad.len() && broad_rows.iter().all(|g| g.balanced.y < g.colour.y),
        format!(
            "gain Y, balanced < colour proposal: {}",
            broad_rows
                .iter()
                .map(|g| format!("{} {:.3} < {:.3}", g.name, g.balanced.y, g.colour.y))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    let narrow_rows: Vec<&Gain> = rows.iter().filter(|g| !broad.contains(&g.key)).collect();
    r.claim(
        "balanced_y_above_colour_y_narrow",
        !narrow_rows.is_empty() && narrow_rows.iter().all(|g| g.balanced.y > g.colour.y),
        format!(
            "gain Y, balanced > colour proposal: {}",
            narrow_rows
                .iter()
                .map(|g| format!("{} {:.1} > {:.1}", g.name, g.balanced.y, g.colour.y))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    let not_lowest = lamps_where(rows, |g| {
        let v = g.relative_variance;
        !(v[3] < v[0] && v[3] < v[1] && v[3] < v[2])
    });
    r.claim(
        "balanced_lowest_mean_relative_variance",
        not_lowest.is_empty(),
        format!(
            "lamps where the balanced proposal's mean relative variance over X, Y, Z is not the lowest of uniform, p ∝ L, colour and balanced: {}",
            list(&not_lowest)
        ),
    );
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
        "\n**Mean relative variance** over X, Y and Z, Var / exact² (smaller is better)\n"
    )?;
    writeln!(
        md,
        "| lamp | uniform | p ∝ L | p ∝ L (x̄+ȳ+z̄) | p ∝ L (x̄/X+ȳ/Y+z̄/Z) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|")?;
    for g in rows {
        let cells: Vec<String> = ["uniform", "own", "colour", "balanced"]
            .iter()
            .zip(g.relative_variance)
            .map(|(proposal, v)| {
                r.number(
                    &format!("{}.{proposal}.mean_relative_variance", g.key),
                    v,
                    "s3",
                )
            })
            .collect();
        writeln!(md, "| {} | {} |", g.name, cells.join(" | "))?;
    }
    writeln!(
        md,
        "\n*Gain: variance of the one-sample estimator of X, Y or Z with λ uniform on \
         380–830 nm, divided by its variance with λ drawn from the proposal p; above 1, the \
         proposal is better. Mean relative variance: the variances of the same estimators \
         over the squares of the exact X, Y and Z, averaged over the three. The proposals are \
         tables at every whole nanometre of 380–830 nm, linear in between; X, Y, Z in the \
         balanced one are the lamp's own. {n} samples per estimator, proposal and lamp (fixed \
         seeds).*"
    )?;
    Ok(md.into_bytes())
}

fn drawing_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::new();
    writeln!(
        md,
        "| lamp | height (px) | largest column error (of the peak) | columns with light lost | share of ∫L lost there | Δ(x, y) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|")?;
    let mut worst_shift_256 = 0.0f64;
    let mut lost_at_32 = Vec::new();
    let mut amber_lost = Vec::new();
    for lamp in lamps() {
        let t = &lamp.spectrum;
        let key = lamp_key(&lamp);
        let xy_table = cie::chromaticity(xyz_unit(t)).context("black lamp")?;
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
            let xy = cie::chromaticity(xyz_unit(&drawn)).context("black drawing")?;
            let shift = (xy - xy_table).length();
            if height == IMAGE_HEIGHT {
                worst_shift_256 = worst_shift_256.max(shift);
            }
            if height == 32 {
                lost_at_32.push((key, lamp.name, lost.len()));
            }
            if key == "amber_led" {
                amber_lost.push((height, lost.len()));
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
    // "Within about 1e-4": below twice that.
    r.claim(
        "drawn_colour_within_about_1e_4",
        worst_shift_256 < 2e-4,
        format!("largest Δ(x, y) at {IMAGE_HEIGHT} px: {worst_shift_256:.2e} < 2e-4"),
    );
    // The amber LED's skirts vanish from hundreds of columns (two hundred or more) at every
    // height.
    r.claim(
        "amber_skirts_lost",
        amber_lost.len() == 2 && amber_lost.iter().all(|&(_, n)| n >= 200),
        format!(
            "amber LED, columns with light lost, each >= 200: {}",
            amber_lost
                .iter()
                .map(|(h, n)| format!("{h} px: {n}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
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

fn speed_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
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
        // colour and balanced proposals are tables sampled the same way, so they are given the
        // same cost).
        let cost = imp / uni;
        r.number(&format!("{key}.cost_ratio"), cost, "s2");
        let gain = gains
            .iter()
            .find(|g| g.key == key)
            .context("a lamp without gains")?;
        for (proposal, g) in [("colour", gain.colour), ("balanced", gain.balanced)] {
            for (axis, g) in [("x", g.x), ("y", g.y), ("z", g.z)] {
                r.number(
                    &format!("{key}.{proposal}_gain_per_cost.{axis}"),
                    g / cost,
                    "s2",
                );
            }
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
