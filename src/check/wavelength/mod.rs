//! The checker of hero wavelengths drawn uniformly: any routine with the signature of
//! [`crate::spectral::wavelength::hero_uniform`] (`f(u) -> Wavelengths`) can be checked
//! against the claims of the chapter *Wavelength sampling and hero wavelengths*
//! (`chapters/spectral/wavelength.md`).
//!
//! * `range`: every lane lies in 360–830 nm;
//! * `hero`: lane 0 is `λ_min + u (λ_max − λ_min)`;
//! * `spacing`: lane `j` is the hero rotated by `j/N` of the range, modulo the range;
//! * `lanes_uniform`: each lane alone is uniform on the range (Kolmogorov-Smirnov, at the
//!   options' level divided among the lanes);
//! * `pdf`: every lane and the hero are weighted by the uniform density `1 / 470` per nm.
//!
//! Planted bugs that it must reject are in [`planted`].

pub mod planted;

use super::{Finding, Options, Verdict};
use crate::rng;
use crate::spectral::wavelength::{N, Wavelengths};
use crate::spectral::{LAMBDA_MAX, LAMBDA_MIN};
use crate::stats::ks;

/// Default number of draws `u`.
pub const CASES: usize = 20_000;
/// Default seed.
pub const SEED: u64 = 0x4e50;
/// Bound of the exact claims' errors, in units of `f64::EPSILON` times 830 nm.
pub const BOUND: f64 = 8.0;

/// Runs the chapter's claims on `f`; `options` sets the number of draws (default
/// [`CASES`]), their seed (default [`SEED`]) and the level of the uniformity test.
pub fn hero(f: &dyn Fn(f64) -> Wavelengths, options: &Options) -> Verdict {
    let cases = options.cases_or(CASES).max(10);
    let mut rng = rng::seeded(options.seed_or(SEED));
    let range = LAMBDA_MAX - LAMBDA_MIN;
    let unit = f64::EPSILON * LAMBDA_MAX;
    let mut in_range = Finding::new("range", "every lane lies in [360, 830] nm");
    let mut hero =
        Finding::new("hero", "lane 0 = 360 + 470 u nm").in_unit("multiples of eps x 830 nm");
    let mut spacing = Finding::new(
        "spacing",
        "lane j = lane 0 + j/N of the range, modulo the range",
    )
    .in_unit("multiples of eps x 830 nm");
    let mut pdf = Finding::new("pdf", "every lane and the hero weighted by 1/470 per nm")
        .in_unit("relative error in machine epsilons");
    let mut lanes: Vec<Vec<f64>> = (0..N).map(|_| Vec::with_capacity(cases + 3)).collect();
    let mut us: Vec<f64> = (0..cases)
        .map(|_| rng::uniform(&mut rng, 0.0, 1.0))
        .collect();
    us.extend([0.0, 0.5, 1.0 - f64::EPSILON / 2.0]);
    for &u in &us {
        let w = f(u);
        let ok = w
            .lambda
            .iter()
            .all(|l| (LAMBDA_MIN..=LAMBDA_MAX).contains(l));
        in_range.record(ok, || format!("u = {u}: lanes {:?}", w.lambda));
        let want = LAMBDA_MIN + u * range;
        hero.measure((w.lambda[0] - want).abs() / unit, BOUND, || {
            format!("u = {u}: lane 0 = {} nm, want {want} nm", w.lambda[0])
        });
        for j in 1..N {
            let offset = (w.lambda[j] - w.lambda[0]).rem_euclid(range);
            let want = j as f64 * range / N as f64;
            let error = (offset - want).abs().min(range - (offset - want).abs()) / unit;
            spacing.measure(error, BOUND, || {
                format!("u = {u}: lane {j} is {offset} nm after the hero (mod 470), want {want}")
            });
        }
        let uniform = 1.0 / range;
        let worst = w
            .pdf
            .iter()
            .chain([&w.hero_pdf])
            .map(|p| (p / uniform - 1.0).abs())
            .fold(0.0, f64::max);
        pdf.measure(worst / f64::EPSILON, BOUND, || {
            format!(
                "u = {u}: pdfs {:?}, hero {} (want {uniform})",
                w.pdf, w.hero_pdf
            )
        });
        for (lane, l) in lanes.iter_mut().zip(w.lambda) {
            lane.push(l);
        }
    }
    let mut uniform = Finding::new(
        "lanes_uniform",
        "each lane alone is uniform on 360-830 nm (KS)",
    );
    let level = options.level() / N as f64;
    for (j, lane) in lanes.iter().enumerate() {
        let p = ks::one_sample(lane, |x| ((x - LAMBDA_MIN) / range).clamp(0.0, 1.0))
            .map_or(0.0, |k| k.p_value);
        uniform.record(p >= level, || {
            format!("lane {j}: KS p = {p:.3e} over {} draws", lane.len())
        });
    }
    let mut verdict = Verdict::new("hero wavelengths (uniform)");
    verdict
        .findings
        .extend([in_range, hero, spacing, uniform, pdf]);
    verdict
}
