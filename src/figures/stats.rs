//! Figures and tables of the chapter *Statistical tests*: are the tests calibrated?
//!
//! A test is calibrated when, with the null hypothesis true, its p-value is uniform on
//! `[0, 1]`: then it rejects at level `a` with probability exactly `a`. Each experiment
//! here draws data for which the null is true by construction, many times with different
//! seeds, and collects the p-values; the figure shows their histograms and the table the
//! observed rejection rates.

use std::fmt::Write as _;
use std::sync::OnceLock;

use rayon::prelude::*;

use super::{Output, Settings};
use crate::plot::{self, BoxError};
use crate::rng::{self, Rng};
use crate::stats::{StatsError, chi2, ks, test_alpha, ttest};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "stats_pvalues.png",
            what: "p-values under the null",
            make: pvalues_png,
        },
        Output {
            file: "stats_calibration.md",
            what: "false-failure rates",
            make: calibration_md,
        },
    ]
}

/// A standard normal deviate by the Box–Muller transform (two uniforms, one deviate;
/// `1 - u` keeps the logarithm finite).
pub fn standard_normal(rng: &mut Rng) -> f64 {
    let u = 1.0 - rng::uniform(rng, 0.0, 1.0);
    let v = rng::uniform(rng, 0.0, 1.0);
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// One experiment in which the null hypothesis of a test is true by construction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NullCase {
    /// Pearson's chi-squared: 1000 draws into 16 cells of geometric probabilities
    /// `∝ 0.7^i` (the sparsest cells are pooled), against their exact expectations.
    Chi2,
    /// One-sample KS, exact p-value: 100 uniform samples against the uniform CDF.
    KsExact,
    /// One-sample KS, asymptotic p-value: 5000 exponential samples against the
    /// exponential CDF.
    KsAsymptotic,
    /// Two-sample KS: 200 and 301 standard normal samples.
    KsTwoSample,
    /// Student's one-sample t-test: 10 standard normal samples against mean 0.
    StudentT,
    /// Welch's t-test: 10 and 40 standard normal samples.
    Welch,
}

/// Every experiment, in the order of the figure and the table.
pub const NULL_CASES: [NullCase; 6] = [
    NullCase::Chi2,
    NullCase::KsExact,
    NullCase::KsAsymptotic,
    NullCase::KsTwoSample,
    NullCase::StudentT,
    NullCase::Welch,
];

/// Cells and draws of the [`NullCase::Chi2`] experiment.
const CHI2_CELLS: usize = 16;
const CHI2_DRAWS: u64 = 1000;

