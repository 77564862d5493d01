//! Grading a submission: the exercises' bodies of a worked hand-out put into the
//! edition's own code, judged by the report card, scored with the teacher's weights.
//! Chapter: *Coursework* (`chapters/coursework.md`); run by `raylemma grade SUBMISSION`.
//!
//! **Only the bodies count.** [`splice`] takes every file of this crate as the edition
//! ships it and replaces each marked body with the lines between the same exercise's
//! markers in the submission. Whatever else the submission changed is the edition's
//! again: a helper the checks call (the disc's `disc_pdf`, whose change would make a
//! non-uniform `disc_polar` look uniform), a test, a checker, the registry, a `use` line.
//! So a body must say everything it needs (a `use` inside the body, a helper as a nested
//! `fn`). An exercise whose markers the submission lost or broke is graded as its stub,
//! with a note that says why, and so is one whose body could reach outside its function
//! ([`refused`]: read by a tokenizer, its brackets must balance outside strings and
//! comments; no `include!`, `mod`, `macro_rules!`, `unsafe` or `extern`, and no path
//! through `std::process`, `std::fs`, `std::env` and the like).
//!
//! **Points.** [`Weights`] come from one TOML file the teacher writes:
//!
//! ```toml
//! default = 1          # points of an exercise the table below does not name
//! [points]
//! disc_polar = 2
//! "Sellmeier::index" = 3
//! ```
//!
//! An exercise scores its points when it passes and 0 otherwise ([`score`]); `raylemma
//! grade` ([`run`]) judges the submission's graded copy ([`judge`]) and writes the grade
//! as text, JSON, JUnit XML and Gradescope's `results.json` ([`report`]).

use std::collections::BTreeMap;
use std::path::Path;

use serde::Deserialize;

use super::card::{Entry, Report};
use super::edition::File;
use super::marker::{self, Marker};
use super::stub;
use crate::data::DataError;

mod job;
pub mod judge;
pub mod report;

pub use job::{GradeError, Job, run};

/// The body of `m` in `text` (a file of the submission whose markers are `theirs`): the
/// lines strictly between its signature and its closing `}`, or why there is none or it
/// is refused ([`refused`]).
fn body_of(m: &Marker, text: &str, theirs: &[Marker]) -> Result<Vec<String>, String> {
    let Some(t) = theirs.iter().find(|t| t.name == m.name) else {
        return Err(format!(
            "{}: the markers of `{}` are not in the submission's file: graded as not started",
            m.file, m.name
        ));
    };
    let body: Vec<String> = text
        .lines()
        .skip(t.signature_end)
        .take(t.close - t.signature_end - 1)
        .map(str::to_string)
        .collect();
    match refused(&body) {
        Some((line, why)) => Err(format!(
            "{}:{}: the body of `{}` is refused: {why}: graded as not started",
            m.file,
            t.signature_end + line,
            m.name
        )),
        None => Ok(body),
    }
}

/// Why the lines `body` of an exercise cannot go into the edition's code, with the line
/// of the body (1-based) where it shows, or `None`. Chapter *Coursework*, "What the grader
/// stops".
///
/// The body is read by a Rust tokenizer (proc-macro2's, which lexes strings, raw strings,
/// characters, lifetimes and nested comments as rustc does). It is refused when:
///
/// - it does not tokenize: a bracket that does not balance outside strings and comments,
///   or a string or comment not closed. Only such a body can end outside its function
///   (`} #[cfg(any())] mod hidden { fn h() {`, closed by a later body, hides and
///   replaces the edition's code between them); a body whose brackets balance is, in the
///   edition, all inside the function's braces;
/// - a line of it is an exercise marker (it would move the graded copy's markers);
/// - it reads a file into the code (`include!`, `include_str!`, `include_bytes!`),
///   declares a module (`mod`: with `#[path]`, another file), defines a macro
///   (`macro_rules!`, which `#[macro_export]` would put at the crate's root), or uses
///   `unsafe` or `extern` (memory, symbols and linking outside the language's rules).
///
/// - it names, as a path, a module that reaches outside the computation (`REACHES`:
///   `std::process`, `std::fs`, `std::env`, `std::net`, `std::os`, `std::thread`, the
///   crate's file writer and its runner of other programs): a body that writes a card of
///   its own to the card's JSON file and calls `std::process::exit(0)` would otherwise
///   score every exercise.
///
/// This is a reading of the text, not a sandbox: what a body does when it runs through
/// a path this list does not name (a dependency's file writer, a process ended by a panic
/// inside a panic) no reading of its text stops. Chapter *Coursework* says which need one.
pub fn refused(body: &[String]) -> Option<(usize, String)> {
    if let Some(i) = body.iter().position(|l| marker::is_marker_line(l)) {
        return Some((i + 1, "a line of it is an exercise marker".into()));
    }
    match body.join("\n").parse::<proc_macro2::TokenStream>() {
        Err(e) => Some((
            e.span().start().line.max(1),
            "its brackets do not balance outside strings and comments, or a string or comment \
             is not closed: a body must end inside its own function"
                .into(),
        )),
        Ok(tokens) => forbidden(tokens),
    }
}

