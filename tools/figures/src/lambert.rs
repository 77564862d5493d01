//! Figures and tables of the chapter *Lambertian reflectance*.

use std::fmt::Write as _;
use std::hint::black_box;

use glam::{DVec2, DVec3};

use super::{Output, Record, Settings, timing};
use crate::plot::{self, BoxError, Panel, Series};
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

fn estimators_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
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

fn furnace_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let n = if settings.quick { 100_000 } else { 1_000_000 };
    let mut md = String::new();
    writeln!(
        md,
        "| albedo a | directions | exact L_e/(1−a) | mean | std. error | p-value | mean vertices |"
    )?;
    writeln!(md, "|---:|---|---:|---:|---:|---:|---:|")?;
    // Every p-value, and per albedo the (cosine, uniform) standard errors.
    let (mut p_values, mut errors) = (Vec::new(), Vec::new());
    for (a_key, a) in [("a0_5", 0.5), ("a0_8", 0.8), ("a0_95", 0.95)] {
        let exact = 1.0 / (1.0 - a);
        let bounces: [(&str, &str, Bounce); 2] = [
            (
                "cosine",
                "cosine (continue with prob. a)",
                furnace_bounce_cosine,
            ),
            (
                "uniform",
                "uniform (roulette on 2a cos)",
                furnace_bounce_uniform,
            ),
        ];
        let mut std_errors = [0.0; 2];
        for (k, (key, name, bounce)) in bounces.into_iter().enumerate() {
            let mut g = rng::seeded(0xF0);
            let (mut s, mut v) = (Summary::default(), Summary::default());
            for _ in 0..n {
                let (l, k) = furnace_walk(1.0, |u| bounce(a, u), &mut g);
                s.push(l);
                v.push(f64::from(k));
            }
            let p = ttest::one_sample(&s, exact).map_or(f64::NAN, |t| t.p_value);
            p_values.push((a, key, p));
            std_errors[k] = s.std_error();
            writeln!(
                md,
                "| {a} | {name} | {exact:.3} | {:.4} | {} | {p:.2} | {:.2} |",
                s.mean,
                r.number(&format!("{a_key}.{key}.std_error"), s.std_error(), ".4"),
                v.mean
            )?;
        }
        errors.push((a, std_errors[0], std_errors[1]));
    }
    r.claim(
        "no_p_value_below_0_01",
        p_values.iter().all(|&(_, _, p)| p >= 0.01),
        format!(
            "every p-value >= 0.01: {}",
            p_values
                .iter()
                .map(|(a, key, p)| format!("a = {a} {key} {p:.2}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    // As a approaches 1 the uniform walk's standard error pulls away from the cosine
    // walk's: the ratio grows with a, and is above 10 at a = 0.95.
    let ratios: Vec<f64> = errors.iter().map(|&(_, c, u)| u / c).collect();
    let last = ratios.last().copied().unwrap_or(f64::NAN);
    r.claim(
        "uniform_std_error_pulls_away_as_a_approaches_1",
        ratios.windows(2).all(|w| w[1] > w[0]) && last > 10.0,
        format!(
            "uniform over cosine standard error, growing with a and > 10 at a = 0.95: {}",
            errors
                .iter()
                .zip(&ratios)
                .map(|(&(a, c, u), q)| format!("a = {a}: {u:.4}/{c:.4} = {q:.2}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    writeln!(
        md,
        "\n*L_e = 1; {n} walks each; p-value of the one-sample t-test against the exact radiance.*"
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

fn sky_variance_svg(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
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
