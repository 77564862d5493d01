//! Figures and tables of the chapter *Dispersion*.

use std::f64::consts::FRAC_PI_2;
use std::fmt::Write as _;

use anyhow::{Context, bail};

use super::{Output, Record, Settings};
use crate::plot::{self, Panel, Series};
use raylemma::optics::dispersion::{
    self as disp, FUSED_SILICA, LINE_C_NM, LINE_D_NM, LINE_F_NM, N_BK7, PrismPath, RENDER_RANGE_NM,
    WATER,
};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "dispersion_index.svg",
            what: "refractive index against wavelength",
            make: index_svg,
        },
        Output {
            file: "dispersion_catalogue.md",
            what: "catalogue checks of the Sellmeier fits",
            make: catalogue_md,
        },
        Output {
            file: "dispersion_prism.svg",
            what: "prism deviation against wavelength and incidence",
            make: prism_svg,
        },
        Output {
            file: "dispersion_prism.md",
            what: "minimum deviation of 60° prisms",
            make: prism_md,
        },
        Output {
            file: "dispersion_rainbow.svg",
            what: "rainbow angle against wavelength",
            make: rainbow_svg,
        },
        Output {
            file: "dispersion_rainbow.md",
            what: "primary bow by wavelength",
            make: rainbow_md,
        },
    ]
}

const MATERIALS: [&str; 3] = [N_BK7, FUSED_SILICA, WATER];

use crate::plot::Legend;

/// The range of the points of `series`, padded by 5 % each side.
fn y_range(series: &[Series]) -> (f64, f64) {
    let (lo, hi) = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .filter(|y| y.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
            (a.min(y), b.max(y))
        });
    let pad = 0.05 * (hi - lo).max(1e-9);
    (lo - pad, hi + pad)
}

/// Wavelengths of the render range in steps of `step` nm, ends included.
fn wavelengths(step: usize) -> Vec<f64> {
    let (lo, hi) = (RENDER_RANGE_NM.0 as usize, RENDER_RANGE_NM.1 as usize);
    (lo..=hi).step_by(step).map(|l| l as f64).collect()
}

fn index_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let ls = wavelengths(5);
    let series = MATERIALS
        .iter()
        .map(|&name| {
            let g = disp::material(name);
            Series::line(name, ls.iter().map(|&l| (l, g.index(l))).collect())
        })
        .collect();
    // The same curves relative to each material's n_d, to compare their dispersion.
    let relative = MATERIALS
        .iter()
        .map(|&name| {
            let g = disp::material(name);
            let nd = g.index(LINE_D_NM);
            Series::line(
                name,
                ls.iter().map(|&l| (l, 1e3 * (g.index(l) - nd))).collect(),
            )
        })
        .collect();
    let range = RENDER_RANGE_NM;
    let panels = [
        Panel::new(
            "Sellmeier fits over the render range",
            "wavelength (nm)",
            "refractive index n",
            series,
        ),
        Panel::new(
            "n(λ) − n_d",
            "wavelength (nm)",
            "(n − n_d) × 1000",
            relative,
        ),
    ];
    let panels = panels.map(|p| {
        let yr = y_range(&p.series);
        (p, range, yr, Legend::UpperRight)
    });
    plot::ranged_chart(&panels)
}

