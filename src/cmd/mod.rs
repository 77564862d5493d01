//! The subcommands of `raylemma`, one file each; `src/main.rs` parses the command line
//! and calls the subcommand's `run`.
//!
//! One exit-status rule, for every subcommand, applied in one place ([`exit`]): each `run`
//! returns a [`CmdResult`]: either an [`Outcome`] or a [`Failure`], and `main.rs` maps it:
//!
//! - **0** success (the images agree, the checker passes, the files are written);
//! - **1** a negative verdict (`compare`: the images differ; `check`: FAIL;
//!   `references --check`: a reference is out of date), or a job that failed on good input
//!   (a figure that could not be made);
//! - **2** bad input or usage: a file, a flag or a program that cannot be used (clap's own
//!   usage errors are 2 as well).

pub mod book;
pub mod card;
pub mod check;
pub mod compare;
pub mod conformance;
pub mod exercises;
pub mod export;
pub mod figures;
pub mod grade;
pub mod merge;
pub mod render;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

/// What a subcommand's work came to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Done, or a positive verdict: exit status 0.
    Done,
    /// A negative verdict, already printed: exit status 1.
    Negative,
}

/// Why a subcommand could not do its work.
#[derive(Debug)]
pub enum Failure {
    /// Bad input or usage (the message names the file, flag or program): exit status 2.
    BadInput(String),
    /// The work failed on good input (the message says what): exit status 1.
    Failed(String),
    /// A workspace tool ended with this status, having said why itself.
    Tool(u8),
}

/// What every subcommand returns.
pub type CmdResult = Result<Outcome, Failure>;

/// The one exit-status rule (the module's documentation): prints a failure's message as
/// `raylemma: error: MESSAGE`.
pub fn exit(result: CmdResult) -> ExitCode {
    match result {
        Ok(Outcome::Done) => ExitCode::SUCCESS,
        Ok(Outcome::Negative) => ExitCode::from(1),
        Err(Failure::BadInput(e)) => {
            eprintln!("raylemma: error: {e}");
            ExitCode::from(2)
        }
        Err(Failure::Failed(e)) => {
            eprintln!("raylemma: error: {e}");
            ExitCode::from(1)
        }
        Err(Failure::Tool(status)) => ExitCode::from(status),
    }
}

/// A typed error of the library (an input that cannot be used: a scene, a table, an image,
/// a program) is bad input, exit status 2: its message names the file, flag or program. A
/// subcommand that judges an error a failure on good input says so with
/// [`Failure::Failed`] where it happens.
impl<E: std::error::Error> From<E> for Failure {
    fn from(e: E) -> Self {
        Failure::BadInput(e.to_string())
    }
}

/// `Ok(())` as [`Outcome::Done`].
pub fn done(result: Result<(), Failure>) -> CmdResult {
    result.map(|()| Outcome::Done)
}

/// The project root: this binary is built from it.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs the workspace tool `package` (`raylemma-figures` or `raylemma-book`) with `args`,
/// compiling it first if needed (cargo shows its own progress). The tool follows the same
/// exit-status rule: its status 1 or 2 is passed on ([`Failure::Tool`]).
pub fn run_tool(package: &str, args: &[&str]) -> CmdResult {
    run_tool_on(package, args, &root())
}

/// [`run_tool`] on the project at `project` (`--root project`; the tool is still this
/// workspace's): `exercises --book` builds an edition's book with it.
pub fn run_tool_on(package: &str, args: &[&str], project: &Path) -> CmdResult {
    let root = root();
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let status = Command::new(&cargo)
        .args(["run", "--release", "--quiet", "-p", package, "--"])
        .args(args)
        .arg("--root")
        .arg(project)
        .current_dir(&root)
        .status()
        .map_err(|e| {
            Failure::Failed(format!("cannot start {}: {e}", Path::new(&cargo).display()))
        })?;
    match status.code() {
        Some(0) => Ok(Outcome::Done),
        Some(code @ 1..=2) => Err(Failure::Tool(code as u8)),
        _ => Err(Failure::Failed(format!("{package} failed ({status})"))),
    }
}
