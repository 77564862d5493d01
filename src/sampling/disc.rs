//! Uniformly sampling the unit disc. Chapter: *The unit disc* (`chapters/sampling/disc.md`).
//!
//! Both maps are area-preserving warps from the unit square with pdf `1 / pi`; they differ
//! in how much they stretch the square's cells, which matters for stratified samples.
//!
//! Written once for both precisions (see [`crate::precision`]): `Float`, `V2`, `V3` are
//! `f64`, `DVec2`, `DVec3` in `raylemma::sampling::disc` and `f32`, `Vec2`, `Vec3` in its
//! twin `raylemma::single::sampling::disc`.

use glam::{DVec2, DVec3};

use super::precision::{Float, V2, V3, consts};

/// Density of a uniform point on the unit disc, per unit area.
pub const DISC_PDF: Float = 1.0 / consts::PI;

// ANCHOR: polar
// EXERCISE sampling/disc disc_polar: map the unit square to the disc with r = sqrt(u1), phi = 2 pi u2
/// The polar map: `r = sqrt(u1)` (the inverse of the radial CDF `r^2`), `phi = 2 pi u2`.
pub fn disc_polar(u: V2) -> V3 {
    let r = u.x.sqrt();
    let phi = consts::TAU * u.y;
    V3::new(r * phi.cos(), r * phi.sin(), 0.0)
}
// END EXERCISE
// ANCHOR_END: polar

// ANCHOR: concentric
// EXERCISE sampling/disc disc_concentric: Shirley and Chiu's concentric map from the unit square to the disc
/// Shirley and Chiu's concentric map (*A Low Distortion Map Between Disk and Square*,
/// JGT 1997): concentric squares of `[-1, 1]^2` go to concentric circles, each square's
/// wedge to a sector of equal angle. Written in the two-wedge form with negative radii
/// that Shirley posted in 2011 (crediting Dave Cline), as pbrt has it; with the second
/// wedge's angle written `pi/2 - psi` it is the same map as the paper's four regions.
/// With `a = 2u - 1`: if `|a.x| > |a.y|`, `r = a.x` and `phi = (pi/4) a.y / a.x`; otherwise
/// `r = a.y` and `phi = pi/2 - (pi/4) a.x / a.y`, whose cosine and sine are the sine and
/// cosine of `psi = (pi/4) a.x / a.y`. Either way the angle to take the sine and cosine of
/// lies in `[-pi/4, pi/4]`, where [`sin_cos_quarter`] needs no range reduction.
pub fn disc_concentric(u: V2) -> V3 {
    let a = 2.0 * u - V2::ONE;
    if a == V2::ZERO {
        return V3::ZERO;
    }
    if a.y.abs() < a.x.abs() {
        let (sin, cos) = sin_cos_quarter(consts::FRAC_PI_4 * (a.y / a.x));
        V3::new(a.x * cos, a.x * sin, 0.0)
    } else {
        let (sin, cos) = sin_cos_quarter(consts::FRAC_PI_4 * (a.x / a.y));
        V3::new(a.y * sin, a.y * cos, 0.0)
    }
}
// END EXERCISE
// ANCHOR_END: concentric

// ANCHOR: sin_cos_quarter
/// How many coefficients each series of [`sin_cos_quarter`] sums in this precision: 8 in
/// `f64` (the sine to `x^17`, the cosine to `x^18`), 4 in `f32` (to `x^9` and `x^10`).
///
/// At `|x| = pi/4` the first omitted terms are `x^19/19! = 8.3e-20` and
/// `x^20/20! = 3.3e-21` in `f64`, `x^11/11! = 1.8e-9` and `x^12/12! = 1.2e-10` in `f32`:
/// each under a tenth of half an ulp of `cos(pi/4) = 0.707` (`5.6e-17` and `3.0e-8`). One
/// coefficient fewer would leave the sine's `x^17/17! = 4.6e-17`, resp. `x^9/9! = 3.1e-7`,
/// which is not. The precision's mantissa decides, so the one source serves both twins.
pub const QUARTER_TERMS: usize = if Float::MANTISSA_DIGITS > f32::MANTISSA_DIGITS {
    8
} else {
    4
};

