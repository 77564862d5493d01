//! Tests of the chapter *Fresnel and Schlick* (`chapters/optics/fresnel.md`).
//!
//! Deterministic checks: constructed angles, sweeps of the whole input domain, and the
//! chapter's checker on the exact formula (which must pass) and on planted bugs and
//! approximations (each of which must fail the claims it breaks). The approximation errors
//! stated in the book's table are pinned here to within 20 %.

use quickcheck::{Arbitrary, Gen, QuickCheck, TestResult};
use raylemma::check::fresnel::{self as check, planted};
use raylemma::check::{Options, max_abs};
use raylemma::optics::fresnel::{
    Amplitudes, ErrorStats, FresnelFit, SWEEP_ANGLES, amplitudes, approximation_error,
    brewster_angle, cos_transmitted, fresnel_dielectric, fresnel_polarized, fresnel_transmittance,
    r0, schlick, schlick_seed,
};
use raylemma::optics::reflect::critical_angle;

const EPS: f64 = f64::EPSILON;

/// The relative indices of the chapter: water, glass, diamond, and glass under water.
const IORS: [f64; 4] = [1.33, 1.5, 2.4, 1.5 / 1.33];

// ---------------------------------------------------------------------------------------
// The checker: the exact formula passes, planted bugs and approximations do not.

#[test]
fn exact_fresnel_passes_every_check() {
    check::reflectance(&fresnel_dielectric, &Options::default()).assert_pass();
}

#[test]
fn checker_rejects_the_naive_formula() {
    // No TIR test: NaN past the critical angle. Matched indices at grazing: 0/0.
    let verdict = check::reflectance(&planted::fresnel_naive, &Options::default());
    for claim in ["range", "tir", "matched"] {
        assert!(verdict.failed(claim), "{claim}\n{verdict}");
    }
    assert!(planted::fresnel_naive(0.0, 1.5, 1.5).is_nan());
    assert_eq!(fresnel_dielectric(0.0, 1.5, 1.5), 0.0);
}

#[test]
fn checker_rejects_a_missing_beam_factor() {
    let verdict = check::reflectance(&planted::fresnel_without_beam_factor, &Options::default());
    assert!(
        verdict.failed("energy") && verdict.failed("normal"),
        "{verdict}"
    );
}

#[test]
fn checker_rejects_p_paired_like_s() {
    let verdict = check::reflectance(&planted::fresnel_p_paired_like_s, &Options::default());
    assert!(verdict.failed("energy"), "{verdict}");
    assert!(
        !verdict.failed("normal") && !verdict.failed("tir"),
        "{verdict}"
    );
}

/// Schlick (with the right cosine) keeps the exact values at both ends, TIR and
/// reciprocity, but not energy, and not matched indices: (1 - cos)^5 is not 0 there.
#[test]
fn checker_on_schlick() {
    let verdict = check::reflectance(&schlick, &Options::default());
    for claim in ["range", "normal", "grazing", "tir", "reciprocity"] {
        assert!(!verdict.failed(claim), "{claim}\n{verdict}");
    }
    assert!(
        verdict.failed("energy") && verdict.failed("matched"),
        "{verdict}"
    );
    assert!((schlick(0.5, 1.5, 1.5) - 0.5f64.powi(5)).abs() < EPS);
}

/// The fit passes every claim but energy (it approximates) and normal (exact only to the
/// rounding of its coefficients, not to 4 eps).
#[test]
fn checker_on_the_fit() {
    let fit = |c: f64, n1: f64, n2: f64| FresnelFit::new(n1, n2).eval(c);
    let verdict = check::reflectance(&fit, &Options::default());
    for claim in ["range", "grazing", "matched", "tir", "reciprocity"] {
        assert!(!verdict.failed(claim), "{claim}\n{verdict}");
    }
    assert!(
        verdict.failed("energy") && verdict.failed("normal"),
        "{verdict}"
    );
}

