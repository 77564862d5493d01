//! Figures and tables of the chapter *Statistical tests*: are the tests calibrated?
//!
//! A test is calibrated when, with the null hypothesis true, its p-value is uniform on
//! `[0, 1]`: then it rejects at level `a` with probability exactly `a`. Each experiment
//! here draws data for which the null is true by construction, many times with different
//! seeds, and collects the p-values; the figure shows their histograms and the table the
//! observed rejection rates.

use std::fmt::Write as _;
use std::sync::OnceLock;

use anyhow::{Context, bail};
use rayon::prelude::*;

use super::{Output, Record, Settings};
use crate::plot::{self, Panel, Series};
use raylemma::rng;
use raylemma::rng::standard_normal;
use raylemma::stats::null::{NULL_CASES, NullCase, chi2_p_value};
use raylemma::stats::{binomial, ks, test_alpha};

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
        Output {
            file: "stats_far_tail.md",
            what: "chi-squared's false-failure rate at test_alpha()",
            make: far_tail_md,
        },
    ]
}

/// The p-values of every experiment.
struct Calibration {
    runs: u64,
    p_values: Vec<(NullCase, Vec<f64>)>,
}

fn calibration(settings: &Settings) -> anyhow::Result<&'static Calibration> {
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

fn pvalues_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
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

/// Stephens' scaled statistic `(sqrt(n) + 0.12 + 0.11 / sqrt(n)) d`, as `ks::two_sample`
/// uses it beyond its exact range (private there).
fn stephens_lambda(n: f64, d: f64) -> f64 {
    let s = n.sqrt();
    (s + 0.12 + 0.11 / s) * d
}

/// The two-sample runs of [`NullCase::KsTwoSample`] again, with the p-value of the limit
/// law (Stephens' correction at the effective size `n_a n_b / (n_a + n_b)`) that
/// `ks::two_sample` used before it computed the exact one at these sizes. Each run draws
/// the samples of the same seed, which the exact p-values of `exact` confirm.
fn two_sample_limit_law(exact: &[f64]) -> anyhow::Result<Vec<f64>> {
    // The generator of run `seed` of `NullCase::KsTwoSample` (its index in NULL_CASES is 3;
    // `NullCase::rng` is private).
    let index = NULL_CASES
        .iter()
        .position(|&c| c == NullCase::KsTwoSample)
        .context("no two-sample case")? as u64;
    let runs: Vec<(f64, f64)> = (0..exact.len() as u64)
        .into_par_iter()
        .map(|seed| {
            let mut g = rng::seeded(0x5747_0000_0000 + (index << 32) + seed);
            let a: Vec<f64> = (0..200).map(|_| standard_normal(&mut g)).collect();
            let b: Vec<f64> = (0..301).map(|_| standard_normal(&mut g)).collect();
            let k = ks::two_sample(&a, &b)?;
            let effective = 200.0 * 301.0 / 501.0;
            Ok((
                k.p_value,
                ks::kolmogorov_sf(stephens_lambda(effective, k.statistic)),
            ))
        })
        .collect::<Result<_, raylemma::stats::StatsError>>()?;
    if runs.iter().zip(exact).any(|((p, _), q)| p != q) {
        bail!("the two-sample runs drawn again differ from NullCase::KsTwoSample's");
    }
    Ok(runs.into_iter().map(|(_, limit)| limit).collect())
}

