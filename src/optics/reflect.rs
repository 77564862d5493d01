//! Mirror reflection and Snell refraction in vector form. Chapter: *Reflection and
//! refraction* (`chapters/optics/reflect.md`).
//!
//! # Convention
//!
//! * `w_i` is the direction the light *travels*, so it points **towards** the surface.
//! * `n` is a unit normal of the surface, on **either** side: the routines work out which
//!   side the light comes from.
//! * Results point **away** from the surface: the reflected ray back into the incident
//!   medium, the transmitted ray into the other one.
//! * `n1` is the refractive index of the medium the light arrives in, `n2` that of the
//!   medium on the far side.
//!
//! Inputs are unit vectors; the outputs are then unit vectors to within a few ulps.
//! Total internal reflection is returned as [`Refraction::TotalInternalReflection`],
//! never as a NaN direction.
//!
//! The source notes write the reflection as `w_o = 2n + w_i`, which is wrong except at
//! normal incidence; see [`crate::check::reflect::planted::seed_reflect`] and the chapter.
//!
//! The chapter's checker, which any routine with the signatures of [`reflect`] and
//! [`refract`] can be run through, is [`crate::check::reflect`]; its planted bugs are in
//! [`crate::check::reflect::planted`].

use glam::DVec3;

// ANCHOR: reflect
// EXERCISE optics/reflect reflect: mirror reflection of w_i about the normal n
/// Mirror reflection of the incident direction `w_i` about the normal `n` (either side):
/// `w_o = w_i - 2 (w_i . n) n`.
///
/// The component of `w_i` along the normal changes sign, the component in the surface is
/// kept. The result does not depend on the sign of `n`, since `n` appears twice.
pub fn reflect(w_i: DVec3, n: DVec3) -> DVec3 {
    w_i - 2.0 * w_i.dot(n) * n
}
// END EXERCISE
// ANCHOR_END: reflect

// ANCHOR: refraction_enum
/// The outcome of [`refract`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refraction {
    /// The transmitted direction: unit length, pointing away from the surface into the
    /// medium of index `n2`.
    Transmitted(DVec3),
    /// There is no transmitted ray, `(n1 / n2) sin(theta_i) > 1`: all the light is
    /// reflected (use [`reflect`] for its direction).
    TotalInternalReflection,
}
// ANCHOR_END: refraction_enum

impl Refraction {
    /// The transmitted direction, or `None` under total internal reflection.
    pub fn transmitted(self) -> Option<DVec3> {
        match self {
            Refraction::Transmitted(w_t) => Some(w_t),
            Refraction::TotalInternalReflection => None,
        }
    }
}

// ANCHOR: refract
// EXERCISE optics/reflect refract: Snell refraction of w_i from index n1 into n2, or total internal reflection
/// Snell refraction of the incident direction `w_i`, travelling in the medium of index
/// `n1`, into the medium of index `n2`, at a surface with unit normal `n` (either side).
///
/// With `m` the normal on the incident side (`w_i . m <= 0`), `cos_i = -w_i . m` and
/// `eta = n1 / n2`, the transmitted ray keeps the surface component of `w_i` scaled by
/// `eta` and gets the normal component `-cos_t m`:
/// `w_t = eta (w_i + cos_i m) - cos_t m`, with
/// `cos_t^2 = 1 - eta^2 sin_i^2 = (1 - eta^2) + (eta cos_i)^2`.
/// A negative `cos_t^2` is total internal reflection.
pub fn refract(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    let mut m = n;
    let mut cos_i = -w_i.dot(m);
    if cos_i < 0.0 {
        // The normal was given on the far side: use the one facing the light.
        m = -m;
        cos_i = -cos_i;
    }
    let eta = n1 / n2;
    // 1 - eta^2 sin^2, written so that for n1 < n2 it is a sum of two positive terms.
    let cos2_t = (1.0 - eta * eta) + (eta * cos_i) * (eta * cos_i);
    if cos2_t < 0.0 {
        return Refraction::TotalInternalReflection;
    }
    let cos_t = cos2_t.sqrt();
    Refraction::Transmitted(eta * w_i + (eta * cos_i - cos_t) * m)
}
// END EXERCISE
// ANCHOR_END: refract

/// The critical angle (radians) for light going from index `n1` to `n2`: `asin(n2 / n1)`,
/// or `None` when `n1 <= n2` (no total internal reflection is possible).
pub fn critical_angle(n1: f64, n2: f64) -> Option<f64> {
    (n1 > n2).then(|| (n2 / n1).asin())
}
