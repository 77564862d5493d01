//! The driver: a render of a whole image, split into square tiles ([`TILE`]) that the
//! worker threads (rayon) take in any order, each pixel by [`super::pixel::render_pixel`],
//! with a progress bar ([`Progress`]); and [`render_file`], which reads a scene file,
//! renders it and times it for its sidecar. Chapter: *The path tracer*
//! (`chapters/renderer/path-tracer.md`).

use std::path::Path;
use std::time::Instant;

use glam::DVec3;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;

use super::camera::Camera;
use super::files::Sidecar;
use super::format;
use super::pixel::{PixelNumbers, pixel_rng, render_pixel};
use super::scene::Scene;
use super::tracer::Tracer;
use crate::image::{Image, Welford};
use crate::spectral::wavelength::Wavelengths;

/// The side of the square tiles the image is split into for the worker threads.
pub const TILE: u32 = 16;

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
/// Each pixel has its own generator ([`super::pixel::pixel_rng`]), so the result does not
/// depend on the number of threads.
pub fn render(scene: &Scene, spp: u32, progress: Progress) -> Image {
    let wavelengths = &scene.settings.wavelengths;
    render_with(scene, spp, progress, &|u| wavelengths.sample(u))
}
// ANCHOR_END: render

/// [`render`] with the wavelengths of every path drawn by `sampler` instead of the scene's
/// strategy (the tests plant wrong samplers through it, as a
/// [`super::pixel::WavelengthSampler`]).
pub fn render_with<S: Fn(f64) -> Wavelengths + Sync + ?Sized>(
    scene: &Scene,
    spp: u32,
    progress: Progress,
    sampler: &S,
) -> Image {
    let whole = Window::of(scene);
    render_window(scene, spp, whole, progress, sampler)
}

/// A rectangle of an image's pixels: `width x height` from the pixel `(x, y)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Window {
    /// The left column.
    pub x: u32,
    /// The top row.
    pub y: u32,
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
}

impl Window {
    /// The whole image of `scene`'s camera.
    pub fn of(scene: &Scene) -> Self {
        Window {
            x: 0,
            y: 0,
            width: scene.camera.width,
            height: scene.camera.height,
        }
    }
}

/// Renders only the pixels of `window` (which must lie inside the image): an image of the
/// window's size whose pixels are exactly those of the whole render, since every pixel's
/// generator depends on its index in the whole image ([`super::pixel::pixel_rng`]). The
/// tests render a crop of a canonical scene this way and compare it with the committed
/// reference.
pub fn render_window<S: Fn(f64) -> Wavelengths + Sync + ?Sized>(
    scene: &Scene,
    spp: u32,
    window: Window,
    progress: Progress,
    sampler: &S,
) -> Image {
    render_window_from(scene, spp, window, progress, sampler, &pixel_rng)
}

/// [`render`] with each pixel's random numbers from `numbers(seed, index)` instead of its
/// own generator ([`pixel_rng`]): the independence check of chapter *Testing the
/// renderer* gives each sample dimension a stream of its own through it.
pub fn render_from<R: PixelNumbers, F: Fn(u64, u64) -> R + Sync>(
    scene: &Scene,
    spp: u32,
    numbers: &F,
) -> Image {
    let wavelengths = &scene.settings.wavelengths;
    let sampler = |u| wavelengths.sample(u);
    let whole = Window::of(scene);
    render_window_from(scene, spp, whole, Progress::Silent, &sampler, numbers)
}

