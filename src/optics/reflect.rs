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
//! The seed notes write the reflection as `w_o = 2n + w_i`, which is wrong except at
//! normal incidence; see [`planted::seed_reflect`] and the chapter.

use glam::DVec3;

// ANCHOR: reflect
/// Mirror reflection of the incident direction `w_i` about the normal `n` (either side):
/// `w_o = w_i - 2 (w_i . n) n`.
///
/// The component of `w_i` along the normal changes sign, the component in the surface is
/// kept. The result does not depend on the sign of `n`, since `n` appears twice.
pub fn reflect(w_i: DVec3, n: DVec3) -> DVec3 {
    w_i - 2.0 * w_i.dot(n) * n
}
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
// ANCHOR_END: refract

/// The critical angle (radians) for light going from index `n1` to `n2`: `asin(n2 / n1)`,
/// or `None` when `n1 <= n2` (no total internal reflection is possible).
pub fn critical_angle(n1: f64, n2: f64) -> Option<f64> {
    (n1 > n2).then(|| (n2 / n1).asin())
}

/// Deliberately wrong implementations, for the tests and the book: each must be rejected by
/// the checker [`check`].
pub mod planted {
    use super::Refraction;
    use glam::DVec3;

    /// The incident side's normal: `n` or `-n`, whichever faces `w_i`.
    fn facing(w_i: DVec3, n: DVec3) -> DVec3 {
        if w_i.dot(n) <= 0.0 { n } else { -n }
    }

    // ANCHOR: seed_reflect
    /// The seed's reflection, `w_o = 2n + w_i`, with `n` the normal facing the light as the
    /// seed intends. Right only at normal incidence: it drops the factor `cos(theta_i)`.
    pub fn seed_reflect(w_i: DVec3, n: DVec3) -> DVec3 {
        2.0 * facing(w_i, n) + w_i
    }
    // ANCHOR_END: seed_reflect

    /// Refraction with `cos_t^2` used where `cos_t` belongs (the square root forgotten).
    pub fn refract_without_sqrt(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
        let m = facing(w_i, n);
        let cos_i = -w_i.dot(m);
        let eta = n1 / n2;
        let cos2_t = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
        if cos2_t < 0.0 {
            return Refraction::TotalInternalReflection;
        }
        Refraction::Transmitted(eta * w_i + (eta * cos_i - cos2_t) * m)
    }

    /// Refraction with the ratio of indices upside down, `eta = n2 / n1`.
    pub fn refract_swapped_indices(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
        super::refract(w_i, n, n2, n1)
    }

    /// Refraction without the total-internal-reflection test: past the critical angle the
    /// square root of a negative number makes the direction NaN.
    pub fn refract_nan_tir(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
        let m = facing(w_i, n);
        let cos_i = -w_i.dot(m);
        let eta = n1 / n2;
        let cos_t = (1.0 - eta * eta * (1.0 - cos_i * cos_i)).sqrt();
        Refraction::Transmitted(eta * w_i + (eta * cos_i - cos_t) * m)
    }

    /// Refraction that trusts `n` to face the light (the seed's "outward facing normal"
    /// assumption) and never flips it.
    pub fn refract_unflipped_normal(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
        let cos_i = -w_i.dot(n);
        let eta = n1 / n2;
        let cos2_t = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
        if cos2_t < 0.0 {
            return Refraction::TotalInternalReflection;
        }
        Refraction::Transmitted(eta * w_i + (eta * cos_i - cos2_t.sqrt()) * n)
    }
}

/// The checker of this chapter: any reflection or refraction routine with the signatures of
/// [`reflect`] and [`refract`] can be checked against the chapter's claims.
pub mod check {
    use glam::DVec3;

    use super::Refraction;
    use crate::check::{Finding, Verdict};
    use crate::rng::{self, Rng};

    /// Pairs `(n1, n2)` the refraction checker draws from: into and out of water, glass and
    /// diamond, glass under water both ways, and matched indices.
    pub const INDEX_PAIRS: [(f64, f64); 9] = [
        (1.0, 1.5),
        (1.5, 1.0),
        (1.0, 1.33),
        (1.33, 1.0),
        (1.0, 2.4),
        (2.4, 1.0),
        (1.33, 1.5),
        (1.5, 1.33),
        (1.2, 1.2),
    ];

    /// Error bounds, in units of `f64::EPSILON`.
    pub const UNIT_BOUND: f64 = 8.0;
    /// Bound of the angle, Snell, coplanarity and side checks, in units of `f64::EPSILON`.
    pub const ANGLE_BOUND: f64 = 8.0;
    /// Bound of the round trip, in units of `f64::EPSILON / cos(theta_i)`.
    pub const REVERSE_BOUND: f64 = 16.0;
    /// `|eta sin(theta_i) - 1|` below which either answer (TIR or a grazing ray) is right.
    pub const CRITICAL_BAND: f64 = 1e-12;

