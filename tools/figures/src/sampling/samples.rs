//! The samples of the samplers, as scatter plots (`sampling_scatter.svg`, chapter *Uniform
//! sphere and hemisphere*) and as histograms against their pdfs (`sampling_histograms.svg`,
//! chapter *Cosine-weighted hemisphere*).

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::plot::{self, Legend, Panel, Series};
use crate::{Record, Settings};
use raylemma::check::warp;
use raylemma::rng::{self, Rng};
use raylemma::sampling::cosine::*;
use raylemma::sampling::disc::*;
use raylemma::sampling::sphere::*;

/// Azimuth in `[0, 2 pi)` and `cos(theta)`: the sphere's equal-area coordinates, in which a
/// uniform sampler looks uniform.
fn phi_z(w: DVec3) -> (f64, f64) {
    let phi = w.y.atan2(w.x);
    (if phi < 0.0 { phi + TAU } else { phi }, w.z)
}

pub(super) fn scatter_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut rng = rng::seeded(0x5CA7);
    let n = 2500;
    let sphere_icdf: Vec<_> = (0..n)
        .map(|_| phi_z(sphere_inverse_cdf(warp::square_point(&mut rng))))
        .collect();
    let sphere_gauss: Vec<_> = (0..n).map(|_| phi_z(sphere_gaussian(&mut rng))).collect();
    // One jittered sample per cell of a 24 x 24 grid: stratified samples.
    let k = 24;
    let strata: Vec<DVec2> = (0..k * k)
        .map(|c| {
            let (i, j) = ((c / k) as f64, (c % k) as f64);
            DVec2::new(
                (i + rng::uniform(&mut rng, 0.0, 1.0)) / k as f64,
                (j + rng::uniform(&mut rng, 0.0, 1.0)) / k as f64,
            )
        })
        .collect();
    let xy = |p: DVec3| (p.x, p.y);
    let malley: Vec<_> = (0..n)
        .map(|_| xy(cosine_malley(warp::square_point(&mut rng))))
        .collect();
    let sphere_panel = |title: &str, points| {
        Panel::new(title, "φ", "cos θ", vec![Series::dots("", points)])
            .x_range((0.0, TAU))
            .y_range((-1.0, 1.0))
    };
    let disc_panel = |title: &str, points| {
        Panel::new(title, "x", "y", vec![Series::dots("", points)])
            .x_range((-1.05, 1.05))
            .y_range((-1.05, 1.05))
    };
    let panels = [
        sphere_panel("sphere, inverse CDF (equal-area coordinates)", sphere_icdf),
        sphere_panel("sphere, Gaussian (equal-area coordinates)", sphere_gauss),
        disc_panel("cosine, Malley: (x, y) of the directions", malley),
        disc_panel(
            "polar map of 24 × 24 stratified samples",
            strata.iter().map(|&u| xy(disc_polar(u))).collect(),
        ),
        disc_panel(
            "concentric map of the same samples",
            strata.iter().map(|&u| xy(disc_concentric(u))).collect(),
        ),
    ];
    plot::chart(&panels, 2)
}

pub(super) fn histograms_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n = if settings.quick { 100_000 } else { 1_000_000 };
    let bins = 40;
    let histogram = |sample: &dyn Fn(&mut Rng) -> f64| {
        let mut rng = rng::seeded(0x4157);
        let mut counts = vec![0usize; bins];
        for _ in 0..n {
            let z = sample(&mut rng);
            counts[((z * bins as f64) as usize).min(bins - 1)] += 1;
        }
        counts
            .iter()
            .map(|&c| c as f64 / n as f64 * bins as f64)
            .collect::<Vec<_>>()
    };
    let edges: Vec<f64> = (0..=bins).map(|k| k as f64 / bins as f64).collect();
    let cosine = histogram(&|r| cosine_malley(warp::square_point(r)).z);
    let uniform =
        histogram(&|r| hemisphere_flip(sphere_inverse_cdf(warp::square_point(r)), DVec3::Z).z);
    let panel = |what: &str, method: &str, density: &[f64], pdf: Series| {
        Panel::new(
            format!("cos θ of {n} {what} samples"),
            "cos θ",
            "density",
            vec![
                Series::bars(format!("histogram ({method})"), &edges, density),
                pdf,
            ],
        )
        .x_range((0.0, 1.0))
        .legend(Legend::UpperLeft)
    };
    let panels = [
        panel(
            "cosine-weighted",
            "Malley",
            &cosine,
            Series::line("pdf 2 cos θ", vec![(0.0, 0.0), (1.0, 2.0)]),
        ),
        panel(
            "uniform hemisphere",
            "flipped inverse CDF",
            &uniform,
            Series::line("pdf 1", vec![(0.0, 1.0), (1.0, 1.0)]),
        )
        .y_range((0.0, 1.5)),
    ];
    plot::chart(&panels, 2)
}
