//! The renderer against the limit of its hot loop (chapter *The reference renderer*,
//! section *Speed against error*): how fast could `cornell` render if tracing its rays
//! were the only work, and what fraction of that the renderer reaches.
//!
//! The renderer's rays are counted ([`raylemma::render::tracer::count_rays`]) while it
//! renders on one thread. The hot loop is the tracer's intersection of one ray with the
//! scene's surfaces, timed alone on a set of rays like the renderer's: camera rays, then
//! at every diffuse hit a shadow ray towards a point on the light and a cosine-weighted
//! continuation, the rays made before the clock starts. The limit is the renderer's rays
//! per sample times the time of one ray of that loop; the renderer's fraction of it is the
//! limit's time over the renderer's.

use std::fmt::Write as _;
use std::hint::black_box;

use glam::{DVec2, DVec3};
use rand::RngExt;

use super::{Output, Record, Settings};
use crate::timing::{machine, median_ns_per_item, quick_note};
use raylemma::render::camera::Camera;
use raylemma::render::integrator::offset_origin;
use raylemma::render::scene::Surface;
use raylemma::render::tracer::{Tracer, count_rays};
use raylemma::render::{self, Progress};
use raylemma::rng::seeded;
use raylemma::sampling::cosine::cosine_malley;
use raylemma::sampling::frame::Frame;

/// The outputs of this part of the chapter.
pub fn outputs() -> Vec<Output> {
    vec![Output {
        file: "render_limit.md",
        what: "the renderer against its hot loop's limit",
        make: limit_md,
    }]
}

/// One ray of the timed set: origin, unit direction, and the distance beyond which a hit
/// does not count (infinite for closest-hit rays).
type TimedRay = (DVec3, DVec3, f64);

/// Rays like the renderer's through `tracer`: `paths` camera rays through random pixels,
/// continued by cosine-weighted bounces with a shadow ray at each diffuse hit, until the
/// path leaves, reaches a light, or `depth` bounces.
fn ray_set(tracer: &Tracer, camera: &Camera, paths: usize, depth: u32) -> Vec<TimedRay> {
    let scene = tracer.scene;
    let (w, h) = (scene.camera.width, scene.camera.height);
    let mut rng = seeded(7);
    let mut rays = Vec::new();
    for _ in 0..paths {
        let (x, y) = (rng.random_range(0..w), rng.random_range(0..h));
        let ray = camera.ray(x, y, DVec2::new(rng.random(), rng.random()));
        let (mut o, mut d) = (ray.origin, ray.dir);
        for _ in 0..depth {
            rays.push((o, d, f64::INFINITY));
            let Some(hit) = tracer.intersect(o, d) else {
                break;
            };
            let Surface::Shape(i) = hit.surface else {
                break;
            };
            let (p, n) = scene.surface_point(i, o, d, hit.t);
            let n = if n.dot(d) < 0.0 { n } else { -n };
            let po = offset_origin(p, n, n);
            if let Some(light) = scene.lights.first() {
                let u = DVec2::new(rng.random(), rng.random());
                if let Some(ls) = light.light().sample(po, u) {
                    rays.push((po, ls.dir, ls.dist * (1.0 + 1e-9)));
                }
            }
            let local = cosine_malley(DVec2::new(rng.random(), rng.random()));
            d = Frame::from_normal(n).to_world(local).normalize();
            o = po;
        }
    }
    rays
}

fn limit_md(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (side, spp, reps) = if settings.quick {
        (32, 4, 3)
    } else {
        (128, 16, 5)
    };
    let scene = crate::render::cornell_timed(settings, side)?;
    let samples = f64::from(side * side * spp);
    // One worker thread: the renderer alone, as the hot loop below.
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    let (ns_per_sample, rays) = pool.install(|| {
        count_rays(true);
        black_box(render::render(&scene, spp, Progress::Silent));
        let rays = count_rays(false);
        let ns = median_ns_per_item(samples as usize, reps, || {
            render::render(&scene, spp, Progress::Silent).width.into()
        });
        (ns, rays as f64)
    });
    let rays_per_sample = rays / samples;
    let tracer = Tracer::new(&scene);
    let camera = Camera::new(&scene.camera);
    let set = ray_set(&tracer, &camera, (samples / 4.0) as usize, 12);
    let ns_per_ray = median_ns_per_item(set.len(), reps, || {
        let mut hits = 0u64;
        for &(o, d, t) in &set {
            hits += u64::from(tracer.intersect_before(o, d, t).is_some());
        }
        hits
    });
    let limit_per_s = 1e9 / (rays_per_sample * ns_per_ray);
    let ours_per_s = 1e9 / ns_per_sample;
    let mut md = String::from("| quantity | value |\n|---|---:|\n");
    let _ = writeln!(
        md,
        "| the renderer, one thread: pixel samples / s | {ours_per_s:.3e} |"
    );
    let _ = writeln!(
        md,
        "| rays traced per pixel sample (closest-hit and shadow) | {rays_per_sample:.2} |"
    );
    let _ = writeln!(
        md,
        "| the hot loop alone: ns per ray ({} rays like the renderer's) | {ns_per_ray:.1} |",
        set.len()
    );
    let _ = writeln!(
        md,
        "| the limit, if tracing rays were the only work: pixel samples / s | {limit_per_s:.3e} |"
    );
    let _ = writeln!(
        md,
        "| **the renderer's fraction of the limit** | **{:.0} %** |",
        100.0 * ours_per_s / limit_per_s
    );
    let _ = write!(
        md,
        "\n*`cornell` at {side}×{side}, {spp} samples per pixel, roulette from depth 5, on one thread; medians of {reps} runs. The hot loop is `Tracer::intersect_before` over rays made before the clock starts (camera rays, and at each diffuse hit a shadow ray and a cosine-weighted bounce). The rest of the renderer's time goes to light and BSDF sampling, spectra, random numbers and bookkeeping (their instruction counts: `figures/render_profile.md`). {}{}*\n",
        machine(),
        quick_note(settings.quick)
    );
    Ok(md.into_bytes())
}
