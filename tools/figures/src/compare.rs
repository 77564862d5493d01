//! The renderer chapter's calibration of `compare` with few candidates: how often it calls
//! a correct candidate different (false alarms at the stated 1 %), with the variance from
//! the spread of 2, 4 or 16 plain images or from one image's own variance channels, next
//! to the same comparisons with normal critical values (the mistake the degrees of freedom
//! correct); and how often it notices a scene 1 % and 3 % brighter.
//!
//! Every trial renders its own reference (many samples per pixel, with its `spp`) and its
//! own candidates (independent seeds), so that the trials are independent. The brighter
//! scenes are the same candidates with every pixel multiplied by `1 + b`: exactly the
//! images of the scene with a light `1 + b` times brighter and the same seeds (the light's
//! spectrum enters every path as a factor; nothing else depends on it).

use std::fmt::Write as _;

use rayon::prelude::*;

use super::{Output, Record, Settings};
use crate::timing::quick_note;
use raylemma::conformance::compare::{Estimate, block_chance, compare, test_level};
use raylemma::image::{Image, ImageError};
use raylemma::render::{self, Progress};
use raylemma::rng;
use raylemma::stats::binomial::wilson;
use raylemma::stats::two_sided_critical;

/// The outputs of this module.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "render_compare_calibration.md",
            what: "false alarms and power of compare with few candidates",
            make: calibration_md,
        },
        Output {
            file: "compare_region_guard.md",
            what: "a block's false alarms and power, plug-in and guarded",
            make: guard_md,
        },
    ]
}

/// The block test of a 32 x 32 comparison at `--alpha 0.01` ([`block_chance`]) with the
/// plug-in and the guarded degrees of freedom: its false alarms as multiples of its level,
/// with the variance spread evenly and with one pixel carrying a thousand and a million
/// times the others'; and its power, spread evenly, against the bias that a test with the
/// exact variance finds half the time, and twice that bias.
fn guard_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let level = test_level(32, 32, ALPHA);
    let half = two_sided_critical(level);
    let mut rng = rng::seeded(0x000b_10c5);
    let mut md = String::new();
    // The guarded false alarms over the level, and the plug-in ones with a pixel 1000x.
    let (mut guarded_worst, mut plug_in_least) = (0.0_f64, f64::INFINITY);
    writeln!(
        md,
        "| candidate | degrees of freedom of a pixel | false alarms ÷ level, spread evenly: plug-in, guarded | one pixel 1000×: plug-in, guarded | one pixel 10⁶×: plug-in, guarded | power, spread evenly, at the half-power bias: plug-in, guarded | at twice it: plug-in, guarded |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|---:|")?;
    let ratio = |r: &mut Record, key: &str, x: f64| {
        if x < 0.01 {
            r.text(key, "< 0.01")
        } else {
            r.number(key, x, "s2")
        }
    };
    for (what, nu) in [
        ("2 plain images", 1),
        ("4 plain images", 3),
        ("16 plain images", 15),
        ("1 image of 64 spp", 63),
    ] {
        let mut cells = Vec::new();
        for rho in [1.0, 1e3, 1e6] {
            let pair: Vec<String> = [false, true]
                .iter()
                .map(|&guarded| {
                    let x = block_chance(nu, rho, 0.0, guarded, level, &mut rng) / level;
                    if guarded && rho > 1.0 {
                        guarded_worst = guarded_worst.max(x);
                    } else if !guarded && rho == 1e3 && nu < 63 {
                        plug_in_least = plug_in_least.min(x);
                    }
                    let key = format!(
                        "nu{nu}.{}.{}",
                        if guarded { "guarded" } else { "plug_in" },
                        match rho as u64 {
                            1 => "even",
                            1000 => "thousand",
                            _ => "million",
                        }
                    );
                    ratio(r, &key, x)
                })
                .collect();
            cells.push(pair.join(", "));
        }
        for (bias, name) in [(half, "power"), (2.0 * half, "power_twice")] {
            let pair: Vec<String> = [false, true]
                .iter()
                .map(|&guarded| {
                    let p = block_chance(nu, 1.0, bias, guarded, level, &mut rng);
                    let key = format!(
                        "nu{nu}.{}.{name}",
                        if guarded { "guarded" } else { "plug_in" }
                    );
                    r.number(&key, p, ".2")
                })
                .collect();
            cells.push(pair.join(", "));
        }
        writeln!(md, "| {what} | {nu} | {} |", cells.join(" | "))?;
    }
    r.claim(
        "guarded_within_the_level",
        guarded_worst <= 1.0,
        format!("the guarded false alarms with one pixel carrying the block at most {guarded_worst:.3} x the level"),
    );
    r.claim(
        "plug_in_liberal_with_a_carrying_pixel",
        plug_in_least > 3.0,
        format!("the plug-in false alarms with one pixel 1000x at least {plug_in_least:.2} x the level with 2, 4 and 16 images"),
    );
    writeln!(
        md,
        "\n*One 16×16 block of a 32×32 comparison at `--alpha {ALPHA}` (each test at {level:.2e}): the candidate's pixel variances estimated with the degrees of freedom shown and not floored, the reference exact with a sixteenth of the candidate's variance. Chances computed, not counted (`block_chance`): exact given the variance estimates for normal samples, the carrying pixel's estimate stratified down to a chance of 1e-12; spread evenly, a Monte Carlo average over about 200 draws of the estimates, good to about 1 %. The half-power bias is the one a test with the exact variance detects half the time ({half:.2} standard errors of the block's mean).*"
    )?;
    Ok(md.into_bytes())
}

