//! RGB to spectrum: the reflectance of a colour given in sRGB, by the sigmoid-polynomial
//! model of Jakob and Hanika, "A Low-Dimensional Function Space for Efficient Spectral
//! Upsampling" (Eurographics 2019). Chapter: *From RGB to spectrum*
//! (`chapters/spectral/upsample.md`).
//!
//! A reflectance is `r(λ) = S(c₀ t² + c₁ t + c₂)` with `t = (λ − 360) / (830 − 360)` and the
//! algebraic sigmoid `S(x) = 1/2 + x / (2 √(1 + x²))`, which stays strictly inside (0, 1)
//! mathematically (in floating point it rounds to 0 or 1 for huge `|x|`).
//! The three coefficients are found per colour by Levenberg-Marquardt on the CIE 1976 colour
//! difference ΔE between the target colour and the colour of `r` under D65:
//! `XYZ = ∫ r D65 (x̄, ȳ, z̄) dλ / ∫ D65 ȳ dλ`.

use std::sync::OnceLock;

use glam::{DMat3, DVec3};

use super::display::lab;
use super::spectrum::{self, Spectrum, Table};
use super::{LAMBDA_MAX, LAMBDA_MIN, cie};

// ANCHOR: sigmoid
/// The algebraic sigmoid `S(x) = 1/2 + x / (2 √(1 + x²))`: from 0 at −∞ to 1 at +∞, never
/// reaching either mathematically; in floating point it rounds to exactly 1 (or 0) once
/// `|x|` passes about 10⁸. `hypot` keeps `√(1 + x²)` finite for huge `x`, and the infinities,
/// where `x / hypot` would be `∞ / ∞`, give the limits 0 and 1.
pub fn sigmoid(x: f64) -> f64 {
    if x.is_infinite() {
        return if x > 0.0 { 1.0 } else { 0.0 };
    }
    0.5 + 0.5 * x / x.hypot(1.0)
}

/// `S'(x) = 1 / (2 (1 + x²)^(3/2))`.
pub fn sigmoid_derivative(x: f64) -> f64 {
    let h = x.hypot(1.0);
    0.5 / (h * h * h)
}

/// The wavelength `nm` mapped to `t ∈ [0, 1]` over 360-830 nm (keeps the fit well
/// conditioned: the coefficients in nm would differ by a factor 10⁵ in size).
pub fn unit_wavelength(nm: f64) -> f64 {
    (nm - LAMBDA_MIN) / (LAMBDA_MAX - LAMBDA_MIN)
}
// ANCHOR_END: sigmoid

/// A reflectance spectrum from [`upsample`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reflectance {
    /// The same value at every wavelength (black, white).
    Constant(f64),
    /// `S(c[0] t² + c[1] t + c[2])`, `t` = [`unit_wavelength`].
    Sigmoid([f64; 3]),
}

impl Reflectance {
    /// The reflectance at wavelength `nm`, in [0, 1].
    pub fn eval(&self, nm: f64) -> f64 {
        match *self {
            Reflectance::Constant(v) => v,
            Reflectance::Sigmoid(c) => {
                let t = unit_wavelength(nm);
                sigmoid((c[0] * t + c[1]) * t + c[2])
            }
        }
    }

    /// The reflectance as a renderer [`Spectrum`]: a 1 nm table over 360-830 nm (the
    /// constant cases stay constant).
    pub fn to_spectrum(&self) -> Spectrum {
        match *self {
            Reflectance::Constant(v) => Spectrum::Constant(v),
            Reflectance::Sigmoid(_) => {
                let nm: Vec<f64> = (0..cie::CMF_ROWS).map(|i| LAMBDA_MIN + i as f64).collect();
                let values = nm.iter().map(|&l| self.eval(l)).collect();
                Spectrum::Table(Table::new(nm, values).expect("finite values in [0, 1]"))
            }
        }
    }
}

/// A colour that cannot be upsampled.
#[derive(Clone, Debug, PartialEq)]
pub struct UpsampleError(pub String);

impl std::fmt::Display for UpsampleError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for UpsampleError {}

/// The result of a fit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit {
    /// The reflectance.
    pub reflectance: Reflectance,
    /// The CIE 1976 ΔE between the target and the reflectance's colour under the
    /// fitter's illuminant.
    pub delta_e: f64,
    /// Levenberg-Marquardt iterations used.
    pub iterations: u32,
}

/// The fit stops when ΔE is below this (far below a just-noticeable difference, about 1–2.3).
pub const DELTA_E_GOAL: f64 = 1e-3;

