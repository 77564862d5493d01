//! Figures and tables of the chapter *Russian roulette*.

use std::fmt::Write as _;

use anyhow::Context;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, Panel, Series};
use raylemma::rng;
use raylemma::stats::ttest::{self, Summary};
use raylemma::transport::lambert::{furnace_tail_index, uniform_weight_moment};
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

fn single_md(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n = if settings.quick { 100_000 } else { 1_000_000 };
    let mut md = String::new();
    writeln!(
        md,
        "| p | mean | p-value vs 1/3 | variance, measured | E[F²]/p − E[F]², formula |"
    )?;
    writeln!(md, "|---:|---:|---:|---:|---:|")?;
    // Each row its own stream of U and u, so that the rows' p-values are independent.
    for (k, p) in (0u64..).zip([0.05, 0.1, 0.3, 0.5, 0.7, 1.0]) {
        let mut r = rng::seeded(0x5E + k);
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
        "\n*F = U², U uniform on [0, 1): E[F] = 1/3, E[F²] = 1/5; {n} estimates per row, each row with its own seed.*"
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

/// The tail index of a fixed survival probability's path (its moments `E[X^s]` are finite
/// for `s` below it), and whether its measured variance is a reliable estimate: only when
/// the sample variance has a finite variance itself, `κ > 4`.
fn reliable(q: f64) -> bool {
    fixed_survival_tail_index(&FURNACE, q) > 4.0
}

fn efficiency_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
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
    let (sound, unsound): (Vec<_>, Vec<_>) = measured.iter().partition(|(q, _)| reliable(*q));
    let panels = [Panel::new(
        format!(
            "furnace a = {}, uniform bounces: efficiency 1/(variance × ns per path)",
            FURNACE.albedo
        ),
        "fixed survival probability q",
        "efficiency",
        vec![
            Series::line("predicted (formula, fitted ns per vertex)", predicted),
            Series::points("measured (tail index κ > 4)", sound),
            Series::points(
                "measured, κ ≤ 4: the sample variance is unreliable",
                unsound,
            ),
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

fn efficiency_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let s = study(settings);
    let a = FURNACE.albedo;
    let mut md = String::new();
    writeln!(
        md,
        "| survival | mean | p-value vs 2 | variance, measured | variance, formula | mean vertices | ns per path | efficiency, measured | efficiency, predicted | tail index κ |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")?;
    let row = |md: &mut String, name: String, m: &Measured, var: f64, pred: f64, kappa: f64| {
        let p = ttest::one_sample(&m.summary, FURNACE.radiance()).map_or(f64::NAN, |t| t.p_value);
        let f = |x: f64, decimals: usize| {
            if x.is_finite() {
                format!("{x:.decimals$}")
            } else {
                "—".into()
            }
        };
        writeln!(
            md,
            "| {name} | {:.4} | {p:.2} | {:.4} | {} | {:.2} | {:.1} | {:.5} | {} | {} |",
            m.summary.mean,
            m.summary.variance(),
            f(var, 4),
            m.vertices,
            m.ns_per_path,
            efficiency(m),
            f(pred, 5),
            if kappa.is_infinite() {
                "∞".to_string()
            } else {
                format!("{kappa:.2}")
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
            fixed_survival_tail_index(&FURNACE, *q),
        )?;
    }
    // The throughput rule: for a <= 1/2 the weight never exceeds 1, the throughput stays 1
    // and the rule is the cosine walk, with 1/(1 - a) vertices per path on average.
    let throughput_variance = throughput_rule_variance(&FURNACE);
    let throughput_vertices = if a <= 0.5 { 1.0 / (1.0 - a) } else { f64::NAN };
    let throughput_predicted = 1.0 / (throughput_variance * throughput_vertices * s.ns_per_vertex);
    row(
        &mut md,
        "p = min(1, T)".into(),
        &s.throughput,
        throughput_variance,
        throughput_predicted,
        furnace_tail_index(a),
    )?;
    let t = &s.throughput;
    let (t_var, t_vertices) = (t.summary.variance(), t.vertices);
    r.claim(
        "throughput_variance_and_vertices_match_formula",
        (t_var / throughput_variance - 1.0).abs() < 0.05
            && (t_vertices / throughput_vertices - 1.0).abs() < 0.05,
        format!(
            "p = min(1, T): variance measured {t_var:.4} / formula {throughput_variance:.4} and mean vertices \
             {t_vertices:.3} / 1/(1 − a) {throughput_vertices:.3}, each within 5 % of 1"
        ),
    );
    r.number("throughput.efficiency_measured", efficiency(t), ".5");
    // The best fixed q of the ladder, and the ends of the ladder against it.
    let (best_q, best) = s
        .fixed
        .iter()
        .max_by(|a, b| efficiency(&a.1).total_cmp(&efficiency(&b.1)))
        .context("no fixed survival probability")?;
    let best_eff = efficiency(best);
    r.number("best_fixed.efficiency_measured", best_eff, "s3");
    // Timings of one run, so a ranking of them can flip under load: the claim is only that
    // the rule is not much worse (within 10 %) than the best fixed q.
    r.claim(
        "throughput_rule_near_best",
        efficiency(t) > 0.9 * best_eff,
        format!(
            "p = min(1, T) efficiency {:.5} > 0.9 × best fixed (q = {best_q}) {best_eff:.5} = {:.5}",
            efficiency(t),
            0.9 * best_eff
        ),
    );
    // The time per vertex of the rule against a fixed q's with the same mean number of
    // vertices (q = 1 - 1/(mean vertices), here q = 0.5 and 2 vertices).
    let same_length = s
        .fixed
        .iter()
        .min_by(|x, y| {
            (x.1.vertices - t_vertices)
                .abs()
                .total_cmp(&(y.1.vertices - t_vertices).abs())
        })
        .context("no fixed survival probability")?;
    r.text("same_length.q", format!("{}", same_length.0));
    let (t_per_vertex, q_per_vertex) = (
        t.ns_per_path / t_vertices,
        same_length.1.ns_per_path / same_length.1.vertices,
    );
    r.claim(
        "throughput_rule_costs_more_per_vertex",
        t_per_vertex > q_per_vertex && (same_length.1.vertices / t_vertices - 1.0).abs() < 0.05,
        format!(
            "ns per vertex: p = min(1, T) {:.1} / {t_vertices:.2} = {t_per_vertex:.1} > q = {} {:.1} / {:.2} = {q_per_vertex:.1} \
             (mean vertices within 5 %)",
            t.ns_per_path, same_length.0, same_length.1.ns_per_path, same_length.1.vertices
        ),
    );
    // In theory, at equal cost per vertex: variance × mean vertices of the rule against the
    // best fixed q's (the formula's optimum).
    let opt = s.optimum;
    let (opt_var, opt_vertices) = (path_variance(&FURNACE, opt), expected_vertices(opt));
    r.number("optimum.q", opt, ".3");
    r.number("optimum.variance_formula", opt_var, "s3");
    r.number("optimum.vertices", opt_vertices, "s2");
    r.number(
        "optimum.variance_times_vertices",
        opt_var * opt_vertices,
        "s3",
    );
    let t_cost = throughput_variance * throughput_vertices;
    r.number("throughput.variance_times_vertices", t_cost, "s2");
    let gain = opt_var * opt_vertices / t_cost;
    r.number("throughput.gain_at_equal_cost_per_vertex", gain, "s2");
    r.claim(
        "throughput_rule_better_in_theory",
        gain > 1.0,
        format!(
            "variance × mean vertices: best fixed q = {opt:.3} {opt_var:.4} × {opt_vertices:.3} = {:.3} > p = min(1, T) \
             {throughput_variance:.3} × {throughput_vertices:.3} = {t_cost:.3} (gain {gain:.3} > 1)",
            opt_var * opt_vertices
        ),
    );
    let (low_q, low) = s.fixed.first().context("no fixed survival probability")?;
    let (high_q, high) = s.fixed.last().context("no fixed survival probability")?;
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
    // Where κ <= 4 the sample variance has an infinite variance itself; a heavy-tailed sample
    // variance is usually below the true one. Say how often it is here.
    let unsound: Vec<&(f64, Measured)> = s.fixed.iter().filter(|(q, _)| !reliable(*q)).collect();
    let below = unsound
        .iter()
        .filter(|(q, m)| m.summary.variance() < path_variance(&FURNACE, *q))
        .count();
    let threshold = uniform_weight_moment(a, 4.0).cbrt();
    let unsound_note = match (unsound.first(), unsound.last()) {
        (Some((lo, _)), Some((hi, _))) => format!(
            " For q below E[w⁴]^(1/3) = {threshold:.3} (the rows q = {lo} to {hi}) the tail index of the path \
             (`fixed_survival_tail_index`) is at most 4: the sample variance then has an infinite variance itself, and \
             the measured variances and efficiencies there are not reliable estimates (usually too low a variance: \
             here below the formula's in {below} of those {} rows).",
            unsound.len()
        ),
        _ => String::new(),
    };
    writeln!(
        md,
        "\n*Furnace L_e = 1, a = {a}, directions uniform on the hemisphere (bounce weight 2a cos θ, E[w²] = {:.4}: the variance is infinite for q ≤ E[w²]). \
         Tail index κ: the root of q^(1−κ) (2a)^κ/(κ+1) = 1 for fixed q, of (2a)^κ/(κ+1) = 1 for p = min(1, T) (∞ for a ≤ 1/2, where the weight never exceeds 1).{unsound_note} \
         The rule p = min(1, T)'s formula columns: its variance a/(1−a)² and 1/(1−a) vertices per path (a ≤ 1/2, where it is the cosine walk). \
         Predicted optimum q = {:.3} (formula); best measured q on this grid = {best_q}. Time per vertex fitted: {:.1} ns. {}.*",
        FURNACE.weight_second_moment(),
        s.optimum,
        s.ns_per_vertex,
        timing::machine()
    )?;
    Ok(md.into_bytes())
}