/// The family-wise level of the calibrated comparisons (`compare`'s default).
const ALPHA: f64 = 0.01;
/// The planted brightenings.
const GAINS: [f64; 2] = [0.01, 0.03];
/// Side of the images (the whole scene at this resolution).
const SIDE: u32 = 32;
/// Samples per pixel of each plain candidate image.
const CANDIDATE_SPP: u32 = 64;
/// Samples per pixel of the reference.
const REFERENCE_SPP: u32 = 1024;
/// The candidate sets: `0` is one image of `16 * CANDIDATE_SPP` samples with its own
/// variance channels; the others are that many plain images.
const SETS: [usize; 4] = [0, 2, 4, 16];

/// The counts of one candidate set over all trials.
#[derive(Clone, Copy, Default)]
struct Counts {
    false_alarms: u32,
    bare_false_alarms: u32,
    normal_false_alarms: u32,
    detected: [u32; 2],
    bare_detected: u32,
    mean_z2: f64,
}

/// One candidate set's outcome in one trial: false alarm, false alarm without the floor,
/// false alarm with normal critical values (and no floor), detected at each gain, the
/// larger gain detected without the floor, mean z².
type Outcome = (bool, bool, bool, [bool; 2], bool, f64);

/// One trial: the outcome of each candidate set.
fn trial(scene: &raylemma::render::Scene, k: u64) -> Result<Vec<Outcome>, ImageError> {
    let seeded = |seed: u64| {
        let mut s = scene.clone();
        s.settings.seed = seed;
        s
    };
    let base = 1_000 + 100 * k;
    let reference = Estimate::from_variance(render::render(
        &seeded(base),
        REFERENCE_SPP,
        Progress::Silent,
    ));
    let plain: Vec<Image> = (0..16)
        .map(|j| render::render(&seeded(base + 1 + j), CANDIDATE_SPP, Progress::Silent))
        .collect();
    let one = render::render(&seeded(base + 50), 16 * CANDIDATE_SPP, Progress::Silent);
    let mut out = Vec::new();
    for &set in &SETS {
        // As `raylemma compare` has it: floored by the reference's per-sample variance over
        // the candidate's samples, when `floored`.
        let candidate = |gain: f64, floored: bool| -> Result<Estimate, ImageError> {
            let samples = CANDIDATE_SPP as u64 * if set == 0 { 16 } else { set as u64 };
            let floor = |mut e: Estimate| {
                if floored {
                    e.floor_from_reference(&reference, samples);
                }
                e
            };
            if set == 0 {
                let mut image = one.clone();
                for m in &mut image.mean {
                    *m *= gain;
                }
                for v in &mut image.var {
                    *v *= gain * gain;
                }
                return Ok(floor(Estimate::from_variance(image)));
            }
            let scaled: Vec<Vec<glam::DVec3>> = plain[..set]
                .iter()
                .map(|i| i.mean.iter().map(|m| *m * gain).collect())
                .collect();
            let means: Vec<&[glam::DVec3]> = scaled.iter().map(|m| &m[..]).collect();
            Estimate::from_spread(SIDE, SIDE, &means).map(floor)
        };
        let correct = candidate(1.0, true)?;
        let same = compare(&reference, &correct, ALPHA)?;
        let bare = compare(&reference, &candidate(1.0, false)?, ALPHA)?;
        let mut normal = candidate(1.0, false)?;
        normal.dof = f64::INFINITY;
        let mut normal_ref = reference.clone();
        normal_ref.dof = f64::INFINITY;
        let wrong = compare(&normal_ref, &normal, ALPHA)?;
        let mut detected = [false; 2];
        for (d, g) in detected.iter_mut().zip(GAINS) {
            *d = !compare(&reference, &candidate(1.0 + g, true)?, ALPHA)?.agree();
        }
        let bare_detected =
            !compare(&reference, &candidate(1.0 + GAINS[1], false)?, ALPHA)?.agree();
        out.push((
            !same.agree(),
            !bare.agree(),
            !wrong.agree(),
            detected,
            bare_detected,
            same.mean_z2,
        ));
    }
    Ok(out)
}

