//! The reference renderer: scenes ([`scene`]), the pinhole camera ([`camera`]), the
//! spectral path tracer ([`integrator`]), images and their files ([`image`]), and the
//! comparison of two renders within their noise ([`compare`]). Chapter: *The reference
//! renderer* (`chapters/renderer/renderer.md`).

pub mod camera;
pub mod compare;
pub mod image;
pub mod integrator;
pub mod scene;

use std::path::{Path, PathBuf};
use std::time::Instant;

use glam::{DVec2, DVec3};
use indicatif::{ProgressBar, ProgressStyle};
use rand::RngExt;
use rayon::prelude::*;

use self::camera::Camera;
use self::image::{Image, Welford};
use self::scene::Scene;
use crate::output::{self, FileError, FileSet};
use crate::rng::Rng;
use crate::spectral::cie;
use crate::spectral::wavelength::{N, Wavelengths};

/// The side of the square tiles the image is split into for the worker threads.
pub const TILE: u32 = 16;

// ANCHOR: pixel_rng
/// The generator of pixel `index` for `seed`: PCG-64 on its own stream. A pixel's samples
/// depend on nothing but the seed and its index, so the image is bit-identical whatever the
/// number of threads or the order in which tiles finish.
pub fn pixel_rng(seed: u64, index: u64) -> Rng {
    let state = u128::from(seed) << 64 | 0x853c_49e6_748f_ea9b;
    Rng::new(state, u128::from(index))
}
// ANCHOR_END: pixel_rng

// ANCHOR: sample_xyz
/// One sample's CIE XYZ from the radiance `l` at the path's wavelengths: the hero
/// estimator `(1/N) sum_j l_j cmf(lambda_j) / pdf_j`, over the live lanes, normalised so
/// that a constant radiance 1 has `Y = 1` (the estimator of
/// [`crate::spectral::wavelength::Wavelengths::estimate`], with the lanes' values
/// already known).
pub fn sample_xyz(l: &integrator::Lanes, wl: &Wavelengths) -> DVec3 {
    let mut sum = DVec3::ZERO;
    for ((&lj, &pdf), &nm) in l.iter().zip(&wl.pdf).zip(&wl.lambda) {
        if pdf > 0.0 {
            sum += lj / pdf * cie::cmf(nm);
        }
    }
    sum / (N as f64 * cie::y_integral())
}
// ANCHOR_END: sample_xyz

/// Draws the wavelengths of one path from a uniform number in `[0, 1)`.
pub type WavelengthSampler<'a> = &'a (dyn Fn(f64) -> Wavelengths + Sync);

/// Renders pixel `(x, y)` with `spp` samples: the mean and variance of its linear sRGB.
pub fn render_pixel(
    scene: &Scene,
    camera: &Camera,
    sampler: WavelengthSampler,
    (x, y): (u32, u32),
    spp: u32,
) -> Welford {
    let to_rgb = cie::xyz_to_linear_srgb_matrix();
    let w = scene.camera.width;
    let mut rng = pixel_rng(
        scene.settings.seed,
        u64::from(y) * u64::from(w) + u64::from(x),
    );
    let mut acc = Welford::default();
    for _ in 0..spp {
        let jitter = DVec2::new(rng.random(), rng.random());
        let ray = camera.ray(x, y, jitter);
        let mut wl = sampler(rng.random());
        let l = integrator::radiance(scene, ray.origin, ray.dir, &mut wl, &mut rng);
        acc.push(to_rgb * sample_xyz(&l, &wl));
    }
    acc
}

/// How a render reports progress.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Progress {
    /// A progress bar on standard error.
    Bar,
    /// Nothing (tests).
    Silent,
}

// ANCHOR: render
/// Renders `scene` with `spp` samples per pixel, over square tiles in parallel (rayon).
/// Each pixel has its own generator ([`pixel_rng`]), so the result does not depend on the
/// number of threads.
pub fn render(scene: &Scene, spp: u32, progress: Progress) -> Image {
    let wavelengths = &scene.settings.wavelengths;
    render_with(scene, spp, progress, &|u| wavelengths.sample(u))
}
// ANCHOR_END: render

/// [`render`] with the wavelengths of every path drawn by `sampler` instead of the scene's
/// strategy (the tests plant wrong samplers through it).
pub fn render_with(
    scene: &Scene,
    spp: u32,
    progress: Progress,
    sampler: WavelengthSampler,
) -> Image {
    let camera = Camera::new(&scene.camera);
    let (w, h) = (scene.camera.width, scene.camera.height);
    let tiles: Vec<(u32, u32)> = (0..h.div_ceil(TILE))
        .flat_map(|ty| (0..w.div_ceil(TILE)).map(move |tx| (tx * TILE, ty * TILE)))
        .collect();
    let bar = match progress {
        Progress::Bar => ProgressBar::new(tiles.len() as u64).with_style(
            ProgressStyle::with_template(
                "  {msg} [{bar:40}] {pos}/{len} tiles, {elapsed} elapsed, about {eta} left",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
        ),
        Progress::Silent => ProgressBar::hidden(),
    };
    bar.set_message(format!("{w}x{h}, {spp} spp"));
    let done: Vec<Vec<(usize, Welford)>> = tiles
        .par_iter()
        .map(|&(x0, y0)| {
            let mut out = Vec::with_capacity((TILE * TILE) as usize);
            for y in y0..(y0 + TILE).min(h) {
                for x in x0..(x0 + TILE).min(w) {
                    let idx = y as usize * w as usize + x as usize;
                    out.push((idx, render_pixel(scene, &camera, sampler, (x, y), spp)));
                }
            }
            bar.inc(1);
            out
        })
        .collect();
    bar.finish_and_clear();
    let n = w as usize * h as usize;
    let mut image = Image {
        width: w,
        height: h,
        mean: vec![DVec3::ZERO; n],
        var: vec![DVec3::ZERO; n],
    };
    for (idx, acc) in done.into_iter().flatten() {
        image.mean[idx] = acc.mean();
        image.var[idx] = acc.var_of_mean();
    }
    image
}

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
    /// [`Scene::hash`].
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

/// Renders the scene file `path` and times it: the image and its sidecar.
///
/// # Errors
/// The scene's [`crate::data::DataError`] as text, before anything is rendered.
pub fn render_file(
    path: &Path,
    spp: Option<u32>,
    seed: Option<u64>,
    progress: Progress,
) -> Result<(Scene, Image, Sidecar), String> {
    let mut scene = scene::load(path).map_err(|e| e.to_string())?;
    if let Some(s) = spp {
        scene.settings.spp = s;
    }
    if let Some(s) = seed {
        scene.settings.seed = s;
    }
    let start = Instant::now();
    let image = render(&scene, scene.settings.spp, progress);
    let seconds = start.elapsed().as_secs_f64();
    let name = scene.settings.wavelengths.name();
    let sidecar = Sidecar {
        scene: path.display().to_string(),
        scene_hash: scene.hash,
        spp: scene.settings.spp,
        seed: scene.settings.seed,
        wavelengths: name.to_string(),
        seconds,
        threads: rayon::current_num_threads(),
    };
    Ok((scene, image, sidecar))
}
