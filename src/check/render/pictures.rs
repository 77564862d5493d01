//! Pictures of a renderer that disagrees with what it must match: for each failing scene,
//! one PNG of three panels side by side, the render, the expected image and their
//! difference. Chapter: *Testing the renderer*; the report card's *results* folder
//! (chapter *Coursework*).

use std::path::{Path, PathBuf};

use glam::DVec3;

use super::Rendered;
use crate::check::Verdict;
use crate::image::png::write_png;
use crate::spectral::display::to_display_rgb8;

/// The folder of the renderer's pictures in the student's results, relative to the crate's
/// root.
pub fn results_dir() -> PathBuf {
    Path::new("results").join("renderer")
}

/// `name` with every character that is not an ASCII letter or digit made `-`.
fn file_name(name: &str) -> String {
    name.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
        .collect()
}

/// Writes `DIR/SCENE.png` for every scene of `rendered` whose claims failed in `verdict`
/// (the findings [`super::judge`] names `SCENE: global` and `SCENE: blocks`): three
/// panels, left to right, the render, the expected image (black where a pixel is not
/// tested) and the difference, `|render - expected|` four times as bright, so that a
/// bias of a few percent shows. Returns the files written; a scene that cannot be written
/// is left out (the pictures explain a failure; they are not the test).
pub fn write_failed(dir: &Path, rendered: &[Rendered], verdict: &Verdict) -> Vec<PathBuf> {
    let mut written = Vec::new();
    for r in rendered {
        let failed = verdict
            .findings
            .iter()
            .any(|f| !f.passed() && f.name.rsplit_once(": ").is_some_and(|(n, _)| n == r.name));
        if !failed {
            continue;
        }
        let (w, h) = (r.image.width as usize, r.image.height as usize);
        let expected: Vec<DVec3> = (0..w * h)
            .map(|i| {
                r.expected
                    .mean
                    .get(i)
                    .copied()
                    .flatten()
                    .unwrap_or(DVec3::ZERO)
            })
            .collect();
        let difference: Vec<DVec3> = r
            .image
            .mean
            .iter()
            .zip(&expected)
            .map(|(a, b)| 4.0 * (*a - *b).abs())
            .collect();
        // One gap of 4 pixels between panels.
        let gap = 4;
        let width = 3 * w + 2 * gap;
        let mut panels = vec![DVec3::splat(0.5); width * h];
        for (k, image) in [&r.image.mean, &expected, &difference]
            .into_iter()
            .enumerate()
        {
            for y in 0..h {
                for x in 0..w {
                    panels[y * width + k * (w + gap) + x] = image[y * w + x];
                }
            }
        }
        let path = dir.join(format!("{}.png", file_name(&r.name)));
        let bytes = to_display_rgb8(&panels, 0.0);
        if std::fs::create_dir_all(dir).is_ok()
            && write_png(&path, width as u32, h as u32, &bytes).is_ok()
        {
            written.push(path);
        }
    }
    written
}
