//! The probes of the sampling and geometry chapters' exercises (see [`super`]).

use glam::{DVec2, DVec3};

use crate::exercise::registry::EstimateFn;
use crate::geometry::{Ray, Sphere};
use crate::sampling::tabulated::{Piecewise1D, PiecewiseLinear1D, Sample};
use crate::sampling::{importance, sphere};

/// Probe inputs on the unit square: a 7 x 7 grid inside it and its four corners; the
/// outputs are every coordinate of every point, in order.
pub fn square(f: fn(DVec2) -> DVec3) -> Vec<f64> {
    let grid = (1..=7).flat_map(|i| (1..=7).map(move |j| DVec2::new(i as f64, j as f64) / 8.0));
    let corners = [DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ONE];
    grid.chain(corners).flat_map(|u| f(u).to_array()).collect()
}

/// Probe inputs of a ray-sphere intersector: rays from outside, inside and beyond, with
/// unit and non-unit directions, a near miss and `t_min` above the first root; the outputs
/// are the `t` returned, NaN for a miss.
pub fn rays(f: fn(&Ray, &Sphere, f64) -> Option<f64>) -> Vec<f64> {
    let unit = Sphere::new(DVec3::ZERO, 1.0);
    let big = Sphere::new(DVec3::new(1.0, 2.0, 3.0), 2.0);
    let below = DVec3::new(0.0, 0.0, -3.0);
    let cases = [
        (Ray::new(below, DVec3::Z), unit, 0.0),
        (Ray::new(below, DVec3::Z), unit, 2.5),
        (Ray::new(below, DVec3::Z), unit, 5.0),
        (Ray::new(DVec3::ZERO, DVec3::Z), unit, 0.0),
        (Ray::new(below, 2.0 * DVec3::Z), unit, 0.0),
        (Ray::new(DVec3::new(0.5, 0.0, -3.0), DVec3::Z), unit, 1e-3),
        (Ray::new(DVec3::new(1.001, 0.0, -3.0), DVec3::Z), unit, 1e-3),
        (
            Ray::new(DVec3::new(1.0, 2.0, -5.0), DVec3::new(0.0, 0.0, 0.5)),
            big,
            0.0,
        ),
        (
            Ray::new(DVec3::new(-4.0, 2.5, 3.0), DVec3::new(3.0, 0.0, 0.0)),
            big,
            1e-3,
        ),
    ];
    cases
        .iter()
        .map(|(ray, sphere, t_min)| f(ray, sphere, *t_min).unwrap_or(f64::NAN))
        .collect()
}

/// Probe inputs of an importance-sampling estimator, drawn from a fixed seed: `x^2` under
/// the uniform and matched proposals, `1 + x` under the linear one, and `x^2` under uniform
/// draws whose density is 0 above 1/2; the outputs are each summary's count, mean and
/// variance.
pub fn estimates(f: EstimateFn) -> Vec<f64> {
    let mut rng = crate::rng::seeded(0x9b0e);
    let plus_one = |x: f64| 1.0 + x;
    let wrong_half = importance::Proposal {
        name: "uniform draws, density 0 above 1/2",
        sample: |u| u,
        pdf: importance::HALF_SUPPORT.pdf,
    };
    type Case<'a> = (&'a dyn Fn(f64) -> f64, importance::Proposal, usize); // f, q, n
    let cases: [Case; 4] = [
        (&importance::square, importance::UNIFORM, 8),
        (&plus_one, importance::LINEAR, 8),
        (&importance::square, importance::MATCHED, 4),
        (&importance::square, wrong_half, 8),
    ];
    cases
        .iter()
        .flat_map(|&(g, q, n)| {
            let s = f(g, &q, n, &mut rng);
            [s.n as f64, s.mean, s.variance()]
        })
        .collect()
}

