//! Figures and tables of the chapter *The missing cosine in specular reflection*.

use std::fmt::Write as _;

use glam::{DVec2, DVec3};

use super::{Output, Record, Settings};
use crate::plot::{self, Panel, Series};
use raylemma::optics::specular::*;
use raylemma::rng;
use raylemma::stats::ttest::Summary;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "specular_lobe.svg",
            what: "narrow lobe against angle",
            make: lobe_svg,
        },
        Output {
            file: "specular_furnace.md",
            what: "white furnace",
            make: furnace_md,
        },
    ]
}

fn lobe_mean(kappa: f64, theta: f64, divide: bool, n: usize) -> f64 {
    let mut rng = rng::seeded(0x10BE);
    let w_o = DVec3::new(theta.sin(), 0.0, theta.cos());
    (0..n)
        .map(|_| {
            let u = DVec2::new(
                rng::uniform(&mut rng, 0.0, 1.0),
                rng::uniform(&mut rng, 0.0, 1.0),
            );
            reflected_radiance_sample(1.0, kappa, w_o, divide, u)
        })
        .sum::<f64>()
        / n as f64
}

fn lobe_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n = if settings.quick { 2_000 } else { 20_000 };
    let angles: Vec<f64> = (0..=44).map(|k| f64::from(k) * 2.0).collect();
    let mut series = Vec::new();
    for (kappa, divide) in [
        (10.0, true),
        (100.0, true),
        (1e4, true),
        (10.0, false),
        (1e4, false),
    ] {
        let label = format!(
            "kappa = {kappa:.0}, {}",
            if divide {
                "f = lobe / cos"
            } else {
                "f = lobe (bug)"
            }
        );
        let points = angles
            .iter()
            .map(|&deg| (deg, lobe_mean(kappa, deg.to_radians(), divide, n)))
            .collect();
        series.push(Series::line(label, points));
    }
    let panels = [Panel::new(
        "reflected radiance of a narrow lobe in a white furnace (ρ = 1)",
        "angle of the outgoing direction from the normal (degrees)",
        "reflected radiance",
        series,
    )];
    plot::chart(&panels, 1)
}

fn furnace_md(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n = if settings.quick { 2_000 } else { 100_000 };
    let mut md = String::new();
    writeln!(
        md,
        "| sphere | specular weight | mean radiance | standard deviation | mean bounces |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|")?;
    for material in [
        FurnaceMaterial::Mirror { rho: 1.0 },
        FurnaceMaterial::Glass { ior: 1.5 },
        FurnaceMaterial::Glass { ior: 2.4 },
    ] {
        for cosine in [CosineTerm::Cancelled, CosineTerm::Kept] {
            let mut rng = rng::seeded(0xF0);
            let mut bounces = 0u64;
            let s = Summary::of((0..n).map(|_| {
                let ray = furnace_camera_ray(&mut rng);
                let path = furnace_path(ray, material, cosine, &mut rng);
                bounces += u64::from(path.bounces);
                path.radiance
            }));
            let name = match material {
                FurnaceMaterial::Mirror { .. } => "mirror".to_string(),
                FurnaceMaterial::Glass { ior } => format!("glass, n = {ior}"),
            };
            let weight = if cosine == CosineTerm::Cancelled {
                "1 (delta, cosine cancelled)"
            } else {
                "cos θ (bug)"
            };
            writeln!(
                md,
                "| {name} | {weight} | {:.6} | {:.2e} | {:.2} |",
                s.mean,
                s.variance().sqrt(),
                bounces as f64 / n as f64
            )?;
        }
    }
    writeln!(
        md,
        "\n*{n} paths per row from 3 radii away, aimed uniformly over the sphere's silhouette; environment radiance 1.*"
    )?;
    Ok(md.into_bytes())
}
