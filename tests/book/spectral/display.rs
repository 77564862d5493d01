//! Tests of the chapter *From spectrum to display* (`src/spectral/display.rs`).
//! Deterministic (no statistical tests). Expected values come from the published sRGB
//! anchors, closed forms derived by hand, or a different computation; every planted bug is
//! the twin of a passing check and must be rejected by it.

use glam::DVec3;
use raylemma::image::png::write_png;
use raylemma::spectral::cie;
use raylemma::spectral::display::*;

// ---------------------------------------------------------------------------------------
// Checks of an encoder (linear → encoded), shared by the real curve and the planted bugs.

/// The largest jump of `f` across `at`: `|f(at + h) − f(at − h)|` for a tiny `h`.
fn jump(f: fn(f64) -> f64, at: f64) -> f64 {
    let h = at * 1e-9;
    (f(at + h) - f(at - h)).abs()
}

/// Continuity everywhere on a fine grid: no step between neighbours larger than the
/// steepest part of the curve allows (the slope near 0 is 12.92, so 1e-6 apart gives at
/// most 1.3e-5; the power segment is flatter).
fn check_continuous(f: fn(f64) -> f64) -> Result<(), String> {
    let n = 1_000_000;
    for i in 0..n {
        let (a, b) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
        let step = (f(b) - f(a)).abs();
        if step > 13.0 * (b - a) + 1e-12 {
            return Err(format!("step {step:e} between {a} and {b}"));
        }
    }
    Ok(())
}

/// Published 8-bit sRGB anchors: linear 0.5 → 188 (#BCBCBC), linear 0.18 (18 % grey card)
/// → 46.1 % = 118, 0 → 0, 1 → 255.
fn check_anchors(f: fn(f64) -> f64) -> Result<(), String> {
    for (x, code) in [(0.5, 188u8), (0.18, 118), (0.0, 0), (1.0, 255)] {
        let got = quantise(f(x));
        if got != code {
            return Err(format!("linear {x} gives code {got}, published {code}"));
        }
    }
    Ok(())
}

/// Planted bug: the source's exponent the wrong way round (x^2.2 instead of x^(1/2.2)).
fn planted_gamma_inverted(x: f64) -> f64 {
    gamma_decode(x, 2.2)
}

/// Planted bug: the decoding breakpoint 0.04045 used on the linear side (the checker's).
fn planted_breakpoint_wrong_side(x: f64) -> f64 {
    raylemma::check::display::planted::encode_with_the_encoded_breakpoint(x)
}

fn gamma22(x: f64) -> f64 {
    gamma_encode(x, 2.2)
}

#[test]
fn srgb_curve_is_continuous_and_nearly_smooth_at_the_breakpoint() {
    // Value: the two pieces meet to 3e-8 (the standard rounds 0.0031308 and 0.04045).
    let b = SRGB_LINEAR_BREAK;
    let gap = (12.92 * b - (1.055 * b.powf(1.0 / 2.4) - 0.055)).abs();
    assert!(gap <= 1e-7, "gap {gap:e} at the breakpoint");
    assert!(
        jump(srgb_encode, b) <= 1e-7,
        "jump {:e}",
        jump(srgb_encode, b)
    );
    // Slope: 12.92 below; 1.055/2.4 b^(1/2.4 − 1) ≈ 12.70 above: equal within 2 %, not exactly.
    let h = 1e-9;
    let below = (srgb_encode(b) - srgb_encode(b - h)) / h;
    let above = (srgb_encode(b + 2.0 * h) - srgb_encode(b + h)) / h;
    let ratio = above / below;
    assert!(
        (0.98..=0.99).contains(&ratio),
        "slope ratio {ratio} (below {below}, above {above})"
    );
    check_continuous(srgb_encode).unwrap();
    check_continuous(srgb_decode).unwrap_or_else(|e| panic!("decode: {e}"));
}

#[test]
fn planted_breakpoint_on_the_wrong_side_is_rejected() {
    let j = jump(planted_breakpoint_wrong_side, SRGB_ENCODED_BREAK);
    assert!(
        j >= 0.1,
        "the planted curve should jump at 0.04045, jumped {j:e}"
    );
    assert!(check_continuous(planted_breakpoint_wrong_side).is_err());
}

