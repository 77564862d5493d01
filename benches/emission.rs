//! Criterion benchmark of the chapter *Importance-sampled emission spectra*: ns per
//! wavelength sample (with its pdf) drawn from each lamp's spectrum, against the uniform
//! proposal, on the same random numbers that `cargo run --release` times for the book
//! (`figures/emission_speed.md`).
//!
//! Run with `cargo bench -p raylemma-bench --bench emission`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use raylemma::spectral::emission::{EmissionSampler, lamps, uniform_wavelength};
use raylemma::workload::uniform_inputs;

fn emission(c: &mut Criterion) {
    let us = uniform_inputs(4096);
    let mut group = c.benchmark_group("emission");
    group.throughput(Throughput::Elements(us.len() as u64));
    for lamp in lamps() {
        let s = EmissionSampler::new(&lamp.spectrum).expect("every lamp emits");
        group.bench_with_input(BenchmarkId::new("importance", lamp.stem), &us, |b, us| {
            b.iter(|| {
                let mut acc = 0.0;
                for &u in us {
                    let w = s.sample(black_box(u));
                    acc += w.nm + w.pdf;
                }
                acc
            });
        });
    }
    group.bench_with_input(BenchmarkId::new("uniform", "any"), &us, |b, us| {
        b.iter(|| {
            let mut acc = 0.0;
            for &u in us {
                let w = uniform_wavelength(black_box(u));
                acc += w.nm + w.pdf;
            }
            acc
        });
    });
    group.finish();
}

criterion_group!(benches, emission);
criterion_main!(benches);
