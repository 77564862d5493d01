//! Figures and tables of the chapter *Dispersion*.

use std::fmt::Write as _;

use super::{Output, Settings};
use crate::plot::{BoxError, Panel, Scale, Series};
use raylemma::optics::dispersion::{
    self as disp, FUSED_SILICA, LINE_C_NM, LINE_D_NM, LINE_F_NM, N_BK7, PrismPath, RENDER_RANGE_NM,
    WATER,
};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "dispersion_index.png",
            what: "refractive index against wavelength",
            make: index_png,
        },
        Output {
            file: "dispersion_catalogue.md",
            what: "catalogue checks of the Sellmeier fits",
            make: catalogue_md,
        },
        Output {
            file: "dispersion_prism.png",
            what: "prism deviation against wavelength and incidence",
            make: prism_png,
        },
        Output {
            file: "dispersion_prism.md",
            what: "minimum deviation of 60° prisms",
            make: prism_md,
        },
        Output {
            file: "dispersion_rainbow.png",
            what: "rainbow angle against wavelength",
            make: rainbow_png,
        },
        Output {
            file: "dispersion_rainbow.md",
            what: "primary bow by wavelength",
            make: rainbow_md,
        },
    ]
}

const MATERIALS: [&str; 3] = [N_BK7, FUSED_SILICA, WATER];

use crate::plot::{Legend, ranged_chart_png};

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

fn index_png(_: &Settings) -> Result<Vec<u8>, BoxError> {
    let ls = wavelengths(5);
    let series = MATERIALS
        .iter()
        .map(|&name| {
            let g = disp::material(name);
            Series {
                label: name.into(),
                points: ls.iter().map(|&l| (l, g.index(l))).collect(),
            }
        })
        .collect();
    // The same curves relative to each material's n_d, to compare their dispersion.
    let relative = MATERIALS
        .iter()
        .map(|&name| {
            let g = disp::material(name);
            let nd = g.index(LINE_D_NM);
            Series {
                label: name.into(),
                points: ls.iter().map(|&l| (l, 1e3 * (g.index(l) - nd))).collect(),
            }
        })
        .collect();
    let range = RENDER_RANGE_NM;
    let panels = [
        Panel {
            title: "Sellmeier fits over the render range".into(),
            x_label: "wavelength (nm)".into(),
            y_label: "refractive index n".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series,
        },
        Panel {
            title: "n(λ) − n_d".into(),
            x_label: "wavelength (nm)".into(),
            y_label: "(n − n_d) × 1000".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series: relative,
        },
    ];
    let panels = panels.map(|p| {
        let yr = y_range(&p.series);
        (p, range, yr, Legend::UpperRight)
    });
    ranged_chart_png(&panels, 1200, 480)
}

fn catalogue_md(_: &Settings) -> Result<Vec<u8>, BoxError> {
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
    for (material, quantity, got, published, tol, source) in rows {
        let digits = if quantity == "V_d" { 3 } else { 6 };
        let (p, diff) = match published {
            Some(p) => (format!("{p}"), format!("{:+.1e}", got - p)),
            None => ("—".into(), "—".into()),
        };
        writeln!(
            md,
            "| {material} | {quantity} | {got:.digits$} | {p} | {diff} | {tol} | {source} |"
        )?;
    }
    writeln!(
        md,
        "\n*Lines: d = {LINE_D_NM} nm (He), F = {LINE_F_NM} nm, C = {LINE_C_NM} nm (H). \
         Tolerances are half a unit of the last printed digit; asserted by `tests/book/optics/dispersion.rs`. \
         Generated by `cargo run --release` (`tools/figures/src/dispersion.rs`).*"
    )?;
    Ok(md.into_bytes())
}

const APEX_DEG: f64 = 60.0;

fn prism_png(_: &Settings) -> Result<Vec<u8>, BoxError> {
    let apex = APEX_DEG.to_radians();
    let ls = wavelengths(5);
    let mut by_wavelength = Vec::new();
    for name in [N_BK7, FUSED_SILICA] {
        let g = disp::material(name);
        let (i0, _) = disp::minimum_deviation_numeric(g.index(LINE_D_NM), apex)
            .ok_or("no ray through the prism")?;
        by_wavelength.push(Series {
            label: format!("{name}, incidence {:.2}°", i0.to_degrees()),
            points: ls
                .iter()
                .filter_map(|&l| {
                    disp::prism(g.index(l), apex, i0)
                        .deviation()
                        .map(|dev| (l, dev.to_degrees()))
                })
                .collect(),
        });
    }
    let g = disp::material(N_BK7);
    let by_incidence = [400.0, 550.0, 700.0]
        .iter()
        .map(|&l| {
            let n = g.index(l);
            Series {
                label: format!("N-BK7, {l:.0} nm"),
                points: (0..=180)
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
            }
        })
        .collect();
    let panels = [
        Panel {
            title: format!("{APEX_DEG:.0}° prism at the d line's minimum-deviation incidence"),
            x_label: "wavelength (nm)".into(),
            y_label: "deviation (degrees)".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series: by_wavelength,
        },
        Panel {
            title: "deviation against incidence (missing: total internal reflection)".into(),
            x_label: "angle of incidence (degrees)".into(),
            y_label: "deviation (degrees)".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series: by_incidence,
        },
    ];
    let [first, second] = panels;
    let (y1, y2) = (y_range(&first.series), y_range(&second.series));
    ranged_chart_png(
        &[
            (first, RENDER_RANGE_NM, y1, Legend::UpperRight),
            (second, (0.0, 90.0), y2, Legend::UpperRight),
        ],
        1200,
        480,
    )
}

