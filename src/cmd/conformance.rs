//! `raylemma conformance --renderer 'CMD {scene} {out} {spp} {seed}'`: another renderer
//! on the conformance ladder (`scenes/conformance/`, [`raylemma::conformance::ladder`]).
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
use raylemma::check::external::ProgramError;
use raylemma::conformance::candidate;
use raylemma::conformance::compare::{self, Failures};
use raylemma::conformance::diagnose::{self, diagnose};
use raylemma::conformance::export::{SceneFile, json, mitsuba, pbrt};
use raylemma::conformance::ladder::{self, LADDER, Rung, header};
use raylemma::output::FileError;

use super::{CmdResult, Failure, Outcome, xml_escape};

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
    /// The scene format the renderer reads (no default: a renderer fed the wrong format
    /// fails on every rung, which would say nothing about its physics).
    #[arg(long, value_enum)]
    pub format: Format,
    /// Renders of each rung, with different seeds: their spread is the candidate's noise.
    #[arg(long, default_value_t = 4, value_parser = clap::value_parser!(u32).range(2..))]
    pub runs: u32,
    /// The card's seed: its K runs of each rung use the seeds K(S - 1) + 1 to K S (with
    /// the default 1, the seeds 1 to K), so that cards of different seeds share no render.
    /// A card that differs can be run again with another seed.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
    pub seed: u64,
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
    /// The suite to run: a folder laid out as raylemma's source tree (its
    /// `scenes/conformance/`, the `data/` files they read and
    /// `figures/reference/conformance/`), such as a clone whose references you rendered
    /// yourself. Default: the suite built into this binary, written out into
    /// `WORK/suite/`. The card names the suite and its hash.
    #[arg(long)]
    pub suite: Option<PathBuf>,
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

/// The suite a card runs: where its files are, where they came from, and their hash.
struct Suite {
    /// The folder holding `scenes/conformance/`, `data/` and `figures/reference/conformance/`.
    dir: PathBuf,
    /// "built into this binary" or the folder given.
    source: String,
    /// FNV-1a of every file of [`ladder::SUITE`]'s list, its path then its bytes, in hexadecimal:
    /// the same for a folder whose files are the built-in ones.
    hash: String,
}

impl Suite {
    /// The built-in suite, written out into `work/suite/`, or the folder `dir`.
    fn open(dir: Option<&Path>, work: &Path) -> Result<Suite, Failure> {
        let mut all = Vec::new();
        let (dir, source) = match dir {
            None => {
                let out = work.join("suite");
                for (path, bytes) in ladder::SUITE {
                    let to = out.join(path);
                    raylemma::output::create_dir_all(to.parent().unwrap_or(&out))?;
                    raylemma::output::write_file(&to, bytes)?;
                    all.extend_from_slice(path.as_bytes());
                    all.extend_from_slice(bytes);
                }
                (out, "built into this binary".to_string())
            }
            Some(dir) => {
                for (path, _) in ladder::SUITE {
                    let from = dir.join(path);
                    let bytes = std::fs::read(&from).map_err(|e| {
                        Failure::BadInput(format!(
                            "--suite {}: {} cannot be read ({e}): a suite is laid out as raylemma's source tree",
                            dir.display(),
                            from.display()
                        ))
                    })?;
                    all.extend_from_slice(path.as_bytes());
                    all.extend_from_slice(&bytes);
                }
                (dir.to_path_buf(), dir.display().to_string())
            }
        };
        Ok(Suite {
            dir,
            source,
            hash: format!("{:016x}", raylemma::output::fnv1a(&all)),
        })
    }

    /// The folder of the ladder's scene files.
    fn scenes(&self) -> PathBuf {
        self.dir.join("scenes/conformance")
    }
}

/// One line of the card.
struct Row {
    rung: Rung,
    depth: Option<u32>,
    /// `agree`, `differ`, `error` (the renderer failed, or the suite could not be read) or
    /// `skipped`.
    verdict: &'static str,
    /// The whole image's relative difference per channel with its 95 % half-width.
    bias: Option<[(f64, f64); 3]>,
    /// `agree`: the worst block; `differ`: the tests that failed ([`Failures::text`]);
    /// `error`: what failed; `skipped`: why.
    detail: String,
    /// The tests that failed, when it differs.
    failures: Option<Failures>,
    /// How the renderer failed, when it did: never a verdict on its physics.
    run_failure: Option<RunFailure>,
    /// What the difference looks like ([`diagnose`]), when it differs.
    diagnosis: Vec<String>,
}

/// How one run of the renderer failed: the command as run, what happened (its exit
/// status, its time running out, no image, an image that cannot be read), the last lines
/// of its output, and the image it was to write.
struct RunFailure {
    command: String,
    what: String,
    log_tail: Vec<String>,
    log: PathBuf,
    expected: PathBuf,
}

/// The last lines of the renderer's output (stdout and stderr together) kept on a card.
const LOG_TAIL: usize = 8;

