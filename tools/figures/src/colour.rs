//! Figures and tables of the chapter *Spectra and CIE colour*
//! (`chapters/spectral/colour.md`).

use std::fmt::Write as _;
use std::hint::black_box;

use glam::{DVec2, DVec3};
use plotters::prelude::*;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, PALETTE, Panel, Series};
use raylemma::spectral::cie::{
    self, chromaticity, cmf, cmf_fit, krystek, xyz, xyz_to_linear_srgb, xyz_with,
};
use raylemma::spectral::spectrum::{self, planck};
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "colour_chromaticity.svg",
            what: "CIE 1931 chromaticity diagram: locus, sRGB, Planckian locus, illuminants",
            make: chromaticity_svg,
        },
        Output {
            file: "colour_illuminants.md",
            what: "illuminant chromaticities: published, CIE sum, quadrature, fit; linear sRGB",
            make: illuminants_md,
        },
        Output {
            file: "colour_fit.svg",
            what: "colour-matching functions: table against the Wyman-Sloan-Shirley fit",
            make: fit_svg,
        },
        Output {
            file: "colour_fit.md",
            what: "error of the Wyman-Sloan-Shirley fit",
            make: fit_md,
        },
        Output {
            file: "colour_speed.md",
            what: "colour matching by table against by fit: ns per evaluation",
            make: speed_md,
        },
        Output {
            file: "colour_planck.md",
            what: "Planckian locus against Krystek's approximation; illuminant A's temperature",
            make: planck_md,
        },
    ]
}

/// The illuminants of `data/` with their published chromaticities (CIE 015:2018, 2°) and
/// the number of decimals they are printed to: `(name, file, x, y, decimals)`. The same
/// values are asserted in `tests/book/spectral/colour.rs`.
pub const ILLUMINANTS: [(&str, &str, f64, f64, i32); 6] = [
    ("A", "cie_illuminant_A.csv", 0.44758, 0.40745, 5),
    ("D65", "cie_illuminant_D65.csv", 0.31272, 0.32903, 5),
    ("FL2", "cie_illuminant_F2.csv", 0.3721, 0.3751, 4),
    ("FL11", "cie_illuminant_F11.csv", 0.3805, 0.3769, 4),
    (
        "HP1",
        "cie_illuminant_HP1_high_pressure_sodium.csv",
        0.5330,
        0.4150,
        4,
    ),
    ("LED-B3", "cie_illuminant_LED_B3.csv", 0.3756, 0.3723, 4),
];

/// The CIE's rule (CIE 015:2018 §7.1): the sum over the 5 nm samples in 380-780 nm, the
/// range of the published chromaticities, of S x̄ȳz̄ (unnormalised).
fn cie_sum(t: &spectrum::Table) -> DVec3 {
    t.wavelengths()
        .iter()
        .zip(t.values())
        .filter(|(nm, _)| (380.0..=780.0).contains(*nm))
        .map(|(&nm, &v)| v * cmf(nm))
        .sum()
}

fn xy_of(c: DVec3) -> DVec2 {
    chromaticity(c).unwrap_or(DVec2::NAN)
}

fn planck_xy(kelvin: f64) -> DVec2 {
    xy_of(xyz(|nm| planck(nm, kelvin)))
}

