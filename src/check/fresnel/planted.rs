//! Planted bugs of the reflectance checker: reflectance routines with the classic
//! mistakes, each of which [`super::reflectance`] must reject on the claims it breaks.
//! Chapter: *Fresnel and Schlick* (`chapters/optics/fresnel.md`).
//!
//! The chapter's tests (`tests/book/optics/fresnel.rs`) and its table of verdicts
//! (`tools/figures/src/fresnel.rs`) use these one copies. The source notes' Schlick,
//! [`crate::optics::fresnel::schlick_seed`], is not here: it is a derivation of the
//! chapter, measured there.

use crate::optics::fresnel::{Amplitudes, amplitudes, fresnel_polarized};

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

/// Schlick with the fourth power, `R0 + (1 - R0)(1 - cos)^4` (cosine on the less dense
/// side): it keeps every claim of a reflectance an approximation keeps (range, normal,
/// grazing, TIR, reciprocity), and [`super::schlick`] must reject it.
pub fn schlick_fourth_power(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let c = cos_i.abs().min(1.0);
    // The cosine on the less dense side.
    let cos = match crate::optics::fresnel::cos_transmitted(c, n1, n2) {
        _ if n1 <= n2 => c,
        Some(cos_t) => cos_t,
        None => return 1.0,
    };
    let r0 = crate::optics::fresnel::r0(n1, n2);
    r0 + (1.0 - r0) * (1.0 - cos).powi(4)
}

/// Planted bugs of the amplitude checker [`super::amplitudes`]: amplitude routines with a
/// mistake that no reflectance sees (`R = r^2` hides every sign).
pub mod amplitude {
    use super::{Amplitudes, amplitudes};

    /// The special case this library once had: `(r_s, r_p, t_s, t_p) = (-1, +1, 0, 0)` at
    /// exactly `cos_i = 0`, where the limit of `r_p` is `-1` (a jump at the end).
    pub fn grazing_jump(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
        let a = amplitudes(cos_i, n1, n2)?;
        if cos_i == 0.0 && n1 != n2 {
            return Some(Amplitudes { r_p: 1.0, ..a });
        }
        Some(a)
    }

    /// `r_p` in the other common convention (the source notes' sign, `r_p = r_s` at normal
    /// incidence) with `t_p` left as Born & Wolf's: two conventions mixed.
    pub fn other_sign_of_r_p(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
        let a = amplitudes(cos_i, n1, n2)?;
        Some(Amplitudes { r_p: -a.r_p, ..a })
    }

    /// The transmission amplitudes forgotten (`t_s = t_p = 0`): invisible to a
    /// reflectance built from `r` alone.
    pub fn no_transmission(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
        let a = amplitudes(cos_i, n1, n2)?;
        Some(Amplitudes {
            t_s: 0.0,
            t_p: 0.0,
            ..a
        })
    }
}
