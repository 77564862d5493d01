//! The checker of dielectric reflectance: any unpolarised reflectance routine
//! `f(cos_i, n1, n2) -> R` (such as [`crate::optics::fresnel::fresnel_dielectric`]) can be
//! checked against the claims of the chapter *Fresnel and Schlick*
//! (`chapters/optics/fresnel.md`): range, normal and grazing incidence, matched indices,
//! total internal reflection, `R + T = 1` and reciprocity. Its planted bugs are in
//! [`planted`]. [`amplitudes`] checks the amplitude coefficients themselves, signs
//! included, which no reflectance can see. [`schlick`] holds an approximation to
//! Schlick's formula itself (its value, its exponent), which the claims of a reflectance
//! an approximation keeps cannot tell from another power.
//!
//! The cases are a deterministic sweep: [`PAIRS`] of indices times the cosines of
//! [`sweep_cosines`]. Of the [`Options`], the number of cases is the number of evenly
//! spaced angles from 0 to 90 degrees (default [`ANGLES`], every 0.25 degree); the seed
//! is not used.

pub mod planted;

use super::{Finding, Options, Verdict};
use crate::optics::fresnel::Amplitudes;

/// Index pairs `(n1, n2)`: water, glass and diamond from both sides, glass under water,
/// a strong contrast, a tiny one, and matched indices.
pub const PAIRS: [(f64, f64); 12] = [
    (1.0, 1.33),
    (1.33, 1.0),
    (1.0, 1.5),
    (1.5, 1.0),
    (1.0, 2.4),
    (2.4, 1.0),
    (1.33, 1.5),
    (1.5, 1.33),
    (1.0, 4.0),
    (1.0001, 1.0),
    (1.0, 1.0),
    (1.5, 1.5),
];

/// Bound of the exact-value claims (normal, grazing, matched, TIR), absolute.
pub const VALUE_BOUND: f64 = 4.0 * f64::EPSILON;
/// Bound of the energy and reciprocity claims, in units of
/// `eps (1 + 1 / min(cos_i, cos_t))`: computing one cosine from the other is
/// ill-conditioned where either is near 0 (grazing, or near the critical angle).
pub(crate) const BALANCE_BOUND: f64 = 64.0;

/// The default number of evenly spaced angles of the sweep: 0 to 90 degrees in steps of
/// 0.25 degree.
pub const ANGLES: usize = 361;

/// The cosines of the sweep: `options`' number of evenly spaced angles from 0 to 90
/// degrees (default [`ANGLES`], every 0.25 degree; at least 2, both ends), then awkward
/// values.
pub fn sweep_cosines(options: &Options) -> Vec<f64> {
    let angles = options.cases_or(ANGLES).max(2);
    let step = 90.0 / (angles - 1) as f64;
    let mut c: Vec<f64> = (0..angles)
        .map(|k| (k as f64 * step).to_radians().cos())
        .collect();
    c.extend([
        0.0,
        -0.0,
        1.0,
        f64::MIN_POSITIVE,
        5e-324,
        1e-300,
        1e-8,
        1.0 - f64::EPSILON,
        -0.5,
        1.0 + f64::EPSILON, // a dot product of unit vectors, rounded up
    ]);
    c
}

/// `cos theta_t` and the transmittance `T = (n2 cos_t)/(n1 cos_i) (t_s^2 + t_p^2)/2`,
/// computed here, from the angles, independently of the code under test. `None`
/// under total internal reflection.
pub(crate) fn independent_transmittance(cos_i: f64, n1: f64, n2: f64) -> Option<(f64, f64)> {
    let c = cos_i.abs().min(1.0);
    let sin_i = ((1.0 - c) * (1.0 + c)).sqrt();
    let sin_t = n1 * sin_i / n2;
    if sin_t > 1.0 {
        return None;
    }
    let cos_t = ((1.0 - sin_t) * (1.0 + sin_t)).sqrt();
    let t_s = 2.0 * n1 * c / (n1 * c + n2 * cos_t);
    let t_p = 2.0 * n1 * c / (n2 * c + n1 * cos_t);
    let t = n2 * cos_t / (n1 * c) * 0.5 * (t_s * t_s + t_p * t_p);
    Some((cos_t, t))
}

/// Bound of [`schlick`]'s `formula` claim, in units of `eps (1 + 1 / cos)` with `cos` the
/// cosine on the less dense side (computing `cos_t` is ill-conditioned near the critical
/// angle): orders of operations, `powi(5)` or products agree far within it; the fourth
/// power differs by up to about `(1 - R0) / 4`, some `1e14` of these units.
pub const SCHLICK_BOUND: f64 = 64.0;
/// Bound of [`schlick`]'s `exponent` claim: the exponent read from the curve, absolute.
pub const EXPONENT_BOUND: f64 = 1e-6;