    const EPS: f64 = f64::EPSILON;

    /// The seed of the reflection checker's cases in the book's tests and tables.
    pub const REFLECTION_SEED: u64 = 1;
    /// The seed of the refraction checker's cases in the book's tests and tables.
    pub const REFRACTION_SEED: u64 = 2;

    /// One incident direction: the light's direction `w_i`, the normal `m` facing it
    /// (`w_i . m <= 0`), and the normal `n` handed to the routine (`m` or `-m`).
    #[derive(Clone, Copy, Debug)]
    pub struct Case {
        /// Incident direction (towards the surface), unit.
        pub w_i: DVec3,
        /// The normal on the incident side.
        pub m: DVec3,
        /// The normal given to the routine under test.
        pub n: DVec3,
    }

    /// Random unit `w_i` and normal; one case in 16 at normal incidence, one in 16 at
    /// grazing incidence, and half with the normal on the far side. `w_i . m` is never
    /// exactly 0, so the side the light comes from is always defined.
    pub fn random_case(rng: &mut Rng, k: usize) -> Case {
        loop {
            let mut m = rng::unit_vector(rng);
            let w_i = match k % 16 {
                0 => -m,
                1 => rng::perpendicular(m),
                _ => rng::unit_vector(rng),
            };
            if w_i.dot(m) == 0.0 {
                continue; // exactly grazing: no side to come from; draw again
            }
            if w_i.dot(m) > 0.0 {
                m = -m;
            }
            let n = if rng::uniform(rng, 0.0, 1.0) < 0.5 {
                m
            } else {
                -m
            };
            return Case { w_i, m, n };
        }
    }

    fn finite(v: DVec3) -> bool {
        v.is_finite()
    }

    /// How far `v` leaves the plane of `w_i` and `m`: the triple product `v . (w_i x m)`,
    /// which is 0 for coplanar vectors (and well conditioned even when `w_i` is along `m`).
    fn off_plane(v: DVec3, w_i: DVec3, m: DVec3) -> f64 {
        v.dot(w_i.cross(m)).abs()
    }

    /// Sine of the angle between `v` and the normal `m`: `|v x m| / |v|`.
    fn sine(v: DVec3, m: DVec3) -> f64 {
        v.cross(m).length() / v.length()
    }

    // ANCHOR: reflection_claims
    /// Checks a reflection routine `f(w_i, n) -> w_o` on `cases` random incident directions.
    pub fn reflection(f: &dyn Fn(DVec3, DVec3) -> DVec3, cases: usize, seed: u64) -> Verdict {
        let mut finite_ = Finding::new("finite", "w_o has finite components");
        let mut unit = Finding::new("unit_length", "| |w_o| - 1 | <= 8 eps");
        let mut angles = Finding::new(
            "equal_angles",
            "w_o leaves on the incident side at the angle of incidence: |w_o.m - cos_i| <= 8 eps",
        );
        let mut plane = Finding::new("coplanar", "w_o lies in the plane of w_i and n");
        let mut side = Finding::new("normal_side", "f(w_i, n) = f(w_i, -n)");
        let mut reverse = Finding::new("reversible", "f(-w_o, n) = -w_i");
        let mut rng = rng::seeded(seed);
        for k in 0..cases {
            let c = random_case(&mut rng, k);
            let w_o = f(c.w_i, c.n);
            let show = || format!("w_i = {:?}, n = {:?} gave w_o = {w_o:?}", c.w_i, c.n);
            finite_.record(finite(w_o), show);
            let cos_i = -c.w_i.dot(c.m);
            unit.measure((w_o.length() - 1.0).abs() / EPS, UNIT_BOUND, || {
                format!("{}: |w_o| = {:.17}", show(), w_o.length())
            });
            angles.measure((w_o.dot(c.m) - cos_i).abs() / EPS, ANGLE_BOUND, || {
                format!(
                    "{}: w_o.m = {:.12} but cos_i = {:.12} (the mirror keeps the angle to the normal)",
                    show(),
                    w_o.dot(c.m),
                    cos_i
                )
            });
            plane.measure(off_plane(w_o, c.w_i, c.m) / EPS, ANGLE_BOUND, show);
            let other = f(c.w_i, -c.n);
            side.measure((other - w_o).length() / EPS, ANGLE_BOUND, show);
            let back = f(-w_o, c.n);
            reverse.measure((back + c.w_i).length() / EPS, ANGLE_BOUND, show);
        }
        let mut verdict = Verdict::new("reflection");
        verdict.findings = vec![finite_, unit, angles, plane, side, reverse];
        verdict
    }
    // ANCHOR_END: reflection_claims