#[test]
fn published_anchor_values() {
    check_anchors(srgb_encode).unwrap();
    // Decoding: code 128 is 21.6 % of the light (the "#808080 is not half grey" value).
    let mid = srgb_decode(128.0 / 255.0);
    assert!((mid - 0.2158605).abs() <= 1e-6, "code 128 decodes to {mid}");
    // 18 % grey encodes to 0.4614 (before rounding).
    let v = srgb_encode(0.18);
    assert!((v - 0.46135).abs() <= 1e-4, "0.18 encodes to {v}");
    // The source's curve: 0.5^(1/2.2) = 0.7297 → 186, two codes darker than sRGB.
    assert_eq!(gamma8(0.5, 2.2), 186);
}

#[test]
fn planted_gamma_applied_the_wrong_way_is_rejected() {
    let e = check_anchors(planted_gamma_inverted).unwrap_err();
    assert!(e.contains("0.5 gives code 55"), "{e}");
    // The source's own curve fails the sRGB anchors too, but only by 2 codes at 0.5.
    assert!(check_anchors(gamma22).is_err());
}

#[test]
fn encode_and_decode_are_inverse() {
    for i in 0..=100_000 {
        let x = i as f64 / 100_000.0;
        for y in [x, x * x * x * 0.01] {
            let back = srgb_decode(srgb_encode(y));
            assert!((back - y).abs() <= 1e-14 + 1e-12 * y, "{y} -> {back}");
            let g = gamma_decode(gamma_encode(y, 2.2), 2.2);
            assert!((g - y).abs() <= 1e-14 + 1e-12 * y, "gamma {y} -> {g}");
        }
    }
    for code in 0..=255u8 {
        let v = f64::from(code) / 255.0;
        assert_eq!(srgb8(srgb_decode(v)), code, "code {code}");
    }
    // Both sides of the breakpoint and the breakpoint itself.
    for x in [
        SRGB_LINEAR_BREAK * (1.0 - 1e-12),
        SRGB_LINEAR_BREAK,
        0.0031309,
    ] {
        let back = srgb_decode(srgb_encode(x));
        assert!((back - x).abs() <= 1e-12 * x, "{x} -> {back}");
    }
}

#[test]
fn gamma_2_2_is_at_most_nine_codes_from_srgb() {
    // Exhaustive: for every sRGB code c, the code a gamma-2.2 writer stores for the same light.
    let diffs: Vec<i32> = (0..=255u8)
        .map(|c| i32::from(gamma8(srgb_decode(f64::from(c) / 255.0), 2.2)) - i32::from(c))
        .collect();
    let worst = *diffs.iter().max_by_key(|d| d.abs()).unwrap();
    let at: Vec<usize> = (0..256).filter(|&c| diffs[c] == worst).collect();
    // Independent bound, by calculus: on the linear segment the difference of the encoded
    // values x^(1/2.2) − 12.92 x peaks where (1/2.2) x^(1/2.2 − 1) = 12.92, i.e. at
    // x* = (2.2 × 12.92)^(−2.2/1.2), with value d*. Above the breakpoint the two curves
    // differ by less (both reach 1 at 1). Rounding moves each code by at most ½.
    let xs = (2.2f64 * 12.92).powf(-2.2 / 1.2);
    let d = xs.powf(1.0 / 2.2) - 12.92 * xs;
    let bound = 255.0 * d;
    assert!(
        xs < SRGB_LINEAR_BREAK,
        "x* = {xs} must be on the linear segment"
    );
    let w = f64::from(worst);
    assert!(
        w <= bound + 0.5 && w >= bound - 0.5,
        "worst {worst} codes at codes {at:?}, analytic {bound:.3}"
    );
    // Where: the sRGB codes around 255 × 12.92 x* ≈ 7.1.
    assert_eq!(at, vec![7, 8], "worst difference {worst}");
    assert!(
        diffs.iter().all(|&d| d >= -1),
        "gamma 2.2 is never more than 1 code darker"
    );
}

#[test]
fn encoders_are_monotone() {
    let n = 200_000;
    let (mut s, mut g, mut s8) = (0.0, 0.0, 0u8);
    for i in 0..=n {
        let x = 1.2 * f64::from(i) / f64::from(n);
        let (sn, gn, s8n) = (srgb_encode(x), gamma_encode(x, 2.2), srgb8(x));
        assert!(sn >= s && gn >= g && s8n >= s8, "not monotone at {x}");
        (s, g, s8) = (sn, gn, s8n);
    }
    assert_eq!(s8, 255);
}

