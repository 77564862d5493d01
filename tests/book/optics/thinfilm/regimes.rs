//! Thin and thick films, grazing incidence, total reflection through a film (frustrated, and at
//! the critical angle), and the corners of the domain: where the plain Airy sum loses digits,
//! and no NaN anywhere.

use super::*;

/// A film much thinner than the wavelength barely changes the interface, and only to
/// second order: with real cosines the first-order change of r is in quadrature with r, so
/// R(d) − R(0) ∝ d² (doubling d quadruples the change; |R(1e-6 nm) − R(0)| < 1e-9).
#[test]
fn very_thin_films_tend_to_the_bare_interface() {
    for (n1, n2, n3) in [(1.0, 1.33, 1.0), (1.0, 1.5, 1.33), (1.52, 1.38, 1.0)] {
        for t in [0.0, 0.5] {
            let r0 = Film::new(n1, n2, n3, 0.0).reflectance(550.0, t);
            let r = |d: f64| Film::new(n1, n2, n3, d).reflectance(550.0, t);
            assert!((r(1e-6) - r0).abs() < 1e-9);
            let (a, b) = (r(2.0) - r0, r(1.0) - r0);
            assert!(a.abs() < 1e-2 && (a / b - 4.0).abs() <= 1e-2, "{a} {b}");
        }
    }
}

/// A thick film's fringes, averaged over one period of the phase, leave the incoherent
/// sum of the multiple reflections, (R12 + R23 − 2 R12 R23)/(1 − R12 R23), per polarisation:
/// 100 µm of oil on water at 30°, sampled at 64 points per fringe over ten fringes (uniform
/// in 1/λ, where the phase is uniform), agrees to 1e-9.
#[test]
fn thick_film_fringes_average_to_the_incoherent_sum() {
    let film = Film::new(1.0, 1.5, 1.33, 1e5);
    let theta1 = 30f64.to_radians();
    let c2 = cos_theta(1.0, theta1.cos(), 1.5).re;
    // 2δ = 4π n2 d c2 / λ advances by 2π when 1/λ advances by 1/(2 n2 d c2).
    let step = 1.0 / (2.0 * 1.5 * 1e5 * c2) / 64.0;
    let (mut s, mut p) = (0.0, 0.0);
    let count = 640;
    for k in 0..count {
        let lambda = 1.0 / (1.0 / 550.0 + step * f64::from(k));
        let r = film.response(lambda, theta1);
        s += r.reflectance_s / f64::from(count);
        p += r.reflectance_p / f64::from(count);
    }
    let [r12s, r12p] = bare(1.0, 1.5, theta1);
    let theta2 = (theta1.sin() / 1.5).asin();
    let [r23s, r23p] = bare(1.5, 1.33, theta2);
    let want_s = incoherent_reflectance(r12s, r23s);
    let want_p = incoherent_reflectance(r12p, r23p);
    assert!((s - want_s).abs() < 1e-9, "{s} vs {want_s}");
    assert!((p - want_p).abs() < 1e-9, "{p} vs {want_p}");
}

/// Grazing incidence reflects everything: R = 1 and T = 0 at exactly 90°, and R → 1
/// continuously as the angle approaches it (1 − R within 10 times the angle to grazing).
#[test]
fn grazing_incidence_reflects_everything() {
    for (n1, n2, n3) in [
        (1.0, 1.33, 1.0),
        (1.0, 1.5, 1.33),
        (1.52, 1.38, 1.0),
        (1.0, 1.0, 1.5),
    ] {
        let film = Film::new(n1, n2, n3, 300.0);
        let r = film.response(550.0, FRAC_PI_2);
        assert!((r.reflectance() - 1.0).abs() <= 1e-12 && r.transmittance().abs() <= 1e-12);
        for k in 1..=8 {
            let gap = 10f64.powi(-k);
            let near = film.reflectance(550.0, FRAC_PI_2 - gap);
            assert!(
                near <= 1.0 + 1e-12 && 1.0 - near <= 10.0 * gap,
                "{gap}: {near}"
            );
        }
    }
}

