//! The checker of a narrow lobe standing in for the mirror's delta: any routine with the
//! signature `f(rho, lobe_pdf, w_i)` of
//! [`crate::optics::specular::narrow_lobe_brdf`] (with its `divide_by_cos` set) can be
//! checked against the claims of the chapter *The missing cosine in specular reflection*
//! (`chapters/optics/specular.md`).
//!
//! * `reflected_radiance`: in a unit environment, every sample `f |cos θ_i| / pdf` of the
//!   reflected radiance, `w_i` drawn from the lobe itself, is exactly `ρ`: the BRDF's
//!   `1 / |cos θ_i|` cancels the rendering equation's cosine, whatever the lobe's width;
//! * `below`: `f = 0` for `w_i` below the surface, and on it (`w_i.z = 0`, where
//!   `1 / |cos θ_i|` is infinite and a sample `f |cos θ_i| / pdf` would be `∞ · 0`, NaN);
//! * `finite`: `f` is finite and non-negative above it.
//!
//! The planted bug is the chapter's own: the lobe without the `1 / |cos θ_i|`
//! (`narrow_lobe_brdf(.., false)`), which returns `ρ cos θ_i` instead. Another, which
//! divides by a grazing cosine of 0, is in [`planted`].

pub mod planted;

use glam::{DVec2, DVec3};

use super::{Finding, Options, Verdict};
use crate::optics::specular::sample_lobe;
use crate::rng;
use crate::sampling::sphere::sphere_uniform;

/// Default number of lobe samples per concentration.
pub const CASES: usize = 5_000;
/// Default seed.
pub const SEED: u64 = 0x5bec;
/// Bound of `|sample / ρ - 1|`, in units of `f64::EPSILON`.
pub const BOUND: f64 = 8.0;
/// The lobes' concentrations: from broad to nearly a delta.
pub(crate) const KAPPAS: [f64; 3] = [10.0, 1e3, 1e5];

/// Runs the chapter's claims on `f`; `options` sets the number of samples (default
/// [`CASES`]) and their seed (default [`SEED`]).
pub fn delta(f: &dyn Fn(f64, f64, DVec3) -> f64, options: &Options) -> Verdict {
    let cases = options.cases_or(CASES);
    let mut rng = rng::seeded(options.seed_or(SEED));
    let mut radiance = Finding::new(
        "reflected_radiance",
        "every sample f |cos theta_i| / pdf of a unit environment's reflection is rho",
    )
    .in_unit("relative error in machine epsilons");
    let mut below = Finding::new("below", "f = 0 for w_i below the surface and on it");
    let mut finite = Finding::new("finite", "f is finite and >= 0 above the surface");
    for kappa in KAPPAS {
        for _ in 0..cases {
            let rho = rng::uniform(&mut rng, 0.05, 1.0);
            let mut w_o = sphere_uniform(&mut rng);
            w_o.z = w_o.z.abs().max(0.05);
            let w_o = w_o.normalize();
            let mirror = DVec3::new(-w_o.x, -w_o.y, w_o.z);
            let u = DVec2::new(
                rng::uniform(&mut rng, 0.0, 1.0),
                rng::uniform(&mut rng, 0.0, 1.0),
            );
            let (w_i, pdf) = sample_lobe(mirror, kappa, u);
            let value = f(rho, pdf, w_i);
            if w_i.z <= 0.0 {
                below.record(value == 0.0, || {
                    format!("rho = {rho}, lobe pdf = {pdf:e}, w_i = {w_i:?}: f = {value}")
                });
                continue;
            }
            finite.record(value.is_finite() && value >= 0.0, || {
                format!("rho = {rho}, lobe pdf = {pdf:e}, w_i = {w_i:?}: f = {value}")
            });
            let sample = value * w_i.z / pdf;
            radiance.measure((sample / rho - 1.0).abs() / f64::EPSILON, BOUND, || {
                format!(
                    "kappa = {kappa:e}, rho = {rho}, w_o = {w_o:?}, w_i = {w_i:?} (cos theta_i = {:.6}): f cos / pdf = {sample}, want rho",
                    w_i.z
                )
            });
        }
    }
    // Exactly grazing directions, which the lobes almost never draw: `f = 0` there too.
    for k in 0..8 {
        let phi = std::f64::consts::TAU * k as f64 / 8.0;
        let w_i = DVec3::new(phi.cos(), phi.sin(), 0.0);
        let (rho, pdf) = (0.5, 1.0);
        let value = f(rho, pdf, w_i);
        below.record(value == 0.0, || {
            format!("rho = {rho}, lobe pdf = {pdf:e}, w_i = {w_i:?} (on the surface): f = {value}")
        });
    }
    let mut verdict = Verdict::new("specular lobe BRDF");
    verdict.findings.extend([radiance, below, finite]);
    verdict
}