/// [`render_window`] with each pixel's numbers from `numbers(seed, index)`.
fn render_window_from<S, R, F>(
    scene: &Scene,
    spp: u32,
    window: Window,
    progress: Progress,
    sampler: &S,
    numbers: &F,
) -> Image
where
    S: Fn(f64) -> Wavelengths + Sync + ?Sized,
    R: PixelNumbers,
    F: Fn(u64, u64) -> R + Sync,
{
    let camera = Camera::new(&scene.camera);
    let tracer = Tracer::new(scene);
    let (w, h) = (window.width, window.height);
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
    let job = TileJob {
        tracer: &tracer,
        camera: &camera,
        sampler,
        numbers,
        window,
        spp,
    };
    let wide = wide_vectors();
    let done: Vec<Vec<(usize, Welford)>> = tiles
        .par_iter()
        .map(|&corner| {
            let out = if wide {
                render_tile_wide(&job, corner)
            } else {
                render_tile(&job, corner)
            };
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
        spp: Some(spp),
    };
    for (idx, acc) in done.into_iter().flatten() {
        image.mean[idx] = acc.mean();
        image.var[idx] = acc.var_of_mean();
    }
    image
}

/// What every tile of a render shares.
struct TileJob<'a, S: ?Sized, F> {
    tracer: &'a Tracer<'a>,
    camera: &'a Camera,
    sampler: &'a S,
    /// Each pixel's random numbers from the seed and its index in the whole image.
    numbers: &'a F,
    window: Window,
    spp: u32,
}

/// The pixels of the tile whose top-left corner is `(x0, y0)` (in the window), each with
/// its index in the window's image.
#[inline(always)]
fn render_tile<S, R, F>(job: &TileJob<S, F>, (x0, y0): (u32, u32)) -> Vec<(usize, Welford)>
where
    S: Fn(f64) -> Wavelengths + Sync + ?Sized,
    R: PixelNumbers,
    F: Fn(u64, u64) -> R + Sync,
{
    let (w, h) = (job.window.width, job.window.height);
    let mut out = Vec::with_capacity((TILE * TILE) as usize);
    for y in y0..(y0 + TILE).min(h) {
        for x in x0..(x0 + TILE).min(w) {
            let idx = y as usize * w as usize + x as usize;
            let (px, py) = (job.window.x + x, job.window.y + y);
            let index = u64::from(py) * u64::from(job.tracer.scene.camera.width) + u64::from(px);
            let mut rng = (job.numbers)(job.tracer.scene.settings.seed, index);
            let acc = render_pixel(
                job.tracer,
                job.camera,
                job.sampler,
                (px, py),
                job.spp,
                &mut rng,
            );
            out.push((idx, acc));
        }
    }
    out
}

/// Whether this CPU has 256-bit vectors (AVX2), for [`render_tile_wide`].
fn wide_vectors() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// [`render_tile`] compiled for 256-bit vectors (AVX2, without fused multiply-add, which
/// would round differently): the same code, the same operations in the same order, so the
/// same bits on every machine, a little faster where the CPU has them.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn render_tile_wide_avx2<S, R, F>(job: &TileJob<S, F>, corner: (u32, u32)) -> Vec<(usize, Welford)>
where
    S: Fn(f64) -> Wavelengths + Sync + ?Sized,
    R: PixelNumbers,
    F: Fn(u64, u64) -> R + Sync,
{
    render_tile(job, corner)
}

/// [`render_tile_wide_avx2`] when the CPU has AVX2 ([`wide_vectors`] said so).
fn render_tile_wide<S, R, F>(job: &TileJob<S, F>, corner: (u32, u32)) -> Vec<(usize, Welford)>
where
    S: Fn(f64) -> Wavelengths + Sync + ?Sized,
    R: PixelNumbers,
    F: Fn(u64, u64) -> R + Sync,
{
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: called only when `wide_vectors()` found AVX2 on this CPU.
        unsafe { render_tile_wide_avx2(job, corner) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        render_tile(job, corner)
    }
}

/// Renders the scene file `path` and times it: the image and its sidecar.
///
/// # Errors
/// The scene's [`crate::data::DataError`], before anything is rendered.
pub fn render_file(
    path: &Path,
    spp: Option<u32>,
    seed: Option<u64>,
    progress: Progress,
) -> Result<(Scene, Image, Sidecar), crate::data::DataError> {
    let mut scene = format::load(path)?;
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
        made_from: None,
        build: None,
        seeds: Vec::new(),
    };
    Ok((scene, image, sidecar))
}
