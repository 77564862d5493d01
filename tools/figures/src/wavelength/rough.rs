//! The rough dispersive toy (`wavelength_dispersive_mis.md`), of the chapter *Wavelength
//! sampling and hero wavelengths*: what a rough dispersive vertex does with the secondary
//! lanes (termination, the hero's path pdf, Wilkie et al.'s weights). The toy of
//! `tests/book/spectral/wavelength.rs` (anchor `rough`), with the same random numbers, here
//! timed too: each choice evaluates only what it needs.

use std::fmt::Write as _;
use std::hint::black_box;

use anyhow::Context;
use glam::DVec3;

use super::measure::interleaved_ns;
use crate::{Record, Settings, timing};
use raylemma::rng;
use raylemma::spectral::cie;
use raylemma::spectral::spectrum::Table;
use raylemma::spectral::spectrum::builtin;
use raylemma::spectral::wavelength::{N, Wavelengths, hero_uniform};
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN};
use raylemma::stats::ttest::Summary;

/// What a rough dispersive vertex does with the secondary lanes.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Secondaries {
    /// Terminate them, as at a delta event.
    Terminate,
    /// Keep them, each lane's throughput divided by the hero's path density.
    HeroPathPdf,
    /// Keep them, with Wilkie et al.'s balance heuristic over which lane was the hero.
    Wilkie,
}

impl Secondaries {
    const ALL: [Secondaries; 3] = [
        Secondaries::Terminate,
        Secondaries::HeroPathPdf,
        Secondaries::Wilkie,
    ];

    fn name(self) -> &'static str {
        match self {
            Secondaries::Terminate => "terminate",
            Secondaries::HeroPathPdf => "hero's path pdf for every lane",
            Secondaries::Wilkie => "Wilkie's weights",
        }
    }

    fn key(self) -> &'static str {
        match self {
            Secondaries::Terminate => "terminate",
            Secondaries::HeroPathPdf => "hero_pdf",
            Secondaries::Wilkie => "wilkie",
        }
    }
}

/// The refraction angle into N-BK7 of light arriving at 60°, radians.
fn refracted(nm: f64) -> f64 {
    let n = raylemma::optics::dispersion::material(raylemma::optics::dispersion::N_BK7).index(nm);
    (60f64.to_radians().sin() / n).asin()
}

/// The normal density of `x` with mean `m` and standard deviation `s`.
fn gauss(x: f64, m: f64, s: f64) -> f64 {
    (-0.5 * ((x - m) / s).powi(2)).exp() / (s * (2.0 * std::f64::consts::PI).sqrt())
}

/// The standard normal distribution function, from the χ² tail with one degree of freedom
/// (`P(χ²₁ > x²) = erfc(|x|/√2)`).
fn normal_cdf(x: f64) -> f64 {
    let tail = 0.5 * raylemma::stats::chi2::upper_tail(x * x, 1);
    if x < 0.0 { tail } else { 1.0 - tail }
}

/// The toy's estimate of `X + Y + Z` for uniform hero lanes at `u` and the direction
/// `θ = θ_t(λ_0) + σ z`: the light (D65) is seen in the directions refracted for 450-650 nm,
/// and lane `j`'s throughput is `D65(λ_j) g(θ; θ_t(λ_j), σ) / g(θ; θ_t(λ_0), σ)`.
fn rough_path(u: f64, z: f64, sigma: f64, how: Secondaries, d65: &Table, seen: (f64, f64)) -> f64 {
    let mut w: Wavelengths = hero_uniform(u);
    let theta = refracted(w.lambda[0]) + sigma * z;
    if !(seen.0..=seen.1).contains(&theta) {
        return 0.0;
    }
    let xyz = if how == Secondaries::Terminate {
        // Only the hero is left, and its lobe cancels its own path density.
        w.terminate_secondary();
        w.xyz(|l| d65.eval(l))
    } else {
        // p(θ | λ_k) for every lane: also the lane's lobe in its throughput.
        let lobe = w.lambda.map(|l| gauss(theta, refracted(l), sigma));
        let hero = lobe[0];
        if how == Secondaries::Wilkie {
            w.balance_path_pdfs(lobe);
        }
        let k = 1.0 / cie::y_integral();
        let mut sum = DVec3::ZERO;
        for ((&l, &p), &g) in w.lambda.iter().zip(&w.pdf).zip(&lobe) {
            if p > 0.0 {
                sum += d65.eval(l) * g / hero * k * cie::cmf(l) / p;
            }
        }
        sum / N as f64
    };
    xyz.element_sum()
}

/// The exact pixel of the toy: quadrature over λ of D65 times the lobe's mass in the window.
fn rough_exact(sigma: f64, d65: &Table, seen: (f64, f64)) -> f64 {
    cie::xyz(|l| {
        let t = refracted(l);
        d65.eval(l) * (normal_cdf((seen.1 - t) / sigma) - normal_cdf((seen.0 - t) / sigma))
    })
    .element_sum()
}

