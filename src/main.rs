//! `raylemma`: regenerates the book's figures and builds the book.
//!
//! `cargo run --release` with no subcommand does both; see `--help`.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

use clap::{Parser, Subcommand};
use raylemma::figures::{self, Settings};

/// Regenerate raylemma's figures and build its book.
///
/// With no subcommand: `figures`, then `book`.
#[derive(Parser, Debug)]
#[command(name = "raylemma", version, about, long_about = None)]
struct Cli {
    /// Fewer samples and shorter timings (for CI); figures keep their shape.
    #[arg(long, global = true)]
    quick: bool,
    #[command(subcommand)]
    command: Option<Cmd>,
}

#[derive(Subcommand, Debug)]
enum Cmd {
    /// Regenerate every figure and generated table into figures/.
    Figures {
        /// Only outputs whose file name contains this text (e.g. `sphere_speed`).
        #[arg(long)]
        only: Option<String>,
    },
    /// Build the HTML book from chapters/ into book/ (mdBook as a library, math as MathML).
    Book,
}

/// The project root: this binary is built from it.
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn run_figures(settings: &Settings, only: Option<&str>) -> Result<(), String> {
    let dir = root().join("figures");
    eprintln!("raylemma: regenerating figures into {}", dir.display());
    let written = figures::write_all(&dir, settings, only).map_err(|e| e.to_string())?;
    eprintln!(
        "raylemma: wrote {} files into {}",
        written.len(),
        dir.display()
    );
    Ok(())
}

/// Builds the book with the `raylemma-book` tool of this workspace, compiling it first if
/// needed (cargo shows its own progress; the first build takes a few minutes).
fn run_book() -> Result<(), String> {
    let root = root();
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    eprintln!("raylemma: building the book tool (the first build compiles mdBook and KaTeX)");
    let status = Command::new(&cargo)
        .args(["run", "--release", "-p", "raylemma-book", "--", "--root"])
        .arg(&root)
        .current_dir(&root)
        .status()
        .map_err(|e| format!("cannot start {}: {e}", Path::new(&cargo).display()))?;
    if status.success() {
        eprintln!(
            "raylemma: open {} in a browser",
            root.join("book").join("index.html").display()
        );
        Ok(())
    } else {
        Err(format!(
            "the book build failed ({status}); book/ was left as it was"
        ))
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let settings = Settings { quick: cli.quick };
    let result = match &cli.command {
        None => run_figures(&settings, None).and_then(|()| run_book()),
        Some(Cmd::Figures { only }) => run_figures(&settings, only.as_deref()),
        Some(Cmd::Book) => run_book(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("raylemma: error: {e}");
            ExitCode::FAILURE
        }
    }
}