fn catalogue_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let bk7 = disp::material(N_BK7);
    let fs = disp::material(FUSED_SILICA);
    let water = disp::material(WATER);
    let d = |g: &disp::Sellmeier| g.index(LINE_D_NM);
    let f = |g: &disp::Sellmeier| g.index(LINE_F_NM);
    let c = |g: &disp::Sellmeier| g.index(LINE_C_NM);
    // (material, quantity, computed, published, tolerance, source)
    type Row = (
        &'static str,
        &'static str,
        f64,
        Option<f64>,
        &'static str,
        &'static str,
    );
    let rows: [Row; 10] = [
        (
            "N-BK7",
            "n_d",
            d(bk7),
            Some(1.51680),
            "5e-6",
            "SCHOTT datasheet",
        ),
        (
            "N-BK7",
            "n_F",
            f(bk7),
            Some(1.52238),
            "5e-6",
            "SCHOTT datasheet",
        ),
        (
            "N-BK7",
            "n_C",
            c(bk7),
            Some(1.51432),
            "5e-6",
            "SCHOTT datasheet",
        ),
        (
            "N-BK7",
            "n_F − n_C",
            f(bk7) - c(bk7),
            Some(0.008054),
            "5e-7",
            "SCHOTT datasheet",
        ),
        (
            "N-BK7",
            "V_d",
            bk7.abbe(),
            Some(64.17),
            "0.005",
            "SCHOTT datasheet",
        ),
        (
            "fused silica",
            "n_d",
            d(fs),
            Some(1.45846),
            "5e-6",
            "Malitson 1965, table",
        ),
        (
            "fused silica",
            "V_d",
            fs.abbe(),
            Some(67.8),
            "0.05",
            "Corning 7980, Heraeus Suprasil",
        ),
        ("water, 20 °C", "n_d", d(water), None, "", "—"),
        (
            "water, 20 °C",
            "n_F − n_C",
            f(water) - c(water),
            None,
            "",
            "—",
        ),
        ("water, 20 °C", "V_d", water.abbe(), None, "", "—"),
    ];
    let mut md = String::new();
    writeln!(
        md,
        "| material | quantity | from the Sellmeier fit | published | difference | tolerance | published in |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---|")?;
    // Every published value within its tolerance, and what that read.
    let mut within = true;
    let mut read = Vec::new();
    for &(material, quantity, got, published, tol, source) in &rows {
        let digits = if quantity == "V_d" { 3 } else { 6 };
        let (p, diff) = match published {
            Some(p) => (format!("{p}"), format!("{:+.1e}", got - p)),
            None => ("—".into(), "—".into()),
        };
        if let Some(p) = published {
            let bound: f64 = tol.parse()?;
            within &= (got - p).abs() <= bound;
            read.push(format!("{material} {quantity} |{:+.2e}| <= {tol}", got - p));
        }
        writeln!(
            md,
            "| {material} | {quantity} | {got:.digits$} | {p} | {diff} | {tol} | {source} |"
        )?;
    }
    r.claim("within_tolerance", within, read.join("; "));
    // Water: the lowest n_d and the lowest Abbe number of the three (from the fits).
    let (nd, vd) = (
        [d(water), d(bk7), d(fs)],
        [water.abbe(), bk7.abbe(), fs.abbe()],
    );
    r.claim(
        "water_lowest_index_and_abbe",
        nd[0] < nd[1] && nd[0] < nd[2] && vd[0] < vd[1] && vd[0] < vd[2],
        format!(
            "n_d: water {:.6} < N-BK7 {:.6}, fused silica {:.6}; V_d: water {:.3} < N-BK7 {:.3}, fused silica {:.3}",
            nd[0], nd[1], nd[2], vd[0], vd[1], vd[2]
        ),
    );
    writeln!(
        md,
        "\n*Lines: d = {LINE_D_NM} nm (He), F = {LINE_F_NM} nm, C = {LINE_C_NM} nm (H). \
         Tolerances are half a unit of the last printed digit; asserted by `tests/book/optics/dispersion.rs`. \
         Generated by `cargo run --release` (`tools/figures/src/dispersion.rs`).*"
    )?;
    Ok(md.into_bytes())
}

const APEX_DEG: f64 = 60.0;

fn prism_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let apex = APEX_DEG.to_radians();
    let ls = wavelengths(5);
    let mut by_wavelength = Vec::new();
    for name in [N_BK7, FUSED_SILICA] {
        let g = disp::material(name);
        let (i0, _) = disp::minimum_deviation_numeric(g.index(LINE_D_NM), apex)
            .context("no ray through the prism")?;
        by_wavelength.push(Series::line(
            format!("{name}, incidence {:.2}°", i0.to_degrees()),
            ls.iter()
                .filter_map(|&l| {
                    disp::prism(g.index(l), apex, i0)
                        .deviation()
                        .map(|dev| (l, dev.to_degrees()))
                })
                .collect(),
        ));
    }
    let g = disp::material(N_BK7);
    let by_incidence = [400.0, 550.0, 700.0]
        .iter()
        .map(|&l| {
            let n = g.index(l);
            Series::line(
                format!("N-BK7, {l:.0} nm"),
                (0..=180)
                    .filter_map(|k| {
                        let i = (f64::from(k) * 0.5).to_radians();
                        match disp::prism(n, apex, i) {
                            PrismPath::Through { deviation, .. } => {
                                Some((i.to_degrees(), deviation.to_degrees()))
                            }
                            _ => None,
                        }
                    })
                    .collect(),
            )
        })
        .collect();
    let panels = [
        Panel::new(
            format!("{APEX_DEG:.0}° prism at the d line's minimum-deviation incidence"),
            "wavelength (nm)",
            "deviation (degrees)",
            by_wavelength,
        ),
        Panel::new(
            "deviation against incidence (missing: total internal reflection)",
            "angle of incidence (degrees)",
            "deviation (degrees)",
            by_incidence,
        ),
    ];
    let [first, second] = panels;
    let (y1, y2) = (y_range(&first.series), y_range(&second.series));
    plot::ranged_chart(&[
        (first, RENDER_RANGE_NM, y1, Legend::Below),
        (second, (0.0, 90.0), y2, Legend::Below),
    ])
}

