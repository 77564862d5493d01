//! Planted bugs: each must disagree with the transfer matrix.

use super::*;

#[test]
fn rejects_a_missing_factor_2_in_the_phase() {
    // e^{iδ} for the round trip instead of e^{2iδ}.
    let cases = sweep(2_000, SWEEP_SEED);
    let (worst, _) = worst_unpolarised(&cases, |c| {
        assembled(c, |n, d, c2, l| 0.5 * phase(n, d, c2, l), false)
    });
    assert!(worst > 0.05, "{worst}");
}

#[test]
fn rejects_the_wrong_sign_of_r12_for_p() {
    // Mixing the two sign conventions of r_p between the two interfaces.
    let cases = sweep(2_000, SWEEP_SEED);
    let (worst, _) = worst_unpolarised(&cases, |c| assembled(c, phase, true));
    assert!(worst > 0.05, "{worst}");
}

#[test]
fn rejects_a_missing_cos_theta2_in_the_phase() {
    // δ = 2π n2 d / λ: right at normal incidence only.
    let cases = sweep(2_000, SWEEP_SEED);
    let (worst, _) = worst_unpolarised(&cases, |c| {
        assembled(
            c,
            |n, d, _c2, l| phase(n, d, Complex64::new(1.0, 0.0), l),
            false,
        )
    });
    assert!(worst > 0.05, "{worst}");
    // ...and at normal incidence it is right, which is why it survives casual testing.
    let normal: Vec<Case> = cases.iter().map(|c| Case { theta1: 0.0, ..*c }).collect();
    let (worst, _) = worst_unpolarised(&normal, |c| {
        assembled(
            c,
            |n, d, _c2, l| phase(n, d, Complex64::new(1.0, 0.0), l),
            false,
        )
    });
    assert!(worst <= 1e-12, "{worst}");
}

#[test]
fn rejects_the_wrong_branch_of_the_evanescent_cosine() {
    // cos θ = −i sqrt(sin²θ − 1) in Born & Wolf's convention: a growing wave. A thick
    // evanescent film then overflows e^{2iδ} to infinity and the sum to NaN.
    let cases = sweep(2_000, SWEEP_SEED);
    let wrong_branch = |n1: f64, cos1: f64, n: f64| cos_theta(n1, cos1, n).conj();
    let (worst, _) = worst_unpolarised(&cases, |c| {
        let Film { n1, n2, n3, .. } = c.film;
        let cos1 = c.theta1.cos();
        let c1 = Complex64::new(cos1, 0.0);
        let (c2, c3) = (wrong_branch(n1, cos1, n2), wrong_branch(n1, cos1, n3));
        let (i12, i23) = (interface(n1, c1, n2, c2), interface(n2, c2, n3, c3));
        let delta = phase(n2, c.film.thickness_nm, c2, c.wavelength_nm);
        0.5 * (airy_r(i12.r_s, i23.r_s, delta).norm_sqr()
            + airy_r(i12.r_p, i23.r_p, delta).norm_sqr())
    });
    assert!(worst > 0.05, "{worst}");
}