impl RunFailure {
    fn new(command: &str, what: String, log: &Path, expected: &Path) -> RunFailure {
        let text = std::fs::read(log).unwrap_or_default();
        let text = String::from_utf8_lossy(&text);
        let lines: Vec<String> = text
            .lines()
            .filter(|l| !l.trim().is_empty())
            .map(|l| l.chars().take(300).collect())
            .collect();
        RunFailure {
            command: command.to_string(),
            what,
            log_tail: lines[lines.len().saturating_sub(LOG_TAIL)..].to_vec(),
            log: log.to_path_buf(),
            expected: expected.to_path_buf(),
        }
    }

    /// The failure for people, several lines indented by `indent`.
    fn text(&self, indent: &str) -> String {
        let mut s = format!(
            "{indent}command: {}\n{indent}what happened: {}\n{indent}the image it was to write: {}\n",
            self.command,
            self.what,
            self.expected.display()
        );
        if self.log_tail.is_empty() {
            let _ = writeln!(s, "{indent}its output ({}): nothing", self.log.display());
        } else {
            let _ = writeln!(
                s,
                "{indent}the last lines of its output ({}):",
                self.log.display()
            );
            for l in &self.log_tail {
                let _ = writeln!(s, "{indent}  | {l}");
            }
        }
        s
    }

