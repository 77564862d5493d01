//! `raylemma compare A.exr B.exr`: do two renders agree within their noise? Exit status 0
//! if they agree, 1 if they differ, 2 for bad input.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Args;
use raylemma::render::{compare, image::Image};

use super::fail;

/// `raylemma compare`.
#[derive(Args, Debug)]
pub struct CompareArgs {
    /// The first image.
    pub a: PathBuf,
    /// The second image.
    pub b: PathBuf,
    /// The family-wise false-alarm rate of the z-tests.
    #[arg(long, default_value_t = 0.01)]
    pub alpha: f64,
    /// Where to write the difference image (PNG).
    #[arg(long)]
    pub diff: Option<PathBuf>,
}

/// Runs `raylemma compare`.
pub fn run(args: &CompareArgs) -> ExitCode {
    match compare_files(&args.a, &args.b, args.alpha, args.diff.as_deref()) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => fail(2, e),
    }
}

/// 0: agree, 1: differ; an error is returned for bad input (exit status 2).
fn compare_files(a: &Path, b: &Path, alpha: f64, diff: Option<&Path>) -> Result<bool, String> {
    let ia = Image::read_exr(a).map_err(|e| e.to_string())?;
    let ib = Image::read_exr(b).map_err(|e| e.to_string())?;
    let c = compare::compare(&ia, &ib, alpha)
        .map_err(|e| format!("{} vs {}: {e}", a.display(), b.display()))?;
    print!("{}", c.report());
    if let Some(path) = diff {
        let bytes = compare::difference_rgb8(&ia, &ib, c.z_critical);
        raylemma::spectral::display::write_png(path, ia.width, ia.height, &bytes)
            .map_err(|e| e.to_string())?;
        println!("difference image: {}", path.display());
    }
    Ok(c.agree())
}
