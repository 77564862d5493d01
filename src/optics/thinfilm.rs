//! Thin-film interference: the Airy sum of the multiple reflections inside one film.
//!
//! Chapter: *Thin-film interference* (`chapters/optics/thinfilm.md`); tests:
//! `tests/book/optics/thinfilm.rs`.
//!
//! Three media: the ambient (index `n1`, where the light comes from), the film (`n2`,
//! thickness `d`) and the substrate (`n3`). All indices are real (lossless media); the
//! cosines of the angles inside the film and the substrate are complex, so that total
//! internal reflection and evanescent (frustrated) waves come out of the same formulas.
//!
//! The reflected and transmitted amplitudes are the Airy sums of the multiple reflections
//! ([`airy_r`], [`airy_t`]); [`Film::response`] evaluates the same sums rearranged
//! ([`airy_stable`]), which keeps its accuracy near the film's critical angle, where the
//! plain sums cancel.
//!
//! Conventions: time dependence `exp(−iωt)`, so an evanescent wave `exp(i k z cos θ)` decays
//! when `Im cos θ > 0`; Fresnel amplitude coefficients as in Born & Wolf (`r_p` and `r_s`
//! have opposite signs at normal incidence). Wavelengths in nm, angles in radians.

use std::f64::consts::PI;

use glam::DVec3;
use num_complex::Complex64;

use crate::spectral::{cie, spectrum};

/// A single film between two half-spaces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Film {
    /// Index of the ambient medium (the light arrives from here).
    pub n1: f64,
    /// Index of the film.
    pub n2: f64,
    /// Index of the substrate.
    pub n3: f64,
    /// Thickness of the film (nm).
    pub thickness_nm: f64,
}

/// Amplitude and power coefficients of a film at one wavelength and angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Response {
    /// Amplitude reflection coefficient, s polarisation (electric field ⊥ plane of incidence).
    pub r_s: Complex64,
    /// Amplitude reflection coefficient, p polarisation (electric field in the plane).
    pub r_p: Complex64,
    /// Amplitude transmission coefficient into the substrate, s.
    pub t_s: Complex64,
    /// Amplitude transmission coefficient into the substrate, p.
    pub t_p: Complex64,
    /// Reflectance `|r_s|²`.
    pub reflectance_s: f64,
    /// Reflectance `|r_p|²`.
    pub reflectance_p: f64,
    /// Transmittance (power into the substrate over incident power), s.
    pub transmittance_s: f64,
    /// Transmittance, p.
    pub transmittance_p: f64,
}

impl Response {
    /// Reflectance of unpolarised light: the mean of s and p.
    pub fn reflectance(&self) -> f64 {
        0.5 * (self.reflectance_s + self.reflectance_p)
    }

    /// Transmittance of unpolarised light: the mean of s and p.
    pub fn transmittance(&self) -> f64 {
        0.5 * (self.transmittance_s + self.transmittance_p)
    }
}

// ANCHOR: cosine
/// `cos θ` in a medium of index `n`, for light arriving from the ambient (index `n1`) at
/// `cos θ1`. Snell's invariant `n1 sin θ1 = n sin θ` gives
/// `cos² θ = 1 − (n1/n)² sin² θ1 = (1 − ρ)(1 + ρ) + (ρ cos θ1)²` with `ρ = n1/n`: written
/// from `cos θ1` so that a medium of the ambient's index gets exactly `cos θ1`, and with
/// the difference factored so that nothing cancels but the physics. The branch is
/// `Re ≥ 0, Im ≥ 0`: real below the critical angle, `+i·sqrt(sin²θ − 1)` above it, so
/// that the wave `exp(i k z cos θ)` decays away from the interface.
pub fn cos_theta(n1: f64, cos1: f64, n: f64) -> Complex64 {
    let rho = n1 / n;
    let c2 = (1.0 - rho) * (1.0 + rho) + (rho * cos1).powi(2);
    if c2 >= 0.0 {
        Complex64::new(c2.sqrt(), 0.0)
    } else {
        Complex64::new(0.0, (-c2).sqrt())
    }
}
// ANCHOR_END: cosine

/// Fresnel amplitude coefficients of one interface, `a → b`, for both polarisations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interface {
    /// Reflection, s.
    pub r_s: Complex64,
    /// Reflection, p.
    pub r_p: Complex64,
    /// Transmission, s.
    pub t_s: Complex64,
    /// Transmission, p.
    pub t_p: Complex64,
}