#[test]
fn bad_numbers_give_defined_outputs() {
    for x in [f64::NAN, f64::NEG_INFINITY, -1.0, -0.0, -1e-300] {
        assert_eq!(srgb_encode(x), 0.0, "{x}");
        assert_eq!(srgb_decode(x), 0.0, "{x}");
        assert_eq!(gamma_encode(x, 2.2), 0.0, "{x}");
        assert_eq!(quantise(x), 0, "{x}");
    }
    assert_eq!(quantise(f64::INFINITY), 255);
    assert_eq!(srgb8(f64::INFINITY), 255);
    assert_eq!(quantise(1e300), 255);
    let weird = [
        DVec3::new(f64::NAN, 0.5, 0.5),
        DVec3::splat(f64::INFINITY),
        DVec3::new(f64::INFINITY, 0.0, 0.0),
        DVec3::new(f64::NEG_INFINITY, 1.0, 1.0),
        DVec3::splat(f64::NAN),
        DVec3::new(-0.5, 0.2, 0.2),
        DVec3::splat(-1.0),
        DVec3::new(1e308, -1e308, 1e308),
    ];
    let bytes = to_display_rgb8(&weird, 0.0);
    assert_eq!(bytes.len(), 3 * weird.len());
    assert_eq!(
        &bytes[0..3],
        to_display_rgb8(&[DVec3::new(0.0, 0.5, 0.5)], 0.0).as_slice(),
        "a NaN component counts as 0"
    );
    assert_eq!(&bytes[3..6], &[255, 255, 255], "+inf is white");
    assert_eq!(&bytes[12..15], &[0, 0, 0], "NaN is black");
    assert_eq!(&bytes[18..21], &[0, 0, 0], "negative luminance is black");
    for p in weird {
        for q in [fit_to_gamut(p), desaturate_seed(p), clip(p)] {
            let ok = q.min_element() >= 0.0 && q.max_element() <= 1.0;
            assert!(ok && q.is_finite(), "{p} -> {q}");
        }
    }
    assert!(to_display_rgb8(&[], 3.0).is_empty());
    // NaN exposure: defined (black), no panic.
    assert_eq!(to_display_rgb8(&[DVec3::ONE], f64::NAN), vec![0, 0, 0]);
}

#[test]
fn exposure_is_in_stops() {
    let c = DVec3::new(0.1, 0.2, 0.3);
    assert_eq!(exposure(c, 1.0), 2.0 * c);
    assert_eq!(exposure(c, -2.0), 0.25 * c);
    assert_eq!(exposure(c, 0.0), c);
    // Middle grey at 0 stops is the published 118; one stop down is linear 0.09, encoded
    // 1.055 · 0.09^(1/2.4) − 0.055 = 0.3318, code round(84.62) = 85.
    assert_eq!(to_display_rgb8(&[DVec3::splat(0.18)], 0.0), vec![118; 3]);
    assert_eq!(to_display_rgb8(&[DVec3::splat(0.18)], -1.0), vec![85; 3]);
    assert_eq!(
        to_display_rgb8(&[DVec3::splat(0.36)], -1.0),
        vec![118; 3],
        "0.36 one stop down is 0.18"
    );
}

/// Scaling *encoded* values by `k` is not the exposure `k`. On a pure power-law display it is
/// exactly an exposure, but of `k^γ`: `decode(k · encode(x)) = k^2.2 x`. On sRGB the factor on
/// the light depends on the level: within 15 % of `k^2.4` at full scale, a lower power of `k`
/// in the shadows (between `k^1.2` and `k^1.9` at linear 0.01), where the offset bends the
/// curve, and `k` itself on the linear toe (at linear 0.001): not nearer 1, nearer `k`.
#[test]
fn scaling_encoded_values_is_not_an_exposure() {
    for k in [0.5_f64, 2.0] {
        for i in 1..=100 {
            let x = f64::from(i) / 100.0 / k.max(1.0);
            let back = gamma_decode(k * gamma_encode(x, 2.2), 2.2);
            assert!(
                (back / (k.powf(2.2) * x) - 1.0).abs() <= 1e-12,
                "power law, k = {k}, x = {x}: {back}"
            );
        }
        let factor = |x: f64| srgb_decode(k * srgb_encode(x)) / x;
        let top = if k < 1.0 { 1.0 } else { 0.4 };
        assert!(
            (factor(top) / k.powf(2.4) - 1.0).abs() <= 0.15,
            "sRGB, k = {k}: factor {} at {top}, k^2.4 = {}",
            factor(top),
            k.powf(2.4)
        );
        let (low, mid) = (factor(0.01), k.powf(2.4));
        assert!(
            (low - 1.0).abs() < (mid - 1.0).abs() * 0.8,
            "sRGB, k = {k}: factor {low} in the shadows against k^2.4 = {mid}"
        );
        let power = low.ln() / k.ln();
        assert!(
            (1.2..1.9).contains(&power),
            "sRGB, k = {k}: factor k^{power} at linear 0.01"
        );
        assert!(
            (factor(0.001) / k - 1.0).abs() <= 1e-12,
            "sRGB, k = {k}: factor {} on the toe",
            factor(0.001)
        );
    }
}

