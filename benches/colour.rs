//! Criterion benchmark of the chapter *Spectra and CIE colour*: ns per colour-matching
//! evaluation by the 1 nm table (`cmf`) and by the Wyman-Sloan-Shirley fit (`cmf_fit`),
//! over 4096 uniform wavelengths, and µs per XYZ of a spectrum (D65, a blackbody) with
//! each.
//!
//! Run with `cargo bench -p raylemma-bench --bench colour`.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec3;
use raylemma::rng;
use raylemma::spectral::cie::{cmf, cmf_fit, xyz, xyz_with};
use raylemma::spectral::spectrum::{builtin, planck};
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN};

fn matching(c: &mut Criterion) {
    let mut r = rng::seeded(0xC0);
    let nms: Vec<f64> = (0..4096)
        .map(|_| rng::uniform(&mut r, LAMBDA_MIN, LAMBDA_MAX))
        .collect();
    let mut group = c.benchmark_group("cmf");
    group.throughput(Throughput::Elements(nms.len() as u64));
    for (name, f) in [("table", cmf as fn(f64) -> DVec3), ("fit", cmf_fit)] {
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut s = DVec3::ZERO;
                for &nm in &nms {
                    s += f(black_box(nm));
                }
                s
            });
        });
    }
    group.finish();
}

fn spectra(c: &mut Criterion) {
    let d65 = builtin("cie_illuminant_D65.csv");
    let mut group = c.benchmark_group("xyz");
    group.bench_function("d65/table", |b| {
        b.iter(|| xyz(|nm| d65.eval(black_box(nm))))
    });
    group.bench_function("d65/fit", |b| {
        b.iter(|| xyz_with(cmf_fit, |nm| d65.eval(black_box(nm))))
    });
    group.bench_function("blackbody_5000K/table", |b| {
        b.iter(|| xyz(|nm| planck(black_box(nm), 5000.0)))
    });
    group.finish();
}

criterion_group!(benches, matching, spectra);
criterion_main!(benches);
