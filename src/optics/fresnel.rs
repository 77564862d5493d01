//! Fresnel reflectance of a dielectric interface, Schlick's approximation, and a fitted
//! polynomial. Chapter: *Fresnel and Schlick* (`chapters/optics/fresnel.md`).
//!
//! # Convention
//!
//! Light travels in the medium of index `n1` and meets the medium of index `n2`.
//! `cos_i` is `|cos theta_i|`, the cosine of the angle between the incident ray and the
//! normal, measured in medium `n1` (its sign is ignored). Reflectances are fractions of
//! the incident *power*; under total internal reflection the reflectance is 1.
//!
//! * [`fresnel_dielectric`]: the exact unpolarised reflectance, `(R_s + R_p) / 2`.
//! * [`fresnel_polarized`] and [`fresnel_transmittance`]: `R_s, R_p` from the reflection
//!   amplitudes and `T_s, T_p` from the *transmission* amplitudes (an independent route to
//!   the same energy balance).
//! * [`schlick`]: Schlick's approximation with the cosine on the less dense side, as it
//!   must be; [`schlick_seed`] is the source notes' version, which uses `cos theta_i` even when
//!   the light leaves the denser medium.
//! * [`FresnelFit`]: a Chebyshev interpolant of degree [`FIT_DEGREE`], built once per
//!   pair of indices: no square root or division (entering the denser medium), and over a
//!   hundred times more accurate than Schlick.
//! * [`approximation_error`]: the worst error of an approximation over an angle sweep.
//!
//! The chapter's checker, which any routine `f(cos_i, n1, n2) -> R` can be run through, is
//! [`crate::check::fresnel`]; its planted bugs are in [`crate::check::fresnel::planted`].

// ANCHOR: cos_t
/// `cos theta_t` from Snell's law, or `None` past the critical angle (total internal
/// reflection). `cos_t^2 = 1 - (n1/n2)^2 sin^2 theta_i`, evaluated as
/// `(1 - eta^2) + (eta cos_i)^2`: for `n1 < n2` a sum of two non-negative terms.
pub fn cos_transmitted(cos_i: f64, n1: f64, n2: f64) -> Option<f64> {
    let (eta, c) = (n1 / n2, cos_i);
    let cos2_t = (1.0 - eta * eta) + (eta * c) * (eta * c);
    (cos2_t >= 0.0).then(|| cos2_t.sqrt())
}
// ANCHOR_END: cos_t

/// `|cos_i|` clamped to at most 1 (a NaN stays NaN, so a bug upstream stays visible).
fn clamp_cos(cos_i: f64) -> f64 {
    let c = cos_i.abs();
    if c > 1.0 { 1.0 } else { c }
}

/// A pair of values for the two polarisations: `s` (electric field perpendicular to the
/// plane of incidence) and `p` (parallel to it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Polarized {
    /// s polarisation.
    pub s: f64,
    /// p polarisation.
    pub p: f64,
}

impl Polarized {
    /// The average of the two: the value for unpolarised light.
    pub fn unpolarized(self) -> f64 {
        0.5 * (self.s + self.p)
    }
}

/// The Fresnel amplitude coefficients of a transmitting interface (no TIR), in Born &
/// Wolf's sign convention: `t_s = 1 + r_s` and `t_p = (n1 / n2)(1 + r_p)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Amplitudes {
    /// `r_s = (n1 cos_i - n2 cos_t) / (n1 cos_i + n2 cos_t)`.
    pub r_s: f64,
    /// `r_p = (n2 cos_i - n1 cos_t) / (n2 cos_i + n1 cos_t)`.
    pub r_p: f64,
    /// `t_s = 2 n1 cos_i / (n1 cos_i + n2 cos_t)`.
    pub t_s: f64,
    /// `t_p = 2 n1 cos_i / (n2 cos_i + n1 cos_t)`.
    pub t_p: f64,
    /// `cos theta_t`.
    pub cos_t: f64,
}

