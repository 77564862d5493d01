//! Figures and tables of the chapter *Shadow-ray pdfs*.

use std::fmt::Write as _;
use std::hint::black_box;

use anyhow::anyhow;
use glam::{DVec2, DVec3};

use super::{Output, Record, Settings, timing};
use crate::plot::{self, Panel, Series};
use raylemma::check::warp::square_point;
use raylemma::rng;
use raylemma::stats::ttest::Summary;
use raylemma::transport::shadow::{
    Heuristic, IrradianceStrategy, Light, QuadLight, SphereCone, SphereLight, estimate_irradiance,
    sphere_irradiance,
};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "shadow_strategies.md",
            what: "light, BSDF and MIS sampling: variance and time",
            make: strategies_md,
        },
        Output {
            file: "shadow_convergence.svg",
            what: "error against time for three strategies",
            make: convergence_svg,
        },
        Output {
            file: "shadow_sphere.md",
            what: "cap-area against cone sampling of a sphere light",
            make: sphere_md,
        },
    ]
}

const STRATEGIES: [(&str, IrradianceStrategy); 4] = [
    ("light", IrradianceStrategy::Light),
    ("BSDF (cosine)", IrradianceStrategy::Bsdf),
    ("MIS (balance)", IrradianceStrategy::Mis(Heuristic::Balance)),
    ("MIS (power)", IrradianceStrategy::Mis(Heuristic::Power)),
];

/// A square light of side `side` centred 0.3 off the normal at height 1 above the origin,
/// facing down; the shading point is the origin with normal `+z`.
pub(crate) fn square_light(side: f64) -> anyhow::Result<QuadLight> {
    Ok(QuadLight::new(
        DVec3::new(0.3 - side / 2.0, -side / 2.0, 1.0),
        DVec3::new(0.0, side, 0.0),
        DVec3::new(side, 0.0, 0.0),
    )?)
}

/// `(exact, variance per sample, ns per sample)` of each strategy for one light.
fn measure(light: &QuadLight, settings: &Settings) -> Vec<(&'static str, f64, f64, f64)> {
    let exact = light.irradiance(DVec3::ZERO, DVec3::Z, 1.0);
    STRATEGIES
        .iter()
        .map(|&(name, strategy)| {
            let (variance, ns) = variance_and_time(light, strategy, settings);
            (name, exact, variance, ns)
        })
        .collect()
}

/// The variance per sample and the nanoseconds per sample of `strategy`'s estimate of the
/// irradiance from `light` at the origin, normal `+z` (radiance 1).
pub(crate) fn variance_and_time(
    light: &dyn Light,
    strategy: IrradianceStrategy,
    settings: &Settings,
) -> (f64, f64) {
    let (p, n) = (DVec3::ZERO, DVec3::Z);
    let samples = if settings.quick { 20_000 } else { 400_000 };
    let mut rng = rng::seeded(7);
    let mut s = Summary::default();
    for _ in 0..samples {
        let (u, v) = (square_point(&mut rng), square_point(&mut rng));
        s.push(estimate_irradiance(light, p, n, 1.0, strategy, u, v));
    }
    let items = 4096;
    let us: Vec<(DVec2, DVec2)> = (0..items)
        .map(|_| (square_point(&mut rng), square_point(&mut rng)))
        .collect();
    let reps = if settings.quick { 5 } else { 51 };
    let ns = timing::median_ns_per_item(items, reps, || {
        let mut acc = 0.0;
        for &(u, v) in &us {
            acc += estimate_irradiance(light, p, n, 1.0, strategy, black_box(u), v);
        }
        acc.to_bits()
    });
    (s.variance(), ns)
}

pub(crate) const SIDES: [(&str, f64); 2] = [("small (0.1 × 0.1)", 0.1), ("large (6 × 6)", 6.0)];

/// One strategy for one light: `(name, exact E, variance per sample, ns per sample)`.
pub(crate) type Row = (&'static str, f64, f64, f64);

/// The strategies measured once per run for each light of [`SIDES`]: the table and the
/// chart show the same measurement.
pub(crate) fn measured(settings: &Settings) -> anyhow::Result<&'static [Vec<Row>]> {
    static MEASURED: std::sync::OnceLock<Result<Vec<Vec<Row>>, String>> =
        std::sync::OnceLock::new();
    MEASURED
        .get_or_init(|| {
            SIDES
                .iter()
                .map(|&(_, side)| {
                    square_light(side)
                        .map(|light| measure(&light, settings))
                        .map_err(|e| crate::job::message(&e))
                })
                .collect()
        })
        .as_deref()
        .map_err(|e| anyhow!("{e}"))
}