/// The claims that tell Schlick's approximation from another curve with the same ends
/// (the chapter *Fresnel and Schlick*): `R0 + (1 - R0)(1 - cos)^5` with `cos` on the less
/// dense side. The claims of [`reflectance`] that an approximation keeps (range, normal,
/// grazing, TIR, reciprocity) hold for any exponent; these do not.
///
/// * `formula`: `f` agrees with the formula, computed here with `cos_t` from the angles,
///   at every pair of [`PAIRS`] and every angle of the sweep (`options`' number of angles,
///   default [`ANGLES`]) that does not reflect totally, within [`SCHLICK_BOUND`]
///   `eps (1 + 1 / cos)`;
/// * `exponent`: entering a denser (or matched) medium, the exponent of `1 - cos` read
///   from `f`'s own curve, `log2((f(0) - f(1)) / (f(1/2) - f(1)))`, is 5 within
///   [`EXPONENT_BOUND`]; the message says which exponent it is.
pub fn schlick(f: &dyn Fn(f64, f64, f64) -> f64, options: &Options) -> Verdict {
    let angles = options.cases_or(ANGLES).max(2);
    let step = 90.0 / (angles - 1) as f64;
    let mut formula = Finding::new(
        "formula",
        "R = R0 + (1 - R0)(1 - cos)^5, cos on the less dense side, within 64 eps (1 + 1/cos) (errors in that unit)",
    )
    .in_unit("multiples of eps (1 + 1/cos)");
    let mut exponent = Finding::new(
        "exponent",
        "entering a denser medium, log2((R(0) - R(1)) / (R(1/2) - R(1))) = 5: the power of (1 - cos)",
    )
    .in_unit("absolute error of the exponent");
    for &(n1, n2) in &PAIRS {
        let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
        for k in 0..angles {
            let cos_i = (k as f64 * step).to_radians().cos();
            // The cosine on the less dense side.
            let cos = match independent_transmittance(cos_i, n1, n2) {
                _ if n1 <= n2 => cos_i,
                Some((cos_t, _)) => cos_t,
                None => continue,
            };
            let x = 1.0 - cos;
            let want = r0 + (1.0 - r0) * x * x * x * x * x;
            let got = f(cos_i, n1, n2);
            let unit = f64::EPSILON * (1.0 + 1.0 / cos.max(f64::MIN_POSITIVE));
            formula.measure((got - want).abs() / unit, SCHLICK_BOUND, || {
                format!(
                    "f({cos_i:e}, {n1}, {n2}) = {got:e}, R0 + (1 - R0)(1 - cos)^5 = {want:e} (cos on the less dense side = {cos:e})"
                )
            });
        }
        if n1 <= n2 {
            let (grazing, half, normal) = (f(0.0, n1, n2), f(0.5, n1, n2), f(1.0, n1, n2));
            let power = ((grazing - normal) / (half - normal)).log2();
            exponent.measure((power - 5.0).abs(), EXPONENT_BOUND, || {
                format!(
                    "from {n1} into {n2}: f(0) = {grazing:e}, f(0.5) = {half:e}, f(1) = {normal:e}: (1 - cos) to the power {power:.6}, not 5"
                )
            });
        }
    }
    let mut verdict = Verdict::new("Schlick's formula");
    verdict.findings.extend([formula, exponent]);
    verdict
}