fn prism_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let apex = APEX_DEG.to_radians();
    let mut md = String::new();
    writeln!(
        md,
        "| material | line | n | incidence at minimum (numerical) | D_min numerical | D_min closed form | n recovered from D_min | limiting incidence | misses the exit face below |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|---:|")?;
    // Per material: the spread of the visible spectrum, D_min(F) − D_min(C) in degrees
    // (from the numerical minima), and the Abbe number.
    let mut spreads = Vec::new();
    for name in [N_BK7, FUSED_SILICA] {
        let g = disp::material(name);
        let (mut at_f, mut at_c) = (f64::NAN, f64::NAN);
        for (line, l) in [("F", LINE_F_NM), ("d", LINE_D_NM), ("C", LINE_C_NM)] {
            let n = g.index(l);
            let (i, dn) = disp::minimum_deviation_numeric(n, apex).context("no ray through")?;
            let de = disp::minimum_deviation_analytic(n, apex).context("no ray through")?;
            let back = disp::index_from_minimum_deviation(apex, de);
            let lim = disp::prism_limiting_incidence(n, apex).context("no ray through")?;
            // Inside, the ray misses the exit face once θ2 <= A − 90°, i.e. below
            // sin θ1 = n sin(A − 90°) (a wide enough prism only).
            let s_miss = n * (apex - FRAC_PI_2).sin();
            let miss = (s_miss.abs() <= 1.0).then(|| s_miss.asin());
            check_caption(n, apex, lim, miss)?;
            match line {
                "F" => at_f = dn.to_degrees(),
                "C" => at_c = dn.to_degrees(),
                _ => {}
            }
            writeln!(
                md,
                "| {name} | {line} | {n:.5} | {:.4}° | {:.6}° | {:.6}° | {back:.5} | {:.2}° | {} |",
                i.to_degrees(),
                dn.to_degrees(),
                de.to_degrees(),
                lim.to_degrees(),
                miss.map_or("—".into(), |m| format!("{:.2}°", m.to_degrees()))
            )?;
        }
        let key = if name == N_BK7 {
            "n_bk7"
        } else {
            "fused_silica"
        };
        r.number(&format!("{key}.spread_deg"), at_f - at_c, ".3");
        spreads.push((at_f - at_c, g.abbe()));
    }
    let ((bk7, bk7_abbe), (silica, silica_abbe)) = (spreads[0], spreads[1]);
    r.claim(
        "fused_silica_larger_abbe_spreads_less",
        silica_abbe > bk7_abbe && silica < bk7,
        format!(
            "fused silica's Abbe number {silica_abbe:.2} > N-BK7's {bk7_abbe:.2}, and its F−C spread of D_min {silica:.4}° < N-BK7's {bk7:.4}°"
        ),
    );
    writeln!(
        md,
        "\n*Apex angle {APEX_DEG:.0}°. Numerical: golden-section search of the traced deviation over the \
         incidences that get through; closed form: 2 asin(n sin(A/2)) − A. Incidence is positive \
         away from the apex. Between the limiting incidence and the incidence below which the ray \
         misses the exit face (on the apex side, asin(n sin(A − 90°))), it is totally reflected \
         at the exit face; every ray traced at 0.01° steps from −90° to 90° does as this says.*"
    )?;
    Ok(md.into_bytes())
}

