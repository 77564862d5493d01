//! Planted bugs of the reflectance checker: reflectance routines with the classic
//! mistakes, each of which [`super::reflectance`] must reject on the claims it breaks.
//! Chapter: *Fresnel and Schlick* (`chapters/optics/fresnel.md`).
//!
//! The chapter's tests (`tests/book/optics/fresnel.rs`) and its table of verdicts
//! (`tools/figures/src/fresnel.rs`) use these one copies. The seed's Schlick,
//! [`crate::optics::fresnel::schlick_seed`], is not here: it is a derivation of the
//! chapter, measured there.

use crate::optics::fresnel::{amplitudes, fresnel_polarized};

/// The textbook formula with no special cases: `cos_t = sqrt(1 - eta^2 sin^2)` becomes
/// NaN past the critical angle, and matched indices at grazing incidence give `0/0`.
pub fn fresnel_naive(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let ratio = n1 / n2;
    let cos_t = (1.0 - ratio * ratio * (1.0 - cos_i * cos_i)).sqrt();
    let r_s = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    let r_p = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    0.5 * (r_s * r_s + r_p * r_p)
}

/// `R = 1 - T` with `T = t^2`, forgetting the factor `(n2 cos_t) / (n1 cos_i)`.
pub fn fresnel_without_beam_factor(cos_i: f64, n1: f64, n2: f64) -> f64 {
    match amplitudes(cos_i, n1, n2) {
        Some(a) => 1.0 - 0.5 * (a.t_s * a.t_s + a.t_p * a.t_p),
        None => 1.0,
    }
}

/// `R_p` computed with the cosines paired as for `R_s` (so `R_p = R_s`): no Brewster
/// angle.
pub fn fresnel_p_paired_like_s(cos_i: f64, n1: f64, n2: f64) -> f64 {
    fresnel_polarized(cos_i, n1, n2).s
}