/// Probe outputs of a rejection sampler: 16 directions from a fixed seed, each with the
/// number of draws it reports.
pub fn rejections(f: fn(&mut crate::rng::Rng) -> (DVec3, u32)) -> Vec<f64> {
    let mut rng = crate::rng::seeded(0x5eed_ba11);
    (0..16)
        .flat_map(|_| {
            let (w, tries) = f(&mut rng);
            [w.x, w.y, w.z, f64::from(tries)]
        })
        .collect()
}

/// Fixed directions over the whole sphere: the uniform map of a 6 x 6 grid of cell centres.
pub fn sphere_grid() -> impl Iterator<Item = DVec3> {
    (0..6)
        .flat_map(|i| (0..6).map(move |j| DVec2::new(i as f64, j as f64) / 6.0 + 1.0 / 12.0))
        .map(sphere::sphere_inverse_cdf)
}

/// Probe inputs of a hemisphere flip: the directions of [`sphere_grid`] around `+z`, a
/// tilted normal and `-x`; the outputs are every coordinate of every result.
pub fn flips(f: fn(DVec3, DVec3) -> DVec3) -> Vec<f64> {
    let normals = [DVec3::Z, DVec3::new(0.3, -0.5, 0.8).normalize(), -DVec3::X];
    normals
        .into_iter()
        .flat_map(|n| sphere_grid().flat_map(move |w| f(w, n).to_array()))
        .collect()
}

/// Probe inputs of a density on the sphere: the directions of [`sphere_grid`], both
/// hemispheres.
pub fn directions(f: fn(DVec3) -> f64) -> Vec<f64> {
    sphere_grid().map(f).collect()
}

/// The probe values of `u` for a table whose CDF at the edges is `levels`: twenty evenly
/// spaced in `[0, 1)`, every level (where the textbook search lands in bins of zero mass),
/// and `u` just below 1.
pub fn table_us(levels: &[f64]) -> Vec<f64> {
    let below_one = 1.0 - f64::EPSILON / 2.0;
    (0..20)
        .map(|k| f64::from(k) / 20.0)
        .chain(levels.iter().copied())
        .chain([below_one])
        .map(|u: f64| u.min(below_one))
        .collect()
}

/// A tabulated sample's outputs: `x`, `pdf`, `bin`, and 1 if the density is positive, else
/// 0 (a sampler left at a zero-valued end differs from the right one by a float's step in
/// `x` and a density of about `1e-16`, both lost in [`crate::exercise::mistakes::fingerprint`]'s rounding: only
/// the density's sign tells them apart).
pub fn sample_outputs(s: Sample) -> [f64; 4] {
    [s.x, s.pdf, s.bin as f64, f64::from(u8::from(s.pdf > 0.0))]
}

/// Probe inputs of a piecewise-constant sampler: the checker's three tables at
/// [`table_us`]; the outputs are each sample's [`sample_outputs`].
pub fn table(f: fn(&Piecewise1D, f64) -> Sample) -> Vec<f64> {
    tabulated(
        &crate::check::tabulated::tables(),
        Piecewise1D::cdf_table,
        f,
    )
}

/// The same for a piecewise-linear sampler, on the checker's three linear tables.
pub fn linear_table(f: fn(&PiecewiseLinear1D, f64) -> Sample) -> Vec<f64> {
    tabulated(
        &crate::check::tabulated::linear_tables(),
        PiecewiseLinear1D::cdf_table,
        f,
    )
}

/// A tabulated sampler `f` on `tables` at each table's [`table_us`] (read from its CDF,
/// `cdf`): every sample's [`sample_outputs`].
fn tabulated<T>(tables: &[(&str, T)], cdf: fn(&T) -> &[f64], f: fn(&T, f64) -> Sample) -> Vec<f64> {
    tables
        .iter()
        .flat_map(|(_, t)| {
            table_us(cdf(t))
                .into_iter()
                .flat_map(move |u| sample_outputs(f(t, u)))
        })
        .collect()
}