fn chromaticity_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let small = || plot::font(plot::TICK_PX);
    plot::svg(plot::WIDTH, 800, |root, _| {
        let rest = plot::draw_title(
            root,
            "CIE 1931 chromaticity: spectral locus, sRGB, Planckian locus",
        )?;
        let mut chart = plot::builder(&rest).build_cartesian_2d(0.0..0.8, 0.0..0.9)?;
        plot::mesh!(chart, "x", "y", &|v| plot::format_linear_tick(*v), &|v| {
            plot::format_linear_tick(*v)
        });
        // The spectral locus, 380-700 nm (beyond 700 nm it stays at the red end), closed by
        // the line of purples.
        let mut locus: Vec<(f64, f64)> = (380..=700)
            .map(|nm| xy_of(cmf(f64::from(nm))))
            .map(|p| (p.x, p.y))
            .collect();
        locus.push(locus[0]);
        chart
            .draw_series(LineSeries::new(locus, BLACK.stroke_width(2)))?
            .label("spectral locus (monochromatic light, nm)")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
        for nm in [460, 480, 500, 520, 540, 560, 580, 600, 620, 700] {
            let p = xy_of(cmf(f64::from(nm)));
            chart.draw_series(std::iter::once(Circle::new((p.x, p.y), 3, BLACK.filled())))?;
            let offset = if p.x < 0.2 { (-38, -6) } else { (6, -6) };
            chart.draw_series(std::iter::once(
                EmptyElement::at((p.x, p.y)) + Text::new(format!("{nm}"), offset, small()),
            ))?;
        }
        // The sRGB gamut.
        let mut tri: Vec<(f64, f64)> = cie::SRGB_PRIMARIES.iter().map(|p| (p.x, p.y)).collect();
        tri.push(tri[0]);
        let blue = PALETTE[0];
        chart
            .draw_series(LineSeries::new(tri, blue.stroke_width(2)))?
            .label("sRGB primaries (IEC 61966-2-1)")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], blue.stroke_width(2))
            });
        // The Planckian locus, 1000-20000 K.
        let orange = PALETTE[1];
        let temps: Vec<f64> = (0..=60)
            .map(|i| 1000.0 * 20f64.powf(f64::from(i) / 60.0))
            .collect();
        let planckian: Vec<(f64, f64)> = temps
            .iter()
            .map(|&t| planck_xy(t))
            .map(|p| (p.x, p.y))
            .collect();
        chart
            .draw_series(LineSeries::new(planckian, orange.stroke_width(2)))?
            .label("Planckian locus, 1000-20000 K")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], orange.stroke_width(2))
            });
        for t in [1000.0, 2000.0, 10000.0] {
            let p = planck_xy(t);
            chart.draw_series(std::iter::once(
                EmptyElement::at((p.x, p.y))
                    + Circle::new((0, 0), 3, orange.filled())
                    + Text::new(format!("{t} K"), (4, 6), small()),
            ))?;
        }
        // The illuminants, computed from their spectra.
        let green = PALETTE[2];
        for (k, (name, file, ..)) in ILLUMINANTS.iter().enumerate() {
            let t = spectrum::builtin(file);
            let p = xy_of(xyz(|nm| t.eval(nm)));
            // Label offsets (pixels) that keep the close ones (FL2, FL11, LED-B3) apart.
            let offset = [(6, -16), (6, 4), (-34, -20), (10, -16), (8, -18), (-52, 4)][k];
            let series = chart.draw_series(std::iter::once(
                EmptyElement::at((p.x, p.y))
                    + Cross::new((0, 0), 5, green.stroke_width(2))
                    + Text::new((*name).to_string(), offset, small()),
            ))?;
            if k == 0 {
                series
                    .label("CIE illuminants (from their spectra)")
                    .legend(move |(x, y)| Cross::new((x + 10, y), 5, green.stroke_width(2)));
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK.mix(0.4))
            .label_font(small())
            .position(SeriesLabelPosition::UpperRight)
            .draw()?;
        Ok(())
    })
}

/// An illuminant's name as a value name: `LED-B3` -> `led_b3`.
fn illuminant_key(name: &str) -> String {
    name.to_lowercase().replace('-', "_")
}

/// The largest and smallest of `xs`.
fn extremes(xs: impl IntoIterator<Item = f64>) -> (f64, f64) {
    xs.into_iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), e| {
            (lo.min(e), hi.max(e))
        })
}

/// One row of the illuminant table: the errors, as the larger of |Δx| and |Δy|.
struct IlluminantRow {
    name: &'static str,
    /// Half a unit of the published value's last printed digit.
    half_unit: f64,
    /// The CIE's 5 nm sum against the published value.
    sum: f64,
    /// The renderer's exact integral against the published value.
    quad: f64,
    /// The renderer's reading against the CIE's sum of the same samples.
    readings: f64,
    /// The fit against the published value.
    fit: f64,
}

