//! `raylemma-figures`: draws the book's figures and generated tables into `figures/`, and
//! renders the reference images into `figures/reference/`.
//!
//! The library (`raylemma`) never depends on this crate: its tests, benches and chapters
//! compile no plotting code. `cargo run --release` at the project root runs this tool (see
//! `raylemma --help`); it can also be run directly:
//!
//! `cargo run --release -p raylemma-figures -- [--quick] [--root DIR] figures [--only NAME]`
//! `cargo run --release -p raylemma-figures -- [--quick] [--root DIR] references`

mod job;
mod plot;
mod render;
mod timing;

mod colour;
mod compare;
mod dispersion;
mod display;
mod emission;
mod export;
mod frame;
mod fresnel;
mod lambert;
mod mitsuba;
mod reflect;
mod roulette;
mod sampling;
mod shadow;
mod specular;
mod sphere;
mod stats;
mod tabulated;
mod testing;
mod thinfilm;
mod upsample;
mod wavelength;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use job::{Output, Settings};

/// Draw raylemma's figures and tables, and render its reference images.
#[derive(Parser, Debug)]
#[command(name = "raylemma-figures", version, about, long_about = None)]
struct Cli {
    /// Fewer samples and shorter timings (for CI); figures keep their shape.
    #[arg(long, global = true)]
    quick: bool,
    /// The project root (default: the one this tool was built from).
    #[arg(long, global = true)]
    root: Option<PathBuf>,
    #[command(subcommand)]
    command: Cmd,
}

#[derive(Subcommand, Debug)]
enum Cmd {
    /// Regenerate every figure and generated table into figures/.
    Figures {
        /// Only outputs whose file name contains this text (e.g. `sphere_speed`).
        #[arg(long)]
        only: Option<String>,
    },
    /// Render every canonical scene into figures/reference/ (EXR, PNG, JSON), with the
    /// noise-level table and the cornell scene's RMSE against time.
    References,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let root = cli
        .root
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../.."));
    let root = std::fs::canonicalize(&root).unwrap_or(root);
    let settings = Settings {
        quick: cli.quick,
        root,
    };
    let dir = settings.root.join("figures");
    let result = match &cli.command {
        Cmd::Figures { only } => {
            eprintln!("raylemma: regenerating figures into {}", dir.display());
            job::write_all(&dir, &settings, only.as_deref())
        }
        Cmd::References => {
            eprintln!(
                "raylemma: rendering the reference images into {}",
                dir.join("reference").display()
            );
            render::write_references(&dir, &settings)
        }
    };
    match result {
        Ok(written) => {
            eprintln!(
                "raylemma: wrote {} files into {}",
                written.len(),
                dir.display()
            );
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("raylemma: error: {e}");
            ExitCode::FAILURE
        }
    }
}
