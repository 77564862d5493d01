//! The checker's calibration: the p-values of correct samplers (`sampling_calibration.svg`)
//! and the false-failure rates (`sampling_calibration.md`), of the chapter *Checking a
//! sampler*.

use std::fmt::Write as _;

use rayon::prelude::*;

use super::{chi2_p, correct_samplers};
use crate::plot::{self, Panel, Series};
use crate::{Record, Settings};
use raylemma::stats;

fn seeds(settings: &Settings) -> u64 {
    if settings.quick { 40 } else { 400 }
}

/// p-values of every correct sampler over many seeds (100 000 samples each).
fn calibration_p_values(settings: &Settings) -> Vec<(String, Vec<f64>)> {
    correct_samplers()
        .into_iter()
        .map(|w| {
            let ps = (0..seeds(settings))
                .into_par_iter()
                .map(|s| chi2_p(w.as_ref(), 100_000, 5000 + s))
                .collect();
            (w.name(), ps)
        })
        .collect()
}

pub(super) fn calibration_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let all: Vec<f64> = calibration_p_values(settings)
        .into_iter()
        .flat_map(|(_, ps)| ps)
        .collect();
    let bins = 20;
    let mut counts = vec![0usize; bins];
    for p in &all {
        counts[((p * bins as f64) as usize).min(bins - 1)] += 1;
    }
    let density: Vec<f64> = counts
        .iter()
        .map(|&c| c as f64 / all.len() as f64 * bins as f64)
        .collect();
    let edges: Vec<f64> = (0..=bins).map(|k| k as f64 / bins as f64).collect();
    let panels = [Panel::new(
        format!(
            "chi-squared p-values of the correct samplers ({} runs)",
            all.len()
        ),
        "p-value",
        "density",
        vec![
            Series::bars("observed", &edges, &density),
            Series::line("uniform (ideal)", vec![(0.0, 1.0), (1.0, 1.0)]),
        ],
    )
    .x_range((0.0, 1.0))];
    plot::chart(&panels, 1)
}

pub(super) fn calibration_md(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let alpha = stats::test_alpha();
    let mut md = String::new();
    writeln!(
        md,
        "| sampler | runs | p < 0.05 (95 % interval) | p < 0.01 (95 % interval) | p < α = {alpha:.1e} (95 % interval) | KS p-value of the p-values |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|")?;
    for (name, ps) in calibration_p_values(settings) {
        // A NaN p-value (an error) counts as a failure here. Each rate with its Wilson
        // interval: over a few hundred runs the rate at α can only read 0 or the share of
        // one run, and the interval says how little that tells.
        let rate = |a: f64, decimals: usize| {
            let k = ps.iter().filter(|&&p| p.is_nan() || p < a).count();
            let n = ps.len();
            let (lo, hi) = stats::binomial::wilson(k as u32, n as u32);
            format!(
                "{:.decimals$} % ({:.decimals$}–{:.decimals$} %)",
                100.0 * k as f64 / n as f64,
                100.0 * lo,
                100.0 * hi
            )
        };
        let ks = stats::ks::one_sample(&ps, |x| x.clamp(0.0, 1.0)).map_or(f64::NAN, |k| k.p_value);
        writeln!(
            md,
            "| {name} | {} | {} | {} | {} | {ks:.3} |",
            ps.len(),
            rate(0.05, 1),
            rate(0.01, 1),
            rate(alpha, 2)
        )?;
    }
    writeln!(
        md,
        "\n*100 000 samples per run, one seed per run; the intervals are Wilson's at 95 % (`raylemma::stats::binomial::wilson`). A well-calibrated test rejects about 5 % and 1 % of correct samplers at those levels, and its p-values are uniform.*"
    )?;
    Ok(md.into_bytes())
}