fn illuminants_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::new();
    writeln!(
        md,
        "| illuminant | published (x, y) | CIE 5 nm sum | CIE sum error | renderer (exact integral) | error | renderer − CIE sum | by the fit | error | linear sRGB at Y = 1 |"
    )?;
    writeln!(md, "|---|---|---|---:|---|---:|---:|---|---:|---|")?;
    let mut rows = Vec::new();
    for (name, file, x, y, decimals) in ILLUMINANTS {
        let key = illuminant_key(name);
        let t = spectrum::builtin(file);
        let published = DVec2::new(x, y);
        let sum = xy_of(cie_sum(&t));
        let exact = xyz(|nm| t.eval(nm));
        let quad = xy_of(exact);
        let fit = xy_of(xyz_with(cmf_fit, |nm| t.eval(nm)));
        let rgb = xyz_to_linear_srgb(exact / exact.y);
        let apart = |p: DVec2, q: DVec2| (p - q).abs().max_element();
        let row = IlluminantRow {
            name,
            half_unit: 0.5 * 10f64.powi(-decimals),
            sum: apart(sum, published),
            quad: apart(quad, published),
            readings: apart(quad, sum),
            fit: apart(fit, published),
        };
        r.number(&format!("{key}.fit_error"), row.fit, "x1");
        writeln!(
            md,
            "| {name} | ({x}, {y}) | ({:.5}, {:.5}) | {:.2e} | ({:.5}, {:.5}) | {:.1e} | {:.1e} | ({:.5}, {:.5}) | {:.1e} | ({:.4}, {:.4}, {:.4}) |",
            sum.x,
            sum.y,
            row.sum,
            quad.x,
            quad.y,
            row.quad,
            row.readings,
            fit.x,
            fit.y,
            row.fit,
            rgb.x,
            rgb.y,
            rgb.z
        )?;
        rows.push(row);
    }
    let smooth = |row: &&IlluminantRow| ["A", "D65"].contains(&row.name);
    let lines = |row: &&IlluminantRow| ["FL2", "FL11", "HP1", "LED-B3"].contains(&row.name);
    let reddish = |row: &&IlluminantRow| ["A", "HP1"].contains(&row.name);
    let show = |rows: &mut dyn Iterator<Item = &IlluminantRow>, f: fn(&IlluminantRow) -> f64| {
        rows.map(|row| format!("{} {:.2e}", row.name, f(row)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    // The CIE's rule reproduces every published value to its last printed digit.
    r.claim(
        "cie_sum_to_last_digit",
        rows.len() == ILLUMINANTS.len() && rows.iter().all(|row| row.sum <= row.half_unit),
        format!(
            "CIE 5 nm sum against the published value, each at most half a unit of its last digit (5e-6 for A and D65, 5e-5 for the others): {}",
            show(&mut rows.iter(), |row| row.sum)
        ),
    );
    // The two readings of the same samples: a few units of the fifth decimal for the
    // smooth spectra, the fourth decimal for the line spectra.
    let (_, smooth_max) = extremes(rows.iter().filter(smooth).map(|row| row.readings));
    r.number("smooth_readings_apart.max", smooth_max, "x1");
    r.claim(
        "smooth_fifth_decimal",
        rows.iter().filter(smooth).count() == 2
            && rows.iter().filter(smooth).all(|row| row.readings < 5e-5),
        format!(
            "renderer − CIE sum, each < 5e-5: {}",
            show(&mut rows.iter().filter(smooth), |row| row.readings)
        ),
    );
    let (lines_min, lines_max) = extremes(rows.iter().filter(lines).map(|row| row.readings));
    r.number("line_readings_apart.min", lines_min, "x1");
    r.number("line_readings_apart.max", lines_max, "x1");
    r.claim(
        "lines_fourth_decimal",
        rows.iter().filter(lines).count() == 4
            && rows
                .iter()
                .filter(lines)
                .all(|row| (1e-4..1e-3).contains(&row.readings)),
        format!(
            "renderer − CIE sum, each in [1e-4, 1e-3): {}",
            show(&mut rows.iter().filter(lines), |row| row.readings)
        ),
    );
    // The renderer's rule within the tolerances of its test: 3e-5 for A and D65 (printed
    // to five decimals), 3e-4 for the others.
    r.claim(
        "quadrature_within_test_tolerances",
        rows.iter().all(|row| {
            row.quad
                <= if row.half_unit < 1e-5 {
                    3e-5
                } else {
                    3e-4
                }
        }),
        format!(
            "renderer against the published value, <= 3e-5 for A and D65 and <= 3e-4 for the others: {}",
            show(&mut rows.iter(), |row| row.quad)
        ),
    );
    // The fit's error on the illuminants that are not reddish (A and HP1 are).
    let (lo, hi) = extremes(rows.iter().filter(|row| !reddish(row)).map(|row| row.fit));
    r.number("fit_error_others.min", lo, "x1");
    r.number("fit_error_others.max", hi, "x1");
    let (reddish_min, _) = extremes(rows.iter().filter(reddish).map(|row| row.fit));
    r.claim(
        "fit_worst_for_reddish",
        rows.iter().filter(reddish).count() == 2 && reddish_min > hi,
        format!(
            "the fit's error, smaller of A and HP1 {reddish_min:.2e} > largest of the others {hi:.2e}"
        ),
    );
    let fit_not_worse: Vec<String> = rows
        .iter()
        .filter(|row| row.quad >= row.fit)
        .map(|row| {
            format!(
                "{}: table {:.2e} >= fit {:.2e}",
                row.name, row.quad, row.fit
            )
        })
        .collect();
    r.claim(
        "table_closer_than_fit_every_illuminant",
        fit_not_worse.is_empty(),
        if fit_not_worse.is_empty() {
            "the table's error is below the fit's for every illuminant".to_string()
        } else {
            fit_not_worse.join("; ")
        },
    );
    writeln!(
        md,
        "\n*Published: CIE 015:2018 (A and D65 to five decimals, the others to four). CIE 5 nm \
         sum: the CIE's rule, Σ S(λ) x̄ȳz̄(λ) over the 5 nm samples from 380 to 780 nm. \
         Renderer: the exact integral of the piecewise-linear spectrum against the 1 nm table \
         over 360–830 nm (`cie::xyz`). Fit: the same integral with the Wyman-Sloan-Shirley \
         functions (`cie::xyz_with(cmf_fit, ..)`). Errors are the larger of |Δx| and |Δy| \
         against the published value; \"renderer − CIE sum\" is the same between the two \
         readings of the samples. Generated by `cargo run --release -- figures --only colour_`.*"
    )?;
    Ok(md.into_bytes())
}

fn fit_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let nms: Vec<f64> = (0..=94).map(|i| 360.0 + 5.0 * f64::from(i)).collect();
    // The error oscillates with a period of about 10 nm: 5 nm steps would alias it.
    let fine: Vec<f64> = (0..=470).map(|i| 360.0 + f64::from(i)).collect();
    let names = ["x-bar", "y-bar", "z-bar"];
    let mut curves = Vec::new();
    let mut errors = Vec::new();
    for (k, name) in names.iter().enumerate() {
        curves.push(Series::line(
            format!("{name} (table)"),
            nms.iter().map(|&l| (l, cmf(l)[k])).collect(),
        ));
        curves.push(Series::line(
            format!("{name} fit"),
            nms.iter().map(|&l| (l, cmf_fit(l)[k])).collect(),
        ));
        errors.push(Series::line(
            format!("{name} fit − table"),
            fine.iter()
                .map(|&l| (l, cmf_fit(l)[k] - cmf(l)[k]))
                .collect(),
        ));
    }
    let worst = errors
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1.abs()))
        .fold(0.0, f64::max);
    let range = (LAMBDA_MIN, LAMBDA_MAX);
    plot::ranged_chart(&[
        (
            Panel::new(
                "CIE 1931 table and the Wyman-Sloan-Shirley fit",
                "wavelength (nm)",
                "value",
                curves,
            ),
            range,
            (-0.05, 1.9),
            plot::Legend::Below,
        ),
        (
            Panel::new("fit − table", "wavelength (nm)", "difference", errors),
            range,
            (-1.1 * worst, 1.1 * worst),
            plot::Legend::Below,
        ),
    ])
}

