//! The files of a render: `SCENE.exr` (the means and their variances), `SCENE.png` (the
//! display image) and `SCENE.json`, the sidecar that says what the render was
//! ([`Sidecar`], written with `serde_json`). All three land together or not at all
//! ([`write_outputs`], through the project's one writer, [`crate::output::FileSet`]), so a
//! failure leaves an earlier render whole. Chapter: *The path tracer*
//! (`chapters/renderer/path-tracer.md`, *What a render writes*).

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::provenance::MadeFrom;
use crate::image::png::encode_png;
use crate::image::{Image, ImageError};
use crate::output::{self, FileError, FileSet};
use crate::spectral::display;

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
    /// What the render was made from, for a reference render ([`MadeFrom`]).
    pub made_from: Option<MadeFrom>,
    /// The build that rendered it: the FNV-1a hash of the `raylemma` executable, which
    /// `raylemma render` records ([`build_id`]) and `raylemma merge` requires to be the
    /// same for every part (`None`: not recorded).
    pub build: Option<String>,
    /// For a merged render, the seeds of every render it pools (empty for one render,
    /// whose seed is `seed`).
    pub seeds: Vec<u64>,
}

/// The sidecar as written, key by key in the order of the renderer chapter.
#[derive(Serialize)]
struct Json<'a> {
    renderer: String,
    scene: &'a str,
    /// 16 hexadecimal digits (JSON numbers lose the low bits of a 64-bit integer).
    scene_hash: String,
    width: u32,
    height: u32,
    spp: u32,
    seed: u64,
    wavelengths: &'a str,
    /// Rounded to milliseconds.
    seconds: f64,
    threads: usize,
    /// Rounded to an integer.
    pixel_samples_per_second: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    made_from: Option<&'a MadeFrom>,
    #[serde(skip_serializing_if = "Option::is_none")]
    build: Option<&'a str>,
    #[serde(skip_serializing_if = "<[u64]>::is_empty")]
    seeds: &'a [u64],
}

/// The keys of a sidecar that are read back (by the reference job).
#[derive(Deserialize)]
struct Read {
    scene: String,
    scene_hash: String,
    spp: u32,
    seed: u64,
    wavelengths: String,
    seconds: f64,
    threads: usize,
    made_from: Option<MadeFrom>,
    #[serde(default)]
    build: Option<String>,
    #[serde(default)]
    seeds: Vec<u64>,
}

/// The FNV-1a hash of the running executable's bytes, in hexadecimal: the same for every
/// render made by one build, whatever machine runs it (`None` if it cannot be read).
pub fn build_id() -> Option<String> {
    let exe = std::env::current_exe().ok()?;
    let bytes = std::fs::read(exe).ok()?;
    Some(format!("{:016x}", super::raw::fnv1a(&bytes)))
}

impl Sidecar {
    /// The seeds of the renders this one pools: `seeds`, or `[seed]` for one render.
    pub(crate) fn all_seeds(&self) -> Vec<u64> {
        if self.seeds.is_empty() {
            vec![self.seed]
        } else {
            self.seeds.clone()
        }
    }

    /// The sidecar of `image` as pretty-printed JSON (the keys of the renderer chapter),
    /// ending with a newline.
    pub fn to_json(&self, image: &Image) -> String {
        let samples = f64::from(image.width) * f64::from(image.height) * f64::from(self.spp);
        let json = Json {
            renderer: format!("raylemma {}", env!("CARGO_PKG_VERSION")),
            scene: &self.scene,
            scene_hash: format!("{:016x}", self.scene_hash),
            width: image.width,
            height: image.height,
            spp: self.spp,
            seed: self.seed,
            wavelengths: &self.wavelengths,
            seconds: (self.seconds * 1000.0).round() / 1000.0,
            threads: self.threads,
            // A float-to-integer `as` saturates (and takes NaN to 0).
            pixel_samples_per_second: (samples / self.seconds.max(1e-9)).round() as u64,
            made_from: self.made_from.as_ref(),
            build: self.build.as_deref(),
            seeds: &self.seeds,
        };
        // Serialising plain strings and numbers into a string cannot fail.
        let mut text = serde_json::to_string_pretty(&json).unwrap_or_default();
        text.push('\n');
        text
    }

    /// Reads a sidecar written by [`Sidecar::to_json`].
    ///
    /// # Errors
    /// A [`FileError`] naming the file when it cannot be read or is not such a sidecar.
    pub fn read(path: &Path) -> Result<Sidecar, FileError> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| FileError::new(path, format!("cannot read: {e}")))?;
        let r: Read = serde_json::from_str(&text)
            .map_err(|e| FileError::new(path, format!("not a render's sidecar: {e}")))?;
        Ok(Sidecar {
            scene: r.scene,
            scene_hash: u64::from_str_radix(&r.scene_hash, 16)
                .map_err(|e| FileError::new(path, format!("scene_hash: {e}")))?,
            spp: r.spp,
            seed: r.seed,
            wavelengths: r.wavelengths,
            seconds: r.seconds,
            threads: r.threads,
            made_from: r.made_from,
            build: r.build,
            seeds: r.seeds,
        })
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
    let mut files = FileSet::new();
    let paths = stage_outputs(&mut files, dir, stem, image, sidecar)?;
    files.commit()?;
    Ok(paths)
}

/// Stages the three files of a render in `dir` (created if needed) into `files`, to land
/// with the rest of that set (the reference job commits every render and table at once).
///
/// # Errors
/// A [`FileError`] naming the file (or folder) that could not be written.
pub fn stage_outputs(
    files: &mut FileSet,
    dir: &Path,
    stem: &str,
    image: &Image,
    sidecar: &Sidecar,
) -> Result<[PathBuf; 3], FileError> {
    output::create_dir_all(dir)?;
    let [exr, png, json] = output_paths(dir, stem);
    files.write_with(&exr, |f| image.encode_exr(f))?;
    let bytes = encode_display_png(image, 0.0).map_err(|e| FileError::new(&png, e.to_string()))?;
    files.write(&png, &bytes)?;
    files.write(&json, sidecar.to_json(image).as_bytes())?;
    Ok([exr, png, json])
}

/// The means of `image` as the bytes of an 8-bit sRGB PNG, through the display chapter's
/// rules (exposure `2^stops`, fit to gamut, the sRGB curve: [`display::to_display_rgb8`]).
///
/// # Errors
/// As [`encode_png`].
pub fn encode_display_png(image: &Image, stops: f64) -> Result<Vec<u8>, ImageError> {
    encode_png(
        image.width,
        image.height,
        &display::to_display_rgb8(&image.mean, stops),
    )
}
