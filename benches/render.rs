//! Criterion benchmark of the chapter *The reference renderer*: pixel samples per second
//! of the path tracer on the `cornell` scene (a 64 x 64 crop of the camera's view at 4
//! samples per pixel, so that one iteration takes a fraction of a second), and of the
//! `cornell-diffuse` scene. The book's speed-against-error table (`figures/render_speed.md`)
//! comes from `cargo run --release`, which renders the full 256 x 256 image.
//!
//! The hot path on its own: `tracer/intersect` (the closest hit of every camera ray of a
//! 64 x 64 view of `cornell`, the loop that takes the largest share of the renderer's
//! instructions, `figures/render_profile.md`) and `tracer/radiance` (whole paths through
//! those pixels, one per pixel, at the scene's hero wavelengths).
//!
//! Run with `cargo bench -p raylemma-bench --bench render`.

use std::path::Path;

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec2;
use raylemma::render::camera::Camera;
use raylemma::render::integrator::radiance;
use raylemma::render::tracer::Tracer;
use raylemma::render::{Progress, load, pixel_rng, render};

fn scenes(c: &mut Criterion) {
    let mut group = c.benchmark_group("render");
    for name in ["cornell", "cornell-diffuse"] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(format!("{name}.toml"));
        let mut s = load(&path).unwrap_or_else(|e| panic!("{e}"));
        s.camera.width = 64;
        s.camera.height = 64;
        let spp = 4;
        group.throughput(Throughput::Elements(64 * 64 * u64::from(spp)));
        group.sample_size(10);
        group.bench_function(name, |b| b.iter(|| render(&s, spp, Progress::Silent)));
    }
    group.finish();
}

fn hot_path(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell.toml");
    let mut s = load(&path).unwrap_or_else(|e| panic!("{e}"));
    s.camera.width = 64;
    s.camera.height = 64;
    let tracer = Tracer::new(&s);
    let camera = Camera::new(&s.camera);
    let rays: Vec<_> = (0..64 * 64)
        .map(|i| camera.ray(i % 64, i / 64, DVec2::splat(0.5)))
        .collect();
    let mut group = c.benchmark_group("tracer");
    group.throughput(Throughput::Elements(rays.len() as u64));
    group.bench_function("intersect", |b| {
        b.iter(|| {
            rays.iter()
                .filter(|r| tracer.intersect(black_box(r.origin), r.dir).is_some())
                .count()
        })
    });
    group.bench_function("radiance", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for (i, r) in rays.iter().enumerate() {
                let mut rng = pixel_rng(1, i as u64);
                let mut wl = s
                    .settings
                    .wavelengths
                    .sample(rand::RngExt::random(&mut rng));
                sum += radiance(&tracer, r.origin, r.dir, &mut wl, &mut rng)[0];
            }
            sum
        })
    });
    group.finish();
}

criterion_group!(benches, scenes, hot_path);
criterion_main!(benches);
