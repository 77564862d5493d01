//! `raylemma figures` and `raylemma references`: run the figure job of the workspace
//! (`tools/figures/`, the crate `raylemma-figures`), which draws every figure and table into
//! `figures/` and renders the reference images into `figures/reference/`.

use std::process::ExitCode;

use clap::Args;

use super::{finish, run_tool};

/// `raylemma figures`.
#[derive(Args, Debug)]
pub struct FiguresArgs {
    /// Only outputs whose file name contains this text (e.g. `sphere_speed`).
    #[arg(long)]
    pub only: Option<String>,
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
}

/// Regenerates the figures (all, or those whose name contains `only`).
pub fn figures(args: &FiguresArgs, quick: bool) -> Result<(), String> {
    let mut cmd = vec!["figures"];
    if let Some(name) = &args.only {
        cmd.extend(["--only", name]);
    }
    if quick {
        cmd.push("--quick");
    }
    run_tool("raylemma-figures", &cmd)
}

/// Renders the reference images that are out of date (or all, or checks them).
pub fn references(args: &ReferencesArgs, quick: bool) -> Result<(), String> {
    let mut cmd = vec!["references"];
    if args.force {
        cmd.push("--force");
    }
    if args.check {
        cmd.push("--check");
    }
    if quick {
        cmd.push("--quick");
    }
    run_tool("raylemma-figures", &cmd)
}

/// With no subcommand: the figures, the references, then the book.
pub fn everything(quick: bool) -> ExitCode {
    finish(
        figures(&FiguresArgs { only: None }, quick)
            .and_then(|()| {
                references(
                    &ReferencesArgs {
                        force: false,
                        check: false,
                    },
                    quick,
                )
            })
            .and_then(|()| super::book::build()),
    )
}
