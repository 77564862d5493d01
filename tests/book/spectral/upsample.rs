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

/// Why the refusal of components above 1 is a choice, not physics: under D65 the colours of
/// reflectances in [0, 1] do not fill the unit cube. The reflectance that is 1 wherever the red
/// of linear sRGB gains from light (`(M⁻¹ (x̄, ȳ, z̄))_R > 0`) and 0 elsewhere has a red of about
/// 1.48, with green and blue inside [0, 1]: a real reflectance, in gamut, with R > 1.
#[test]
fn a_real_reflectance_can_have_red_above_one() {
    let red_weight = |nm: f64| cie::xyz_to_linear_srgb(cie::cmf(nm)).x;
    let rgb = srgb_under_d65(|nm| if red_weight(nm) > 0.0 { 1.0 } else { 0.0 });
    eprintln!("the red-optimal reflectance under D65: {rgb}");
    assert!(rgb.x > 1.4, "{rgb}");
    assert!(
        rgb.y >= 0.0 && rgb.y <= 1.0 && rgb.z >= 0.0 && rgb.z <= 1.0,
        "{rgb}"
    );
    // And the fitter refuses it, as the chapter says.
    assert!(upsample(rgb).is_err());
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
    // The limits themselves, where x / hypot(x, 1) would be ∞ / ∞ = NaN.
    assert_eq!(sigmoid(f64::INFINITY), 1.0);
    assert_eq!(sigmoid(f64::NEG_INFINITY), 0.0);
    assert_eq!(sigmoid_derivative(f64::INFINITY), 0.0);
    // In floating point S reaches 1 and 0: the smallest x (by bisection) with S(x) = 1 and
    // S(−x) = 0 lie between 10⁷ and 10⁸ (the chapter says "about 10⁸").
    let first = |f: &dyn Fn(f64) -> bool| {
        let (mut lo, mut hi) = (1.0_f64, 1e12_f64);
        for _ in 0..200 {
            let mid = (lo * hi).sqrt();
            if f(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        hi
    };
    let (one, zero) = (
        first(&|x| sigmoid(x) == 1.0),
        first(&|x| sigmoid(-x) == 0.0),
    );
    eprintln!("S(x) = 1 from x = {one:.3e}; S(-x) = 0 from x = {zero:.3e}");
    assert!(
        (1e7..=1e8).contains(&one) && (1e7..=1e8).contains(&zero),
        "{one}, {zero}"
    );
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
    // Tens of ΔE, not a marginal miss (the chapter's "tens of ΔE away").
    assert!(de >= 10.0, "the logistic sigmoid passed: ΔE {de} at {at}");
}

#[test]
fn planted_fit_under_illuminant_e_is_rejected() {
    // Fitted under the equal-energy illuminant E, seen under D65: not the colour asked for.
    let (_, de, at) = round_trip(&Fitter::new(|_| 1.0), &grid(), Reflectance::eval);
    assert!(de >= 10.0, "fitting under E passed: ΔE {de} at {at}");
}

// ---------------------------------------------------------------------------------------
// Exercises (ignored until the student fills in the scaffolds; each test fails on the stub).

/// Exercise 1 of *From RGB to spectrum*: a checker of a sigmoid `s` and its derivative `ds`.
/// On a grid of `x` that includes ±10³⁰⁰ and ±∞ it must report (as `Err`, with the reason)
/// a NaN, a value outside `[0, 1]`, a derivative outside `[0, 1/2]`, a broken symmetry
/// `s(−x) ≠ 1 − s(x)` (beyond 2⁻⁵² absolute), and limits other than `s(±∞) = 1, 0` and
/// `s(±10³⁰⁰) = 1, 0`.
fn your_sigmoid_check(s: &dyn Fn(f64) -> f64, ds: &dyn Fn(f64) -> f64) -> Result<(), String> {
    let _ = (s, ds);
    unimplemented!("exercise 1 of From RGB to spectrum: a checker of the sigmoid")
}

/// Checks exercise 1: your checker accepts the crate's `sigmoid` and rejects four planted
/// ones: the old `x / hypot(x, 1)` that is NaN at ±∞, `√(1 + x²)` without `hypot` (it
/// overflows, so `S(10³⁰⁰) = 1/2`), a sigmoid shifted up by 10⁻³ (above 1), and a derivative
/// twice too large (1 at 0).
#[test]
#[ignore = "exercise 1 of From RGB to spectrum: fill in your_sigmoid_check, then run it"]
fn exercise_1_the_sigmoids_limits() {
    assert_eq!(your_sigmoid_check(&sigmoid, &sigmoid_derivative), Ok(()));
    let nan_at_infinity = |x: f64| 0.5 + 0.5 * x / x.hypot(1.0);
    let no_hypot = |x: f64| 0.5 + 0.5 * x / (1.0 + x * x).sqrt();
    let shifted = |x: f64| sigmoid(x) + 1e-3;
    let twice = |x: f64| 2.0 * sigmoid_derivative(x);
    for (name, s, ds) in [
        (
            "NaN at ±∞",
            &nan_at_infinity as &dyn Fn(f64) -> f64,
            &sigmoid_derivative as &dyn Fn(f64) -> f64,
        ),
        ("no hypot", &no_hypot, &sigmoid_derivative),
        ("shifted up", &shifted, &sigmoid_derivative),
        ("derivative doubled", &sigmoid, &twice),
    ] {
        let v = your_sigmoid_check(s, ds);
        eprintln!("planted {name}: {v:?}");
        assert!(v.is_err(), "the planted sigmoid '{name}' passed");
    }
}

/// Exercise 2's answers: under illuminant A (`Fitter::new` with A's table), fitting the
/// XYZ of each sRGB colour of the 11³ grid (what `Fitter::fit` targets), the number of grid
/// colours whose round trip under A misses by more than ΔE = 1, and the colour that misses most.
const YOUR_COUNT_ABOVE_1_UNDER_A: Option<usize> = None;
const YOUR_WORST_UNDER_A: Option<DVec3> = None;

/// Checks exercise 2: the round trip under A computed here by `cie::xyz` of `r · A` (over the
/// Y of A), against the XYZ of the sRGB colour, in CIELAB with sRGB's white.
#[test]
#[ignore = "exercise 2 of From RGB to spectrum: fill in the two answers, then run it"]
fn exercise_2_another_illuminant() {
    let a = raylemma::spectral::spectrum::builtin("cie_illuminant_A.csv");
    let fitter = Fitter::new(|nm| a.eval(nm));
    let norm = cie::xyz(|nm| a.eval(nm)).y;
    let white = cie::linear_srgb_to_xyz(DVec3::ONE);
    let lab = |xyz: DVec3| raylemma::spectral::display::lab(xyz, white);
    let (mut count, mut worst, mut at) = (0, 0.0_f64, DVec3::ZERO);
    for c in grid() {
        let fit = fitter.fit(c).unwrap();
        let xyz = cie::xyz(|nm| fit.reflectance.eval(nm) * a.eval(nm)) / norm;
        let e = (lab(xyz) - lab(cie::linear_srgb_to_xyz(c))).length();
        if e > 1.0 {
            count += 1;
        }
        if e > worst {
            (worst, at) = (e, c);
        }
    }
    eprintln!("{count} colours above ΔE 1; worst ΔE {worst:.2} at {at}");
    assert_eq!(YOUR_COUNT_ABOVE_1_UNDER_A, Some(count));
    let yours = YOUR_WORST_UNDER_A.expect("fill in YOUR_WORST_UNDER_A");
    assert!((yours - at).abs().max_element() <= 1e-9, "{yours} vs {at}");
}

/// Exercise 3 of *From RGB to spectrum*: a table of fitted coefficients on the `n³` grid of
/// RGB `i / (n − 1)`, interpolated trilinearly; returns the reflectance of any colour of the
/// unit cube. (Black and white are constants, not sigmoids: decide what the table holds there.)
fn your_coefficient_table(n: usize) -> Box<dyn Fn(DVec3) -> Reflectance> {
    let _ = n;
    unimplemented!("exercise 3 of From RGB to spectrum: a 16³ table of coefficients")
}

/// Exercise 3's answer: the largest round-trip ΔE of your 16³ table at the centres of its
/// cells.
const YOUR_CELL_CENTRE_DELTA_E: Option<f64> = None;

/// Checks exercise 3 with your table at n = 16: at the grid's nodes (but black and white) it
/// reproduces the fits (ΔE ≤ 0.02); the largest ΔE over the 15³ cell centres, measured here by
/// `srgb_under_d65`, agrees with your answer to 10 %; and a lookup is at least 10 times faster
/// than `Fitter::fit` (timed here on the same colours).
#[test]
#[ignore = "exercise 3 of From RGB to spectrum: fill in your_coefficient_table and YOUR_CELL_CENTRE_DELTA_E, then run it"]
fn exercise_3_a_table_instead_of_a_fit() {
    let n = 16;
    let table = your_coefficient_table(n);
    let node = |i: usize| i as f64 / (n - 1) as f64;
    for (i, j, k) in [
        (1, 2, 3),
        (15, 0, 0),
        (0, 15, 0),
        (0, 0, 15),
        (7, 7, 7),
        (15, 15, 3),
    ] {
        let c = DVec3::new(node(i), node(j), node(k));
        let back = srgb_under_d65(|nm| table(c).eval(nm));
        assert!(
            delta_e(back, c) <= 0.02,
            "node {c}: ΔE {}",
            delta_e(back, c)
        );
    }
    let mut centres = Vec::new();
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            for k in 0..n - 1 {
                let h = 0.5 / (n - 1) as f64;
                centres.push(DVec3::new(node(i) + h, node(j) + h, node(k) + h));
            }
        }
    }
    let worst = centres
        .iter()
        .map(|&c| delta_e(srgb_under_d65(|nm| table(c).eval(nm)), c))
        .fold(0.0_f64, nan_max);
    eprintln!("largest ΔE at the cell centres: {worst:.3}");
    let answer = YOUR_CELL_CENTRE_DELTA_E.expect("fill in YOUR_CELL_CENTRE_DELTA_E");
    assert!((answer / worst - 1.0).abs() <= 0.1, "{answer} vs {worst}");
    let sample = &centres[..500];
    let t0 = std::time::Instant::now();
    let looked_up: f64 = sample.iter().map(|&c| table(c).eval(555.0)).sum();
    let lookup = t0.elapsed();
    let t0 = std::time::Instant::now();
    let fitted: f64 = sample
        .iter()
        .map(|&c| Fitter::d65().fit(c).unwrap().reflectance.eval(555.0))
        .sum();
    let fit = t0.elapsed();
    eprintln!("500 lookups {lookup:?}, 500 fits {fit:?} ({looked_up:.3}, {fitted:.3})");
    assert!(lookup * 10 < fit, "lookup {lookup:?} vs fit {fit:?}");
}