/// The amplitudes themselves, signs included, pass their own checker; each planted bug of
/// it fails the claims it breaks, although every one of them has the exact reflectance.
#[test]
fn amplitude_checker_passes_the_library_and_rejects_the_planted_bugs() {
    type AmplitudeFn = dyn Fn(f64, f64, f64) -> Option<Amplitudes>;
    check::amplitudes(&amplitudes, &Options::default()).assert_pass();
    let cases: [(&AmplitudeFn, &[&str]); 3] = [
        (&planted::amplitude::grazing_jump, &["grazing", "brewster"]),
        (
            &planted::amplitude::other_sign_of_r_p,
            &["values", "normal", "stokes", "brewster"],
        ),
        (
            &planted::amplitude::no_transmission,
            &["values", "normal", "stokes"],
        ),
    ];
    for (f, claims) in cases {
        let verdict = check::amplitudes(f, &Options::default());
        for claim in claims {
            assert!(verdict.failed(claim), "{claim}\n{verdict}");
        }
        // R = r^2 cannot tell: the reflectance built from each is the exact one.
        let reflectance = |c: f64, n1: f64, n2: f64| match f(c, n1, n2) {
            Some(a) => 0.5 * (a.r_s * a.r_s + a.r_p * a.r_p),
            None => 1.0,
        };
        check::reflectance(&reflectance, &Options::default()).assert_pass();
    }
}

// ANCHOR: seed_schlick
/// Source notes: "R(theta) = R0 + (1 - R0)(1 - cos theta_i)^5". Leaving the denser medium this
/// ignores total internal reflection and the bending of the ray.
#[test]
fn seed_schlick_fails_tir_and_reciprocity() {
    let verdict = check::reflectance(&schlick_seed, &Options::default());
    for claim in ["tir", "reciprocity", "energy"] {
        assert!(verdict.failed(claim), "{claim}\n{verdict}");
    }
    // Glass to air just past the critical angle (41.81°): the truth is 1, the source notes say 0.04.
    let past = 42f64.to_radians().cos();
    assert_eq!(fresnel_dielectric(past, 1.5, 1.0), 1.0);
    assert_eq!(schlick(past, 1.5, 1.0), 1.0);
    assert!(schlick_seed(past, 1.5, 1.0) < 0.05);
}
// ANCHOR_END: seed_schlick

// ---------------------------------------------------------------------------------------
// Constructed values.

/// Normal incidence: R = ((n1 - n2)/(n1 + n2))^2, from both sides; 0.04 for glass.
#[test]
fn normal_incidence_reflectance() {
    assert!((fresnel_dielectric(1.0, 1.0, 1.5) - 0.04).abs() < 2.0 * EPS);
    for n in IORS {
        let expected = ((1.0 - n) / (1.0 + n)).powi(2);
        for (n1, n2) in [(1.0, n), (n, 1.0)] {
            let r = fresnel_polarized(1.0, n1, n2);
            assert!((r.s - expected).abs() < 2.0 * EPS && (r.p - expected).abs() < 2.0 * EPS);
            assert!((fresnel_dielectric(1.0, n1, n2) - r0(n1, n2)).abs() < 2.0 * EPS);
        }
    }
}

/// Grazing incidence: R -> 1, and exactly 1 at cos_i = 0, for both polarisations.
#[test]
fn grazing_reflectance_tends_to_one() {
    for n in IORS {
        let mut previous = 0.0;
        for degrees in [80.0, 85.0, 89.0, 89.9, 89.99, 89.999] {
            let r = fresnel_dielectric(f64::to_radians(degrees).cos(), 1.0, n);
            assert!(r > previous, "{n} {degrees}");
            previous = r;
        }
        assert!(previous > 0.999, "{n}: {previous}");
        assert_eq!(
            fresnel_polarized(0.0, 1.0, n),
            fresnel_polarized(0.0, n, 1.0)
        );
        assert_eq!(fresnel_dielectric(0.0, 1.0, n), 1.0);
    }
}

