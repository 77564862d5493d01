//! The seed's formula.

use super::*;

/// The seed's denominator has −2 r12 r23 cos φ where the Airy sum gives +2 r12 r23 cos φ
/// (|1 + r12 r23 e^{iφ}|² = 1 + r12² r23² + 2 r12 r23 cos φ). For the quarter-wave soap film
/// at normal incidence it gives 0.0836 instead of 0.0771 (so R + T = 1.0064 > 1), and near
/// grazing incidence it exceeds 1: 2.83 at 89°.
#[test]
fn seed_airy_denominator_has_the_wrong_sign() {
    let soap = Film::new(1.0, 1.33, 1.0, 550.0 / (4.0 * 1.33));
    let seed = seed_reflectance(&soap, 550.0, 0.0);
    let right = soap.response(550.0, 0.0);
    assert!((seed - 0.0836).abs() < 5e-5, "{seed}");
    assert!((right.reflectance() - 0.0771).abs() < 5e-5);
    assert!((seed + right.transmittance() - 1.0064).abs() < 5e-5);
    let grazing = seed_reflectance(&soap, 550.0, 89f64.to_radians());
    assert!((grazing - 2.83).abs() < 5e-3, "{grazing}");
    assert!(soap.reflectance(550.0, 89f64.to_radians()) <= 1.0);
    // With the sign corrected (and the seed's other choices kept: s only, real cosines)
    // the formula is the library's s reflectance wherever the cosines are real (short of
    // exactly grazing, where its real cosines give 0/0).
    let fixed = |f: &Film, l: f64, t: f64| {
        let (n1, n2, n3, d) = (f.n1, f.n2, f.n3, f.thickness_nm);
        let c1 = t.cos();
        let c2 = (1.0 - (n1 / n2 * t.sin()).powi(2)).sqrt();
        let c3 = (1.0 - (n1 / n3 * t.sin()).powi(2)).sqrt();
        let r12 = (n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2);
        let r23 = (n2 * c2 - n3 * c3) / (n2 * c2 + n3 * c3);
        let phi = 4.0 * PI * n2 * d * c2 / l;
        (r12 * r12 + r23 * r23 + 2.0 * r12 * r23 * phi.cos())
            / (1.0 + r12 * r12 * r23 * r23 + 2.0 * r12 * r23 * phi.cos())
    };
    for case in sweep(2_000, SWEEP_SEED) {
        let f = case.film;
        if f.n2 >= f.n1 && f.n3 >= f.n1 && case.theta1 < 1.5 {
            let want = f.response(case.wavelength_nm, case.theta1).reflectance_s;
            let got = fixed(&f, case.wavelength_nm, case.theta1);
            assert!((got - want).abs() <= 1e-12, "{got} vs {want} for {case:?}");
        }
    }
}

/// The seed's cosines are real, sqrt(1 − sin²θ): beyond a critical angle they are NaN, and
/// so is its reflectance. Glass (1.52) | MgF2 (1.38) | air beyond 41.1°: every angle NaN,
/// where the true reflectance is 1.
#[test]
fn seed_real_cosines_give_nan_beyond_the_critical_angle() {
    let film = Film::new(1.52, 1.38, 1.0, 100.0);
    for a in [42, 50, 60, 70, 80, 89] {
        let t = f64::from(a).to_radians();
        assert!(seed_reflectance(&film, 550.0, t).is_nan(), "{a}°");
        assert!((film.reflectance(550.0, t) - 1.0).abs() <= 1e-12);
    }
    let cases = sweep(2_000, SWEEP_SEED);
    let (worst, _) = worst_unpolarised(&cases, |c| {
        seed_reflectance(&c.film, c.wavelength_nm, c.theta1)
    });
    assert!(worst.is_infinite());
}

/// The seed uses the s-polarised coefficients for all light. Unpolarised light is the mean
/// of s and p, and they differ away from normal incidence: for the 300 nm soap film at
/// 550 nm and 60°, R_s = 0.0536 and R_p = 0.0017, so the seed's choice (even with its sign
/// fixed) reports 0.0536 where unpolarised light sees 0.0277, almost twice as much.
#[test]
fn seed_uses_s_polarisation_for_unpolarised_light() {
    let soap = Film::new(1.0, 1.33, 1.0, 300.0);
    let r = soap.response(550.0, 60f64.to_radians());
    assert!(
        (r.reflectance_s - 0.0536).abs() < 5e-5,
        "{}",
        r.reflectance_s
    );
    assert!(
        (r.reflectance_p - 0.0017).abs() < 5e-5,
        "{}",
        r.reflectance_p
    );
    assert!(
        (r.reflectance() - 0.0277).abs() < 5e-5,
        "{}",
        r.reflectance()
    );
    // At normal incidence s and p agree, so the seed's choice is harmless there.
    let r0 = soap.response(550.0, 0.0);
    assert!((r0.reflectance_s - r0.reflectance_p).abs() <= 1e-15);
}

/// Sanity of the building blocks' conventions (Born & Wolf): r_p = −r_s at normal
/// incidence; r_p = 0 at Brewster's angle; the evanescent cosine has Im > 0.
#[test]
fn building_block_conventions() {
    let one = Complex64::new(1.0, 0.0);
    let i = interface(1.0, one, 1.5, one);
    assert!((i.r_s + i.r_p).norm() <= 1e-15 && (i.r_s.re + 0.2).abs() <= 1e-15);
    let brewster = 1.5f64.atan();
    let c1 = Complex64::new(brewster.cos(), 0.0);
    let c2 = cos_theta(1.0, brewster.cos(), 1.5);
    assert!(interface(1.0, c1, 1.5, c2).r_p.norm() <= 1e-15);
    let ev = cos_theta(1.5, 0.6, 1.0); // n1 sin θ1 = 1.2 > 1
    assert!(ev.re == 0.0 && ev.im > 0.0);
}
