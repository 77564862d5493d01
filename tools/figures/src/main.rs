//! `raylemma-figures`: draws the book's figures and generated tables into `figures/`, and
//! renders the reference images into `figures/reference/`.
//!
//! The library (`raylemma`) never depends on this crate: its tests, benches and chapters
//! compile no plotting code. `cargo run --release` at the project root runs this tool (see
//! `raylemma --help`); it can also be run directly:
//!
//! `cargo run --release -p raylemma-figures -- [--quick] [--timings] [--root DIR] figures [--only NAME]`
//! `cargo run --release -p raylemma-figures -- [--quick] [--root DIR] references`

mod job;
mod plot;
mod render;
mod timing;

mod accuracy;
mod colour;
mod compare;
mod conformance;
mod coursework;
mod diagram;
mod dispersion;
mod display;
mod emission;
mod export;
mod external;
mod frame;
mod fresnel;
mod lambert;
mod limit;
mod mitsuba;
mod rectangle;
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

use job::{Output, Record, Settings};

/// Draw raylemma's figures and tables, and render its reference images.
#[derive(Parser, Debug)]
#[command(name = "raylemma-figures", version, about, long_about = None)]
struct Cli {
    /// Fewer samples and shorter timings (for CI); figures keep their shape.
    #[arg(long, global = true)]
    quick: bool,
    /// Measure the timing tables again on this machine (otherwise a full run keeps the
    /// committed ones, each naming the machine it was measured on).
    #[arg(long, global = true)]
    timings: bool,
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
    /// Render the canonical scenes whose references in figures/reference/ are out of date
    /// (EXR, PNG, JSON, each recording what it was made from), with the noise-level table
    /// and the cornell scene's RMSE against time.
    References {
        /// Render every reference, current or not.
        #[arg(long)]
        force: bool,
        /// Render nothing: exit with status 1, naming each reference that is out of date
        /// and why, unless all are current.
        #[arg(long, conflicts_with = "force")]
        check: bool,
    },
    /// Print the machine as every timing caption names it, with its fingerprint (for tools
    /// outside the figure job, such as tools/mitsuba/speed.sh, whose tables the book then
    /// compares with the figure job's).
    Machine,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    // Every figure draws text with the embedded font, whichever figures this run makes.
    plot::register_embedded_font();
    let root = cli
        .root
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../.."));
    let root = std::fs::canonicalize(&root).unwrap_or(root);
    let settings = Settings {
        quick: cli.quick,
        // An output named by `--only` is made, whatever it measures.
        timings: cli.timings || matches!(&cli.command, Cmd::Figures { only: Some(_) }),
        root,
    };

    let dir = settings.root.join("figures");
    let result = match &cli.command {
        Cmd::Machine => {
            println!("{}", timing::machine_name());
            return ExitCode::SUCCESS;
        }
        Cmd::Figures { only } => {
            eprintln!("raylemma: regenerating figures into {}", dir.display());
            job::write_all(&dir, &settings, only.as_deref())
        }
        Cmd::References { check: true, .. } => {
            return match render::stale_references(&dir, &settings) {
                Ok(stale) if stale.is_empty() => {
                    eprintln!(
                        "raylemma: every reference in {} is current",
                        dir.join("reference").display()
                    );
                    ExitCode::SUCCESS
                }
                Ok(stale) => {
                    for (name, why) in &stale {
                        eprintln!(
                            "raylemma: figures/reference/{name}.exr is out of date: {}",
                            why.join("; ")
                        );
                    }
                    eprintln!(
                        "raylemma: regenerate with `cargo run --release -- references` (it renders only these) and commit figures/"
                    );
                    ExitCode::FAILURE
                }
                Err(e) => {
                    eprintln!("raylemma: error: {}", job::message(&e));
                    ExitCode::from(2)
                }
            };
        }
        Cmd::References { force, .. } => {
            eprintln!(
                "raylemma: the reference images in {}",
                dir.join("reference").display()
            );
            render::write_references(&dir, &settings, *force)
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
            eprintln!("raylemma: error: {}", job::message(&e));
            ExitCode::FAILURE
        }
    }
}