/// The modules a body may not name as a path (`std::process::exit`, `use std::fs;`,
/// `crate::output::write_file`), with what they reach: an exercise computes, and what it
/// would do with these is the grader's to fear (exit the card early, write the card's JSON
/// file, rewrite it from another thread or process).
const REACHES: [(&str, &str); 10] = [
    ("process", "the process (exiting it, starting others)"),
    ("fs", "files"),
    ("env", "the command line and the environment"),
    ("net", "the network"),
    ("os", "the operating system"),
    ("thread", "threads"),
    ("output", "files (the crate's writer, `output`)"),
    ("raylemma_output", "files (the crate's writer)"),
    ("external", "other programs (the crate's `check::external`)"),
    (
        "exercise",
        "the card and the grader (the crate's `exercise`; only the stub's `crate::exercise::todo` may name it)",
    ),
];

/// The first token of `tokens` (at any depth) that [`refused`] does not allow, with its
/// line and why.
fn forbidden(tokens: proc_macro2::TokenStream) -> Option<(usize, String)> {
    forbidden_in(tokens, false)
}

/// [`forbidden`] of `tokens`, `in_use` when they are inside a `use` item (each name in
/// them a path's).
fn forbidden_in(tokens: proc_macro2::TokenStream, in_use: bool) -> Option<(usize, String)> {
    use proc_macro2::TokenTree;
    let trees: Vec<TokenTree> = tokens.into_iter().collect();
    let colon = |k: usize| matches!(trees.get(k), Some(TokenTree::Punct(p)) if p.as_char() == ':');
    let mut using = in_use;
    for (i, tree) in trees.iter().enumerate() {
        let ident = match tree {
            TokenTree::Group(g) => match forbidden_in(g.stream(), using) {
                Some(found) => return Some(found),
                None => continue,
            },
            TokenTree::Punct(p) if p.as_char() == ';' => {
                using = in_use;
                continue;
            }
            TokenTree::Ident(ident) => ident,
            TokenTree::Punct(_) | TokenTree::Literal(_) => continue,
        };
        let word = ident.to_string();
        if word == "use" {
            using = true;
        }
        let bang = matches!(trees.get(i + 1), Some(TokenTree::Punct(p)) if p.as_char() == '!');
        let why = match word.as_str() {
            "include" | "include_str" | "include_bytes" if bang => {
                "it reads a file into the code when it is compiled".to_string()
            }
            "macro_rules" if bang => "it defines a macro".into(),
            "mod" => "it declares a module".into(),
            "unsafe" => "it uses `unsafe`".into(),
            "extern" => "it declares or links outside code (`extern`)".into(),
            _ => {
                // A name is a path's when `::` is before or after it, or in a `use`.
                let in_path = using
                    || (i >= 2 && colon(i - 1) && colon(i - 2))
                    || (colon(i + 1) && colon(i + 2));
                let stub = word == "exercise"
                    && !using
                    && matches!(trees.get(i + 3), Some(TokenTree::Ident(t)) if t == "todo");
                match REACHES.iter().find(|(m, _)| *m == word) {
                    Some((_, what)) if in_path && !stub => format!(
                        "it reaches {what}, which an exercise has no need of and the grader cannot \
                         let a body touch"
                    ),
                    _ => continue,
                }
            }
        };
        return Some((ident.span().start().line, format!("{why} (`{ident}`)")));
    }
    None
}

