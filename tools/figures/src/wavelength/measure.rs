//! Measuring a wavelength strategy, for the chapter *Wavelength sampling and hero
//! wavelengths*: one path's XYZ estimate, its relative error and variance, and its time per
//! path (the strategies' batches interleaved, so that their ratios are steady).

use std::hint::black_box;

use glam::DVec3;

use crate::timing;
use raylemma::rng;
use raylemma::spectral::spectrum::Spectrum;
use raylemma::spectral::wavelength::WavelengthStrategy;
use raylemma::stats::ttest::Summary;

/// The XYZ estimate of one path.
pub(super) fn path_xyz(s: WavelengthStrategy, u: f64, spectrum: &Spectrum) -> DVec3 {
    s.sample(u).xyz(|l| spectrum.eval(l))
}

/// The mean over X, Y, Z of the squared relative error of `est`.
pub(super) fn relative_sq(est: DVec3, exact: DVec3) -> f64 {
    ((est / exact - DVec3::ONE).powf(2.0)).element_sum() / 3.0
}

/// Median nanoseconds per item of each of `batches` (each processing `items` items per
/// call), timed in turn, one call of each per round, for `reps` rounds after a warm-up
/// call of each. A slow spell of the machine (another process on the core) then slows
/// every batch of the round alike, so the ratios of the medians, which the efficiency
/// tables print, are steadier than those of batches timed one after the other.
pub(super) fn interleaved_ns(
    items: usize,
    reps: usize,
    batches: &mut [Box<dyn FnMut() -> u64 + '_>],
) -> Vec<f64> {
    for batch in batches.iter_mut() {
        black_box(batch());
    }
    let mut times = vec![Vec::with_capacity(reps); batches.len()];
    for _ in 0..reps.max(1) {
        for (batch, t) in batches.iter_mut().zip(&mut times) {
            let start = std::time::Instant::now();
            black_box(batch());
            t.push(start.elapsed().as_secs_f64() * 1e9 / items as f64);
        }
    }
    times
        .into_iter()
        .map(|mut t| {
            t.sort_by(f64::total_cmp);
            t[t.len() / 2]
        })
        .collect()
}

/// ns per path (lanes and XYZ estimate) of every strategy on `spectrum`, interleaved.
pub(super) fn ns_per_path_all(spectrum: &Spectrum, reps: usize) -> Vec<f64> {
    let batch = 2000;
    let mut r = rng::seeded(0x7173);
    let us: Vec<f64> = (0..batch).map(|_| rng::uniform(&mut r, 0.0, 1.0)).collect();
    let us = &us;
    let mut batches: Vec<Box<dyn FnMut() -> u64 + '_>> = WavelengthStrategy::ALL
        .iter()
        .map(|&s| {
            Box::new(move || {
                let mut acc = 0.0;
                for &u in us {
                    acc += path_xyz(s, black_box(u), spectrum).y;
                }
                acc.to_bits()
            }) as Box<dyn FnMut() -> u64 + '_>
        })
        .collect();
    interleaved_ns(batch, reps, &mut batches)
}

/// ns per path (lanes and XYZ estimate) of strategy `s` on `spectrum`.
pub(super) fn ns_per_path(s: WavelengthStrategy, spectrum: &Spectrum, reps: usize) -> f64 {
    let batch = 2000;
    let mut r = rng::seeded(0x7173);
    let us: Vec<f64> = (0..batch).map(|_| rng::uniform(&mut r, 0.0, 1.0)).collect();
    timing::median_ns_per_item(batch, reps, || {
        let mut acc = 0.0;
        for &u in &us {
            acc += path_xyz(s, black_box(u), spectrum).y;
        }
        acc.to_bits()
    })
}

/// Relative variance per path: the mean over X, Y, Z of `Var[est] / exact²`.
pub(super) fn relative_variance(
    s: WavelengthStrategy,
    spectrum: &Spectrum,
    exact: DVec3,
    n: usize,
) -> f64 {
    let mut r = rng::seeded(0x5EED);
    let mut sums = [Summary::default(), Summary::default(), Summary::default()];
    for _ in 0..n {
        let e = path_xyz(s, rng::uniform(&mut r, 0.0, 1.0), spectrum) / exact;
        for (k, sum) in sums.iter_mut().enumerate() {
            sum.push(e[k]);
        }
    }
    sums.iter().map(Summary::variance).sum::<f64>() / 3.0
}