    fn json(&self) -> serde_json::Value {
        serde_json::json!({
            "command": self.command,
            "what": self.what,
            "log": self.log.display().to_string(),
            "log_tail": self.log_tail,
            "expected": self.expected.display().to_string(),
        })
    }
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
    let suite = Suite::open(args.suite.as_deref(), &args.work)?;
    let comparisons: usize = rungs.iter().map(|r| r.depths.len()).sum();
    let level = raylemma::stats::sidak(args.alpha, comparisons as u32);
    let mut rows = Vec::new();
    for rung in rungs {
        for &depth in rung.depths {
            let row = one(args, &suite, rung, depth, level);
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
    let card = card_text(&rows, args, &suite);
    print!("{card}");
    let write = |path: &Path, text: String| {
        raylemma::output::write_file(path, text.as_bytes()).map_err(Failure::from)
    };
    if let Some(p) = &args.json {
        write(p, card_json(&rows, args, &suite))?;
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
fn one(args: &ConformanceArgs, suite: &Suite, rung: Rung, depth: Option<u32>, level: f64) -> Row {
    let row = |verdict, detail: String| Row {
        rung,
        depth,
        verdict,
        bias: None,
        detail,
        failures: None,
        run_failure: None,
        diagnosis: Vec::new(),
    };
    let failed = |failure: RunFailure| Row {
        detail: format!("the renderer failed: {}", failure.what),
        run_failure: Some(failure),
        ..row("error", String::new())
    };
    let name = ladder::reference_name(&rung, depth);
    let dir = args.work.join(&name);
    let (scene, file) = match write_scene(suite, rung, depth, args.format, &dir) {
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
    for run in 1..=args.runs {
        let seed = u64::from(args.runs) * (args.seed - 1) + u64::from(run);
        let outdir = dir.join(format!("run-{run}"));
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
        let failure = |what: String| failed(RunFailure::new(&command, what, &log, &out));
        match raylemma::check::external::run_logged(
            &command,
            &log,
            Duration::from_secs_f64(args.timeout),
        ) {
            Err(ProgramError::Status { status, .. }) => {
                return failure(format!(
                    "run {run} (seed {seed}) {}",
                    raylemma::check::external::ended(status)
                ));
            }
            Err(ProgramError::Timeout { timeout, .. }) => {
                return failure(format!(
                    "run {run} (seed {seed}) did not finish in {:.0} s (--timeout): killed it",
                    timeout.as_secs_f64()
                ));
            }
            Err(e) => return failure(format!("run {run} (seed {seed}): {e}")),
            Ok(()) => {}
        }
        if !out.is_file() {
            return failure(format!(
                "run {run} (seed {seed}) ended with status 0 but wrote no image"
            ));
        }
        if let Err(e) = raylemma::image::ExrContents::read(&out) {
            return failure(format!(
                "run {run} (seed {seed}) wrote an image that cannot be read: {e}"
            ));
        }
        outs.push(out);
    }
    let reference_of = |d: Option<u32>| {
        let path = suite
            .dir
            .join("figures/reference/conformance")
            .join(format!("{}.exr", ladder::reference_name(&rung, d)));
        candidate::reference(&path)
    };
    let result = reference_of(depth).and_then(|reference| {
        let (candidate, _, _) = candidate::candidate(&outs, &reference, Some(args.spp))?;
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
                    rung: rung.number,
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
            let failures = c.failures();
            let detail = if failures.is_empty() {
                c.regions.first().map_or(String::new(), |r| {
                    format!(
                        "worst block at ({}, {}) channel {}: z = {:.1} (|z| > {:.2} fails)",
                        r.x,
                        r.y,
                        ["R", "G", "B"][r.channel],
                        r.z,
                        c.z_critical
                    )
                })
            } else {
                format!("failed: {}", failures.text())
            };
            Row {
                rung,
                depth,
                verdict: if c.agree() { "agree" } else { "differ" },
                bias: Some(c.image.map(|(_, _, rel)| rel)),
                detail,
                failures: (!failures.is_empty()).then_some(failures),
                run_failure: None,
                diagnosis,
            }
        }
    }
}

/// `path` made absolute against the working directory (the scene is written elsewhere, and
/// its data paths must hold from there).
fn absolute(path: &Path) -> PathBuf {
    std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf())
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
    suite: &Suite,
    rung: Rung,
    depth: Option<u32>,
    format: Format,
    dir: &Path,
) -> Result<Written, Box<dyn std::error::Error>> {
    let source = suite.scenes().join(rung.file);
    let text =
        std::fs::read_to_string(&source).map_err(|e| FileError::new(&source, e.to_string()))?;
    let mut text: String = text
        .lines()
        .filter(|l| !(depth.is_some() && l.trim_start().starts_with("max_depth")))
        .map(|l| {
            let l = l.replace(
                "\"../../data/",
                &format!("\"{}/", absolute(&suite.dir.join("data")).display()),
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
    let file = SceneFile::parse(&text, rung.file, &suite.scenes())?;
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
fn card_text(rows: &[Row], args: &ConformanceArgs, suite: &Suite) -> String {
    let mut s = format!(
        "conformance of `{}` ({:?} scenes, {} runs of {} spp each, card seed {}; false alarms at most {} % over the card)\nsuite {} ({})\n",
        args.renderer,
        args.format,
        args.runs,
        args.spp,
        args.seed,
        100.0 * args.alpha,
        suite.hash,
        suite.source
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
    let errors: Vec<&Row> = rows.iter().filter(|r| r.verdict == "error").collect();
    if let Some(r) = errors.first() {
        let _ = writeln!(
            s,
            "the renderer FAILED on {} of {} comparisons: no image to judge there, so no verdict on its physics; the first, rung {} at {}:",
            errors.len(),
            rows.len(),
            r.rung.number,
            depth_name(r.depth)
        );
        match &r.run_failure {
            Some(f) => s += &f.text("  "),
            None => {
                let _ = writeln!(s, "  {}", r.detail);
            }
        }
    }
    if let Some(r) = rows.iter().find(|r| r.verdict == "differ") {
        let text = std::fs::read_to_string(suite.scenes().join(r.rung.file)).unwrap_or_default();
        let h = header(&text);
        let _ = writeln!(
            s,
            "first differing: rung {} ({}) at {}: it tests {}",
            r.rung.number,
            h.title,
            depth_name(r.depth),
            h.tests,
        );
        let _ = writeln!(
            s,
            "  what failed: {}",
            r.detail.trim_start_matches("failed: ")
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
    }
    s += match (
        errors.is_empty(),
        rows.iter().any(|r| r.verdict == "differ"),
    ) {
        (true, false) => "verdict: every rung AGREES\n",
        (_, true) => "verdict: the renderer DIFFERS\n",
        (false, false) if rows.iter().any(|r| r.verdict == "agree") => {
            "verdict: the renderer FAILED to render (see above); every comparison it rendered agrees\n"
        }
        (false, false) => "verdict: the renderer FAILED to render (see above)\n",
    };
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

fn card_json(rows: &[Row], args: &ConformanceArgs, suite: &Suite) -> String {
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
                "failed_tests": r.failures.as_ref().map(failures_json),
                "renderer_failure": r.run_failure.as_ref().map(RunFailure::json),
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
        "seed": args.seed,
        "suite": {"hash": suite.hash, "source": suite.source},
        "alpha": args.alpha,
        "rungs": rungs,
        "first_failing_rung": first,
    });
    serde_json::to_string_pretty(&v).unwrap_or_default() + "\n"
}

/// The failed tests of a comparison as JSON: each kind's count and worst failure.
fn failures_json(f: &Failures) -> serde_json::Value {
    let rgb = ["R", "G", "B"];
    serde_json::json!({
        "z_critical": f.z_critical,
        "pixels": {
            "count": f.pixels.0,
            "worst": f.pixels.1.map(|(x, y, c, z)| serde_json::json!({"x": x, "y": y, "channel": rgb[c], "z": z})),
        },
        "blocks": {
            "count": f.blocks.0,
            "size": compare::BLOCK,
            "worst": f.blocks.1.map(|r| serde_json::json!({"x": r.x, "y": r.y, "channel": rgb[r.channel], "z": r.z})),
        },
        "whole_image": f.image.iter().map(|(c, z)| serde_json::json!({"channel": rgb[*c], "z": z})).collect::<Vec<_>>(),
        "text": f.text(),
    })
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
        let detail = xml_escape(&match &r.run_failure {
            Some(f) => f.text(""),
            None => format!("{} {}", bias_text(&r.bias), r.detail),
        });
        let _ = match r.verdict {
            "differ" => writeln!(
                s,
                "  <testcase name=\"{name}\"><failure message=\"differs from the reference\">{detail}</failure></testcase>"
            ),
            "error" => writeln!(
                s,
                "  <testcase name=\"{name}\"><error message=\"the renderer failed: not a verdict on its physics\">{detail}</error></testcase>"
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
