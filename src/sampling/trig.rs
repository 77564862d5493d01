//! The sine and cosine of an angle in `[-pi/4, pi/4]` by their Taylor series: the speed
//! trick of the concentric disc map (chapter *The unit disc*, `chapters/sampling/disc.md`),
//! kept apart from the map a student re-implements, and kept at all because it pays: the
//! chapter's table `disc_quarter_speed.md` measures it against the standard library's
//! `sin_cos`, alone and inside the map.
//!
//! Written once for both precisions (see [`crate::precision`]): `Float` is `f64` in
//! `raylemma::sampling::trig` and `f32` in its twin `raylemma::single::sampling::trig`, and
//! the number of terms follows the precision's mantissa.

use super::precision::Float;

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