fn calibration_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let cal = calibration(settings)?;
    let alpha = test_alpha();
    let mut md = String::new();
    writeln!(
        md,
        "| test | experiment (null true) | runs | rejected at 0.05 | at 0.01 | at test_alpha() = {alpha:.3e} | KS of the p-values against uniform: D | its p-value |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|")?;
    let two_sample = cal
        .p_values
        .iter()
        .find(|(c, _)| *c == NullCase::KsTwoSample)
        .map(|(_, ps)| ps.as_slice())
        .context("no two-sample case")?;
    let limit = two_sample_limit_law(two_sample)?;
    // How much the limit law overstates the exact p-value in the body of the distribution
    // (exact p from 0.05 to 0.95): the mean of limit / exact - 1 over those runs.
    let body: Vec<f64> = two_sample
        .iter()
        .zip(&limit)
        .filter(|&(&p, _)| (0.05..=0.95).contains(&p))
        .map(|(&p, &q)| q / p - 1.0)
        .collect();
    let overstated = 100.0 * body.iter().sum::<f64>() / body.len() as f64;
    r.number(
        "ks_two_samples_limit_law.body_overstatement_percent",
        overstated,
        ".1",
    );
    r.claim(
        "ks_two_samples_limit_law.overstates_by_a_few_percent",
        (0.5..=10.0).contains(&overstated),
        format!(
            "the limit law's two-sample p-value over the exact one, mean of limit/exact - 1 over the {} runs with exact p in [0.05, 0.95]: {overstated:.2} %, in [0.5, 10] %",
            body.len()
        ),
    );
    let mut rows: Vec<(&str, &str, &str, &[f64])> = cal
        .p_values
        .iter()
        .map(|(case, ps)| (key(*case), case.test(), case.experiment(), ps.as_slice()))
        .collect();
    rows.push((
        "ks_two_samples_limit_law",
        "KS, two samples, limit law",
        "the same runs, p from the limit law with Stephens' correction",
        &limit,
    ));
    // Every test of the suite (not the limit law, which it no longer uses) must look
    // uniform at the suite's level.
    let mut uniform = Vec::new();
    for &(name, test, experiment, ps) in &rows {
        let rejected = |a: f64| ps.iter().filter(|&&p| p < a).count();
        let uniformity = ks::one_sample(ps, |x| x.clamp(0.0, 1.0))?;
        if name == "ks_two_samples_limit_law" {
            r.claim(
                "ks_two_samples_limit_law.uniformity_rejected_at_0_01",
                uniformity.p_value < 0.01,
                format!(
                    "KS of the limit law's two-sample p-values against uniform: D = {:.4}, p = {:.3e} < 0.01",
                    uniformity.statistic, uniformity.p_value
                ),
            );
        } else {
            uniform.push((name, uniformity.p_value));
        }
        if name == "ks_two_samples" {
            r.claim(
                "ks_two_samples.looks_uniform",
                uniformity.p_value >= alpha,
                format!(
                    "KS of the exact two-sample p-values against uniform: D = {:.4}, p = {:.3e} >= test_alpha() = {alpha:.3e}",
                    uniformity.statistic, uniformity.p_value
                ),
            );
        }
        writeln!(
            md,
            "| {test} | {experiment} | {} | {} | {} | {} | {:.4} | {} |",
            ps.len(),
            percent(rejected(0.05), cal.runs),
            percent(rejected(0.01), cal.runs),
            percent(rejected(alpha), cal.runs),
            uniformity.statistic,
            r.number(&format!("{name}.uniformity_p"), uniformity.p_value, ".3"),
        )?;
    }
    r.claim(
        "uniform_every_row",
        uniform.len() == NULL_CASES.len() && uniform.iter().all(|&(_, p)| p >= alpha),
        format!(
            "KS of each test's p-values against uniform, p >= test_alpha() = {alpha:.3e}: {}",
            uniform
                .iter()
                .map(|(n, p)| format!("{n} {p:.3e}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    let runs = cal.runs as f64;
    writeln!(
        md,
        "\n*A calibrated test rejects a fraction α of the runs, give or take the binomial standard error √(α(1−α)/runs): {:.2} % at 0.05 and {:.2} % at 0.01 for {} runs; at test_alpha() it expects {:.2} false failures per test ({:.2} in all, over the {} tests of the suite). The last row is not a test of the suite: it recomputes the two-sample runs with the limit law that the suite no longer uses at these sizes. Generated by `cargo run --release` (`tools/figures/src/stats.rs`).*",
        100.0 * (0.05f64 * 0.95 / runs).sqrt(),
        100.0 * (0.01f64 * 0.99 / runs).sqrt(),
        cal.runs,
        alpha * runs,
        alpha * runs * NULL_CASES.len() as f64,
        NULL_CASES.len(),
    )?;
    Ok(md.into_bytes())
}

/// Pearson's chi-squared in the far tail: the experiment of the calibration table's first
/// row run long enough to measure its false-failure rate at `test_alpha()` itself.
fn far_tail_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let runs: u64 = if settings.quick { 200_000 } else { 8_000_000 };
    let alpha = test_alpha();
    let rejected = (0..runs)
        .into_par_iter()
        .map(|seed| chi2_p_value(seed, 5.0).map(|p| u64::from(p < alpha)))
        .try_reduce(|| 0, |a, b| Ok(a + b))?;
    let rate = rejected as f64 / runs as f64;
    let (lo, hi) = binomial::wilson(u32::try_from(rejected)?, u32::try_from(runs)?);
    let mut md = String::new();
    writeln!(
        md,
        "| test | experiment (null true) | runs | rejected at test_alpha() = {alpha:.3e} | rate (95 % interval) | rate / test_alpha() (95 % interval) |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|")?;
    writeln!(
        md,
        "| {} | {} | {runs} | {} | {:.3e} ({:.3e}–{:.3e}) | {} ({:.1}–{:.1}) |",
        NullCase::Chi2.test(),
        NullCase::Chi2.experiment(),
        r.number("chi2_rejected", rejected as f64, "int"),
        rate,
        lo,
        hi,
        r.number("chi2_rate_over_nominal", rate / alpha, ".1"),
        lo / alpha,
        hi / alpha,
    )?;
    r.number("runs", runs as f64, "x0");
    r.claim(
        "chi2_about_twice_nominal",
        (1.5..=3.0).contains(&(lo / alpha)) && (1.5..=3.0).contains(&(hi / alpha)),
        format!(
            "chi-squared's false-failure rate at test_alpha() over the nominal: {:.2} (95 % interval {:.2} to {:.2}), within [1.5, 3]",
            rate / alpha,
            lo / alpha,
            hi / alpha
        ),
    );
    writeln!(
        md,
        "\n*The experiment of the calibration table's first row (seeds 0 to {}), the cells that expect fewer than 5 samples pooled; Wilson's interval at 95 %. Generated by `cargo run --release` (`tools/figures/src/stats.rs`).*",
        runs - 1
    )?;
    Ok(md.into_bytes())
}