/// Seen from inside glass (1.52) through an MgF2 film (1.38) into air, every angle beyond
/// the glass–air critical angle (41.1°) is totally reflected: R = 1, T = 0, with no NaN,
/// although the wave in the air (and, beyond 65.2°, in the film too) is evanescent.
#[test]
fn total_internal_reflection_through_a_film() {
    let film = Film::new(1.52, 1.38, 1.0, 100.0);
    let critical = (1.0f64 / 1.52).asin();
    assert!((critical.to_degrees() - 41.14).abs() < 0.01);
    let film_critical = (1.38f64 / 1.52).asin();
    assert!((film_critical.to_degrees() - 65.2).abs() < 0.05);
    for k in 0..=200 {
        let t = critical + (FRAC_PI_2 - critical) * f64::from(k) / 200.0 + 1e-12;
        let t = t.min(FRAC_PI_2);
        let r = film.response(550.0, t);
        assert!(
            (r.reflectance_s - 1.0).abs() <= 1e-12 && (r.reflectance_p - 1.0).abs() <= 1e-12,
            "{t}: {r:?}"
        );
        assert!(r.transmittance() == 0.0, "{t}: {r:?}");
    }
}

/// Frustrated total internal reflection: an air gap (n2 = 1) between two glass blocks
/// (1.5) at 60°, beyond the critical angle. Light tunnels through a thin gap, T falls by
/// e^{−2 k κ Δd} for each added Δd of thickness (κ = n2 |cos θ2|), and the sum stays 1.
#[test]
fn frustrated_total_internal_reflection_tunnels_and_decays() {
    let theta1 = 60f64.to_radians();
    let kappa = cos_theta(1.5, theta1.cos(), 1.0).im;
    assert!(kappa > 0.0);
    let k = 2.0 * PI / 550.0;
    let t = |d: f64| Film::new(1.5, 1.0, 1.5, d).response(550.0, theta1);
    assert!(t(10.0).transmittance() > 0.5);
    for d in [600.0, 1200.0, 2400.0] {
        let ratio = t(d + 50.0).transmittance_s / t(d).transmittance_s;
        let want = (-2.0 * k * kappa * 50.0).exp();
        assert!((ratio / want - 1.0).abs() < 1e-3, "{ratio} vs {want}");
        let r = t(d);
        assert!((r.reflectance() + r.transmittance() - 1.0).abs() <= 1e-12);
    }
}

/// The film exactly at its critical angle: n1 = 1.25, n2 = 1, cos θ1 = 0.6, so that
/// cos²θ2 = (1 − 1.25²) + (1.25 · 0.6)² = 0 exactly in floating point. The plain Airy sum
/// is 0/0 there (r12 = 1, r23 = −1, z = 1); the rearranged form needs no special case and
/// agrees with the transfer matrix to 1e-12, conserving energy.
#[test]
fn film_exactly_at_its_critical_angle() {
    let (n1, n2, n3, cos1) = (1.25, 1.0, 1.5, 0.6);
    assert_eq!(cos_theta(n1, cos1, n2).norm_sqr(), 0.0);
    for d in [0.0, 1.0, 100.0, 5000.0] {
        let film = Film::new(n1, n2, n3, d);
        let r = film.response_cos(550.0, cos1);
        let got = [
            r.reflectance_s,
            r.reflectance_p,
            r.transmittance_s,
            r.transmittance_p,
        ];
        let want = tmm_cos(&film, 550.0, cos1);
        for k in 0..4 {
            assert!(
                got[k].is_finite() && (got[k] - want[k]).abs() <= 1e-12,
                "d = {d}: {got:?} vs {want:?}"
            );
        }
        assert!((got[0] + got[2] - 1.0).abs() <= 1e-12 && (got[1] + got[3] - 1.0).abs() <= 1e-12);
    }
}

