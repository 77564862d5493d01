//! The amber LED model.

use super::*;

/// Ohno's shape `(g + 2 g^5) / 3` is half its peak where `g + 2 g^5 = 3/2`; with
/// `g = exp(-s^2)` the full width at half maximum is `2 Δ sqrt(-ln g)`. The root is found
/// here by bisection and compared with the width measured on the 1 nm table.
#[test]
fn amber_led_peak_and_width() {
    let (mut a, mut b) = (0.5f64, 1.0f64);
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        if m + 2.0 * m.powi(5) < 1.5 {
            a = m
        } else {
            b = m
        }
    }
    let fwhm = 2.0 * AMBER_WIDTH_NM * (-a.ln()).sqrt();
    assert!((fwhm - 16.6).abs() < 0.1, "FWHM {fwhm}");
    let t = amber_led_table();
    assert_eq!(t.eval(AMBER_PEAK_NM), 1.0);
    // Half-maximum crossings on either side, by linear interpolation in the table.
    let k = t.wavelengths();
    let cross = |from: usize| -> f64 {
        let i = (from..k.len() - 1)
            .find(|&i| (t.values()[i] - 0.5) * (t.values()[i + 1] - 0.5) <= 0.0)
            .unwrap();
        let (v0, v1) = (t.values()[i], t.values()[i + 1]);
        k[i] + (0.5 - v0) / (v1 - v0)
    };
    let left = cross(0);
    let right = cross(212);
    assert!(
        ((right - left) - fwhm).abs() < 0.05,
        "{left}..{right} vs {fwhm}"
    );
    assert!(t.eval(380.0) < 1e-50 && t.eval(830.0) < 1e-50);
}
