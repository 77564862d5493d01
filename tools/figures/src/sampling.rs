//! Figures and tables of the chapters *Checking a sampler*, *Uniform sphere and
//! hemisphere*, *The unit disc* and *Cosine-weighted hemisphere*.
//!
//! The modules, one per output or pair of outputs: [`samples`] (scatter plots and
//! histograms), [`distortion`] (the disc maps' distortion), [`methods`] (the methods
//! table), [`quarter_speed`] (the quarter-range series), [`power`] (the power against
//! planted bugs) and [`calibration`] (the false-failure rates). This module holds the
//! outputs, the correct samplers the tables run and their chi-squared p-value.

mod calibration;
mod distortion;
mod methods;
mod power;
mod quarter_speed;
mod samples;

use glam::{DVec2, DVec3};

use super::Output;
use raylemma::check::Options;
use raylemma::check::warp::{self, Domain, RngWarp, SquareWarp, Warp, WarpOptions};
use raylemma::rng::Rng;
use raylemma::sampling::cosine::*;
use raylemma::sampling::disc::*;
use raylemma::sampling::sphere::*;

/// The outputs of these chapters.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "sampling_scatter.svg",
            what: "sample scatter plots",
            make: samples::scatter_svg,
        },
        Output {
            file: "sampling_histograms.svg",
            what: "histograms against pdfs",
            make: samples::histograms_svg,
        },
        Output {
            file: "sampling_warped_grids.svg",
            what: "disc maps' distortion",
            make: distortion::warped_grids_svg,
        },
        Output {
            file: "sampling_distortion.md",
            what: "disc maps' anisotropy",
            make: distortion::distortion_md,
        },
        Output {
            file: "sampling_methods.md",
            what: "speed and accuracy of every sampler",
            make: methods::methods_md,
        },
        Output {
            file: "disc_quarter_speed.md",
            what: "the quarter-range series against the standard library's sin_cos",
            make: quarter_speed::quarter_speed_md,
        },
        Output {
            file: "sampling_power.md",
            what: "power against planted bugs",
            make: power::power_md,
        },
        Output {
            file: "sampling_calibration.svg",
            what: "p-values of correct samplers",
            make: calibration::calibration_svg,
        },
        Output {
            file: "sampling_calibration.md",
            what: "false-failure rates",
            make: calibration::calibration_md,
        },
    ]
}

type Boxed = Box<dyn Warp + Send>;

fn square_warp(
    name: &str,
    domain: Domain,
    sample: fn(DVec2) -> DVec3,
    pdf: fn(DVec3) -> f64,
) -> Boxed {
    Box::new(SquareWarp::new(name, domain, sample, pdf))
}

fn hemisphere_pdf_z(w: DVec3) -> f64 {
    hemisphere_pdf(w, DVec3::Z)
}

/// Every correct sampler of the sampling chapters.
fn correct_samplers() -> Vec<Boxed> {
    vec![
        square_warp(
            "sphere, inverse CDF",
            Domain::Sphere,
            sphere_inverse_cdf,
            sphere_pdf,
        ),
        Box::new(RngWarp {
            name: "sphere, Gaussian".into(),
            domain: Domain::Sphere,
            sample: sphere_gaussian,
            pdf: sphere_pdf,
        }),
        Box::new(RngWarp {
            name: "sphere, rejection".into(),
            domain: Domain::Sphere,
            sample: |r: &mut Rng| sphere_rejection(r).0,
            pdf: sphere_pdf,
        }),
        Box::new(RngWarp {
            name: "hemisphere, flipped inverse CDF".into(),
            domain: Domain::Sphere,
            sample: |r: &mut Rng| {
                hemisphere_flip(sphere_inverse_cdf(warp::square_point(r)), DVec3::Z)
            },
            pdf: hemisphere_pdf_z,
        }),
        square_warp("disc, polar", Domain::Disc, disc_polar, disc_pdf),
        square_warp("disc, concentric", Domain::Disc, disc_concentric, disc_pdf),
        square_warp(
            "cosine, seed angles",
            Domain::Sphere,
            cosine_seed_angles,
            cosine_pdf,
        ),
        square_warp(
            "cosine, seed Cartesian",
            Domain::Sphere,
            cosine_seed_cartesian,
            cosine_pdf,
        ),
        square_warp(
            "cosine, Malley (concentric)",
            Domain::Sphere,
            cosine_malley,
            cosine_pdf,
        ),
    ]
}

/// The chi-squared p-value of `w` with `samples` samples on a 21-row grid. An error
/// (which none of the figure's samplers should produce) is a NaN p-value, which every
/// table shows and no rate counts as a rejection.
fn chi2_p(w: &dyn Warp, samples: usize, seed: u64) -> f64 {
    let options = WarpOptions {
        resolution: 21,
        points: 0,
        ..WarpOptions::from(Options::default().cases(samples).seed(seed))
    };
    warp::chi_squared(w, &options).map_or(f64::NAN, |(c, _, _)| c.p_value)
}

/// A label as a value name, for a row added without a key of its own: lowercase words of
/// `a-z` and `0-9` joined by `_`.
fn value_name(label: &str) -> String {
    label
        .to_lowercase()
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join("_")
}
