//! Tables of the chapter *Testing the renderer*: the power of each renderer check against
//! planted biases of known size, and its false alarms, over many seeds.
//!
//! Each check's images are rendered once per seed; biases are then planted in copies of the
//! images (every pixel `1 + b` times brighter, or only the block at the image's middle) and
//! the check's own test is run on each copy at the level it has in `cargo test` (the
//! suite's per-test level, shared by Šidák between the check's scenes).

use std::fmt::Write as _;

use rayon::prelude::*;

use super::{Output, Record, Settings};
use raylemma::check::Options;
use raylemma::check::render::independence::{self, render_independence};
use raylemma::check::render::pool::pool_blocks;
use raylemma::check::render::{
    Rendered, Renderer, edge_scenes, ours, planted, references, render_agreement, render_exact,
    render_exact_of,
};
use raylemma::image::Image;
use raylemma::render::Scene;
use raylemma::stats::{sidak, test_alpha};
use raylemma_values::slug;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![Output {
        file: "render_test_power.md",
        what: "power of the renderer checks",
        make: power_md,
    }]
}

/// The planted biases, relative.
const BIASES: [f64; 16] = [
    0.001, 0.002, 0.003, 0.005, 0.0075, 0.01, 0.015, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3,
    0.5,
];

/// Whether the check's test of `r` (at `level`) fails with `plant` applied to its image.
fn fails(r: &Rendered, level: f64, plant: impl Fn(&mut Rendered)) -> bool {
    let mut r = r.clone();
    plant(&mut r);
    !pool_blocks(&r.image, &r.expected, level, r.block).passed()
}

/// The centre block of `r`'s image, aligned to its blocks.
fn centre(r: &Rendered) -> (u32, u32) {
    let b = r.block;
    (r.image.width / 2 / b * b, r.image.height / 2 / b * b)
}

/// One row: the smallest bias detected in at least 9 of 10 seeds, globally and in the
/// centre block, and the false alarms without a bias.
struct Row {
    check: &'static str,
    name: String,
    pixels: usize,
    block: u32,
    global: Option<f64>,
    local: Option<f64>,
    false_alarms: usize,
}

fn rows_of(check: &'static str, runs: &[Vec<Rendered>]) -> Vec<Row> {
    let items = runs[0].len();
    let level = sidak(test_alpha(), items as u32);
    let seeds = runs.len();
    let need = (9 * seeds).div_ceil(10);
    (0..items)
        .map(|i| {
            let smallest = |plant: &dyn Fn(&mut Rendered, f64)| {
                BIASES.iter().copied().find(|&b| {
                    runs.iter()
                        .filter(|run| fails(&run[i], level, |r| plant(r, b)))
                        .count()
                        >= need
                })
            };
            Row {
                check,
                name: runs[0][i].name.clone(),
                pixels: runs[0][i].expected.tested(),
                block: runs[0][i].block,
                global: smallest(&|r, b| planted::brighten(&mut r.image, b)),
                local: smallest(&|r, b| {
                    let at = centre(r);
                    let side = r.block;
                    planted::brighten_square(&mut r.image, b, at, side);
                }),
                false_alarms: runs
                    .iter()
                    .filter(|run| fails(&run[i], level, |_| ()))
                    .count(),
            }
        })
        .collect()
}

fn percent(b: Option<f64>) -> String {
    b.map_or_else(|| "> 50 %".into(), |b| format!("{} %", 100.0 * b))
}

/// The comparisons the chapter *Testing the renderer* states about the power table.
fn power_claims(rec: &mut Record, rows: &[Row]) {
    let smooth = [
        "floor under a quad light",
        "floor under a sphere light",
        "glass sphere in a sky",
        "mirror sphere in a sky",
        "thin film in a sky",
    ];
    let global = |check: &str, name: &str| {
        rows.iter()
            .find(|r| r.check == check && r.name == name)
            .and_then(|r| r.global)
            .unwrap_or(f64::INFINITY)
    };
    let read = |names: &[&str], check: &str| {
        names
            .iter()
            .map(|n| format!("{n}: {}", percent(Some(global(check, n)))))
            .collect::<Vec<_>>()
            .join("; ")
    };
    rec.claim(
        "exact_smooth_below_one_percent",
        smooth.iter().all(|n| global("exact", n) < 0.01),
        format!("smallest global bias below 1 %: {}", read(&smooth, "exact")),
    );
    rec.claim(
        "exact_smooth_at_most_half_a_percent",
        smooth.iter().all(|n| global("exact", n) <= 0.005),
        format!(
            "smallest global bias at most 0.5 %: {}",
            read(&smooth, "exact")
        ),
    );
    let agreement: Vec<&str> = rows
        .iter()
        .filter(|r| r.check == "agreement")
        .map(|r| r.name.as_str())
        .collect();
    let worst = agreement
        .iter()
        .map(|n| global("agreement", n))
        .fold(0.0, f64::max);
    rec.number("agreement_worst_smallest_global", 100.0 * worst, "s2");
    rec.claim(
        "agreement_worst_above_ten_percent",
        worst > 0.10,
        format!(
            "the agreement check's largest threshold above 10 %: {}",
            read(&agreement, "agreement")
        ),
    );
}