impl NullCase {
    /// Short name of the test.
    pub fn test(self) -> &'static str {
        match self {
            Self::Chi2 => "Pearson χ²",
            Self::KsExact => "KS, exact p",
            Self::KsAsymptotic => "KS, asymptotic p",
            Self::KsTwoSample => "KS, two samples",
            Self::StudentT => "Student t",
            Self::Welch => "Welch t",
        }
    }

    /// The experiment, in words.
    pub fn experiment(self) -> &'static str {
        match self {
            Self::Chi2 => "1000 draws into 16 cells with P ∝ 0.7^i, against N·P",
            Self::KsExact => "100 uniform samples against the uniform CDF",
            Self::KsAsymptotic => "5000 exponential samples against the exponential CDF",
            Self::KsTwoSample => "200 against 301 normal samples",
            Self::StudentT => "mean of 10 normal samples against 0",
            Self::Welch => "mean of 10 against mean of 40 normal samples",
        }
    }

    fn index(self) -> u64 {
        NULL_CASES.iter().position(|&c| c == self).unwrap_or(0) as u64
    }

    /// The p-value of one run of the experiment, with its own seed.
    ///
    /// # Errors
    /// Only if a test rejects its input, which for these well-formed inputs is a bug.
    pub fn p_value(self, seed: u64) -> Result<f64, StatsError> {
        let mut rng = rng::seeded(0x5747_0000_0000 + (self.index() << 32) + seed);
        let normals = |rng: &mut Rng, n: usize| -> Vec<f64> {
            (0..n).map(|_| standard_normal(rng)).collect()
        };
        Ok(match self {
            Self::Chi2 => {
                let (observed, expected) = geometric_counts(&mut rng);
                chi2::pearson(&observed, &expected, 5.0)?.p_value
            }
            Self::KsExact => {
                let xs: Vec<f64> = (0..100).map(|_| rng::uniform(&mut rng, 0.0, 1.0)).collect();
                ks::one_sample(&xs, |x| x.clamp(0.0, 1.0))?.p_value
            }
            Self::KsAsymptotic => {
                let xs: Vec<f64> = (0..5000)
                    .map(|_| -(1.0 - rng::uniform(&mut rng, 0.0, 1.0)).ln())
                    .collect();
                ks::one_sample(&xs, |x| -(-x.max(0.0)).exp_m1())?.p_value
            }
            Self::KsTwoSample => {
                let a = normals(&mut rng, 200);
                let b = normals(&mut rng, 301);
                ks::two_sample(&a, &b)?.p_value
            }
            Self::StudentT => {
                let s = ttest::Summary::of(normals(&mut rng, 10));
                ttest::one_sample(&s, 0.0)?.p_value
            }
            Self::Welch => {
                let a = ttest::Summary::of(normals(&mut rng, 10));
                let b = ttest::Summary::of(normals(&mut rng, 40));
                ttest::welch(&a, &b)?.p_value
            }
        })
    }

    /// The p-values of runs `0..runs`, in parallel.
    ///
    /// # Errors
    /// As [`NullCase::p_value`].
    pub fn p_values(self, runs: u64) -> Result<Vec<f64>, StatsError> {
        (0..runs).into_par_iter().map(|s| self.p_value(s)).collect()
    }
}

/// Counts of [`NullCase::Chi2`]: `CHI2_DRAWS` draws by inversion into cells with
/// probabilities `∝ 0.7^i`, and the expected counts `N P_i`.
fn geometric_counts(rng: &mut Rng) -> (Vec<u64>, Vec<f64>) {
    let weights: Vec<f64> = (0..CHI2_CELLS).map(|i| 0.7f64.powi(i as i32)).collect();
    let total: f64 = weights.iter().sum();
    let mut cumulative = Vec::with_capacity(CHI2_CELLS);
    let mut acc = 0.0;
    for w in &weights {
        acc += w / total;
        cumulative.push(acc);
    }
    let mut observed = vec![0u64; CHI2_CELLS];
    for _ in 0..CHI2_DRAWS {
        let u = rng::uniform(rng, 0.0, 1.0);
        let cell = cumulative.partition_point(|&c| c <= u).min(CHI2_CELLS - 1);
        observed[cell] += 1;
    }
    let expected = weights
        .iter()
        .map(|w| CHI2_DRAWS as f64 * w / total)
        .collect();
    (observed, expected)
}

/// The p-values of every experiment.
struct Calibration {
    runs: u64,
    p_values: Vec<(NullCase, Vec<f64>)>,
}

