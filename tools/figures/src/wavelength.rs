//! Figures and tables of the chapter *Wavelength sampling and hero wavelengths*
//! (`chapters/spectral/wavelength.md`).

use std::fmt::Write as _;
use std::hint::black_box;

use glam::DVec3;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, BoxError, Panel, Series};
use raylemma::rng;
use raylemma::spectral::cie;
use raylemma::spectral::spectrum::Table;
use raylemma::spectral::spectrum::{Spectrum, builtin};
use raylemma::spectral::wavelength::{
    N, SEED_BAND, SeedBand, Strategy, Wavelengths, hero_uniform, seed_band, seed_band_weight,
};
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN};
use raylemma::stats::ttest::Summary;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "wavelength_error.svg",
            what: "RMS relative error of XYZ against time per wavelength strategy",
            make: error_svg,
        },
        Output {
            file: "wavelength_efficiency.md",
            what: "variance per path, ns per path and efficiency per strategy and spectrum",
            make: efficiency_md,
        },
        Output {
            file: "wavelength_seed_bias.md",
            what: "bias of the seed's band, predicted and measured",
            make: seed_bias_md,
        },
        Output {
            file: "wavelength_dispersive_mis.md",
            what: "rough dispersive toy: termination, the hero's path pdf and Wilkie's weights",
            make: dispersive_mis_md,
        },
        Output {
            file: "wavelength_speed.md",
            what: "ns to generate the lanes per strategy",
            make: speed_md,
        },
    ]
}

/// The spectra of the chapter's tables: the five measured lamps, D65, A and a blackbody.
pub fn spectra() -> Vec<(&'static str, Spectrum)> {
    let t = |f: &str| Spectrum::Table(builtin(f));
    vec![
        ("incandescent", t("lamp_incandescent.csv")),
        ("cool white fl.", t("lamp_cool_white_fluorescent.csv")),
        ("LED (YAG)", t("lamp_phosphor_led_yag.csv")),
        ("high-pr. sodium", t("lamp_high_pressure_sodium.csv")),
        ("low-pr. sodium", t("lamp_low_pressure_sodium.csv")),
        ("D65", t("cie_illuminant_D65.csv")),
        ("A", t("cie_illuminant_A.csv")),
        (
            "blackbody 5000 K",
            Spectrum::Blackbody {
                kelvin: 5000.0,
                peak: 1.0,
            },
        ),
    ]
}

/// The XYZ estimate of one path.
fn path_xyz(s: Strategy, u: f64, spectrum: &Spectrum) -> DVec3 {
    s.sample(u).xyz(|l| spectrum.eval(l))
}

/// The mean over X, Y, Z of the squared relative error of `est`.
fn relative_sq(est: DVec3, exact: DVec3) -> f64 {
    ((est / exact - DVec3::ONE).powf(2.0)).element_sum() / 3.0
}

