//! Another renderer on the conformance ladder (`scenes/conformance/`, [`super::ladder`]):
//! each rung, at each depth it has a reference for, is written in the chosen format, the
//! renderer is run several times with different seeds, its images are compared with the
//! reference (`figures/reference/conformance/`), and the card ([`super::card`]) says per
//! rung and depth whether they agree. `raylemma conformance` parses its arguments into a
//! [`Conformance`] and calls [`run`]. Chapter: *Reference scenes and interop*
//! (`chapters/renderer/scenes.md`, *The conformance ladder*).

use std::path::{Path, PathBuf};
use std::time::Duration;

use super::candidate;
use super::card::{self, Format, Row, RunFailure, Settings, Suite, depth_name};
use super::compare;
use super::diagnose::{self, diagnose};
use super::export::{SceneFile, json, mitsuba, pbrt};
use super::ladder::{self, LADDER, Rung};
use crate::check::external::ProgramError;
use crate::output::FileError;

/// A run of the card: what it states ([`Settings`]) and how it runs.
#[derive(Clone, Debug)]
pub struct Conformance {
    /// The renderer, format, runs, samples, seed and false-alarm rate.
    pub settings: Settings,
    /// Only these rungs (numbers); all when empty.
    pub rungs: Vec<u32>,
    /// Seconds one render may take.
    pub timeout: f64,
    /// The suite's folder, or `None` for the one built into the library.
    pub suite: Option<PathBuf>,
    /// Where the scenes and renders go.
    pub work: PathBuf,
    /// Also write the card as JSON to this file.
    pub json: Option<PathBuf>,
    /// Also write the card as JUnit XML to this file.
    pub junit: Option<PathBuf>,
}

/// Why a card could not be run.
#[derive(Debug)]
pub enum ConformanceError {
    /// Bad input or usage (a parameter out of range, no such rung, a suite that cannot be
    /// read): the message says which.
    BadInput(String),
    /// A file of the card could not be written.
    File(FileError),
}

impl std::fmt::Display for ConformanceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ConformanceError::BadInput(m) => f.write_str(m),
            ConformanceError::File(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ConformanceError {}

impl From<FileError> for ConformanceError {
    fn from(e: FileError) -> Self {
        ConformanceError::File(e)
    }
}

/// Runs the card: prints it, writes its JSON and JUnit forms if asked; `Ok(true)` if every
/// rung agrees (or is skipped).
///
/// # Errors
/// [`ConformanceError::BadInput`] for `alpha` outside (0, 1), a timeout that is not a
/// positive number, a rung that does not exist or a suite that cannot be read;
/// [`ConformanceError::File`] if a file of the card cannot be written.
pub fn run(conformance: &Conformance) -> Result<bool, ConformanceError> {
    let args = conformance;
    let set = &args.settings;
    if !(set.alpha > 0.0 && set.alpha < 1.0) {
        return Err(ConformanceError::BadInput(format!(
            "--alpha {} must be in (0, 1)",
            set.alpha
        )));
    }
    if !(args.timeout > 0.0 && args.timeout.is_finite()) {
        return Err(ConformanceError::BadInput(format!(
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
        return Err(ConformanceError::BadInput(format!(
            "--rungs: no rung {n} (the ladder has 1 to {})",
            LADDER.len()
        )));
    }
    let suite = open_suite(args.suite.as_deref(), &args.work)?;
    let comparisons: usize = rungs.iter().map(|r| r.depths.len()).sum();
    let level = crate::stats::sidak(set.alpha, comparisons as u32);
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
    let text = card::text(&rows, set, &suite);
    print!("{text}");
    let write = |path: &Path, text: String| crate::output::write_file(path, text.as_bytes());
    if let Some(p) = &args.json {
        write(p, card::json(&rows, set, &suite))?;
    }
    if let Some(p) = &args.junit {
        write(p, card::junit(&rows))?;
    }
    Ok(rows
        .iter()
        .all(|r| matches!(r.verdict, "agree" | "skipped")))
}

/// The built-in suite, written out into `work/suite/`, or the folder `dir`.
fn open_suite(dir: Option<&Path>, work: &Path) -> Result<Suite, ConformanceError> {
    let mut all = Vec::new();
    let (dir, source) = match dir {
        None => {
            let out = work.join("suite");
            for (path, bytes) in ladder::SUITE {
                let to = out.join(path);
                crate::output::create_dir_all(to.parent().unwrap_or(&out))?;
                crate::output::write_file(&to, bytes)?;
                all.extend_from_slice(path.as_bytes());
                all.extend_from_slice(bytes);
            }
            (out, "built into this binary".to_string())
        }
        Some(dir) => {
            for (path, _) in ladder::SUITE {
                let from = dir.join(path);
                let bytes = std::fs::read(&from).map_err(|e| {
                    ConformanceError::BadInput(format!(
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
        hash: format!("{:016x}", crate::output::fnv1a(&all)),
    })
}

/// One rung at one depth: written, rendered `runs` times, compared.
fn one(args: &Conformance, suite: &Suite, rung: Rung, depth: Option<u32>, level: f64) -> Row {
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
    let (scene, file) = match write_scene(suite, rung, depth, args.settings.format, &dir) {
        Ok(Written::Scene(p, file)) => (p, file),
        Ok(Written::Refused(why)) => {
            return row(
                "skipped",
                format!("the {:?} export refuses it: {why}", args.settings.format),
            );
        }
        Err(e) => return row("error", format!("the scene could not be written: {e}")),
    };
    let mut outs = Vec::new();
    for run in 1..=args.settings.runs {
        let seed = u64::from(args.settings.runs) * (args.settings.seed - 1) + u64::from(run);
        let outdir = dir.join(format!("run-{run}"));
        let out = outdir.join("scene.exr");
        let _ = std::fs::remove_file(&out);
        if let Err(e) = std::fs::create_dir_all(&outdir) {
            return row("error", format!("{}: {e}", outdir.display()));
        }
        let command = args
            .settings
            .renderer
            .replace("{scene}", &scene.display().to_string())
            .replace("{outdir}", &outdir.display().to_string())
            .replace("{out}", &out.display().to_string())
            .replace("{spp}", &args.settings.spp.to_string())
            .replace("{seed}", &seed.to_string())
            .replace("{depth}", &file.scene.settings.max_depth.to_string());
        let log = outdir.join("log.txt");
        let failure = |what: String| failed(RunFailure::new(&command, what, &log, &out));
        match crate::check::external::run_logged(
            &command,
            &log,
            Duration::from_secs_f64(args.timeout),
        ) {
            Err(ProgramError::Status { status, .. }) => {
                return failure(format!(
                    "run {run} (seed {seed}) {}",
                    crate::check::external::ended(status)
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
        if let Err(e) = crate::image::ExrContents::read(&out) {
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
        let (candidate, _, _) = candidate::candidate(&outs, &reference, Some(args.settings.spp))?;
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
    crate::output::write_file(&path, body.as_bytes())?;
    Ok(Written::Scene(path, Box::new(file)))
}