/// `(sin x, cos x)` for `|x| <= pi/4`, by their Taylor series, summed only as far as the
/// precision needs ([`QUARTER_TERMS`]): what is left is the sums' rounding, within
/// `2 eps` of the value (a test measures it against the standard library's). No range
/// reduction and no branch; outside `[-pi/4, pi/4]` it is not accurate. Each series is a
/// polynomial in `z = x^2` (of degree 7 in `f64`, 3 in `f32`), summed by Estrin's scheme
/// rather than Horner's: pairs `k0 + k1 z`, then pairs of pairs with `z^2`, then (in
/// `f64`) the two halves with `z^4`. That is Horner's multiplications and additions plus
/// the one multiplication for `z^4`, in three dependent steps instead of seven (two
/// instead of three in `f32`).
#[inline]
pub fn sin_cos_quarter(x: Float) -> (Float, Float) {
    // sin x = x - x z (1/3! - z/5! + z^2/7! - ... - z^7/17!)
    const SIN: [Float; 8] = [
        1.0 / 6.0,
        -1.0 / 120.0,
        1.0 / 5_040.0,
        -1.0 / 362_880.0,
        1.0 / 39_916_800.0,
        -1.0 / 6_227_020_800.0,
        1.0 / 1_307_674_368_000.0,
        -1.0 / 355_687_428_096_000.0,
    ];
    // cos x = 1 - z/2 + z^2 (1/4! - z/6! + z^2/8! - ... + z^7/18!)
    const COS: [Float; 8] = [
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 20_922_789_888_000.0,
        -1.0 / 6_402_373_705_728_000.0,
    ];
    let z = x * x;
    let z2 = z * z;
    // The first QUARTER_TERMS coefficients of k (a constant: the other branch is not
    // compiled into the twin).
    let estrin = |k: &[Float; 8]| {
        let low = (k[0] + k[1] * z) + z2 * (k[2] + k[3] * z);
        if QUARTER_TERMS == 4 {
            return low;
        }
        let high = (k[4] + k[5] * z) + z2 * (k[6] + k[7] * z);
        low + (z2 * z2) * high
    };
    (x - x * z * estrin(&SIN), 1.0 - 0.5 * z + z2 * estrin(&COS))
}
// ANCHOR_END: sin_cos_quarter

/// The inverse of [`disc_polar`].
pub fn disc_polar_invert(p: V3) -> V2 {
    let phi = p.y.atan2(p.x);
    let phi = if phi < 0.0 { phi + consts::TAU } else { phi };
    V2::new(p.x * p.x + p.y * p.y, phi / consts::TAU)
}

/// The inverse of [`disc_concentric`], wedge by wedge.
pub fn disc_concentric_invert(p: V3) -> V2 {
    let radius = (p.x * p.x + p.y * p.y).sqrt();
    if radius == 0.0 {
        return V2::splat(0.5);
    }
    let a = if p.x.abs() >= p.y.abs() {
        let ax = radius.copysign(p.x);
        V2::new(ax, ax * (p.y / p.x).atan() / consts::FRAC_PI_4)
    } else {
        let ay = radius.copysign(p.y);
        V2::new(ay * (p.x / p.y).atan() / consts::FRAC_PI_4, ay)
    };
    (a + V2::ONE) / 2.0
}

/// The uniform disc density: `1 / pi` inside, 0 outside.
pub fn disc_pdf(p: V3) -> Float {
    if p.x * p.x + p.y * p.y <= 1.0 {
        DISC_PDF
    } else {
        0.0
    }
}

/// Anisotropy of a warp at `u`: the ratio of the larger to the smaller singular value of
/// its Jacobian (1 = cells keep their shape), by central differences.
///
/// A measurement of `f64` maps, in `f64` in both twins: its step `h = 1e-6` would leave
/// nothing but rounding in `f32`.
pub fn anisotropy(warp: impl Fn(DVec2) -> DVec3, u: DVec2) -> f64 {
    let h = 1e-6;
    let du = (warp(u + DVec2::new(h, 0.0)) - warp(u - DVec2::new(h, 0.0))) / (2.0 * h);
    let dv = (warp(u + DVec2::new(0.0, h)) - warp(u - DVec2::new(0.0, h))) / (2.0 * h);
    // Singular values of [du dv] from its Gram matrix [[a, b], [b, c]].
    let (a, b, c) = (du.length_squared(), du.dot(dv), dv.length_squared());
    let mean = (a + c) / 2.0;
    let spread = (((a - c) / 2.0).powi(2) + b * b).sqrt();
    ((mean + spread) / (mean - spread).max(f64::MIN_POSITIVE)).sqrt()
}
