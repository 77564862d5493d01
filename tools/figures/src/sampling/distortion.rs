//! The disc maps' distortion, as a table of their anisotropy (`sampling_distortion.md`) and
//! as warped grids (`sampling_warped_grids.svg`), of the chapter *The unit disc*.

use std::f64::consts::{FRAC_PI_4, PI};
use std::fmt::Write as _;

use glam::{DVec2, DVec3};

use crate::plot;
use crate::{Record, Settings};
use raylemma::sampling::disc::*;

pub(super) fn distortion_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let grid: Vec<DVec2> = (0..200)
        .flat_map(|i| {
            (0..200).map(move |j| DVec2::new((i as f64 + 0.5) / 200.0, (j as f64 + 0.5) / 200.0))
        })
        .collect();
    let mut md = String::new();
    writeln!(md, "| map | mean anisotropy | worst anisotropy |")?;
    writeln!(md, "|---|---:|---:|")?;
    // (mean, worst) anisotropy of each map.
    let mut maps = Vec::new();
    for (name, f) in [
        ("polar", disc_polar as fn(DVec2) -> DVec3),
        ("concentric", disc_concentric),
    ] {
        let a: Vec<f64> = grid.iter().map(|&u| anisotropy(f, u)).collect();
        let mean = a.iter().sum::<f64>() / a.len() as f64;
        let worst = a.iter().copied().fold(0.0, f64::max);
        maps.push((mean, worst));
        writeln!(
            md,
            "| {name} | {} | {} |",
            r.number(&format!("{name}.mean_anisotropy"), mean, ".2"),
            r.number(&format!("{name}.worst_anisotropy"), worst, ".1"),
        )?;
    }
    let (polar, concentric) = (maps[0], maps[1]);
    // The concentric map's closed form: in the wedge |a_x| > |a_y|, with t = a_y / a_x, its
    // Jacobian in the disc's polar frame is twice [[1, 0], [-pi/4 t, pi/4]]; the ratio of
    // its singular values is 4/pi at t = 0 and grows with |t| to its supremum at t = 1.
    let ratio = |t: f64| {
        let (a, b, c, d) = (1.0, 0.0, -FRAC_PI_4 * t, FRAC_PI_4);
        // Singular values of [[a, b], [c, d]]: from the trace and determinant of M^T M.
        let (tr, det) = (a * a + b * b + c * c + d * d, (a * d - b * c).powi(2));
        let root = (tr * tr - 4.0 * det).max(0.0).sqrt();
        ((tr + root) / (tr - root)).sqrt()
    };
    let (centre_line, supremum) = (ratio(0.0), ratio(1.0));
    r.number("concentric.centre_line_anisotropy", centre_line, ".2");
    r.number("concentric.supremum", supremum, ".2");
    r.claim(
        "concentric_below_sup",
        centre_line <= concentric.1 && concentric.1 <= supremum * (1.0 + 1e-12),
        format!(
            "concentric worst anisotropy {:.4} between 4/pi = {centre_line:.4} and the supremum {supremum:.4}",
            concentric.1
        ),
    );
    // The polar map's closed form: r = sqrt(u1), phi = 2 pi u2 stretch a cell by 1/(2 r)
    // radially and 2 pi r around, so the anisotropy is max(4 pi u1, 1 / (4 pi u1)); the
    // worst is at the grid's smallest u1 = 1/400.
    let closed = |u1: f64| (4.0 * PI * u1).max(1.0 / (4.0 * PI * u1));
    let closed_worst = closed(0.5 / 200.0);
    let closed_mean = (0..200)
        .map(|i| closed((f64::from(i) + 0.5) / 200.0))
        .sum::<f64>()
        / 200.0;
    let near = |x: f64, y: f64| (x - y).abs() <= 1e-3 * y;
    r.claim(
        "polar_closed_form",
        near(polar.1, closed_worst) && near(polar.0, closed_mean),
        format!(
            "polar worst anisotropy {:.4} against the closed form max(4 pi u1, 1/(4 pi u1)) at u1 = 1/400, {closed_worst:.4}; mean {:.4} against the closed form's mean over the grid, {closed_mean:.4}; each within 0.1 %",
            polar.1, polar.0
        ),
    );
    r.claim(
        "concentric_less_anisotropic",
        concentric.0 < polar.0 && concentric.1 < polar.1,
        format!(
            "concentric mean anisotropy {:.2} < polar {:.2}, and worst {:.1} < polar {:.1}",
            concentric.0, polar.0, concentric.1, polar.1
        ),
    );
    writeln!(
        md,
        "\n*Ratio of the larger to the smaller singular value of the map's Jacobian (1 = cells keep their shape), at the centres of a 200 × 200 grid of the unit square.*"
    )?;
    Ok(md.into_bytes())
}

pub(super) fn warped_grids_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    use plotters::prelude::*;
    plot::svg(plot::WIDTH, 420, |root, _| {
        type Map = fn(DVec2) -> DVec3;
        let maps: [(&str, Map); 2] = [
            ("polar map", disc_polar),
            ("concentric map", disc_concentric),
        ];
        for ((name, f), area) in maps.iter().zip(root.split_evenly((1, 2)).iter()) {
            let rest = plot::draw_title(area, name)?;
            let mut chart = ChartBuilder::on(&rest)
                .margin(15)
                .build_cartesian_2d(-1.05..1.05, -1.05..1.05)?;
            let lines = 12;
            for k in 0..=lines {
                let c = k as f64 / lines as f64;
                let along = |g: &dyn Fn(f64) -> DVec2| -> Vec<(f64, f64)> {
                    (0..=200)
                        .map(|s| f(g(f64::from(s) / 200.0)))
                        .map(|p| (p.x, p.y))
                        .collect()
                };
                let u1 = along(&|s| DVec2::new(c, s));
                let u2 = along(&|s| DVec2::new(s, c));
                chart.draw_series(LineSeries::new(u1, plot::PALETTE[0].stroke_width(1)))?;
                chart.draw_series(LineSeries::new(u2, plot::PALETTE[1].stroke_width(1)))?;
            }
        }
        Ok(())
    })
}