/// This crate's files `sources` with every exercise of `exercises` given the body it has
/// in the submission under `submission`, and one note per exercise graded as its stub
/// because the submission's file is missing, unreadable or lost the exercise's markers
/// (`chapters` are the book's, to parse the submission's markers against).
pub fn splice(
    sources: Vec<File>,
    exercises: &[Marker],
    chapters: &[String],
    submission: &Path,
) -> (Vec<File>, Vec<String>) {
    let mut notes = Vec::new();
    let mut out = Vec::with_capacity(sources.len());
    for mut file in sources {
        let mine = super::edition::markers_of(exercises, &file.path);
        if mine.is_empty() {
            out.push(file);
            continue;
        }
        let theirs = std::fs::read(submission.join(&file.path))
            .map_err(|e| format!("{}: cannot read the submission's copy: {e}", file.path))
            .and_then(|bytes| {
                String::from_utf8(bytes).map_err(|_| format!("{}: not UTF-8", file.path))
            })
            .and_then(|text| {
                let markers = marker::parse(&file.path, &text, chapters)
                    .map_err(|e| format!("the submission's markers are malformed: {e}"))?;
                Ok((text, markers))
            });
        let mut bodies = BTreeMap::new();
        match &theirs {
            Ok((text, markers)) => {
                for m in &mine {
                    match body_of(m, text, markers) {
                        Ok(body) => {
                            bodies.insert(m.name.clone(), body);
                        }
                        Err(note) => notes.push(note),
                    }
                }
            }
            Err(e) => notes.push(format!(
                "{e}: its exercises ({}) are graded as not started",
                mine.iter()
                    .map(|m| m.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            )),
        }
        let text = String::from_utf8_lossy(&file.bytes).into_owned();
        let (spliced, _) = stub::replace_bodies(&text, &mine, |m| {
            bodies
                .get(&m.name)
                .cloned()
                .unwrap_or_else(|| vec![stub::stub_line(&m.indent, &m.name)])
        });
        file.bytes = spliced.into_bytes();
        out.push(file);
    }
    (out, notes)
}

/// The grade's note when the submission's hand-out was made from commit `stamped` (its
/// stamp's, `None` if it records none) and the grader's code is at `ours` (`None` if the
/// grader is not a git clone): the bodies are judged by the grader's checks and spliced
/// into its code, so they should be the hand-out's. `None` when the two are the same
/// commit, unmodified.
pub fn commit_note(stamped: Option<&str>, ours: Option<&str>) -> Option<String> {
    match (stamped, ours) {
        (Some(s), Some(o)) if s == o && !o.ends_with("-modified") => None,
        (Some(s), Some(o)) => Some(format!(
            "the hand-out was made from commit {s}; this grader's code is {o}: its checks and \
             the code around the bodies may differ from the hand-out's (grade with a build of \
             the hand-out's commit, `git checkout {}`)",
            s.trim_end_matches("-modified")
        )),
        (None, _) => Some(
            "the hand-out's stamp records no commit (made by an older raylemma, or not from a \
             git clone): the grader cannot check that its code is the hand-out's"
                .into(),
        ),
        (Some(s), None) => Some(format!(
            "the hand-out was made from commit {s}; this grader is not a git clone, so it \
             cannot check that its code is that commit's"
        )),
    }
}

/// Points per exercise, from the teacher's weights file (see the module's documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct Weights {
    /// The points of an exercise `points` does not name.
    pub default: f64,
    /// Points by exercise name.
    pub points: BTreeMap<String, f64>,
}

impl Default for Weights {
    /// One point an exercise.
    fn default() -> Self {
        Weights {
            default: 1.0,
            points: BTreeMap::new(),
        }
    }
}