/// Median nanoseconds per item of each of `batches` (each processing `items` items per
/// call), timed in turn, one call of each per round, for `reps` rounds after a warm-up
/// call of each. A slow spell of the machine (another process on the core) then slows
/// every batch of the round alike, so the ratios of the medians, which the efficiency
/// tables print, are steadier than those of batches timed one after the other.
fn interleaved_ns(
    items: usize,
    reps: usize,
    batches: &mut [Box<dyn FnMut() -> u64 + '_>],
) -> Vec<f64> {
    for batch in batches.iter_mut() {
        black_box(batch());
    }
    let mut times = vec![Vec::with_capacity(reps); batches.len()];
    for _ in 0..reps.max(1) {
        for (batch, t) in batches.iter_mut().zip(&mut times) {
            let start = std::time::Instant::now();
            black_box(batch());
            t.push(start.elapsed().as_secs_f64() * 1e9 / items as f64);
        }
    }
    times
        .into_iter()
        .map(|mut t| {
            t.sort_by(f64::total_cmp);
            t[t.len() / 2]
        })
        .collect()
}

/// ns per path (lanes and XYZ estimate) of every strategy on `spectrum`, interleaved.
fn ns_per_path_all(spectrum: &Spectrum, reps: usize) -> Vec<f64> {
    let batch = 2000;
    let mut r = rng::seeded(0x7173);
    let us: Vec<f64> = (0..batch).map(|_| rng::uniform(&mut r, 0.0, 1.0)).collect();
    let us = &us;
    let mut batches: Vec<Box<dyn FnMut() -> u64 + '_>> = Strategy::ALL
        .iter()
        .map(|&s| {
            Box::new(move || {
                let mut acc = 0.0;
                for &u in us {
                    acc += path_xyz(s, black_box(u), spectrum).y;
                }
                acc.to_bits()
            }) as Box<dyn FnMut() -> u64 + '_>
        })
        .collect();
    interleaved_ns(batch, reps, &mut batches)
}

/// ns per path (lanes and XYZ estimate) of strategy `s` on `spectrum`.
fn ns_per_path(s: Strategy, spectrum: &Spectrum, reps: usize) -> f64 {
    let batch = 2000;
    let mut r = rng::seeded(0x7173);
    let us: Vec<f64> = (0..batch).map(|_| rng::uniform(&mut r, 0.0, 1.0)).collect();
    timing::median_ns_per_item(batch, reps, || {
        let mut acc = 0.0;
        for &u in &us {
            acc += path_xyz(s, black_box(u), spectrum).y;
        }
        acc.to_bits()
    })
}

/// Relative variance per path: the mean over X, Y, Z of `Var[est] / exact²`.
fn relative_variance(s: Strategy, spectrum: &Spectrum, exact: DVec3, n: usize) -> f64 {
    let mut r = rng::seeded(0x5EED);
    let mut sums = [Summary::default(), Summary::default(), Summary::default()];
    for _ in 0..n {
        let e = path_xyz(s, rng::uniform(&mut r, 0.0, 1.0), spectrum) / exact;
        for (k, sum) in sums.iter_mut().enumerate() {
            sum.push(e[k]);
        }
    }
    sums.iter().map(Summary::variance).sum::<f64>() / 3.0
}

fn error_svg(settings: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
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
        for s in Strategy::ALL {
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

/// A spectrum's name as a value name: `blackbody 5000 K` -> `blackbody_5000_k`.
fn spectrum_key(name: &str) -> String {
    let mut key = String::new();
    for c in name.to_lowercase().chars() {
        if c.is_ascii_alphanumeric() {
            key.push(c);
        } else if !key.ends_with('_') && !key.is_empty() {
            key.push('_');
        }
    }
    key.trim_end_matches('_').to_string()
}

/// A strategy as a value name (the renderer's names, `hero-visible` as `hero_visible`).
fn strategy_key(s: Strategy) -> &'static str {
    match s {
        Strategy::Uniform => "uniform",
        Strategy::Visible => "visible",
        Strategy::HeroUniform => "hero_uniform",
        Strategy::HeroVisible => "hero_visible",
        Strategy::HeroBalance => "hero_balance",
        Strategy::SeedBand => "seed_band",
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

fn efficiency_md(settings: &Settings, r: &mut Record) -> Result<Vec<u8>, BoxError> {
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
            Strategy::ALL
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
    for (i, s) in Strategy::ALL.iter().enumerate() {
        write!(md, "| {} |", s.name())?;
        for v in &variance {
            write!(md, " {:.4} |", v[i])?;
        }
        writeln!(md)?;
    }
    writeln!(md, "\n**ns per path** (lanes and the XYZ estimate)\n")?;
    header(&mut md, "strategy")?;
    for (i, s) in Strategy::ALL.iter().enumerate() {
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
    for (i, s) in Strategy::ALL.iter().enumerate() {
        write!(md, "| {} |", s.name())?;
        for ((name, _), e) in spectra.iter().zip(&efficiency) {
            let key = format!("{}.{}.efficiency", spectrum_key(name), strategy_key(*s));
            write!(md, " {} |", r.number(&key, e[i], ".2"))?;
        }
        writeln!(md)?;
    }
    let hero = Strategy::ALL
        .iter()
        .position(|&s| s == Strategy::HeroVisible)
        .ok_or("no hero-visible strategy")?;
    let seed = Strategy::ALL
        .iter()
        .position(|&s| s == Strategy::SeedBand)
        .ok_or("no seed's band strategy")?;
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
    let at = |s: Strategy| Strategy::ALL.iter().position(|&t| t == s).unwrap_or(0);
    let (uniform, hero_uniform, balance) = (
        at(Strategy::Uniform),
        at(Strategy::HeroUniform),
        at(Strategy::HeroBalance),
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
        .ok_or("no low-pressure sodium spectrum")?;
    let easier: Vec<&str> = Strategy::ALL
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

/// The readings of the seed's unspecified range and band spacing that the bias table shows.
pub fn seed_readings() -> Vec<(&'static str, SeedBand)> {
    let b = |lo, hi, spacing| SeedBand { lo, hi, spacing };
    vec![
        ("380–780, 5 nm (chapter)", SEED_BAND),
        ("380–780, 10 nm", b(380.0, 780.0, 10.0)),
        ("380–700, 5 nm", b(380.0, 700.0, 5.0)),
        ("400–700, 5 nm", b(400.0, 700.0, 5.0)),
        ("360–830, 5 nm", b(360.0, 830.0, 5.0)),
    ]
}

fn seed_bias_md(settings: &Settings, r: &mut Record) -> Result<Vec<u8>, BoxError> {
    let spectra = spectra();
    let readings = seed_readings();
    let mut md = String::new();
    writeln!(
        md,
        "**Predicted relative bias** `∫ w f / ∫ f − 1` of X / Y / Z (quadrature with the \
         seed's weight `w`, `seed_band_weight`)\n"
    )?;
    write!(md, "| spectrum |")?;
    for (name, _) in &readings {
        write!(md, " {name} |")?;
    }
    writeln!(md)?;
    writeln!(md, "|---|{}", "---:|".repeat(readings.len()))?;
    for (name, spectrum) in &spectra {
        let exact = cie::xyz(|l| spectrum.eval(l));
        write!(md, "| {name} |")?;
        for (k, (_, band)) in readings.iter().enumerate() {
            let biased = cie::xyz(|l| spectrum.eval(l) * seed_band_weight(l, band));
            let rel = biased / exact - DVec3::ONE;
            if k == 0 {
                // The chapter's reading, 380–780 nm at 5 nm.
                r.number(
                    &format!("{}.predicted_bias_z_380_780", spectrum_key(name)),
                    rel.z,
                    "x1",
                );
            }
            write!(md, " {:.1e} / {:.1e} / {:.1e} |", rel.x, rel.y, rel.z)?;
        }
        writeln!(md)?;
    }
    let n = if settings.quick { 200_000 } else { 4_000_000 };
    let band = readings[3].1;
    writeln!(
        md,
        "\n**Measured** with the reading 400–700 nm, 5 nm: relative error of the mean of {n} \
         paths ± its standard error, against the predicted bias\n"
    )?;
    writeln!(
        md,
        "| spectrum | X measured | X predicted | Z measured | Z predicted |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|")?;
    for (name, spectrum) in spectra
        .iter()
        .filter(|(n, _)| ["D65", "A", "blackbody 5000 K"].contains(n))
    {
        let exact = cie::xyz(|l| spectrum.eval(l));
        let biased = cie::xyz(|l| spectrum.eval(l) * seed_band_weight(l, &band));
        let mut g = rng::seeded(0xB1A5);
        let (mut x, mut z) = (Summary::default(), Summary::default());
        for _ in 0..n {
            let e = seed_band(rng::uniform(&mut g, 0.0, 1.0), &band).xyz(|l| spectrum.eval(l));
            x.push(e.x / exact.x - 1.0);
            z.push(e.z / exact.z - 1.0);
        }
        let key = spectrum_key(name);
        r.number(
            &format!("{key}.measured_400_700.z_std_error"),
            z.std_error(),
            "x1",
        );
        let z_predicted = biased.z / exact.z - 1.0;
        r.number(&format!("{key}.measured_400_700.z_measured"), z.mean, "x2");
        r.number(
            &format!("{key}.measured_400_700.z_predicted"),
            z_predicted,
            "x2",
        );
        // The measured bias is the predicted one within its noise (two standard errors).
        r.claim(
            &format!("{key}_z_measured_matches_predicted"),
            (z.mean - z_predicted).abs() < 2.0 * z.std_error(),
            format!(
                "{name}, Z, reading 400–700 nm: |measured {:.3e} − predicted {z_predicted:.3e}| < 2 × standard error {:.2e}",
                z.mean,
                z.std_error()
            ),
        );
        writeln!(
            md,
            "| {name} | {:.2e} ± {:.1e} | {:.2e} | {:.2e} ± {:.1e} | {:.2e} |",
            x.mean,
            x.std_error(),
            biased.x / exact.x - 1.0,
            z.mean,
            z.std_error(),
            biased.z / exact.z - 1.0
        )?;
    }
    writeln!(
        md,
        "\n*The band has {N} wavelengths `λ₀ + j · spacing`; `λ₀` uniform on the range.*"
    )?;
    Ok(md.into_bytes())
}

// ---------------------------------------------------------------------------------------
// A rough dispersive interface: termination, the hero's path pdf, Wilkie et al.'s weights.
// The toy of `tests/book/spectral/wavelength.rs` (anchor `rough`), with the same random
// numbers, here timed too: each choice evaluates only what it needs.

/// What a rough dispersive vertex does with the secondary lanes.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Secondaries {
    /// Terminate them, as at a delta event.
    Terminate,
    /// Keep them, each lane's throughput divided by the hero's path density.
    HeroPathPdf,
    /// Keep them, with Wilkie et al.'s balance heuristic over which lane was the hero.
    Wilkie,
}

impl Secondaries {
    const ALL: [Secondaries; 3] = [
        Secondaries::Terminate,
        Secondaries::HeroPathPdf,
        Secondaries::Wilkie,
    ];

    fn name(self) -> &'static str {
        match self {
            Secondaries::Terminate => "terminate",
            Secondaries::HeroPathPdf => "hero's path pdf for every lane",
            Secondaries::Wilkie => "Wilkie's weights",
        }
    }

    fn key(self) -> &'static str {
        match self {
            Secondaries::Terminate => "terminate",
            Secondaries::HeroPathPdf => "hero_pdf",
            Secondaries::Wilkie => "wilkie",
        }
    }
}

/// The refraction angle into N-BK7 of light arriving at 60°, radians.
fn refracted(nm: f64) -> f64 {
    let n = raylemma::optics::dispersion::material(raylemma::optics::dispersion::N_BK7).index(nm);
    (60f64.to_radians().sin() / n).asin()
}

/// The normal density of `x` with mean `m` and standard deviation `s`.
fn gauss(x: f64, m: f64, s: f64) -> f64 {
    (-0.5 * ((x - m) / s).powi(2)).exp() / (s * (2.0 * std::f64::consts::PI).sqrt())
}

/// The standard normal distribution function, from the χ² tail with one degree of freedom
/// (`P(χ²₁ > x²) = erfc(|x|/√2)`).
fn normal_cdf(x: f64) -> f64 {
    let tail = 0.5 * raylemma::stats::chi2::upper_tail(x * x, 1);
    if x < 0.0 { tail } else { 1.0 - tail }
}

/// The toy's estimate of `X + Y + Z` for uniform hero lanes at `u` and the direction
/// `θ = θ_t(λ_0) + σ z`: the light (D65) is seen in the directions refracted for 450-650 nm,
/// and lane `j`'s throughput is `D65(λ_j) g(θ; θ_t(λ_j), σ) / g(θ; θ_t(λ_0), σ)`.
fn rough_path(u: f64, z: f64, sigma: f64, how: Secondaries, d65: &Table, seen: (f64, f64)) -> f64 {
    let mut w: Wavelengths = hero_uniform(u);
    let theta = refracted(w.lambda[0]) + sigma * z;
    if !(seen.0..=seen.1).contains(&theta) {
        return 0.0;
    }
    let xyz = if how == Secondaries::Terminate {
        // Only the hero is left, and its lobe cancels its own path density.
        w.terminate_secondary();
        w.xyz(|l| d65.eval(l))
    } else {
        // p(θ | λ_k) for every lane: also the lane's lobe in its throughput.
        let lobe = w.lambda.map(|l| gauss(theta, refracted(l), sigma));
        let hero = lobe[0];
        if how == Secondaries::Wilkie {
            w.balance_path_pdfs(lobe);
        }
        let k = 1.0 / cie::y_integral();
        let mut sum = DVec3::ZERO;
        for ((&l, &p), &g) in w.lambda.iter().zip(&w.pdf).zip(&lobe) {
            if p > 0.0 {
                sum += d65.eval(l) * g / hero * k * cie::cmf(l) / p;
            }
        }
        sum / N as f64
    };
    xyz.element_sum()
}

/// The exact pixel of the toy: quadrature over λ of D65 times the lobe's mass in the window.
fn rough_exact(sigma: f64, d65: &Table, seen: (f64, f64)) -> f64 {
    cie::xyz(|l| {
        let t = refracted(l);
        d65.eval(l) * (normal_cdf((seen.1 - t) / sigma) - normal_cdf((seen.0 - t) / sigma))
    })
    .element_sum()
}

/// One cell group of the dispersive table: one choice at one lobe width.
#[derive(Clone, Copy, Debug, Default)]
struct Cell {
    /// Variance of one path's X + Y + Z over the exact value squared.
    variance: f64,
    /// The sample mean over the exact value.
    mean: f64,
    /// ns per path.
    ns: f64,
    /// (variance × ns) of terminate over that of this choice.
    efficiency: f64,
}

/// The lobe widths of the table, in units of the spread of the refraction angles.
const LOBE_RATIOS: [f64; 6] = [0.01, 0.1, 0.3, 1.0, 3.0, 10.0];

/// A lobe width as a value name: `0.3` -> `s0_3`.
fn ratio_key(ratio: f64) -> String {
    format!("s{ratio}").replace('.', "_")
}

fn dispersive_mis_md(settings: &Settings, r: &mut Record) -> Result<Vec<u8>, BoxError> {
    let (n, reps) = if settings.quick {
        (20_000, 5)
    } else {
        (200_000, 51)
    };
    let d65 = builtin("cie_illuminant_D65.csv");
    let seen = (refracted(450.0), refracted(650.0));
    let spread = refracted(LAMBDA_MAX) - refracted(LAMBDA_MIN);
    r.number("spread_deg", spread.to_degrees(), ".1");
    // The random numbers of the test (seed 16): u for the lanes, then z for the direction.
    let mut g = rng::seeded(16);
    let draws: Vec<(f64, f64)> = (0..n)
        .map(|_| {
            let u = rng::uniform(&mut g, 0.0, 1.0);
            (u, raylemma::stats::null::standard_normal(&mut g))
        })
        .collect();
    let batch = &draws[..2000.min(n)];
    let mut md = String::new();
    write!(md, "| σ / Δθ |")?;
    for how in Secondaries::ALL {
        write!(
            md,
            " {}: relative variance | mean / exact | ns per path | efficiency |",
            how.name()
        )?;
    }
    writeln!(md)?;
    writeln!(
        md,
        "|---:|{}",
        "---:|---:|---:|---:|".repeat(Secondaries::ALL.len())
    )?;
    // Per lobe width: (variance, ns, efficiency) of each choice.
    let mut rows = Vec::new();
    for ratio in LOBE_RATIOS {
        let sigma = ratio * spread;
        let exact = rough_exact(sigma, &d65, seen);
        let d65 = &d65;
        let mut batches: Vec<Box<dyn FnMut() -> u64 + '_>> = Secondaries::ALL
            .iter()
            .map(|&how| {
                Box::new(move || {
                    let mut acc = 0.0;
                    for &(u, z) in batch {
                        acc += rough_path(black_box(u), z, sigma, how, d65, seen);
                    }
                    acc.to_bits()
                }) as Box<dyn FnMut() -> u64 + '_>
            })
            .collect();
        let ns = interleaved_ns(batch.len(), reps, &mut batches);
        let mut cells = [Cell::default(); 3];
        for (k, how) in Secondaries::ALL.into_iter().enumerate() {
            let s = Summary::of(
                draws
                    .iter()
                    .map(|&(u, z)| rough_path(u, z, sigma, how, d65, seen)),
            );
            cells[k] = Cell {
                variance: s.variance() / (exact * exact),
                mean: s.mean / exact,
                ns: ns[k],
                efficiency: 0.0,
            };
        }
        let base = cells[0].variance * cells[0].ns;
        for c in &mut cells {
            c.efficiency = base / (c.variance * c.ns);
        }
        write!(md, "| {ratio} |")?;
        for (how, c) in Secondaries::ALL.iter().zip(cells) {
            let key = format!("{}.{}", ratio_key(ratio), how.key());
            write!(
                md,
                " {} | {} | {} | {} |",
                r.number(&format!("{key}.relative_variance"), c.variance, "s4"),
                r.number(&format!("{key}.mean_over_exact"), c.mean, ".3"),
                r.number(&format!("{key}.ns"), c.ns, "s3"),
                r.number(&format!("{key}.efficiency"), c.efficiency, "s3"),
            )?;
        }
        writeln!(md)?;
        rows.push((ratio, cells));
    }
    let (terminate, hero_pdf, wilkie) = (0, 1, 2);
    let row = |ratio: f64| {
        rows.iter()
            .find(|(x, _)| *x == ratio)
            .map(|(_, row)| *row)
            .ok_or_else(|| format!("no row σ/Δθ = {ratio}"))
    };
    let (narrow, wide) = (row(0.01)?, row(10.0)?);
    let (at_0_1, at_0_3) = (row(0.1)?, row(0.3)?);
    let between = [at_0_1, at_0_3];
    // The limits: with narrow lobes Wilkie's weights do what termination does, with wide ones
    // what the hero's path pdf does (variances within 2 %); in between Wilkie's variance is
    // more than 10 % below both.
    r.claim(
        "narrow_lobe_wilkie_is_termination",
        (narrow[wilkie].variance / narrow[terminate].variance - 1.0).abs() <= 0.02,
        format!(
            "σ/Δθ = 0.01: relative variance, Wilkie {:.4} within 2 % of terminate {:.4}",
            narrow[wilkie].variance, narrow[terminate].variance
        ),
    );
    r.claim(
        "wide_lobe_wilkie_is_hero_pdf",
        (wide[wilkie].variance / wide[hero_pdf].variance - 1.0).abs() <= 0.02,
        format!(
            "σ/Δθ = 10: relative variance, Wilkie {:.4} within 2 % of the hero's path pdf {:.4}",
            wide[wilkie].variance, wide[hero_pdf].variance
        ),
    );
    r.claim(
        "wilkie_variance_lowest_in_between",
        between.iter().all(|c| {
            c[wilkie].variance < 0.9 * c[terminate].variance
                && c[wilkie].variance < 0.9 * c[hero_pdf].variance
        }),
        format!(
            "σ/Δθ = 0.1 and 0.3: relative variance, Wilkie below 0.9 × terminate and 0.9 × the hero's path pdf: {}",
            between
                .iter()
                .map(|c| format!(
                    "{:.4} vs {:.4} and {:.4}",
                    c[wilkie].variance, c[terminate].variance, c[hero_pdf].variance
                ))
                .collect::<Vec<_>>()
                .join("; ")
        ),
    );
    // With the narrowest lobes the hero's path pdf makes fireflies too rare for the sample
    // to contain one: its sample mean is far below the exact value (each lane other than the
    // hero almost always adds nothing), so its variance and efficiency in that row mean
    // nothing.
    r.claim(
        "hero_pdf_sample_misses_its_fireflies_narrow",
        narrow[hero_pdf].mean < 0.5,
        format!(
            "σ/Δθ = 0.01: the hero's path pdf, sample mean / exact {:.4} < 0.5",
            narrow[hero_pdf].mean
        ),
    );
    // Efficiency, which also counts the time per path. Against the hero's path pdf, which
    // evaluates the same lobes, Wilkie's weights win where they help. Against termination,
    // which evaluates one lane, they cost more than 1.5 times the time per path in this toy
    // (whose one vertex is the whole path): termination stays the more efficient at
    // σ/Δθ = 0.1, and at 0.3 the two are within a factor of 2.
    let show = |pick: usize| {
        between
            .iter()
            .map(|c| format!("{:.3}", c[pick].efficiency))
            .collect::<Vec<_>>()
            .join(", ")
    };
    r.claim(
        "wilkie_beats_hero_pdf_in_between",
        between
            .iter()
            .all(|c| c[wilkie].efficiency > c[hero_pdf].efficiency),
        format!(
            "σ/Δθ = 0.1, 0.3: efficiency relative to terminate, Wilkie {} > the hero's path pdf {}",
            show(wilkie),
            show(hero_pdf)
        ),
    );
    let time_ratio: Vec<f64> = between
        .iter()
        .map(|c| c[wilkie].ns / c[terminate].ns)
        .collect();
    r.number("s0_1.wilkie_over_terminate_ns", time_ratio[0], "s2");
    r.number("s0_3.wilkie_over_terminate_ns", time_ratio[1], "s2");
    r.claim(
        "wilkie_costs_more_than_terminate_in_between",
        time_ratio.iter().all(|&x| x > 1.5),
        format!(
            "σ/Δθ = 0.1, 0.3: ns per path, Wilkie over terminate, each > 1.5: {:.2}, {:.2}",
            time_ratio[0], time_ratio[1]
        ),
    );
    r.claim(
        "terminate_more_efficient_at_0_1",
        at_0_1[wilkie].efficiency < 1.0,
        format!(
            "σ/Δθ = 0.1: Wilkie's efficiency relative to terminate {:.3} < 1",
            at_0_1[wilkie].efficiency
        ),
    );
    r.claim(
        "wilkie_within_factor_2_of_terminate_at_0_3",
        (0.5..2.0).contains(&at_0_3[wilkie].efficiency),
        format!(
            "σ/Δθ = 0.3: 0.5 <= Wilkie's efficiency relative to terminate {:.3} < 2",
            at_0_3[wilkie].efficiency
        ),
    );
    writeln!(
        md,
        "\n*The toy of `tests/book/spectral/wavelength.rs` (anchor `rough`): light at 60° refracts \
         into N-BK7 at θ_t(λ), a lobe of width σ spreads it, and D65 is seen in the directions \
         refracted for 450–650 nm; Δθ = θ_t(830) − θ_t(360) = {:.2}°. Uniform hero lanes, {N} \
         per path; {n} paths per cell with the same random numbers for every choice (seed 16, \
         as the test). Relative variance: of one path's X + Y + Z, over the exact value squared. \
         Mean / exact: the sample mean over the exact value (far from 1, the sample has \
         not seen the estimator's rare large values, and its variance means nothing). ns per \
         path: the lanes and this one vertex, each choice evaluating only what it needs \
         (terminate: the hero's refraction; the other two: every lane's refraction and lobe); \
         {}, median of {reps} batches of {} paths, the three choices timed in turn{}. \
         Efficiency: (variance × ns) of terminate over (variance × ns) of the choice.*",
        spread.to_degrees(),
        timing::machine(),
        batch.len(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}

fn speed_md(settings: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    let reps = if settings.quick { 5 } else { 101 };
    let us = raylemma::workload::uniform_inputs(4096);
    let mut md = String::new();
    writeln!(md, "| strategy | ns to generate the {N} lanes |")?;
    writeln!(md, "|---|---:|")?;
    for s in Strategy::ALL {
        let ns = timing::median_ns_per_input(&us, reps, |u| {
            let w = s.sample(u);
            w.lambda[3] + w.pdf[0]
        });
        writeln!(md, "| {} | {ns:.1} |", s.name())?;
    }
    writeln!(
        md,
        "\n*{}; 4096 random u per batch, median of {reps} batches{}.*",
        timing::machine(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
