//! `raylemma figures` and `raylemma references`: run the figure job of the workspace
//! (`tools/figures/`, the crate `raylemma-figures`), which draws every figure and table into
//! `figures/` and renders the reference images into `figures/reference/`.

use clap::Args;

use super::{CmdResult, Outcome, run_tool};

/// `raylemma figures`.
#[derive(Args, Debug)]
pub struct FiguresArgs {
    /// Only outputs whose file name contains this text (e.g. `sphere_speed`).
    #[arg(long)]
    pub only: Option<String>,
    /// Fewer samples and shorter timings (for CI); figures keep their shape.
    #[arg(long)]
    pub quick: bool,
    /// Measure the timing tables again on this machine; otherwise they are kept as
    /// committed, each naming the machine it was measured on (`--only` remakes what it
    /// names either way).
    #[arg(long)]
    pub timings: bool,
}

/// `raylemma references`.
#[derive(Args, Debug)]
pub struct ReferencesArgs {
    /// Render every reference, current or not.
    #[arg(long)]
    pub force: bool,
    /// Render nothing: exit with status 1, naming each reference that is out of date and
    /// why, unless all are current (CI runs this).
    #[arg(long, conflicts_with = "force")]
    pub check: bool,
    /// A 32nd of the samples (for CI).
    #[arg(long)]
    pub quick: bool,
}

/// Regenerates the figures (all, or those whose name contains `only`).
pub fn figures(args: &FiguresArgs) -> CmdResult {
    let mut cmd = vec!["figures"];
    if let Some(name) = &args.only {
        cmd.extend(["--only", name]);
    }
    if args.quick {
        cmd.push("--quick");
    }
    if args.timings {
        cmd.push("--timings");
    }
    run_tool("raylemma-figures", &cmd)
}

/// Renders the reference images that are out of date (or all, or checks them).
pub fn references(args: &ReferencesArgs) -> CmdResult {
    let mut cmd = vec!["references"];
    if args.force {
        cmd.push("--force");
    }
    if args.check {
        cmd.push("--check");
    }
    if args.quick {
        cmd.push("--quick");
    }
    run_tool("raylemma-figures", &cmd)
}

/// With no subcommand: the figures, the references, then the book.
pub fn everything(quick: bool) -> CmdResult {
    figures(&FiguresArgs {
        only: None,
        quick,
        timings: false,
    })?;
    references(&ReferencesArgs {
        force: false,
        check: false,
        quick,
    })?;
    super::book::build()?;
    Ok(Outcome::Done)
}
