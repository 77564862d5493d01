//! Figures and tables of the chapter *Lambertian reflectance*.

use std::fmt::Write as _;
use std::hint::black_box;

use glam::{DVec2, DVec3};

use super::{Output, Record, Settings, timing};
use crate::plot::{self, Panel, Series};
use raylemma::rng;
use raylemma::stats::ttest::{self, Summary};
use raylemma::transport::lambert::*;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "lambert_estimators.md",
            what: "uniform vs cosine estimators: variance per unit time",
            make: estimators_md,
        },
        Output {
            file: "lambert_furnace.md",
            what: "white furnace random walks",
            make: furnace_md,
        },
        Output {
            file: "lambert_sky_variance.svg",
            what: "variance against the sky's exponent",
            make: sky_variance_svg,
        },
    ]
}

const RHO: f64 = 0.7;

fn square_point(r: &mut rng::Rng) -> DVec2 {
    DVec2::new(rng::uniform(r, 0.0, 1.0), rng::uniform(r, 0.0, 1.0))
}

type Estimator = fn(f64, fn(DVec3) -> f64, DVec2) -> f64;
type Bounce = fn(f64, DVec2) -> f64;

/// One environment of the estimators' table, for the claims.
struct Compared {
    env: &'static str,
    uniform_variance: f64,
    cosine_variance: f64,
    /// Cosine's efficiency relative to uniform directions.
    cosine_efficiency: f64,
}

fn estimators_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n = if settings.quick { 100_000 } else { 1_000_000 };
    let reps = if settings.quick { 5 } else { 51 };
    let mut md = String::new();
    writeln!(
        md,
        "| environment | directions | mean | exact | p-value | variance | ns per sample | relative efficiency |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|")?;
    let mut compared: Vec<Compared> = Vec::new();
    for (env_key, env) in [("gradient", GRADIENT), ("sky", SKY)] {
        let exact = RHO * env.reflected_white;
        let strategies: [(&str, &str, Estimator); 2] = [
            ("uniform", "uniform, 2ρL cos", |r, l, u| {
                estimate_uniform(r, l, u)
            }),
            ("cosine", "cosine, ρL", |r, l, u| estimate_cosine(r, l, u)),
        ];
        let mut rows = Vec::new();
        for (key, name, est) in strategies {
            let s = summarize(|u| est(RHO, env.radiance, u), n, &mut rng::seeded(0x1A3));
            let p = ttest::one_sample(&s, exact).map_or(f64::NAN, |t| t.p_value);
            let mut g = rng::seeded(5);
            let batch = 4096;
            let ns = timing::median_ns_per_item(batch, reps, || {
                let mut acc = 0.0;
                for _ in 0..batch {
                    acc += est(RHO, env.radiance, black_box(square_point(&mut g)));
                }
                acc.to_bits()
            });
            rows.push((key, name, s, p, ns, 1.0 / (s.variance() * ns)));
        }
        let base = rows[0].5;
        for &(key, name, s, p, ns, eff) in &rows {
            writeln!(
                md,
                "| {} | {name} | {:.5} | {exact:.5} | {p:.2} | {} | {ns:.1} | {} |",
                env.name,
                s.mean,
                r.number(&format!("{env_key}.{key}.variance"), s.variance(), ".4"),
                r.number(
                    &format!("{env_key}.{key}.relative_efficiency"),
                    eff / base,
                    ".2"
                ),
            )?;
        }
        compared.push(Compared {
            env: env.name,
            uniform_variance: rows[0].2.variance(),
            cosine_variance: rows[1].2.variance(),
            cosine_efficiency: rows[1].5 / base,
        });
    }
    let list =
        |f: &dyn Fn(&Compared) -> String| compared.iter().map(f).collect::<Vec<_>>().join("; ");
    r.claim(
        "cosine_more_efficient_in_both",
        compared.iter().all(|c| c.cosine_efficiency > 1.0),
        format!(
            "cosine's efficiency relative to uniform > 1: {}",
            list(&|c| format!("{} {:.2}", c.env, c.cosine_efficiency))
        ),
    );
    // The lower variance in both environments of the table and at every exponent of the
    // figure `lambert_sky_variance.svg`, by formula and measured.
    let sky = sky_variance_points(settings);
    let higher: Vec<String> = sky
        .iter()
        .filter(|p| !(p.cosine.0 < p.uniform.0 && p.cosine.1 < p.uniform.1))
        .map(|p| {
            format!(
                "k = {}: cosine {:.4}/{:.4} against uniform {:.4}/{:.4}",
                p.k, p.cosine.0, p.cosine.1, p.uniform.0, p.uniform.1
            )
        })
        .collect();
    r.claim(
        "cosine_lower_variance_everywhere",
        compared
            .iter()
            .all(|c| c.cosine_variance < c.uniform_variance)
            && higher.is_empty(),
        format!(
            "cosine's variance < uniform's: {}; the figure's exponents k = {}…{} (formula/measured) where it is not: {}",
            list(&|c| format!(
                "{} {:.4} < {:.4}",
                c.env, c.cosine_variance, c.uniform_variance
            )),
            sky.first().map_or(0, |p| p.k),
            sky.last().map_or(0, |p| p.k),
            if higher.is_empty() {
                "none".to_string()
            } else {
                higher.join(", ")
            }
        ),
    );
    writeln!(
        md,
        "\n*Albedo ρ = {RHO}; {n} one-sample estimates each; p-value of the one-sample t-test against the exact answer; efficiency 1/(variance × time), relative to uniform directions in the same environment. {}.*",
        timing::machine()
    )?;
    Ok(md.into_bytes())
}

