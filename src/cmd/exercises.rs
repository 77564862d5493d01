//! `raylemma exercises DIR`: writes the student edition (`src/exercise/edition.rs`):
//! the hand-out, every marked body a stub, or with `--solutions` the teachers' copy.
//! Refuses a non-empty DIR unless `--overwrite` (and then only an edition written before),
//! a malformed marker (its file and line) and a hand-out that would still contain a line
//! of a solution; nothing is written unless all of the edition is. With `--book` it then
//! builds the edition's book and refuses it if a solution line is in any page.

use std::path::{Path, PathBuf};

use clap::Args;
use raylemma::exercise::edition::{self, EditionError, Kind};
use raylemma::exercise::scrub;

use super::{CmdResult, Failure, Outcome, root};

/// `raylemma exercises`.
#[derive(Args, Debug)]
pub struct ExercisesArgs {
    /// The folder to write the edition into (must not exist, or be empty).
    pub dir: PathBuf,
    /// Write the solutions edition (every exercise written) instead of the hand-out.
    #[arg(long)]
    pub solutions: bool,
    /// Also build the edition's book into DIR/book (the hand-out's: every exercise's code
    /// shown as its stub), and refuse it if a line of a removed solution is in any page.
    #[arg(long)]
    pub book: bool,
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
        .and_then(|mut e| {
            edition::stamp_commit(&mut e, edition::commit_of(&root).as_deref());
            edition::write(&e, &args.dir).map(|dir| (e, dir))
        });
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
            if args.book {
                book(&e, &dir)?;
            }
            Ok(Outcome::Done)
        }
        Err(e @ (EditionError::Refused(_) | EditionError::Marker(_))) => {
            Err(Failure::BadInput(e.to_string()))
        }
        Err(e) => Err(Failure::Failed(e.to_string())),
    }
}

/// Builds the book of the edition `e` written at `dir` with this workspace's book tool,
/// then looks for every removed solution line in every page of it (HTML unescaped), as
/// the scrubber looked in the edition's files.
fn book(e: &edition::Edition, dir: &Path) -> CmdResult {
    eprintln!(
        "raylemma: building the {}'s book into {}",
        e.kind.name(),
        dir.join("book").display()
    );
    super::run_tool_on("raylemma-book", &[], dir)?;
    let mut pages = Vec::new();
    html_pages(&dir.join("book"), &mut pages)
        .map_err(|e| Failure::Failed(format!("cannot read the book just built: {e}")))?;
    let leaks = scrub::leaks(&e.removed, &pages);
    if !leaks.is_empty() {
        let mut message = format!(
            "{} line(s) of removed solutions are in the {}'s book:",
            leaks.len(),
            e.kind.name()
        );
        for leak in leaks.iter().take(20) {
            message.push_str(&format!("\n  {leak}"));
        }
        return Err(Failure::Failed(message));
    }
    eprintln!(
        "raylemma: {} pages of the book, none with a line of the {} solution lines taken out; open {}",
        pages.len(),
        e.removed.len(),
        dir.join("book").join("index.html").display()
    );
    Ok(Outcome::Done)
}

/// Every `.html` file under `dir` as (path, its text with HTML's escapes undone).
fn html_pages(dir: &Path, out: &mut Vec<(String, String)>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if path.is_dir() {
            html_pages(&path, out)?;
        } else if path.extension().is_some_and(|x| x == "html") {
            let text = std::fs::read_to_string(&path)?
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&quot;", "\"")
                .replace("&#39;", "'")
                .replace("&#x27;", "'")
                .replace("&amp;", "&");
            out.push((path.display().to_string(), text));
        }
    }
    Ok(())
}
