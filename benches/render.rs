//! Criterion benchmark of the chapter *The reference renderer*: pixel samples per second
//! of the path tracer on the `cornell` scene (a 64 x 64 crop of the camera's view at 4
//! samples per pixel, so that one iteration takes a fraction of a second), and of the
//! `cornell-diffuse` scene. The book's speed-against-error table (`figures/render_speed.md`)
//! comes from `cargo run --release`, which renders the full 256 x 256 image.
//!
//! Run with `cargo bench --bench render`.

use std::path::Path;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use raylemma::render::{Progress, load, render};

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

criterion_group!(benches, scenes);
criterion_main!(benches);
