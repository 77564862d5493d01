//! CIE 1931 colour: the 2° colour-matching functions, XYZ of a spectrum, chromaticity, and
//! XYZ to linear sRGB. Chapter: *Spectra and CIE colour* (`chapters/spectral/colour.md`).
//!
//! The colour-matching functions x̄, ȳ, z̄ come from the CIE's 1 nm table (360-830 nm,
//! `data/cie1931_2deg_cmf_1nm.csv`), linear between entries and zero outside. The XYZ of a
//! spectrum `S` is normalised so that the constant spectrum 1 has `Y = 1`:
//!
//! `X = ∫ S x̄ dλ / ∫ ȳ dλ`, and likewise `Y`, `Z`, over 360-830 nm.

use std::sync::OnceLock;

use glam::{DMat3, DVec2, DVec3};

use super::{LAMBDA_MAX, LAMBDA_MIN};

/// The CIE 1931 2° table, embedded (see `data/README.md` for its source).
pub(crate) const CMF_CSV: &str = include_str!("../../data/cie1931_2deg_cmf_1nm.csv");

/// The number of 1 nm rows of the table, 360..=830.
pub const CMF_ROWS: usize = 471;

struct Cmf {
    /// x̄, ȳ, z̄ at 360 + i nm.
    rows: Vec<DVec3>,
    /// ∫ ȳ dλ over the table (trapezoids, exact for the linear interpolant).
    y_integral: f64,
}

fn table() -> &'static Cmf {
    static CMF: OnceLock<Cmf> = OnceLock::new();
    CMF.get_or_init(|| {
        let tables = super::spectrum::parse_csv(CMF_CSV, "cie1931_2deg_cmf_1nm.csv")
            .unwrap_or_else(|e| panic!("{e}"));
        let nm = tables[0].1.wavelengths();
        assert!(
            nm.len() == CMF_ROWS && nm[0] == LAMBDA_MIN && nm[CMF_ROWS - 1] == LAMBDA_MAX,
            "the CIE table must have 1 nm rows from 360 to 830 nm"
        );
        let rows: Vec<DVec3> = (0..CMF_ROWS)
            .map(|i| {
                DVec3::new(
                    tables[0].1.values()[i],
                    tables[1].1.values()[i],
                    tables[2].1.values()[i],
                )
            })
            .collect();
        let y_integral = tables[1].1.integral();
        Cmf { rows, y_integral }
    })
}

// ANCHOR: cmf
/// (x̄, ȳ, z̄) at `nm`: linear interpolation in the 1 nm table, zero outside 360-830 nm.
pub fn cmf(nm: f64) -> DVec3 {
    let rows = &table().rows;
    let s = nm - LAMBDA_MIN;
    // NaN fails the comparison and is mapped to zero like any wavelength outside.
    if !(s >= 0.0 && s <= (CMF_ROWS - 1) as f64) {
        return DVec3::ZERO;
    }
    let i = (s as usize).min(CMF_ROWS - 2);
    let t = s - i as f64;
    rows[i].lerp(rows[i + 1], t)
}
// ANCHOR_END: cmf

/// The table row at `360 + i` nm, exactly as published.
pub fn cmf_row(i: usize) -> DVec3 {
    table().rows[i]
}

/// `∫ ȳ dλ` over 360-830 nm (≈ 106.86 nm): the normaliser that gives the constant
/// spectrum 1 a luminance `Y = 1`.
pub fn y_integral() -> f64 {
    table().y_integral
}

/// Gauss-Legendre nodes and weights on [0, 1], four points: exact for polynomials of
/// degree 7, so exact for a piecewise-linear spectrum with knots on whole nanometres times
/// the piecewise-linear colour-matching functions.
const GAUSS4: [(f64, f64); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_87, 0.326_072_577_431_273_07),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

// ANCHOR: xyz
/// The CIE XYZ of the spectrum `s` (a function of nm), normalised so that `s = 1` gives
/// `Y = 1`: `∫ s(λ) (x̄, ȳ, z̄)(λ) dλ / ∫ ȳ dλ` over 360-830 nm.
///
/// The integral is 4-point Gauss-Legendre on each 1 nm interval of the table: exact when
/// `s` is piecewise linear with knots on whole nanometres (every table in `data/`), and
/// accurate to ~1e-12 for smooth spectra such as a blackbody. This is the reference value
/// that the Monte Carlo estimators of the *Wavelength sampling* chapter are tested against.
pub fn xyz(s: impl Fn(f64) -> f64) -> DVec3 {
    let rows = &table().rows;
    let mut sum = DVec3::ZERO;
    for i in 0..CMF_ROWS - 1 {
        let lo = LAMBDA_MIN + i as f64;
        for (t, w) in GAUSS4 {
            sum += w * s(lo + t) * rows[i].lerp(rows[i + 1], t);
        }
    }
    sum / y_integral()
}
// ANCHOR_END: xyz