/// The amplitudes are continuous at both ends of the range of cosines, in both directions
/// through the interface: at normal incidence (Born & Wolf: r_p = -r_s, t_s = t_p), at
/// grazing incidence from the less dense side (r_s = r_p = -1, t_s = t_p = 0: no jump at
/// cos_i = 0), and at the critical angle from the denser side, where the real amplitudes
/// (r_s = r_p = 1) meet the complex ones of total internal reflection (`thinfilm::interface`,
/// with cos_t imaginary), which run on to -1 at grazing incidence.
#[test]
fn amplitudes_are_continuous_at_the_ends() {
    use num_complex::Complex64;
    use raylemma::optics::thinfilm::{cos_theta, interface};
    let close = |a: f64, b: f64, tol: f64, what: &str| {
        assert!((a - b).abs() <= tol, "{what}: {a} against {b}");
    };
    let real = |x: f64| Complex64::new(x, 0.0);
    for n in IORS {
        for (n1, n2) in [(1.0, n), (n, 1.0)] {
            // Normal incidence, approached from below: Born & Wolf's r_p = -r_s.
            let at = amplitudes(1.0, n1, n2).unwrap();
            let near = amplitudes(1.0 - 1e-12, n1, n2).unwrap();
            let r = (n1 - n2) / (n1 + n2);
            close(at.r_s, r, 2.0 * EPS, "r_s at normal incidence");
            close(at.r_p, -r, 2.0 * EPS, "r_p = -r_s at normal incidence");
            close(at.t_s, at.t_p, 2.0 * EPS, "t_s = t_p at normal incidence");
            close(
                at.t_s,
                2.0 * n1 / (n1 + n2),
                4.0 * EPS,
                "t at normal incidence",
            );
            for (x, y) in [
                (at.r_s, near.r_s),
                (at.r_p, near.r_p),
                (at.t_s, near.t_s),
                (at.t_p, near.t_p),
            ] {
                close(
                    x,
                    y,
                    1e-10,
                    &format!("{n1}->{n2}: cos 1 against cos 1 - 1e-12"),
                );
            }
            // Every amplitude agrees with the complex ones of the thin-film chapter wherever
            // the transmitted wave propagates.
            for k in 0..=900 {
                let c = f64::to_radians(f64::from(k) * 0.1).cos();
                let Some(a) = amplitudes(c, n1, n2) else {
                    continue;
                };
                let i = interface(n1, real(c), n2, cos_theta(n1, c, n2));
                for (x, z) in [
                    (a.r_s, i.r_s),
                    (a.r_p, i.r_p),
                    (a.t_s, i.t_s),
                    (a.t_p, i.t_p),
                ] {
                    assert!(
                        (z - x).norm() <= 1e-13,
                        "{n1}->{n2} at {k}/10 deg: {x} against {z}"
                    );
                }
            }
        }
        // Grazing incidence from the less dense side: -1, -1, 0, 0 at cos_i = 0 and in the
        // limit; the gap closes linearly in cos_i.
        let at = amplitudes(0.0, 1.0, n).unwrap();
        assert_eq!(
            (at.r_s, at.r_p, at.t_s, at.t_p),
            (-1.0, -1.0, 0.0, 0.0),
            "{n}"
        );
        for c in [1e-300, 1e-12, 1e-6] {
            let near = amplitudes(c, 1.0, n).unwrap();
            for (x, y) in [
                (at.r_s, near.r_s),
                (at.r_p, near.r_p),
                (at.t_s, near.t_s),
                (at.t_p, near.t_p),
            ] {
                close(
                    x,
                    y,
                    10.0 * c + EPS,
                    &format!("{n}: cos 0 against cos {c:e}"),
                );
            }
        }
        // Leaving the denser medium: towards the critical angle the real amplitudes tend to
        // r_s = r_p = 1, t_s = 2, t_p = 2 n1/n2; just past it the complex ones start there,
        // with |r| = 1, and at grazing incidence they reach -1, -1, 0, 0 too.
        let theta_c = critical_angle(n, 1.0).unwrap();
        for side in [-1.0, 1.0] {
            let c = (theta_c + side * 1e-12).cos();
            let (r_s, r_p, t_s, t_p) = match amplitudes(c, n, 1.0) {
                Some(a) => (real(a.r_s), real(a.r_p), real(a.t_s), real(a.t_p)),
                None => {
                    let i = interface(n, real(c), 1.0, cos_theta(n, c, 1.0));
                    close(
                        i.r_s.norm(),
                        1.0,
                        1e-14,
                        "|r_s| under total internal reflection",
                    );
                    close(
                        i.r_p.norm(),
                        1.0,
                        1e-14,
                        "|r_p| under total internal reflection",
                    );
                    (i.r_s, i.r_p, i.t_s, i.t_p)
                }
            };
            assert_eq!(
                amplitudes(c, n, 1.0).is_none(),
                side > 0.0,
                "{n}: which side of the critical angle"
            );
            for (z, limit) in [(r_s, 1.0), (r_p, 1.0), (t_s, 2.0), (t_p, 2.0 * n)] {
                assert!(
                    (z - real(limit)).norm() <= 1e-4,
                    "{n}, {side} side of the critical angle: {z} against {limit}"
                );
            }
        }
        for c in [0.0, 1e-12] {
            let i = interface(n, real(c), 1.0, cos_theta(n, c, 1.0));
            for (z, limit) in [(i.r_s, -1.0), (i.r_p, -1.0), (i.t_s, 0.0), (i.t_p, 0.0)] {
                assert!(
                    (z - real(limit)).norm() <= 1e-10,
                    "{n} leaving at cos {c:e}: {z} against {limit}"
                );
            }
        }
    }
}

