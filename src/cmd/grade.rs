//! `raylemma grade SUBMISSION`: grades a worked hand-out (`src/exercise/grade/`). Its
//! exercise bodies are put into the edition's own code, in a copy kept under `--work`
//! with its own target folder (the next submission rebuilds only the library, in
//! seconds, not the dependencies). The copy's `raylemma card --json` judges them, and
//! the grade is written to `--out`: `grade.txt`, `grade.json`, `junit.xml` and
//! Gradescope's `results.json`, all four or none.

use std::path::PathBuf;
use std::time::Duration;

use clap::Args;
use raylemma::exercise::grade::{self, GradeError, Job};

use super::{CmdResult, Failure, Outcome, root};

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
    let root = root();
    let job = Job {
        root: &root,
        submission: &args.submission,
        out: &args.out,
        weights: args.weights.as_deref(),
        work: args.work.as_deref(),
        limit: Duration::from_secs(args.limit),
    };
    match grade::run(&job) {
        Ok(grade) if grade.rows.iter().all(|r| r.entry.passed()) => Ok(Outcome::Done),
        Ok(_) => Ok(Outcome::Negative),
        Err(e @ GradeError::Summary(_)) => Err(Failure::Failed(e.to_string())),
        Err(e) => Err(e.into()),
    }
}
