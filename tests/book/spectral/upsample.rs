//! Tests of the chapter *From RGB to spectrum* (`src/spectral/upsample.rs`).
//! Deterministic (no statistical tests). The round trip is checked with an independent
//! quadrature (`cie::xyz`, 4-point Gauss-Legendre per nm, on the D65 table directly) rather
//! than the fitter's own trapezoid sums; each planted bug must be rejected by the check its
//! twin passes.

use glam::DVec3;
use raylemma::rng;
use raylemma::spectral::display::delta_e;
use raylemma::spectral::spectrum::Spectrum;
use raylemma::spectral::upsample::*;
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN, cie};

/// The 11³ = 1331 colours with components 0, 0.1, ..., 1.
fn grid() -> Vec<DVec3> {
    let mut v = Vec::new();
    for r in 0..=10 {
        for g in 0..=10 {
            for b in 0..=10 {
                v.push(DVec3::new(f64::from(r), f64::from(g), f64::from(b)) / 10.0);
            }
        }
    }
    v
}

/// The larger of `a` and `b`, NaN if either is NaN (`f64::max` and glam's `max_element`
/// drop a NaN, which would let `err <= tol` pass on one).
fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// The worst round-trip errors over `colours`: (linear sRGB max-abs, ΔE, colour of worst ΔE),
/// with `eval` turning a fit into a spectrum. A NaN anywhere makes the errors NaN, which
/// fails every `<=` below.
fn round_trip(
    fitter: &Fitter,
    colours: &[DVec3],
    eval: fn(&Reflectance, f64) -> f64,
) -> (f64, f64, DVec3) {
    let (mut lin, mut de, mut at) = (0.0f64, 0.0f64, DVec3::ZERO);
    for &c in colours {
        let fit = fitter.fit(c).unwrap();
        let back = srgb_under_d65(|nm| eval(&fit.reflectance, nm));
        let d = (back - c).abs();
        lin = nan_max(lin, nan_max(d.x, nan_max(d.y, d.z)));
        let e = delta_e(back, c);
        if e.is_nan() || e > de {
            (de, at) = (nan_max(de, e), c);
        }
    }
    (lin, de, at)
}

#[test]
fn round_trip_over_the_grid_under_d65() {
    let (lin, de, at) = round_trip(Fitter::d65(), &grid(), Reflectance::eval);
    assert!(lin <= 1e-3, "linear sRGB error {lin:e}");
    assert!(de <= 0.02, "ΔE {de} at {at}");
}

#[test]
fn round_trip_of_random_and_extreme_colours() {
    let mut r = rng::seeded(0x5EC7);
    let mut colours: Vec<DVec3> = (0..300)
        .map(|_| {
            DVec3::new(
                rng::uniform(&mut r, 0.0, 1.0),
                rng::uniform(&mut r, 0.0, 1.0),
                rng::uniform(&mut r, 0.0, 1.0),
            )
        })
        .collect();
    // Near black, near white, single primaries at the gamut corners and faint ones.
    colours.extend([
        DVec3::new(1e-4, 0.0, 0.0),
        DVec3::new(0.0, 0.0, 1e-3),
        DVec3::new(0.999, 1.0, 1.0),
        DVec3::new(1.0, 1.0, 0.999),
        DVec3::new(0.01, 0.0, 0.01),
    ]);
    let (lin, de, at) = round_trip(Fitter::d65(), &colours, Reflectance::eval);
    assert!(lin <= 1e-3, "linear sRGB error {lin:e}");
    assert!(de <= 0.02, "ΔE {de} at {at}");
}

#[test]
fn black_and_white_are_constant() {
    assert_eq!(
        upsample(DVec3::ZERO).unwrap().reflectance,
        Reflectance::Constant(0.0)
    );
    assert_eq!(
        upsample(DVec3::ONE).unwrap().reflectance,
        Reflectance::Constant(1.0)
    );
    // White's round trip is limited by D65 itself: the CIE table's chromaticity
    // (0.31273, 0.32902) vs the (0.3127, 0.3290) sRGB rounds to.
    let white = srgb_under_d65(|_| 1.0);
    let d = (white - DVec3::ONE).abs();
    let err = nan_max(d.x, nan_max(d.y, d.z));
    assert!(err <= 5e-4, "white comes back as {white}");
    assert!(delta_e(white, DVec3::ONE) <= 0.05);
}

