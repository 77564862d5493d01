//! Each exercise's probe: its function run on fixed inputs, the outputs flattened (see
//! [`super`]). The probe of the crate's own function is in [`PROBES`]; the twins run the
//! same probe functions on themselves. The probe functions are in one file per part of the
//! book, as the twins are.

use crate::optics::{dispersion, fresnel, reflect, specular, thinfilm};
use crate::sampling::tabulated::{Piecewise1D, PiecewiseLinear1D};
use crate::sampling::{cosine, disc, importance, sphere};

mod optics;
mod sampling;
mod spectral;
mod transport;

pub use optics::*;
pub use sampling::*;
pub use spectral::*;
pub use transport::*;

/// A probe: a function run on fixed inputs, its outputs flattened.
pub type Probe = fn() -> Vec<f64>;

/// The probe of the crate's own function (the student's, in a hand-out), by exercise, in
/// the book's order.
pub const PROBES: &[(&str, Probe)] = &[
    ("intersect_stable", || {
        rays(crate::geometry::sphere::intersect_stable)
    }),
    ("estimate", || {
        estimates(|f, q, n, rng| importance::estimate(f, q, n, rng))
    }),
    ("sphere_rejection", || rejections(sphere::sphere_rejection)),
    ("hemisphere_flip", || flips(sphere::hemisphere_flip)),
    ("disc_polar", || square(disc::disc_polar)),
    ("disc_concentric", || square(disc::disc_concentric)),
    ("cosine_malley", || square(cosine::cosine_malley)),
    ("cosine_pdf", || directions(cosine::cosine_pdf)),
    ("Piecewise1D::sample", || table(Piecewise1D::sample)),
    ("PiecewiseLinear1D::sample", || {
        linear_table(PiecewiseLinear1D::sample)
    }),
    ("reflect", || reflect_probe(reflect::reflect)),
    ("refract", || refract_probe(reflect::refract)),
    ("amplitudes", || amplitude_probe(fresnel::amplitudes)),
    ("fresnel_transmittance", || {
        transmittance_probe(fresnel::fresnel_transmittance)
    }),
    ("schlick", || scalar_probe(fresnel::schlick)),
    ("narrow_lobe_brdf", || {
        lobe_probe(specular::narrow_lobe_brdf)
    }),
    ("Sellmeier::index", || {
        sellmeier_probe(dispersion::Sellmeier::index)
    }),
    ("airy_r", || airy_probe(thinfilm::airy_r)),
    ("lambert_brdf", || {
        brdfs(crate::transport::lambert::lambert_brdf)
    }),
    ("roulette", || {
        roulettes(crate::transport::roulette::roulette)
    }),
    ("area_to_solid_angle", || {
        areas(crate::transport::shadow::area_to_solid_angle)
    }),
    ("hero_uniform", || {
        heroes(crate::spectral::wavelength::hero_uniform)
    }),
    ("srgb_encode", || {
        encodings(crate::spectral::display::srgb_encode)
    }),
    ("srgb_decode", || {
        decodings(crate::spectral::display::srgb_decode)
    }),
];

/// The probe of exercise `name`'s function in this crate.
pub fn of(name: &str) -> Option<Probe> {
    PROBES.iter().find(|(n, _)| *n == name).map(|(_, p)| *p)
}