/// r_p changes sign at Brewster's angle, and r_s never does. Entering the denser medium r_p
/// is positive below Brewster's angle (+(n2 - n1)/(n1 + n2) at normal incidence) and
/// negative above it (down to -1 at grazing); leaving it, the other way round, up to +1 at
/// the critical angle. r_s is negative entering and positive leaving, at every angle.
#[test]
fn r_p_changes_sign_at_brewsters_angle() {
    for n in IORS {
        for (n1, n2) in [(1.0, n), (n, 1.0)] {
            let theta_b = brewster_angle(n1, n2);
            let entering = n1 < n2;
            for k in 0..=9000 {
                let theta = f64::to_radians(f64::from(k) * 0.01);
                let Some(a) = amplitudes(theta.cos(), n1, n2) else {
                    continue; // past the critical angle
                };
                assert_eq!(
                    a.r_s < 0.0,
                    entering,
                    "{n1}->{n2} at {theta}: r_s = {}",
                    a.r_s
                );
                if (theta - theta_b).abs() > 1e-9 {
                    let positive = (theta < theta_b) == entering;
                    assert_eq!(
                        a.r_p > 0.0,
                        positive,
                        "{n1}->{n2} at {theta}: r_p = {}",
                        a.r_p
                    );
                }
            }
            let below = amplitudes((theta_b - 1e-3).cos(), n1, n2).unwrap().r_p;
            let above = amplitudes((theta_b + 1e-3).cos(), n1, n2).unwrap().r_p;
            assert!(below * above < 0.0, "{n1}->{n2}: {below} and {above}");
            assert!(amplitudes(theta_b.cos(), n1, n2).unwrap().r_p.abs() < 1e-14);
        }
    }
}

/// Brewster's angle atan(n2/n1): R_p = 0 there, from either side (inside, Brewster's
/// angle is below the critical angle), and the unpolarised R is half of R_s.
#[test]
fn brewster_angle_zeroes_r_p() {
    for n in IORS {
        for (n1, n2) in [(1.0, n), (n, 1.0)] {
            let theta_b = brewster_angle(n1, n2);
            let r = fresnel_polarized(theta_b.cos(), n1, n2);
            assert!(r.p < 1e-28, "{n1}->{n2}: R_p = {:e}", r.p);
            assert!(r.s > 0.01);
            // The planted bug has no Brewster angle: its "R_p" is R_s.
            assert!(planted::fresnel_p_paired_like_s(theta_b.cos(), n1, n2) > 0.01);
        }
    }
    // Glass: 56.31° from air, 33.69° from inside.
    assert!((brewster_angle(1.0, 1.5).to_degrees() - 56.31).abs() < 0.005);
    assert!((brewster_angle(1.5, 1.0).to_degrees() - 33.69).abs() < 0.005);
}