fn prism_md(_: &Settings) -> Result<Vec<u8>, BoxError> {
    let apex = APEX_DEG.to_radians();
    let mut md = String::new();
    writeln!(
        md,
        "| material | line | n | incidence at minimum (numerical) | D_min numerical | D_min closed form | n recovered from D_min | limiting incidence |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|")?;
    for name in [N_BK7, FUSED_SILICA] {
        let g = disp::material(name);
        for (line, l) in [("F", LINE_F_NM), ("d", LINE_D_NM), ("C", LINE_C_NM)] {
            let n = g.index(l);
            let (i, dn) = disp::minimum_deviation_numeric(n, apex).ok_or("no ray through")?;
            let de = disp::minimum_deviation_analytic(n, apex).ok_or("no ray through")?;
            let back = disp::index_from_minimum_deviation(apex, de);
            let lim = disp::prism_limiting_incidence(n, apex).ok_or("no ray through")?;
            writeln!(
                md,
                "| {name} | {line} | {n:.5} | {:.4}° | {:.6}° | {:.6}° | {back:.5} | {:.2}° |",
                i.to_degrees(),
                dn.to_degrees(),
                de.to_degrees(),
                lim.to_degrees()
            )?;
        }
    }
    writeln!(
        md,
        "\n*Apex angle {APEX_DEG:.0}°. Numerical: golden-section search of the traced deviation over the \
         incidences that get through; closed form: 2 asin(n sin(A/2)) − A. Below the limiting \
         incidence the ray is totally reflected at the second face.*"
    )?;
    Ok(md.into_bytes())
}

fn rainbow_png(_: &Settings) -> Result<Vec<u8>, BoxError> {
    let water = disp::material(WATER);
    let ls = wavelengths(5);
    let bow = vec![Series {
        label: "primary bow, water at 20 °C".into(),
        points: ls
            .iter()
            .map(|&l| (l, disp::rainbow_angle(water.index(l)).to_degrees()))
            .collect(),
    }];
    let curves = [400.0, 550.0, 700.0]
        .iter()
        .map(|&l| {
            let n = water.index(l);
            Series {
                label: format!("{l:.0} nm"),
                points: (0..=90)
                    .map(|k| {
                        let i = f64::from(k).to_radians();
                        (
                            f64::from(k),
                            180.0 - disp::drop_deviation(n, i).to_degrees(),
                        )
                    })
                    .collect(),
            }
        })
        .collect();
    let panels = [
        Panel {
            title: "radius of the primary bow".into(),
            x_label: "wavelength (nm)".into(),
            y_label: "angle from the antisolar point (degrees)".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series: bow,
        },
        Panel {
            title: "180° − D(i): rays pile up at the maximum".into(),
            x_label: "angle of incidence on the drop (degrees)".into(),
            y_label: "angle from the antisolar point (degrees)".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series: curves,
        },
    ];
    let [first, second] = panels;
    let y1 = y_range(&first.series);
    ranged_chart_png(
        &[
            (first, RENDER_RANGE_NM, y1, Legend::LowerRight),
            (second, (0.0, 90.0), (0.0, 45.0), Legend::UpperRight),
        ],
        1200,
        480,
    )
}

fn rainbow_md(_: &Settings) -> Result<Vec<u8>, BoxError> {
    let water = disp::material(WATER);
    let mut md = String::new();
    writeln!(
        md,
        "| wavelength (nm) | n (water, 20 °C) | incidence at minimum, closed form | numerical | bow radius 180° − D_min |"
    )?;
    writeln!(md, "|---:|---:|---:|---:|---:|")?;
    for l in [
        380.0, 400.0, 450.0, 500.0, 550.0, 600.0, 650.0, 700.0, 780.0,
    ] {
        let n = water.index(l);
        let i = disp::rainbow_incidence_analytic(n);
        let (i_num, _) = disp::rainbow_minimum_numeric(n);
        writeln!(
            md,
            "| {l:.0} | {n:.5} | {:.4}° | {:.4}° | {:.3}° |",
            i.to_degrees(),
            i_num.to_degrees(),
            disp::rainbow_angle(n).to_degrees()
        )?;
    }
    writeln!(
        md,
        "\n*Closed form: cos² i = (n² − 1)/3; numerical: golden-section minimum of D(i) = 180° + 2i − 4r. \
         Water: Daimon & Masumura (2007), 20 °C.*"
    )?;
    Ok(md.into_bytes())
}