#[test]
fn greys_are_flat() {
    for g in 1..10 {
        let g = f64::from(g) / 10.0;
        let fit = upsample(DVec3::splat(g)).unwrap();
        let values: Vec<f64> = (360..=830)
            .map(|nm| fit.reflectance.eval(f64::from(nm)))
            .collect();
        assert!(values.iter().all(|v| !v.is_nan()), "grey {g}: NaN");
        let (lo, hi) = values
            .iter()
            .fold((1.0f64, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
        assert!(hi - lo <= 2e-3, "grey {g}: from {lo} to {hi}");
        assert!(
            (0.5 * (lo + hi) - g).abs() <= 2e-3,
            "grey {g}: level {lo}..{hi}"
        );
    }
}

#[test]
fn reflectances_stay_in_the_unit_interval_and_are_smooth() {
    for c in grid() {
        let fit = upsample(c).unwrap();
        // 0.1 nm steps, and beyond the visible range.
        let values: Vec<f64> = (2000..=10_000)
            .map(|i| fit.reflectance.eval(f64::from(i) / 10.0))
            .collect();
        assert!(
            values.iter().all(|v| (0.0..=1.0).contains(v)),
            "{c}: a value outside [0, 1]"
        );
        // A sigmoid of a quadratic has at most one interior extremum: the slope changes
        // sign at most once.
        let signs: Vec<bool> = values
            .windows(2)
            .filter(|w| (w[1] - w[0]).abs() > 1e-15)
            .map(|w| w[1] > w[0])
            .collect();
        let changes = signs.windows(2).filter(|s| s[0] != s[1]).count();
        assert!(changes <= 1, "{c}: {changes} changes of slope");
    }
}

#[test]
fn colours_outside_the_unit_cube_are_refused() {
    for (c, name) in [
        (DVec3::new(1.2, 0.5, 0.5), "red = 1.2"),
        (DVec3::new(0.5, -0.1, 0.5), "green = -0.1"),
        (DVec3::new(0.5, 0.5, f64::NAN), "blue = NaN"),
        (DVec3::new(0.5, f64::INFINITY, 0.5), "green = inf"),
    ] {
        let e = upsample(c).unwrap_err().to_string();
        assert!(e.contains(name) && e.contains("[0, 1]"), "{e}");
    }
}

#[test]
fn the_spectrum_table_matches_the_model() {
    let fit = upsample(DVec3::new(0.7, 0.2, 0.1)).unwrap();
    let Spectrum::Table(t) = fit.reflectance.to_spectrum() else {
        panic!("a sigmoid gives a table");
    };
    assert_eq!(t.wavelengths().len(), cie::CMF_ROWS);
    for nm in [LAMBDA_MIN, 400.0, 555.0, 700.0, LAMBDA_MAX] {
        assert!((t.eval(nm) - fit.reflectance.eval(nm)).abs() <= 1e-15);
    }
    let back = srgb_under_d65(|nm| t.eval(nm));
    assert!(delta_e(back, DVec3::new(0.7, 0.2, 0.1)) <= 0.02);
    assert_eq!(
        upsample(DVec3::ZERO).unwrap().reflectance.to_spectrum(),
        Spectrum::Constant(0.0)
    );
}

#[test]
fn the_sigmoid_is_the_papers() {
    // S(0) = 1/2, S(±1) = 1/2 ± 1/(2√2), limits 0 and 1, and S'(x) by finite differences.
    assert_eq!(sigmoid(0.0), 0.5);
    assert!((sigmoid(1.0) - (0.5 + 0.5 / 2f64.sqrt())).abs() <= 1e-15);
    assert!((sigmoid(-1.0) - (0.5 - 0.5 / 2f64.sqrt())).abs() <= 1e-15);
    assert_eq!(sigmoid(1e300), 1.0);
    assert_eq!(sigmoid(-1e300), 0.0);
    for x in [-30.0, -2.0, -0.3, 0.0, 0.7, 5.0] {
        let h = 1e-6;
        let fd = (sigmoid(x + h) - sigmoid(x - h)) / (2.0 * h);
        assert!((fd - sigmoid_derivative(x)).abs() <= 1e-8, "S'({x})");
    }
}

/// Planted bug: the coefficients evaluated with the logistic sigmoid 1 / (1 + e^−x).
fn logistic_eval(r: &Reflectance, nm: f64) -> f64 {
    match *r {
        Reflectance::Constant(v) => v,
        Reflectance::Sigmoid(c) => {
            let t = unit_wavelength(nm);
            1.0 / (1.0 + (-((c[0] * t + c[1]) * t + c[2])).exp())
        }
    }
}

#[test]
fn planted_wrong_sigmoid_is_rejected() {
    let (_, de, at) = round_trip(Fitter::d65(), &grid(), logistic_eval);
    assert!(de >= 1.0, "the logistic sigmoid passed: ΔE {de} at {at}");
}

#[test]
fn planted_fit_under_illuminant_e_is_rejected() {
    // Fitted under the equal-energy illuminant E, seen under D65: not the colour asked for.
    let (_, de, at) = round_trip(&Fitter::new(|_| 1.0), &grid(), Reflectance::eval);
    assert!(de >= 1.0, "fitting under E passed: ΔE {de} at {at}");
}
