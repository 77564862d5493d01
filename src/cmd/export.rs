//! `raylemma export SCENE --to mitsuba|pbrt|json --out FILE`: the scene for other
//! renderers, as a Mitsuba 3 XML file, a pbrt-v4 scene file or fully resolved JSON. A bad scene, or a feature the target
//! cannot express, is refused with file, line and reason (exit status 2), and nothing is
//! written; the file is written atomically, so an earlier one is never left half
//! overwritten.

use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use raylemma::conformance::export::{SceneFile, json, mitsuba, pbrt};

use super::{CmdResult, Failure, done};

/// The formats `export` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Target {
    /// A Mitsuba 3 scene (XML) for `mitsuba.load_file`, spectral variants.
    Mitsuba,
    /// A pbrt-v4 scene file for `pbrt` (rules: tools/pbrt/NOTES.md).
    Pbrt,
    /// Fully resolved JSON: defaults filled in, spectra on the 1 nm grid, transforms explicit.
    Json,
}

/// `raylemma export`.
#[derive(Args, Debug)]
pub struct ExportArgs {
    /// The scene file (TOML; see scenes/ and the renderer chapter).
    pub scene: PathBuf,
    /// The format to write.
    #[arg(long, value_enum)]
    pub to: Target,
    /// The file to write.
    #[arg(long)]
    pub out: PathBuf,
}

/// Runs `raylemma export`: what cannot be exported is bad input (exit status 2).
pub fn run(args: &ExportArgs) -> CmdResult {
    done(export(&args.scene, args.to, &args.out))
}

fn export(scene: &Path, to: Target, out: &Path) -> Result<(), Failure> {
    let file = SceneFile::load(scene)?;
    let text = match to {
        Target::Mitsuba => mitsuba::to_xml(&file)?,
        Target::Pbrt => pbrt::to_pbrt(&file)?,
        Target::Json => json::to_json(&file),
    };
    raylemma::output::write_file(out, text.as_bytes())?;
    eprintln!("raylemma: wrote {}", out.display());
    Ok(())
}
