//! Figures and tables of the chapter *Russian roulette*.

use std::fmt::Write as _;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, BoxError, Panel, Series};
use raylemma::rng;
use raylemma::stats::ttest::{self, Summary};
use raylemma::transport::roulette::*;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "roulette_single.md",
            what: "single-step roulette: variance against p",
            make: single_md,
        },
        Output {
            file: "roulette_efficiency.svg",
            what: "efficiency against the survival probability",
            make: efficiency_svg,
        },
        Output {
            file: "roulette_efficiency.md",
            what: "variance, time and efficiency per survival rule",
            make: efficiency_md,
        },
    ]
}

const FURNACE: Furnace = Furnace {
    emission: 1.0,
    albedo: 0.5,
};

fn single_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let n = if settings.quick { 100_000 } else { 1_000_000 };
    let mut md = String::new();
    writeln!(
        md,
        "| p | mean | p-value vs 1/3 | variance, measured | E[F²]/p − E[F]², formula |"
    )?;
    writeln!(md, "|---:|---:|---:|---:|---:|")?;
    for p in [0.05, 0.1, 0.3, 0.5, 0.7, 1.0] {
        let mut r = rng::seeded(0x5E);
        let s = Summary::of((0..n).map(|_| {
            let x = rng::uniform(&mut r, 0.0, 1.0);
            roulette(x * x, p, rng::uniform(&mut r, 0.0, 1.0))
        }));
        let pv = ttest::one_sample(&s, 1.0 / 3.0).map_or(f64::NAN, |t| t.p_value);
        writeln!(
            md,
            "| {p} | {:.4} | {pv:.2} | {:.4} | {:.4} |",
            s.mean,
            s.variance(),
            roulette_variance(1.0 / 3.0, 0.2, p)
        )?;
    }
    writeln!(
        md,
        "\n*F = U², U uniform on [0, 1): E[F] = 1/3, E[F²] = 1/5; {n} estimates per row.*"
    )?;
    Ok(md.into_bytes())
}

/// One measured survival rule: variance, ns per path, mean vertices, mean.
struct Measured {
    summary: Summary,
    ns_per_path: f64,
    vertices: f64,
}

fn measure(survival: Survival, n: usize, reps: usize) -> Measured {
    // Variance and vertices from one long run; time as the median of `reps` shorter runs.
    let mut r = rng::seeded(0xE7);
    let (mut summary, mut verts) = (Summary::default(), 0u64);
    for _ in 0..n {
        let (l, v) = furnace_path(&FURNACE, survival, true, &mut r);
        summary.push(l);
        verts += u64::from(v);
    }
    let batch = 2000;
    let ns_per_path = timing::median_ns_per_item(batch, reps, || {
        let mut acc = 0.0;
        for _ in 0..batch {
            acc += furnace_path(&FURNACE, survival, true, &mut r).0;
        }
        acc.to_bits()
    });
    Measured {
        summary,
        ns_per_path,
        vertices: verts as f64 / n as f64,
    }
}

fn grid() -> Vec<f64> {
    vec![
        0.36, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95, 0.98,
    ]
}

struct Study {
    fixed: Vec<(f64, Measured)>,
    throughput: Measured,
    ns_per_vertex: f64,
    optimum: f64,
}

fn study(settings: &Settings) -> Study {
    let n = if settings.quick { 50_000 } else { 400_000 };
    let reps = if settings.quick { 3 } else { 21 };
    let fixed: Vec<(f64, Measured)> = grid()
        .into_iter()
        .map(|q| (q, measure(Survival::Fixed(q), n, reps)))
        .collect();
    let throughput = measure(Survival::Throughput, n, reps);
    // Least-squares slope through the origin of time against mean vertices.
    let (sxy, sxx) = fixed.iter().fold((0.0, 0.0), |(a, b), (_, m)| {
        (a + m.vertices * m.ns_per_path, b + m.vertices * m.vertices)
    });
    Study {
        fixed,
        throughput,
        ns_per_vertex: sxy / sxx,
        optimum: optimal_survival(&FURNACE),
    }
}

fn efficiency(m: &Measured) -> f64 {
    1.0 / (m.summary.variance() * m.ns_per_path)
}