// ANCHOR: fresnel
/// Fresnel amplitude coefficients from medium `a` (index `na`, cosine `ca`) into medium
/// `b` (Born & Wolf §1.5.2):
///
/// `r_s = (na ca − nb cb) / (na ca + nb cb)`, `t_s = 2 na ca / (na ca + nb cb)`,
/// `r_p = (nb ca − na cb) / (nb ca + na cb)`, `t_p = 2 na ca / (nb ca + na cb)`.
///
/// Two media of the same index form no interface (`r = 0`, `t = 1`), also at the
/// grazing angle where both cosines vanish and the formulas would give 0/0.
pub fn interface(na: f64, ca: Complex64, nb: f64, cb: Complex64) -> Interface {
    if na == nb {
        let (zero, one) = (Complex64::new(0.0, 0.0), Complex64::new(1.0, 0.0));
        return Interface {
            r_s: zero,
            r_p: zero,
            t_s: one,
            t_p: one,
        };
    }
    let (a, b) = (ca * na, cb * nb); // n cos θ on each side
    let (a_p, b_p) = (ca * nb, cb * na); // the crossed products of p
    Interface {
        r_s: (a - b) / (a + b),
        r_p: (a_p - b_p) / (a_p + b_p),
        t_s: 2.0 * a / (a + b),
        t_p: 2.0 * a / (a_p + b_p),
    }
}
// ANCHOR_END: fresnel

// ANCHOR: phase
/// The one-way phase thickness of the film, `δ = 2π n2 d cos θ2 / λ`. A round trip
/// (down and up) adds `2δ`; complex when the wave in the film is evanescent.
pub fn phase(n2: f64, thickness_nm: f64, cos2: Complex64, wavelength_nm: f64) -> Complex64 {
    cos2 * (2.0 * PI * n2 * thickness_nm / wavelength_nm)
}
// ANCHOR_END: phase

// ANCHOR: airy
// EXERCISE optics/thinfilm airy_r: the Airy sum of the film's multiply reflected waves, in closed form
/// The Airy sum of the multiply reflected waves:
///
/// `r = r12 + t12 t21 r23 e^{2iδ} Σ_k (r21 r23 e^{2iδ})^k = (r12 + r23 e^{2iδ}) / (1 + r12 r23 e^{2iδ})`,
///
/// using `r21 = −r12` and `t12 t21 = 1 − r12²` (Stokes).
pub fn airy_r(r12: Complex64, r23: Complex64, delta: Complex64) -> Complex64 {
    let z = (2.0 * Complex64::i() * delta).exp();
    (r12 + r23 * z) / (1.0 + r12 * r23 * z)
}
// END EXERCISE

/// The transmitted amplitude: one pass `t12 t23 e^{iδ}`, then the same geometric series,
/// `t = t12 t23 e^{iδ} / (1 + r12 r23 e^{2iδ})`.
pub fn airy_t(
    r12: Complex64,
    r23: Complex64,
    t12: Complex64,
    t23: Complex64,
    delta: Complex64,
) -> Complex64 {
    let i = Complex64::i();
    t12 * t23 * (i * delta).exp() / (1.0 + r12 * r23 * (2.0 * i * delta).exp())
}
// ANCHOR_END: airy

// ANCHOR: stable
/// The Airy sum rearranged so that nothing cancels. With admittances `a = n cos θ` (s) or
/// `a = cos θ / n` (p), every Fresnel coefficient is `r_ij = (a_i − a_j)/(a_i + a_j)`;
/// substituting, and multiplying numerator and denominator by
/// `(a1 + a2)(a2 + a3) e^{−iδ} / (2 a2)`:
///
/// `r = [(a1 − a3) cos δ + i (a2² − a1 a3) S] / [(a1 + a3) cos δ − i (a2² + a1 a3) S]`,
/// `t = 2 a1 / [(a1 + a3) cos δ − i (a2² + a1 a3) S]` (times `n1/n3` for p),
///
/// where `S = sin δ / a2 = K sin δ / δ`, `K = k d` (s) or `k n2² d` (p), `k = 2π/λ`.
/// Returns `(r, t)` for one polarisation; `a` are the three admittances.
pub fn airy_stable(a: [Complex64; 3], k_factor: f64, delta: Complex64) -> (Complex64, Complex64) {
    let [a1, a2, a3] = a;
    let (cos, sinc) = scaled_cos_sinc(delta);
    let s = sinc * k_factor;
    let i = Complex64::i();
    let den = (a1 + a3) * cos - i * (a2 * a2 + a1 * a3) * s;
    let num = (a1 - a3) * cos + i * (a2 * a2 - a1 * a3) * s;
    let t = 2.0 * a1 * (-delta.im.abs()).exp() / den;
    (num / den, t)
}

