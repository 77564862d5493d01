//! The report card: every exercise's checkers run on the crate's own functions, one
//! exercise at a time, each isolated from the others' panics. Chapter: *Coursework*
//! (`chapters/coursework.md`).
//!
//! An exercise is *not started* when its own stub panics ([`super::todo`]), *waiting*
//! when the stub of an exercise it calls panics first, *failing* when a checker's verdict
//! fails (the card lists each failed claim with its count and worst error against the
//! bound) or its code panics or does not return within [`LIMIT`], and *passing* when
//! every verdict passes. The edition's `cargo test` prints the card at its very end
//! (`tests/book/report_card.rs`).

use std::cell::Cell;
use std::fmt;
use std::panic::{self, AssertUnwindSafe};
use std::sync::{Once, mpsc};
use std::time::Duration;

use serde::{Deserialize, Serialize};

use super::marker::Marker;
use super::mistakes;
use super::registry::{self, LATER};
use super::section::{self, Section};
use crate::check::Verdict;

/// Where an exercise stands.
#[derive(Clone, Debug, PartialEq)]
pub enum Status {
    /// Every verdict passed.
    Passing,
    /// A verdict failed (one line per failed claim) or the code panicked (its message).
    Failing(Vec<String>),
    /// The stub of another exercise, named here, panicked first.
    Waiting(String),
    /// Its own stub panicked.
    NotStarted,
    /// No checks are registered for it (a mistake of the crate, not the student's).
    Unchecked,
}

impl Status {
    /// The status in the card's first column.
    pub fn label(&self) -> &'static str {
        match self {
            Status::Passing => "passing",
            Status::Failing(_) => "failing",
            Status::Waiting(_) => "waiting",
            Status::NotStarted => "not started",
            Status::Unchecked => "unchecked",
        }
    }

    /// The lines the card prints under the row: the failed claims or the panic, what it
    /// waits for; none if passing or not started.
    pub fn details(&self) -> Vec<String> {
        match self {
            Status::Failing(lines) => lines.clone(),
            Status::Waiting(other) => vec![format!("waiting for `{other}`")],
            Status::Unchecked => vec!["no checks are registered for it".into()],
            Status::Passing | Status::NotStarted => Vec::new(),
        }
    }
}

/// One exercise on the card.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The exercise.
    pub name: String,
    /// Its chapter (`sampling/disc`).
    pub chapter: String,
    /// Its file.
    pub file: String,
    /// Where it stands.
    pub status: Status,
    /// What finishing it unlocks (exercises, then later checks).
    pub unlocks: Vec<&'static str>,
    /// The section of its chapter that teaches it ([`Card::with_sections`]).
    pub section: Option<Section>,
}

/// The report card.
#[derive(Clone, Debug, PartialEq)]
pub struct Card {
    /// One row per exercise, in the book's order.
    pub rows: Vec<Row>,
    /// Registry entries with no marker (mistakes of the crate).
    pub problems: Vec<String>,
}

thread_local! {
    /// True while this thread runs an exercise's checks: its panics are the card's to
    /// report, not the panic hook's to print.
    static QUIET: Cell<bool> = const { Cell::new(false) };
    /// Where the last quiet panic of this thread happened (`src/sampling/disc.rs:21:5`):
    /// the card names it under the exercise.
    static PANICKED_AT: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

/// Installs, once, a panic hook that stays silent on a thread running the card's checks
/// and defers to the hook that was there (libtest's capture, or the default) elsewhere.
fn quiet_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if QUIET.with(Cell::get) {
                let at = info
                    .location()
                    .map(|l| format!("{}:{}:{}", l.file(), l.line(), l.column()));
                PANICKED_AT.with(|p| *p.borrow_mut() = at);
            } else {
                previous(info);
            }
        }));
    });
}

/// The folder of exercise `name`'s own pictures, relative to the crate's root:
/// `results/NAME/` (`::` written `-`), where its checks draw their failure images when the
/// card judges it; removed when it passes.
pub fn results_dir(name: &str) -> std::path::PathBuf {
    std::path::Path::new("results").join(name.replace("::", "-"))
}

/// How long one exercise's checks may run before the card judges them stuck: every
/// exercise's checks on the solutions take a fraction of a second (24 in about 1 s on 2
/// cores), so 30 s is a loop, not a slow machine.
pub const LIMIT: Duration = Duration::from_secs(30);

