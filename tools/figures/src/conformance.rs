//! The conformance card's false alarms at its defaults, measured: raylemma itself as the
//! candidate on every rung of the ladder at every depth, with `raylemma conformance`'s
//! default settings (4 runs of 64 spp, `--alpha 0.01` over the card), over many card
//! seeds; and, as the planted twin each comparison must reject, the same runs with the
//! light 2 % brighter. Chapter: *Reference scenes and interop*, *The conformance ladder*.
//!
//! A trial is one card: card seed `S` renders each rung's `K` runs with the seeds
//! `K (S - 1) + 1` to `K S`, as `raylemma conformance --seed S` does, and compares them with
//! the committed reference (`figures/reference/conformance/`), the candidate's variance
//! floored by the reference's ([`Estimate::floor_from_reference`]), at the card's Šidák
//! level. The same trial without the floor is the card as it was before the floor: the
//! false alarms the floor removes. The light 2 % brighter is every candidate mean times
//! 1.02: exactly the images of the same seeds under a brighter light, since every rung's
//! light is its only source and no sampling decision depends on its brightness.

use std::fmt::Write as _;

use rayon::prelude::*;

use super::{Output, Record, Settings};
use crate::timing::quick_note;
use raylemma::conformance::compare::{Estimate, compare};
use raylemma::conformance::ladder::{self, LADDER, Rung};
use raylemma::image::Image;
use raylemma::render::{self, Progress};
use raylemma::stats::binomial::wilson;
use raylemma::stats::sidak;

/// The outputs of this module.
pub fn outputs() -> Vec<Output> {
    vec![Output {
        file: "conformance_false_alarms.md",
        what: "the conformance card's false alarms at its defaults, raylemma against itself",
        make: false_alarms_md,
    }]
}

/// `raylemma conformance`'s defaults: runs, samples per pixel of each, the card's alpha.
const RUNS: u64 = 4;
const SPP: u32 = 64;
const ALPHA: f64 = 0.01;
/// The first of the spectral rungs (a lamp's line spectrum, a thin film, dispersion).
const SPECTRAL_FROM: u32 = 9;
/// The planted twin: the light this much brighter.
const BRIGHTER: f64 = 0.02;

/// One comparison's outcome in one card: a false alarm with the floor, without it, and
/// the brighter twin detected with the floor.
type Outcome = [bool; 3];

/// Every comparison of one card seed.
fn card(
    rungs: &[(Rung, Option<u32>, render::Scene, Estimate)],
    seed: u64,
    level: f64,
) -> anyhow::Result<Vec<Outcome>> {
    let mut out = Vec::new();
    for (_, _, scene, reference) in rungs {
        let images: Vec<Image> = (1..=RUNS)
            .map(|run| {
                let mut s = scene.clone();
                s.settings.seed = RUNS * (seed - 1) + run;
                render::render(&s, SPP, Progress::Silent)
            })
            .collect();
        let (w, h) = (reference.image.width, reference.image.height);
        let candidate = |gain: f64, floored: bool| -> anyhow::Result<Estimate> {
            let scaled: Vec<Vec<glam::DVec3>> = images
                .iter()
                .map(|i| i.mean.iter().map(|m| *m * gain).collect())
                .collect();
            let means: Vec<&[glam::DVec3]> = scaled.iter().map(|m| &m[..]).collect();
            let mut e = Estimate::from_spread(w, h, &means)?;
            if floored {
                e.floor_from_reference(reference, RUNS * u64::from(SPP));
            }
            Ok(e)
        };
        let differs =
            |e: Estimate| -> anyhow::Result<bool> { Ok(!compare(reference, &e, level)?.agree()) };
        out.push([
            differs(candidate(1.0, true)?)?,
            differs(candidate(1.0, false)?)?,
            differs(candidate(1.0 + BRIGHTER, true)?)?,
        ]);
    }
    Ok(out)
}

