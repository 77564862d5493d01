//! Planck's law.

use super::*;

/// The maximiser of `f` on [lo, hi] by golden-section search (unimodal `f`).
fn argmax(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let (a, b) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if f(a) < f(b) {
            lo = a;
        } else {
            hi = b;
        }
    }
    0.5 * (lo + hi)
}

/// Planck with λ⁴ instead of λ⁵ (a planted bug).
fn planck_without_lambda5(nm: f64, kelvin: f64) -> f64 {
    planck(nm, kelvin) * nm * 1e-9
}

#[test]
fn planck_peaks_at_wien() {
    for t in [1000.0, 2856.0, 5778.0, 10000.0] {
        let peak = argmax(|nm| planck(nm, t), 50.0, 5000.0);
        // CODATA 2018 Wien constant b = 2.897771955e-3 m K.
        let wien = 2.897_771_955e-3 / t * 1e9;
        assert!(
            (peak / wien - 1.0).abs() <= 1e-7,
            "T = {t}: peak at {peak} nm vs b/T = {wien} nm"
        );
        let wrong = argmax(|nm| planck_without_lambda5(nm, t), 50.0, 5000.0);
        assert!(
            (wrong / wien - 1.0).abs() > 0.1,
            "T = {t}: the λ⁴ Planck peaks at {wrong} nm, too close to Wien"
        );
    }
}