/// The plain Airy sum `(r12 + r23 z)/(1 + r12 r23 z)`, assembled from the library's
/// pieces, is right away from two corners: 1e-12 against the transfer matrix wherever
/// |cos θ1| and |cos θ2| exceed 1e-3. In the corners its denominator is a difference of
/// nearly equal numbers:
/// * near the film's critical angle r12 → 1, r23 → −1, z → 1. At 30° in glass of
///   n1 = 2.4 under a film of n2 = 1.2 (n1 sin θ1 = n2 but for rounding, |cos θ2| < 1e-7)
///   with d = 0 it is wrong by more than 1e-10;
/// * within 1e-12 rad of grazing incidence over a sub-picometre film whose far side has
///   the ambient's index, r12 → −1, r23 → 1: n1 = n3 = 1, n2 = 1.33, d = 1e-9 nm, it is
///   wrong by more than 1e-7 (a corner no real scene reaches).
///
/// The library's rearranged form stays within 1e-13 in both.
#[test]
fn plain_airy_sum_loses_digits_in_two_corners() {
    let cases = sweep(SWEEP_CASES, SWEEP_SEED);
    let away: Vec<Case> = cases
        .into_iter()
        .filter(|c| {
            let cos1 = c.theta1.cos();
            cos1 > 1e-3 && cos_theta(c.film.n1, cos1, c.film.n2).norm() > 1e-3
        })
        .collect();
    assert!(away.len() > SWEEP_CASES / 2);
    let (worst, at) = worst_unpolarised(&away, |c| assembled(c, phase, false));
    assert!(worst <= 1e-12, "{worst} at {at:?}");

    for (film, t, threshold) in [
        (Film::new(2.4, 1.2, 1.0, 0.0), 30f64.to_radians(), 1e-10),
        (Film::new(1.0, 1.33, 1.0, 1e-9), FRAC_PI_2 - 1e-12, 1e-7),
    ] {
        let case = Case {
            film,
            wavelength_nm: 550.0,
            theta1: t,
        };
        let [rs, rp, ..] = tmm(&film, 550.0, t);
        let reference = 0.5 * (rs + rp);
        let plain = assembled(&case, phase, false);
        let plain_error = (plain - reference).abs();
        let stable_error = (film.reflectance(550.0, t) - reference).abs();
        assert!(
            plain_error.is_nan() || plain_error > threshold,
            "plain sum error {plain_error} for {film:?}"
        );
        assert!(
            stable_error <= 1e-13,
            "stable error {stable_error} for {film:?}"
        );
    }
    // The first reference is known exactly: the bare interface totally reflects.
    assert_eq!(bare(2.4, 1.0, 30f64.to_radians()), [1.0, 1.0]);
}

/// No NaN, R and T in [0, 1], R + T = 1 on a grid over the whole domain: indices 1, 1.33,
/// 1.5, 2.4 in every combination, thicknesses 0 to 100 µm, the ends of the render range,
/// and angles 0 to exactly 90° plus each exact critical angle.
#[test]
fn no_nan_anywhere_in_the_domain() {
    let indices = [1.0f64, 1.33, 1.5, 2.4];
    let mut count = 0;
    for &n1 in &indices {
        for &n2 in &indices {
            for &n3 in &indices {
                let mut angles: Vec<f64> =
                    (0..=90).map(|a| FRAC_PI_2 * f64::from(a) / 90.0).collect();
                for n in [n2, n3] {
                    if n < n1 {
                        angles.push((n / n1).asin());
                    }
                }
                for d in [0.0, 1e-3, 1.0, 100.0, 1e3, 1e5] {
                    for lambda in [360.0, 550.0, 830.0] {
                        for &t in &angles {
                            let r = Film::new(n1, n2, n3, d).response(lambda, t);
                            for (rr, tt) in [
                                (r.reflectance_s, r.transmittance_s),
                                (r.reflectance_p, r.transmittance_p),
                            ] {
                                assert!(
                                    rr.is_finite()
                                        && tt.is_finite()
                                        && (-1e-12..=1.0 + 1e-12).contains(&rr)
                                        && (-1e-12..=1.0 + 1e-12).contains(&tt)
                                        && (rr + tt - 1.0).abs() <= 1e-10,
                                    "{n1}/{n2}/{n3}, d {d}, λ {lambda}, θ {t}: {r:?}"
                                );
                            }
                            count += 1;
                        }
                    }
                }
            }
        }
    }
    assert!(count > 100_000);
}