/// The comparisons the renderer chapter states about the calibration table, each as strong
/// as its sentence.
fn calibration_claims(r: &mut Record, all: &[(&str, usize, Counts)], n: u32) {
    let get = |scene: &str, set: usize| {
        all.iter()
            .find(|(s, k, _)| *s == scene && *k == set)
            .map(|(_, _, c)| *c)
            .unwrap_or_default()
    };
    let list = |f: &dyn Fn(&Counts) -> String| {
        all.iter()
            .map(|(s, k, c)| format!("{s} {}: {}", set_name(*k), f(c)))
            .collect::<Vec<_>>()
            .join("; ")
    };
    let worst = all
        .iter()
        .map(|(_, _, c)| c.false_alarms)
        .max()
        .unwrap_or(0);
    r.number("max_false_alarms", f64::from(worst), "int");
    r.number("trials", f64::from(n), "int");
    let bare_worst = all
        .iter()
        .map(|(_, _, c)| c.bare_false_alarms)
        .max()
        .unwrap_or(0);
    r.number("max_bare_false_alarms", f64::from(bare_worst), "int");
    r.claim(
        "floor_adds_no_false_alarm",
        all.iter()
            .all(|(_, _, c)| c.false_alarms <= c.bare_false_alarms),
        format!(
            "false alarms with the floor at most those without it, in every row: {}",
            list(&|c| format!("{} and {}", c.false_alarms, c.bare_false_alarms))
        ),
    );
    let contains = |k: u32| {
        let (lo, hi) = wilson(k, n);
        lo <= ALPHA && ALPHA <= hi
    };
    r.claim(
        "every_interval_contains_the_level",
        all.iter().all(|(_, _, c)| contains(c.false_alarms)),
        format!(
            "false alarms of {n} trials, each row's 95 % Wilson interval must contain {ALPHA}: {}",
            list(&|c| {
                let (lo, hi) = wilson(c.false_alarms, n);
                format!("{} ({lo:.3}-{hi:.3})", c.false_alarms)
            })
        ),
    );
    let few = [
        ("cornell-diffuse", 2),
        ("cornell-diffuse", 4),
        ("cornell", 2),
        ("cornell", 4),
    ];
    r.claim(
        "normal_values_alarm_in_most_trials_with_few_images",
        few.iter()
            .all(|&(s, k)| 2 * get(s, k).normal_false_alarms > n),
        format!(
            "with normal critical values, more than half of {n}: {}",
            list(&|c| c.normal_false_alarms.to_string())
        ),
    );
    let sixteen = get("cornell-diffuse", 16).normal_false_alarms;
    r.claim(
        "normal_values_alarm_too_often_with_sixteen",
        wilson(sixteen, n).0 > ALPHA,
        format!(
            "cornell-diffuse, 16 images, normal critical values: {sixteen} of {n}, 95 % interval from {:.3}, above {ALPHA}",
            wilson(sixteen, n).0
        ),
    );
    r.claim(
        "one_image_columns_equal",
        SCENES.iter().all(|s| {
            let c = get(s, 0);
            c.false_alarms == c.normal_false_alarms
        }),
        format!(
            "one image with its variance channels: false alarms and with normal values: {}",
            list(&|c| format!("{} and {}", c.false_alarms, c.normal_false_alarms))
        ),
    );
    r.claim(
        "mean_z2_falls_below_one_with_fewer_images",
        SCENES.iter().all(|s| {
            let z = |k| get(s, k).mean_z2;
            z(2) < z(4) && z(4) < z(16) && z(16) < 1.0
        }),
        format!(
            "mean z² of 2 < 4 < 16 images < 1: {}",
            list(&|c| format!("{:.3}", c.mean_z2))
        ),
    );
    r.claim(
        "diffuse_three_percent_noticed_by_every_set",
        SETS.iter()
            .all(|&k| get("cornell-diffuse", k).detected[1] == n),
        format!(
            "cornell-diffuse, 3 % brighter, detected in all {n}: {}",
            list(&|c| c.detected[1].to_string())
        ),
    );
    r.claim(
        "diffuse_one_percent_noticed_by_sixteen_and_one_image",
        [0, 16].iter().all(|&k| 10 * get("cornell-diffuse", k).detected[0] >= 9 * n),
        format!("cornell-diffuse, 1 % brighter, detected in at least 90 % of {n} by 16 images and by one image: {}", list(&|c| c.detected[0].to_string())),
    );
    r.claim(
        "cornell_three_percent_only_sixteen_and_one_image",
        [0, 16].iter().all(|&k| 2 * get("cornell", k).detected[1] > n)
            && [2, 4].iter().all(|&k| 10 * get("cornell", k).detected[1] < n),
        format!("cornell, 3 % brighter: 16 images and one image in more than half of {n}, 2 and 4 images in under a tenth: {}", list(&|c| c.detected[1].to_string())),
    );
    r.claim(
        "cornell_one_percent_noticed_by_none",
        SETS.iter()
            .all(|&k| 20 * get("cornell", k).detected[0] <= n),
        format!(
            "cornell, 1 % brighter, at most 5 % of {n} in every row: {}",
            list(&|c| c.detected[0].to_string())
        ),
    );
}