/// The least-squares single exponent for sRGB: `γ` minimising `∫₀¹ (x^(1/γ) − srgb(x))² dx`
/// (on encoded values) is about 2.22, and on decoded values (`∫₀¹ (V^γ − srgb⁻¹(V))² dV`)
/// about 2.23: 2.2 is close, not the optimum.
#[test]
fn least_squares_exponent_of_srgb() {
    let fit = |err: &dyn Fn(f64, f64) -> f64| {
        let cost = |g: f64| {
            (0..=20_000)
                .map(|i| err(f64::from(i) / 20_000.0, g).powi(2))
                .sum::<f64>()
        };
        let (mut lo, mut hi) = (1.8_f64, 2.6_f64);
        let r = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..100 {
            let (a, b) = (hi - r * (hi - lo), lo + r * (hi - lo));
            if cost(a) < cost(b) {
                hi = b;
            } else {
                lo = a;
            }
        }
        0.5 * (lo + hi)
    };
    let encoded = fit(&|x, g| gamma_encode(x, g) - srgb_encode(x));
    let decoded = fit(&|v, g| gamma_decode(v, g) - srgb_decode(v));
    eprintln!("least-squares exponents: {encoded:.4} (encoded), {decoded:.4} (decoded)");
    assert!((encoded - 2.216).abs() <= 0.005, "encoded: {encoded}");
    assert!((decoded - 2.233).abs() <= 0.005, "decoded: {decoded}");
}

#[test]
fn luminance_weights_match_the_srgb_primaries() {
    // BT.709's published Y row vs the one derived from the primaries and D65 in `cie`.
    let derived = DVec3::new(
        cie::linear_srgb_to_xyz(DVec3::X).y,
        cie::linear_srgb_to_xyz(DVec3::Y).y,
        cie::linear_srgb_to_xyz(DVec3::Z).y,
    );
    // Component by component: glam's `max_element` would drop a NaN.
    let err = (derived - LUMA).abs();
    let err = if err.is_nan() {
        f64::NAN
    } else {
        err.max_element()
    };
    assert!(err <= 5e-5, "derived {derived} vs published {LUMA}");
}

// ---------------------------------------------------------------------------------------
// Over-bright colours: the source's claims about clipping and desaturation.

/// A saturated orange, over-exposed by `k`.
fn orange(k: f64) -> DVec3 {
    k * DVec3::new(0.9, 0.3, 0.05)
}

fn xy_hue_shift(a: DVec3, b: DVec3) -> f64 {
    hue_difference(hue_xy_degrees(a).unwrap(), hue_xy_degrees(b).unwrap()).abs()
}

#[test]
fn clipping_shifts_hue_as_the_seed_says() {
    // "once the largest value hits 255, the increase among all three values is no longer
    // proportional": the clipped orange at 4x is (1, 1, 0.2), a yellow.
    let shift = xy_hue_shift(orange(4.0), clip(orange(4.0)));
    assert!(shift >= 10.0, "clipping moved the hue by only {shift}°");
}

#[test]
fn seed_desaturation_keeps_the_xy_hue() {
    for k in [1.2, 2.0, 4.0, 20.0] {
        let out = desaturate_seed(orange(k));
        assert!((out.max_element() - 1.0).abs() <= 1e-12, "peak {out}");
        let shift = xy_hue_shift(orange(k), out);
        assert!(shift <= 1e-9, "k = {k}: hue moved {shift}°");
    }
    // Below the peak of 1 nothing changes.
    assert_eq!(desaturate_seed(orange(1.0)), orange(1.0));
    // A negative component is set to 0 first, which moves the hue before the mixture: the
    // xy hue is kept only for colours with no negative component.
    let out_of_gamut = DVec3::new(2.0, 0.6, -0.3);
    let shift = xy_hue_shift(out_of_gamut, desaturate_seed(out_of_gamut));
    assert!(shift > 1.0, "a negative blue kept its hue: {shift}°");
}