/// `cos δ` and `sin δ / δ`, both times `e^{−|Im δ|}` (the common factor cancels from `r`
/// and is restored in `t`): a thick evanescent film has `|Im δ|` in the thousands, and
/// `cos δ` alone would overflow. `sin δ / δ` is taken from its series near 0.
fn scaled_cos_sinc(delta: Complex64) -> (Complex64, Complex64) {
    let (x, y) = (delta.re, delta.im);
    let e = (-2.0 * y.abs()).exp();
    let (ch, sh) = (0.5 * (1.0 + e), 0.5 * (1.0 - e) * y.signum()); // cosh, sinh × e^{−|y|}
    let (sx, cx) = x.sin_cos();
    let cos = Complex64::new(cx * ch, -sx * sh);
    let sin = Complex64::new(sx * ch, cx * sh);
    let sinc = if delta.norm() < 1e-3 {
        let d2 = delta * delta;
        (1.0 - d2 / 6.0 + d2 * d2 / 120.0) * (-y.abs()).exp()
    } else {
        sin / delta
    };
    (cos, sinc)
}
// ANCHOR_END: stable

impl Film {
    /// A film of index `n2` and thickness `thickness_nm` between `n1` and `n3`.
    pub fn new(n1: f64, n2: f64, n3: f64, thickness_nm: f64) -> Self {
        Self {
            n1,
            n2,
            n3,
            thickness_nm,
        }
    }

    /// Reflection and transmission at `wavelength_nm`, for light arriving from the ambient
    /// at `theta1` (rad) from the normal. See [`Self::response_cos`].
    ///
    /// # Panics
    /// If `theta1` is outside `[0, π/2]`, or as [`Self::response_cos`].
    pub fn response(&self, wavelength_nm: f64, theta1: f64) -> Response {
        assert!(
            (0.0..=PI / 2.0).contains(&theta1),
            "angle of incidence {theta1} outside [0, π/2]"
        );
        self.response_cos(wavelength_nm, theta1.cos())
    }

    // ANCHOR: response
    /// Reflection and transmission at `wavelength_nm`, for light arriving from the ambient
    /// with `cos θ1 = cos1` (as a renderer has it, from a dot product).
    ///
    /// # Panics
    /// If an index or the wavelength is not positive, the thickness is negative, or
    /// `cos1` is outside `[0, 1]`.
    pub fn response_cos(&self, wavelength_nm: f64, cos1: f64) -> Response {
        let Self { n1, n2, n3, .. } = *self;
        let d = self.thickness_nm;
        assert!(
            n1 > 0.0 && n2 > 0.0 && n3 > 0.0 && wavelength_nm > 0.0 && d >= 0.0,
            "film {self:?} at {wavelength_nm} nm: indices and wavelength must be positive, the thickness non-negative"
        );
        assert!(
            (0.0..=1.0).contains(&cos1),
            "cos θ1 = {cos1} outside [0, 1]"
        );
        if cos1 == 0.0 {
            return grazing();
        }
        let c1 = Complex64::new(cos1, 0.0);
        let (c2, c3) = (cos_theta(n1, cos1, n2), cos_theta(n1, cos1, n3));
        let delta = phase(n2, d, c2, wavelength_nm);
        let k = 2.0 * PI / wavelength_nm;
        let (r_s, t_s) = airy_stable([c1 * n1, c2 * n2, c3 * n3], k * d, delta);
        let (r_p, t_p) = airy_stable([c1 / n1, c2 / n2, c3 / n3], k * n2 * n2 * d, delta);
        let t_p = t_p * (n1 / n3); // with a = cos θ / n the form gives (n3/n1) t_p
        // Power: the normal component of the Poynting vector, Re(n cos θ) |E|² on each side.
        // The ratio is taken last: |t|² ∝ cos²θ1 underflows to 0 for a subnormal cos θ1,
        // where Re(n3 cos θ3) / (n1 cos θ1) is already ∞ (and ∞ · 0 = NaN).
        let (flux, incident) = ((c3 * n3).re, n1 * cos1);
        Response {
            r_s,
            r_p,
            t_s,
            t_p,
            reflectance_s: r_s.norm_sqr(),
            reflectance_p: r_p.norm_sqr(),
            transmittance_s: flux * t_s.norm_sqr() / incident,
            transmittance_p: flux * t_p.norm_sqr() / incident,
        }
    }
    // ANCHOR_END: response

