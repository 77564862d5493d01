//! The subcommands of `raylemma`, one file each; `src/main.rs` parses the command line
//! and calls the subcommand's `run`.
//!
//! Exit statuses: 0 success; 1 a negative verdict (`compare`: the images differ; `check`:
//! the verdict is FAIL) or a failed job; 2 bad input (a file or argument that cannot be
//! used, a program that cannot answer; usage errors are clap's, also 2).

pub mod book;
pub mod check;
pub mod compare;
pub mod exercises;
pub mod export;
pub mod figures;
pub mod render;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

/// Prints `raylemma: error: MESSAGE` and returns the exit status `status`.
pub fn fail(status: u8, message: impl std::fmt::Display) -> ExitCode {
    eprintln!("raylemma: error: {message}");
    ExitCode::from(status)
}

/// Exit status 0 for `Ok`, else the error printed and exit status 1.
pub fn finish(result: Result<(), String>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(1, e),
    }
}

/// The project root: this binary is built from it.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs the workspace tool `package` (`raylemma-figures` or `raylemma-book`) with `args`,
/// compiling it first if needed (cargo shows its own progress).
pub fn run_tool(package: &str, args: &[&str]) -> Result<(), String> {
    let root = root();
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let status = Command::new(&cargo)
        .args(["run", "--release", "--quiet", "-p", package, "--"])
        .args(args)
        .arg("--root")
        .arg(&root)
        .current_dir(&root)
        .status()
        .map_err(|e| format!("cannot start {}: {e}", Path::new(&cargo).display()))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("{package} failed ({status})"))
    }
}
