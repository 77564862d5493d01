//! `raylemma exercises DIR`: writes the student edition (`src/exercise/edition.rs`):
//! the hand-out, every marked body a stub, or with `--solutions` the teachers' copy.
//! Refuses a non-empty DIR unless `--overwrite` (and then only an edition written before),
//! a malformed marker (its file and line) and a hand-out that would still contain a line
//! of a solution; nothing is written unless all of the edition is.

use std::path::PathBuf;

use clap::Args;
use raylemma::exercise::edition::{self, EditionError, Kind};

use super::{CmdResult, Failure, Outcome, root};

/// `raylemma exercises`.
#[derive(Args, Debug)]
pub struct ExercisesArgs {
    /// The folder to write the edition into (must not exist, or be empty).
    pub dir: PathBuf,
    /// Write the solutions edition (every exercise written) instead of the hand-out.
    #[arg(long)]
    pub solutions: bool,
    /// Replace DIR if it holds an edition written before.
    #[arg(long)]
    pub overwrite: bool,
    /// The crate to make the edition from (default: the one this program was built from).
    #[arg(long, hide = true)]
    pub root: Option<PathBuf>,
}

/// Runs `raylemma exercises`: a refused DIR or a malformed marker is bad input (2); a
/// leaked solution line or a file that could not be read or written, a failed job (1).
pub fn run(args: &ExercisesArgs) -> CmdResult {
    let root = args.root.clone().unwrap_or_else(root);
    let kind = if args.solutions {
        Kind::Solutions
    } else {
        Kind::HandOut
    };
    let result = edition::check_destination(&args.dir, &root, args.overwrite)
        .and_then(|()| Ok(edition::read_sources(&root)?))
        .and_then(|sources| edition::make(sources, kind))
        .and_then(|e| edition::write(&e, &args.dir).map(|dir| (e, dir)));
    match result {
        Ok((e, dir)) => {
            eprintln!(
                "raylemma: wrote the {} ({} exercises, {} files, {} solution lines taken out) to {}",
                kind.name(),
                e.exercises.len(),
                e.files.len(),
                e.removed.len(),
                dir.display()
            );
            eprintln!("raylemma: cd {} && cargo test", dir.display());
            Ok(Outcome::Done)
        }
        Err(e @ (EditionError::Refused(_) | EditionError::Marker(_))) => {
            Err(Failure::BadInput(e.to_string()))
        }
        Err(e) => Err(Failure::Failed(e.to_string())),
    }
}