/// A light and a strategy as a value name: `small.mis_power`.
fn row_key(side: &str, strategy: &str) -> String {
    let light = if side.starts_with("small") {
        "small"
    } else {
        "large"
    };
    let strategy = match strategy {
        "light" => "light",
        "BSDF (cosine)" => "bsdf",
        "MIS (balance)" => "mis_balance",
        _ => "mis_power",
    };
    format!("{light}.{strategy}")
}

fn strategies_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::new();
    writeln!(
        md,
        "| light | strategy | exact E | variance per sample / E² | ns per sample | relative efficiency |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|")?;
    // Per light: (relative variance, relative efficiency) by strategy, in STRATEGIES' order.
    let mut lights = Vec::new();
    for ((label, _), rows) in SIDES.iter().zip(measured(settings)?) {
        let best = rows.iter().map(|r| 1.0 / (r.2 * r.3)).fold(0.0, f64::max);
        let mut of_light = Vec::new();
        for &(name, exact, var, ns) in rows {
            let key = row_key(label, name);
            let (rel_var, eff) = (var / (exact * exact), 1.0 / (var * ns) / best);
            r.number(&format!("{key}.efficiency"), eff, "s2");
            of_light.push((rel_var, eff));
            writeln!(
                md,
                "| {label} | {name} | {exact:.4e} | {rel_var:.3e} | {ns:.0} | {eff:.2e} |"
            )?;
        }
        lights.push(of_light);
    }
    // STRATEGIES: light, BSDF, MIS (balance), MIS (power).
    let (small, large) = (&lights[0], &lights[1]);
    let var = |l: &Vec<(f64, f64)>, k: usize| l[k].0;
    let (light, bsdf, balance, power) = (0, 1, 2, 3);
    r.claim(
        "light_wins_small_cosine_wins_large",
        var(small, light) < var(small, bsdf) && var(large, light) > var(large, bsdf),
        format!(
            "variance per sample / E²: small light {:.3e} < BSDF {:.3e}; large light {:.3e} > BSDF {:.3e}",
            var(small, light),
            var(small, bsdf),
            var(large, light),
            var(large, bsdf)
        ),
    );
    let mis: Vec<f64> = [small, large]
        .iter()
        .flat_map(|l| [l[balance].1, l[power].1])
        .collect();
    r.claim(
        "mis_not_most_efficient_either_light",
        mis.iter().all(|&e| e < 1.0),
        format!(
            "relative efficiency of MIS (balance, power): small {:.3}, {:.3}; large {:.3}, {:.3}; each < 1",
            mis[0], mis[1], mis[2], mis[3]
        ),
    );
    // MIS's factors are near 1 (`.1`, not `s2`, which shows 0.99998 as "1.00"); the wrong
    // strategy's are large.
    let ratios = [
        (
            "small.mis_power_over_light",
            var(small, power) / var(small, light),
            ".1",
        ),
        (
            "large.mis_power_over_bsdf",
            var(large, power) / var(large, bsdf),
            ".1",
        ),
        (
            "small.bsdf_over_light",
            var(small, bsdf) / var(small, light),
            "s2",
        ),
        (
            "large.light_over_bsdf",
            var(large, light) / var(large, bsdf),
            "s2",
        ),
    ];
    for (name, x, format) in ratios {
        r.number(&format!("{name}.variance_ratio"), x, format);
    }
    let [mis_small, mis_large, wrong_small, wrong_large] = ratios.map(|(_, x, _)| x);
    // MIS's price is a small factor (< 3); the wrong single strategy's, more than an order
    // of magnitude for each light (and more than two for the small one).
    r.claim(
        "mis_price_small_wrong_strategy_large",
        wrong_small > 100.0 && wrong_large > 10.0 && mis_small < 3.0 && mis_large < 3.0,
        format!(
            "variance ratios: small BSDF / light {wrong_small:.3} > 100, large light / BSDF {wrong_large:.3} > 10, \
             small MIS (power) / light {mis_small:.3} < 3, large MIS (power) / BSDF {mis_large:.3} < 3"
        ),
    );
    // Veach's theorem 9.2 with one sample of each strategy: the balance heuristic's variance
    // exceeds any other weighting's (a single strategy's among them) by at most mu^2 / 2, 0.5
    // in the table's units (variance / E^2). For the small light it is several (> 2) times
    // light sampling's and yet only a small fraction (< 0.05) of mu^2 above it.
    const BOUND: f64 = 0.5;
    let (over_small, over_large) = (
        var(small, balance) - var(small, light),
        var(large, balance) - var(large, bsdf),
    );
    let balance_factor_small = var(small, balance) / var(small, light);
    r.claim(
        "balance_within_veach_bound",
        over_small < BOUND
            && over_large < BOUND
            && over_small < 0.05
            && balance_factor_small > 2.0,
        format!(
            "variance per sample / E²: small balance {:.4e} − light {:.4e} = {over_small:.3e} < 0.05 (and < {BOUND}); \
             large balance {:.4e} − BSDF {:.4e} = {over_large:.4} < {BOUND}; small balance / light {balance_factor_small:.2} > 2",
            var(small, balance),
            var(small, light),
            var(large, balance),
            var(large, bsdf)
        ),
    );
    // Exercise 3: the power heuristic's variance matches light sampling's for the small
    // light (within 5 %), and the balance heuristic's is below the power heuristic's for the
    // large one.
    r.claim(
        "power_matches_light_small_balance_lower_large",
        (mis_small - 1.0).abs() < 0.05 && var(large, balance) < var(large, power),
        format!(
            "small MIS (power) / light {mis_small:.4}, within 5 % of 1; large MIS (balance) {:.4e} < MIS (power) {:.4e}",
            var(large, balance),
            var(large, power)
        ),
    );
    let worst_is = |l: &Vec<(f64, f64)>, k: usize| (0..l.len()).all(|j| j == k || l[j].0 < l[k].0);
    r.claim(
        "bsdf_worst_small_light_worst_large",
        worst_is(small, bsdf) && worst_is(large, light),
        format!(
            "variance per sample / E²: small {:.3e} (light, BSDF, MIS balance, MIS power: BSDF the largest), \
             large {:.3e} (light the largest)",
            small.iter().map(|x| x.0).fold(0.0, f64::max),
            large.iter().map(|x| x.0).fold(0.0, f64::max),
        ),
    );
    writeln!(
        md,
        "\nShading point at the origin, normal +z, square light centred 0.3 off the normal at height 1. \
         Efficiency is 1 / (variance × time), relative to the best strategy for that light. \
         Timed on {}.",
        timing::machine()
    )?;
    Ok(md.into_bytes())
}

