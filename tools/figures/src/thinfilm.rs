//! Figures and tables of the chapter *Thin-film interference*.

use std::fmt::Write as _;

use num_complex::Complex64;
use plotters::prelude::*;

use super::{Output, Record, Settings};
use crate::plot::Legend;
use crate::plot::{self, Panel, Series};
use raylemma::optics::thinfilm::{
    Film, airy_r, cos_theta, film_colour, interface, phase, quarter_wave_reflectance,
    seed_reflectance,
};
use raylemma::spectral::display;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "thinfilm_spectra.svg",
            what: "reflectance against wavelength",
            make: spectra_svg,
        },
        Output {
            file: "thinfilm_map.png",
            what: "reflectance against wavelength and thickness",
            make: map_png,
        },
        Output {
            file: "thinfilm_colours.png",
            what: "colours of a soap film and of oil on water against thickness",
            make: colours_png,
        },
        Output {
            file: "thinfilm_angle.svg",
            what: "s, p and unpolarised reflectance against angle",
            make: angle_svg,
        },
        Output {
            file: "thinfilm_seed.md",
            what: "the seed's formula against the Airy sum",
            make: seed_md,
        },
        Output {
            file: "thinfilm_precision.md",
            what: "the plain Airy sum near the film's critical angle",
            make: precision_md,
        },
    ]
}

/// Soap film: water-like index in air.
const SOAP: (f64, f64, f64) = (1.0, 1.33, 1.0);
/// Oil on water, seen from the air.
const OIL: (f64, f64, f64) = (1.0, 1.5, 1.33);

fn film(n: (f64, f64, f64), d: f64) -> Film {
    Film::new(n.0, n.1, n.2, d)
}

fn spectra_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let thicknesses = [100.0, 250.0, 400.0, 800.0];
    let panel = |title: &str, n: (f64, f64, f64)| {
        Panel::new(
            title,
            "wavelength (nm)",
            "reflectance (normal incidence)",
            thicknesses
                .iter()
                .map(|&d| {
                    Series::line(
                        format!("d = {d:.0} nm"),
                        (380..=780)
                            .step_by(4)
                            .map(|l| {
                                let l = f64::from(l);
                                (l, film(n, d).reflectance(l, 0.0))
                            })
                            .collect(),
                    )
                })
                .collect(),
        )
    };
    let panels = [
        (
            panel("soap film (n = 1.33) in air", SOAP),
            (380.0, 780.0),
            (0.0, 0.1),
            Legend::UpperLeft,
        ),
        (
            panel("oil (n = 1.5) on water (n = 1.33)", OIL),
            (380.0, 780.0),
            (0.0, 0.1),
            Legend::UpperLeft,
        ),
    ];
    plot::ranged_chart(&panels)
}