/// One cell group of the dispersive table: one choice at one lobe width.
#[derive(Clone, Copy, Debug, Default)]
struct Cell {
    /// Variance of one path's X + Y + Z over the exact value squared.
    variance: f64,
    /// The sample mean over the exact value.
    mean: f64,
    /// ns per path.
    ns: f64,
    /// (variance × ns) of terminate over that of this choice.
    efficiency: f64,
}

/// The lobe widths of the table, in units of the spread of the refraction angles.
const LOBE_RATIOS: [f64; 6] = [0.01, 0.1, 0.3, 1.0, 3.0, 10.0];

/// A lobe width as a value name: `0.3` -> `s0_3`.
fn ratio_key(ratio: f64) -> String {
    format!("s{ratio}").replace('.', "_")
}

pub(super) fn dispersive_mis_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (n, reps) = if settings.quick {
        (20_000, 5)
    } else {
        (200_000, 51)
    };
    let d65 = builtin("cie_illuminant_D65.csv");
    let seen = (refracted(450.0), refracted(650.0));
    let spread = refracted(LAMBDA_MAX) - refracted(LAMBDA_MIN);
    r.number("spread_deg", spread.to_degrees(), ".1");
    // The random numbers of the test (seed 16): u for the lanes, then z for the direction.
    let mut g = rng::seeded(16);
    let draws: Vec<(f64, f64)> = (0..n)
        .map(|_| {
            let u = rng::uniform(&mut g, 0.0, 1.0);
            (u, raylemma::rng::standard_normal(&mut g))
        })
        .collect();
    let batch = &draws[..2000.min(n)];
    let mut md = String::new();
    write!(md, "| σ / Δθ |")?;
    for how in Secondaries::ALL {
        write!(
            md,
            " {}: relative variance | mean / exact | ns per path | efficiency |",
            how.name()
        )?;
    }
    writeln!(md)?;
    writeln!(
        md,
        "|---:|{}",
        "---:|---:|---:|---:|".repeat(Secondaries::ALL.len())
    )?;
    // Per lobe width: (variance, ns, efficiency) of each choice.
    let mut rows = Vec::new();
    for ratio in LOBE_RATIOS {
        let sigma = ratio * spread;
        let exact = rough_exact(sigma, &d65, seen);
        let d65 = &d65;
        let mut batches: Vec<Box<dyn FnMut() -> u64 + '_>> = Secondaries::ALL
            .iter()
            .map(|&how| {
                Box::new(move || {
                    let mut acc = 0.0;
                    for &(u, z) in batch {
                        acc += rough_path(black_box(u), z, sigma, how, d65, seen);
                    }
                    acc.to_bits()
                }) as Box<dyn FnMut() -> u64 + '_>
            })
            .collect();
        let ns = interleaved_ns(batch.len(), reps, &mut batches);
        let mut cells = [Cell::default(); 3];
        for (k, how) in Secondaries::ALL.into_iter().enumerate() {
            let s = Summary::of(
                draws
                    .iter()
                    .map(|&(u, z)| rough_path(u, z, sigma, how, d65, seen)),
            );
            cells[k] = Cell {
                variance: s.variance() / (exact * exact),
                mean: s.mean / exact,
                ns: ns[k],
                efficiency: 0.0,
            };
        }
        let base = cells[0].variance * cells[0].ns;
        for c in &mut cells {
            c.efficiency = base / (c.variance * c.ns);
        }
        write!(md, "| {ratio} |")?;
        for (how, c) in Secondaries::ALL.iter().zip(cells) {
            let key = format!("{}.{}", ratio_key(ratio), how.key());
            write!(
                md,
                " {} | {} | {} | {} |",
                r.number(&format!("{key}.relative_variance"), c.variance, "s4"),
                r.number(&format!("{key}.mean_over_exact"), c.mean, ".3"),
                r.number(&format!("{key}.ns"), c.ns, "s3"),
                r.number(&format!("{key}.efficiency"), c.efficiency, "s3"),
            )?;
        }
        writeln!(md)?;
        rows.push((ratio, cells));
    }
    let (terminate, hero_pdf, wilkie) = (0, 1, 2);
    let row = |ratio: f64| {
        rows.iter()
            .find(|(x, _)| *x == ratio)
            .map(|(_, row)| *row)
            .with_context(|| format!("no row σ/Δθ = {ratio}"))
    };
    let (narrow, wide) = (row(0.01)?, row(10.0)?);
    let (at_0_1, at_0_3) = (row(0.1)?, row(0.3)?);
    let between = [at_0_1, at_0_3];
    // The limits: with narrow lobes Wilkie's weights do what termination does, with wide ones
    // what the hero's path pdf does (variances within 2 %); in between Wilkie's variance is
    // more than 10 % below both.
    r.claim(
        "narrow_lobe_wilkie_is_termination",
        (narrow[wilkie].variance / narrow[terminate].variance - 1.0).abs() <= 0.02,
        format!(
            "σ/Δθ = 0.01: relative variance, Wilkie {:.4} within 2 % of terminate {:.4}",
            narrow[wilkie].variance, narrow[terminate].variance
        ),
    );
    r.claim(
        "wide_lobe_wilkie_is_hero_pdf",
        (wide[wilkie].variance / wide[hero_pdf].variance - 1.0).abs() <= 0.02,
        format!(
            "σ/Δθ = 10: relative variance, Wilkie {:.4} within 2 % of the hero's path pdf {:.4}",
            wide[wilkie].variance, wide[hero_pdf].variance
        ),
    );
    r.claim(
        "wilkie_variance_lowest_in_between",
        between.iter().all(|c| {
            c[wilkie].variance < 0.9 * c[terminate].variance
                && c[wilkie].variance < 0.9 * c[hero_pdf].variance
        }),
        format!(
            "σ/Δθ = 0.1 and 0.3: relative variance, Wilkie below 0.9 × terminate and 0.9 × the hero's path pdf: {}",
            between
                .iter()
                .map(|c| format!(
                    "{:.4} vs {:.4} and {:.4}",
                    c[wilkie].variance, c[terminate].variance, c[hero_pdf].variance
                ))
                .collect::<Vec<_>>()
                .join("; ")
        ),
    );
    // With the narrowest lobes the hero's path pdf makes fireflies too rare for the sample
    // to contain one: its sample mean is far below the exact value (each lane other than the
    // hero almost always adds nothing), so its variance and efficiency in that row mean
    // nothing.
    r.claim(
        "hero_pdf_sample_misses_its_fireflies_narrow",
        narrow[hero_pdf].mean < 0.5,
        format!(
            "σ/Δθ = 0.01: the hero's path pdf, sample mean / exact {:.4} < 0.5",
            narrow[hero_pdf].mean
        ),
    );
    // Efficiency, which also counts the time per path. Against the hero's path pdf, which
    // evaluates the same lobes, Wilkie's weights win where they help. Against termination,
    // which evaluates one lane, they cost more than 1.5 times the time per path in this toy
    // (whose one vertex is the whole path): termination stays the more efficient at
    // σ/Δθ = 0.1, and at 0.3 the two are within a factor of 2.
    let show = |pick: usize| {
        between
            .iter()
            .map(|c| format!("{:.3}", c[pick].efficiency))
            .collect::<Vec<_>>()
            .join(", ")
    };
    r.claim(
        "wilkie_beats_hero_pdf_in_between",
        between
            .iter()
            .all(|c| c[wilkie].efficiency > c[hero_pdf].efficiency),
        format!(
            "σ/Δθ = 0.1, 0.3: efficiency relative to terminate, Wilkie {} > the hero's path pdf {}",
            show(wilkie),
            show(hero_pdf)
        ),
    );
    let time_ratio: Vec<f64> = between
        .iter()
        .map(|c| c[wilkie].ns / c[terminate].ns)
        .collect();
    r.number("s0_1.wilkie_over_terminate_ns", time_ratio[0], "s2");
    r.number("s0_3.wilkie_over_terminate_ns", time_ratio[1], "s2");
    r.claim(
        "wilkie_costs_more_than_terminate_in_between",
        time_ratio.iter().all(|&x| x > 1.5),
        format!(
            "σ/Δθ = 0.1, 0.3: ns per path, Wilkie over terminate, each > 1.5: {:.2}, {:.2}",
            time_ratio[0], time_ratio[1]
        ),
    );
    r.claim(
        "terminate_more_efficient_at_0_1",
        at_0_1[wilkie].efficiency < 1.0,
        format!(
            "σ/Δθ = 0.1: Wilkie's efficiency relative to terminate {:.3} < 1",
            at_0_1[wilkie].efficiency
        ),
    );
    r.claim(
        "wilkie_within_factor_2_of_terminate_at_0_3",
        (0.5..2.0).contains(&at_0_3[wilkie].efficiency),
        format!(
            "σ/Δθ = 0.3: 0.5 <= Wilkie's efficiency relative to terminate {:.3} < 2",
            at_0_3[wilkie].efficiency
        ),
    );
    writeln!(
        md,
        "\n*The toy of `tests/book/spectral/wavelength.rs` (anchor `rough`): light at 60° refracts \
         into N-BK7 at θ_t(λ), a lobe of width σ spreads it, and D65 is seen in the directions \
         refracted for 450–650 nm; Δθ = θ_t(830) − θ_t(360) = {:.2}°. Uniform hero lanes, {N} \
         per path; {n} paths per cell with the same random numbers for every choice (seed 16, \
         as the test). Relative variance: of one path's X + Y + Z, over the exact value squared. \
         Mean / exact: the sample mean over the exact value (far from 1, the sample has \
         not seen the estimator's rare large values, and its variance means nothing). ns per \
         path: the lanes and this one vertex, each choice evaluating only what it needs \
         (terminate: the hero's refraction; the other two: every lane's refraction and lobe); \
         {}, median of {reps} batches of {} paths, the three choices timed in turn{}. \
         Efficiency: (variance × ns) of terminate over (variance × ns) of the choice.*",
        spread.to_degrees(),
        timing::machine(),
        batch.len(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
