//! `raylemma conformance --renderer 'CMD {scene} {out} {spp} {seed}'`: another renderer
//! on the conformance ladder (`scenes/conformance/`, [`raylemma::conformance::ladder`]).
//! Each rung, at each depth it has a reference for, is written in the chosen format, the
//! renderer is run `--runs` times with different seeds, its images are compared with the
//! reference (`figures/reference/conformance/`), and a card says per rung and depth
//! whether they agree, how large the difference is, and what the first failing rung
//! points to. Exit status 0 if every rung agrees, 1 if one differs or its renderer failed,
//! 2 for bad usage. The card is [`raylemma::conformance::run`]; this file parses the
//! arguments. Chapter: *Reference scenes and interop*, *The conformance ladder*.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use raylemma::conformance::card::{self, Settings};
use raylemma::conformance::run::{self, Conformance, ConformanceError};

use super::{CmdResult, Failure, Outcome};

/// The scene format the candidate reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// raylemma's own TOML (data paths made absolute).
    Toml,
    /// Fully resolved JSON (`raylemma export --to json`).
    Json,
    /// Mitsuba 3 XML (`raylemma export --to mitsuba`); the rungs it refuses (the
    /// spectral-only ones) are skipped.
    Mitsuba,
    /// pbrt-v4 (`raylemma export --to pbrt`); the rungs it refuses (thin films) are skipped.
    Pbrt,
}

/// `raylemma conformance`.
#[derive(Args, Debug)]
pub struct ConformanceArgs {
    /// The renderer, run by `sh -c`, with `{scene}` (the scene file to read), `{out}` (the
    /// EXR to write: plain R, G, B, or X, Y, Z), `{outdir}` (its folder), `{spp}`, `{seed}`
    /// and `{depth}` (the maximum depth in raylemma's count of bounces, as the written scene
    /// has it: the rung's own where no other is asked, 1000 for the default) replaced.
    #[arg(long)]
    pub renderer: String,
    /// The scene format the renderer reads (no default: a renderer fed the wrong format
    /// fails on every rung, which would say nothing about its physics).
    #[arg(long, value_enum)]
    pub format: Format,
    /// Renders of each rung, with different seeds: their spread is the candidate's noise.
    #[arg(long, default_value_t = 4, value_parser = clap::value_parser!(u32).range(2..))]
    pub runs: u32,
    /// The card's seed: its K runs of each rung use the seeds K(S - 1) + 1 to K S (with
    /// the default 1, the seeds 1 to K), so that cards of different seeds share no render.
    /// A card that differs can be run again with another seed.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
    pub seed: u64,
    /// Samples per pixel of each render.
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..))]
    pub spp: u32,
    /// Only these rungs (numbers, comma-separated).
    #[arg(long, value_delimiter = ',')]
    pub rungs: Vec<u32>,
    /// Seconds one render may take.
    #[arg(long, default_value_t = 600.0)]
    pub timeout: f64,
    /// The family-wise false-alarm rate of the whole card (Šidák over its comparisons).
    #[arg(long, default_value_t = 0.01)]
    pub alpha: f64,
    /// The suite to run: a folder laid out as raylemma's source tree (its
    /// `scenes/conformance/`, the `data/` files they read and
    /// `figures/reference/conformance/`), such as a clone whose references you rendered
    /// yourself. Default: the suite built into this binary, written out into
    /// `WORK/suite/`. The card names the suite and its hash.
    #[arg(long)]
    pub suite: Option<PathBuf>,
    /// Where the scenes and renders go [default: conformance/ in the working directory].
    #[arg(long, default_value = "conformance")]
    pub work: PathBuf,
    /// Also write the card as JSON to this file.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Also write the card as JUnit XML to this file (for CI systems and autograders).
    #[arg(long)]
    pub junit: Option<PathBuf>,
}

/// Runs `raylemma conformance`.
pub fn run(args: &ConformanceArgs) -> CmdResult {
    let format = match args.format {
        Format::Toml => card::Format::Toml,
        Format::Json => card::Format::Json,
        Format::Mitsuba => card::Format::Mitsuba,
        Format::Pbrt => card::Format::Pbrt,
    };
    let conformance = Conformance {
        settings: Settings {
            renderer: args.renderer.clone(),
            format,
            runs: args.runs,
            spp: args.spp,
            seed: args.seed,
            alpha: args.alpha,
        },
        rungs: args.rungs.clone(),
        timeout: args.timeout,
        suite: args.suite.clone(),
        work: args.work.clone(),
        json: args.json.clone(),
        junit: args.junit.clone(),
    };
    match run::run(&conformance) {
        Ok(true) => Ok(Outcome::Done),
        Ok(false) => Ok(Outcome::Negative),
        Err(ConformanceError::BadInput(m)) => Err(Failure::BadInput(m)),
        Err(ConformanceError::File(e)) => Err(Failure::from(e)),
    }
}