// ANCHOR: fitter
/// The colour of a reflectance under one illuminant, on a 1 nm grid: `XYZ = Σ wᵢ r(λᵢ)` with
/// `wᵢ = E(λᵢ) (x̄, ȳ, z̄)(λᵢ) Δλᵢ / Σ E ȳ Δλ` (trapezoid weights), so that `r = 1` has
/// `Y = 1`.
pub struct Fitter {
    t: Vec<f64>,
    w: Vec<DVec3>,
}

impl Fitter {
    /// A fitter for the illuminant `e` (a function of nm).
    pub fn new(e: impl Fn(f64) -> f64) -> Fitter {
        let n = cie::CMF_ROWS;
        let mut w: Vec<DVec3> = (0..n)
            .map(|i| {
                let nm = LAMBDA_MIN + i as f64;
                let trapezoid = if i == 0 || i == n - 1 { 0.5 } else { 1.0 };
                trapezoid * e(nm) * cie::cmf_row(i)
            })
            .collect();
        let y: f64 = w.iter().map(|v| v.y).sum();
        w.iter_mut().for_each(|v| *v /= y);
        let t = (0..n)
            .map(|i| unit_wavelength(LAMBDA_MIN + i as f64))
            .collect();
        Fitter { t, w }
    }

    /// The fitter under CIE D65 (`data/cie_illuminant_D65.csv`), built once.
    pub fn d65() -> &'static Fitter {
        static F: OnceLock<Fitter> = OnceLock::new();
        F.get_or_init(|| {
            let d65 = spectrum::builtin("cie_illuminant_D65.csv");
            Fitter::new(|nm| d65.eval(nm))
        })
    }

    /// The XYZ of the reflectance `r` under this illuminant.
    pub fn xyz(&self, r: &Reflectance) -> DVec3 {
        let sum: DVec3 = self
            .t
            .iter()
            .zip(&self.w)
            .map(|(&t, &w)| w * r.eval(LAMBDA_MIN + t * (LAMBDA_MAX - LAMBDA_MIN)))
            .sum();
        sum
    }

    /// XYZ of the sigmoid with coefficients `c` and its Jacobian `∂XYZ/∂c` (columns).
    fn xyz_and_jacobian(&self, c: [f64; 3]) -> (DVec3, DMat3) {
        let (mut xyz, mut j) = (DVec3::ZERO, [DVec3::ZERO; 3]);
        for (&t, &w) in self.t.iter().zip(&self.w) {
            let x = (c[0] * t + c[1]) * t + c[2];
            // S and S' share √(1 + x²); `hypot` only where x² would overflow.
            let h = if x.abs() < 1e150 {
                (1.0 + x * x).sqrt()
            } else {
                x.hypot(1.0)
            };
            xyz += w * (0.5 + 0.5 * x / h);
            let d = w * (0.5 / (h * h * h));
            j[0] += d * (t * t);
            j[1] += d * t;
            j[2] += d;
        }
        (xyz, DMat3::from_cols(j[0], j[1], j[2]))
    }
    // ANCHOR_END: fitter

    // ANCHOR: fit
    /// Upsamples linear sRGB `rgb` (components in [0, 1]) to a reflectance whose colour under
    /// this illuminant matches `linear_srgb_to_xyz(rgb)`. Black and white are the constants 0
    /// and 1 (the sigmoid reaches neither). Otherwise Levenberg-Marquardt on the three CIELAB
    /// residuals, from the flat spectrum of the right luminance, stopping at
    /// ΔE < [`DELTA_E_GOAL`]. If 60 iterations do not get there, the fit restarts by
    /// continuation from the grey of the same luminance (the result says how close it got).
    ///
    /// # Errors
    /// If a component is NaN or outside [0, 1]: the message names the component and value.
    pub fn fit(&self, rgb: DVec3) -> Result<Fit, UpsampleError> {
        for (name, v) in ["red", "green", "blue"].iter().zip(rgb.to_array()) {
            if !(0.0..=1.0).contains(&v) {
                return Err(UpsampleError(format!(
                    "{name} = {v} in {rgb}: linear sRGB reflectances must be in [0, 1]"
                )));
            }
        }
        let constant = |v: f64| Fit {
            reflectance: Reflectance::Constant(v),
            delta_e: 0.0,
            iterations: 0,
        };
        if rgb == DVec3::ZERO {
            return Ok(constant(0.0));
        }
        if rgb == DVec3::ONE {
            return Ok(constant(1.0));
        }
        // Start flat at the target's luminance Y: S(c₂) = Y, c₂ = u / √(1 − u²), u = 2Y − 1.
        let y = cie::linear_srgb_to_xyz(rgb).y;
        let u = (2.0 * y - 1.0).clamp(-0.999, 0.999);
        let flat = [0.0, 0.0, u / (1.0 - u * u).sqrt()];
        let (c, delta_e, mut iterations) = self.solve(flat, rgb, DELTA_E_GOAL, 60);
        if delta_e < DELTA_E_GOAL {
            return Ok(Fit {
                reflectance: Reflectance::Sigmoid(c),
                delta_e,
                iterations,
            });
        }
        // Continuation (as Jakob and Hanika build their table): walk from the grey of the
        // same luminance to the target in small steps, each fit starting from the last.
        let mut c = flat;
        let mut delta_e = f64::INFINITY;
        let steps = 32;
        for k in 1..=steps {
            let on_the_way = DVec3::splat(y).lerp(rgb, f64::from(k) / f64::from(steps));
            let goal = if k == steps { DELTA_E_GOAL } else { 0.1 };
            let its;
            (c, delta_e, its) = self.solve(c, on_the_way, goal, 200);
            iterations += its;
        }
        Ok(Fit {
            reflectance: Reflectance::Sigmoid(c),
            delta_e,
            iterations,
        })
    }

    /// Levenberg-Marquardt from the coefficients `c` toward the colour `rgb`, until
    /// ΔE < `goal` or `max_iterations`: (coefficients, ΔE, iterations).
    fn solve(
        &self,
        mut c: [f64; 3],
        rgb: DVec3,
        goal: f64,
        max_iterations: u32,
    ) -> ([f64; 3], f64, u32) {
        let white = cie::linear_srgb_to_xyz(DVec3::ONE);
        let target = lab(cie::linear_srgb_to_xyz(rgb), white);
        let residual = |c: [f64; 3]| -> (DVec3, DMat3) {
            let (xyz, j) = self.xyz_and_jacobian(c);
            (lab(xyz, white) - target, lab_jacobian(xyz, white) * j)
        };
        let (mut r, mut j) = residual(c);
        let mut mu = 1e-3;
        let mut iterations = 0;
        while r.length() >= goal && iterations < max_iterations {
            iterations += 1;
            let jtj = j.transpose() * j;
            let g = j.transpose() * r;
            let diagonal = DVec3::new(jtj.x_axis.x, jtj.y_axis.y, jtj.z_axis.z);
            let damped = jtj + DMat3::from_diagonal(mu * diagonal + DVec3::splat(1e-12));
            let step = -(damped.inverse() * g);
            let trial = [c[0] + step.x, c[1] + step.y, c[2] + step.z];
            let (r2, j2) = residual(trial);
            if r2.is_finite() && r2.length() < r.length() {
                (c, r, j) = (trial, r2, j2);
                mu = (mu / 3.0).max(1e-12);
            } else {
                mu *= 4.0;
                if mu > 1e12 {
                    break;
                }
            }
        }
        (c, r.length(), iterations)
    }
    // ANCHOR_END: fit
}