#[test]
fn seed_desaturation_does_not_keep_luminance() {
    // Blue at twice full scale has luminance 2 × 0.0722 = 0.144, displayable without any
    // clipping of luminance; the source's mix with white shows it at Y = 1 − 0.9278/2 = 0.536
    // (from the formula c/m² + 1 − 1/m with m = 2: (0.5, 0.5, 1)), 3.7 times too bright.
    let blue = DVec3::new(0.0, 0.0, 2.0);
    let seed = desaturate_seed(blue);
    let d = (seed - DVec3::new(0.5, 0.5, 1.0)).abs();
    assert!(d.x <= 1e-12 && d.y <= 1e-12 && d.z <= 1e-12, "{seed}");
    let ratio = luminance(seed) / luminance(blue);
    assert!(ratio >= 3.5, "seed brightens by {ratio}");
    // The project's rule keeps Y and the xy hue, and lands in range.
    let ours = fit_to_gamut(blue);
    assert!((luminance(ours) - luminance(blue)).abs() <= 1e-12, "{ours}");
    assert!(xy_hue_shift(blue, ours) <= 1e-9);
    assert!(ours.max_element() <= 1.0 && ours.min_element() >= 0.0);
}

#[test]
fn fit_to_gamut_keeps_luminance_and_hue() {
    let cases = [
        orange(1.5),
        orange(1.8),
        DVec3::new(-0.2, 0.6, 0.3),  // out of gamut: negative red
        DVec3::new(1.4, -0.1, 0.05), // both at once
        DVec3::new(0.3, 0.2, 0.1),   // already inside: unchanged
    ];
    for c in cases {
        let out = fit_to_gamut(c);
        assert!(
            out.min_element() >= 0.0 && out.max_element() <= 1.0,
            "{c} -> {out}"
        );
        assert!(
            (luminance(out) - luminance(c)).abs() <= 1e-12,
            "{c} -> {out}"
        );
        assert!(xy_hue_shift(c, out) <= 1e-9, "{c} -> {out}");
        // As little desaturation as possible: one component touches the boundary.
        let touches = out.max_element() >= 1.0 - 1e-12 || out.min_element() <= 1e-12;
        assert!(touches || out == c, "{c} -> {out}");
    }
    assert_eq!(
        fit_to_gamut(DVec3::new(0.3, 0.2, 0.1)),
        DVec3::new(0.3, 0.2, 0.1)
    );
    assert_eq!(fit_to_gamut(DVec3::splat(5.0)), DVec3::ONE);
    // Too bright to show at its luminance (Y = 1.23): white.
    assert_eq!(fit_to_gamut(orange(3.0)), DVec3::ONE);
}

// ---------------------------------------------------------------------------------------
// PNG files.

fn scratch(name: &str) -> crate::support::Scratch {
    crate::support::scratch(&format!("display-{name}"))
}

