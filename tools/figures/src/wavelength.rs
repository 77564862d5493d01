//! Figures and tables of the chapter *Wavelength sampling and hero wavelengths*
//! (`chapters/spectral/wavelength.md`).

use std::fmt::Write as _;
use std::hint::black_box;

use glam::DVec3;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, BoxError, Panel, Series};
use raylemma::rng;
use raylemma::spectral::cie;
use raylemma::spectral::spectrum::{Spectrum, builtin};
use raylemma::spectral::wavelength::{
    N, SEED_BAND, SeedBand, Strategy, seed_band, seed_band_weight,
};
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

fn error_svg(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
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

fn efficiency_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let (n, reps) = if settings.quick {
        (20_000, 3)
    } else {
        (200_000, 11)
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
        times.push(
            Strategy::ALL
                .map(|s| ns_per_path(s, spectrum, reps))
                .to_vec(),
        );
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
    writeln!(
        md,
        "\n*{n} paths per cell (seeded); {}; median of {reps} batches of 2000 paths{}. \
         The seed's band uses 380–780 nm and 5 nm steps.*",
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

fn seed_bias_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
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
        r.number(
            &format!("{}.measured_400_700.z_std_error", spectrum_key(name)),
            z.std_error(),
            "x1",
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

fn speed_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
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
