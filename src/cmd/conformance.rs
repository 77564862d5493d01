//! `raylemma conformance --renderer 'CMD {scene} {out} {spp} {seed}'`: another renderer
//! on the conformance ladder (`scenes/conformance/`, [`raylemma::check::render::ladder`]).
//! Each rung, at each depth it has a reference for, is written in the chosen format, the
//! renderer is run `--runs` times with different seeds, its images are compared with the
//! reference (`figures/reference/conformance/`), and a card says per rung and depth
//! whether they agree, how large the difference is, and what the first failing rung
//! points to. Exit status 0 if every rung agrees, 1 if one differs or its renderer failed,
//! 2 for bad usage. Chapter: *Reference scenes and interop*, *The conformance ladder*.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Duration;

use clap::{Args, ValueEnum};
use raylemma::check::render::diagnose::{self, diagnose};
use raylemma::check::render::ladder::{self, LADDER, Rung, header};
use raylemma::output::FileError;
use raylemma::render::compare;
use raylemma::render::export::{SceneFile, json, mitsuba, pbrt};

use super::{CmdResult, Failure, Outcome, root, xml_escape};

/// The scene format the candidate reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// raylemma's own TOML (data paths made absolute).
    Toml,
    /// Fully resolved JSON (`raylemma export --to json`).
    Json,
    /// Mitsuba 3 XML (`raylemma export --to mitsuba`); the rungs it refuses (the
    /// spectral-only ones) are skipped.
    Mitsuba,
    /// pbrt-v4 (`raylemma export --to pbrt`); the rungs it refuses (thin films) are skipped.
    Pbrt,
}

/// `raylemma conformance`.
#[derive(Args, Debug)]
pub struct ConformanceArgs {
    /// The renderer, run by `sh -c`, with `{scene}` (the scene file to read), `{out}` (the
    /// EXR to write: plain R, G, B, or X, Y, Z), `{outdir}` (its folder), `{spp}`, `{seed}`
    /// and `{depth}` (the maximum depth in raylemma's count of bounces, as the written scene
    /// has it: the rung's own where no other is asked, 1000 for the default) replaced.
    #[arg(long)]
    pub renderer: String,
    /// The scene format the renderer reads.
    #[arg(long, value_enum, default_value = "json")]
    pub format: Format,
    /// Renders of each rung, with seeds 1, 2, ...: their spread is the candidate's noise.
    #[arg(long, default_value_t = 4, value_parser = clap::value_parser!(u32).range(2..))]
    pub runs: u32,
    /// Samples per pixel of each render.
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..))]
    pub spp: u32,
    /// Only these rungs (numbers, comma-separated).
    #[arg(long, value_delimiter = ',')]
    pub rungs: Vec<u32>,
    /// Seconds one render may take.
    #[arg(long, default_value_t = 600.0)]
    pub timeout: f64,
    /// The family-wise false-alarm rate of the whole card (Šidák over its comparisons).
    #[arg(long, default_value_t = 0.01)]
    pub alpha: f64,
    /// Where the scenes and renders go [default: conformance/ in the working directory].
    #[arg(long, default_value = "conformance")]
    pub work: PathBuf,
    /// Also write the card as JSON to this file.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Also write the card as JUnit XML to this file (for CI systems and autograders).
    #[arg(long)]
    pub junit: Option<PathBuf>,
}

/// One line of the card.
struct Row {
    rung: Rung,
    depth: Option<u32>,
    /// `agree`, `differ`, `error` or `skipped`.
    verdict: &'static str,
    /// The whole image's relative difference per channel with its 95 % half-width.
    bias: Option<[(f64, f64); 3]>,
    /// The worst block, or the error, or why it was skipped.
    detail: String,
    /// What the difference looks like ([`diagnose`]), when it differs.
    diagnosis: Vec<String>,
}

