//! The checker of mirror reflection and Snell refraction: any routine with the signatures
//! of [`crate::optics::reflect::reflect`] and [`crate::optics::reflect::refract`] can be
//! checked against the claims of the chapter *Reflection and refraction*
//! (`chapters/optics/reflect.md`).
//!
//! * [`reflection`]: finite, unit length, equal angles, coplanar, either side's normal,
//!   reversible;
//! * [`refraction`]: finite, total internal reflection exactly past the critical angle,
//!   unit length, Snell's law, into the far medium, coplanar, either side's normal,
//!   reversible, matched indices;
//! * [`planted`]: the source notes' reflection and refractions with the classic mistakes, which
//!   the checker must reject.
//!
//! Both are called with the routine and one [`Options`]: the number of random cases
//! (default [`CASES`]) and their seed (default [`REFLECTION_SEED`], [`REFRACTION_SEED`]).

pub mod planted;

use crate::sampling::sphere::sphere_uniform;
use glam::DVec3;

use super::{Finding, Options, Verdict};
use crate::optics::reflect::Refraction;
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
pub(crate) const UNIT_BOUND: f64 = 8.0;
/// Bound of the angle, Snell, coplanarity and side checks, in units of `f64::EPSILON`.
pub(crate) const ANGLE_BOUND: f64 = 8.0;
/// Bound of the round trip, in units of `f64::EPSILON / cos(theta_i)`.
pub(crate) const REVERSE_BOUND: f64 = 16.0;
/// `|eta sin(theta_i) - 1|` below which either answer (TIR or a grazing ray) is right.
pub(crate) const CRITICAL_BAND: f64 = 1e-12;

const EPS: f64 = f64::EPSILON;

/// The default number of random cases of [`reflection`] and [`refraction`] (the book's
/// tests and tables use it).
pub const CASES: usize = 20_000;
/// The default seed of [`reflection`]'s cases (the book's tests and tables use it).
pub const REFLECTION_SEED: u64 = 1;
/// The default seed of [`refraction`]'s cases (the book's tests and tables use it).
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
        let mut m = sphere_uniform(rng);
        let w_i = match k % 16 {
            0 => -m,
            1 => rng::perpendicular(m),
            _ => sphere_uniform(rng),
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
/// Checks a reflection routine `f(w_i, n) -> w_o` on random incident directions: as many
/// as `options` says (default [`CASES`]), from its seed (default [`REFLECTION_SEED`]).
pub fn reflection(f: &dyn Fn(DVec3, DVec3) -> DVec3, options: &Options) -> Verdict {
    let cases = options.cases_or(CASES);
    let mut finite_ = Finding::new("finite", "w_o has finite components");
    let mut unit =
        Finding::new("unit_length", "| |w_o| - 1 | <= 8 eps").in_unit("machine epsilons");
    let mut angles = Finding::new(
        "equal_angles",
        "w_o leaves on the incident side at the angle of incidence: |w_o.m - cos_i| <= 8 eps",
    )
    .in_unit("machine epsilons");
    let mut plane =
        Finding::new("coplanar", "w_o lies in the plane of w_i and n").in_unit("machine epsilons");
    let mut side =
        Finding::new("normal_side", "f(w_i, n) = f(w_i, -n)").in_unit("machine epsilons");
    let mut reverse = Finding::new("reversible", "f(-w_o, n) = -w_i").in_unit("machine epsilons");
    let mut rng = rng::seeded(options.seed_or(REFLECTION_SEED));
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
/// Checks a refraction routine `f(w_i, n, n1, n2) -> Refraction` on random incident
/// directions and index pairs from [`INDEX_PAIRS`]: as many as `options` says (default
/// [`CASES`]), from its seed (default [`REFRACTION_SEED`]).
pub fn refraction(f: &dyn Fn(DVec3, DVec3, f64, f64) -> Refraction, options: &Options) -> Verdict {
    let cases = options.cases_or(CASES);
    let mut finite_ = Finding::new("finite", "a transmitted w_t has finite components");
    let mut tir = Finding::new(
        "tir_iff",
        "total internal reflection exactly when (n1/n2) sin_i > 1",
    );
    let mut unit =
        Finding::new("unit_length", "| |w_t| - 1 | <= 8 eps").in_unit("machine epsilons");
    let mut snell = Finding::new(
        "snell",
        "|n1 sin_i - n2 sin_t| <= 8 eps max(n1, n2), sines from |w x n| / |w|",
    )
    .in_unit("machine epsilons");
    let mut far = Finding::new("far_side", "w_t points into the far medium: w_t.m <= 8 eps");
    let mut plane =
        Finding::new("coplanar", "w_t lies in the plane of w_i and n").in_unit("machine epsilons");
    let mut side =
        Finding::new("normal_side", "f(w_i, n) = f(w_i, -n)").in_unit("machine epsilons");
    let mut reverse = Finding::new(
        "reversible",
        "f(-w_t, n, n2, n1) = -w_i within 16 eps / cos_i",
    )
    .in_unit("machine epsilons, times cos_i");
    let mut matched = Finding::new("matched", "n1 = n2 leaves the direction unchanged")
        .in_unit("machine epsilons");
    let mut rng = rng::seeded(options.seed_or(REFRACTION_SEED));
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
