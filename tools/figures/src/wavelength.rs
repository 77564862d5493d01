//! Figures and tables of the chapter *Wavelength sampling and hero wavelengths*
//! (`chapters/spectral/wavelength.md`).
//!
//! The modules: [`measure`] (a strategy's estimate, error, variance and time per path),
//! [`efficiency`] (the error figure and the efficiency table), [`seed`] (the bias of the
//! seed's band) and [`rough`] (the rough dispersive toy). This module holds the outputs, the
//! spectra of the tables and the timing of the lanes.

mod efficiency;
mod measure;
mod rough;
mod seed;

use std::fmt::Write as _;

use super::{Output, Record, Settings, timing};
use raylemma::spectral::spectrum::{Spectrum, builtin};
use raylemma::spectral::wavelength::{N, WavelengthStrategy};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "wavelength_error.svg",
            what: "RMS relative error of XYZ against time per wavelength strategy",
            make: efficiency::error_svg,
        },
        Output {
            file: "wavelength_efficiency.md",
            what: "variance per path, ns per path and efficiency per strategy and spectrum",
            make: efficiency::efficiency_md,
        },
        Output {
            file: "wavelength_seed_bias.md",
            what: "bias of the seed's band, predicted and measured",
            make: seed::seed_bias_md,
        },
        Output {
            file: "wavelength_dispersive_mis.md",
            what: "rough dispersive toy: termination, the hero's path pdf and Wilkie's weights",
            make: rough::dispersive_mis_md,
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

fn speed_md(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let reps = if settings.quick { 5 } else { 101 };
    let us = raylemma::workload::uniform_inputs(4096);
    let mut md = String::new();
    writeln!(md, "| strategy | ns to generate the {N} lanes |")?;
    writeln!(md, "|---|---:|")?;
    for s in WavelengthStrategy::ALL {
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
