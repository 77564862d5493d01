//! The conformance card: one line per rung of the ladder and depth (its verdict, the
//! whole image's relative difference, the worst block or the failed tests, how the renderer
//! failed), the first failing rung with what it tests and what a failure there usually
//! means, and the verdict; as text for people ([`text`]), JSON ([`json`]) and JUnit XML
//! ([`junit`], for CI systems and autograders). [`super::run`] fills it. Chapter:
//! *Reference scenes and interop* (`chapters/renderer/scenes.md`, *The conformance ladder*).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::compare::{self, Failures};
use super::ladder::{Rung, header};

/// The scene format the candidate reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// raylemma's own TOML (data paths made absolute).
    Toml,
    /// Fully resolved JSON.
    Json,
    /// Mitsuba 3 XML; the rungs it refuses (the spectral-only ones) are skipped.
    Mitsuba,
    /// pbrt-v4; the rungs it refuses (thin films) are skipped.
    Pbrt,
}

/// What a card was run with, as the card states it.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// The renderer's command template.
    pub renderer: String,
    /// The scene format it reads.
    pub format: Format,
    /// Renders of each rung, with different seeds.
    pub runs: u32,
    /// Samples per pixel of each render.
    pub spp: u32,
    /// The card's seed.
    pub seed: u64,
    /// The family-wise false-alarm rate of the whole card.
    pub alpha: f64,
}

/// The suite a card runs: where its files are, where they came from, and their hash.
pub struct Suite {
    /// The folder holding `scenes/conformance/`, `data/` and `figures/reference/conformance/`.
    pub dir: PathBuf,
    /// "built into this binary" or the folder given.
    pub source: String,
    /// FNV-1a of every file of [`super::ladder::SUITE`]'s list, its path then its bytes, in hexadecimal:
    /// the same for a folder whose files are the built-in ones.
    pub hash: String,
}

impl Suite {
    /// The folder of the ladder's scene files.
    pub fn scenes(&self) -> PathBuf {
        self.dir.join("scenes/conformance")
    }
}

/// One line of the card.
pub struct Row {
    pub rung: Rung,
    pub depth: Option<u32>,
    /// `agree`, `differ`, `error` (the renderer failed, or the suite could not be read) or
    /// `skipped`.
    pub verdict: &'static str,
    /// The whole image's relative difference per channel with its 95 % half-width.
    pub bias: Option<[(f64, f64); 3]>,
    /// `agree`: the worst block; `differ`: the tests that failed ([`Failures::text`]);
    /// `error`: what failed; `skipped`: why.
    pub detail: String,
    /// The tests that failed, when it differs.
    pub failures: Option<Failures>,
    /// How the renderer failed, when it did: never a verdict on its physics.
    pub run_failure: Option<RunFailure>,
    /// What the difference looks like ([`super::diagnose::diagnose`]), when it differs.
    pub diagnosis: Vec<String>,
}

/// How one run of the renderer failed: the command as run, what happened (its exit
/// status, its time running out, no image, an image that cannot be read), the last lines
/// of its output, and the image it was to write.
pub struct RunFailure {
    pub command: String,
    pub what: String,
    pub log_tail: Vec<String>,
    pub log: PathBuf,
    pub expected: PathBuf,
}

/// The last lines of the renderer's output (stdout and stderr together) kept on a card.
const LOG_TAIL: usize = 8;

impl RunFailure {
    /// The failure of `command`, `what` happened, its output in `log`, the image it was
    /// to write `expected`.
    pub fn new(command: &str, what: String, log: &Path, expected: &Path) -> RunFailure {
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
    pub fn text(&self, indent: &str) -> String {
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

    /// The failure as JSON.
    pub fn json(&self) -> serde_json::Value {
        serde_json::json!({
            "command": self.command,
            "what": self.what,
            "log": self.log.display().to_string(),
            "log_tail": self.log_tail,
            "expected": self.expected.display().to_string(),
        })
    }
}

/// `depth 2`, or `own depth` (the rung's own).
pub fn depth_name(depth: Option<u32>) -> String {
    depth.map_or("own depth".into(), |d| format!("depth {d}"))
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
pub fn text(rows: &[Row], args: &Settings, suite: &Suite) -> String {
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

/// The card as JSON (pretty-printed, one trailing newline).
pub fn json(rows: &[Row], args: &Settings, suite: &Suite) -> String {
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

/// The card as JUnit XML: one test case per row; `differ` a failure, `error` an error,
/// `skipped` skipped.
pub fn junit(rows: &[Row]) -> String {
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

/// `s` as XML text or attribute value (the JUnit files of `conformance` and `grade`).
pub fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