/// [`judge`] on a thread of its own, given at most `limit`: checks that have not returned
/// by then are failing, and their thread is left to run (a loop cannot be stopped from
/// outside; the process ends it when it exits).
pub fn judge_within(name: &str, check: fn() -> Vec<Verdict>, limit: Duration) -> Status {
    let owned = name.to_string();
    let dir = results_dir(name);
    let judged = within(name, limit, move || {
        crate::check::pictures::with_failure_dir(dir, || judge(&owned, &check))
    });
    let status = match judged {
        Ok(status @ Status::Failing(_)) => naming(status, recognised(name)),
        Ok(status) => status,
        Err(why) => Status::Failing(vec![why]),
    };
    if status == Status::Passing {
        // Pictures of a failure that the student has since fixed would mislead.
        let _ = std::fs::remove_dir_all(results_dir(name));
    }
    status
}

/// The typical mistake that the crate's function of the failing exercise `name` behaves
/// like ([`mistakes::recognise`]): its probe run as its checks are, quietly and within
/// [`LIMIT`] (only after they returned, so a loop is never run twice).
fn recognised(name: &str) -> Option<&'static mistakes::Known> {
    let owned = name.to_string();
    within(name, LIMIT, move || {
        quiet_hook();
        QUIET.with(|q| q.set(true));
        let m = mistakes::recognise(&owned);
        QUIET.with(|q| q.set(false));
        m
    })
    .ok()?
}

/// A failing `status` with, first under it, the typical mistake its answer behaves like,
/// if one does: the card's one way of saying so.
pub fn naming(status: Status, mistake: Option<&mistakes::Known>) -> Status {
    match (status, mistake) {
        (Status::Failing(mut lines), Some(m)) => {
            lines.insert(
                0,
                format!(
                    "this behaves like a typical mistake: {} (reread the section below)",
                    m.words
                ),
            );
            Status::Failing(lines)
        }
        (status, _) => status,
    }
}

/// `f` on a thread named for the exercise `name`, given at most `limit`; why not, if the
/// thread could not start or `f` did not return in time (its thread is then left to run).
fn within<T: Send + 'static>(
    name: &str,
    limit: Duration,
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, String> {
    let (done, result) = mpsc::channel();
    std::thread::Builder::new()
        .name(format!("exercise {name}"))
        .spawn(move || {
            let _ = done.send(f());
        })
        .map_err(|e| format!("its checks could not start a thread: {e}"))?;
    result.recv_timeout(limit).map_err(|_| {
        format!(
            "{STUCK} {} s: a loop that never ends (a rejection loop that never accepts, a `while` whose condition never changes); the other exercises were judged on",
            limit.as_secs()
        )
    })
}

/// How the card's line under an exercise whose checks did not return within the limit
/// begins.
const STUCK: &str = "its checks did not return within";

/// True iff `status` says that the checks did not return within the limit: running them
/// again would wait as long again, for nothing.
pub fn stuck(status: &Status) -> bool {
    matches!(status, Status::Failing(lines) if lines.iter().any(|l| l.starts_with(STUCK)))
}

/// The full verdicts of the exercise `name`'s checks that fail (each with its claim in
/// words and its first and worst failing inputs), run as [`run`] runs them, given the
/// `status` the card gave it ([`verdicts_of`]); empty if the exercise is not registered.
pub fn failed_verdicts(name: &str, status: &Status) -> Vec<Verdict> {
    match registry::find(name) {
        Some(e) => verdicts_of(name, status, e.check),
        None => Vec::new(),
    }
}

/// The failing verdicts of `check`, the checks of the exercise `name` whose card gave it
/// `status`: run again only if it is failing and its checks returned, so that a loop is
/// never waited for twice (`raylemma card disc_polar` on a looping `disc_polar` takes the
/// card's 30 s, not 60); empty if it is not failing, or if the checks are stuck, panic or
/// do not return within [`LIMIT`] this time (the card's line says which).
pub fn verdicts_of(name: &str, status: &Status, check: fn() -> Vec<Verdict>) -> Vec<Verdict> {
    if !matches!(status, Status::Failing(_)) || stuck(status) {
        return Vec::new();
    }
    // Its pictures go where the card's went (`results/NAME/`), not into `warp-failures/`.
    let dir = results_dir(name);
    within(name, LIMIT, move || {
        crate::check::pictures::with_failure_dir(dir, || quietly(&check).unwrap_or_default())
    })
    .unwrap_or_default()
    .into_iter()
    .filter(|v| !v.passed())
    .collect()
}

/// The status of the exercise `name` from running `check` (with panics caught).
pub fn judge(name: &str, check: &dyn Fn() -> Vec<Verdict>) -> Status {
    match quietly(check) {
        Ok(verdicts) if verdicts.iter().all(Verdict::passed) && !verdicts.is_empty() => {
            Status::Passing
        }
        Ok(verdicts) => Status::Failing(verdicts.iter().flat_map(failed_claims).collect()),
        Err(payload) => {
            let message = super::panic_message(payload.as_ref());
            match super::not_started(&message) {
                Some(n) if n == name => Status::NotStarted,
                Some(other) => Status::Waiting(other.to_string()),
                None => {
                    let at = PANICKED_AT
                        .with(|p| p.borrow_mut().take())
                        .map_or_else(String::new, |at| format!(" at {at}"));
                    Status::Failing(vec![format!("panicked{at}: {}", first_line(&message))])
                }
            }
        }
    }
}