/// Traces rays at 0.01° steps from −90° to 90° through the prism and fails unless each
/// does what the caption says: through above `limiting`, totally reflected at the exit
/// face between `miss` and `limiting`, missing the exit face below `miss` (rays within
/// 0.001° of a threshold are left out: rounding decides them).
fn check_caption(n: f64, apex: f64, limiting: f64, miss: Option<f64>) -> anyhow::Result<()> {
    let lowest = miss.unwrap_or(-FRAC_PI_2);
    let near = |a: f64, b: f64| (a - b).abs() < 1e-3f64.to_radians();
    for k in -9000..=9000 {
        let i = (f64::from(k) * 0.01).to_radians();
        if near(i, limiting) || near(i, lowest) {
            continue;
        }
        let path = disp::prism(n, apex, i);
        let ok = match path {
            PrismPath::Through { .. } => i > limiting,
            PrismPath::TotalInternalReflection {
                face: disp::Face::Exit,
                ..
            } => i < limiting && i > lowest,
            PrismPath::MissesExitFace => miss.is_some_and(|m| i < m),
            PrismPath::TotalInternalReflection { .. } => false,
        };
        if !ok {
            bail!(
                "n = {n}, apex {:.1}°: at incidence {:.2}° the ray is {path:?}, not what the caption of dispersion_prism.md says (limiting incidence {:.2}°, misses below {:?})",
                apex.to_degrees(),
                i.to_degrees(),
                limiting.to_degrees(),
                miss.map(f64::to_degrees)
            );
        }
    }
    Ok(())
}

fn rainbow_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let water = disp::material(WATER);
    let ls = wavelengths(5);
    let bow = vec![Series::line(
        "primary bow, water at 20 °C",
        ls.iter()
            .map(|&l| (l, disp::rainbow_angle(water.index(l)).to_degrees()))
            .collect(),
    )];
    let curves = [400.0, 550.0, 700.0]
        .iter()
        .map(|&l| {
            let n = water.index(l);
            Series::line(
                format!("{l:.0} nm"),
                (0..=90)
                    .map(|k| {
                        let i = f64::from(k).to_radians();
                        (
                            f64::from(k),
                            180.0 - disp::drop_deviation(n, i).to_degrees(),
                        )
                    })
                    .collect(),
            )
        })
        .collect();
    let panels = [
        Panel::new(
            "radius of the primary bow",
            "wavelength (nm)",
            "from the antisolar point (°)",
            bow,
        ),
        Panel::new(
            "180° − D(i): rays pile up at the maximum",
            "angle of incidence on the drop (degrees)",
            "from the antisolar point (°)",
            curves,
        ),
    ];
    let [first, second] = panels;
    let y1 = y_range(&first.series);
    plot::ranged_chart(&[
        (first, RENDER_RANGE_NM, y1, Legend::Below),
        (second, (0.0, 90.0), (0.0, 45.0), Legend::Below),
    ])
}

fn rainbow_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let water = disp::material(WATER);
    let mut md = String::new();
    writeln!(
        md,
        "| wavelength (nm) | n (water, 20 °C) | incidence at minimum, closed form | numerical | bow radius 180° − D_min |"
    )?;
    writeln!(md, "|---:|---:|---:|---:|---:|")?;
    let mut radii = Vec::new();
    for l in [
        380.0, 400.0, 450.0, 500.0, 550.0, 600.0, 650.0, 700.0, 780.0,
    ] {
        let n = water.index(l);
        let i = disp::rainbow_incidence_analytic(n);
        let (i_num, _) = disp::rainbow_minimum_numeric(n);
        let radius = disp::rainbow_angle(n).to_degrees();
        radii.push((l, radius));
        if [400.0, 550.0, 700.0].contains(&l) {
            r.number(&format!("radius_{l:.0}"), radius, ".2");
        }
        writeln!(
            md,
            "| {l:.0} | {n:.5} | {:.4}° | {:.4}° | {radius:.3}° |",
            i.to_degrees(),
            i_num.to_degrees(),
        )?;
    }
    let at = |l: f64| {
        radii
            .iter()
            .find(|&&(w, _)| w == l)
            .map(|&(_, d)| d)
            .with_context(|| format!("no row for {l} nm"))
    };
    r.number("band_400_700", at(700.0)? - at(400.0)?, ".2");
    let red = at(650.0)?;
    r.claim(
        "red_42_3_is_650",
        (red - 42.3).abs() <= 0.05,
        format!("the bow radius at 650 nm, {red:.3}°, within 0.05° of 42.3°"),
    );
    writeln!(
        md,
        "\n*Closed form: cos² i = (n² − 1)/3; numerical: golden-section minimum of D(i) = 180° + 2i − 4r. \
         Water: Daimon & Masumura (2007), 20 °C.*"
    )?;
    Ok(md.into_bytes())
}
