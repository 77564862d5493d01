//! The strategies' error against time (`wavelength_error.svg`) and their efficiency table
//! (`wavelength_efficiency.md`), of the chapter *Wavelength sampling and hero wavelengths*.

use std::fmt::Write as _;

use anyhow::Context;
use glam::DVec3;

use super::measure::{ns_per_path, ns_per_path_all, path_xyz, relative_sq, relative_variance};
use super::{spectra, spectrum_key};
use crate::plot::{self, Panel, Series};
use crate::{Record, Settings, timing};
use raylemma::rng;
use raylemma::spectral::cie;
use raylemma::spectral::wavelength::WavelengthStrategy;

pub(super) fn error_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (repeats, max_pow, reps) = if settings.quick {
        (60, 8, 3)
    } else {
        (200, 11, 11)
    };
    let chosen = ["incandescent", "cool white fl.", "low-pr. sodium"];
    let mut panels = Vec::new();
    for (name, spectrum) in spectra().into_iter().filter(|(n, _)| chosen.contains(n)) {
        let exact = cie::xyz(|l| spectrum.eval(l));
        let mut series = Vec::new();
        for s in WavelengthStrategy::ALL {
            let ns = ns_per_path(s, &spectrum, reps);
            let mut r = rng::seeded(0xE44);
            let points = (2..=max_pow)
                .map(|k| {
                    let n = 1usize << k;
                    let mse = (0..repeats)
                        .map(|_| {
                            let mut sum = DVec3::ZERO;
                            for _ in 0..n {
                                sum += path_xyz(s, rng::uniform(&mut r, 0.0, 1.0), &spectrum);
                            }
                            relative_sq(sum / n as f64, exact)
                        })
                        .sum::<f64>()
                        / repeats as f64;
                    (n as f64 * ns, mse.sqrt())
                })
                .collect();
            series.push(Series::measured(s.name(), points));
        }
        panels.push(
            Panel::new(
                format!("{name}: XYZ of the lamp"),
                "time per estimate (ns)",
                "RMS relative error",
                series,
            )
            .log_x()
            .log_y(),
        );
    }
    plot::chart(&panels, 2)
}

/// A strategy as a value name (the renderer's names, `hero-visible` as `hero_visible`).
fn strategy_key(s: WavelengthStrategy) -> &'static str {
    match s {
        WavelengthStrategy::Uniform => "uniform",
        WavelengthStrategy::Visible => "visible",
        WavelengthStrategy::HeroUniform => "hero_uniform",
        WavelengthStrategy::HeroVisible => "hero_visible",
        WavelengthStrategy::HeroBalance => "hero_balance",
        WavelengthStrategy::SeedBand => "seed_band",
    }
}

