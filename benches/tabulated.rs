//! Criterion benchmark of the chapters *Tabulated distributions* and *Tangent frames*:
//! ns per sample of the piecewise-constant and piecewise-linear tables at 16, 256, 4096
//! and 65536 bins, and ns per frame of Duff et al.'s and Frisvad's constructions, on the
//! same inputs that `cargo run --release` times for the book
//! (`figures/tabulated_speed.md`, `figures/frame_speed.md`).
//!
//! Run with `cargo bench -p raylemma-bench --bench tabulated`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use raylemma::sampling::frame::{Frame, frisvad};
use raylemma::workload::{TIMING_BINS, timing_normals, timing_tables, uniform_inputs};

fn tabulated(c: &mut Criterion) {
    let us = uniform_inputs(4096);
    let mut group = c.benchmark_group("tabulated");
    group.throughput(Throughput::Elements(us.len() as u64));
    for bins in TIMING_BINS {
        let (constant, linear) = timing_tables(bins);
        group.bench_with_input(BenchmarkId::new("constant", bins), &us, |b, us| {
            b.iter(|| {
                let mut acc = 0.0;
                for &u in us {
                    acc += constant.sample(black_box(u)).x;
                }
                acc
            });
        });
        group.bench_with_input(BenchmarkId::new("linear", bins), &us, |b, us| {
            b.iter(|| {
                let mut acc = 0.0;
                for &u in us {
                    acc += linear.sample(black_box(u)).x;
                }
                acc
            });
        });
    }
    group.finish();
}

fn frames(c: &mut Criterion) {
    let normals = timing_normals(4096);
    let mut out = vec![0.0; normals.len()];
    let mut group = c.benchmark_group("frame");
    group.throughput(Throughput::Elements(normals.len() as u64));
    group.bench_function("duff/f64", |b| {
        b.iter(|| {
            for (o, &n) in out.iter_mut().zip(&normals) {
                let f = Frame::from_normal(black_box(n));
                *o = f.t.x + f.b.y;
            }
            black_box(&out);
        });
    });
    group.bench_function("frisvad/f64", |b| {
        b.iter(|| {
            for (o, &n) in out.iter_mut().zip(&normals) {
                let (t, bt) = frisvad(black_box(n));
                *o = t.x + bt.y;
            }
            black_box(&out);
        });
    });
    group.finish();
}

criterion_group!(benches, tabulated, frames);
criterion_main!(benches);