/// Matched indices: no interface, no reflection, at every angle including grazing, where
/// the naive formula divides 0 by 0.
#[test]
fn matched_indices_reflect_nothing() {
    for n in [1.0, 1.33, 1.5, 2.4] {
        for &c in &check::sweep_cosines(&Options::default()) {
            assert_eq!(fresnel_dielectric(c, n, n), 0.0);
            assert_eq!(fresnel_transmittance(c, n, n).unpolarized(), 1.0);
        }
    }
    assert!(planted::fresnel_naive(0.0, 1.0, 1.0).is_nan());
}

/// At normal incidence on glass t_s = 0.8, so t_s^2 = 0.64, while T = 1 - R = 0.96: the
/// square of the transmission amplitude is not the transmitted power.
#[test]
fn transmission_amplitude_squared_is_not_transmittance() {
    let a = amplitudes(1.0, 1.0, 1.5).unwrap();
    assert!((a.t_s - 0.8).abs() < 2.0 * EPS && (a.t_s * a.t_s - 0.64).abs() < 2.0 * EPS);
    assert!((1.0 - fresnel_dielectric(1.0, 1.0, 1.5) - 0.96).abs() < 2.0 * EPS);
    assert!((fresnel_transmittance(1.0, 1.0, 1.5).s - 0.96).abs() < 2.0 * EPS);
}

// ANCHOR: energy_test
/// Energy: R + T = 1, with T built in this test from the transmission amplitudes, angle by
/// angle (theta_t = asin(n1 sin theta_i / n2)), never from R.
#[test]
fn reflectance_plus_transmittance_is_one() {
    let mut worst: f64 = 0.0;
    for n in IORS {
        for (n1, n2) in [(1.0, n), (n, 1.0)] {
            for k in 0..900 {
                let theta_i = f64::to_radians(f64::from(k) * 0.1);
                let sin_t = n1 * theta_i.sin() / n2;
                if sin_t >= 1.0 - 1e-6 {
                    continue; // past (or at) the critical angle
                }
                let (cos_i, cos_t) = (theta_i.cos(), sin_t.asin().cos());
                let t_s = 2.0 * n1 * cos_i / (n1 * cos_i + n2 * cos_t);
                let t_p = 2.0 * n1 * cos_i / (n2 * cos_i + n1 * cos_t);
                let beam = (n2 * cos_t) / (n1 * cos_i);
                let (big_t_s, big_t_p) = (beam * t_s * t_s, beam * t_p * t_p);
                let r = fresnel_polarized(cos_i, n1, n2);
                worst = max_abs([worst, r.s + big_t_s - 1.0, r.p + big_t_p - 1.0]);
                // Without the beam factor, t^2 is not a transmittance (except at n1 = n2).
                assert!((r.s + t_s * t_s - 1.0).abs() > 1e-3, "{n1}->{n2} {k}");
            }
        }
    }
    assert!(worst < 1e-12, "worst |R + T - 1| = {worst:e}");
}
// ANCHOR_END: energy_test

/// The library's own transmittance (from its amplitudes) balances R too, everywhere.
#[test]
fn library_transmittance_balances_reflectance() {
    for &(n1, n2) in &check::PAIRS {
        for &c in &check::sweep_cosines(&Options::default()) {
            let (r, t) = (
                fresnel_polarized(c, n1, n2),
                fresnel_transmittance(c, n1, n2),
            );
            let unit = EPS * (1.0 + 1.0 / cos_transmitted(c.abs().min(1.0), n1, n2).unwrap_or(1.0));
            assert!((r.s + t.s - 1.0).abs() <= 64.0 * unit, "{n1} {n2} {c}");
            assert!((r.p + t.p - 1.0).abs() <= 64.0 * unit, "{n1} {n2} {c}");
        }
    }
}