/// The largest |fit − table| of each function over 360-830 nm at 0.1 nm, with where it is,
/// and the mean |fit − table|.
pub fn fit_errors() -> [(f64, f64, f64); 3] {
    let mut out = [(0.0, 0.0, 0.0); 3];
    let n = 4701;
    for i in 0..n {
        let nm = LAMBDA_MIN + 0.1 * f64::from(i);
        let d = (cmf_fit(nm) - cmf(nm)).abs();
        for (k, o) in out.iter_mut().enumerate() {
            if d[k] > o.0 {
                o.0 = d[k];
                o.1 = nm;
            }
            o.2 += d[k] / f64::from(n);
        }
    }
    out
}

fn fit_md(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let errors = fit_errors();
    let mut peak = DVec3::ZERO;
    for i in 0..cie::CMF_ROWS {
        peak = peak.max(cie::cmf_row(i));
    }
    let mut md = String::new();
    writeln!(
        md,
        "| function | peak of the table | max abs(fit − table) | at | relative to the peak | mean abs(fit − table) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|")?;
    for (k, name) in ["x̄", "ȳ", "z̄"].iter().enumerate() {
        let (max, at, mean) = errors[k];
        writeln!(
            md,
            "| {name} | {:.4} | {max:.4} | {at:.1} nm | {:.2} % | {mean:.5} |",
            peak[k],
            100.0 * max / peak[k]
        )?;
    }
    writeln!(
        md,
        "\n*Over 360-830 nm at 0.1 nm steps. The fit: Wyman, Sloan and Shirley, JCGT 2(2), \
         2013, Listing 2 (`cie::cmf_fit`). Its effect on colours is in the illuminant table.*"
    )?;
    Ok(md.into_bytes())
}

