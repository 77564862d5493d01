//! One pixel: its generator ([`pixel_rng`]), its samples (a jittered camera ray, the
//! path's wavelengths, the path's radiance, its colour: [`sample_xyz`]), and their running
//! mean and variance ([`render_pixel`]). Chapter: *The path tracer*
//! (`chapters/renderer/path-tracer.md`, *From lanes to a pixel*).

use glam::{DVec2, DVec3};
use rand::RngExt;

use super::camera::Camera;
use super::integrator::{self, Lanes};
use super::tracer::Tracer;
use crate::image::Welford;
use crate::rng::Rng;
use crate::spectral::cie;
use crate::spectral::wavelength::{N, Wavelengths};

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
pub fn sample_xyz(l: &Lanes, wl: &Wavelengths) -> DVec3 {
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

/// Where a pixel's random numbers come from. The renderer's own is one PCG-64 stream per
/// pixel read in order ([`pixel_rng`]): a sample's `k`-th number is its sample dimension
/// `k` (the jitter's two, the wavelengths', then each vertex's). A check may put another
/// source in its place (one stream per dimension, `check::render::independence`), told
/// where each sample starts.
pub trait PixelNumbers: rand::Rng {
    /// Called before each sample's first number (one stream read in order ignores it).
    fn start_sample(&mut self) {}
}

impl PixelNumbers for Rng {}

/// Renders pixel `(x, y)` with `spp` samples drawn from `rng` (the pixel's own generator,
/// [`pixel_rng`]): the mean and variance of its linear sRGB. `sampler` draws each path's
/// wavelengths (generic, so that the scene's own strategy is compiled into the pixel loop;
/// a [`WavelengthSampler`] works too).
#[inline(always)]
pub fn render_pixel<S: Fn(f64) -> Wavelengths + ?Sized, R: PixelNumbers>(
    tracer: &Tracer,
    camera: &Camera,
    sampler: &S,
    (x, y): (u32, u32),
    spp: u32,
    rng: &mut R,
) -> Welford {
    let to_rgb = cie::xyz_to_linear_srgb_matrix();
    let mut acc = Welford::default();
    for _ in 0..spp {
        rng.start_sample();
        let jitter = DVec2::new(rng.random(), rng.random());
        let ray = camera.ray(x, y, jitter);
        let mut wl = sampler(rng.random());
        let l = integrator::radiance(tracer, ray.origin, ray.dir, &mut wl, rng);
        acc.push(to_rgb * sample_xyz(&l, &wl));
    }
    acc
}