fn calibration(settings: &Settings) -> Result<&'static Calibration, BoxError> {
    static FULL: OnceLock<Calibration> = OnceLock::new();
    static QUICK: OnceLock<Calibration> = OnceLock::new();
    let (cell, runs) = if settings.quick {
        (&QUICK, 200)
    } else {
        (&FULL, 20_000)
    };
    if let Some(c) = cell.get() {
        return Ok(c);
    }
    let p_values = NULL_CASES
        .iter()
        .map(|&case| case.p_values(runs).map(|p| (case, p)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(cell.get_or_init(|| Calibration { runs, p_values }))
}

const BINS: usize = 20;

fn pvalues_png(settings: &Settings) -> Result<Vec<u8>, BoxError> {
    use plotters::prelude::*;
    let cal = calibration(settings)?;
    let (width, height) = (1200u32, 720u32);
    plot::register_embedded_font();
    let mut buffer = vec![255u8; (width * height * 3) as usize];
    // Under the null each bin holds Binomial(runs, 1/BINS) p-values: density 1 ± 2 sd.
    let share = 1.0 / BINS as f64;
    let sd = (share * (1.0 - share) / cal.runs as f64).sqrt() / share;
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (width, height)).into_drawing_area();
        root.fill(&WHITE)?;
        let root = root.titled(
            &format!(
                "p-values under a true null hypothesis, {} runs each (uniform if calibrated)",
                cal.runs
            ),
            ("sans-serif", 20),
        )?;
        for ((case, ps), area) in cal.p_values.iter().zip(root.split_evenly((2, 3)).iter()) {
            let mut counts = [0usize; BINS];
            for &p in ps {
                counts[((p * BINS as f64) as usize).min(BINS - 1)] += 1;
            }
            let density = |c: usize| c as f64 / (ps.len() as f64 * share);
            let top = counts
                .iter()
                .map(|&c| density(c))
                .fold(1.0 + 3.0 * sd, f64::max)
                * 1.1;
            let mut chart = ChartBuilder::on(area)
                .caption(case.test(), ("sans-serif", 17))
                .margin(10)
                .x_label_area_size(36)
                .y_label_area_size(46)
                .build_cartesian_2d(0f64..1f64, 0f64..top)?;
            chart
                .configure_mesh()
                .disable_x_mesh()
                .light_line_style(TRANSPARENT)
                .x_desc("p-value")
                .y_desc("density")
                .label_style(("sans-serif", 12))
                .axis_desc_style(("sans-serif", 13))
                .x_label_formatter(&|v| plot::format_tick(*v))
                .y_label_formatter(&|v| plot::format_tick(*v))
                .draw()?;
            let RGBColor(r, g, b) = plot::PALETTE[0];
            let light = |c: u8| ((u16::from(c) + 2 * 255) / 3) as u8;
            let fill = RGBColor(light(r), light(g), light(b));
            for style in [fill.filled(), plot::PALETTE[0].stroke_width(1)] {
                chart.draw_series(counts.iter().enumerate().map(|(i, &c)| {
                    let x0 = i as f64 * share;
                    Rectangle::new([(x0, 0.0), (x0 + share, density(c))], style)
                }))?;
            }
            for (y, style) in [
                (1.0, BLACK.stroke_width(2)),
                (1.0 - 2.0 * sd, plot::PALETTE[1].stroke_width(1)),
                (1.0 + 2.0 * sd, plot::PALETTE[1].stroke_width(1)),
            ] {
                chart.draw_series(DashedLineSeries::new(vec![(0.0, y), (1.0, y)], 6, 4, style))?;
            }
        }
        root.present()?;
    }
    plot::encode_png(width, height, buffer)
}

fn percent(rejected: usize, runs: u64) -> String {
    format!(
        "{:.2} % ({rejected})",
        100.0 * rejected as f64 / runs as f64
    )
}

fn calibration_md(settings: &Settings) -> Result<Vec<u8>, BoxError> {
    let cal = calibration(settings)?;
    let alpha = test_alpha();
    let mut md = String::new();
    writeln!(
        md,
        "| test | experiment (null true) | runs | rejected at 0.05 | at 0.01 | at test_alpha() = {alpha:.3e} | KS of the p-values against uniform: D | its p-value |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|")?;
    for (case, ps) in &cal.p_values {
        let rejected = |a: f64| ps.iter().filter(|&&p| p < a).count();
        let uniformity = ks::one_sample(ps, |x| x.clamp(0.0, 1.0))?;
        writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {:.4} | {:.3} |",
            case.test(),
            case.experiment(),
            cal.runs,
            percent(rejected(0.05), cal.runs),
            percent(rejected(0.01), cal.runs),
            percent(rejected(alpha), cal.runs),
            uniformity.statistic,
            uniformity.p_value,
        )?;
    }
    let runs = cal.runs as f64;
    writeln!(
        md,
        "\n*A calibrated test rejects a fraction α of the runs, give or take the binomial standard error √(α(1−α)/runs): {:.2} % at 0.05 and {:.2} % at 0.01 for {} runs; at test_alpha() it expects {:.2} false failures in all. Generated by `cargo run --release` (`src/figures/stats.rs`).*",
        100.0 * (0.05f64 * 0.95 / runs).sqrt(),
        100.0 * (0.01f64 * 0.99 / runs).sqrt(),
        cal.runs,
        alpha * runs,
    )?;
    Ok(md.into_bytes())
}
