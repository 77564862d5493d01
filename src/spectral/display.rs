//! From linear sRGB to the 8-bit codes of a display: exposure, over-bright and out-of-gamut
//! colours, the transfer function (gamma 2.2 of the source notes and the exact sRGB curve)
//! and 8-bit quantisation. The PNG file that holds the codes is written by
//! [`crate::image::png`]. Chapter: *From spectrum to display*
//! (`chapters/spectral/display.md`).
//!
//! The pipeline of [`to_display_rgb8`] is: multiply by `2^stops`; bring each pixel into
//! `[0, 1]³` by moving it toward the grey of equal luminance ([`fit_to_gamut`]); encode
//! with the sRGB curve ([`srgb_encode`]); round to 8 bits ([`quantise`]).

use glam::{DVec2, DVec3};

use super::cie;

// ---------------------------------------------------------------------------------------
// Transfer functions.

// ANCHOR: gamma
/// The source's display encoding: a display shows `L_o = V^γ`, so the value to store for a
/// linear intensity `x` is `V = x^(1/γ)` (γ = 2.2 in the source notes). Negative and NaN inputs
/// give 0; values above 1 are not clipped here (see [`quantise`]).
pub fn gamma_encode(x: f64, gamma: f64) -> f64 {
    if x > 0.0 { x.powf(1.0 / gamma) } else { 0.0 }
}

/// The inverse of [`gamma_encode`]: the intensity `V^γ` a pure power-law display shows.
pub fn gamma_decode(v: f64, gamma: f64) -> f64 {
    if v > 0.0 { v.powf(gamma) } else { 0.0 }
}
// ANCHOR_END: gamma

// ANCHOR: srgb
/// The linear-segment breakpoint of the sRGB encoding (IEC 61966-2-1), in linear light.
pub const SRGB_LINEAR_BREAK: f64 = 0.003_130_8;
/// The breakpoint in encoded values, as the standard states it for decoding.
pub const SRGB_ENCODED_BREAK: f64 = 0.040_45;

// EXERCISE spectral/display srgb_encode: the sRGB transfer function, linear to encoded
/// The sRGB transfer function (IEC 61966-2-1), linear `x` to encoded `V`:
/// `V = 12.92 x` for `x ≤ 0.0031308`, `V = 1.055 x^(1/2.4) − 0.055` above.
/// Negative and NaN inputs give 0; values above 1 are not clipped here.
pub fn srgb_encode(x: f64) -> f64 {
    if x > SRGB_LINEAR_BREAK {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    } else if x > 0.0 {
        12.92 * x
    } else {
        0.0
    }
}
// END EXERCISE

// EXERCISE spectral/display srgb_decode: the sRGB transfer function's inverse, encoded to linear
/// The inverse of [`srgb_encode`]: `x = V / 12.92` for `V ≤ 0.04045`,
/// `x = ((V + 0.055) / 1.055)^2.4` above. Negative and NaN inputs give 0.
pub fn srgb_decode(v: f64) -> f64 {
    if v > SRGB_ENCODED_BREAK {
        ((v + 0.055) / 1.055).powf(2.4)
    } else if v > 0.0 {
        v / 12.92
    } else {
        0.0
    }
}
// END EXERCISE
// ANCHOR_END: srgb

// ANCHOR: quantise
/// An encoded value in `[0, 1]` to an 8-bit code: `round(255 V)`, clamped to 0..=255.
/// NaN gives 0, +∞ gives 255.
pub fn quantise(v: f64) -> u8 {
    // `as` saturates and maps NaN to 0; the clamp makes the intent explicit.
    (255.0 * v).round().clamp(0.0, 255.0) as u8
}
// ANCHOR_END: quantise

/// The 8-bit sRGB code of linear `x`.
pub fn srgb8(x: f64) -> u8 {
    quantise(srgb_encode(x))
}

/// The 8-bit code of linear `x` under the power law `x^(1/γ)`.
pub fn gamma8(x: f64, gamma: f64) -> u8 {
    quantise(gamma_encode(x, gamma))
}

// ---------------------------------------------------------------------------------------
// Exposure, luminance, hue.

/// Exposure: linear light times `2^stops` (one stop doubles the light).
pub fn exposure(rgb: DVec3, stops: f64) -> DVec3 {
    rgb * stops.exp2()
}

/// The luminance weights of linear sRGB, as ITU-R BT.709 publishes them (the Y row of
/// the RGB → XYZ matrix, rounded to four digits).
pub const LUMA: DVec3 = DVec3::new(0.2126, 0.7152, 0.0722);

/// The relative luminance `Y` of linear sRGB.
pub fn luminance(rgb: DVec3) -> f64 {
    LUMA.dot(rgb)
}

/// The hue of a linear sRGB colour as the angle, in degrees, of its CIE xy chromaticity
/// seen from the D65 white point; `None` for black and for the white point itself.
/// Additive mixture with white moves a colour along the straight line to the white
/// point, so it keeps this angle (the colour's dominant wavelength).
pub fn hue_xy_degrees(rgb: DVec3) -> Option<f64> {
    let c = cie::chromaticity(cie::linear_srgb_to_xyz(rgb))? - cie::SRGB_WHITE;
    (c.length() > 1e-12).then(|| c.y.atan2(c.x).to_degrees())
}