fn convergence_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut panels = Vec::new();
    for ((label, _), rows) in SIDES.iter().zip(measured(settings)?) {
        let series = rows
            .iter()
            .map(|&(name, exact, var, ns)| {
                Series::line(
                    name,
                    // n independent samples: relative RMS error sqrt(var / n) / E after n * ns.
                    (0..=16)
                        .map(|k| {
                            let n = 2f64.powi(k);
                            (n * ns / 1e3, (var / n).sqrt() / exact)
                        })
                        .collect(),
                )
            })
            .collect();
        panels.push(
            Panel::new(
                format!("{label} light"),
                "time per estimate (µs)",
                "relative RMS error",
                series,
            )
            .log_x()
            .log_y(),
        );
    }
    plot::chart(&panels, 2)
}

fn sphere_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let samples = if settings.quick { 20_000 } else { 400_000 };
    let mut md = String::new();
    writeln!(
        md,
        "| distance / radius | exact E | variance / E², cap area | variance / E², cone |"
    )?;
    writeln!(md, "|---:|---:|---:|---:|")?;
    let mut cap_not_worse = Vec::new();
    for d in [1.05, 2.0, 10.0, 100.0] {
        let light = SphereLight::new(DVec3::new(0.0, 0.0, d), 1.0)?;
        let (p, n) = (DVec3::ZERO, DVec3::Z);
        let exact = sphere_irradiance(p, n, &light, 1.0);
        let variance = |l: &dyn Light| {
            let mut rng = rng::seeded(8);
            let mut s = Summary::default();
            for _ in 0..samples {
                let (u, v) = (square_point(&mut rng), square_point(&mut rng));
                s.push(estimate_irradiance(
                    l,
                    p,
                    n,
                    1.0,
                    IrradianceStrategy::Light,
                    u,
                    v,
                ));
            }
            s.variance() / (exact * exact)
        };
        let (cap, cone) = (variance(&light), variance(&SphereCone(light)));
        if cone >= cap {
            cap_not_worse.push(format!("{d}: cone {cone:.3e} >= cap area {cap:.3e}"));
        }
        writeln!(md, "| {d} | {exact:.4e} | {cap:.3e} | {cone:.3e} |")?;
    }
    r.claim(
        "cone_below_cap_area_every_distance",
        cap_not_worse.is_empty(),
        if cap_not_worse.is_empty() {
            "cone sampling's variance is below cap-area sampling's at every distance".to_string()
        } else {
            cap_not_worse.join("; ")
        },
    );
    writeln!(
        md,
        "\nOne light sample per estimate, {samples} estimates; shading normal towards the centre."
    )?;
    Ok(md.into_bytes())
}
