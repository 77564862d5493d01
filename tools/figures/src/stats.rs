//! Figures and tables of the chapter *Statistical tests*: are the tests calibrated?
//!
//! A test is calibrated when, with the null hypothesis true, its p-value is uniform on
//! `[0, 1]`: then it rejects at level `a` with probability exactly `a`. Each experiment
//! here draws data for which the null is true by construction, many times with different
//! seeds, and collects the p-values; the figure shows their histograms and the table the
//! observed rejection rates.

use std::fmt::Write as _;
use std::sync::OnceLock;

use super::{Output, Settings};
use crate::plot::{self, BoxError};
use raylemma::stats::null::{NULL_CASES, NullCase};
use raylemma::stats::{ks, test_alpha};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "stats_pvalues.png",
            what: "p-values under the null",
            make: pvalues_png,
        },
        Output {
            file: "stats_calibration.md",
            what: "false-failure rates",
            make: calibration_md,
        },
    ]
}

/// The p-values of every experiment.
struct Calibration {
    runs: u64,
    p_values: Vec<(NullCase, Vec<f64>)>,
}

fn calibration(settings: &Settings) -> Result<&'static Calibration, BoxError> {
    static FULL: OnceLock<Calibration> = OnceLock::new();
    static QUICK: OnceLock<Calibration> = OnceLock::new();
    let (cell, runs) = if settings.quick {
        (&QUICK, 200)
    } else {
        (&FULL, 20_000)
    };
    if let Some(c) = cell.get() {
        return Ok(c);
    }
    let p_values = NULL_CASES
        .iter()
        .map(|&case| case.p_values(runs).map(|p| (case, p)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(cell.get_or_init(|| Calibration { runs, p_values }))
}

const BINS: usize = 20;

fn pvalues_png(settings: &Settings) -> Result<Vec<u8>, BoxError> {
    use plotters::prelude::*;
    let cal = calibration(settings)?;
    let (width, height) = (1200u32, 720u32);
    plot::register_embedded_font();
    let mut buffer = vec![255u8; (width * height * 3) as usize];
    // Under the null each bin holds Binomial(runs, 1/BINS) p-values: density 1 ± 2 sd.
    let share = 1.0 / BINS as f64;
    let sd = (share * (1.0 - share) / cal.runs as f64).sqrt() / share;
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (width, height)).into_drawing_area();
        root.fill(&WHITE)?;
        let root = root.titled(
            &format!(
                "p-values under a true null hypothesis, {} runs each (uniform if calibrated)",
                cal.runs
            ),
            ("sans-serif", 20),
        )?;
        for ((case, ps), area) in cal.p_values.iter().zip(root.split_evenly((2, 3)).iter()) {
            let mut counts = [0usize; BINS];
            for &p in ps {
                counts[((p * BINS as f64) as usize).min(BINS - 1)] += 1;
            }
            let density = |c: usize| c as f64 / (ps.len() as f64 * share);
            let top = counts
                .iter()
                .map(|&c| density(c))
                .fold(1.0 + 3.0 * sd, f64::max)
                * 1.1;
            let mut chart = ChartBuilder::on(area)
                .caption(case.test(), ("sans-serif", 17))
                .margin(10)
                .x_label_area_size(36)
                .y_label_area_size(46)
                .build_cartesian_2d(0f64..1f64, 0f64..top)?;
            chart
                .configure_mesh()
                .disable_x_mesh()
                .light_line_style(TRANSPARENT)
                .x_desc("p-value")
                .y_desc("density")
                .label_style(("sans-serif", 12))
                .axis_desc_style(("sans-serif", 13))
                .x_label_formatter(&|v| plot::format_tick(*v))
                .y_label_formatter(&|v| plot::format_tick(*v))
                .draw()?;
            let RGBColor(r, g, b) = plot::PALETTE[0];
            let light = |c: u8| ((u16::from(c) + 2 * 255) / 3) as u8;
            let fill = RGBColor(light(r), light(g), light(b));
            for style in [fill.filled(), plot::PALETTE[0].stroke_width(1)] {
                chart.draw_series(counts.iter().enumerate().map(|(i, &c)| {
                    let x0 = i as f64 * share;
                    Rectangle::new([(x0, 0.0), (x0 + share, density(c))], style)
                }))?;
            }
            for (y, style) in [
                (1.0, BLACK.stroke_width(2)),
                (1.0 - 2.0 * sd, plot::PALETTE[1].stroke_width(1)),
                (1.0 + 2.0 * sd, plot::PALETTE[1].stroke_width(1)),
            ] {
                chart.draw_series(DashedLineSeries::new(vec![(0.0, y), (1.0, y)], 6, 4, style))?;
            }
        }
        root.present()?;
    }
    plot::encode_png(width, height, buffer)
}

fn percent(rejected: usize, runs: u64) -> String {
    format!(
        "{:.2} % ({rejected})",
        100.0 * rejected as f64 / runs as f64
    )
}

fn calibration_md(settings: &Settings) -> Result<Vec<u8>, BoxError> {
    let cal = calibration(settings)?;
    let alpha = test_alpha();
    let mut md = String::new();
    writeln!(
        md,
        "| test | experiment (null true) | runs | rejected at 0.05 | at 0.01 | at test_alpha() = {alpha:.3e} | KS of the p-values against uniform: D | its p-value |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|")?;
    for (case, ps) in &cal.p_values {
        let rejected = |a: f64| ps.iter().filter(|&&p| p < a).count();
        let uniformity = ks::one_sample(ps, |x| x.clamp(0.0, 1.0))?;
        writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {:.4} | {:.3} |",
            case.test(),
            case.experiment(),
            cal.runs,
            percent(rejected(0.05), cal.runs),
            percent(rejected(0.01), cal.runs),
            percent(rejected(alpha), cal.runs),
            uniformity.statistic,
            uniformity.p_value,
        )?;
    }
    let runs = cal.runs as f64;
    writeln!(
        md,
        "\n*A calibrated test rejects a fraction α of the runs, give or take the binomial standard error √(α(1−α)/runs): {:.2} % at 0.05 and {:.2} % at 0.01 for {} runs; at test_alpha() it expects {:.2} false failures in all. Generated by `cargo run --release` (`tools/figures/src/stats.rs`).*",
        100.0 * (0.05f64 * 0.95 / runs).sqrt(),
        100.0 * (0.01f64 * 0.99 / runs).sqrt(),
        cal.runs,
        alpha * runs,
    )?;
    Ok(md.into_bytes())
}
