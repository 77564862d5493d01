//! `raylemma compare REF.exr CANDIDATE.exr [CANDIDATE.exr ...]`: does a candidate agree
//! with a reference within their noise? The reference carries its variance channels (a
//! raylemma render); the candidate is one image with variance channels, or several
//! independent plain RGB images of the scene (different seeds), whose spread gives its
//! variance. Exit status 0 if they agree, 1 if they differ, 2 for bad input. The reading
//! and the comparison are `raylemma::conformance::candidate`.

use std::path::PathBuf;

use clap::Args;
use raylemma::conformance::candidate;

use super::{CmdResult, Failure, Outcome};

/// `raylemma compare`.
#[derive(Args, Debug)]
pub struct CompareArgs {
    /// The reference: an EXR with variance channels (var.R, var.G, var.B), such as
    /// `raylemma render` writes and figures/reference/ holds.
    pub reference: PathBuf,
    /// The candidate: one EXR with variance channels, or two or more independent plain RGB
    /// EXRs of the same scene (different seeds; any channel order, half or float).
    #[arg(required = true, num_args = 1..)]
    pub candidates: Vec<PathBuf>,
    /// The family-wise false-alarm rate of the tests.
    #[arg(long, default_value_t = 0.01)]
    pub alpha: f64,
    /// Where to write the difference image (PNG).
    #[arg(long)]
    pub diff: Option<PathBuf>,
    /// Samples per pixel of each plain candidate (read from an EXR's `spp` attribute when it
    /// has one). With it, a candidate's variance is never taken below the reference's
    /// per-sample variance over the candidates' samples: where every candidate reads the same
    /// by chance (all 0 on a sliver of lit floor), their spread of 0 is not their noise.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub spp: Option<u32>,
}

/// Runs `raylemma compare`: agree (0), differ (1), bad input (2).
pub fn run(args: &CompareArgs) -> CmdResult {
    let diff = args.diff.as_deref();
    match candidate::compare_files(
        &args.reference,
        &args.candidates,
        args.alpha,
        args.spp,
        diff,
    ) {
        Ok(true) => Ok(Outcome::Done),
        Ok(false) => Ok(Outcome::Negative),
        Err(e) => Err(Failure::from(e)),
    }
}