// ---------------------------------------------------------------------------------------
// The analytic fit of Wyman, Sloan and Shirley (2013).

/// One lobe of the multi-lobe fit: `weight · exp(−½ ((λ − mu) · s)²)` with
/// `s = inv_sigma_below` for `λ < mu` and `inv_sigma_above` otherwise (a Gaussian with a
/// different width on each side of its peak).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lobe {
    /// The lobe's height.
    pub weight: f64,
    /// The wavelength of its peak, nm.
    pub mu: f64,
    /// 1/σ below the peak, 1/nm.
    pub inv_sigma_below: f64,
    /// 1/σ above the peak, 1/nm.
    pub inv_sigma_above: f64,
}

impl Lobe {
    const fn new(weight: f64, mu: f64, inv_sigma_below: f64, inv_sigma_above: f64) -> Self {
        Lobe {
            weight,
            mu,
            inv_sigma_below,
            inv_sigma_above,
        }
    }

    /// The lobe at `nm`.
    #[inline]
    pub fn eval(&self, nm: f64) -> f64 {
        let d = nm - self.mu;
        let t = d * if d < 0.0 {
            self.inv_sigma_below
        } else {
            self.inv_sigma_above
        };
        self.weight * (-0.5 * t * t).exp()
    }
}

// ANCHOR: fit_lobes
/// The lobes of the multi-lobe fit of x̄, ȳ, z̄: C. Wyman, P.-P. Sloan and P. Shirley,
/// *Simple Analytic Approximations to the CIE XYZ Color Matching Functions*, Journal of
/// Computer Graphics Techniques 2(2), 1-11, 2013, Listing 2 (the widths are the listing's
/// reciprocals 1/σ, e.g. 0.0264 = 1/37.9 nm).
pub const FIT_X: [Lobe; 3] = [
    Lobe::new(1.056, 599.8, 0.0264, 0.0323),
    Lobe::new(0.362, 442.0, 0.0624, 0.0374),
    Lobe::new(-0.065, 501.1, 0.0490, 0.0382),
];
/// The lobes of ȳ (see [`FIT_X`]).
pub const FIT_Y: [Lobe; 2] = [
    Lobe::new(0.821, 568.8, 0.0213, 0.0247),
    Lobe::new(0.286, 530.9, 0.0613, 0.0322),
];
/// The lobes of z̄ (see [`FIT_X`]).
pub const FIT_Z: [Lobe; 2] = [
    Lobe::new(1.217, 437.0, 0.0845, 0.0278),
    Lobe::new(0.681, 459.0, 0.0385, 0.0725),
];
// ANCHOR_END: fit_lobes

// ANCHOR: cmf_fit
/// (x̄, ȳ, z̄) at `nm` by the Wyman-Sloan-Shirley fit ([`FIT_X`], [`FIT_Y`], [`FIT_Z`]):
/// seven exponentials instead of a table look-up. Like [`cmf`] it is zero outside
/// 360-830 nm and for NaN, so that both describe the same observer on the same range.
/// Its error against the table is measured in the chapter (`figures/colour_fit.md`).
pub fn cmf_fit(nm: f64) -> DVec3 {
    if !(LAMBDA_MIN..=LAMBDA_MAX).contains(&nm) {
        return DVec3::ZERO;
    }
    let sum = |lobes: &[Lobe]| lobes.iter().map(|l| l.eval(nm)).sum::<f64>();
    DVec3::new(sum(&FIT_X), sum(&FIT_Y), sum(&FIT_Z))
}
// ANCHOR_END: cmf_fit

/// The XYZ of the spectrum `s` with any colour-matching functions `cmf` (for instance
/// [`cmf_fit`]): the same 4-point Gauss-Legendre rule on each 1 nm interval of 360-830 nm
/// as [`xyz`], normalised by the same rule's `∫ ȳ dλ` of `cmf` itself, so that `s = 1`
/// has `Y = 1` for every `cmf`.
pub fn xyz_with(cmf: impl Fn(f64) -> DVec3, s: impl Fn(f64) -> f64) -> DVec3 {
    let (mut sum, mut y) = (DVec3::ZERO, 0.0);
    for i in 0..CMF_ROWS - 1 {
        let lo = LAMBDA_MIN + i as f64;
        for (t, w) in GAUSS4 {
            let c = cmf(lo + t);
            sum += w * s(lo + t) * c;
            y += w * c.y;
        }
    }
    sum / y
}