fn efficiency_svg(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let s = study(settings);
    let fine: Vec<f64> = (1..200)
        .map(|i| 0.34 + (0.995 - 0.34) * f64::from(i) / 200.0)
        .collect();
    let predicted: Vec<(f64, f64)> = fine
        .iter()
        .map(|&q| (q, predicted_efficiency(&FURNACE, q, s.ns_per_vertex)))
        .collect();
    let peak = predicted_efficiency(&FURNACE, s.optimum, s.ns_per_vertex);
    let measured: Vec<(f64, f64)> = s.fixed.iter().map(|(q, m)| (*q, efficiency(m))).collect();
    let top = measured
        .iter()
        .map(|p| p.1)
        .chain([peak])
        .fold(0.0, f64::max);
    let panels = [Panel::new(
        format!(
            "furnace a = {}, uniform bounces: efficiency 1/(variance × ns per path)",
            FURNACE.albedo
        ),
        "fixed survival probability q",
        "efficiency",
        vec![
            Series::line("predicted (formula, fitted ns per vertex)", predicted),
            Series::points("measured", measured),
            Series::line(
                format!("predicted optimum q = {:.3}", s.optimum),
                vec![(s.optimum, 0.0), (s.optimum, top * 1.05)],
            ),
            Series::line(
                "throughput-based p = min(1, T), measured",
                vec![
                    (0.34, efficiency(&s.throughput)),
                    (1.0, efficiency(&s.throughput)),
                ],
            ),
        ],
    )
    .x_range((0.3, 1.02))
    .legend(plot::Legend::Below)];
    plot::chart(&panels, 1)
}

fn efficiency_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let s = study(settings);
    let mut md = String::new();
    writeln!(
        md,
        "| survival | mean | p-value vs 2 | variance, measured | variance, formula | mean vertices | ns per path | efficiency, measured | efficiency, predicted |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|---:|---:|---:|")?;
    let row = |md: &mut String, name: String, m: &Measured, var: f64, pred: f64| {
        let p = ttest::one_sample(&m.summary, FURNACE.radiance()).map_or(f64::NAN, |t| t.p_value);
        let f = |x: f64| {
            if x.is_finite() {
                format!("{x:.4}")
            } else {
                "—".into()
            }
        };
        writeln!(
            md,
            "| {name} | {:.4} | {p:.2} | {:.4} | {} | {:.2} | {:.1} | {:.5} | {} |",
            m.summary.mean,
            m.summary.variance(),
            f(var),
            m.vertices,
            m.ns_per_path,
            efficiency(m),
            if pred.is_finite() {
                format!("{pred:.5}")
            } else {
                "—".into()
            }
        )
    };
    for (q, m) in &s.fixed {
        row(
            &mut md,
            format!("q = {q}"),
            m,
            path_variance(&FURNACE, *q),
            predicted_efficiency(&FURNACE, *q, s.ns_per_vertex),
        )?;
    }
    row(
        &mut md,
        "p = min(1, T)".into(),
        &s.throughput,
        f64::NAN,
        f64::NAN,
    )?;
    r.number(
        "throughput.efficiency_measured",
        efficiency(&s.throughput),
        ".5",
    );
    // The best fixed q of the ladder, and the ends of the ladder against it.
    let (best_q, best) = s
        .fixed
        .iter()
        .max_by(|a, b| efficiency(&a.1).total_cmp(&efficiency(&b.1)))
        .ok_or("no fixed survival probability")?;
    let best_eff = efficiency(best);
    r.number("best_fixed.efficiency_measured", best_eff, "s3");
    let (low_q, low) = s.fixed.first().ok_or("no fixed survival probability")?;
    let (high_q, high) = s.fixed.last().ok_or("no fixed survival probability")?;
    let (low_eff, high_eff) = (efficiency(low), efficiency(high));
    let (low_var, best_var) = (low.summary.variance(), best.summary.variance());
    r.claim(
        "fixed_efficiency_falls_away_at_both_ends",
        low_eff < 0.5 * best_eff
            && high_eff < 0.5 * best_eff
            && low_var > best_var
            && high.vertices > best.vertices,
        format!(
            "efficiency at q = {low_q} {low_eff:.5} and at q = {high_q} {high_eff:.5} < half the best fixed q's (q = {best_q}) {best_eff:.5}; \
             variance at q = {low_q} {low_var:.4} > at q = {best_q} {best_var:.4}; mean vertices at q = {high_q} {:.2} > at q = {best_q} {:.2}",
            high.vertices, best.vertices
        ),
    );
    writeln!(
        md,
        "\n*Furnace L_e = 1, a = {}, directions uniform on the hemisphere (bounce weight 2a cos θ, E[w²] = {:.4}: the variance is infinite for q ≤ E[w²]). Predicted optimum q = {:.3} (formula); best measured q on this grid = {best_q}. Time per vertex fitted: {:.1} ns. {}.*",
        FURNACE.albedo,
        FURNACE.weight_second_moment(),
        s.optimum,
        s.ns_per_vertex,
        timing::machine()
    )?;
    Ok(md.into_bytes())
}
