//! The checks as `raylemma check` runs them: from the command line's values (a program's
//! command or a file, the numbers of cases, a seed, a level) to the checker's verdict,
//! printed ([`check_sampler`], [`check_fresnel`], [`check_refraction`],
//! [`check_corpora`]). The command parses its flags and maps the [`Checked`] or the error
//! to its exit status. Chapter: *Checks from any language*
//! (`chapters/checking/external.md`).

use std::path::{Path, PathBuf};
use std::time::Duration;

use super::{Density, Function, Program, Sampler, TIMEOUT, Target};
use crate::check::accuracy::{self, Expect, corpus};
use crate::check::warp::Domain;
use crate::check::{Options, Verdict};
use crate::data::DataError;
use crate::output::FileError;

/// What a check came to (its verdict is printed).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Checked {
    /// Every verdict passed.
    Passed,
    /// A verdict failed.
    Failed,
    /// No check: the questions were written (`--questions`).
    QuestionsWritten,
}

impl Checked {
    fn of(passed: bool) -> Self {
        if passed {
            Checked::Passed
        } else {
            Checked::Failed
        }
    }
}

/// Why a function's check could not run: bad input, or a file of questions that cannot
/// be written.
#[derive(Debug)]
pub enum CheckError {
    /// A file, a program or an answer that cannot be used.
    Data(DataError),
    /// The file of questions cannot be written.
    File(FileError),
}

impl std::fmt::Display for CheckError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CheckError::Data(e) => write!(f, "{e}"),
            CheckError::File(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for CheckError {}

impl From<DataError> for CheckError {
    fn from(e: DataError) -> Self {
        CheckError::Data(e)
    }
}

impl From<FileError> for CheckError {
    fn from(e: FileError) -> Self {
        CheckError::File(e)
    }
}

/// `Options` from the flags; unset flags leave the checker's defaults.
fn options(cases: Option<u64>, seed: Option<u64>, alpha: Option<f64>) -> Options {
    let mut options = Options::new();
    if let Some(n) = cases {
        options = options.cases(usize::try_from(n).unwrap_or(usize::MAX));
    }
    if let Some(s) = seed {
        options = options.seed(s);
    }
    if let Some(a) = alpha {
        options = options.alpha(a);
    }
    options
}

/// A usage error that the command line's parser already refuses (kept as an error, never
/// a panic).
fn usage(problem: &str) -> DataError {
    DataError::new("raylemma check", 0, problem)
}

/// The program `command`, with `timeout` per run (default [`TIMEOUT`]).
fn program(command: &str, timeout: Option<Duration>) -> Program {
    Program::new(command).timeout(timeout.unwrap_or(TIMEOUT))
}

/// Prints the verdict; whether it passed.
fn verdict(verdict: Verdict) -> Checked {
    print!("{verdict}");
    Checked::of(verdict.passed())
}

/// `raylemma check sampler`'s values.
#[derive(Clone, Debug, Default)]
pub struct SamplerCheck<'a> {
    /// The sampler program's command.
    pub program: Option<&'a str>,
    /// Or a CSV file of samples.
    pub samples: Option<&'a Path>,
    /// The density the samples should follow.
    pub target: Option<Target>,
    /// Or the program states its own density, on this domain.
    pub domain: Option<Domain>,
    /// The program answers `invert`.
    pub inverse: bool,
    /// Samples drawn from the program (default [`super::SAMPLES`]).
    pub cases: Option<u64>,
    /// Seed of the points of the square.
    pub seed: Option<u64>,
    /// Significance level of the chi-squared test.
    pub alpha: Option<f64>,
    /// Seconds one run of the program may take (default [`TIMEOUT`]).
    pub timeout: Option<Duration>,
    /// Where the failure images go.
    pub failure_images: Option<&'a Path>,
}

/// `raylemma check sampler`: the sampler checked, its verdict printed.
pub fn check_sampler(args: &SamplerCheck) -> Result<Checked, DataError> {
    if let Some(dir) = args.failure_images {
        crate::check::pictures::set_failure_dir(dir.to_path_buf());
    }
    let options = options(
        Some(args.cases.unwrap_or(super::SAMPLES as u64)),
        args.seed,
        args.alpha,
    );
    let density = match (args.target, args.domain) {
        (Some(target), _) => Density::Target(target),
        (None, Some(domain)) => Density::Program(domain),
        (None, None) => return Err(usage("--target or --domain is needed")),
    };
    let sampler = match (args.program, args.samples, density) {
        (Some(command), _, density) => Sampler::Program {
            program: program(command, args.timeout),
            density,
            inverse: args.inverse,
        },
        (None, Some(path), Density::Target(target)) => Sampler::Samples {
            path: path.to_path_buf(),
            target,
        },
        (None, Some(_), Density::Program(_)) => {
            return Err(usage("a file of samples needs a --target"));
        }
        (None, None, _) => return Err(usage("--program or --samples is needed")),
    };
    super::sampler(&sampler, &options).map(verdict)
}