// ANCHOR: amplitudes
// EXERCISE optics/fresnel amplitudes: the Fresnel amplitude coefficients r_s, r_p, t_s, t_p, or None under total internal reflection
/// The amplitude coefficients, or `None` under total internal reflection, in Born & Wolf's
/// sign convention (`r_p = -r_s` at normal incidence; `r_p` changes sign at Brewster's
/// angle).
///
/// Matched indices (`n1 == n2`) form no interface: `r = 0`, `t = 1`, also at grazing
/// incidence, where the formulas would be `0/0`. With different indices, grazing incidence
/// (`cos_i = 0`) from the less dense side needs no special case: `cos_t > 0`, and the
/// formulas give their limit `r_s = r_p = -1`, `t_s = t_p = 0` (from the denser side it is
/// past the critical angle). Both cosines are never 0 together: `cos_t = 0` needs
/// `n1 > n2` and an angle of incidence at the critical angle, where `cos_i > 0`.
pub fn amplitudes(cos_i: f64, n1: f64, n2: f64) -> Option<Amplitudes> {
    let c = clamp_cos(cos_i);
    if n1 == n2 {
        let (r_s, r_p, t_s, t_p) = (0.0, 0.0, 1.0, 1.0);
        return Some(Amplitudes {
            r_s,
            r_p,
            t_s,
            t_p,
            cos_t: c,
        });
    }
    let cos_t = cos_transmitted(c, n1, n2)?;
    let (a, b) = (n1 * c, n2 * cos_t); // the s denominators' terms
    let (d, e) = (n2 * c, n1 * cos_t); // the p denominators' terms
    Some(Amplitudes {
        r_s: (a - b) / (a + b),
        r_p: (d - e) / (d + e),
        t_s: 2.0 * a / (a + b),
        t_p: 2.0 * a / (d + e),
        cos_t,
    })
}
// END EXERCISE
// ANCHOR_END: amplitudes

// ANCHOR: polarized
/// Reflectances `R_s = r_s^2` and `R_p = r_p^2`; both 1 under total internal reflection.
pub fn fresnel_polarized(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    match amplitudes(cos_i, n1, n2) {
        Some(a) => Polarized {
            s: a.r_s * a.r_s,
            p: a.r_p * a.r_p,
        },
        None => Polarized { s: 1.0, p: 1.0 },
    }
}

/// The exact unpolarised reflectance `(R_s + R_p) / 2` of a dielectric interface, for
/// light in medium `n1` meeting medium `n2` at `|cos theta_i| = cos_i`. Total internal
/// reflection gives 1; matched indices give 0 at every angle, grazing included.
pub fn fresnel_dielectric(cos_i: f64, n1: f64, n2: f64) -> f64 {
    fresnel_polarized(cos_i, n1, n2).unpolarized()
}
// ANCHOR_END: polarized

// ANCHOR: transmittance
// EXERCISE optics/fresnel fresnel_transmittance: the transmittances T_s and T_p, 0 under total internal reflection and 1 for matched indices
/// Transmittances from the transmission amplitudes, `T = (n2 cos_t) / (n1 cos_i) t^2`:
/// the factor converts the ratio of field amplitudes into a ratio of powers through the
/// interface (intensity scales with `n`, the beam's cross-section with `cos`).
/// With `a = n1 cos_i` and `b = n2 cos_t` it simplifies to `T_s = 4ab / (a + b)^2`, and
/// with `d = n2 cos_i`, `e = n1 cos_t` to `T_p = 4ab / (d + e)^2`, which never divides by
/// `cos_i`. Both 0 under total internal reflection, both 1 for matched indices.
pub fn fresnel_transmittance(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    if n1 == n2 {
        return Polarized { s: 1.0, p: 1.0 };
    }
    let c = clamp_cos(cos_i);
    let Some(cos_t) = cos_transmitted(c, n1, n2) else {
        return Polarized { s: 0.0, p: 0.0 };
    };
    let (a, b) = (n1 * c, n2 * cos_t);
    let (d, e) = (n2 * c, n1 * cos_t);
    if a + b == 0.0 {
        return Polarized { s: 0.0, p: 0.0 }; // grazing on both sides
    }
    let four_ab = 4.0 * a * b;
    Polarized {
        s: (four_ab / ((a + b) * (a + b))).min(1.0),
        p: (four_ab / ((d + e) * (d + e))).min(1.0),
    }
}
// END EXERCISE
// ANCHOR_END: transmittance

