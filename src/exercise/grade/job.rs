//! Grading one submission from start to end ([`run`]): the hand-out checked, the weights
//! read, its bodies spliced into the edition's code, the graded copy written and judged
//! ([`judge`](super::judge::judge)), the grade written in its four formats
//! ([`report`](super::report)) and printed. What `raylemma grade SUBMISSION` does; the
//! command maps the result to its exit status. Chapter: *Coursework*
//! (`chapters/coursework.md`).

use std::path::{Path, PathBuf};
use std::time::Duration;

use super::{Grade, Weights, judge, report};
use crate::data::DataError;
use crate::exercise::card::Report;
use crate::exercise::edition::{self, EditionError, Kind, STAMP};
use crate::exercise::marker;
use crate::output::FileError;

/// What to grade, and where: `raylemma grade`'s flags.
#[derive(Clone, Debug)]
pub struct Job<'a> {
    /// The project whose edition the submission is (its `chapters/SUMMARY.md` and sources).
    pub root: &'a Path,
    /// The submission: a hand-out a student worked in.
    pub submission: &'a Path,
    /// The folder the grade is written to.
    pub out: &'a Path,
    /// The teacher's weights file; `None`: one point an exercise.
    pub weights: Option<&'a Path>,
    /// Where the graded copy is written and built; `None`: [`judge::default_work`].
    pub work: Option<&'a Path>,
    /// How long the build and the card may take together.
    pub limit: Duration,
}

/// Why a submission could not be graded (a grade that says an exercise fails is not an
/// error: it is written).
#[derive(Debug)]
pub enum GradeError {
    /// The submission is not a hand-out: it has no stamp.
    NotEdition(PathBuf),
    /// The project's `chapters/SUMMARY.md` cannot be read.
    Summary(std::io::Error),
    /// A file that cannot be read or written.
    File(FileError),
    /// A weights file or a marker that cannot be used.
    Data(DataError),
    /// The graded copy cannot be made or written.
    Edition(EditionError),
}

impl std::fmt::Display for GradeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GradeError::NotEdition(path) => write!(
                f,
                "{}: not a raylemma edition (it has no {STAMP}; make one with `raylemma exercises DIR`)",
                path.display()
            ),
            GradeError::Summary(e) => write!(f, "cannot read chapters/SUMMARY.md: {e}"),
            GradeError::File(e) => write!(f, "{e}"),
            GradeError::Data(e) => write!(f, "{e}"),
            GradeError::Edition(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for GradeError {}

impl From<FileError> for GradeError {
    fn from(e: FileError) -> Self {
        GradeError::File(e)
    }
}

impl From<DataError> for GradeError {
    fn from(e: DataError) -> Self {
        GradeError::Data(e)
    }
}

impl From<EditionError> for GradeError {
    fn from(e: EditionError) -> Self {
        GradeError::Edition(e)
    }
}

/// Grades `job.submission`: writes the grade to `job.out` (all four files or none),
/// prints it, and returns it (whether every exercise passes is
/// [`Grade::rows`]' to say). Progress goes to the error output.
pub fn run(job: &Job) -> Result<Grade, GradeError> {
    if !job.submission.join(STAMP).is_file() {
        return Err(GradeError::NotEdition(job.submission.to_path_buf()));
    }
    let root = job.root;
    let sources = edition::read_sources(root)?;
    let exercises = edition::markers(&sources)?;
    let summary =
        std::fs::read_to_string(root.join("chapters/SUMMARY.md")).map_err(GradeError::Summary)?;
    let chapters = marker::chapters(&summary);
    let weights = match job.weights {
        Some(path) => {
            let (text, name) = crate::data::read_text(path)?;
            super::parse_weights(&text, &name, &exercises)?
        }
        None => Weights::default(),
    };
    let (files, mut notes) = super::splice(sources, &exercises, &chapters, job.submission);
    let stamp = std::fs::read_to_string(job.submission.join(STAMP)).unwrap_or_default();
    if let Some(note) = super::commit_note(
        edition::stamped_commit(&stamp),
        edition::commit_of(root).as_deref(),
    ) {
        eprintln!("raylemma: {note}");
        notes.insert(0, note);
    }
    let graded = edition::make(files, Kind::Graded)?;
    let work = job
        .work
        .map(Path::to_path_buf)
        .unwrap_or_else(judge::default_work);
    let copy = work.join("crate");
    crate::output::create_dir_all(&work)?;
    edition::write(&graded, &copy)?;
    eprintln!(
        "raylemma: grading {}: its {} exercise bodies in the edition's own code, at {}",
        job.submission.display(),
        exercises.len(),
        copy.display()
    );
    let judged = judge::judge(&copy, &work, job.limit).and_then(|report| {
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
        Ok(report) => super::score(&report, &weights, notes),
        Err(why) => super::unbuilt(&exercises, &weights, &why, notes),
    };
    let text = report::text(&grade, job.submission);
    report::write_all(job.out, &grade, &text)?;
    print!("{text}");
    eprintln!("raylemma: wrote the grade to {}", job.out.display());
    Ok(grade)
}