fn false_alarms_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let seeds: u64 = if settings.quick { 2 } else { 200 };
    let n = u32::try_from(seeds)?;
    let mut rungs = Vec::new();
    for rung in LADDER {
        for &depth in rung.depths {
            let mut scene =
                render::load(&settings.root.join("scenes/conformance").join(rung.file))?;
            if let Some(d) = depth {
                scene.settings.max_depth = d;
            }
            let path = settings
                .root
                .join("figures/reference/conformance")
                .join(format!("{}.exr", ladder::reference_name(&rung, depth)));
            let reference = Image::read_exr(&path)?;
            rungs.push((rung, depth, scene, Estimate::from_variance(reference)));
        }
    }
    let level = sidak(ALPHA, u32::try_from(rungs.len())?);
    let cards: Vec<Vec<Outcome>> = (1..=seeds)
        .into_par_iter()
        .map(|seed| card(&rungs, seed, level))
        .collect::<anyhow::Result<_>>()?;
    let count = |i: usize, k: usize| -> u32 { cards.iter().map(|c| u32::from(c[i][k])).sum() };
    let rate = |k: u32| {
        let (lo, hi) = wilson(k, n);
        format!("{k} ({:.1}–{:.1} %)", 100.0 * lo, 100.0 * hi)
    };
    let mut md = String::new();
    writeln!(
        md,
        "| rung | depth | false alarms of {n} cards (95 % interval) | without the floor | light {} % brighter detected |",
        100.0 * BRIGHTER
    )?;
    writeln!(md, "|---|---|---:|---:|---:|")?;
    let mut weakest = (n, String::new());
    for (i, (rung, depth, _, _)) in rungs.iter().enumerate() {
        let name = ladder::reference_name(rung, *depth);
        let detected = count(i, 2);
        if detected < weakest.0 {
            weakest = (detected, name.clone());
        }
        writeln!(
            md,
            "| {} `{}` | {} | {} | {} | {detected} of {n} |",
            rung.number,
            rung.file.trim_end_matches(".toml"),
            depth.map_or("own".to_string(), |d| d.to_string()),
            rate(count(i, 0)),
            rate(count(i, 1)),
        )?;
    }
    let cards_alarmed = |k: usize| -> u32 {
        cards
            .iter()
            .map(|c| u32::from(c.iter().any(|o| o[k])))
            .sum()
    };
    let (with, without) = (cards_alarmed(0), cards_alarmed(1));
    writeln!(
        md,
        "| **the card** | all {} | **{}** | **{}** | |",
        rungs.len(),
        rate(with),
        rate(without)
    )?;
    r.number("cards", f64::from(n), "int");
    r.number("comparisons", rungs.len() as f64, "int");
    r.number("card_false_alarms", f64::from(with), "int");
    r.number("card_false_alarms_without_floor", f64::from(without), "int");
    let (lo, hi) = wilson(with, n);
    r.number("card_upper_percent", 100.0 * hi, ".1");
    r.claim(
        "card_at_or_below_its_level",
        f64::from(with) <= ALPHA * f64::from(n),
        format!(
            "{with} of {n} cards with a false alarm ({:.1}–{:.1} %), at most {ALPHA} of them",
            100.0 * lo,
            100.0 * hi
        ),
    );
    r.claim(
        "without_floor_above_its_level",
        wilson(without, n).0 > ALPHA,
        format!(
            "without the floor {without} of {n} cards alarm; the 95 % interval starts at {:.3}, above {ALPHA}",
            wilson(without, n).0
        ),
    );
    // The rungs before the spectral ones (9: a lamp's line spectrum, 10: a thin film,
    // 11: dispersion), whose light is smooth in wavelength.
    let grey: Vec<usize> = (0..rungs.len())
        .filter(|&i| rungs[i].0.number < SPECTRAL_FROM)
        .collect();
    r.claim(
        "rungs_before_the_spectral_ones_detect_in_every_card",
        grey.iter().all(|&i| count(i, 2) == n),
        format!(
            "the light {} % brighter detected in all {n} cards on rungs 1 to {}: {}",
            100.0 * BRIGHTER,
            SPECTRAL_FROM - 1,
            grey.iter()
                .map(|&i| format!(
                    "{} {}",
                    ladder::reference_name(&rungs[i].0, rungs[i].1),
                    count(i, 2)
                ))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    r.number("weakest_detected", f64::from(weakest.0), "int");
    r.text("weakest_rung", format!("`{}`", weakest.1));
    writeln!(
        md,
        "\n*raylemma as its own candidate through the card's statistics at `raylemma conformance`'s defaults: each rung at each depth rendered {RUNS} times at {SPP} spp with the seeds of card seed S (`--seed S`: seeds {RUNS}(S − 1) + 1 to {RUNS}S), S = 1 to {n}, compared with the committed reference at the card's Šidák level for `--alpha {ALPHA}` over {} comparisons. A card alarms when any of its comparisons differs. \"Without the floor\": the candidate's variance from the spread of its runs alone, as the card had it before. The brighter light: every candidate mean times {}.{}*",
        rungs.len(),
        1.0 + BRIGHTER,
        quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
