//! Criterion benchmark of the chapter *Wavelength sampling and hero wavelengths*: ns to
//! generate the lanes of one path per strategy, on the same uniform numbers that
//! `cargo run --release -- figures` times for the book (`figures/wavelength_speed.md`).
//!
//! Run with `cargo bench -p raylemma-bench --bench wavelength`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use raylemma::spectral::wavelength::WavelengthStrategy;
use raylemma::workload::uniform_inputs;

fn lanes(c: &mut Criterion) {
    let us = uniform_inputs(4096);
    let mut group = c.benchmark_group("wavelength_lanes");
    group.throughput(Throughput::Elements(us.len() as u64));
    for s in WavelengthStrategy::ALL {
        group.bench_with_input(BenchmarkId::from_parameter(s.name()), &us, |b, us| {
            b.iter(|| {
                let mut acc = 0.0;
                for &u in us {
                    let w = s.sample(black_box(u));
                    acc += w.lambda[3] + w.pdf[0];
                }
                acc
            });
        });
    }
    group.finish();
}

criterion_group!(benches, lanes);
criterion_main!(benches);