/// One row of the furnace table, for the claims.
struct FurnaceRow {
    a: f64,
    key: &'static str,
    /// Tail index of the walk (infinite for the cosine walk).
    tail_index: f64,
    /// Exact variance of one walk (infinite where the tail index is at most 2).
    variance: f64,
    std_error: f64,
    p_value: f64,
}

/// A tail index or standard error as the table prints it: "∞" when infinite.
fn finite_or_infinity(r: &mut Record, name: &str, x: f64, format: &str) -> String {
    if x.is_infinite() {
        r.text(name, "∞")
    } else {
        r.number(name, x, format)
    }
}

fn furnace_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n = if settings.quick { 100_000 } else { 1_000_000 };
    const LEVEL: f64 = 0.01;
    let mut md = String::new();
    writeln!(
        md,
        "| albedo a | directions | exact L_e/(1−a) | mean | std. error | p-value | mean vertices | tail index κ |"
    )?;
    writeln!(md, "|---:|---|---:|---:|---:|---:|---:|---:|")?;
    let mut rows: Vec<FurnaceRow> = Vec::new();
    for (a_key, a) in [("a0_5", 0.5), ("a0_8", 0.8), ("a0_95", 0.95)] {
        let exact = 1.0 / (1.0 - a);
        // (key, name, bounce, tail index, exact variance of one walk): the cosine walk's
        // weight is exactly a, its throughput always 1 (no tail), its count geometric.
        let bounces: [(&str, &str, Bounce, f64, f64); 2] = [
            (
                "cosine",
                "cosine (continue with prob. a)",
                furnace_bounce_cosine,
                f64::INFINITY,
                a / ((1.0 - a) * (1.0 - a)),
            ),
            (
                "uniform",
                "uniform (roulette on 2a cos)",
                furnace_bounce_uniform,
                furnace_tail_index(a),
                furnace_uniform_variance(a),
            ),
        ];
        for (key, name, bounce, tail_index, variance) in bounces {
            let mut g = rng::seeded(0xF0);
            let (mut s, mut v) = (Summary::default(), Summary::default());
            for _ in 0..n {
                let (l, k) = furnace_walk(1.0, |u| bounce(a, u), &mut g);
                s.push(l);
                v.push(f64::from(k));
            }
            let p = ttest::one_sample(&s, exact).map_or(f64::NAN, |t| t.p_value);
            // Where the variance is infinite the column's population value is ∞, and the
            // sample's standard error and the t-test's p-value estimate nothing.
            let (std_error, p_cell) = if variance.is_infinite() {
                (
                    finite_or_infinity(r, &format!("{a_key}.{key}.std_error"), variance, ".4"),
                    "—".to_string(),
                )
            } else {
                (
                    r.number(&format!("{a_key}.{key}.std_error"), s.std_error(), ".4"),
                    format!("{p:.2}"),
                )
            };
            let kappa =
                finite_or_infinity(r, &format!("{a_key}.{key}.tail_index"), tail_index, ".2");
            writeln!(
                md,
                "| {a} | {name} | {exact:.3} | {:.4} | {std_error} | {p_cell} | {:.2} | {kappa} |",
                s.mean, v.mean
            )?;
            rows.push(FurnaceRow {
                a,
                key,
                tail_index,
                variance,
                std_error: s.std_error(),
                p_value: p,
            });
        }
    }
    let list =
        |f: &dyn Fn(&FurnaceRow) -> String| rows.iter().map(f).collect::<Vec<_>>().join(", ");
    let is_heavy = |row: &FurnaceRow| row.a == 0.95 && row.key == "uniform";
    // The tail index is below 2 (infinite variance) on the a = 0.95 uniform row only; the
    // variance formula agrees with it row by row.
    r.claim(
        "tail_index_below_2_only_at_0_95_uniform",
        rows.iter().all(|row| {
            (row.tail_index < 2.0) == is_heavy(row)
                && row.variance.is_infinite() == (row.tail_index <= 2.0)
        }),
        format!(
            "tail index < 2 (and variance infinite) exactly on a = 0.95 uniform: {}",
            list(&|row| format!(
                "a = {} {} κ {:.4}, variance {:.4}",
                row.a, row.key, row.tail_index, row.variance
            ))
        ),
    );
    let kappa_0_8 = rows
        .iter()
        .find(|row| row.a == 0.8 && row.key == "uniform")
        .map_or(f64::NAN, |row| row.tail_index);
    r.claim(
        "uniform_0_8_third_moment_infinite",
        kappa_0_8 > 2.0 && kappa_0_8 <= 3.0,
        format!("a = 0.8 uniform: 2 < κ {kappa_0_8:.4} <= 3"),
    );
    // The t-test means something only where the variance is finite: there every row accepts
    // the exact mean at the caption's level.
    let finite: Vec<&FurnaceRow> = rows.iter().filter(|row| row.variance.is_finite()).collect();
    r.claim(
        "finite_variance_rows_accept",
        finite.len() == rows.len() - 1 && finite.iter().all(|row| row.p_value >= LEVEL),
        format!(
            "p-value >= {LEVEL} on each of the {} rows of finite variance: {}",
            finite.len(),
            finite
                .iter()
                .map(|row| format!("a = {} {} {:.3}", row.a, row.key, row.p_value))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    // The measured standard error against sqrt(Var / n) from the variance formulas: loose
    // for the a = 0.8 uniform walk (κ = 2.89 < 4: its sample variance settles slowly),
    // tight for the geometric counts of the cosine walk.
    let ratio = |row: &FurnaceRow| row.std_error / (row.variance / n as f64).sqrt();
    let uniform_0_8: Vec<&FurnaceRow> = rows
        .iter()
        .filter(|row| row.a == 0.8 && row.key == "uniform")
        .collect();
    r.claim(
        "uniform_0_8_matches_formula",
        uniform_0_8.len() == 1
            && uniform_0_8
                .iter()
                .all(|row| (ratio(row) - 1.0).abs() < 0.15),
        format!(
            "a = 0.8 uniform: std. error / sqrt(Var / n) within 15 % of 1: {}",
            uniform_0_8
                .iter()
                .map(|row| format!(
                    "{:.5} / sqrt({:.3} / {n}) = {:.4}",
                    row.std_error,
                    row.variance,
                    ratio(row)
                ))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    let cosine: Vec<&FurnaceRow> = rows.iter().filter(|row| row.key == "cosine").collect();
    r.claim(
        "cosine_std_errors_match_geometric",
        cosine.len() == 3 && cosine.iter().all(|row| (ratio(row) - 1.0).abs() < 0.05),
        format!(
            "cosine rows: std. error / sqrt(a/(1-a)^2 / n) within 5 % of 1: {}",
            cosine
                .iter()
                .map(|row| format!(
                    "a = {}: {:.5} / {:.5} = {:.4}",
                    row.a,
                    row.std_error,
                    (row.variance / n as f64).sqrt(),
                    ratio(row)
                ))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    writeln!(
        md,
        "\n*L_e = 1; {n} walks each; p-value of the one-sample t-test against the exact radiance (level {LEVEL}). \
         Tail index κ: the root of (2a)^κ/(κ+1) = 1 for uniform bounces (`furnace_tail_index`), ∞ for cosine bounces \
         (weight exactly a, throughput always 1); the variance is finite exactly where κ > 2.{}*",
        rows.iter()
            .filter(|row| row.variance.is_infinite())
            .map(|row| format!(
                " The {} walk at a = {} has infinite variance (tail index below 2): its std. error is ∞, and the sample's \
                 standard error and the p-value estimate nothing (chapter text).",
                row.key, row.a
            ))
            .collect::<String>()
    )?;
    Ok(md.into_bytes())
}

/// One exponent of the sky figure: the (formula, measured) variance of each estimator.
struct SkyPoint {
    k: i32,
    uniform: (f64, f64),
    cosine: (f64, f64),
}

/// The sky figure's variances, measured once per run: the figure and the estimators'
/// claim read the same numbers.
fn sky_variance_points(settings: &Settings) -> &'static [SkyPoint] {
    static POINTS: std::sync::OnceLock<Vec<SkyPoint>> = std::sync::OnceLock::new();
    POINTS.get_or_init(|| {
        let n = if settings.quick { 20_000 } else { 200_000 };
        (0..=10)
            .map(|k| {
                let env = move |w: DVec3| w.z.max(0.0).powi(k);
                let (vu, vc) = sky_variances(RHO, k);
                let su = summarize(|u| estimate_uniform(RHO, env, u), n, &mut rng::seeded(40));
                let sc = summarize(|u| estimate_cosine(RHO, env, u), n, &mut rng::seeded(41));
                SkyPoint {
                    k,
                    uniform: (vu, su.variance()),
                    cosine: (vc, sc.variance()),
                }
            })
            .collect()
    })
}

fn sky_variance_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut series = vec![
        Series::line("uniform, formula", Vec::new()),
        Series::points("uniform, measured", Vec::new()),
        Series::line("cosine, formula", Vec::new()),
        Series::points("cosine, measured", Vec::new()),
    ];
    for p in sky_variance_points(settings) {
        let x = f64::from(p.k);
        series[0].points.push((x, p.uniform.0));
        series[1].points.push((x, p.uniform.1));
        series[2].points.push((x, p.cosine.0));
        series[3].points.push((x, p.cosine.1));
    }
    // Relative variance (divided by the squared mean) shows how hard each sky is.
    let rel: Vec<Series> = series
        .iter()
        .map(|s| Series {
            points: s
                .points
                .iter()
                .map(|&(x, v)| (x, v / (2.0 * RHO / (x + 2.0)).powi(2)))
                .collect(),
            ..s.clone()
        })
        .collect();
    let panels = [
        Panel::new(
            format!("variance of one estimate, sky max(z,0)^k, ρ = {RHO}"),
            "sky exponent k",
            "variance",
            series,
        ),
        Panel::new(
            "relative variance (variance / exact²)",
            "sky exponent k",
            "relative variance",
            rel,
        ),
    ];
    plot::chart(&panels, 2)
}