/// A planted mistake: its check (`exact` or `independence`), its name, the renderer.
type Twin = (
    &'static str,
    &'static str,
    Box<dyn Fn(&Scene) -> Image + Sync>,
);

/// The planted mistakes of the edge and independence checks, each a renderer: the
/// footprint moved or widened, a dimension reusing another's number.
fn twins() -> Vec<Twin> {
    let mut v: Vec<Twin> = vec![
        (
            "exact",
            "footprint half a pixel off",
            Box::new(planted::shifted_half_a_pixel(&ours)),
        ),
        (
            "exact",
            "footprint twice as wide",
            Box::new(planted::twice_as_wide(&ours)),
        ),
    ];
    for (what, from, to) in independence::TWINS {
        v.push((
            "independence",
            what,
            Box::new(independence::reused(from, to)),
        ));
    }
    v
}

/// The second table: each planted mistake of [`twins`] on each scene of its check, over
/// `seeds` seeds at the suite's level: in how many seeds the check rejects it, and the
/// smallest ratio of the largest `|z|` (whole image or block) to the critical value.
fn twins_md(md: &mut String, rec: &mut Record, seeds: u64) -> anyhow::Result<()> {
    writeln!(
        md,
        "\n| check | planted mistake | scene | rejected in {seeds} seeds | least \\|z\\| / critical | least finite \\|z\\| / critical |"
    )?;
    writeln!(md, "|---|---|---|---:|---:|---:|")?;
    let options = |s: u64| Options::default().seed(0x7_1A5 + s);
    // The tests hold each asserted twin to every seed of this count.
    rec.number("twins.seeds", seeds as f64, "int");
    // (mistake, scene, seeds that rejected it), for the chapter's claims.
    let mut results: Vec<(&str, String, u64)> = Vec::new();
    for (check, what, twin) in twins() {
        let twin: Renderer = twin.as_ref();
        let runs: Vec<Vec<Rendered>> = (0..seeds)
            .into_par_iter()
            .map(|s| match check {
                "exact" => render_exact_of(twin, edge_scenes(1.0), &options(s)),
                _ => render_independence(twin, &options(s)),
            })
            .collect();
        let items = runs[0].len();
        let level = sidak(test_alpha(), items as u32);
        for i in 0..items {
            let mut rejected = 0u64;
            let mut least = f64::INFINITY;
            let mut least_finite = f64::INFINITY;
            for run in &runs {
                let r = &run[i];
                let p = pool_blocks(&r.image, &r.expected, level, r.block);
                if !p.passed() {
                    rejected += 1;
                }
                let z = if p.global_z.is_nan() || p.block_z.is_nan() {
                    f64::INFINITY
                } else {
                    p.global_z.max(p.block_z)
                };
                least = least.min(z / p.critical);
                // The largest finite |z| of the seed: what is left when a block of
                // zero-variance pixels off their expected value makes |z| infinite.
                let finite = [p.global_z, p.block_z]
                    .into_iter()
                    .filter(|z| z.is_finite())
                    .fold(0.0, f64::max);
                least_finite = least_finite.min(finite / p.critical);
            }
            results.push((what, runs[0][i].name.clone(), rejected));
            let key = format!("twins.{}.{}", slug(what), slug(&runs[0][i].name));
            rec.number(&format!("{key}.rejected"), rejected as f64, "int");
            rec.number(&format!("{key}.least_ratio"), least, ".2");
            rec.number(&format!("{key}.least_finite_ratio"), least_finite, ".2");
            writeln!(
                md,
                "| {check} | {what} | {} | {rejected} | {least:.2} | {least_finite:.2} |",
                runs[0][i].name
            )?;
        }
    }
    let rejected = |what: &str, scene: &str| {
        results
            .iter()
            .find(|(w, s, _)| *w == what && s == scene)
            .map_or(0, |r| r.2)
    };
    let every = |what: &str, scenes: &[&str]| scenes.iter().all(|s| rejected(what, s) == seeds);
    let edges = [
        "edges of two lights seen directly",
        "edges of a red quad in a sky",
        "shadows of two lights",
    ];
    let [(jitter, ..), (choice, ..)] = independence::TWINS;
    rec.claim(
        "footprint_twins_rejected_in_every_seed",
        every("footprint half a pixel off", &edges) && every("footprint twice as wide", &edges),
        "both footprint mistakes rejected in every seed on the three scenes of edges",
    );
    rec.claim(
        "reuse_twins_rejected_in_every_seed_where_they_show",
        every(jitter, &["edges of a red quad in a sky"])
            && every(choice, &["shadows of two lights", "floor under two lights"]),
        "the reused wavelengths on the red quad, the reused light choice on the two two-light scenes",
    );
    let hero = rejected(jitter, "edges of two lights seen directly");
    rec.number("hero_lights_reused_jitter_rejected", hero as f64, "int");
    rec.claim(
        "hero_lights_miss_the_reused_jitter_in_most_seeds",
        2 * hero <= seeds,
        format!("the lights (hero) reject the reused jitter in {hero} of {seeds} seeds"),
    );
    writeln!(
        md,
        "\n*Each planted mistake rendered with {seeds} seeds (other seeds than the first \
         table's) and judged by its check at the level it has in the suite. \"least |z| / \
         critical\": over the seeds, the smallest ratio of the scene's largest |z| (whole \
         image or one block) to its critical value; above 1 in every seed is a rejection \
         every time. It is infinite (inf) where a block whose pixels all have zero variance \
         (every sample 0) differs from an expected value above 0: a certain rejection, \
         since a tested pixel is expected to meet its polygon at least 20 times. The last \
         column leaves such |z| out: the margin of the rest of the image.*"
    )?;
    Ok(())
}