/// The scenes calibrated: `cornell-diffuse` (every surface diffuse: next-event estimation
/// does the work, pixels are nearly normal) and `cornell` (caustics through the glass and
/// the mirror: heavy-tailed pixels).
const SCENES: [&str; 2] = ["cornell-diffuse", "cornell"];

/// The counts of every candidate set over `trials` trials of `name`.
fn calibrate(settings: &Settings, name: &str, trials: u64) -> anyhow::Result<[Counts; 4]> {
    let mut scene = render::load(&settings.root.join("scenes").join(format!("{name}.toml")))?;
    scene.camera.width = SIDE;
    scene.camera.height = SIDE;
    let results: Vec<Vec<Outcome>> = (0..trials)
        .into_par_iter()
        .map(|k| trial(&scene, k))
        .collect::<Result<_, _>>()?;
    let mut counts = [Counts::default(); SETS.len()];
    for r in &results {
        for (c, &(fa, bfa, nfa, det, bdet, z2)) in counts.iter_mut().zip(r) {
            c.false_alarms += u32::from(fa);
            c.bare_false_alarms += u32::from(bfa);
            c.normal_false_alarms += u32::from(nfa);
            for (d, x) in c.detected.iter_mut().zip(det) {
                *d += u32::from(x);
            }
            c.bare_detected += u32::from(bdet);
            c.mean_z2 += z2 / trials as f64;
        }
    }
    Ok(counts)
}