/// Brewster's angle (radians), `atan(n2 / n1)`: there `R_p = 0`.
pub fn brewster_angle(n1: f64, n2: f64) -> f64 {
    (n2 / n1).atan()
}

/// Reflectance at normal incidence, `((n1 - n2) / (n1 + n2))^2`; the same from either side.
pub fn r0(n1: f64, n2: f64) -> f64 {
    let r = (n1 - n2) / (n1 + n2);
    r * r
}

// ANCHOR: schlick
// EXERCISE optics/fresnel schlick: Schlick's approximation, with the cosine on the less dense side
/// Schlick's approximation `R0 + (1 - R0)(1 - cos)^5`, with the cosine of the angle on
/// the *less dense* side: `cos theta_i` entering a denser medium, `cos theta_t` leaving
/// it, and 1 under total internal reflection.
pub fn schlick(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let c = clamp_cos(cos_i);
    let cos = if n1 <= n2 {
        c
    } else {
        match cos_transmitted(c, n1, n2) {
            Some(cos_t) => cos_t,
            None => return 1.0,
        }
    };
    let (r0, x) = (r0(n1, n2), 1.0 - cos);
    let x4 = (x * x) * (x * x);
    r0 + (1.0 - r0) * x4 * x
}
// END EXERCISE
// ANCHOR_END: schlick

// ANCHOR: schlick_seed
/// The source notes' Schlick: `R0 + (1 - R0)(1 - cos theta_i)^5` whichever side the light is on.
/// Leaving a denser medium it ignores the critical angle and is wrong by up to ~0.96.
pub fn schlick_seed(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let r0 = r0(n1, n2);
    let x = 1.0 - clamp_cos(cos_i);
    let x2 = x * x;
    r0 + (1.0 - r0) * x2 * x2 * x
}
// ANCHOR_END: schlick_seed

/// Degree of the polynomial of [`FresnelFit`].
pub const FIT_DEGREE: usize = 8; // `FresnelFit::eval` is written out for degree 8

// ANCHOR: fit
/// The exact reflectance interpolated by a polynomial of degree [`FIT_DEGREE`] in `cos`,
/// at the Chebyshev points (of the second kind: both ends included) of `[0, 1]`
/// (Trefethen, *Approximation Theory and Approximation Practice*, SIAM 2013: the points
/// and coefficients in ch. 2-4, near-best in the maximum norm by ch. 16). Since the ends
/// are nodes, it is exact at normal incidence (`R0`) and at grazing incidence (1).
///
/// Fitted once per pair of indices, on the less dense side; leaving the denser medium it
/// is evaluated at `cos theta_t`, like Schlick, since reflectance is the same from both
/// sides of a transmitting pair of angles. The result is clamped to `[0, 1]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FresnelFit {
    /// Coefficients of the polynomial in `x = 2 cos - 1`, lowest degree first.
    coeffs: [f64; FIT_DEGREE + 1],
    n1: f64,
    n2: f64,
}

impl FresnelFit {
    /// Fits the reflectance of the interface between `n1` and `n2` (either order).
    pub fn new(n1: f64, n2: f64) -> Self {
        const N: usize = FIT_DEGREE + 1;
        let (lo, hi) = if n1 <= n2 { (n1, n2) } else { (n2, n1) };
        // Chebyshev points x_j = cos(theta_j), theta_j = pi j / d, of [-1, 1] (both ends
        // included), mapped to cos = (x + 1) / 2, and the exact reflectance there.
        let theta = |j: usize| std::f64::consts::PI * j as f64 / FIT_DEGREE as f64;
        let values: [f64; N] =
            std::array::from_fn(|j| fresnel_dielectric(0.5 * (theta(j).cos() + 1.0), lo, hi));
        // Chebyshev polynomials as monomial coefficients: T_0 = 1, T_1 = x,
        // T_{k+1} = 2x T_k - T_{k-1}.
        let mut t = [[0.0; N]; N];
        t[0][0] = 1.0;
        t[1][1] = 1.0;
        for k in 1..N - 1 {
            for i in 0..N {
                let shifted = if i > 0 { 2.0 * t[k][i - 1] } else { 0.0 };
                t[k + 1][i] = shifted - t[k - 1][i];
            }
        }
        // Interpolant sum_k a_k T_k with a_k = (2/d) sum''_j f(x_j) cos(k theta_j), where
        // '' halves the first and last terms, and a_0, a_d halved (Trefethen, ch. 3-4).
        let ends = |j: usize| if j == 0 || j == FIT_DEGREE { 0.5 } else { 1.0 };
        let mut coeffs = [0.0; N];
        for (k, t_k) in t.iter().enumerate() {
            let sum: f64 = (0..N)
                .map(|j| ends(j) * values[j] * (k as f64 * theta(j)).cos())
                .sum();
            let a_k = ends(k) * 2.0 * sum / FIT_DEGREE as f64;
            for (c, t_ki) in coeffs.iter_mut().zip(t_k) {
                *c += a_k * t_ki;
            }
        }
        Self { coeffs, n1, n2 }
    }

