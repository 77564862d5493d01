//! The checker of a Lambertian BRDF: any routine with the signature of
//! [`crate::transport::lambert::lambert_brdf`] (`f(rho, w_i, w_o)`, normal `+z`) can be
//! checked against the claims of the chapter *Lambertian reflectance*
//! (`chapters/transport/lambert.md`).
//!
//! * `albedo`: `∫ f cos θ_i dω_i = ρ` for every `w_o` above the surface (quadrature);
//! * `reciprocity`: `f(ρ, a, b) = f(ρ, b, a)`;
//! * `below`: `f = 0` when either direction is below the surface;
//! * `finite`: `f` is finite and non-negative above it.
//!
//! Planted bugs that it must reject are in [`planted`].

pub mod planted;

use glam::DVec3;

use super::{Finding, Options, Verdict};
use crate::rng;
use crate::sampling::sphere::sphere_uniform;
use crate::transport::lambert::albedo;

/// Default number of random direction pairs per claim.
pub const CASES: usize = 10_000;
/// Default seed.
pub const SEED: u64 = 0x1a3b;
/// Cells of the albedo quadrature (`n` by `2n` in `θ, φ`).
pub(crate) const QUADRATURE: usize = 512;
/// Bound of the albedo's relative error (the quadrature's is about `2e-6`).
pub(crate) const ALBEDO_BOUND: f64 = 1e-5;

/// Runs the chapter's claims on `f`; `options` sets the number of random pairs (default
/// [`CASES`]) and their seed (default [`SEED`]).
pub fn brdf(f: &dyn Fn(f64, DVec3, DVec3) -> f64, options: &Options) -> Verdict {
    let cases = options.cases_or(CASES);
    let mut rng = rng::seeded(options.seed_or(SEED));
    let mut verdict = Verdict::new("Lambertian BRDF");
    let mut albedo_ = Finding::new(
        "albedo",
        "int f cos(theta_i) dw_i = rho for every w_o above",
    )
    .in_unit("relative error");
    for rho in [0.1, 0.5, 1.0] {
        for z in [1.0_f64, 0.7, 0.3, 0.05] {
            let wo = DVec3::new((1.0 - z * z).sqrt(), 0.0, z);
            let a = albedo(|wi, wo| f(rho, wi, wo), wo, QUADRATURE);
            let error = (a / rho - 1.0).abs();
            albedo_.measure(error, ALBEDO_BOUND, || {
                format!("rho = {rho}, w_o = {wo:?}: albedo {a}")
            });
        }
    }
    let mut reciprocity = Finding::new("reciprocity", "f(rho, a, b) = f(rho, b, a)");
    let mut below = Finding::new("below", "f = 0 when w_i or w_o is below the surface");
    let mut finite = Finding::new("finite", "f is finite and >= 0 for directions above");
    for _ in 0..cases {
        let rho = rng::uniform(&mut rng, 0.0, 1.0);
        let (a, b) = (sphere_uniform(&mut rng), sphere_uniform(&mut rng));
        let (fab, fba) = (f(rho, a, b), f(rho, b, a));
        reciprocity.record(
            fab == fba || (fab - fba).abs() <= 4.0 * f64::EPSILON * fab.abs(),
            || format!("rho = {rho}, a = {a:?}, b = {b:?}: f(a, b) = {fab}, f(b, a) = {fba}"),
        );
        if a.z < 0.0 || b.z < 0.0 {
            below.record(fab == 0.0, || {
                format!("rho = {rho}, w_i = {a:?}, w_o = {b:?}: f = {fab}")
            });
        } else {
            finite.record(fab.is_finite() && fab >= 0.0, || {
                format!("rho = {rho}, w_i = {a:?}, w_o = {b:?}: f = {fab}")
            });
        }
    }
    verdict
        .findings
        .extend([albedo_, reciprocity, below, finite]);
    verdict
}
