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

fn estimators_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let n = if settings.quick { 100_000 } else { 1_000_000 };
    let reps = if settings.quick { 5 } else { 51 };
    let mut md = String::new();
    writeln!(
        md,
        "| environment | directions | mean | exact | p-value | variance | ns per sample | relative efficiency |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|")?;
    for env in [GRADIENT, SKY] {
        let exact = RHO * env.reflected_white;
        let strategies: [(&str, Estimator); 2] = [
            ("uniform, 2ρL cos", |r, l, u| estimate_uniform(r, l, u)),
            ("cosine, ρL", |r, l, u| estimate_cosine(r, l, u)),
        ];
        let mut rows = Vec::new();
        for (name, est) in strategies {
            let s = summarize(|u| est(RHO, env.radiance, u), n, &mut rng::seeded(0x1A3));
            let p = ttest::one_sample(&s, exact).map_or(f64::NAN, |t| t.p_value);
            let mut r = rng::seeded(5);
            let batch = 4096;
            let ns = timing::median_ns_per_item(batch, reps, || {
                let mut acc = 0.0;
                for _ in 0..batch {
                    acc += est(RHO, env.radiance, black_box(square_point(&mut r)));
                }
                acc.to_bits()
            });
            rows.push((name, s, p, ns, 1.0 / (s.variance() * ns)));
        }
        let base = rows[0].4;
        for (name, s, p, ns, eff) in rows {
            writeln!(
                md,
                "| {} | {name} | {:.5} | {exact:.5} | {p:.2} | {:.4} | {ns:.1} | {:.2} |",
                env.name,
                s.mean,
                s.variance(),
                eff / base
            )?;
        }
    }
    writeln!(
        md,
        "\n*Albedo ρ = {RHO}; {n} one-sample estimates each; p-value of the one-sample t-test against the exact answer; efficiency 1/(variance × time), relative to uniform directions in the same environment. {}.*",
        timing::machine()
    )?;
    Ok(md.into_bytes())
}

fn furnace_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let n = if settings.quick { 100_000 } else { 1_000_000 };
    let mut md = String::new();
    writeln!(
        md,
        "| albedo a | directions | exact L_e/(1−a) | mean | std. error | p-value | mean vertices |"
    )?;
    writeln!(md, "|---:|---|---:|---:|---:|---:|---:|")?;
    for a in [0.5, 0.8, 0.95] {
        let exact = 1.0 / (1.0 - a);
        let bounces: [(&str, Bounce); 2] = [
            ("cosine (continue with prob. a)", furnace_bounce_cosine),
            ("uniform (roulette on 2a cos)", furnace_bounce_uniform),
        ];
        for (name, bounce) in bounces {
            let mut r = rng::seeded(0xF0);
            let (mut s, mut v) = (Summary::default(), Summary::default());
            for _ in 0..n {
                let (l, k) = furnace_walk(1.0, |u| bounce(a, u), &mut r);
                s.push(l);
                v.push(f64::from(k));
            }
            let p = ttest::one_sample(&s, exact).map_or(f64::NAN, |t| t.p_value);
            writeln!(
                md,
                "| {a} | {name} | {exact:.3} | {:.4} | {:.4} | {p:.2} | {:.2} |",
                s.mean,
                s.std_error(),
                v.mean
            )?;
        }
    }
    writeln!(
        md,
        "\n*L_e = 1; {n} walks each; p-value of the one-sample t-test against the exact radiance.*"
    )?;
    Ok(md.into_bytes())
}

fn sky_variance_svg(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let n = if settings.quick { 20_000 } else { 200_000 };
    let ks: Vec<i32> = (0..=10).collect();
    let mut series = vec![
        Series::line("uniform, formula", Vec::new()),
        Series::points("uniform, measured", Vec::new()),
        Series::line("cosine, formula", Vec::new()),
        Series::points("cosine, measured", Vec::new()),
    ];
    for &k in &ks {
        let env = move |w: DVec3| w.z.max(0.0).powi(k);
        let (vu, vc) = sky_variances(RHO, k);
        let su = summarize(|u| estimate_uniform(RHO, env, u), n, &mut rng::seeded(40));
        let sc = summarize(|u| estimate_cosine(RHO, env, u), n, &mut rng::seeded(41));
        let x = f64::from(k);
        series[0].points.push((x, vu));
        series[1].points.push((x, su.variance()));
        series[2].points.push((x, vc));
        series[3].points.push((x, sc.variance()));
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
