//! The failure images of the warp checker: observed counts, expected counts and their
//! difference, one block per cell, written when the chi-squared test fails. Chapter:
//! *Checking a sampler*.

use std::path::PathBuf;
use std::sync::OnceLock;

use super::cells::grid;
use super::{Warp, WarpOptions};

/// The folder set by [`set_failure_dir`] (`raylemma check sampler --failure-images DIR`).
static FAILURE_DIR: OnceLock<PathBuf> = OnceLock::new();

/// The folder the failure images go into: the one [`set_failure_dir`] set, else
/// `warp-failures/` in the working directory (never a folder fixed when the binary was
/// built, which may be read-only or another user's).
pub fn failure_dir() -> PathBuf {
    FAILURE_DIR
        .get()
        .cloned()
        .unwrap_or_else(|| PathBuf::from("warp-failures"))
}

/// Sets the folder of the failure images for the rest of the process (the first call
/// wins; `false` if it was already set to another folder).
pub fn set_failure_dir(dir: PathBuf) -> bool {
    FAILURE_DIR.get_or_init(|| dir.clone()) == &dir
}

/// Writes `observed`, `expected` and `difference` PNGs (one pixel block per cell) into
/// `<name>/` of [`failure_dir`] and returns that directory. Rows are the cells' first coordinate
/// (the interval's `x`, the square's `u2`, the disc's `r^2`, the sphere's `z`), increasing
/// upwards; columns the second (the square's `u1`, the azimuth), increasing to the right.
pub(super) fn write_failure_images(
    warp: &dyn Warp,
    options: &WarpOptions,
    observed: &[u64],
    expected: &[f64],
) -> Option<PathBuf> {
    let (rows, cols) = grid(warp.domain(), options.resolution);
    let safe: String = warp
        .name()
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    let dir = failure_dir().join(safe);
    std::fs::create_dir_all(&dir).ok()?;
    let max = expected
        .iter()
        .copied()
        .fold(0.0, f64::max)
        .max(observed.iter().copied().max().unwrap_or(0) as f64);
    let scale = 4;
    let image = |value: &dyn Fn(usize) -> [u8; 3]| {
        image::RgbImage::from_fn((cols * scale) as u32, (rows * scale) as u32, |x, y| {
            let (i, j) = (rows - 1 - y as usize / scale, x as usize / scale);
            image::Rgb(value(i * cols + j))
        })
    };
    let grey = |v: f64| {
        let g = (255.0 * (v / max).clamp(0.0, 1.0)) as u8;
        [g, g, g]
    };
    // The three images land together (the project's one writer), never half of them.
    let mut files = crate::output::FileSet::new();
    let mut stage = |name: &str, img: image::RgbImage| {
        let png = crate::spectral::display::encode_png(img.width(), img.height(), img.as_raw());
        png.ok()
            .and_then(|bytes| files.write(&dir.join(name), &bytes).ok())
    };
    stage("observed.png", image(&|k| grey(observed[k] as f64)))?;
    stage("expected.png", image(&|k| grey(expected[k])))?;
    let difference = image(&|k| {
        // Red: more samples than expected; blue: fewer; in standard deviations, saturating at 5.
        let z = (observed[k] as f64 - expected[k]) / expected[k].max(1.0).sqrt();
        let c = (255.0 * (z.abs() / 5.0).min(1.0)) as u8;
        if z > 0.0 {
            [255, 255 - c, 255 - c]
        } else {
            [255 - c, 255 - c, 255]
        }
    });
    stage("difference.png", difference)?;
    files.commit().ok()?;
    Some(dir)
}