/// The transmittance is symmetric: T from 1 to 2 at theta_i equals T from 2 to 1 at
/// theta_t (and so is the reflectance).
#[test]
fn transmittance_is_symmetric() {
    for n in IORS {
        for k in 0..=900 {
            let cos_i = f64::to_radians(f64::from(k) * 0.1).cos();
            let cos_t = cos_transmitted(cos_i, 1.0, n).unwrap();
            let (there, back) = (
                fresnel_transmittance(cos_i, 1.0, n),
                fresnel_transmittance(cos_t, n, 1.0),
            );
            let unit = EPS * (1.0 + 1.0 / cos_i.max(1e-300));
            assert!((there.s - back.s).abs() <= 64.0 * unit, "{n} {k}");
            assert!((there.p - back.p).abs() <= 64.0 * unit, "{n} {k}");
        }
    }
}

/// Past the critical angle R = 1 and T = 0; just before it, T > 0.
#[test]
fn total_internal_reflection_past_the_critical_angle() {
    for n in IORS {
        let theta_c = critical_angle(n, 1.0).unwrap();
        for step in 1..100 {
            let theta = theta_c + f64::from(step) * (90f64.to_radians() - theta_c) / 100.0;
            assert_eq!(fresnel_dielectric(theta.cos(), n, 1.0), 1.0);
            assert_eq!(
                fresnel_transmittance(theta.cos(), n, 1.0).unpolarized(),
                0.0
            );
            assert!(amplitudes(theta.cos(), n, 1.0).is_none());
        }
        let before = (theta_c - 1e-6).cos();
        assert!(fresnel_transmittance(before, n, 1.0).unpolarized() > 0.0);
        assert!(fresnel_dielectric(before, n, 1.0) < 1.0);
    }
}

/// What the rearranged `cos^2 theta_t = (1 - eta^2) + (eta cos_i)^2` does not buy leaving a
/// denser medium: just inside the critical angle, where the exact value is a few times
/// 1e-17, the textbook `1 - eta^2 (1 - cos_i^2)` and the rearranged sum both round below 0,
/// and `cos_transmitted` reports total internal reflection. `eta = 265/128` and
/// `cos_i = m 2^-53` are chosen so that the exact sign is an integer comparison:
/// `1 - eta^2 (1 - cos_i^2) > 0` iff `2^120 > 265^2 (2^106 - m^2)`.
#[test]
fn both_forms_of_cos_t_squared_can_round_below_zero_leaving_a_denser_medium() {
    let m: u64 = 0x1c_04ff_24f2_087f;
    let cos_i = m as f64 / 2f64.powi(53);
    let eta = 265.0 / 128.0;
    let exact_positive =
        (1u128 << 120) > 265u128 * 265 * ((1u128 << 106) - u128::from(m) * u128::from(m));
    assert!(exact_positive, "the incidence is below the critical angle");
    let textbook = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    let rearranged = (1.0 - eta * eta) + (eta * cos_i) * (eta * cos_i);
    assert!(textbook < 0.0, "textbook {textbook:e}");
    assert!(rearranged < 0.0, "rearranged {rearranged:e}");
    assert!(cos_transmitted(cos_i, eta, 1.0).is_none());
}

/// Every input of the domain, and some outside it: no NaN, R in [0, 1].
#[test]
fn sweep_of_the_domain_gives_no_nan() {
    let indices = [1.0, 1.0 + 1e-15, 1.0001, 1.2, 1.33, 1.5, 2.4, 4.0, 1e3];
    let mut count = 0;
    for &n1 in &indices {
        for &n2 in &indices {
            let fit = FresnelFit::new(n1, n2);
            for k in -2000..=2000 {
                let cos_i = f64::from(k) / 2000.0;
                for r in [
                    fresnel_dielectric(cos_i, n1, n2),
                    schlick(cos_i, n1, n2),
                    fit.eval(cos_i),
                    fresnel_transmittance(cos_i, n1, n2).s,
                    fresnel_transmittance(cos_i, n1, n2).p,
                ] {
                    assert!((0.0..=1.0).contains(&r), "{n1} {n2} {cos_i}: {r}");
                    count += 1;
                }
            }
        }
    }
    assert!(count > 1_000_000);
}