/// Runs `raylemma conformance`.
pub fn run(args: &ConformanceArgs) -> CmdResult {
    if !(args.alpha > 0.0 && args.alpha < 1.0) {
        return Err(Failure::BadInput(format!(
            "--alpha {} must be in (0, 1)",
            args.alpha
        )));
    }
    if !(args.timeout > 0.0 && args.timeout.is_finite()) {
        return Err(Failure::BadInput(format!(
            "--timeout {} must be a positive number of seconds",
            args.timeout
        )));
    }
    let rungs: Vec<Rung> = LADDER
        .iter()
        .copied()
        .filter(|r| args.rungs.is_empty() || args.rungs.contains(&r.number))
        .collect();
    if let Some(n) = args
        .rungs
        .iter()
        .find(|n| !LADDER.iter().any(|r| r.number == **n))
    {
        return Err(Failure::BadInput(format!(
            "--rungs: no rung {n} (the ladder has 1 to {})",
            LADDER.len()
        )));
    }
    let comparisons: usize = rungs.iter().map(|r| r.depths.len()).sum();
    let level = raylemma::stats::sidak(args.alpha, comparisons as u32);
    let mut rows = Vec::new();
    for rung in rungs {
        for &depth in rung.depths {
            let row = one(args, rung, depth, level);
            eprintln!(
                "raylemma: rung {} {}: {} {}",
                rung.number,
                depth_name(depth),
                row.verdict,
                row.detail
            );
            rows.push(row);
        }
    }
    let card = card_text(&rows, args);
    print!("{card}");
    let write = |path: &Path, text: String| {
        raylemma::output::write_file(path, text.as_bytes()).map_err(Failure::from)
    };
    if let Some(p) = &args.json {
        write(p, card_json(&rows, args))?;
    }
    if let Some(p) = &args.junit {
        write(p, card_junit(&rows))?;
    }
    if rows
        .iter()
        .all(|r| matches!(r.verdict, "agree" | "skipped"))
    {
        Ok(Outcome::Done)
    } else {
        Ok(Outcome::Negative)
    }
}

fn depth_name(depth: Option<u32>) -> String {
    depth.map_or("own depth".into(), |d| format!("depth {d}"))
}

/// One rung at one depth: written, rendered `runs` times, compared.
fn one(args: &ConformanceArgs, rung: Rung, depth: Option<u32>, level: f64) -> Row {
    let row = |verdict, detail: String| Row {
        rung,
        depth,
        verdict,
        bias: None,
        detail,
        diagnosis: Vec::new(),
    };
    let name = ladder::reference_name(&rung, depth);
    let dir = args.work.join(&name);
    let (scene, file) = match write_scene(rung, depth, args.format, &dir) {
        Ok(Written::Scene(p, file)) => (p, file),
        Ok(Written::Refused(why)) => {
            return row(
                "skipped",
                format!("the {:?} export refuses it: {why}", args.format),
            );
        }
        Err(e) => return row("error", format!("the scene could not be written: {e}")),
    };
    let mut outs = Vec::new();
    for seed in 1..=args.runs {
        let outdir = dir.join(format!("run-{seed}"));
        let out = outdir.join("scene.exr");
        let _ = std::fs::remove_file(&out);
        if let Err(e) = std::fs::create_dir_all(&outdir) {
            return row("error", format!("{}: {e}", outdir.display()));
        }
        let command = args
            .renderer
            .replace("{scene}", &scene.display().to_string())
            .replace("{outdir}", &outdir.display().to_string())
            .replace("{out}", &out.display().to_string())
            .replace("{spp}", &args.spp.to_string())
            .replace("{seed}", &seed.to_string())
            .replace("{depth}", &file.scene.settings.max_depth.to_string());
        let log = outdir.join("log.txt");
        if let Err(e) = raylemma::check::external::run_logged(
            &command,
            &log,
            Duration::from_secs_f64(args.timeout),
        ) {
            return row(
                "error",
                format!("run {seed}: {e} (its output: {})", log.display()),
            );
        }
        if !out.is_file() {
            return row("error", format!("run {seed} wrote no {}", out.display()));
        }
        outs.push(out);
    }
    let reference_of = |d: Option<u32>| {
        let path = root()
            .join("figures/reference/conformance")
            .join(format!("{}.exr", ladder::reference_name(&rung, d)));
        super::compare::reference(&path)
    };
    let result = reference_of(depth).and_then(|reference| {
        let size = (reference.image.width, reference.image.height);
        let (candidate, _, _) = super::compare::candidate(&outs, size)?;
        let c = compare::compare(&reference, &candidate, level)?;
        Ok((reference, candidate, c))
    });
    match result {
        Err(e) => row("error", e.to_string()),
        Ok((reference, candidate, c)) => {
            let diagnosis = if c.agree() {
                Vec::new()
            } else {
                let context = diagnose::Context {
                    scene: &file.scene,
                    materials: &file
                        .materials
                        .iter()
                        .map(|(n, _)| n.clone())
                        .collect::<Vec<_>>(),
                    other_depths: rung
                        .depths
                        .iter()
                        .filter(|&&d| d != depth)
                        .filter_map(|&d| reference_of(d).ok().map(|r| (d, r)))
                        .collect(),
                };
                diagnose(&reference, &candidate, level, &context)
            };
            let worst = c.regions.first().map_or(String::new(), |r| {
                format!(
                    "worst block at ({}, {}) channel {}: z = {:.1}",
                    r.x,
                    r.y,
                    ["R", "G", "B"][r.channel],
                    r.z
                )
            });
            Row {
                rung,
                depth,
                verdict: if c.agree() { "agree" } else { "differ" },
                bias: Some(c.image.map(|(_, _, rel)| rel)),
                detail: worst,
                diagnosis,
            }
        }
    }
}