/// `check` run with its panics caught and kept off the screen (the card reports them).
fn quietly(check: &dyn Fn() -> Vec<Verdict>) -> std::thread::Result<Vec<Verdict>> {
    quiet_hook();
    QUIET.with(|q| q.set(true));
    let result = panic::catch_unwind(AssertUnwindSafe(check));
    QUIET.with(|q| q.set(false));
    result
}

fn first_line(text: &str) -> &str {
    text.lines().next().unwrap_or("")
}

/// The lines the card gives for each failed claim of `verdict`: the claim in words, in how
/// many cases it is wrong and by how much (the worst error, in its unit, against what the
/// claim allows), the input that shows it best (its first two lines, at most 300 characters each; the worst failure if
/// there is one, else the first), and the picture the checker drew, if any.
pub(crate) fn failed_claims(verdict: &Verdict) -> Vec<String> {
    if verdict.findings.is_empty() {
        return vec![format!("{}: no claim was checked", verdict.subject)];
    }
    let mut lines = Vec::new();
    for f in verdict.findings.iter().filter(|f| !f.passed()) {
        lines.push(format!("{}: `{}`: {}", verdict.subject, f.name, f.claim));
        let mut wrong = format!("  wrong in {} of {} cases", f.failures, f.cases);
        if let Some((worst, bound)) = f.worst {
            let unit = if f.unit.is_empty() {
                String::new()
            } else {
                format!(" ({})", f.unit)
            };
            wrong.push_str(&format!(
                "; worst error {worst:.3e}{unit}, where the claim allows {bound:.3e}"
            ));
        }
        lines.push(wrong);
        if let Some(example) = f.worst_example.as_ref().or(f.example.as_ref()) {
            let what = if f.worst_example.is_some() {
                "worst input"
            } else {
                "first input"
            };
            for (k, line) in example.lines().take(2).enumerate() {
                let head = if k == 0 { what } else { "" };
                lines.push(format!("  {head:<11} {}", clip(line.trim(), 300)));
            }
        }
        if let Some(picture) = &f.picture {
            lines.push(format!("  picture     {picture}"));
        }
    }
    lines
}

/// `text` cut to at most `max` characters, with an ellipsis when cut.
fn clip(text: &str, max: usize) -> String {
    if text.chars().count() <= max {
        text.to_string()
    } else {
        let cut: String = text.chars().take(max).collect();
        format!("{cut} ...")
    }
}

/// The card of the exercises `markers` (in their order), each with the status `status`
/// gives it (the figure job's demonstration card judges planted mistakes this way).
pub fn run_with(markers: &[Marker], status: impl Fn(&Marker) -> Status) -> Card {
    let rows = markers
        .iter()
        .map(|m| Row {
            name: m.name.clone(),
            chapter: m.chapter.clone(),
            file: m.file.clone(),
            status: status(m),
            unlocks: registry::unlocks(&m.name),
            section: None,
        })
        .collect();
    Card {
        rows,
        problems: Vec::new(),
    }
}

/// The card of the exercises `markers`, each judged by its checks in
/// [`registry::EXERCISES`] run on the crate's own functions, within [`LIMIT`]; a registry
/// entry that no marker names is a problem of the card.
pub fn run(markers: &[Marker]) -> Card {
    let mut card = run_some(markers);
    card.problems = registry::EXERCISES
        .iter()
        .filter(|e| !markers.iter().any(|m| m.name == e.name))
        .map(|e| {
            format!(
                "the registry checks `{}`, which no // EXERCISE marker names",
                e.name
            )
        })
        .collect();
    card
}

/// The card of some of the crate's exercises, `markers`, each judged as [`run`] judges
/// it, without comparing the registry with the markers (`raylemma card disc_polar`).
pub fn run_some(markers: &[Marker]) -> Card {
    run_with(markers, |m| match registry::find(&m.name) {
        Some(e) => judge_within(e.name, e.check, LIMIT),
        None => Status::Unchecked,
    })
}

impl Card {
    /// The card with each row's section ([`section::of`]) found in the crate's files under
    /// `root`, `markers` being the rows' exercises: the card names it under a row that
    /// is failing or waiting.
    pub fn with_sections(mut self, root: &std::path::Path, markers: &[Marker]) -> Self {
        for row in &mut self.rows {
            row.section = markers
                .iter()
                .find(|m| m.name == row.name)
                .and_then(|m| section::of(root, m));
        }
        self
    }

