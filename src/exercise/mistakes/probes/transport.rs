//! The probes of the transport chapters' exercises (see [`super`]).

use glam::DVec3;

/// Probe inputs of a BRDF: two albedos and every ordered pair of five directions (three
/// above the surface, two below); the outputs are `f`'s values.
pub fn brdfs(f: fn(f64, DVec3, DVec3) -> f64) -> Vec<f64> {
    let directions = [
        DVec3::Z,
        DVec3::new(0.6, 0.0, 0.8),
        DVec3::new(0.0, -0.28, 0.96),
        DVec3::new(0.8, 0.0, -0.6),
        DVec3::new(0.0, 0.6, -0.8),
    ];
    [0.2, 0.7]
        .into_iter()
        .flat_map(|rho| {
            directions
                .into_iter()
                .flat_map(move |wi| directions.into_iter().map(move |wo| f(rho, wi, wo)))
        })
        .collect()
}

/// Probe inputs of Russian roulette: two values, survival probabilities 0, 1/4, 1/2, 1 and
/// seven points `u` (0 and each probability among them); the outputs are `f`'s values.
pub fn roulettes(f: fn(f64, f64, f64) -> f64) -> Vec<f64> {
    let mut out = Vec::new();
    for value in [1.0, 0.3] {
        for p in [0.0, 0.25, 0.5, 1.0] {
            for u in [0.0, 0.1, 0.25, 0.4, 0.5, 0.75, 0.999] {
                out.push(f(value, p, u));
            }
        }
    }
    out
}

/// Probe inputs of the change of variables: area densities 0.5 and 2, distances 0.5 and 3,
/// cosines 0.8, -0.3, 0 and -0; the outputs are `f`'s values.
pub fn areas(f: fn(f64, f64, f64) -> f64) -> Vec<f64> {
    let mut out = Vec::new();
    for pdf_area in [0.5, 2.0] {
        for dist in [0.5, 3.0] {
            for cos_light in [0.8, -0.3, 0.0, -0.0] {
                out.push(f(pdf_area, dist, cos_light));
            }
        }
    }
    out
}
