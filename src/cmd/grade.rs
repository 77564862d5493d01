//! `raylemma grade SUBMISSION`: grades a worked hand-out (`src/exercise/grade.rs`). Its
//! exercise bodies are put into the edition's own code, in a copy kept under `--work`
//! with its own target folder (the next submission rebuilds only the library, in
//! seconds, not the dependencies). The copy's `raylemma card --json` judges them, and
//! the grade is written to `--out`: `grade.txt`, `grade.json`, `junit.xml` and
//! Gradescope's `results.json`, all four or none.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use clap::Args;
use raylemma::exercise::card::Report;
use raylemma::exercise::edition::{self, Kind, STAMP};
use raylemma::exercise::grade::{self, Grade, Graded, Weights};
use raylemma::exercise::marker;
use raylemma::output::FileSet;

use super::{CmdResult, Failure, Outcome, root, xml_escape};

/// `raylemma grade`.
#[derive(Args, Debug)]
pub struct GradeArgs {
    /// The submission: a hand-out (`raylemma exercises DIR`) a student worked in.
    pub submission: PathBuf,
    /// The folder the grade is written to (grade.txt, grade.json, junit.xml, results.json).
    #[arg(long, value_name = "DIR", default_value = "grade")]
    pub out: PathBuf,
    /// The teacher's points per exercise (TOML: `default = 1` and a `[points]` table);
    /// without it, one point an exercise.
    #[arg(long, value_name = "FILE")]
    pub weights: Option<PathBuf>,
    /// Where the graded copy is written and built (its target folder is DIR/target, or
    /// $CARGO_TARGET_DIR if set), kept between submissions (default: `raylemma-grade` in
    /// the system's cache folder, ~/.cache).
    #[arg(long, value_name = "DIR")]
    pub work: Option<PathBuf>,
    /// Seconds the build and the card may take together before the grade says so.
    #[arg(long, value_name = "SECONDS", default_value_t = 1800)]
    pub limit: u64,
}

/// Runs `raylemma grade`: 0 if every exercise passes, 1 if one does not (the grade is
/// written either way), 2 for a submission that is not a hand-out, a bad weights file or
/// a folder that cannot be written.
pub fn run(args: &GradeArgs) -> CmdResult {
    if !args.submission.join(STAMP).is_file() {
        return Err(Failure::BadInput(format!(
            "{}: not a raylemma edition (it has no {STAMP}; make one with `raylemma exercises DIR`)",
            args.submission.display()
        )));
    }
    let root = root();
    let sources = edition::read_sources(&root)?;
    let exercises = edition::markers(&sources)?;
    let summary = std::fs::read_to_string(root.join("chapters/SUMMARY.md"))
        .map_err(|e| Failure::Failed(format!("cannot read chapters/SUMMARY.md: {e}")))?;
    let chapters = marker::chapters(&summary);
    let weights = match &args.weights {
        Some(path) => {
            let (text, name) = raylemma::data::read_text(path)?;
            grade::parse_weights(&text, &name, &exercises)?
        }
        None => Weights::default(),
    };
    let (files, mut notes) = grade::splice(sources, &exercises, &chapters, &args.submission);
    let stamp = std::fs::read_to_string(args.submission.join(STAMP)).unwrap_or_default();
    if let Some(note) = grade::commit_note(
        edition::stamped_commit(&stamp),
        edition::commit_of(&root).as_deref(),
    ) {
        eprintln!("raylemma: {note}");
        notes.insert(0, note);
    }
    let graded = edition::make(files, Kind::Graded)?;
    let work = args.work.clone().unwrap_or_else(default_work);
    let copy = work.join("crate");
    raylemma::output::create_dir_all(&work)?;
    edition::write(&graded, &copy)?;
    eprintln!(
        "raylemma: grading {}: its {} exercise bodies in the edition's own code, at {}",
        args.submission.display(),
        exercises.len(),
        copy.display()
    );
    let limit = Duration::from_secs(args.limit);
    let judged = judge(&copy, &work, limit).and_then(|report| {
        // Every exercise, in the book's order, and nothing else: a card with other rows
        // was not written by the card.
        let names = |r: &Report| r.rows.iter().map(|e| e.name.clone()).collect::<Vec<_>>();
        let want: Vec<String> = exercises.iter().map(|m| m.name.clone()).collect();
        if names(&report) == want {
            Ok(report)
        } else {
            Err(format!(
                "the card's JSON does not list the edition's {} exercises in order: it is not trusted",
                want.len()
            ))
        }
    });
    let grade = match judged {
        Ok(report) => grade::score(&report, &weights, notes),
        Err(why) => grade::unbuilt(&exercises, &weights, &why, notes),
    };
    let text = text(&grade, &args.submission);
    write_all(&args.out, &grade, &text)?;
    print!("{text}");
    eprintln!("raylemma: wrote the grade to {}", args.out.display());
    Ok(if grade.rows.iter().all(|r| r.entry.passed()) {
        Outcome::Done
    } else {
        Outcome::Negative
    })
}

