//! Planted biases of known size: the twins every renderer check must reject. Chapter:
//! *Testing the renderer* (`chapters/renderer/testing.md`).
//!
//! A realistic mistake in a path tracer biases its image, globally (every pixel a little
//! too bright) or locally (one region, such as the edge of a glass sphere, wrong). These
//! plant such a bias in rendered images (or wrap a renderer to plant it in all of its
//! images), so that a check's power against a bias of a given size is shown and measured.

use glam::DVec3;

use super::Renderer;
use crate::render::image::Image;
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
