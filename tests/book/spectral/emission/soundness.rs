//! Every sample is sound; the hard values of u.

use super::*;

#[test]
fn every_sample_is_sound_with_a_constant_weight() {
    for (k, l) in lamps().iter().enumerate() {
        let s = sampler(&l.spectrum);
        for u in uniforms(130 + k as u64, 20_000) {
            if let Some(e) = unsound(&l.spectrum, &s, u) {
                panic!("{}: {e}", l.name);
            }
        }
    }
}

/// u = 0, u -> 1 (the largest double below 1, and 1 itself), and the CDF at every knot
/// with its neighbouring doubles: the plateaus of the zero segments.
#[test]
fn hard_u_values_give_sound_samples() {
    for l in lamps() {
        let s = sampler(&l.spectrum);
        // 0, the smallest positive (subnormal) and normal doubles, the largest below 1, 1.
        let mut us = vec![
            0.0,
            f64::from_bits(1),
            f64::MIN_POSITIVE,
            ONE_MINUS_EPSILON,
            1.0,
        ];
        for &k in l.spectrum.wavelengths() {
            let c = s.cdf(k);
            us.extend([c, c.next_down().max(0.0), c.next_up().min(1.0)]);
        }
        for u in us {
            if let Some(e) = unsound(&l.spectrum, &s, u) {
                panic!("{}: {e}", l.name);
            }
        }
    }
}

/// Low-pressure sodium: one 5 nm knot at 590 nm among zeros, so 78 of its 80 segments
/// have no mass. Every u lands in 585-595 nm; u = 0 just above 585, u -> 1 just below 595.
#[test]
fn low_pressure_sodium_spike() {
    let t = lamp("low-pressure").spectrum;
    let positive: Vec<f64> = t
        .wavelengths()
        .iter()
        .zip(t.values())
        .filter(|(_, v)| **v > 0.0)
        .map(|(k, _)| *k)
        .collect();
    assert_eq!(positive, vec![590.0], "the table is one knot at 590 nm");
    let s = sampler(&t);
    let first = s.sample(0.0);
    assert!(first.nm > 585.0 && first.nm - 585.0 < 1e-9, "{first:?}");
    for u in [ONE_MINUS_EPSILON, 1.0] {
        let last = s.sample(u);
        assert!(last.nm < 595.0 && 595.0 - last.nm < 1e-6, "{last:?}");
    }
    let half = s.sample(0.5);
    assert!(
        (half.nm - 590.0).abs() < 1e-12,
        "the median is 590: {half:?}"
    );
    assert!(
        (half.pdf - 0.2).abs() < 1e-12,
        "peak density 1/5 nm: {half:?}"
    );
    let xs = draw(&s, 140);
    assert!(xs.iter().all(|&x| x > 585.0 && x < 595.0));
}

#[test]
fn pdf_is_normalised_and_zero_outside() {
    for l in lamps() {
        let s = sampler(&l.spectrum);
        let k = l.spectrum.wavelengths();
        let (lo, hi) = (k[0], k[k.len() - 1]);
        // Midpoint rule on 0.01 nm cells: exact for the linear pieces away from knots.
        let cells = ((hi - lo) * 100.0) as usize;
        let integral: f64 = (0..cells)
            .map(|i| s.pdf(lo + (i as f64 + 0.5) * 0.01) * 0.01)
            .sum();
        assert!(
            (integral - 1.0).abs() <= 1e-9,
            "{}: ∫p = {integral}",
            l.name
        );
        for x in [lo.next_down(), hi, hi + 0.5, 831.0, -1.0, f64::NAN] {
            assert_eq!(s.pdf(x), 0.0, "{}: pdf({x})", l.name);
        }
        assert!(s.cdf(f64::NAN).is_nan());
        assert_eq!(s.cdf(lo - 1.0), 0.0);
        assert_eq!(s.cdf(hi + 1.0), 1.0);
        // The pdf is the table over its trapezoid integral (computed here).
        let a = areas(&l.spectrum);
        let total = a[a.len() - 1];
        for x in [lo + 0.3, 0.5 * (lo + hi) + 0.1, hi - 0.7] {
            let want = l.spectrum.eval(x) / total;
            assert!(
                (s.pdf(x) - want).abs() <= 1e-14 + 1e-12 * want,
                "{}: pdf({x}) = {} vs {want}",
                l.name,
                s.pdf(x)
            );
        }
    }
}

#[test]
fn an_all_zero_spectrum_is_refused() {
    let t = Table::new(vec![380.0, 500.0, 830.0], vec![0.0; 3]).unwrap();
    assert!(EmissionSampler::new(&t).is_err());
}

/// A NaN u is a broken generator: debug builds (the tests) stop on it.
#[cfg(debug_assertions)]
#[test]
#[should_panic(expected = "the generator is broken")]
fn nan_u_stops_debug_builds() {
    let _ = sampler(&lamp("amber").spectrum).sample(f64::NAN);
}