fn errors(f: &dyn Fn(f64) -> f64, n1: f64, n2: f64) -> ErrorStats {
    approximation_error(f, n1, n2, SWEEP_ANGLES)
}

mod approximations;
mod properties;

// ---------------------------------------------------------------------------------------
// Exercises. Each scaffold is the student's to fill in; each ignored test checks it, and
// fails until it is done: `cargo test --test book optics::fresnel::exercise_ -- --ignored`.

/// Exercise 1 of *Fresnel and Schlick*: the unpolarised reflectance `(|r_s|^2 + |r_p|^2)/2`
/// of light in a dielectric of index `n1` meeting a conductor of complex index `n2 = n + ik`.
#[allow(unused_variables)]
fn your_conductor_reflectance(cos_i: f64, n1: f64, n2: num_complex::Complex64) -> f64 {
    unimplemented!("exercise 1 of Fresnel and Schlick: write the reflectance of a conductor")
}

/// The conductor's reflectance written as pbrt-v4 writes it (`FrComplex`), with the
/// principal complex square root: the test's independent reference.
fn pbrt_fr_complex(cos_i: f64, n1: f64, n2: num_complex::Complex64) -> f64 {
    let eta = n2 / n1;
    let c = cos_i.clamp(0.0, 1.0);
    let sin2_t = (1.0 - c * c) / (eta * eta);
    let cos_t = (1.0 - sin2_t).sqrt();
    let r_parl = (eta * c - cos_t) / (eta * c + cos_t);
    let r_perp = (c - eta * cos_t) / (c + eta * cos_t);
    0.5 * (r_parl.norm_sqr() + r_perp.norm_sqr())
}

#[test]
#[ignore = "exercise 1 of Fresnel and Schlick: fill in your_conductor_reflectance, then run it"]
fn exercise_1_conductor_reflectance() {
    use num_complex::Complex64;
    // Gold-like, aluminium-like and silver-like indices at about 550 nm, and a made-up one.
    let metals = [
        Complex64::new(0.2, 3.0),
        Complex64::new(0.96, 6.69),
        Complex64::new(0.06, 3.59),
        Complex64::new(2.5, 0.5),
    ];
    for m in metals {
        let (n, k) = (m.re, m.im);
        let normal = ((n - 1.0).powi(2) + k * k) / ((n + 1.0).powi(2) + k * k);
        let r1 = your_conductor_reflectance(1.0, 1.0, m);
        assert!(
            (r1 - normal).abs() <= 1e-14,
            "{m}: R(normal) = {r1}, expected {normal}"
        );
        let r0 = your_conductor_reflectance(0.0, 1.0, m);
        assert!(
            (r0 - 1.0).abs() <= 1e-14,
            "{m}: R(grazing) = {r0}, expected 1"
        );
        for k in 0..=90 {
            let c = f64::to_radians(f64::from(k)).cos();
            for n1 in [1.0, 1.33] {
                let (got, want) = (
                    your_conductor_reflectance(c, n1, m),
                    pbrt_fr_complex(c, n1, m),
                );
                assert!(
                    (got - want).abs() <= 1e-12,
                    "{m} from {n1} at {k} deg: {got}, expected {want}"
                );
                assert!((0.0..=1.0).contains(&got), "{m} at {k} deg: {got}");
            }
        }
    }
    // A real index is a dielectric: the exact formula, matched indices included.
    for n in [1.0, 1.33, 1.5, 2.4] {
        for k in 0..=90 {
            let c = f64::to_radians(f64::from(k)).cos();
            let (got, want) = (
                your_conductor_reflectance(c, 1.0, Complex64::new(n, 0.0)),
                fresnel_dielectric(c, 1.0, n),
            );
            assert!(
                (got - want).abs() <= 1e-14,
                "real index {n} at {k} deg: {got}, expected {want}"
            );
        }
    }
}