fn power_md(settings: &Settings, rec: &mut Record) -> anyhow::Result<Vec<u8>> {
    let seeds: u64 = if settings.quick { 2 } else { 10 };
    let root = settings.root.clone();
    let options = |s: u64| Options::default().seed(0xB1A5 + s);
    let exact: Vec<Vec<Rendered>> = (0..seeds)
        .into_par_iter()
        .map(|s| render_exact(&ours, &options(s)))
        .collect();
    let agreement: Vec<Vec<Rendered>> = (0..seeds)
        .into_par_iter()
        .map(|s| render_agreement(&ours, &options(s)))
        .collect();
    let refs: Vec<Vec<Rendered>> = (0..seeds)
        .into_par_iter()
        .map(|s| references::render_references(&references::ours_window, &root, &options(s)))
        .collect::<Result<_, _>>()?;
    let indep: Vec<Vec<Rendered>> = (0..seeds)
        .into_par_iter()
        .map(|s| render_independence(&ours, &options(s)))
        .collect();
    let mut rows = rows_of("exact", &exact);
    rows.extend(rows_of("agreement", &agreement));
    rows.extend(rows_of("independence", &indep));
    rows.extend(rows_of("references", &refs));
    let mut md = String::new();
    writeln!(
        md,
        "| check | scene | pixels | block | smallest global bias detected | smallest bias of one block detected | false alarms in {seeds} seeds |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---:|")?;
    for r in &rows {
        let key = format!("{}.{}", r.check, slug(&r.name));
        if let Some(g) = r.global {
            rec.number(&format!("{key}.smallest_global"), 100.0 * g, "s2");
        }
        writeln!(
            md,
            "| {} | {} | {} | {b} x {b} | {} | {} | {} |",
            r.check,
            r.name,
            r.pixels,
            percent(r.global),
            percent(r.local),
            r.false_alarms,
            b = r.block
        )?;
    }
    power_claims(rec, &rows);
    twins_md(&mut md, rec, seeds)?;
    writeln!(
        md,
        "\n*Each check's images rendered with {seeds} seeds at the settings of `cargo test` \
         (`tests/book/renderer/testing.rs`); a bias counts as detected when the check's test \
         fails for at least {} of the {seeds} seeds, at the level it has in the suite (the \
         per-test level split by Šidák between the check's scenes). Biases tried: {} %. \
         \"One block\": the block at the middle of the image alone made brighter.{}*",
        (9 * seeds).div_ceil(10),
        BIASES
            .iter()
            .map(|b| format!("{}", 100.0 * b))
            .collect::<Vec<_>>()
            .join(", "),
        if settings.quick {
            " Quick mode: 2 seeds."
        } else {
            ""
        }
    )?;
    Ok(md.into_bytes())
}