/// The CIELAB hue angle `h_ab` in degrees (D65 white `Y = 1`); `None` for greys.
pub fn hue_lab_degrees(rgb: DVec3) -> Option<f64> {
    let lab = lab(
        cie::linear_srgb_to_xyz(rgb),
        cie::linear_srgb_to_xyz(DVec3::ONE),
    );
    let ab = DVec2::new(lab.y, lab.z);
    (ab.length() > 1e-9).then(|| ab.y.atan2(ab.x).to_degrees())
}

/// CIELAB (CIE 1976) of `xyz` relative to the white `white`.
pub fn lab(xyz: DVec3, white: DVec3) -> DVec3 {
    let f = |t: f64| {
        const D: f64 = 6.0 / 29.0;
        if t > D * D * D {
            t.cbrt()
        } else {
            t / (3.0 * D * D) + 4.0 / 29.0
        }
    };
    let (fx, fy, fz) = (f(xyz.x / white.x), f(xyz.y / white.y), f(xyz.z / white.z));
    DVec3::new(116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz))
}

/// The CIE 1976 colour difference ΔE*ab between two linear sRGB colours: the distance of
/// their CIELAB coordinates, white = sRGB (1, 1, 1).
pub fn delta_e(a: DVec3, b: DVec3) -> f64 {
    let white = cie::linear_srgb_to_xyz(DVec3::ONE);
    (lab(cie::linear_srgb_to_xyz(a), white) - lab(cie::linear_srgb_to_xyz(b), white)).length()
}

/// The signed difference of two hue angles in degrees, in (−180, 180].
pub fn hue_difference(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    if d > 180.0 { d - 360.0 } else { d }
}

// ---------------------------------------------------------------------------------------
// Over-bright and out-of-gamut colours.

// ANCHOR: clip
/// Clipping: each component to `[0, 1]` on its own (NaN to 0). Changes the ratios of the
/// components, hence the hue, as soon as one of them leaves the range.
pub fn clip(rgb: DVec3) -> DVec3 {
    let c = |x: f64| if x > 0.0 { x.min(1.0) } else { 0.0 };
    DVec3::new(c(rgb.x), c(rgb.y), c(rgb.z))
}
// ANCHOR_END: clip

// ANCHOR: desaturate_seed
/// The source's desaturation: "interpolate between the computed radiance and pure white using
/// the peak as the interpolating variable". The source gives no formula; this is the reading
/// that stays in range. Negative and NaN components count as 0. With the peak `m = max(r, g, b) > 1`, the colour scaled to peak 1,
/// `c / m`, is mixed with white `(1, 1, 1)` with the weight `t = 1 − 1/m` of white:
/// `(1 − t) c / m + t = c / m² + 1 − 1/m`. Colours with `m ≤ 1` are unchanged. The peak of
/// the result is exactly 1.
pub fn desaturate_seed(rgb: DVec3) -> DVec3 {
    let pos = |x: f64| if x > 0.0 { x } else { 0.0 };
    let c = DVec3::new(pos(rgb.x), pos(rgb.y), pos(rgb.z));
    let m = c.max_element();
    if m <= 1.0 {
        return clip(c);
    }
    if !m.is_finite() {
        return DVec3::ONE;
    }
    let t = 1.0 - 1.0 / m;
    (1.0 - t) * c / m + DVec3::splat(t)
}
// ANCHOR_END: desaturate_seed

// ANCHOR: fit_to_gamut
/// The project's rule for colours outside `[0, 1]³` (over-bright, or out of the sRGB gamut
/// with a negative component): move the colour along the straight line toward the grey of
/// equal luminance `(Y, Y, Y)`, `c' = Y + s (c − Y)`, with the largest `s ≤ 1` that brings
/// every component into `[0, 1]`. Luminance is kept whenever `0 ≤ Y ≤ 1`, and so is the
/// xy hue (the line to the grey is the line to the white point in xy). `Y > 1` gives
/// white, `Y < 0` black. NaN components count as 0; infinities as huge numbers.
pub fn fit_to_gamut(rgb: DVec3) -> DVec3 {
    let tame = |x: f64| {
        if x.is_nan() {
            0.0
        } else {
            x.clamp(-1e100, 1e100)
        }
    };
    let c = DVec3::new(tame(rgb.x), tame(rgb.y), tame(rgb.z));
    let y = luminance(c);
    if y >= 1.0 {
        return DVec3::ONE;
    }
    if y <= 0.0 {
        return DVec3::ZERO;
    }
    let (hi, lo) = (c.max_element(), c.min_element());
    let mut s: f64 = 1.0;
    if hi > 1.0 {
        s = s.min((1.0 - y) / (hi - y));
    }
    if lo < 0.0 {
        s = s.min(y / (y - lo));
    }
    // Rounding can leave 1 + 1e-16: clip the last ulp.
    clip(DVec3::splat(y) + s * (c - DVec3::splat(y)))
}
// ANCHOR_END: fit_to_gamut

// ANCHOR: to_display
/// Linear sRGB pixels (row-major) to the 8-bit sRGB bytes of a PNG: exposure `2^stops`,
/// [`fit_to_gamut`], the sRGB curve, rounding. Three bytes per pixel; never panics.
pub fn to_display_rgb8(linear_srgb: &[DVec3], stops: f64) -> Vec<u8> {
    let mut out = Vec::with_capacity(3 * linear_srgb.len());
    for &p in linear_srgb {
        let c = fit_to_gamut(exposure(p, stops));
        out.extend([srgb8(c.x), srgb8(c.y), srgb8(c.z)]);
    }
    out
}
// ANCHOR_END: to_display