/// What [`write_scene`] did.
enum Written {
    /// The scene file it wrote, and the scene.
    Scene(PathBuf, Box<SceneFile>),
    /// The format cannot express the rung: the export's refusal (`file:line: reason`).
    Refused(String),
}

/// The rung's scene at `depth` in `format`, written into `dir`, or the export's refusal.
fn write_scene(
    rung: Rung,
    depth: Option<u32>,
    format: Format,
    dir: &Path,
) -> Result<Written, Box<dyn std::error::Error>> {
    let source = root().join("scenes/conformance").join(rung.file);
    let text =
        std::fs::read_to_string(&source).map_err(|e| FileError::new(&source, e.to_string()))?;
    let mut text: String = text
        .lines()
        .filter(|l| !(depth.is_some() && l.trim_start().starts_with("max_depth")))
        .map(|l| {
            let l = l.replace(
                "\"../../data/",
                &format!("\"{}/", root().join("data").display()),
            );
            if l.trim() == "[render]"
                && let Some(d) = depth
            {
                format!("{l}\nmax_depth = {d}")
            } else {
                l
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    text.push('\n');
    let file = SceneFile::parse(&text, rung.file, &root().join("scenes/conformance"))?;
    let exported = match format {
        Format::Toml => Ok(("toml", text)),
        Format::Json => Ok(("json", json::to_json(&file))),
        Format::Mitsuba => mitsuba::to_xml(&file).map(|x| ("xml", x)),
        Format::Pbrt => pbrt::to_pbrt(&file).map(|x| ("pbrt", x)),
    };
    let (ext, body) = match exported {
        Ok(e) => e,
        Err(e) => return Ok(Written::Refused(e.to_string())),
    };
    std::fs::create_dir_all(dir).map_err(|e| FileError::new(dir, e.to_string()))?;
    let path = dir.join(format!("scene.{ext}"));
    raylemma::output::write_file(&path, body.as_bytes())?;
    Ok(Written::Scene(path, Box::new(file)))
}

fn bias_text(bias: &Option<[(f64, f64); 3]>) -> String {
    bias.map_or("".into(), |b| {
        b.iter()
            .zip(["R", "G", "B"])
            .map(|((r, h), c)| format!("{c} {:+.2} % ± {:.2} %", 100.0 * r, 100.0 * h))
            .collect::<Vec<_>>()
            .join(", ")
    })
}

/// The card for people: one line per rung and depth, then the first failing rung and what
/// a failure there usually means (its scene file's header).
fn card_text(rows: &[Row], args: &ConformanceArgs) -> String {
    let mut s = format!(
        "conformance of `{}` ({:?} scenes, {} runs of {} spp each; false alarms at most {} % over the card)\n",
        args.renderer,
        args.format,
        args.runs,
        args.spp,
        100.0 * args.alpha
    );
    for r in rows {
        let _ = writeln!(
            s,
            "  rung {:>2} {:<22} {:<9} {:<6} {} {}",
            r.rung.number,
            r.rung.file.trim_end_matches(".toml"),
            depth_name(r.depth),
            r.verdict,
            bias_text(&r.bias),
            r.detail
        );
    }
    match rows
        .iter()
        .find(|r| matches!(r.verdict, "differ" | "error"))
    {
        None => s += "verdict: every rung AGREES\n",
        Some(r) => {
            let text = std::fs::read_to_string(root().join("scenes/conformance").join(r.rung.file))
                .unwrap_or_default();
            let h = header(&text);
            let _ = writeln!(
                s,
                "first failing: rung {} ({}) at {}: it tests {}",
                r.rung.number,
                h.title,
                depth_name(r.depth),
                h.tests,
            );
            if let Some(at) = depth_meaning(r.depth, r.rung) {
                let _ = writeln!(s, "  {at}");
            }
            if !r.diagnosis.is_empty() {
                s += "  what the difference looks like:\n";
                for d in &r.diagnosis {
                    let _ = writeln!(s, "    - {d}");
                }
            }
            let _ = writeln!(
                s,
                "  a failure here usually means: {}\n  derived in: {}",
                h.failure, h.chapter
            );
            s += "verdict: the renderer DIFFERS\n";
        }
    }
    s
}

/// What the first failing depth of a rung says, when the rung has several: what that depth
/// adds to the ones before it, which agreed.
fn depth_meaning(depth: Option<u32>, rung: Rung) -> Option<&'static str> {
    if rung.depths.len() < 2 {
        return None;
    }
    let ladder = rung.depths.contains(&Some(3));
    Some(match depth {
        Some(1) => {
            "at depth 1 the paths have two segments: the direct light (next-event estimation, the BSDF sample that reaches a light, their MIS weights)"
        }
        Some(2) => {
            "depth 1 agrees: what depth 2 adds is the first indirect bounce (the bounce's throughput, light sampled from the second vertex)"
        }
        Some(_) => {
            "depths 1 and 2 agree: what depth 3 adds is the second indirect bounce (throughput carried across bounces, where roulette may start)"
        }
        None if ladder => {
            "every bounded depth agrees: what is left is the depth limit itself or Russian roulette (the survival probability divided out)"
        }
        None => {
            "depth 1 agrees: what the rung's own depth adds is the indirect light (a bounce's throughput, light sampled from later vertices, roulette where the depth allows it)"
        }
    })
}

fn card_json(rows: &[Row], args: &ConformanceArgs) -> String {
    let rungs: Vec<serde_json::Value> = rows
        .iter()
        .map(|r| {
            serde_json::json!({
                "rung": r.rung.number,
                "scene": format!("scenes/conformance/{}", r.rung.file),
                "depth": r.depth,
                "verdict": r.verdict,
                "relative_difference": r.bias.map(|b| b.map(|(rel, half)| serde_json::json!({"value": rel, "half_width_95": half}))),
                "detail": r.detail,
                "diagnosis": r.diagnosis,
            })
        })
        .collect();
    let first = rows
        .iter()
        .find(|r| matches!(r.verdict, "differ" | "error"))
        .map(|r| r.rung.number);
    let v = serde_json::json!({
        "renderer": args.renderer,
        "runs": args.runs,
        "spp": args.spp,
        "alpha": args.alpha,
        "rungs": rungs,
        "first_failing_rung": first,
    });
    serde_json::to_string_pretty(&v).unwrap_or_default() + "\n"
}

fn card_junit(rows: &[Row]) -> String {
    let failures = rows.iter().filter(|r| r.verdict == "differ").count();
    let errors = rows.iter().filter(|r| r.verdict == "error").count();
    let skipped = rows.iter().filter(|r| r.verdict == "skipped").count();
    let mut s = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"raylemma conformance\" tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\" skipped=\"{skipped}\">\n",
        rows.len()
    );
    for r in rows {
        let name = xml_escape(&format!(
            "rung {} {} {}",
            r.rung.number,
            r.rung.file.trim_end_matches(".toml"),
            depth_name(r.depth)
        ));
        let detail = xml_escape(&format!("{} {}", bias_text(&r.bias), r.detail));
        let _ = match r.verdict {
            "differ" => writeln!(
                s,
                "  <testcase name=\"{name}\"><failure message=\"differs from the reference\">{detail}</failure></testcase>"
            ),
            "error" => writeln!(
                s,
                "  <testcase name=\"{name}\"><error message=\"the renderer failed\">{detail}</error></testcase>"
            ),
            "skipped" => writeln!(
                s,
                "  <testcase name=\"{name}\"><skipped message=\"{detail}\"/></testcase>"
            ),
            _ => writeln!(s, "  <testcase name=\"{name}\"/>"),
        };
    }
    s += "</testsuite>\n";
    s
}
