//! Figures and tables of the chapter *Statistical tests*: are the tests calibrated?
//!
//! A test is calibrated when, with the null hypothesis true, its p-value is uniform on
//! `[0, 1]`: then it rejects at level `a` with probability exactly `a`. Each experiment
//! here draws data for which the null is true by construction, many times with different
//! seeds, and collects the p-values; the figure shows their histograms and the table the
//! observed rejection rates.

use std::fmt::Write as _;
use std::sync::OnceLock;

use super::{Output, Record, Settings};
use crate::plot::{self, BoxError, Panel, Series};
use raylemma::stats::null::{NULL_CASES, NullCase};
use raylemma::stats::{ks, test_alpha};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "stats_pvalues.svg",
            what: "p-values under the null",
            make: pvalues_svg,
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

fn pvalues_svg(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let cal = calibration(settings)?;
    // Under the null each bin holds Binomial(runs, 1/BINS) p-values: density 1 ± 2 sd.
    let share = 1.0 / BINS as f64;
    let sd = (share * (1.0 - share) / cal.runs as f64).sqrt() / share;
    let edges: Vec<f64> = (0..=BINS).map(|i| i as f64 * share).collect();
    let panels: Vec<Panel> = cal
        .p_values
        .iter()
        .map(|(case, ps)| {
            let mut counts = [0usize; BINS];
            for &p in ps {
                counts[((p * BINS as f64) as usize).min(BINS - 1)] += 1;
            }
            let density: Vec<f64> = counts
                .iter()
                .map(|&c| c as f64 / (ps.len() as f64 * share))
                .collect();
            let top = density.iter().copied().fold(1.0 + 3.0 * sd, f64::max) * 1.1;
            let (lo, hi) = (1.0 - 2.0 * sd, 1.0 + 2.0 * sd);
            Panel::new(
                case.test(),
                "p-value",
                "density",
                vec![
                    Series::bars(
                        format!("p-values of {} runs, {BINS} bins", cal.runs),
                        &edges,
                        &density,
                    ),
                    Series::line("uniform density 1", vec![(0.0, 1.0), (1.0, 1.0)]),
                    Series::line(
                        "1 ± 2 sd of a bin under the null",
                        vec![
                            (0.0, lo),
                            (1.0, lo),
                            (f64::NAN, f64::NAN),
                            (0.0, hi),
                            (1.0, hi),
                        ],
                    ),
                ],
            )
            .x_range((0.0, 1.0))
            .y_range((0.0, top))
        })
        .collect();
    plot::chart(&panels, 2)
}

fn percent(rejected: usize, runs: u64) -> String {
    format!(
        "{:.2} % ({rejected})",
        100.0 * rejected as f64 / runs as f64
    )
}

/// A row's name in the record.
fn key(case: NullCase) -> &'static str {
    match case {
        NullCase::Chi2 => "pearson",
        NullCase::KsExact => "ks_exact",
        NullCase::KsAsymptotic => "ks_asymptotic",
        NullCase::KsTwoSample => "ks_two_samples",
        NullCase::StudentT => "student_t",
        NullCase::Welch => "welch_t",
    }
}

fn calibration_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
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
        let name = key(*case);
        if *case == NullCase::KsTwoSample {
            r.claim(
                "ks_two_samples.uniformity_rejected_at_0_01",
                uniformity.p_value < 0.01,
                format!(
                    "KS of the two-sample test's p-values against uniform: p = {:.3e} < 0.01",
                    uniformity.p_value
                ),
            );
        }
        writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {:.4} | {} |",
            case.test(),
            case.experiment(),
            cal.runs,
            percent(rejected(0.05), cal.runs),
            percent(rejected(0.01), cal.runs),
            percent(rejected(alpha), cal.runs),
            uniformity.statistic,
            r.number(&format!("{name}.uniformity_p"), uniformity.p_value, ".3"),
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