/// Names as the book lists them: `a`, `a and b`, `a, b and c`, or `none`.
fn join_names(names: &[&str]) -> String {
    match names {
        [] => "none".into(),
        [one] => (*one).to_string(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// The index of the smallest (`better` = `f64::lt`) or largest (`f64::gt`) value of
/// `column`, or `None` when two share it.
fn extreme(column: &[f64], better: fn(&f64, &f64) -> bool) -> Option<usize> {
    let mut best = 0;
    for (k, x) in column.iter().enumerate() {
        if better(x, &column[best]) {
            best = k;
        }
    }
    (column.iter().filter(|&&x| x == column[best]).count() == 1).then_some(best)
}

pub(super) fn efficiency_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (n, reps) = if settings.quick {
        (20_000, 5)
    } else {
        (200_000, 51)
    };
    let spectra = spectra();
    let mut variance = Vec::new();
    let mut times = Vec::new();
    for (_, spectrum) in &spectra {
        let exact = cie::xyz(|l| spectrum.eval(l));
        variance.push(
            WavelengthStrategy::ALL
                .map(|s| relative_variance(s, spectrum, exact, n))
                .to_vec(),
        );
        times.push(ns_per_path_all(spectrum, reps));
    }
    let header = |md: &mut String, first: &str| -> std::fmt::Result {
        write!(md, "| {first} |")?;
        for (name, _) in &spectra {
            write!(md, " {name} |")?;
        }
        writeln!(md)?;
        writeln!(md, "|---|{}", "---:|".repeat(spectra.len()))
    };
    let mut md = String::new();
    writeln!(
        md,
        "**Relative variance per path** (mean over X, Y, Z of Var / exact²; smaller is better)\n"
    )?;
    header(&mut md, "strategy")?;
    for (i, s) in WavelengthStrategy::ALL.iter().enumerate() {
        write!(md, "| {} |", s.name())?;
        for v in &variance {
            write!(md, " {:.4} |", v[i])?;
        }
        writeln!(md)?;
    }
    writeln!(md, "\n**ns per path** (lanes and the XYZ estimate)\n")?;
    header(&mut md, "strategy")?;
    for (i, s) in WavelengthStrategy::ALL.iter().enumerate() {
        write!(md, "| {} |", s.name())?;
        for t in &times {
            write!(md, " {:.0} |", t[i])?;
        }
        writeln!(md)?;
    }
    writeln!(
        md,
        "\n**Efficiency relative to one uniform wavelength**, `(Var × ns)` of uniform over \
         `(Var × ns)` of the strategy (larger is better)\n"
    )?;
    header(&mut md, "strategy")?;
    // efficiency[spectrum][strategy]
    let efficiency: Vec<Vec<f64>> = variance
        .iter()
        .zip(&times)
        .map(|(v, t)| (0..v.len()).map(|i| v[0] * t[0] / (v[i] * t[i])).collect())
        .collect();
    for (i, s) in WavelengthStrategy::ALL.iter().enumerate() {
        write!(md, "| {} |", s.name())?;
        for ((name, _), e) in spectra.iter().zip(&efficiency) {
            let key = format!("{}.{}.efficiency", spectrum_key(name), strategy_key(*s));
            write!(md, " {} |", r.number(&key, e[i], ".2"))?;
        }
        writeln!(md)?;
    }
    let hero = WavelengthStrategy::ALL
        .iter()
        .position(|&s| s == WavelengthStrategy::HeroVisible)
        .context("no hero-visible strategy")?;
    let seed = WavelengthStrategy::ALL
        .iter()
        .position(|&s| s == WavelengthStrategy::SeedBand)
        .context("no seed's band strategy")?;
    // The smallest relative variance of every spectrum: hero-visible's?
    let not_smallest: Vec<&str> = spectra
        .iter()
        .zip(&variance)
        .filter(|(_, v)| extreme(v, f64::lt) != Some(hero))
        .map(|((name, _), _)| *name)
        .collect();
    r.claim(
        "hero_visible_smallest_variance_every_spectrum",
        not_smallest.is_empty(),
        format!(
            "spectra where hero, visible pdf (sample space) does not have the smallest relative variance (alone): {}",
            join_names(&not_smallest)
        ),
    );
    let (most, not_most): (Vec<_>, Vec<_>) = spectra
        .iter()
        .zip(&efficiency)
        .map(|((name, _), e)| (*name, extreme(e, f64::gt) == Some(hero)))
        .partition(|(_, is)| *is);
    r.number(
        "hero_visible_most_efficient.count",
        most.len() as f64,
        "int",
    );
    let not_most: Vec<&str> = not_most.iter().map(|(name, _)| *name).collect();
    r.text("hero_visible_most_efficient.except", join_names(&not_most));
    let seed_below = efficiency.iter().filter(|e| e[seed] < 1.0).count();
    r.number("seed_band_below_uniform.count", seed_below as f64, "int");
    r.number("spectra.count", spectra.len() as f64, "int");
    let at = |s: WavelengthStrategy| {
        WavelengthStrategy::ALL
            .iter()
            .position(|&t| t == s)
            .unwrap_or(0)
    };
    let (uniform, hero_uniform, balance) = (
        at(WavelengthStrategy::Uniform),
        at(WavelengthStrategy::HeroUniform),
        at(WavelengthStrategy::HeroBalance),
    );
    let names = |pred: &dyn Fn(usize) -> bool| -> Vec<&str> {
        (0..spectra.len())
            .filter(|&k| pred(k))
            .map(|k| spectra[k].0)
            .collect()
    };
    let range = |xs: &[f64]| {
        xs.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                (lo.min(x), hi.max(x))
            })
    };
    // The cut in relative variance (over X, Y and Z) by uniform hero lanes: large on every
    // spectrum (above 4), and smaller than the cut of more than 20 that
    // `seed_band_barely_reduces_variance` asserts for the Y of D65 (below 20).
    let cut: Vec<f64> = variance
        .iter()
        .map(|v| v[uniform] / v[hero_uniform])
        .collect();
    let (cut_lo, cut_hi) = range(&cut);
    r.number("hero_cut.min", cut_lo, ".1");
    r.number("hero_cut.max", cut_hi, ".1");
    let cut_list = || {
        spectra
            .iter()
            .zip(&cut)
            .map(|((name, _), c)| format!("{name} {c:.2}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    r.claim(
        "hero_cut_large",
        cut.iter().all(|&c| c > 4.0),
        format!(
            "relative variance of one uniform wavelength over that of uniform hero lanes, each > 4: {}",
            cut_list()
        ),
    );
    r.claim(
        "hero_cut_below_y_cut",
        cut.iter().all(|&c| c < 20.0),
        format!(
            "relative variance of one uniform wavelength over that of uniform hero lanes, each < 20 (the test's cut on the Y of D65 is above 20): {}",
            cut_list()
        ),
    );
    // The source's band is at least as efficient as one uniform wavelength only on the
    // low-pressure sodium lamp.
    let helps = names(&|k| efficiency[k][seed] >= 1.0);
    r.claim(
        "band_helps_only_sodium",
        helps == ["low-pr. sodium"],
        format!(
            "spectra where the seed's band's efficiency is >= 1: {}",
            join_names(&helps)
        ),
    );
    // Rotating in sample space against rotating in wavelength space (balance heuristic over
    // the rotations): a relative variance smaller by a factor of 1.5 or more on every
    // spectrum (which does not depend on the machine), and the larger efficiency on every
    // spectrum (which does, but the sample-space lanes are also the cheaper).
    let by_spectrum = |xs: &[f64]| {
        spectra
            .iter()
            .zip(xs)
            .map(|((name, _), x)| format!("{name} {x:.2}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let variance_ratio: Vec<f64> = variance.iter().map(|v| v[balance] / v[hero]).collect();
    let (vr_lo, vr_hi) = range(&variance_ratio);
    r.number("balance_over_sample_space_variance.min", vr_lo, "s2");
    r.number("balance_over_sample_space_variance.max", vr_hi, "s2");
    r.claim(
        "sample_space_variance_smaller_by_1_5",
        variance_ratio.iter().all(|&x| x >= 1.5),
        format!(
            "relative variance of the wavelength-space balance over that of hero, visible pdf (sample space), each >= 1.5: {}",
            by_spectrum(&variance_ratio)
        ),
    );
    let ratio: Vec<f64> = efficiency.iter().map(|e| e[hero] / e[balance]).collect();
    let (ratio_lo, ratio_hi) = range(&ratio);
    r.number("sample_space_over_balance.min", ratio_lo, "s2");
    r.number("sample_space_over_balance.max", ratio_hi, "s2");
    r.claim(
        "sample_space_more_efficient",
        ratio.iter().all(|&x| x > 1.0),
        format!(
            "efficiency of hero, visible pdf (sample space) over that of the wavelength-space balance, each > 1: {}",
            by_spectrum(&ratio)
        ),
    );
    // The wavelength-space balance against uniform hero lanes: less efficient, and a larger
    // relative variance, on every spectrum.
    let not_below = names(&|k| efficiency[k][balance] >= efficiency[k][hero_uniform]);
    r.claim(
        "balance_below_hero_uniform",
        not_below.is_empty(),
        format!(
            "spectra where the wavelength-space balance is at least as efficient as hero, uniform: {}",
            join_names(&not_below)
        ),
    );
    let not_above = names(&|k| variance[k][balance] <= variance[k][hero_uniform]);
    r.claim(
        "balance_variance_above_hero_uniform",
        not_above.is_empty(),
        format!(
            "spectra where the wavelength-space balance's relative variance is not above that of hero, uniform: {}",
            join_names(&not_above)
        ),
    );
    // The low-pressure sodium lamp has the largest relative variance for every strategy.
    let sodium = spectra
        .iter()
        .position(|(name, _)| *name == "low-pr. sodium")
        .context("no low-pressure sodium spectrum")?;
    let easier: Vec<&str> = WavelengthStrategy::ALL
        .iter()
        .enumerate()
        .filter(|&(i, _)| {
            let column: Vec<f64> = variance.iter().map(|v| v[i]).collect();
            extreme(&column, f64::gt) != Some(sodium)
        })
        .map(|(_, s)| s.name())
        .collect();
    r.claim(
        "sodium_hardest",
        easier.is_empty(),
        format!(
            "strategies whose largest relative variance is not (alone) the low-pressure sodium lamp's: {}",
            join_names(&easier)
        ),
    );
    writeln!(
        md,
        "\n*{n} paths per cell (seeded); {}; median of {reps} batches of 2000 paths, the \
         strategies of a spectrum timed in turn, one batch each per round{}. The seed's band \
         uses 380–780 nm and 5 nm steps.*",
        timing::machine(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
