//! Criterion benchmark of the sampling chapters: ns per sample for every sphere,
//! hemisphere, disc and cosine method (`cargo bench -p raylemma-bench --bench sampling`). The book's table
//! (`figures/sampling_methods.md`) times the same functions with the quick harness.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::{DVec2, DVec3};
use raylemma::rng::{self, Rng};
use raylemma::sampling::cosine::*;
use raylemma::sampling::disc::*;
use raylemma::sampling::sphere::*;

fn square(rng: &mut Rng) -> DVec2 {
    DVec2::new(rng::uniform(rng, 0.0, 1.0), rng::uniform(rng, 0.0, 1.0))
}

type Method = (&'static str, fn(&mut Rng) -> DVec3);

fn sampling(c: &mut Criterion) {
    let methods: [Method; 9] = [
        ("sphere/inverse_cdf", |r| sphere_inverse_cdf(square(r))),
        ("sphere/gaussian", sphere_gaussian),
        ("sphere/rejection", |r| sphere_rejection(r).0),
        ("hemisphere/flip", |r| {
            hemisphere_flip(sphere_inverse_cdf(square(r)), DVec3::Z)
        }),
        ("disc/polar", |r| disc_polar(square(r))),
        ("disc/concentric", |r| disc_concentric(square(r))),
        ("cosine/seed_angles", |r| cosine_seed_angles(square(r))),
        ("cosine/seed_cartesian", |r| {
            cosine_seed_cartesian(square(r))
        }),
        ("cosine/malley", |r| cosine_malley(square(r))),
    ];
    let mut group = c.benchmark_group("sampling");
    group.throughput(Throughput::Elements(1024));
    for (name, draw) in methods {
        let mut rng = rng::seeded(1);
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut acc = DVec3::ZERO;
                for _ in 0..1024 {
                    acc += draw(black_box(&mut rng));
                }
                acc
            });
        });
    }
    group.finish();
}

criterion_group!(benches, sampling);
criterion_main!(benches);