// ANCHOR: claims
/// Runs every claim on `f` over [`PAIRS`] and [`sweep_cosines`]`(options)`.
pub fn reflectance(f: &dyn Fn(f64, f64, f64) -> f64, options: &Options) -> Verdict {
    let cosines = sweep_cosines(options);
    let mut range = Finding::new("range", "R is finite and in [0, 1] for every input");
    let mut normal =
        Finding::new("normal", "R(cos_i = 1) = ((n1 - n2)/(n1 + n2))^2").in_unit("absolute error");
    let mut grazing =
        Finding::new("grazing", "R(cos_i = 0) = 1 when n1 != n2").in_unit("absolute error");
    let mut matched =
        Finding::new("matched", "R = 0 at every angle when n1 = n2").in_unit("absolute error");
    let mut tir = Finding::new("tir", "R = 1 past the critical angle").in_unit("absolute error");
    let mut energy = Finding::new(
        "energy",
        "R + T = 1, T from the transmission amplitudes, within 64 eps (1 + 1/min(cos_i, cos_t)) (errors in that unit)",
    )
.in_unit("multiples of eps (1 + 1/min(cos_i, cos_t))");
    let mut reciprocity = Finding::new(
        "reciprocity",
        "R(cos_i; n1 -> n2) = R(cos_t; n2 -> n1), within 64 eps (1 + 1/min(cos_i, cos_t)) (errors in that unit)",
    )
.in_unit("multiples of eps (1 + 1/min(cos_i, cos_t))");
    for &(n1, n2) in &PAIRS {
        for &cos_i in &cosines {
            let r = f(cos_i, n1, n2);
            let angle = cos_i.abs().min(1.0).acos().to_degrees();
            let show = || format!("f({cos_i:e}, {n1}, {n2}) = {r:e} (theta_i = {angle:.3} deg)");
            range.record(r.is_finite() && (0.0..=1.0).contains(&r), show);
            let c = cos_i.abs();
            if c >= 1.0 {
                let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
                normal.measure((r - r0).abs(), VALUE_BOUND, show);
            }
            if n1 == n2 {
                matched.measure(r.abs(), VALUE_BOUND, show);
                continue;
            }
            if c == 0.0 {
                grazing.measure((r - 1.0).abs(), VALUE_BOUND, show);
            }
            match independent_transmittance(cos_i, n1, n2) {
                None => tir.measure((r - 1.0).abs(), VALUE_BOUND, || {
                    let critical = (n2 / n1).asin().to_degrees();
                    format!(
                        "{}: past the critical angle {critical:.3} deg from {n1} into {n2}, R must be 1",
                        show()
                    )
                }),
                // Subnormal cosines would overflow the beam factor: skip them here.
                Some((cos_t, t)) if c > 1e-100 && cos_t > 0.0 => {
                    let unit = f64::EPSILON * (1.0 + 1.0 / c.min(cos_t));
                    energy.measure((r + t - 1.0).abs() / unit, BALANCE_BOUND, || {
                        format!("{}: R = {r:.6e}, T = {t:.6e}, R + T - 1 = {:.3e}", show(), r + t - 1.0)
                    });
                    let back = f(cos_t, n2, n1);
                    reciprocity.measure((r - back).abs() / unit, BALANCE_BOUND, || {
                        format!(
                            "{}, but from the other side f({cos_t:e}, {n2}, {n1}) = {back:e} (theta_t = {:.3} deg)",
                            show(),
                            cos_t.acos().to_degrees()
                        )
                    });
                }
                Some(_) => {}
            }
        }
    }
    let mut verdict = Verdict::new("dielectric reflectance");
    verdict.findings = vec![range, normal, grazing, matched, tir, energy, reciprocity];
    verdict
}
// ANCHOR_END: claims

/// The amplitude coefficients `(r_s, r_p, t_s, t_p)` in Born & Wolf's convention, computed
/// here from the angles (`sin_t = n1 sin_i / n2`), independently of the code under test.
/// `None` under total internal reflection.
pub(crate) fn independent_amplitudes(cos_i: f64, n1: f64, n2: f64) -> Option<[f64; 4]> {
    let c = cos_i.abs().min(1.0);
    let sin_i = ((1.0 - c) * (1.0 + c)).sqrt();
    let sin_t = n1 * sin_i / n2;
    if sin_t > 1.0 {
        return None;
    }
    let cos_t = ((1.0 - sin_t) * (1.0 + sin_t)).sqrt();
    let (a, b, d, e) = (n1 * c, n2 * cos_t, n2 * c, n1 * cos_t);
    Some([
        (a - b) / (a + b),
        (d - e) / (d + e),
        2.0 * a / (a + b),
        2.0 * a / (d + e),
    ])
}