/// `raylemma-grade` in the cache folder (`$XDG_CACHE_HOME`, else `~/.cache`, else the
/// system's temporary folder).
fn default_work() -> PathBuf {
    std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
        .unwrap_or_else(std::env::temp_dir)
        .join("raylemma-grade")
}

/// Builds the graded copy at `copy` (target folder `$CARGO_TARGET_DIR` or `work/target`:
/// its package, `raylemma-graded`, keeps its build apart from the other editions') and
/// runs its card;
/// the card as data, or why there is none (the compiler's errors, a time-out).
fn judge(copy: &Path, work: &Path, limit: Duration) -> Result<Report, String> {
    let json = work.join("card.json");
    let log = work.join("build.log");
    let _ = std::fs::remove_file(&json);
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let log_file =
        std::fs::File::create(&log).map_err(|e| format!("cannot write {}: {e}", log.display()))?;
    eprintln!(
        "raylemma: building the graded copy (the first submission builds the dependencies, minutes; later ones only the library) and running its card; cargo's output goes to {}",
        log.display()
    );
    let mut child = Command::new(&cargo)
        .args([
            "run",
            "--profile",
            "test",
            "--quiet",
            "--bin",
            "raylemma",
            "--",
            "card",
        ])
        .arg("--json")
        .arg(&json)
        .current_dir(copy)
        .env(
            "CARGO_TARGET_DIR",
            std::env::var_os("CARGO_TARGET_DIR").unwrap_or_else(|| work.join("target").into()),
        )
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(log_file)
        .spawn()
        .map_err(|e| format!("cannot start cargo: {e}"))?;
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if start.elapsed() >= limit => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!(
                    "the build and the card did not finish within {} s (--limit)",
                    limit.as_secs()
                ));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(200)),
            Err(e) => return Err(format!("cannot wait for cargo: {e}")),
        }
    };
    match std::fs::read_to_string(&json) {
        // The card ends with 0 or 1 after writing its JSON: a JSON file with any other end
        // (a signal, an abort, an exit of a status of the body's choosing) is not the card's.
        Ok(_) if !matches!(status.code(), Some(0 | 1)) => Err(format!(
            "the graded copy's card ended with {status} after its JSON was written, not as the card ends (0 or 1): the JSON is not trusted; the end of {}:\n{}",
            log.display(),
            tail(&std::fs::read_to_string(&log).unwrap_or_default(), 20)
        )),
        Ok(text) => serde_json::from_str(&text)
            .map_err(|e| format!("the card's JSON ({}) cannot be read: {e}", json.display())),
        Err(_) => {
            let said = std::fs::read_to_string(&log).unwrap_or_default();
            let errors: Vec<&str> = said
                .lines()
                .skip_while(|l| !l.starts_with("error"))
                .take(40)
                .collect();
            Err(if errors.is_empty() {
                format!(
                    "the graded copy's card did not finish ({status}); the end of {}:\n{}",
                    log.display(),
                    tail(&said, 20)
                )
            } else {
                errors.join("\n")
            })
        }
    }
}

fn tail(text: &str, n: usize) -> String {
    let lines: Vec<&str> = text.lines().collect();
    lines[lines.len().saturating_sub(n)..].join("\n")
}

