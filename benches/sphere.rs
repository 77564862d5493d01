//! Criterion benchmark of the chapter *Ray-sphere intersection*: ns per intersection for
//! the textbook and the stable form, in f32 and f64, over the same 4096 rays that
//! `cargo run --release` times for the book (`raylemma::workload::timing_rays`).
//!
//! Run with `cargo bench -p raylemma-bench --bench sphere`.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use raylemma::geometry::sphere::{intersect_stable, intersect_textbook};
use raylemma::real::Real;
use raylemma::single::geometry::sphere as single;
use raylemma::workload::timing_rays;

type Intersect<R> = fn(&<R as Real>::Ray, &<R as Real>::Sphere, R) -> Option<R>;

fn bench_form<R: Real>(c: &mut Criterion, name: &str, f: Intersect<R>) {
    let (rays, sphere) = timing_rays::<R>(4096);
    let mut group = c.benchmark_group("sphere");
    group.throughput(Throughput::Elements(rays.len() as u64));
    group.bench_function(format!("{name}/{}", R::NAME), |b| {
        b.iter(|| {
            let mut hits = 0u32;
            for ray in &rays {
                hits += u32::from(f(black_box(ray), black_box(&sphere), R::ZERO).is_some());
            }
            hits
        });
    });
    group.finish();
}

fn sphere(c: &mut Criterion) {
    bench_form::<f32>(c, "textbook", single::intersect_textbook);
    bench_form::<f32>(c, "stable", single::intersect_stable);
    bench_form::<f64>(c, "textbook", intersect_textbook);
    bench_form::<f64>(c, "stable", intersect_stable);
}

criterion_group!(benches, sphere);
criterion_main!(benches);
