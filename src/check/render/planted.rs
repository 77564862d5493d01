//! Planted biases of known size: the twins every renderer check must reject. Chapter:
//! *Testing the renderer* (`chapters/renderer/testing.md`).
//!
//! A realistic mistake in a path tracer biases its image, globally (every pixel a little
//! too bright) or locally (one region, such as the edge of a glass sphere, wrong). These
//! plant such a bias in rendered images (or wrap a renderer to plant it in all of its
//! images), so that a check's power against a bias of a given size is shown and measured.

use glam::DVec3;

use super::Renderer;
use crate::image::Image;
use crate::render::scene::{DirectLight, Scene};

/// Every pixel of `image` `1 + bias` times brighter.
pub fn brighten(image: &mut Image, bias: f64) {
    for m in &mut image.mean {
        *m *= 1.0 + bias;
    }
}

/// The pixels of the `side x side` square at `(x, y)` of `image` (clipped to it)
/// `1 + bias` times brighter.
pub fn brighten_square(image: &mut Image, bias: f64, (x, y): (u32, u32), side: u32) {
    for py in y..(y + side).min(image.height) {
        for px in x..(x + side).min(image.width) {
            let i = image.index(px, py);
            image.mean[i] *= 1.0 + bias;
        }
    }
}

/// `renderer`'s image with every pixel `1 + bias` times brighter.
pub fn global(renderer: Renderer<'_>, bias: f64) -> impl Fn(&Scene) -> Image + Sync + '_ {
    move |scene| {
        let mut image = renderer(scene);
        brighten(&mut image, bias);
        image
    }
}

/// `renderer`'s image with the pixels of the `side x side` square at `(x, y)` (clipped to
/// the image) `1 + bias` times brighter.
pub fn local(
    renderer: Renderer<'_>,
    bias: f64,
    (x, y): (u32, u32),
    side: u32,
) -> impl Fn(&Scene) -> Image + Sync + '_ {
    move |scene| {
        let mut image = renderer(scene);
        brighten_square(&mut image, bias, (x, y), side);
        image
    }
}

/// `renderer` with light sampling one vertex too deep: a scene estimated by light sampling
/// alone (`DirectLight::Light`) is rendered with one bounce more than its `max_depth`,
/// which is what next-event estimation at the path's last vertex adds (the mistake of
/// sampling a light from a vertex whose BSDF half is never traced).
pub fn light_sampling_one_vertex_deeper(
    renderer: Renderer<'_>,
) -> impl Fn(&Scene) -> Image + Sync + '_ {
    move |scene| {
        if scene.settings.direct == DirectLight::Light {
            let mut deeper = scene.clone();
            deeper.settings.max_depth += 1;
            renderer(&deeper)
        } else {
            renderer(scene)
        }
    }
}

/// `renderer`'s image with the colour `shift` (linear sRGB) added to every pixel.
pub fn offset(renderer: Renderer<'_>, shift: DVec3) -> impl Fn(&Scene) -> Image + Sync + '_ {
    move |scene| {
        let mut image = renderer(scene);
        for m in &mut image.mean {
            *m += shift;
        }
        image
    }
}

/// `renderer` with every pixel's footprint changed: the scene rendered at twice the
/// resolution with a quarter of the samples, each pixel then the mean of the half-size
/// pixels at the offsets `offsets` (in half-pixels from its first, along each axis; those
/// outside the image left out). Offsets `[0, 1]` are the pixel itself.
fn refiltered<'a>(
    renderer: Renderer<'a>,
    offsets: &'static [i64],
) -> impl Fn(&Scene) -> Image + Sync + 'a {
    move |scene| {
        let mut fine = scene.clone();
        fine.camera.width *= 2;
        fine.camera.height *= 2;
        fine.settings.spp = scene.settings.spp.div_ceil(4);
        let f = renderer(&fine);
        let (w, h) = (scene.camera.width, scene.camera.height);
        let mut image = Image {
            width: w,
            height: h,
            mean: Vec::with_capacity((w * h) as usize),
            var: Vec::with_capacity((w * h) as usize),
            spp: Some(scene.settings.spp),
        };
        for y in 0..h {
            for x in 0..w {
                let (mut mean, mut var, mut n) = (DVec3::ZERO, DVec3::ZERO, 0.0);
                for &oy in offsets {
                    for &ox in offsets {
                        let (fx, fy) = (2 * i64::from(x) + ox, 2 * i64::from(y) + oy);
                        if (0..i64::from(f.width)).contains(&fx)
                            && (0..i64::from(f.height)).contains(&fy)
                        {
                            let i = f.index(fx as u32, fy as u32);
                            mean += f.mean[i];
                            var += f.var[i];
                            n += 1.0;
                        }
                    }
                }
                image.mean.push(mean / n);
                image.var.push(var / (n * n));
            }
        }
        image
    }
}

/// `renderer` with every pixel's footprint moved by half a pixel right and down: the
/// mistake of a jitter in `[0.5, 1.5)` (or a camera ray through the pixel's far corner).
pub fn shifted_half_a_pixel(renderer: Renderer<'_>) -> impl Fn(&Scene) -> Image + Sync + '_ {
    refiltered(renderer, &[1, 2])
}

/// `renderer` with every pixel's footprint twice as wide (a box of two pixels around the
/// pixel's centre): the mistake of a jitter in `[-0.5, 1.5)`, or of a wider filter.
pub fn twice_as_wide(renderer: Renderer<'_>) -> impl Fn(&Scene) -> Image + Sync + '_ {
    refiltered(renderer, &[-1, 0, 1, 2])
}