// ANCHOR: amplitude_claims
/// Runs the claims on the amplitude coefficients over [`PAIRS`] and
/// [`sweep_cosines`]`(options)`. Matched pairs are skipped: `r = 0, t = 1` there is the
/// reflectance checker's `matched` claim.
pub fn amplitudes(f: &dyn Fn(f64, f64, f64) -> Option<Amplitudes>, options: &Options) -> Verdict {
    let cosines = sweep_cosines(options);
    let mut range = Finding::new("range", "every amplitude finite, |r| <= 1 and t >= 0");
    let mut tir =
        Finding::new("tir", "None exactly past the critical angle").in_unit("absolute error");
    let mut values = Finding::new(
        "values",
        "r_s, r_p, t_s, t_p equal Born & Wolf's formulas, within 64 eps (1 + 1/min(cos_i, cos_t)) (errors in that unit)",
    )
.in_unit("multiples of eps (1 + 1/min(cos_i, cos_t))");
    let mut normal = Finding::new(
        "normal",
        "at cos_i = 1: r_s = (n1 - n2)/(n1 + n2), r_p = -r_s, t_s = t_p = 2 n1/(n1 + n2), within 4 eps",
    )
.in_unit("absolute error");
    let mut grazing = Finding::new(
        "grazing",
        "at cos_i = 0 from the less dense side: r_s = r_p = -1 and t_s = t_p = 0, the limits (no jump)",
    )
.in_unit("absolute error");
    let mut stokes = Finding::new(
        "stokes",
        "t_s = 1 + r_s and t_p = (n1/n2)(1 + r_p), within 8 eps (1 + n1/n2)",
    )
    .in_unit("absolute error");
    let mut brewster = Finding::new(
        "brewster",
        "r_p has the sign of (cos_i - cos theta_B)(n2 - n1): it changes sign at Brewster's angle",
    );
    for &(n1, n2) in PAIRS.iter().filter(|(n1, n2)| n1 != n2) {
        let cos_b = (n2 / n1).atan().cos();
        for &cos_i in &cosines {
            let got = f(cos_i, n1, n2);
            let c = cos_i.abs().min(1.0);
            let angle = c.acos().to_degrees();
            let show = || format!("f({cos_i:e}, {n1}, {n2}) = {got:?} (theta_i = {angle:.3} deg)");
            let expected = independent_amplitudes(cos_i, n1, n2);
            tir.record(got.is_none() == expected.is_none(), || {
                format!(
                    "{}, but the transmitted wave {} there",
                    show(),
                    if expected.is_none() {
                        "does not exist"
                    } else {
                        "exists"
                    }
                )
            });
            let (Some(a), Some(want)) = (got, expected) else {
                continue;
            };
            let have = [a.r_s, a.r_p, a.t_s, a.t_p];
            range.record(
                have.iter().all(|v| v.is_finite())
                    && a.r_s.abs() <= 1.0
                    && a.r_p.abs() <= 1.0
                    && a.t_s >= 0.0
                    && a.t_p >= 0.0,
                show,
            );
            let cos_t = {
                let sin_t = n1 * ((1.0 - c) * (1.0 + c)).sqrt() / n2;
                ((1.0 - sin_t) * (1.0 + sin_t)).sqrt()
            };
            if c > 1e-100 && cos_t > 0.0 {
                let unit = f64::EPSILON * (1.0 + 1.0 / c.min(cos_t));
                let error = have
                    .iter()
                    .zip(want)
                    .map(|(h, w)| (h - w).abs())
                    .fold(0.0, f64::max);
                values.measure(error / unit, BALANCE_BOUND, || {
                    format!(
                        "{}; Born & Wolf give (r_s, r_p, t_s, t_p) = {want:?}",
                        show()
                    )
                });
            }
            let unit = 8.0 * f64::EPSILON * (1.0 + n1 / n2);
            let error = (a.t_s - (1.0 + a.r_s))
                .abs()
                .max((a.t_p - n1 / n2 * (1.0 + a.r_p)).abs());
            stokes.measure(error, unit, || {
                format!(
                    "{}: t_s - (1 + r_s) = {:e}, t_p - (n1/n2)(1 + r_p) = {:e}",
                    show(),
                    a.t_s - (1.0 + a.r_s),
                    a.t_p - n1 / n2 * (1.0 + a.r_p)
                )
            });
            if c >= 1.0 {
                let r = (n1 - n2) / (n1 + n2);
                let t = 2.0 * n1 / (n1 + n2);
                let error = [a.r_s - r, a.r_p + r, a.t_s - t, a.t_p - t]
                    .iter()
                    .fold(0.0f64, |m, e| m.max(e.abs()));
                normal.measure(error, VALUE_BOUND, || {
                    format!(
                        "{}; at normal incidence r_s = {r}, r_p = {}, t_s = t_p = {t}",
                        show(),
                        -r
                    )
                });
            }
            if c == 0.0 {
                let error = [a.r_s + 1.0, a.r_p + 1.0, a.t_s, a.t_p]
                    .iter()
                    .fold(0.0f64, |m, e| m.max(e.abs()));
                grazing.measure(error, VALUE_BOUND, || {
                    format!(
                        "{}; the limit at grazing incidence is (-1, -1, 0, 0)",
                        show()
                    )
                });
            }
            // Away from Brewster's angle (and from the critical angle, where r_p = 1 is
            // approached from the same side), the sign of r_p is fixed.
            if (c - cos_b).abs() > 1e-6 {
                let positive = (c > cos_b) == (n2 > n1);
                brewster.record((a.r_p > 0.0) == positive, || {
                    format!(
                        "{}: r_p should be {} {} Brewster's angle {:.3} deg",
                        show(),
                        if positive { "positive" } else { "negative" },
                        if c > cos_b { "below" } else { "above" },
                        cos_b.acos().to_degrees()
                    )
                });
            }
        }
    }
    let mut verdict = Verdict::new("Fresnel amplitudes");
    verdict.findings = vec![range, tir, values, normal, grazing, stokes, brewster];
    verdict
}
// ANCHOR_END: amplitude_claims
