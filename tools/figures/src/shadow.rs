//! Figures and tables of the chapter *Shadow-ray pdfs*.

use std::fmt::Write as _;
use std::hint::black_box;

use glam::{DVec2, DVec3};

use super::{Output, Record, Settings, timing};
use crate::plot::{self, BoxError, Panel, Series};
use raylemma::check::warp::square_point;
use raylemma::rng;
use raylemma::stats::ttest::Summary;
use raylemma::transport::shadow::{
    Heuristic, Light, QuadLight, SphereCone, SphereLight, Strategy, estimate_irradiance,
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

const STRATEGIES: [(&str, Strategy); 4] = [
    ("light", Strategy::Light),
    ("BSDF (cosine)", Strategy::Bsdf),
    ("MIS (balance)", Strategy::Mis(Heuristic::Balance)),
    ("MIS (power)", Strategy::Mis(Heuristic::Power)),
];

/// A square light of side `side` at height 1 above the origin, facing down; the shading
/// point is the origin with normal `+z`.
fn square_light(side: f64) -> Result<QuadLight, BoxError> {
    Ok(QuadLight::new(
        DVec3::new(0.3 - side / 2.0, -side / 2.0, 1.0),
        DVec3::new(0.0, side, 0.0),
        DVec3::new(side, 0.0, 0.0),
    )?)
}

/// `(exact, variance per sample, ns per sample)` of each strategy for one light.
fn measure(light: &QuadLight, settings: &Settings) -> Vec<(&'static str, f64, f64, f64)> {
    let (p, n) = (DVec3::ZERO, DVec3::Z);
    let exact = light.irradiance(p, n, 1.0);
    let samples = if settings.quick { 20_000 } else { 400_000 };
    STRATEGIES
        .iter()
        .map(|&(name, strategy)| {
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
            (name, exact, s.variance(), ns)
        })
        .collect()
}

const SIDES: [(&str, f64); 2] = [("small (0.1 × 0.1)", 0.1), ("large (6 × 6)", 6.0)];

fn strategies_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let mut md = String::new();
    writeln!(
        md,
        "| light | strategy | exact E | variance per sample / E² | ns per sample | relative efficiency |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---:|")?;
    for (label, side) in SIDES {
        let rows = measure(&square_light(side)?, settings);
        let best = rows.iter().map(|r| 1.0 / (r.2 * r.3)).fold(0.0, f64::max);
        for (name, exact, var, ns) in rows {
            writeln!(
                md,
                "| {label} | {name} | {exact:.4e} | {:.3e} | {ns:.0} | {:.2e} |",
                var / (exact * exact),
                1.0 / (var * ns) / best
            )?;
        }
    }
    writeln!(
        md,
        "\nShading point at the origin, normal +z, square light centred 0.3 off the normal at height 1. \
         Efficiency is 1 / (variance × time), relative to the best strategy for that light. \
         Timed on {}.",
        timing::machine()
    )?;
    Ok(md.into_bytes())
}

fn convergence_svg(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let mut panels = Vec::new();
    for (label, side) in SIDES {
        let rows = measure(&square_light(side)?, settings);
        let series = rows
            .into_iter()
            .map(|(name, exact, var, ns)| {
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

fn sphere_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let samples = if settings.quick { 20_000 } else { 400_000 };
    let mut md = String::new();
    writeln!(
        md,
        "| distance / radius | exact E | variance / E², cap area | variance / E², cone |"
    )?;
    writeln!(md, "|---:|---:|---:|---:|")?;
    for d in [1.05, 2.0, 10.0, 100.0] {
        let light = SphereLight::new(DVec3::new(0.0, 0.0, d), 1.0)?;
        let (p, n) = (DVec3::ZERO, DVec3::Z);
        let exact = sphere_irradiance(p, n, &light, 1.0);
        let variance = |l: &dyn Light| {
            let mut rng = rng::seeded(8);
            let mut s = Summary::default();
            for _ in 0..samples {
                let (u, v) = (square_point(&mut rng), square_point(&mut rng));
                s.push(estimate_irradiance(l, p, n, 1.0, Strategy::Light, u, v));
            }
            s.variance() / (exact * exact)
        };
        writeln!(
            md,
            "| {d} | {exact:.4e} | {:.3e} | {:.3e} |",
            variance(&light),
            variance(&SphereCone(light))
        )?;
    }
    writeln!(
        md,
        "\nOne light sample per estimate, {samples} estimates; shading normal towards the centre."
    )?;
    Ok(md.into_bytes())
}
