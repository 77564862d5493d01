//! The files of a render: `SCENE.exr` (the means and their variances), `SCENE.png` (the
//! display image) and `SCENE.json`, the sidecar that says what the render was
//! ([`Sidecar`]). All three land together or not at all
//! ([`write_outputs`], through the project's one writer, [`crate::output::FileSet`]), so a
//! failure leaves an earlier render whole. Chapter: *The reference renderer*
//! (`chapters/renderer/renderer.md`, *What a render writes*).

use std::path::{Path, PathBuf};

use super::image::Image;
use crate::output::{self, FileError, FileSet};

/// `s` as a JSON string literal: quotes, backslashes and control characters escaped.
pub fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if u32::from(c) < 0x20 => out.push_str(&format!("\\u{:04x}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// What a render was, for its JSON sidecar.
#[derive(Clone, Debug, PartialEq)]
pub struct Sidecar {
    /// The scene file as given.
    pub scene: String,
    /// [`super::scene::Scene::hash`].
    pub scene_hash: u64,
    /// Samples per pixel.
    pub spp: u32,
    /// The seed.
    pub seed: u64,
    /// The wavelength strategy's name.
    pub wavelengths: String,
    /// Wall-clock seconds of the rendering (not of reading or writing).
    pub seconds: f64,
    /// Worker threads.
    pub threads: usize,
}

impl Sidecar {
    /// The sidecar as JSON (the keys of the renderer chapter).
    pub fn to_json(&self, image: &Image) -> String {
        let samples = f64::from(image.width) * f64::from(image.height) * f64::from(self.spp);
        format!(
            "{{\n  \"renderer\": \"raylemma {}\",\n  \"scene\": {},\n  \"scene_hash\": \"{:016x}\",\n  \"width\": {},\n  \"height\": {},\n  \"spp\": {},\n  \"seed\": {},\n  \"wavelengths\": {},\n  \"seconds\": {:.3},\n  \"threads\": {},\n  \"pixel_samples_per_second\": {:.0}\n}}\n",
            env!("CARGO_PKG_VERSION"),
            json_string(&self.scene),
            self.scene_hash,
            image.width,
            image.height,
            self.spp,
            self.seed,
            json_string(&self.wavelengths),
            self.seconds,
            self.threads,
            samples / self.seconds.max(1e-9)
        )
    }
}

/// The files of a render called `stem` in `dir`: `stem.exr`, `stem.png`, `stem.json`.
pub fn output_paths(dir: &Path, stem: &str) -> [PathBuf; 3] {
    ["exr", "png", "json"].map(|ext| dir.join(format!("{stem}.{ext}")))
}

/// Writes the three files of a render into `dir` (created if needed), as one
/// [`FileSet`]: each is written to a temporary file beside its destination, and all three
/// are renamed into place only once all are written, so that a failure leaves any earlier
/// render whole and no temporary file behind.
///
/// # Errors
/// A [`FileError`] naming the file (or folder) that could not be written.
pub fn write_outputs(
    dir: &Path,
    stem: &str,
    image: &Image,
    sidecar: &Sidecar,
) -> Result<[PathBuf; 3], FileError> {
    output::create_dir_all(dir)?;
    let [exr, png, json] = output_paths(dir, stem);
    let mut files = FileSet::new();
    files.write_with(&exr, |f| image.encode_exr(f))?;
    let bytes = image
        .encode_png(0.0)
        .map_err(|problem| FileError::new(&png, problem))?;
    files.write(&png, &bytes)?;
    files.write(&json, sidecar.to_json(image).as_bytes())?;
    files.commit()?;
    Ok([exr, png, json])
}