    /// The approximate reflectance for light in medium `n1` at `|cos theta_i| = cos_i`.
    pub fn eval(&self, cos_i: f64) -> f64 {
        let cos_in = clamp_cos(cos_i);
        let cos = if self.n1 <= self.n2 {
            cos_in
        } else {
            match cos_transmitted(cos_in, self.n1, self.n2) {
                Some(cos_t) => cos_t,
                None => return 1.0,
            }
        };
        // Estrin's scheme: the same polynomial as Horner's rule, but as a tree of depth 4
        // instead of a chain of 8 dependent multiply-adds.
        let c = &self.coeffs;
        let x = 2.0 * cos - 1.0;
        let (x2, x4) = (x * x, x * x * (x * x));
        let low = (c[0] + c[1] * x) + x2 * (c[2] + c[3] * x);
        let high = (c[4] + c[5] * x) + x2 * (c[6] + c[7] * x);
        (low + x4 * (high + x4 * c[8])).clamp(0.0, 1.0)
    }
}
// ANCHOR_END: fit

/// Worst errors of an approximation against [`fresnel_dielectric`] over an angle sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorStats {
    /// Largest `|approx - exact|`.
    pub worst_abs: f64,
    /// Angle of incidence (degrees, in medium `n1`) where it occurs.
    pub worst_abs_deg: f64,
    /// Largest `|approx - exact| / exact`.
    pub worst_rel: f64,
    /// Angle of incidence (degrees) where it occurs.
    pub worst_rel_deg: f64,
}

/// Angles of [`approximation_error`]'s sweep: 0 to 90 degrees in steps of 0.01.
pub const SWEEP_ANGLES: usize = 9001;

// ANCHOR: sweep
/// Sweeps the angle of incidence in medium `n1` over `[0, 90]` degrees (`samples` evenly
/// spaced angles, both ends included, `cos 90° = 0` exactly) and returns the worst absolute
/// and relative errors of `approx(cos_i)` against the exact reflectance.
pub fn approximation_error(
    approx: &dyn Fn(f64) -> f64,
    n1: f64,
    n2: f64,
    samples: usize,
) -> ErrorStats {
    let mut stats = ErrorStats {
        worst_abs: 0.0,
        worst_abs_deg: 0.0,
        worst_rel: 0.0,
        worst_rel_deg: 0.0,
    };
    for k in 0..samples {
        let degrees = 90.0 * k as f64 / (samples - 1) as f64;
        let cos_i = if k + 1 == samples {
            0.0
        } else {
            degrees.to_radians().cos()
        };
        let exact = fresnel_dielectric(cos_i, n1, n2);
        let error = (approx(cos_i) - exact).abs();
        // NaN is never "not worse": it must show in the result.
        if error > stats.worst_abs || error.is_nan() {
            stats.worst_abs = error;
            stats.worst_abs_deg = degrees;
        }
        let relative = error / exact;
        if exact > 0.0 && (relative > stats.worst_rel || relative.is_nan()) {
            stats.worst_rel = relative;
            stats.worst_rel_deg = degrees;
        }
    }
    stats
}
// ANCHOR_END: sweep