/// The grade in words: a line per exercise with its points, what is wrong, the notes.
fn text(grade: &Grade, submission: &Path) -> String {
    let mut s = format!(
        "GRADE of {}: {} of {} points\n",
        submission.display(),
        points(grade.score()),
        points(grade.max())
    );
    for r in &grade.rows {
        let _ = writeln!(
            s,
            "  {:>6} / {:<6} {:<11} {} ({})",
            points(r.score),
            points(r.max),
            r.entry.status,
            r.entry.name,
            r.entry.chapter
        );
        for d in &r.entry.details {
            let _ = writeln!(s, "      {d}");
        }
    }
    for n in &grade.notes {
        let _ = writeln!(s, "  note: {n}");
    }
    s
}

/// Points as the grade prints them: `2`, `0.5`.
fn points(x: f64) -> String {
    format!("{x}")
}

/// Writes the four files of the grade into `out`, all or none.
fn write_all(out: &Path, grade: &Grade, text: &str) -> Result<(), raylemma::output::FileError> {
    raylemma::output::create_dir_all(out)?;
    let mut set = FileSet::new();
    set.write(&out.join("grade.txt"), text.as_bytes())?;
    set.write(&out.join("grade.json"), json(grade).as_bytes())?;
    set.write(&out.join("junit.xml"), junit(grade).as_bytes())?;
    set.write(&out.join("results.json"), gradescope(grade).as_bytes())?;
    set.commit()?;
    Ok(())
}

/// What a row says in words: its status and the lines under it.
fn output(r: &Graded) -> String {
    let mut s = format!("{} ({}, {})", r.entry.status, r.entry.chapter, r.entry.file);
    for d in &r.entry.details {
        s.push_str("\n  ");
        s.push_str(d);
    }
    s
}

/// The grade as JSON: `score`, `max_score`, `notes` and one object per exercise.
fn json(grade: &Grade) -> String {
    let rows: Vec<serde_json::Value> = grade
        .rows
        .iter()
        .map(|r| {
            serde_json::json!({
                "name": r.entry.name,
                "chapter": r.entry.chapter,
                "file": r.entry.file,
                "status": r.entry.status,
                "details": r.entry.details,
                "score": r.score,
                "max_score": r.max,
            })
        })
        .collect();
    let v = serde_json::json!({
        "score": grade.score(),
        "max_score": grade.max(),
        "notes": grade.notes,
        "exercises": rows,
    });
    serde_json::to_string_pretty(&v).unwrap_or_default() + "\n"
}

/// The grade as Gradescope's `results.json`: the total, the notes as the output, and one
/// test per exercise with its score, maximum, status and what is wrong.
fn gradescope(grade: &Grade) -> String {
    let tests: Vec<serde_json::Value> = grade
        .rows
        .iter()
        .map(|r| {
            serde_json::json!({
                "name": r.entry.name,
                "score": r.score,
                "max_score": r.max,
                "status": if r.entry.passed() { "passed" } else { "failed" },
                "output": output(r),
            })
        })
        .collect();
    let v = serde_json::json!({
        "score": grade.score(),
        "output": grade.notes.join("\n"),
        "tests": tests,
    });
    serde_json::to_string_pretty(&v).unwrap_or_default() + "\n"
}

/// The grade as JUnit XML: one test case per exercise (class: its chapter), a failure for
/// each exercise that does not pass.
fn junit(grade: &Grade) -> String {
    let failures = grade.rows.iter().filter(|r| !r.entry.passed()).count();
    let mut s = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"raylemma exercises\" tests=\"{}\" failures=\"{failures}\">\n",
        grade.rows.len()
    );
    for r in &grade.rows {
        let name = xml_escape(&r.entry.name);
        let class = xml_escape(&r.entry.chapter);
        if r.entry.passed() {
            let _ = writeln!(s, "  <testcase classname=\"{class}\" name=\"{name}\"/>");
        } else {
            let _ = writeln!(
                s,
                "  <testcase classname=\"{class}\" name=\"{name}\"><failure message=\"{}\">{}</failure></testcase>",
                xml_escape(&r.entry.status),
                xml_escape(&output(r))
            );
        }
    }
    if !grade.notes.is_empty() {
        let _ = writeln!(
            s,
            "  <system-out>{}</system-out>",
            xml_escape(&grade.notes.join("\n"))
        );
    }
    s += "</testsuite>\n";
    s
}