/// π ∫ B dλ over all wavelengths, by Simpson's rule in ln λ from 10 nm to 10⁸ nm (the
/// tails beyond carry less than 1e-12 of the power at these temperatures).
fn exitance(b: impl Fn(f64) -> f64) -> f64 {
    let (a, z, n) = (10f64.ln(), 1e8f64.ln(), 20_000);
    let h = (z - a) / f64::from(n);
    let f = |u: f64| {
        let nm = u.exp();
        b(nm) * nm
    };
    let mut s = f(a) + f(z);
    for i in 1..n {
        s += f(a + h * f64::from(i)) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    std::f64::consts::PI * s * h / 3.0
}

#[test]
fn planck_integrates_to_stefan_boltzmann() {
    for t in [1000.0, 2856.0, 5778.0, 10000.0] {
        let m = exitance(|nm| planck(nm, t));
        let sigma_t4 = STEFAN_BOLTZMANN * t.powi(4);
        assert!(
            (m / sigma_t4 - 1.0).abs() <= 1e-8,
            "T = {t}: π∫B = {m} vs σT⁴ = {sigma_t4}"
        );
        let wrong = exitance(|nm| planck_without_lambda5(nm, t));
        assert!(
            (wrong / sigma_t4 - 1.0).abs() > 0.1,
            "T = {t}: the λ⁴ Planck passes Stefan-Boltzmann"
        );
    }
}

/// CIE 015:2018 defines illuminant A by a formula with the old second radiation constant
/// c₂ = 1.435e7 nm K and T = 2848 K: S_A(λ) = 100 (560/λ)⁵ (e^{c₂/(2848·560)} − 1) /
/// (e^{c₂/(2848 λ)} − 1). With today's c₂ = hc/k the same curve is a Planckian at
/// T = 2848 · (hc/k) / 1.435e7 = 2855.50 K: the "2856 K" of the standard.
fn illuminant_a_formula(nm: f64) -> f64 {
    let c2: f64 = 1.435e7;
    100.0 * (560.0 / nm).powi(5) * (c2 / (2848.0 * 560.0)).exp_m1() / (c2 / (2848.0 * nm)).exp_m1()
}

#[test]
fn illuminant_a_is_a_2856_k_planckian() {
    let t_a = 2848.0 * (PLANCK_H * LIGHT_C / BOLTZMANN_K * 1e9) / 1.435e7;
    // 2855.50 K: the standard's "approximately 2856 K".
    assert!((t_a - 2856.0).abs() <= 1.0, "A's temperature {t_a} K");
    let scale = illuminant_a_formula(560.0) / planck(560.0, t_a);
    for k in 0..=106 {
        let nm = 300.0 + 5.0 * f64::from(k);
        let r = planck(nm, t_a) * scale / illuminant_a_formula(nm);
        assert!((r - 1.0).abs() <= 1e-12, "{nm} nm: Planck / A = {r}");
    }
    // The data file is the formula printed to six significant digits: each value within half
    // a unit of its sixth significant digit.
    let a = builtin("cie_illuminant_A.csv");
    for (&nm, &v) in a.wavelengths().iter().zip(a.values()) {
        let half_unit = 0.5 * 10f64.powi(v.log10().floor() as i32 - 5);
        let d = (v - illuminant_a_formula(nm)).abs();
        assert!(
            d <= half_unit,
            "{nm} nm: file {v} vs formula {}, {:.3} of half a unit of the sixth digit",
            illuminant_a_formula(nm),
            d / half_unit
        );
    }
    // The Planckian's chromaticity is A's published one.
    let p = xy(|nm| planck(nm, 2856.0));
    let err = (p - DVec2::new(0.44758, 0.40745)).max_abs();
    assert!(err <= 1e-4, "2856 K at {p}");
    // Planted bug: the λ⁴ Planck is not A's shape (the ratio to the formula drifts with λ)
    // and misses A's published chromaticity.
    let wrong_scale = illuminant_a_formula(560.0) / planck_without_lambda5(560.0, t_a);
    let r = planck_without_lambda5(400.0, t_a) * wrong_scale / illuminant_a_formula(400.0);
    assert!((r - 1.0).abs() > 0.1, "the λ⁴ Planck has A's shape: {r}");
    let wrong = xy(|nm| planck_without_lambda5(nm, 2856.0));
    let err = (wrong - DVec2::new(0.44758, 0.40745)).max_abs();
    assert!(err > 4e-3, "the λ⁴ Planck lands on A: {wrong}");
}

#[test]
fn planckian_locus_matches_krystek() {
    // D65's correlated colour temperature is 6504 K; 2000-10000 K covers the lamps of the
    // scenes. Krystek's fit was made with older CMF data and constants; its distance to
    // the exact locus is below 4e-4 in xy over this range (`figures/colour_planck.md`).
    for t in [2000.0, 2856.0, 4000.0, 5000.0, 6504.0, 8000.0, 10000.0] {
        let p = xy(|nm| planck(nm, t));
        let err = (p - krystek(t)).max_abs();
        assert!(err <= 4e-4, "{t} K: {p} vs Krystek {}", krystek(t));
        let wrong = xy(|nm| planck_without_lambda5(nm, t));
        assert!(
            (wrong - krystek(t)).max_abs() > 4e-3,
            "{t} K: the λ⁴ Planck lands on the locus"
        );
    }
}

#[test]
fn planck_hard_cases() {
    for (nm, t) in [
        (f64::NAN, 3000.0),
        (500.0, f64::NAN),
        (0.0, 3000.0),
        (-5.0, 3000.0),
        (500.0, 0.0),
        (500.0, -1.0),
    ] {
        assert!(
            planck(nm, t) == 0.0,
            "planck({nm}, {t}) = {}",
            planck(nm, t)
        );
        assert!(
            planck_normalised(nm, t) == 0.0,
            "planck_normalised({nm}, {t})"
        );
    }
    // Far into the blue at a low temperature the exponential overflows: zero, not NaN.
    assert!(planck(1.0, 300.0) == 0.0);
    // Far into the red the exponent is tiny and exp_m1 keeps it accurate: Rayleigh-Jeans,
    // B ≈ 2 c k T / λ⁴, to 1e-6 at hc/(λkT) ≈ 1.4e-6.
    let (nm, t): (f64, f64) = (1e10, 1000.0);
    let l = nm * 1e-9;
    let rj = 2.0 * LIGHT_C * BOLTZMANN_K * t / l.powi(4) * 1e-9;
    assert!((planck(nm, t) / rj - 1.0).abs() <= 1e-5);
    let bb = Spectrum::Blackbody {
        kelvin: 5000.0,
        peak: 2.0,
    };
    let peak = WIEN_B / 5000.0 * 1e9;
    assert!((bb.eval(peak) - 2.0).abs() <= 1e-12);
}