impl Weights {
    /// The points of the exercise `name`.
    pub fn of(&self, name: &str) -> f64 {
        self.points.get(name).copied().unwrap_or(self.default)
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawWeights {
    default: Option<toml::Spanned<f64>>,
    #[serde(default)]
    points: BTreeMap<toml::Spanned<String>, toml::Spanned<f64>>,
}

/// Reads the weights file `text` (named `file` in errors) for the exercises `exercises`.
///
/// # Errors
/// A [`DataError`] with the line: not TOML or a key other than `default` and `points`,
/// points that are negative or not finite, or an exercise name no marker has (a typo
/// would silently give the default).
pub fn parse_weights(text: &str, file: &str, exercises: &[Marker]) -> Result<Weights, DataError> {
    let line = |offset: usize| crate::data::line_of(text, offset);
    let raw: RawWeights = toml::from_str(text).map_err(|e| {
        let at = e.span().map_or(0, |s| line(s.start));
        DataError::new(file, at, e.message().to_string())
    })?;
    let checked = |v: &toml::Spanned<f64>, what: &str| {
        let x = *v.get_ref();
        if x.is_finite() && x >= 0.0 {
            Ok(x)
        } else {
            Err(DataError::new(
                file,
                line(v.span().start),
                format!("{what} must be a number of points >= 0, not {x}"),
            ))
        }
    };
    let default = match &raw.default {
        Some(v) => checked(v, "`default`")?,
        None => 1.0,
    };
    let mut points = BTreeMap::new();
    for (name, v) in &raw.points {
        let name_text = name.get_ref();
        if !exercises.iter().any(|m| m.name == *name_text) {
            let mut known: Vec<&str> = exercises.iter().map(|m| m.name.as_str()).collect();
            known.sort_unstable();
            return Err(DataError::new(
                file,
                line(name.span().start),
                format!(
                    "no exercise is called `{name_text}`; the exercises are: {}",
                    known.join(", ")
                ),
            ));
        }
        points.insert(name_text.clone(), checked(v, &format!("`{name_text}`"))?);
    }
    Ok(Weights { default, points })
}

/// One exercise's grade.
#[derive(Clone, Debug, PartialEq)]
pub struct Graded {
    /// The card's row.
    pub entry: Entry,
    /// Points scored: all of `max` if it passes, else 0.
    pub score: f64,
    /// Points it is worth.
    pub max: f64,
}

/// A submission's grade.
#[derive(Clone, Debug, PartialEq)]
pub struct Grade {
    /// One per exercise, in the book's order.
    pub rows: Vec<Graded>,
    /// What the grader noted (exercises graded as stubs, a build that failed).
    pub notes: Vec<String>,
}

impl Grade {
    /// Points scored.
    pub fn score(&self) -> f64 {
        self.rows.iter().map(|r| r.score).sum()
    }
    /// Points possible.
    pub fn max(&self) -> f64 {
        self.rows.iter().map(|r| r.max).sum()
    }
}

/// The grade of the card `report` with `weights`, and the grader's `notes`.
pub fn score(report: &Report, weights: &Weights, notes: Vec<String>) -> Grade {
    let rows = report
        .rows
        .iter()
        .map(|e| {
            let max = weights.of(&e.name);
            Graded {
                entry: e.clone(),
                score: if e.passed() { max } else { 0.0 },
                max,
            }
        })
        .collect();
    let mut notes = notes;
    notes.extend(report.problems.iter().cloned());
    Grade { rows, notes }
}

/// The grade of a submission that did not build: every exercise 0, the compiler's words
/// (`why`) as the note and as every exercise's detail.
pub fn unbuilt(exercises: &[Marker], weights: &Weights, why: &str, notes: Vec<String>) -> Grade {
    let report = Report {
        rows: exercises
            .iter()
            .map(|m| Entry {
                name: m.name.clone(),
                chapter: m.chapter.clone(),
                file: m.file.clone(),
                status: "failing".into(),
                details: vec!["the submission does not compile (see the grade's notes)".into()],
                section: None,
            })
            .collect(),
        problems: Vec::new(),
    };
    let mut notes = notes;
    notes.push(format!("the submission does not compile:\n{why}"));
    score(&report, weights, notes)
}