/// Exercise 2 of *Fresnel and Schlick*: Lazányi and Szirmay-Kalos' correction of Schlick,
/// `R0 + (1 - R0)(1 - c)^5 - a c (1 - c)^6`, with `a` chosen so that it is exact at
/// `c = cos theta = 1/7`, for light entering the denser medium (`n1 < n2`).
#[allow(unused_variables)]
fn your_lazanyi_schlick(cos_i: f64, n1: f64, n2: f64) -> f64 {
    unimplemented!(
        "exercise 2 of Fresnel and Schlick: write Schlick with the Lazányi term, exact at cos = 1/7"
    )
}

#[test]
#[ignore = "exercise 2 of Fresnel and Schlick: fill in your_lazanyi_schlick, then run it"]
fn exercise_2_lazanyi_schlick() {
    for n in IORS {
        let f = |c: f64| your_lazanyi_schlick(c, 1.0, n);
        let at = 1.0 / 7.0;
        assert!(
            (f(at) - fresnel_dielectric(at, 1.0, n)).abs() <= 4.0 * EPS,
            "{n}: not exact at 1/7"
        );
        assert!(
            (f(1.0) - r0(1.0, n)).abs() <= 4.0 * EPS,
            "{n}: not exact at normal incidence"
        );
        assert!(
            (f(0.0) - 1.0).abs() <= 4.0 * EPS,
            "{n}: not exact at grazing incidence"
        );
        let ls = errors(&f, 1.0, n).worst_abs;
        let plain = errors(&|c| schlick(c, 1.0, n), 1.0, n).worst_abs;
        let fit = FresnelFit::new(1.0, n);
        let fitted = errors(&|c| fit.eval(c), 1.0, n).worst_abs;
        assert!(
            ls < plain,
            "{n}: worst error {ls:e}, no better than Schlick's {plain:e}"
        );
        assert!(
            ls > fitted,
            "{n}: worst error {ls:e} below the fit's {fitted:e}: check the sweep"
        );
    }
}

/// Exercise 4 of *Fresnel and Schlick*: your own approximation of the exact reflectance,
/// for light from `n1` into `n2` (either order), cheaper than the exact formula.
#[allow(unused_variables)]
fn your_approximation(cos_i: f64, n1: f64, n2: f64) -> f64 {
    unimplemented!("exercise 4 of Fresnel and Schlick: write your approximation of the reflectance")
}

#[test]
#[ignore = "exercise 4 of Fresnel and Schlick: fill in your_approximation, then run it"]
fn exercise_4_your_approximation() {
    let verdict = check::reflectance(&your_approximation, &Options::default());
    for claim in ["range", "normal", "grazing", "tir", "reciprocity"] {
        assert!(!verdict.failed(claim), "{claim}\n{verdict}");
    }
    for n in IORS {
        for (n1, n2) in [(1.0, n), (n, 1.0)] {
            let yours = errors(&|c| your_approximation(c, n1, n2), n1, n2).worst_abs;
            let plain = errors(&|c| schlick(c, n1, n2), n1, n2).worst_abs;
            assert!(
                yours < plain,
                "{n1}->{n2}: worst error {yours:e}, no better than Schlick's {plain:e}"
            );
        }
    }
}

/// Exercise 5 of *Fresnel and Schlick*: the factor (unpolarised) by which a path tracer
/// that weights a camera ray entering a glass block (1 -> 1.5) at 60° by `t^2` instead of
/// `T` makes what is inside the block brighter (> 1) or darker (< 1).
const YOUR_FACTOR_INSIDE_GLASS_AT_60: Option<f64> = None;

#[test]
#[ignore = "exercise 5 of Fresnel and Schlick: set YOUR_FACTOR_INSIDE_GLASS_AT_60, then run it"]
fn exercise_5_the_missing_cosine_in_t() {
    let a = amplitudes(0.5, 1.0, 1.5).unwrap();
    let t = fresnel_transmittance(0.5, 1.0, 1.5);
    let factor = (a.t_s * a.t_s + a.t_p * a.t_p) / (t.s + t.p);
    let yours =
        YOUR_FACTOR_INSIDE_GLASS_AT_60.expect("exercise 5: set YOUR_FACTOR_INSIDE_GLASS_AT_60");
    assert!(
        (yours - factor).abs() <= 1e-3,
        "{yours}, but t^2 / T = {factor}"
    );
}
