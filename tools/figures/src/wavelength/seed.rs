//! The bias of the seed's band, predicted and measured, for each reading of its range and
//! spacing (`wavelength_seed_bias.md`), of the chapter *Wavelength sampling and hero
//! wavelengths*.

use std::fmt::Write as _;

use glam::DVec3;

use super::{spectra, spectrum_key};
use crate::{Record, Settings};
use raylemma::rng;
use raylemma::spectral::cie;
use raylemma::spectral::wavelength::{N, SEED_BAND, SeedBand, seed_band, seed_band_weight};
use raylemma::stats::ttest::Summary;

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

pub(super) fn seed_bias_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
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
