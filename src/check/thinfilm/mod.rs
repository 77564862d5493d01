//! The checker of the Airy sum of a thin film: any routine with the signature of
//! [`crate::optics::thinfilm::airy_r`] (`f(r12, r23, δ)`, complex) can be checked against
//! the claims of the chapter *Thin-film interference* (`chapters/optics/thinfilm.md`).
//!
//! * `series`: `r` is the sum of the multiply reflected waves,
//!   `r12 + (1 − r12²) r23 z Σ_k (−r12 r23 z)^k` with `z = e^{2iδ}`, summed here term by
//!   term (real and complex coefficients, real and evanescent phases);
//! * `bare`: `r23 = 0` leaves `r12`, and `r12 = 0` leaves `r23 e^{2iδ}`;
//! * `quarter_wave`: `r12 = r23` with `δ = π/2` cancels, `r = 0`;
//! * `period`: `r(δ + π) = r(δ)` for real `δ`;
//! * `energy`: `|r| ≤ 1` for real `r12`, `r23` in `[−1, 1]` and real `δ`.
//!
//! Planted bugs that it must reject are in [`planted`].

pub mod planted;

use num_complex::Complex64;

use super::{Finding, Options, Verdict};
use crate::rng::{self, Rng};

/// Default number of random cases per claim.
pub const CASES: usize = 5_000;
/// Default seed.
pub const SEED: u64 = 0xa1e7;
/// Bound of the absolute errors.
pub const BOUND: f64 = 1e-12;

/// The multiple-reflection series, summed until its terms are below `1e-18`.
pub fn series(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    let z = (Complex64::new(0.0, 2.0) * delta).exp();
    let ratio = -r12 * r23 * z;
    let mut term = (1.0 - r12 * r12) * r23 * z;
    let mut sum = r12;
    for _ in 0..100_000 {
        sum += term;
        if term.norm() < 1e-18 {
            break;
        }
        term *= ratio;
    }
    sum
}

fn coefficient(rng: &mut Rng, complex: bool) -> Complex64 {
    let (r, phase) = (rng::uniform(rng, 0.0, 0.9), rng::uniform(rng, -3.1, 3.1));
    if complex {
        Complex64::from_polar(r, phase)
    } else {
        Complex64::new(r * phase.signum(), 0.0)
    }
}

/// Runs the chapter's claims on `f`; `options` sets the number of cases (default
/// [`CASES`]) and their seed (default [`SEED`]).
pub fn airy(
    f: &dyn Fn(Complex64, Complex64, Complex64) -> Complex64,
    options: &Options,
) -> Verdict {
    let cases = options.cases_or(CASES);
    let mut rng = rng::seeded(options.seed_or(SEED));
    let mut sum = Finding::new("series", "r = the sum of the multiply reflected waves")
        .in_unit("absolute error of the amplitude");
    let mut bare = Finding::new("bare", "r23 = 0 gives r12; r12 = 0 gives r23 e^(2 i delta)")
        .in_unit("absolute error of the amplitude");
    let mut period = Finding::new("period", "r(delta + pi) = r(delta) for real delta")
        .in_unit("absolute error of the amplitude");
    let mut energy = Finding::new(
        "energy",
        "|r| <= 1 for real r12, r23 in [-0.9, 0.9], real delta",
    )
    .in_unit("excess of |r|^2 over 1");
    let zero = Complex64::new(0.0, 0.0);
    for k in 0..cases {
        let complex = k % 2 == 1;
        let (r12, r23) = (
            coefficient(&mut rng, complex),
            coefficient(&mut rng, complex),
        );
        let re = rng::uniform(&mut rng, -10.0, 10.0);
        let im = if k % 3 == 0 {
            rng::uniform(&mut rng, 0.0, 2.0)
        } else {
            0.0
        };
        let delta = Complex64::new(re, im);
        let (got, want) = (f(r12, r23, delta), series(r12, r23, delta));
        sum.measure((got - want).norm(), BOUND, || {
            format!("r12 = {r12}, r23 = {r23}, delta = {delta}: r = {got}, the series gives {want}")
        });
        let only_first = f(r12, zero, delta);
        let only_second = f(zero, r23, delta);
        let z = (Complex64::new(0.0, 2.0) * delta).exp();
        let error = (only_first - r12)
            .norm()
            .max((only_second - r23 * z).norm());
        bare.measure(error, BOUND, || {
            format!("r12 = {r12}, r23 = {r23}, delta = {delta}: f(r12, 0) = {only_first}, f(0, r23) = {only_second}")
        });
        let real = Complex64::new(re, 0.0);
        let shifted = f(r12, r23, real + std::f64::consts::PI);
        let base = f(r12, r23, real);
        period.measure((shifted - base).norm(), BOUND, || {
            format!("r12 = {r12}, r23 = {r23}, delta = {re}: r = {base}, r(delta + pi) = {shifted}")
        });
        if !complex {
            let r = base.norm();
            energy.measure((r - 1.0).max(0.0), BOUND, || {
                format!("r12 = {r12}, r23 = {r23}, delta = {re}: |r| = {r}")
            });
        }
    }
    let mut quarter = Finding::new("quarter_wave", "r12 = r23 and delta = pi/2 give r = 0")
        .in_unit("absolute error of the amplitude");
    for rho in [0.02, 0.2, 0.5, -0.3] {
        let c = Complex64::new(rho, 0.0);
        let got = f(c, c, Complex64::new(std::f64::consts::FRAC_PI_2, 0.0));
        quarter.measure(got.norm(), BOUND, || {
            format!("r12 = r23 = {rho}: r = {got}")
        });
    }
    let mut verdict = Verdict::new("Airy sum");
    verdict
        .findings
        .extend([sum, bare, quarter, period, energy]);
    verdict
}