#[test]
fn png_round_trip() {
    let dir = scratch("roundtrip");
    let (w, h) = (7u32, 3u32);
    let pixels: Vec<DVec3> = (0..w * h)
        .map(|i| DVec3::new(f64::from(i) / 21.0, 0.18, 1.0 - f64::from(i) / 21.0))
        .collect();
    let bytes = to_display_rgb8(&pixels, 0.0);
    let path = dir.join("out.png");
    write_png(&path, w, h, &bytes).unwrap();
    let back = crate::support::read_png(&path);
    assert_eq!((back.width, back.height), (w, h));
    assert_eq!(back.bytes, bytes);
    // No temporary file left beside it.
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, vec![std::ffi::OsString::from("out.png")]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn failed_png_writes_name_the_path_and_leave_the_old_file() {
    let dir = scratch("atomic");
    let good = dir.join("good.png");
    write_png(&good, 1, 1, &[10, 20, 30]).unwrap();
    let before = std::fs::read(&good).unwrap();
    // Wrong buffer size: refused before anything is written.
    let e = write_png(&good, 2, 2, &[0; 5]).unwrap_err();
    assert!(
        e.to_string().contains("good.png") && e.to_string().contains("12"),
        "{e}"
    );
    assert_eq!(std::fs::read(&good).unwrap(), before);
    // A directory that does not exist.
    let missing = dir.join("no/such/dir/x.png");
    let e = write_png(&missing, 1, 1, &[0; 3]).unwrap_err();
    assert!(e.to_string().contains("no/such/dir/x.png"), "{e}");
    // The target is a (non-empty) directory: the rename fails; the directory and its
    // contents are untouched, and the temporary file is removed.
    let target = dir.join("taken.png");
    std::fs::create_dir(&target).unwrap();
    std::fs::write(target.join("keep"), b"keep").unwrap();
    let e = write_png(&target, 1, 1, &[0; 3]).unwrap_err();
    assert!(e.to_string().contains("taken.png"), "{e}");
    assert_eq!(std::fs::read(target.join("keep")).unwrap(), b"keep");
    let mut names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, vec!["good.png", "taken.png"]);
    assert_eq!(std::fs::read(&good).unwrap(), before);
    // Zero size.
    assert!(write_png(&dir.join("z.png"), 0, 1, &[]).is_err());
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---------------------------------------------------------------------------------------
// Exercises (ignored until the student fills in the answers; each test fails until then).

/// Exercise 1 of *From spectrum to display*: the names of the claims of
/// `check::display::srgb_encode` that the source's curve `x^(1/2.2)` fails.
const YOUR_FAILED_CLAIMS: Option<&[&str]> = None;
/// Exercise 1: `x^(1/2.2)` minus the sRGB encoding at `x = 0.001`.
const YOUR_GAP_AT_0_001: Option<f64> = None;
/// Exercise 1: how many of the 256 sRGB codes a gamma-2.2 writer stores differently.
const YOUR_CODES_THAT_DIFFER: Option<usize> = None;

/// Checks exercise 1 against the checker's own verdict, the two curves at 0.001 (to 1e-4) and
/// the exhaustive count over the codes.
#[test]
#[ignore = "exercise 1 of From spectrum to display: fill in the three answers, then run it"]
fn exercise_1_the_sources_gamma() {
    let v = raylemma::check::display::srgb_encode(
        &|x| gamma_encode(x, 2.2),
        &raylemma::check::Options::default(),
    );
    eprintln!("{v}");
    let mut failed: Vec<&str> = v
        .findings
        .iter()
        .filter(|f| !f.passed())
        .map(|f| f.name.as_str())
        .collect();
    let mut yours = YOUR_FAILED_CLAIMS
        .expect("fill in YOUR_FAILED_CLAIMS")
        .to_vec();
    failed.sort_unstable();
    yours.sort_unstable();
    assert_eq!(yours, failed, "the claims the source's curve fails");
    let gap = gamma_encode(0.001, 2.2) - srgb_encode(0.001);
    let answer = YOUR_GAP_AT_0_001.expect("fill in YOUR_GAP_AT_0_001");
    assert!((answer - gap).abs() <= 1e-4, "{answer} vs {gap}");
    let differ = (0..=255u8)
        .filter(|&c| gamma8(srgb_decode(f64::from(c) / 255.0), 2.2) != c)
        .count();
    assert_eq!(YOUR_CODES_THAT_DIFFER, Some(differ));
}

/// Exercise 2 of *From spectrum to display*: `(sRGB, gamma 2.2)`, the numbers of codes
/// `c` in 0..=255 that do not come back from decoding `c / 255` and encoding to 8 bits again.
const YOUR_ROUND_TRIP_FAILURES: Option<(usize, usize)> = None;

/// Checks exercise 2 against the exhaustive count for each curve.
#[test]
#[ignore = "exercise 2 of From spectrum to display: fill in YOUR_ROUND_TRIP_FAILURES, then run it"]
fn exercise_2_round_trip_through_8_bits() {
    let srgb = (0..=255u8)
        .filter(|&c| srgb8(srgb_decode(f64::from(c) / 255.0)) != c)
        .count();
    let gamma = (0..=255u8)
        .filter(|&c| gamma8(gamma_decode(f64::from(c) / 255.0, 2.2), 2.2) != c)
        .count();
    assert_eq!(YOUR_ROUND_TRIP_FAILURES, Some((srgb, gamma)));
}

/// Exercise 3 of *From spectrum to display*: a gamut rule that keeps the CIELAB hue and
/// lightness (white = sRGB (1, 1, 1)) and reduces the chroma until the colour fits in
/// `[0, 1]³`; white when `L* > 100`.
fn your_lab_gamut_rule(rgb: DVec3) -> DVec3 {
    let _ = rgb;
    unimplemented!("exercise 3 of From spectrum to display: a CIELAB gamut rule")
}

/// Checks exercise 3 on the chapter's colours (the orange, a blue and a green, twice and four
/// times over-exposed) and two out-of-gamut colours (a 520 nm line and a sodium yellow at
/// Y = 0.5): the result lies in `[0, 1]³`; brighter than white gives white; otherwise `L*` is
/// kept (to 1e-6, and so `Y`, to 1e-6), the CIELAB hue within 0.5°, and the colour is on the
/// gamut's boundary (a component at 0 or 1, to 1e-6). It reports the xy hue shift of both
/// rules, and asserts that the CIELAB rule moves the orange's xy hue where `fit_to_gamut` does not.
#[test]
#[ignore = "exercise 3 of From spectrum to display: fill in your_lab_gamut_rule, then run it"]
fn exercise_3_cielab_gamut_rule() {
    let white = cie::linear_srgb_to_xyz(DVec3::ONE);
    let lab_of = |c: DVec3| lab(cie::linear_srgb_to_xyz(c), white);
    let line = cie::xyz_to_linear_srgb(cie::cmf(520.0));
    let sodium = cie::xyz_to_linear_srgb(cie::cmf(589.0));
    let mut colours = vec![];
    for k in [2.0, 4.0] {
        colours.push(orange(k));
        colours.push(k * DVec3::new(0.05, 0.1, 0.5));
        colours.push(k * DVec3::new(0.1, 0.5, 0.15));
    }
    colours.push(line * 0.5 / luminance(line));
    colours.push(sodium * 0.5 / luminance(sodium));
    for c in colours {
        let out = your_lab_gamut_rule(c);
        assert!(
            out.min_element() >= -1e-9 && out.max_element() <= 1.0 + 1e-9,
            "{c} -> {out}"
        );
        if luminance(c) >= 1.0 {
            assert!(
                (out - DVec3::ONE).abs().max_element() <= 1e-9,
                "{c} -> {out}"
            );
            continue;
        }
        let (a, b) = (lab_of(c), lab_of(out));
        assert!((a.x - b.x).abs() <= 1e-6, "{c}: L* {} -> {}", a.x, b.x);
        let y = |c: DVec3| cie::linear_srgb_to_xyz(c).y;
        assert!((y(c) - y(out)).abs() <= 1e-6, "{c}: Y changed");
        let dh = hue_difference(b.z.atan2(b.y).to_degrees(), a.z.atan2(a.y).to_degrees());
        assert!(dh.abs() <= 0.5, "{c}: CIELAB hue moved {dh}°");
        let boundary = out.min_element().abs().min((out.max_element() - 1.0).abs());
        assert!(
            boundary <= 1e-6,
            "{c} -> {out} is not on the gamut's boundary"
        );
        let ours = fit_to_gamut(c);
        eprintln!(
            "{c}: xy hue shift, CIELAB rule {:.2}°, fit_to_gamut {:.2}°",
            xy_hue_shift(c, out),
            xy_hue_shift(c, ours)
        );
    }
    let o = orange(2.0);
    assert!(xy_hue_shift(o, your_lab_gamut_rule(o)) > 1.0);
    assert!(xy_hue_shift(o, fit_to_gamut(o)) <= 1e-9);
}

/// The card's line for a failing sRGB curve prints its numbers without the noise digits of
/// the nearest `f64` (`0.02584`, not `0.025840000000000002`).
#[test]
fn the_reference_lines_print_numbers_without_noise_digits() {
    use raylemma::check::display::{digits, srgb_encode};
    assert_eq!(digits(0.025_840_000_000_000_002), "0.02584");
    assert_eq!(digits(0.059_319_222_841_505_14), "0.0593192228415");
    assert_eq!(digits(1.0), "1");
    assert_eq!(digits(f64::NAN), "NaN");
    let verdict = srgb_encode(&gamma22, &Default::default());
    let reference = verdict
        .findings
        .iter()
        .find(|f| f.name == "reference")
        .unwrap();
    let example = reference.worst_example.as_ref().unwrap();
    assert!(
        example.contains("the standard gives") && !example.contains("00000000"),
        "{example}"
    );
}