/// Viridis, by linear interpolation between five of its colours; `t` in `[0, 1]`.
fn viridis(t: f64) -> RGBColor {
    const STOPS: [(u8, u8, u8); 5] = [
        (68, 1, 84),
        (59, 82, 139),
        (33, 145, 140),
        (94, 201, 98),
        (253, 231, 37),
    ];
    let x = t.clamp(0.0, 1.0) * 4.0;
    let k = (x.floor() as usize).min(3);
    let f = x - k as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    let (a, b) = (STOPS[k], STOPS[k + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Reflectance maps against wavelength (380–780 nm) and thickness (0–1000 nm), at normal
/// incidence, for the soap film and for oil on water, with a common colour bar.
fn map_png(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (dl, dd) = if settings.quick {
        (4.0, 10.0)
    } else {
        (2.0, 4.0)
    };
    let r_max = 0.08;
    let (width, height) = (1300u32, 520u32);
    plot::draw_png(width, height, |root| {
        let (maps, bar) = root.split_horizontally(width - 130);
        let areas = maps.split_evenly((1, 2));
        for (area, (title, n)) in areas.iter().zip([
            ("soap film (n = 1.33) in air", SOAP),
            ("oil (n = 1.5) on water (n = 1.33)", OIL),
        ]) {
            let mut chart = ChartBuilder::on(area)
                .caption(title, ("sans-serif", 18))
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(70)
                .build_cartesian_2d(380f64..780f64, 0f64..1000f64)?;
            chart
                .configure_mesh()
                .disable_mesh()
                .x_desc("wavelength (nm)")
                .y_desc("thickness (nm)")
                .x_label_formatter(&|v| plot::format_tick(*v))
                .y_label_formatter(&|v| plot::format_tick(*v))
                .label_style(("sans-serif", 13))
                .axis_desc_style(("sans-serif", 15))
                .draw()?;
            let nl = (400.0 / dl) as usize;
            let nd = (1000.0 / dd) as usize;
            let cells = (0..nl).flat_map(|i| (0..nd).map(move |j| (i, j)));
            chart.draw_series(cells.map(|(i, j)| {
                let l0 = 380.0 + dl * i as f64;
                let d0 = dd * j as f64;
                let r = film(n, d0 + 0.5 * dd).reflectance(l0 + 0.5 * dl, 0.0);
                Rectangle::new([(l0, d0), (l0 + dl, d0 + dd)], viridis(r / r_max).filled())
            }))?;
        }
        let mut chart = ChartBuilder::on(&bar)
            .caption("R", ("sans-serif", 18))
            .margin(12)
            .margin_left(4)
            .x_label_area_size(40)
            .y_label_area_size(55)
            .build_cartesian_2d(0f64..1f64, 0f64..r_max)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .label_style(("sans-serif", 13))
            .y_label_formatter(&|v| plot::format_tick(*v))
            .draw()?;
        let steps = 200;
        chart.draw_series((0..steps).map(|k| {
            let (a, b) = (
                r_max * f64::from(k) / f64::from(steps),
                r_max * f64::from(k + 1) / f64::from(steps),
            );
            Rectangle::new([(0.0, a), (1.0, b)], viridis(a / r_max).filled())
        }))?;
        Ok(())
    })
}

fn angle_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let angles: Vec<f64> = (0..=180).map(|k| f64::from(k) * 0.5).collect();
    let panel = |title: String, f: Film| {
        let curve = |label: &str, pick: &dyn Fn(f64) -> f64| {
            Series::line(
                label,
                angles.iter().map(|&a| (a, pick(a.to_radians()))).collect(),
            )
        };
        Panel::new(
            title,
            "angle of incidence (degrees)",
            "reflectance at 550 nm",
            vec![
                curve("s", &|t| f.response(550.0, t).reflectance_s),
                curve("p", &|t| f.response(550.0, t).reflectance_p),
                curve("unpolarised", &|t| f.reflectance(550.0, t)),
                curve("seed's formula (NaN: not drawn; clipped at 1.05)", &|t| {
                    let r = seed_reflectance(&f, 550.0, t);
                    if r.is_nan() { r } else { r.min(1.05) }
                }),
            ],
        )
    };
    let panels = [
        (
            panel("soap film, 300 nm, in air".into(), film(SOAP, 300.0)),
            (0.0, 90.0),
            (0.0, 1.06),
            Legend::UpperLeft,
        ),
        (
            panel(
                "from glass (1.52) through MgF2 (1.38, 100 nm) into air".into(),
                Film::new(1.52, 1.38, 1.0, 100.0),
            ),
            (0.0, 90.0),
            (0.0, 1.06),
            Legend::LowerRight,
        ),
    ];
    plot::ranged_chart(&panels)
}

fn seed_md(_: &Settings, rec: &mut Record) -> anyhow::Result<Vec<u8>> {
    let quarter = film(SOAP, 550.0 / (4.0 * SOAP.1));
    let soap300 = film(SOAP, 300.0);
    let tir = Film::new(1.52, 1.38, 1.0, 100.0);
    let fmt = |x: f64| {
        if x.is_nan() {
            "NaN".to_string()
        } else {
            format!("{x:.4}")
        }
    };
    let mut md = String::new();
    writeln!(
        md,
        "| film, 550 nm | angle | seed's R | R_s | R_p | R (unpolarised) | T (unpolarised) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|---:|")?;
    // Per row: (seed's R, R_s, R_p, R, T).
    let mut got = Vec::new();
    for (name, f, deg) in [
        ("quarter-wave soap film (103.4 nm)", quarter, 0.0),
        ("quarter-wave soap film (103.4 nm)", quarter, 60.0),
        ("quarter-wave soap film (103.4 nm)", quarter, 89.0),
        ("soap film, 300 nm", soap300, 60.0),
        ("glass │ MgF2 100 nm │ air", tir, 30.0),
        ("glass │ MgF2 100 nm │ air", tir, 60.0),
    ] {
        let t = f64::to_radians(deg);
        let r = f.response(550.0, t);
        got.push((
            seed_reflectance(&f, 550.0, t),
            r.reflectance_s,
            r.reflectance_p,
            r.reflectance(),
            r.transmittance(),
        ));
        writeln!(
            md,
            "| {name} | {deg:.0}° | {} | {} | {} | {} | {} |",
            fmt(seed_reflectance(&f, 550.0, t)),
            fmt(r.reflectance_s),
            fmt(r.reflectance_p),
            fmt(r.reflectance()),
            fmt(r.transmittance())
        )?;
    }
    let quarter_max = quarter_wave_reflectance(SOAP.0, SOAP.1, SOAP.2);
    let (normal, grazing, soap) = (got[0], got[2], got[3]);
    rec.number("seed_r_normal", normal.0, ".4");
    rec.number("quarter_wave_r", normal.3, ".4");
    rec.number("seed_r_plus_t_normal", normal.0 + normal.4, ".4");
    rec.number("seed_r_89", grazing.0, ".2");
    rec.number("soap300_60_r_s", soap.1, ".4");
    rec.number("soap300_60_r_p", soap.2, ".4");
    rec.number("soap300_60_r", soap.3, ".4");
    rec.claim(
        "seed_above_quarter_wave",
        normal.0 > normal.3 && normal.0 > quarter_max && normal.0 + normal.4 > 1.0,
        format!(
            "quarter-wave soap film at 0°: the seed's R {:.5} > R {:.5} (the quarter-wave maximum {quarter_max:.5}), and the seed's R + T = {:.5} > 1",
            normal.0,
            normal.3,
            normal.0 + normal.4
        ),
    );
    rec.claim(
        "seed_above_one_at_89",
        grazing.0 > 1.0,
        format!(
            "quarter-wave soap film at 89°: the seed's R {:.4} > 1",
            grazing.0
        ),
    );
    rec.claim(
        "s_only_almost_twice",
        soap.2 < 0.1 * soap.1 && (1.8..2.0).contains(&(soap.1 / soap.3)),
        format!(
            "soap film, 300 nm, 60°: R_p {:.5} < 0.1 x R_s {:.5}, and R_s / R = {:.4} in [1.8, 2)",
            soap.2,
            soap.1,
            soap.1 / soap.3
        ),
    );
    writeln!(
        md,
        "\n*The seed's formula: s-polarised coefficients, real cosines, and −2 r12 r23 cos φ in the \
         denominator. The other columns: the library (`Film::response`), checked against a transfer \
         matrix in `tests/book/optics/thinfilm.rs`. Quarter-wave maximum for the soap film: {quarter_max:.4}.*"
    )?;
    Ok(md.into_bytes())
}

/// The plain Airy sum, assembled from the library's pieces, unpolarised.
fn plain_airy(f: &Film, wavelength_nm: f64, theta1: f64) -> f64 {
    let cos1 = theta1.cos();
    let c1 = Complex64::new(cos1, 0.0);
    let (c2, c3) = (cos_theta(f.n1, cos1, f.n2), cos_theta(f.n1, cos1, f.n3));
    let (i12, i23) = (interface(f.n1, c1, f.n2, c2), interface(f.n2, c2, f.n3, c3));
    let delta = phase(f.n2, f.thickness_nm, c2, wavelength_nm);
    0.5 * (airy_r(i12.r_s, i23.r_s, delta).norm_sqr() + airy_r(i12.r_p, i23.r_p, delta).norm_sqr())
}

fn precision_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (n1, n2, n3) = (2.4, 1.2, 2.0);
    let mut md = String::new();
    writeln!(
        md,
        "| cos θ2 | d (nm) | R, rearranged sum | plain sum − rearranged | ε / cos θ2 |"
    )?;
    writeln!(md, "|---:|---:|---:|---:|---:|")?;
    // (nominal cos θ2, cos θ2, |plain − rearranged| of each thickness), from the least
    // grazing row down.
    let mut rows: Vec<(f64, f64, Vec<f64>)> = Vec::new();
    for c2 in [1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8] {
        // n1 sin θ1 = n2 sqrt(1 − c2²).
        let t = (n2 * (1.0f64 - c2 * c2).sqrt() / n1).asin();
        let c2_actual = cos_theta(n1, t.cos(), n2).re;
        let mut errors = Vec::new();
        for d in [0.0, 100.0] {
            let f = Film::new(n1, n2, n3, d);
            let stable = f.reflectance(550.0, t);
            let plain = plain_airy(&f, 550.0, t);
            errors.push((plain - stable).abs());
            writeln!(
                md,
                "| {c2_actual:.1e} | {d:.0} | {stable:.6} | {:+.1e} | {:.1e} |",
                plain - stable,
                f64::EPSILON / c2_actual
            )?;
        }
        rows.push((c2, c2_actual, errors));
    }
    // The error grows like ε / cos θ2: it stays below it on every row, and once
    // cos θ2 <= 1e-4 it is at least 1e-3 of it on every row (so that neither a constant
    // error nor one growing like ε / sqrt(cos θ2) would pass); and the least-squares slope
    // of log(worst error of a row) against log(cos θ2), over cos θ2 <= 1e-2, lies in
    // (−1.3, −0.7).
    let bound = |c2: f64| f64::EPSILON / c2;
    let ratio = |c2: f64, e: f64| e / bound(c2);
    let below = rows
        .iter()
        .all(|(_, c2, e)| e.iter().all(|&x| ratio(*c2, x) <= 1.0));
    let above = rows
        .iter()
        .filter(|(nominal, _, _)| *nominal <= 1e-4)
        .all(|(_, c2, e)| e.iter().all(|&x| ratio(*c2, x) >= 1e-3));
    let points: Vec<(f64, f64)> = rows
        .iter()
        .filter(|(nominal, _, _)| *nominal <= 1e-2)
        .map(|(_, c2, e)| (c2.log10(), e.iter().copied().fold(0.0, f64::max).log10()))
        .collect();
    let slope = least_squares_slope(&points);
    r.number("plain_error_slope", slope, ".2");
    let ratios: Vec<String> = rows
        .iter()
        .map(|(_, c2, e)| {
            let list: Vec<String> = e.iter().map(|&x| format!("{:.4}", ratio(*c2, x))).collect();
            format!("{c2:.1e}: {}", list.join(", "))
        })
        .collect();
    r.claim(
        "plain_error_grows_like_eps_over_cos",
        below && above && slope > -1.3 && slope < -0.7,
        format!(
            "|plain − rearranged| / (ε / cos θ2) by row ({}): each <= 1, and >= 1e-3 where \
             cos θ2 <= 1e-4; slope of log worst error against log cos θ2 over cos θ2 <= 1e-2: \
             {slope:.3}, in (−1.3, −0.7)",
            ratios.join("; ")
        ),
    );
    writeln!(
        md,
        "\n*Glass of n1 = {n1} under a film of n2 = {n2} on a substrate of n3 = {n3}, at 550 nm, at \
         angles approaching the film's critical angle (30°). The rearranged sum agrees with the \
         transfer matrix to 1e-12 (`tests/book/optics/thinfilm.rs`).*"
    )?;
    Ok(md.into_bytes())
}

/// The least-squares slope of `y` against `x` over `points`.
fn least_squares_slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (mx, my) = (
        points.iter().map(|p| p.0).sum::<f64>() / n,
        points.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = points.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    sxy / sxx
}

/// Colour strips against thickness, one per film, each scaled so that its brightest
/// thickness has `Y = 0.9`, brought into gamut and encoded by the display chapter's rules.
fn colours_png(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let step = if settings.quick { 10.0 } else { 2.0 };
    let max_d = 1500.0;
    let films = [
        ("soap film in air (n = 1.33), reflected daylight", SOAP),
        ("oil (n = 1.5) on water, reflected daylight", OIL),
    ];
    let (width, height) = (1200u32, 360u32);
    plot::draw_png(width, height, |root| {
        let areas = root.split_evenly((films.len(), 1));
        for ((title, n), area) in films.iter().zip(areas.iter()) {
            let columns: Vec<(f64, glam::DVec3)> = (0..)
                .map(|i| f64::from(i) * step)
                .take_while(|&d| d <= max_d)
                .map(|d| (d, film_colour(&film(*n, d))))
                .collect();
            let brightest = columns
                .iter()
                .map(|(_, c)| display::luminance(*c))
                .fold(0.0, f64::max);
            let scale = if brightest > 0.0 {
                0.9 / brightest
            } else {
                1.0
            };
            let mut chart = ChartBuilder::on(area)
                .caption(*title, ("sans-serif", 18))
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(20)
                .build_cartesian_2d(0.0..max_d, 0.0..1.0)?;
            chart
                .configure_mesh()
                .disable_mesh()
                .y_labels(0)
                .x_desc("film thickness (nm)")
                .label_style(("sans-serif", 13))
                .axis_desc_style(("sans-serif", 15))
                .x_label_formatter(&|v| plot::format_linear_tick(*v))
                .draw()?;
            chart.draw_series(columns.iter().map(|(d, c)| {
                let rgb = display::fit_to_gamut(*c * scale);
                let colour = RGBColor(
                    display::srgb8(rgb.x),
                    display::srgb8(rgb.y),
                    display::srgb8(rgb.z),
                );
                Rectangle::new([(*d, 0.0), (*d + step, 1.0)], colour.filled())
            }))?;
        }
        Ok(())
    })
}