/// A candidate set as a value name: `one_image`, `plain2`, `plain4`, `plain16`.
fn set_name(set: usize) -> String {
    if set == 0 {
        "one_image".into()
    } else {
        format!("plain{set}")
    }
}

fn calibration_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let trials: u64 = if settings.quick { 2 } else { 200 };
    let n = u32::try_from(trials)?;
    let rate = |k: u32| {
        let (lo, hi) = wilson(k, n);
        format!(
            "{k} ({:.1} %; {:.1}–{:.1} %)",
            100.0 * f64::from(k) / f64::from(n),
            100.0 * lo,
            100.0 * hi
        )
    };
    let mut md = String::new();
    writeln!(
        md,
        "| scene | candidate | degrees of freedom of a pixel | false alarms (nominal 1 %; 95 % interval) | without the floor | with normal critical values | 1 % brighter detected | 3 % brighter detected | 3 % brighter detected without the floor | mean z² |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")?;
    let mut all = Vec::new();
    for name in SCENES {
        let counts = calibrate(settings, name, trials)?;
        for (&set, c) in SETS.iter().zip(&counts) {
            let (what, dof) = if set == 0 {
                (
                    format!(
                        "1 image of {} spp with its variance channels",
                        16 * CANDIDATE_SPP
                    ),
                    16 * CANDIDATE_SPP - 1,
                )
            } else {
                (
                    format!("{set} plain images of {CANDIDATE_SPP} spp"),
                    set as u32 - 1,
                )
            };
            let key = format!("{}.{}", name.replace('-', "_"), set_name(set));
            let count = |r: &mut Record, what: &str, k: u32| {
                r.number(&format!("{key}.{what}"), f64::from(k), "int")
            };
            count(r, "false_alarms", c.false_alarms);
            count(r, "normal_false_alarms", c.normal_false_alarms);
            count(r, "bare_false_alarms", c.bare_false_alarms);
            writeln!(
                md,
                "| `{name}` | {what} | {dof} | {} | {} | {} | {} of {n} | {} of {n} | {} of {n} | {} |",
                rate(c.false_alarms),
                rate(c.bare_false_alarms),
                rate(c.normal_false_alarms),
                count(r, "detected_1pc", c.detected[0]),
                count(r, "detected_3pc", c.detected[1]),
                count(r, "bare_detected_3pc", c.bare_detected),
                r.number(&format!("{key}.mean_z2"), c.mean_z2, ".3"),
            )?;
            all.push((name, set, *c));
        }
    }
    calibration_claims(r, &all, n);
    writeln!(
        md,
        "\n*Each scene at {SIDE}x{SIDE} pixels, {trials} trials, each with its own reference of {REFERENCE_SPP} spp and its own candidates (independent seeds), compared at `--alpha {ALPHA}`, the candidate's variance floored by the reference's per-sample variance over its samples, as `raylemma compare` does when it knows the candidate's samples per pixel. \"Without the floor\": the candidate's own variance alone, and so the region tests guarded against a pixel whose variance came out small. \"Normal critical values\": the comparisons without the floor with both sides' degrees of freedom taken as infinite. The brighter scenes are the candidates with every pixel {} % higher: the images of the same seeds under a light that much brighter.{}*",
        GAINS
            .iter()
            .map(|g| format!("{}", 100.0 * g))
            .collect::<Vec<_>>()
            .join(" and "),
        quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