    // ANCHOR: refraction_claims
    /// Checks a refraction routine `f(w_i, n, n1, n2) -> Refraction` on `cases` random
    /// incident directions and index pairs from [`INDEX_PAIRS`].
    pub fn refraction(
        f: &dyn Fn(DVec3, DVec3, f64, f64) -> Refraction,
        cases: usize,
        seed: u64,
    ) -> Verdict {
        let mut finite_ = Finding::new("finite", "a transmitted w_t has finite components");
        let mut tir = Finding::new(
            "tir_iff",
            "total internal reflection exactly when (n1/n2) sin_i > 1",
        );
        let mut unit = Finding::new("unit_length", "| |w_t| - 1 | <= 8 eps");
        let mut snell = Finding::new(
            "snell",
            "|n1 sin_i - n2 sin_t| <= 8 eps max(n1, n2), sines from |w x n| / |w|",
        );
        let mut far = Finding::new("far_side", "w_t points into the far medium: w_t.m <= 8 eps");
        let mut plane = Finding::new("coplanar", "w_t lies in the plane of w_i and n");
        let mut side = Finding::new("normal_side", "f(w_i, n) = f(w_i, -n)");
        let mut reverse = Finding::new(
            "reversible",
            "f(-w_t, n, n2, n1) = -w_i within 16 eps / cos_i",
        );
        let mut matched = Finding::new("matched", "n1 = n2 leaves the direction unchanged");
        let mut rng = rng::seeded(seed);
        for k in 0..cases {
            let c = random_case(&mut rng, k);
            let (n1, n2) = INDEX_PAIRS[(k / 16) % INDEX_PAIRS.len()];
            let out = f(c.w_i, c.n, n1, n2);
            let show = || {
                format!(
                    "w_i = {:?}, n = {:?}, n1 = {n1}, n2 = {n2} gave {out:?}",
                    c.w_i, c.n
                )
            };
            let cos_i = -c.w_i.dot(c.m);
            let sin_i = sine(c.w_i, c.m);
            let past = n1 / n2 * sin_i - 1.0;
            if past.abs() > CRITICAL_BAND {
                let is_tir = matches!(out, Refraction::TotalInternalReflection);
                tir.record(is_tir == (past > 0.0), show);
            }
            let other = f(c.w_i, -c.n, n1, n2);
            match (out, other) {
                (Refraction::Transmitted(a), Refraction::Transmitted(b)) => {
                    side.measure((a - b).length() / EPS, ANGLE_BOUND, show)
                }
                (Refraction::TotalInternalReflection, Refraction::TotalInternalReflection) => {
                    side.record(true, show)
                }
                _ => side.record(past.abs() <= CRITICAL_BAND, show),
            }
            let Refraction::Transmitted(w_t) = out else {
                continue;
            };
            finite_.record(finite(w_t), show);
            unit.measure((w_t.length() - 1.0).abs() / EPS, UNIT_BOUND, || {
                format!("{}: |w_t| = {:.17}", show(), w_t.length())
            });
            let sin_t = sine(w_t, c.m);
            let snell_error = (n1 * sin_i - n2 * sin_t).abs() / n1.max(n2);
            snell.measure(snell_error / EPS, ANGLE_BOUND, || {
                format!(
                    "{}: n1 sin_i = {:.12}, n2 sin_t = {:.12} (Snell wants them equal; sin_t should be {:.12})",
                    show(),
                    n1 * sin_i,
                    n2 * sin_t,
                    n1 * sin_i / n2
                )
            });
            far.record(w_t.dot(c.m) <= ANGLE_BOUND * EPS, show);
            plane.measure(off_plane(w_t, c.w_i, c.m) / EPS, ANGLE_BOUND, show);
            if n1 == n2 {
                matched.measure((w_t - c.w_i).length() / EPS, ANGLE_BOUND, || {
                    format!("{}: expected w_i itself", show())
                });
            }
            // The round trip is ill-conditioned at grazing incidence: skip cos_i < 1e-6.
            if cos_i >= 1e-6 {
                let back = f(-w_t, c.n, n2, n1);
                let error = match back {
                    Refraction::Transmitted(back) => (back + c.w_i).length() * cos_i / EPS,
                    Refraction::TotalInternalReflection => f64::INFINITY,
                };
                reverse.measure(error, REVERSE_BOUND, || match back {
                    Refraction::TotalInternalReflection => format!(
                        "{}: sending -w_t back from {n2} into {n1} gave total internal reflection (infinite error); light retraces its path",
                        show()
                    ),
                    Refraction::Transmitted(b) => {
                        format!("{}: sending -w_t back gave {b:?}, expected -w_i = {:?}", show(), -c.w_i)
                    }
                });
            }
        }
        let mut verdict = Verdict::new("refraction");
        verdict.findings = vec![
            finite_, tir, unit, snell, far, plane, side, reverse, matched,
        ];
        verdict
    }
    // ANCHOR_END: refraction_claims
}