/// `∂Lab/∂XYZ` (rows L, a, b) at `xyz`, for the white `white`.
fn lab_jacobian(xyz: DVec3, white: DVec3) -> DMat3 {
    const D: f64 = 6.0 / 29.0;
    let df = |t: f64| {
        if t > D * D * D {
            1.0 / (3.0 * t.cbrt() * t.cbrt())
        } else {
            1.0 / (3.0 * D * D)
        }
    };
    let fx = df(xyz.x / white.x) / white.x;
    let fy = df(xyz.y / white.y) / white.y;
    let fz = df(xyz.z / white.z) / white.z;
    // Rows: L = 116 f(Y), a = 500 (f(X) − f(Y)), b = 200 (f(Y) − f(Z)); from_cols takes columns.
    DMat3::from_cols(
        DVec3::new(0.0, 500.0 * fx, 0.0),
        DVec3::new(116.0 * fy, -500.0 * fy, 200.0 * fy),
        DVec3::new(0.0, 0.0, -200.0 * fz),
    )
}

/// Upsamples linear sRGB `rgb` under D65 (see [`Fitter::fit`]).
///
/// # Errors
/// As [`Fitter::fit`].
pub fn upsample(rgb: DVec3) -> Result<Fit, UpsampleError> {
    Fitter::d65().fit(rgb)
}

/// Linear sRGB of the reflectance `r` under D65 by [`cie::xyz`]'s quadrature (4 Gauss
/// points per nm): the XYZ of `r · D65` divided by the Y of D65. Independent of the
/// fitter's own 1 nm trapezoid grid, so the round-trip tests and table use it as the check.
pub fn srgb_under_d65(r: impl Fn(f64) -> f64) -> DVec3 {
    let d65 = spectrum::builtin("cie_illuminant_D65.csv");
    let norm = super::cie::xyz(|nm| d65.eval(nm)).y;
    super::cie::xyz_to_linear_srgb(super::cie::xyz(|nm| r(nm) * d65.eval(nm)) / norm)
}
