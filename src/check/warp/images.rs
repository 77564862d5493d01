//! The failure images of the warp checker: observed counts, expected counts and their
//! difference, one block per cell, written when the chi-squared test fails. Chapter:
//! *Checking a sampler*.

use std::path::PathBuf;

use super::cells::grid;
use super::{Warp, WarpOptions};
use crate::check::pictures::failure_dir;

/// The folder name of `warp`'s images: its name with every character that is not an ASCII
/// letter or digit made `_`.
fn safe_name(warp: &dyn Warp) -> String {
    warp.name()
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

/// Writes `observed`, `expected` and `difference` PNGs (one pixel block per cell, at least
/// 256 pixels on each side) and a `README.txt` saying what their axes and colours
/// are into `<name>/` of [`failure_dir`] and returns that directory. Rows are the cells' first coordinate
/// (the interval's `x`, the square's `u2`, the disc's `r^2`, the sphere's `z`), increasing
/// upwards; columns the second (the square's `u1`, the azimuth), increasing to the right.
pub(super) fn write_failure_images(
    warp: &dyn Warp,
    options: &WarpOptions,
    observed: &[u64],
    expected: &[f64],
) -> Option<PathBuf> {
    let (rows, cols) = grid(warp.domain(), options.resolution);
    let dir = failure_dir().join(safe_name(warp));
    std::fs::create_dir_all(&dir).ok()?;
    let max = expected
        .iter()
        .copied()
        .fold(0.0, f64::max)
        .max(observed.iter().copied().max().unwrap_or(0) as f64);
    // Each cell a block of pixels, so that each side is at least 256 pixels (a cell of an
    // interval's single column is a wide bar).
    let (sx, sy) = (
        256usize.div_ceil(cols.max(1)),
        256usize.div_ceil(rows.max(1)),
    );
    let (width, height) = (cols * sx, rows * sy);
    // RGB bytes, row-major from the top: the image's row `y` is the cells' row
    // `rows - 1 - y / sy`, so that the first coordinate increases upwards.
    let image = |value: &dyn Fn(usize) -> [u8; 3]| -> Vec<u8> {
        (0..height)
            .flat_map(|y| (0..width).map(move |x| (rows - 1 - y / sy, x / sx)))
            .flat_map(|(i, j)| value(i * cols + j))
            .collect()
    };
    let grey = |v: f64| {
        let g = (255.0 * (v / max).clamp(0.0, 1.0)) as u8;
        [g, g, g]
    };
    // The three images land together (the project's one writer), never half of them.
    let mut files = crate::output::FileSet::new();
    let mut stage = |name: &str, rgb8: Vec<u8>| {
        let png = crate::image::png::encode_png(width as u32, height as u32, &rgb8);
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
    let readme = legend(warp, rows, cols, (sx, sy));
    files
        .write(&dir.join("README.txt"), readme.as_bytes())
        .ok()?;
    files.commit().ok()?;
    Some(dir)
}

/// What the three images show, written beside them: the axes of the domain's cells and
/// the colours, since the PNGs carry no text.
fn legend(warp: &dyn Warp, rows: usize, cols: usize, (sx, sy): (usize, usize)) -> String {
    use super::Domain;
    let (up, right) = match warp.domain() {
        Domain::Interval { lo, hi } => (
            format!("x from {lo} (bottom) to {hi} (top)"),
            "-".to_string(),
        ),
        Domain::Square => (
            "u2 from 0 (bottom) to 1 (top)".into(),
            "u1 from 0 (left) to 1 (right)".into(),
        ),
        Domain::Disc => (
            "r^2 from 0 (bottom, the centre) to 1 (top, the rim): equal-area rings".into(),
            "the azimuth phi from 0 (left) to 360 degrees (right)".into(),
        ),
        Domain::Sphere => (
            "z from -1 (bottom) to 1 (top): equal-area bands".into(),
            "the azimuth phi from 0 (left) to 360 degrees (right)".into(),
        ),
    };
    format!(
        "The failure images of the sampler `{}` (raylemma's warp checker, chapter Checking a sampler).\n\
         {rows} rows x {cols} columns of cells of equal measure, each {sx} pixels wide and {sy} tall.\n\
         Rows (up): {up}.\nColumns (right): {right}.\n\
         observed.png: the samples in each cell; expected.png: the integral of the pdf over it \
         times the number of samples (one grey scale for both: white is the largest count).\n\
         difference.png: (observed - expected) / sqrt(expected) per cell, red where there are \
         more samples than the pdf says and blue where there are fewer, full colour at 5 \
         standard deviations; white where they agree.\n\
         The folder is removed when the sampler passes its chi-squared test again.\n",
        warp.name()
    )
}

/// Removes the failure images of `warp` left by an earlier failing run, now that it passes:
/// a folder of images next to a sampler that passes would say it fails.
pub(super) fn remove_stale_images(warp: &dyn Warp) {
    let _ = std::fs::remove_dir_all(failure_dir().join(safe_name(warp)));
}