    /// How many rows have the status `label`.
    pub fn count(&self, label: &str) -> usize {
        self.rows
            .iter()
            .filter(|r| r.status.label() == label)
            .count()
    }

    /// True iff every exercise passes and the registry matches the markers.
    pub fn passed(&self) -> bool {
        self.problems.is_empty() && self.rows.iter().all(|r| r.status == Status::Passing)
    }

    /// The counts: `3 passing, 2 failing, 19 not started (24 exercises)`.
    pub fn total(&self) -> String {
        let mut parts = vec![format!("{} passing", self.count("passing"))];
        for label in ["failing", "waiting", "not started", "unchecked"] {
            let n = self.count(label);
            if n > 0 {
                parts.push(format!("{n} {label}"));
            }
        }
        format!("{} ({} exercises)", parts.join(", "), self.rows.len())
    }
}

/// One row of the card as `raylemma card --json` writes it and the grader reads it
/// (`super::grade`): the exercise, where it is, its status's label and the lines the
/// printed card gives under it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    /// The exercise.
    pub name: String,
    /// Its chapter (`sampling/disc`).
    pub chapter: String,
    /// Its file.
    pub file: String,
    /// [`Status::label`].
    pub status: String,
    /// What is wrong (the failed claims, a panic, what it waits for); empty if passing or
    /// not started.
    pub details: Vec<String>,
    /// The section of the chapter to reread, `The polar map
    /// (chapters/sampling/disc.md#the-polar-map)`, if the card found it.
    #[serde(default)]
    pub section: Option<String>,
}

impl Entry {
    /// True iff the exercise passes.
    pub fn passed(&self) -> bool {
        self.status == Status::Passing.label()
    }
}

/// The card as data: one [`Entry`] per row and the card's problems ([`Card::report`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Report {
    /// One entry per exercise, in the book's order.
    pub rows: Vec<Entry>,
    /// Registry entries with no marker (mistakes of the crate).
    pub problems: Vec<String>,
}

impl Card {
    /// The card as data, with the lines its text gives under each row.
    pub fn report(&self) -> Report {
        let rows = self
            .rows
            .iter()
            .map(|r| Entry {
                name: r.name.clone(),
                chapter: r.chapter.clone(),
                file: r.file.clone(),
                status: r.status.label().to_string(),
                details: r.status.details(),
                section: r
                    .section
                    .as_ref()
                    .map(|s| format!("{} ({})", s.title, s.link)),
            })
            .collect();
        Report {
            rows,
            problems: self.problems.clone(),
        }
    }
}

impl fmt::Display for Card {
    fn fmt(&self, out: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            out,
            "REPORT CARD: {} of {} exercises pass",
            self.count("passing"),
            self.rows.len()
        )?;
        let name_width = self
            .rows
            .iter()
            .map(|r| r.name.len())
            .max()
            .unwrap_or(8)
            .max(8);
        let chapter_width = self
            .rows
            .iter()
            .map(|r| r.chapter.len())
            .max()
            .unwrap_or(7)
            .max(7);
        writeln!(
            out,
            "  {:<11}  {:<name_width$}  {:<chapter_width$}  unlocks",
            "status", "exercise", "chapter"
        )?;
        for r in &self.rows {
            let unlocks = if r.unlocks.is_empty() {
                "-".to_string()
            } else {
                r.unlocks.join(", ")
            };
            writeln!(
                out,
                "  {:<11}  {:<name_width$}  {:<chapter_width$}  {unlocks}",
                r.status.label(),
                r.name,
                r.chapter
            )?;
            for line in r.status.details() {
                writeln!(out, "      {line}")?;
            }
            if let (Some(s), Status::Failing(_) | Status::Waiting(_)) = (&r.section, &r.status) {
                writeln!(out, "      reread      {} ({})", s.title, s.link)?;
            }
        }
        for p in &self.problems {
            writeln!(out, "  problem: {p}")?;
        }
        for later in LATER {
            let missing: Vec<&str> = later
                .needs
                .iter()
                .copied()
                .filter(|n| {
                    self.rows
                        .iter()
                        .any(|r| r.name == *n && r.status != Status::Passing)
                })
                .collect();
            if !missing.is_empty() {
                writeln!(
                    out,
                    "  {} ({}) needs {} more: {}",
                    later.name,
                    later.command,
                    missing.len(),
                    missing.join(", ")
                )?;
            }
        }
        writeln!(out, "total: {}", self.total())?;
        write!(
            out,
            "one exercise's full verdict, its claims in words and the inputs that fail them: cargo run -- card NAME (e.g. disc_polar); one chapter's tests: cargo test --test book CHAPTER (e.g. sampling::disc)"
        )
    }
}
