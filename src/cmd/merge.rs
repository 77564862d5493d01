//! `raylemma merge A.exr B.exr ... --out M.exr`: pools independent renders of one scene
//! (different seeds) into one, exactly ([`raylemma::conformance::merge`]), and writes `M.exr`,
//! `M.png` and `M.json` together. Renders of different scenes, settings, sizes or builds,
//! and two with a seed in common, are bad input (exit status 2).

use std::path::PathBuf;

use clap::Args;
use raylemma::conformance::merge;
use raylemma::render;

use super::{CmdResult, Failure, done};

/// `raylemma merge`.
#[derive(Args, Debug)]
pub struct MergeArgs {
    /// The renders to pool: EXRs written by `raylemma render`, each with its `.json`
    /// sidecar beside it, made with different seeds.
    #[arg(required = true, num_args = 1..)]
    pub renders: Vec<PathBuf>,
    /// The merged render's EXR; its PNG and JSON sidecar are written beside it.
    #[arg(long)]
    pub out: PathBuf,
}

/// Runs `raylemma merge`.
pub fn run(args: &MergeArgs) -> CmdResult {
    done(merge_files(args))
}

fn merge_files(args: &MergeArgs) -> Result<(), Failure> {
    let stem = args
        .out
        .file_stem()
        .filter(|_| args.out.extension().is_some_and(|e| e == "exr"))
        .map(|s| s.to_string_lossy().into_owned())
        .ok_or_else(|| {
            Failure::BadInput(format!(
                "--out {}: the merged render's name must end in .exr",
                args.out.display()
            ))
        })?;
    let parts = args
        .renders
        .iter()
        .map(|p| merge::read_part(p))
        .collect::<Result<Vec<_>, _>>()?;
    let (image, sidecar) = merge::merge(&parts)?;
    let dir = args.out.parent().filter(|d| !d.as_os_str().is_empty());
    let dir = dir.map_or_else(|| PathBuf::from("."), PathBuf::from);
    let files = render::write_outputs(&dir, &stem, &image, &sidecar)?;
    eprintln!(
        "raylemma: merged {} renders of {} ({} spp in all, seeds {:?})",
        parts.len(),
        sidecar.scene,
        sidecar.spp,
        sidecar.seeds
    );
    for f in files {
        eprintln!("raylemma: wrote {}", f.display());
    }
    Ok(())
}
