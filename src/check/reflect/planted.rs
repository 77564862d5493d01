//! Planted bugs of the reflection and refraction checker: the source notes' reflection and
//! refractions with the classic mistakes, each of which [`super::reflection`] or
//! [`super::refraction`] must reject on the claims it breaks. Chapter: *Reflection and
//! refraction* (`chapters/optics/reflect.md`).
//!
//! The chapter's tests (`tests/book/optics/reflect.rs`) and its table of verdicts
//! (`tools/figures/src/reflect.rs`) use these one copies.

use glam::DVec3;

use crate::optics::reflect::{Refraction, refract};

/// The incident side's normal: `n` or `-n`, whichever faces `w_i`.
fn facing(w_i: DVec3, n: DVec3) -> DVec3 {
    if w_i.dot(n) <= 0.0 { n } else { -n }
}

// ANCHOR: seed_reflect
/// The source notes' reflection, `w_o = 2n + w_i`, with `n` the normal facing the light as the
/// source notes intend. Right only at normal incidence: it drops the factor `cos(theta_i)`.
pub fn seed_reflect(w_i: DVec3, n: DVec3) -> DVec3 {
    2.0 * facing(w_i, n) + w_i
}
// ANCHOR_END: seed_reflect

/// Refraction with `cos_t^2` used where `cos_t` belongs (the square root forgotten).
pub fn refract_without_sqrt(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    let m = facing(w_i, n);
    let cos_i = -w_i.dot(m);
    let ratio = n1 / n2;
    let cos2_t = 1.0 - ratio * ratio * (1.0 - cos_i * cos_i);
    if cos2_t < 0.0 {
        return Refraction::TotalInternalReflection;
    }
    Refraction::Transmitted(ratio * w_i + (ratio * cos_i - cos2_t) * m)
}

/// Refraction with the ratio of indices upside down, `eta = n2 / n1`.
pub fn refract_swapped_indices(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    refract(w_i, n, n2, n1)
}

/// Refraction without the total-internal-reflection test: past the critical angle the
/// square root of a negative number makes the direction NaN.
pub fn refract_nan_tir(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    let m = facing(w_i, n);
    let cos_i = -w_i.dot(m);
    let ratio = n1 / n2;
    let cos_t = (1.0 - ratio * ratio * (1.0 - cos_i * cos_i)).sqrt();
    Refraction::Transmitted(ratio * w_i + (ratio * cos_i - cos_t) * m)
}

/// Refraction that trusts `n` to face the light (the source notes' "outward facing normal"
/// assumption) and never flips it.
pub fn refract_unflipped_normal(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    let cos_i = -w_i.dot(n);
    let ratio = n1 / n2;
    let cos2_t = 1.0 - ratio * ratio * (1.0 - cos_i * cos_i);
    if cos2_t < 0.0 {
        return Refraction::TotalInternalReflection;
    }
    Refraction::Transmitted(ratio * w_i + (ratio * cos_i - cos2_t.sqrt()) * n)
}

/// A reflection that returns NaN for every input. Fails `finite` and `unit_length`.
pub fn reflect_nan(_w_i: DVec3, _n: DVec3) -> DVec3 {
    DVec3::NAN
}

/// The identity, `w_o = w_i`: unit length, coplanar and reversible, so only the angle
/// claim (`equal_angles`) sees it.
pub fn reflect_identity(w_i: DVec3, _n: DVec3) -> DVec3 {
    w_i
}