/// The chromaticity `(x, y) = (X, Y) / (X + Y + Z)`, or `None` when `X + Y + Z` is not
/// positive (black has no chromaticity).
pub fn chromaticity(xyz: DVec3) -> Option<DVec2> {
    let sum = xyz.x + xyz.y + xyz.z;
    (sum > 0.0).then(|| DVec2::new(xyz.x / sum, xyz.y / sum))
}

/// The chromaticities of the sRGB (ITU-R BT.709) primaries red, green, blue.
pub const SRGB_PRIMARIES: [DVec2; 3] = [
    DVec2::new(0.64, 0.33),
    DVec2::new(0.30, 0.60),
    DVec2::new(0.15, 0.06),
];

/// The chromaticity of the sRGB white point, D65 as IEC 61966-2-1 rounds it.
pub const SRGB_WHITE: DVec2 = DVec2::new(0.3127, 0.3290);

// ANCHOR: rgb_to_xyz
/// The matrix taking linear RGB with the given primaries to XYZ, scaled so that RGB
/// (1, 1, 1) maps to the white point with `Y = 1`. Each column is a primary's XYZ
/// `(x/y, 1, (1 − x − y)/y)`, times the factor that makes the columns sum to the white.
pub fn rgb_to_xyz_matrix(primaries: [DVec2; 3], white: DVec2) -> DMat3 {
    let xyz_of = |c: DVec2| DVec3::new(c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y);
    let m = DMat3::from_cols(
        xyz_of(primaries[0]),
        xyz_of(primaries[1]),
        xyz_of(primaries[2]),
    );
    let scale = m.inverse() * xyz_of(white);
    DMat3::from_cols(m.x_axis * scale.x, m.y_axis * scale.y, m.z_axis * scale.z)
}
// ANCHOR_END: rgb_to_xyz

fn srgb_matrices() -> &'static (DMat3, DMat3) {
    static M: OnceLock<(DMat3, DMat3)> = OnceLock::new();
    M.get_or_init(|| {
        let to_xyz = rgb_to_xyz_matrix(SRGB_PRIMARIES, SRGB_WHITE);
        (to_xyz, to_xyz.inverse())
    })
}

/// Linear sRGB to XYZ (white (1, 1, 1) ↦ D65 with `Y = 1`).
pub fn linear_srgb_to_xyz(rgb: DVec3) -> DVec3 {
    srgb_matrices().0 * rgb
}

// ANCHOR: to_srgb
/// XYZ to linear sRGB. Colours outside the sRGB gamut get negative components; they stay
/// negative here and are only dealt with at display time (*From spectrum to display*).
pub fn xyz_to_linear_srgb(xyz: DVec3) -> DVec3 {
    srgb_matrices().1 * xyz
}
// ANCHOR_END: to_srgb

/// The XYZ → linear sRGB matrix itself (for figures and for comparison with IEC 61966-2-1).
pub fn xyz_to_linear_srgb_matrix() -> DMat3 {
    srgb_matrices().1
}

/// M. Krystek, *An algorithm to calculate correlated colour temperature*, Color Research
/// and Application 10(1), 38-40 (1985): a rational approximation of the Planckian locus,
/// the chromaticity of a blackbody at `t` kelvin (1000 K to 15 000 K), in CIE 1960 `(u, v)`
/// converted to `(x, y)` by `x = 3u / (2u - 8v + 4)`, `y = 2v / (2u - 8v + 4)`. A published
/// fit, independent of this module's integrals: the colour chapter checks the exact
/// Planckian chromaticities against it.
pub fn krystek(t: f64) -> DVec2 {
    let u = (0.860_117_757 + 1.541_182_54e-4 * t + 1.286_412_12e-7 * t * t)
        / (1.0 + 8.424_202_35e-4 * t + 7.081_451_63e-7 * t * t);
    let v = (0.317_398_726 + 4.228_062_45e-5 * t + 4.204_816_91e-8 * t * t)
        / (1.0 - 2.897_418_16e-5 * t + 1.614_560_53e-7 * t * t);
    let d = 2.0 * u - 8.0 * v + 4.0;
    DVec2::new(3.0 * u / d, 2.0 * v / d)
}
