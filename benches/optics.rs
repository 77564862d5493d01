//! Criterion benchmark of the chapters *Reflection and refraction* and *Fresnel and
//! Schlick*: ns per call of `reflect` and `refract`, and ns per reflectance of the exact
//! Fresnel formula, Schlick's approximation and the Chebyshev fit, entering and leaving
//! glass, over the same 4096 cosines that `cargo run --release` times for the book
//! (`raylemma::workload::timing_cosines`).
//!
//! Run with `cargo bench -p raylemma-bench --bench optics`.

use raylemma::sampling::sphere::sphere_uniform;
use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec3;
use raylemma::optics::fresnel::{FresnelFit, fresnel_dielectric, schlick, schlick_seed};
use raylemma::optics::reflect::{Refraction, reflect, refract};
use raylemma::rng;
use raylemma::workload::timing_cosines;

/// One method over the batch; generic so that it is inlined (no indirect call).
fn bench_one(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    id: String,
    cosines: &[f64],
    f: impl Fn(f64) -> f64,
) {
    group.bench_function(id, |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for &x in cosines {
                sum += f(black_box(x));
            }
            sum
        });
    });
}

fn fresnel(c: &mut Criterion) {
    let cosines = timing_cosines(4096);
    let mut group = c.benchmark_group("fresnel");
    group.throughput(Throughput::Elements(cosines.len() as u64));
    for (side, n1, n2) in [("entering", 1.0, 1.5), ("leaving", 1.5, 1.0)] {
        let fit = FresnelFit::new(n1, n2);
        let id = |name: &str| format!("{name}/{side}");
        bench_one(&mut group, id("exact"), &cosines, |x| {
            fresnel_dielectric(x, n1, n2)
        });
        bench_one(&mut group, id("schlick"), &cosines, |x| schlick(x, n1, n2));
        bench_one(&mut group, id("chebyshev8"), &cosines, |x| fit.eval(x));
        bench_one(&mut group, id("seed_schlick"), &cosines, |x| {
            schlick_seed(x, n1, n2)
        });
    }
    group.finish();
}

fn directions(c: &mut Criterion) {
    let mut rng = rng::seeded(0xd1);
    let pairs: Vec<(DVec3, DVec3)> = (0..4096)
        .map(|_| (sphere_uniform(&mut rng), sphere_uniform(&mut rng)))
        .collect();
    let mut group = c.benchmark_group("directions");
    group.throughput(Throughput::Elements(pairs.len() as u64));
    group.bench_function("reflect", |b| {
        b.iter(|| {
            let mut sum = DVec3::ZERO;
            for &(w, n) in &pairs {
                sum += reflect(black_box(w), black_box(n));
            }
            sum
        });
    });
    group.bench_function("refract/glass", |b| {
        b.iter(|| {
            let mut sum = DVec3::ZERO;
            for &(w, n) in &pairs {
                if let Refraction::Transmitted(w_t) = refract(black_box(w), black_box(n), 1.0, 1.5)
                {
                    sum += w_t;
                }
            }
            sum
        });
    });
    group.finish();
}

criterion_group!(benches, fresnel, directions);
criterion_main!(benches);
