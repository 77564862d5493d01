//! The book's figures and generated tables, and the job that writes them to `figures/`.
//!
//! Each chapter module here owns the figures of one chapter. Every output is produced
//! into a staging directory first; only when *all* outputs succeeded are they moved into
//! `figures/` (one rename per file), so a failed run leaves the previous figures intact.

pub mod colour;
pub mod dispersion;
pub mod display;
pub mod emission;
pub mod frame;
pub mod fresnel;
pub mod lambert;
pub mod reflect;
pub mod render;
pub mod roulette;
pub mod sampling;
pub mod shadow;
pub mod specular;
pub mod sphere;
pub mod stats;
pub mod tabulated;
pub mod thinfilm;
pub mod timing;
pub mod upsample;
pub mod wavelength;

use std::fs;
use std::path::{Path, PathBuf};

use indicatif::{ProgressBar, ProgressStyle};

use crate::plot::BoxError;

/// Options shared by all figures.
#[derive(Clone, Copy, Debug, Default)]
pub struct Settings {
    /// Fewer samples and shorter timings (for CI); the figures keep their shape.
    pub quick: bool,
}

/// One output file of the figure job.
pub struct Output {
    /// File name inside `figures/`, e.g. `sphere_far_error.png`.
    pub file: &'static str,
    /// What it shows, for progress and error messages.
    pub what: &'static str,
    /// Produces the file's bytes.
    pub make: fn(&Settings) -> Result<Vec<u8>, BoxError>,
}

/// Every output of every chapter, in book order.
pub fn all() -> Vec<Output> {
    let mut outputs = Vec::new();
    outputs.extend(sphere::outputs());
    outputs.extend(stats::outputs());
    outputs.extend(sampling::outputs());
    outputs.extend(tabulated::outputs());
    outputs.extend(frame::outputs());
    outputs.extend(reflect::outputs());
    outputs.extend(fresnel::outputs());
    outputs.extend(specular::outputs());
    outputs.extend(dispersion::outputs());
    outputs.extend(thinfilm::outputs());
    outputs.extend(lambert::outputs());
    outputs.extend(roulette::outputs());
    outputs.extend(shadow::outputs());
    outputs.extend(colour::outputs());
    outputs.extend(wavelength::outputs());
    outputs.extend(emission::outputs());
    outputs.extend(display::outputs());
    outputs.extend(upsample::outputs());
    outputs
}

/// Writes the outputs whose file name contains `only` (all if `None`) into `dir`.
///
/// # Errors
/// If nothing matches `only`, or as [`write_outputs`].
pub fn write_all(
    dir: &Path,
    settings: &Settings,
    only: Option<&str>,
) -> Result<Vec<PathBuf>, BoxError> {
    let outputs: Vec<Output> = all()
        .into_iter()
        .filter(|o| only.is_none_or(|s| o.file.contains(s)))
        .collect();
    if outputs.is_empty() {
        let names: Vec<_> = all().iter().map(|o| o.file).collect();
        return Err(format!(
            "no figure matches {:?}; figures are: {}",
            only.unwrap_or(""),
            names.join(", ")
        )
        .into());
    }
    write_outputs(dir, &outputs, settings)
}

/// Produces `outputs` in a staging directory beside `dir`, then moves them into `dir`.
///
/// # Errors
/// Names the first output that failed; `dir` is then left exactly as it was.
pub fn write_outputs(
    dir: &Path,
    outputs: &[Output],
    settings: &Settings,
) -> Result<Vec<PathBuf>, BoxError> {
    fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let staging = dir.with_file_name(format!(
        "{}.tmp-{}",
        dir.file_name()
            .and_then(|n| n.to_str())
            .unwrap_or("figures"),
        std::process::id()
    ));
    fs::create_dir_all(&staging)
        .map_err(|e| format!("cannot create {}: {e}", staging.display()))?;
    let result = produce(outputs, &staging, settings).and_then(|()| commit(outputs, &staging, dir));
    let _ = fs::remove_dir_all(&staging);
    result
}

fn produce(outputs: &[Output], staging: &Path, settings: &Settings) -> Result<(), BoxError> {
    let bar = ProgressBar::new(outputs.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{elapsed:>4} [{bar:30}] {pos}/{len} {msg}")
            .map_err(|e| e.to_string())?
            .progress_chars("=> "),
    );
    for output in outputs {
        bar.set_message(format!("{} ({})", output.file, output.what));
        let bytes = (output.make)(settings)
            .map_err(|e| format!("figure {} ({}) failed: {e}", output.file, output.what))?;
        let path = staging.join(output.file);
        fs::write(&path, bytes).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        bar.inc(1);
    }
    bar.finish_with_message("done");
    Ok(())
}

fn commit(outputs: &[Output], staging: &Path, dir: &Path) -> Result<Vec<PathBuf>, BoxError> {
    let mut written = Vec::new();
    for output in outputs {
        let target = dir.join(output.file);
        fs::rename(staging.join(output.file), &target)
            .map_err(|e| format!("cannot move {} into place: {e}", target.display()))?;
        written.push(target);
    }
    Ok(written)
}
