//! A small timing harness for the speed tables the book prints.
//!
//! `cargo bench` (criterion, `benches/`) gives the careful measurement; this harness
//! gives the same quantity quickly so that `cargo run --release` can regenerate the book's
//! tables on the reader's own machine. It reports the median over repeated batches,
//! which is robust to the occasional interrupted batch.

use std::hint::black_box;
use std::time::Instant;

/// Median nanoseconds per item of `batch`, which processes `items` items per call.
/// Runs a warm-up call, then `reps` timed calls.
pub fn median_ns_per_item(items: usize, reps: usize, mut batch: impl FnMut() -> u64) -> f64 {
    black_box(batch());
    let mut times: Vec<f64> = (0..reps.max(1))
        .map(|_| {
            let start = Instant::now();
            black_box(batch());
            start.elapsed().as_secs_f64() * 1e9 / items as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// A one-line description of the machine, for the caption of a speed table.
pub fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| std::env::consts::ARCH.to_string());
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!("{cpu}, {cores} cores, single thread")
}

/// Median nanoseconds per call of `f` over `inputs` (see [`median_ns_per_item`]); the
/// results are summed so that the optimiser cannot drop the calls.
pub fn median_ns_per_input(inputs: &[f64], reps: usize, f: impl Fn(f64) -> f64) -> f64 {
    median_ns_per_item(inputs.len(), reps, || {
        let mut acc = 0.0;
        for &u in inputs {
            acc += f(black_box(u));
        }
        acc.to_bits()
    })
}

/// The caption's warning for tables timed in quick mode.
pub fn quick_note(quick: bool) -> &'static str {
    if quick { " (quick mode: noisy)" } else { "" }
}