fn speed_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let reps = if settings.quick { 5 } else { 41 };
    // Wavelengths as a renderer draws them: uniform over the range, not on the knots.
    let mut rng = raylemma::rng::seeded(0xC0);
    let nms: Vec<f64> = (0..4096)
        .map(|_| raylemma::rng::uniform(&mut rng, LAMBDA_MIN, LAMBDA_MAX))
        .collect();
    let batch = |f: fn(f64) -> DVec3| {
        let nms = &nms;
        move || {
            let mut s = DVec3::ZERO;
            for &nm in nms {
                s += f(black_box(nm));
            }
            (s.x + s.y + s.z).to_bits()
        }
    };
    let table_ns = timing::median_ns_per_item(nms.len(), reps, batch(cmf));
    let fit_ns = timing::median_ns_per_item(nms.len(), reps, batch(cmf_fit));
    let d65 = spectrum::builtin("cie_illuminant_D65.csv");
    let xyz_reps = if settings.quick { 5 } else { 21 };
    let xyz_table = timing::median_ns_per_item(1, xyz_reps, || {
        xyz(|nm| d65.eval(black_box(nm))).x.to_bits()
    });
    let xyz_fit = timing::median_ns_per_item(1, xyz_reps, || {
        xyz_with(cmf_fit, |nm| d65.eval(black_box(nm))).x.to_bits()
    });
    let errors = fit_errors();
    let worst = errors.iter().map(|e| e.0).fold(0.0, f64::max);
    r.claim(
        "fit_is_slower",
        fit_ns > table_ns,
        format!("ns per (x̄, ȳ, z̄): fit {fit_ns:.2} > table {table_ns:.2}"),
    );
    let mut md = String::new();
    writeln!(
        md,
        "| colour matching | ns per (x̄, ȳ, z̄) | max abs error | µs per XYZ of D65 (1880 points) |"
    )?;
    writeln!(md, "|---|---:|---:|---:|")?;
    writeln!(
        md,
        "| 1 nm table, linear interpolation (`cmf`) | {} | 0 (the definition) | {} |",
        r.number("table.ns_per_evaluation", table_ns, ".2"),
        r.number("table.us_per_xyz", xyz_table / 1e3, ".1"),
    )?;
    writeln!(
        md,
        "| Wyman-Sloan-Shirley fit (`cmf_fit`) | {} | {worst:.4} | {} |",
        r.number("fit.ns_per_evaluation", fit_ns, ".2"),
        r.number("fit.us_per_xyz", xyz_fit / 1e3, ".1"),
    )?;
    writeln!(
        md,
        "\n*Median of {reps} batches of 4096 uniform wavelengths; {}. Measured by \
         `cargo run --release -- figures`; `cargo bench -p raylemma-bench --bench colour` measures the same with \
         criterion.*",
        timing::machine()
    )?;
    Ok(md.into_bytes())
}

fn planck_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::new();
    writeln!(
        md,
        "| T (K) | Planck, exact integral (x, y) | Krystek 1985 (x, y) | max(abs Δx, abs Δy) |"
    )?;
    writeln!(md, "|---:|---|---|---:|")?;
    for t in [
        1000.0, 1500.0, 2000.0, 2856.0, 4000.0, 5000.0, 6504.0, 8000.0, 10000.0, 15000.0,
    ] {
        let p = planck_xy(t);
        let k = krystek(t);
        let apart = (p - k).abs().max_element();
        if t == 6504.0 {
            // D65's correlated colour temperature: the locus agrees with Krystek's to within
            // the accuracy `planckian_locus_matches_krystek` holds over 2000-10000 K.
            r.number("k6504.apart", apart, "x1");
            r.claim(
                "d65_within_accuracy",
                apart <= 4e-4,
                format!("6504 K: max(|Δx|, |Δy|) {apart:.3e} <= 4e-4"),
            );
        }
        writeln!(
            md,
            "| {t} | ({:.5}, {:.5}) | ({:.5}, {:.5}) | {apart:.1e} |",
            p.x, p.y, k.x, k.y,
        )?;
    }
    let c2 = spectrum::PLANCK_H * spectrum::LIGHT_C / spectrum::BOLTZMANN_K;
    writeln!(
        md,
        "\n*Illuminant A is defined with the old second radiation constant c₂ = 1.435 × 10⁻² m K \
         at 2848 K; with today's c₂ = hc/k = {c2:.6e} m K the same curve is a Planckian at \
         {:.2} K.*",
        2848.0 * c2 / 1.435e-2
    )?;
    Ok(md.into_bytes())
}