    /// Unpolarised reflectance at `wavelength_nm` and `theta1`.
    pub fn reflectance(&self, wavelength_nm: f64, theta1: f64) -> f64 {
        self.response(wavelength_nm, theta1).reflectance()
    }
}

/// Grazing incidence (`cos θ1 = 0`): every wave is reflected, `r_s = r_p = −1`.
fn grazing() -> Response {
    let (one, zero) = (Complex64::new(1.0, 0.0), Complex64::new(0.0, 0.0));
    Response {
        r_s: -one,
        r_p: -one,
        t_s: zero,
        t_p: zero,
        reflectance_s: 1.0,
        reflectance_p: 1.0,
        transmittance_s: 0.0,
        transmittance_p: 0.0,
    }
}

// ---------------------------------------------------------------------------------------
// The source notes' formula, kept to show what it gets wrong.

// ANCHOR: seed
/// Reflectance exactly as the source notes write it: real cosines `sqrt(1 − sin²θ)`, the
/// s-polarised Fresnel coefficients for all light, the round-trip phase
/// `φ = 4π n2 d cos θ2 / λ`, and
/// `R = (r12² + r23² + 2 r12 r23 cos φ) / (1 + r12² r23² − 2 r12 r23 cos φ)`.
/// Wrong: see the chapter (the sign in the denominator, NaN beyond a critical angle,
/// s polarisation only).
pub fn seed_reflectance(film: &Film, wavelength_nm: f64, theta1: f64) -> f64 {
    let Film { n1, n2, n3, .. } = *film;
    let d = film.thickness_nm;
    let sin1 = theta1.sin();
    let cos1 = (1.0 - sin1 * sin1).sqrt();
    let sin2 = n1 / n2 * sin1;
    let cos2 = (1.0 - sin2 * sin2).sqrt();
    let sin3 = n2 / n3 * sin2;
    let cos3 = (1.0 - sin3 * sin3).sqrt();
    let r12 = (n1 * cos1 - n2 * cos2) / (n1 * cos1 + n2 * cos2);
    let r23 = (n2 * cos2 - n3 * cos3) / (n2 * cos2 + n3 * cos3);
    let phi = 4.0 * PI * n2 * d * cos2 / wavelength_nm;
    (r12 * r12 + r23 * r23 + 2.0 * r12 * r23 * phi.cos())
        / (1.0 + r12 * r12 * r23 * r23 - 2.0 * r12 * r23 * phi.cos())
}
// ANCHOR_END: seed

// ANCHOR: quarter_wave
/// Reflectance of a quarter-wave film (`n2 d = λ/4`) at normal incidence, where
/// `e^{2iδ} = −1`: `R = ((n1 n3 − n2²) / (n1 n3 + n2²))²`.
pub fn quarter_wave_reflectance(n1: f64, n2: f64, n3: f64) -> f64 {
    ((n1 * n3 - n2 * n2) / (n1 * n3 + n2 * n2)).powi(2)
}
// ANCHOR_END: quarter_wave

/// Reflectance of a thick film whose fringes are averaged out (incoherent sum of the
/// multiple reflections): `R = (R12 + R23 − 2 R12 R23) / (1 − R12 R23)`, for one
/// polarisation with interface reflectances `R12`, `R23`.
pub fn incoherent_reflectance(r12: f64, r23: f64) -> f64 {
    (r12 + r23 - 2.0 * r12 * r23) / (1.0 - r12 * r23)
}

// ANCHOR: film_colour
/// The colour of the light a film reflects at normal incidence under daylight: the XYZ of
/// `R(λ) D65(λ)`, relative to the XYZ of D65 itself (so a perfect mirror has `Y = 1`),
/// in linear sRGB. Chapters *Thin-film interference* and *Spectra and CIE colour*.
pub fn film_colour(film: &Film) -> DVec3 {
    let d65 = spectrum::builtin("cie_illuminant_D65.csv");
    let white = cie::xyz(|nm| d65.eval(nm)).y;
    let xyz = cie::xyz(|nm| film.reflectance(nm, 0.0) * d65.eval(nm)) / white;
    cie::xyz_to_linear_srgb(xyz)
}
// ANCHOR_END: film_colour
