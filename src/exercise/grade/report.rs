//! The grade written down: as text for a person ([`text`]), as JSON ([`json`]), as
//! Gradescope's `results.json` ([`gradescope`]) and as JUnit XML ([`junit`]); `raylemma
//! grade` writes all four into its `--out` folder ([`write_all`]), all or none. Chapter:
//! *Coursework* (`chapters/coursework.md`).

use std::fmt::Write as _;
use std::path::Path;

use super::{Grade, Graded};
use crate::conformance::card::xml_escape;
use crate::output::{FileError, FileSet};

/// The grade in words: a line per exercise with its points, what is wrong, the notes.
/// `submission` is the folder graded, named in the first line.
pub fn text(grade: &Grade, submission: &Path) -> String {
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

/// Writes the four files of the grade into `out` (`grade.txt` holding `text`,
/// `grade.json`, `junit.xml`, `results.json`), all or none.
pub fn write_all(out: &Path, grade: &Grade, text: &str) -> Result<(), FileError> {
    crate::output::create_dir_all(out)?;
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
pub fn json(grade: &Grade) -> String {
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
pub fn gradescope(grade: &Grade) -> String {
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
pub fn junit(grade: &Grade) -> String {
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