/// Where a function's answers come from (`raylemma check fresnel|refraction`), or the
/// file its questions are written to.
#[derive(Clone, Debug, Default)]
pub struct FunctionCheck<'a> {
    /// The program's command.
    pub program: Option<&'a str>,
    /// A CSV table of questions and answers.
    pub table: Option<&'a Path>,
    /// Write the questions `table` (if any) does not answer to this file, instead of
    /// checking.
    pub questions: Option<&'a Path>,
    /// Seconds one run of the program may take (default [`TIMEOUT`]).
    pub timeout: Option<Duration>,
}

/// `raylemma check fresnel`: `cases` angles of incidence (default: the checker's).
pub fn check_fresnel(from: &FunctionCheck, cases: Option<u64>) -> Result<Checked, CheckError> {
    let options = options(cases, None, None);
    function(from, &options, super::fresnel, super::fresnel_questions)
}

/// `raylemma check refraction`: `cases` incident directions from `seed` (default: the
/// checker's).
pub fn check_refraction(
    from: &FunctionCheck,
    cases: Option<u64>,
    seed: Option<u64>,
) -> Result<Checked, CheckError> {
    let options = options(cases, seed, None);
    function(
        from,
        &options,
        super::refraction,
        super::refraction_questions,
    )
}

type Check = fn(&Function, &Options) -> Result<Verdict, DataError>;
type Questions = fn(Option<&Path>, &Options) -> Result<String, DataError>;

/// A function checked (its verdict printed), or its questions written.
fn function(
    from: &FunctionCheck,
    options: &Options,
    check: Check,
    questions: Questions,
) -> Result<Checked, CheckError> {
    if let Some(out) = from.questions {
        write_questions(from.table, out, options, questions)?;
        return Ok(Checked::QuestionsWritten);
    }
    let function = match (from.program, from.table) {
        (Some(command), _) => Function::Program(program(command, from.timeout)),
        (None, Some(path)) => Function::Table(path.to_path_buf()),
        (None, None) => {
            return Err(usage("--program, --table or --questions is needed").into());
        }
    };
    Ok(verdict(check(&function, options)?))
}

/// Writes the questions `table` does not answer into `out` (whole, or not at all).
fn write_questions(
    table: Option<&Path>,
    out: &Path,
    options: &Options,
    questions: Questions,
) -> Result<(), CheckError> {
    let text = questions(table, options)?;
    crate::output::write_file(out, text.as_bytes())?;
    let rows = text.lines().count() - 1;
    if rows == 0 {
        eprintln!("raylemma: the table answers every question; check it with --table");
    } else {
        eprintln!(
            "raylemma: wrote {rows} questions to {} (add each row's answer, then --table)",
            out.display()
        );
    }
    Ok(())
}

/// `raylemma check corpus`: the corpora `files` (every `data/corpus/*.txt` under the
/// current folder if none), each checked on `program` (with `timeout` per run) or, without
/// one, on this crate's own routines, for `verbs` (every verb if empty); every verdict
/// printed as it comes.
pub fn check_corpora(
    files: &[PathBuf],
    program_command: Option<&str>,
    verbs: &[String],
    timeout: Option<Duration>,
) -> Result<Checked, DataError> {
    let corpora = if files.is_empty() {
        corpus::load_all(Path::new("."))?
    } else {
        files
            .iter()
            .map(|p| corpus::load(p))
            .collect::<Result<Vec<_>, _>>()?
    };
    let mut passed = true;
    for c in &corpora {
        let verdict = match program_command {
            Some(command) => accuracy::check_program(c, verbs, &program(command, timeout))?,
            None => {
                let forms = accuracy::forms::of(&c.name).ok_or_else(|| {
                    DataError::new(
                        &c.file,
                        0,
                        "no routine of this crate answers this corpus (check another \
                         implementation with --program)",
                    )
                })?;
                let forms: Vec<_> = forms
                    .into_iter()
                    .filter(|f| f.expect == Expect::Within)
                    .filter(|f| verbs.is_empty() || verbs.iter().any(|v| v == f.verb))
                    .collect();
                accuracy::check_forms(c, &forms)
            }
        };
        print!("{verdict}");
        passed &= verdict.passed();
    }
    Ok(Checked::of(passed))
}
