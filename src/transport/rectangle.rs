//! A rectangle light sampled uniformly in solid angle, by the area-preserving
//! parametrization of spherical rectangles of Ureña, Fajardo and King (2013, "An
//! Area-Preserving Parametrization for Spherical Rectangles", EGSR). Chapter: *Sampling a
//! rectangle by solid angle* (`chapters/transport/rectangle.md`).
//!
//! Seen from a shading point `p`, a rectangle covers a spherical rectangle of solid angle
//! `Omega`. [`RectangleLight`] draws directions with the constant density `1 / Omega` over
//! it, where [`QuadLight`] draws points uniformly by area and has the density
//! `r^2 / (A |cos theta_l|)`, which varies over the light.
//!
//! In the rectangle's frame (unit edges `x`, `y`, normal `z`), `p` sees the corner at
//! `(x0, y0, z0)` and the rectangle is `[x0, x1] x [y0, y1]` in the plane at height `z0`;
//! `z0` is taken negative (seen from the emitting side it is; the frame's `z` is flipped
//! when `p` is behind the light), so that the formulas hold on both sides. The interior
//! angle of the spherical rectangle at the corner `(x, y, z0)` is `atan2(|z0| r, +-x y)`,
//! `r` that corner's distance, and `Omega` is the sum of the four angles minus `2 pi`
//! (Girard's theorem).
//!
//! The sub-rectangle `[x0, x] x [y0, y1]` keeps the two angles at `x0` and adds two new
//! ones `gamma_b + gamma_t` at `x`: its solid angle is linear in that sum, so drawing the
//! sum uniformly draws `x` with the right marginal; given `x`, the solid angle of the strip
//! below `y` is linear in `h = y / sqrt(x^2 + z0^2 + y^2)`, which is drawn uniformly and
//! inverted for `y`.

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::transport::shadow::{
    Light, LightError, LightHit, LightSample, QuadLight, triangle_solid_angle,
};

/// Below this solid angle (steradians) the light falls back to [`QuadLight`]'s sampling
/// uniform in area, and its pdf with it.
///
/// The sampler maps `u.x` to the sum of two angles through `u Omega + k`, with `k` a sum of
/// two angles near `pi`: each carries a rounding of about `1e-16` absolute, a relative error
/// of about `1e-16 / Omega` in the point's position within the light. At `1e-6` sr that is
/// `1e-10`; far below it the mapping loses its digits (and at `Omega` near `1e-16` it would
/// be noise). Seen edge-on, `N` and `1 - s^2` of [`SphericalRectangle::abscissa`] cancel as
/// well and the error grows like `1e-15 / Omega^2`: about `5e-4` of the solid angle at
/// `1.5e-6` sr. A light that small is seen far away or nearly edge-on, where the area pdf is
/// nearly constant over it anyway or the light contributes almost nothing.
pub const MIN_SOLID_ANGLE: f64 = 1e-6;

/// From this solid angle (steradians) on, `Omega` is taken from Girard's formula, the angles
/// the sampler computes anyway, to a relative `1e-13` or better; below it from two
/// triangles ([`SphericalRectangle::new`]).
pub const GIRARD_FROM: f64 = 1e-2;

/// The largest `|cos|` of the angle between the edges that [`RectangleLight::new`] accepts
/// as perpendicular.
pub const PERPENDICULAR_TOLERANCE: f64 = 1e-9;

// ANCHOR: view
/// The rectangle `[x0, x1] x [y0, y1]` at height `z0 < 0` seen from the origin, in its own
/// frame, prepared for sampling: the solid angle and the constants of the inversion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphericalRectangle {
    /// The rectangle's extent along its first edge.
    pub x0: f64,
    /// The far end along the first edge, `x0 + |e1|`.
    pub x1: f64,
    /// The rectangle's extent along its second edge.
    pub y0: f64,
    /// The far end along the second edge, `y0 + |e2|`.
    pub y1: f64,
    /// The height of the plane, negative.
    pub z0: f64,
    /// The `z` component of the unit normal of the plane through the origin and the edge at
    /// `y0`, `b0 = -y0 / sqrt(y0^2 + z0^2)`, and `b0 - b1` for the one at `y1`,
    /// `b1 = y1 / sqrt(y1^2 + z0^2)` (without cancellation when both are near 1).
    b0: f64,
    b0_minus_b1: f64,
    /// `2 pi` minus the interior angles at the corners `(x0, y0)` and `(x0, y1)`, and at
    /// `(x1, y0)` and `(x1, y1)`: each a sum of two supplements, computed directly (not as
    /// a difference from `2 pi`, which loses them when they are tiny: `p` near the plane).
    k: f64,
    k_end: f64,
    /// The solid angle `Omega`.
    pub omega: f64,
}

/// `pi` minus the interior angle of the spherical rectangle at the corner `(x, y, z0)`.
/// The interior angle's cosine is `c x y / (sqrt(x^2 + z0^2) sqrt(y^2 + z0^2))` (`c = -1` at
/// `(x0, y0)` and `(x1, y1)`, `+1` at the other two) and its sine
/// `|z0| r / (sqrt(x^2 + z0^2) sqrt(y^2 + z0^2))`, `r` the corner's distance: the
/// supplement is `atan2` of the two numerators with the cosine's negated, accurate where
/// `acos` of a cosine near `-1` loses half the digits.
fn corner_supplement(x: f64, y: f64, z0: f64, c: f64) -> f64 {
    let r = (x * x + y * y + z0 * z0).sqrt();
    (z0.abs() * r).atan2(-c * x * y)
}

/// `1 - |y| / sqrt(y^2 + z^2)` without cancellation: `z^2 / (r (r + |y|))`.
fn one_minus_sine(y: f64, z: f64) -> f64 {
    let r = (y * y + z * z).sqrt();
    z * z / (r * (r + y.abs()))
}

impl SphericalRectangle {
    /// The rectangle `[x0, x1] x [y0, y1]` in the plane at height `z0` (either sign; the
    /// frame is flipped for a positive one), seen from the origin. `None` when `z0` is zero
    /// (the origin in the rectangle's plane sees it edge-on) or when the solid angle is below
    /// [`MIN_SOLID_ANGLE`] or not finite.
    ///
    /// The solid angle is Girard's sum of the four angles minus `2 pi`, which loses about
    /// `1e-15 / Omega` of its relative accuracy to the subtraction; below [`GIRARD_FROM`]
    /// it is computed as two triangles by Van Oosterom and Strackee
    /// ([`triangle_solid_angle`]) instead, which keep it (and cost two more `atan2`s and
    /// six square roots: Girard reuses the angles the sampler needs anyway).
    pub fn new(x0: f64, x1: f64, y0: f64, y1: f64, z0: f64) -> Option<Self> {
        if z0 == 0.0 || !z0.is_finite() {
            return None;
        }
        let z0 = -z0.abs();
        let corners = [
            DVec3::new(x0, y0, z0),
            DVec3::new(x1, y0, z0),
            DVec3::new(x1, y1, z0),
            DVec3::new(x0, y1, z0),
        ];
        let k = corner_supplement(x0, y0, z0, -1.0) + corner_supplement(x0, y1, z0, 1.0);
        let k_end = corner_supplement(x1, y0, z0, 1.0) + corner_supplement(x1, y1, z0, -1.0);
        // Girard: the four interior angles sum to 4 pi - k - k_end.
        let girard = TAU - k - k_end;
        let omega = if girard >= GIRARD_FROM {
            girard
        } else {
            let [a, b, c, d] = corners;
            triangle_solid_angle(a, b, c) + triangle_solid_angle(a, c, d)
        };
        if !(omega >= MIN_SOLID_ANGLE && omega.is_finite()) {
            return None;
        }
        let b0 = -y0 / (y0 * y0 + z0 * z0).sqrt();
        let b1 = y1 / (y1 * y1 + z0 * z0).sqrt();
        // Both near 1 when y0 < 0 < y1 and z0 is small: subtract their distances from 1.
        let b0_minus_b1 = if y0 < 0.0 && y1 > 0.0 {
            one_minus_sine(y1, z0) - one_minus_sine(y0, z0)
        } else {
            b0 - b1
        };
        Some(Self {
            x0,
            x1,
            y0,
            y1,
            z0,
            b0,
            b0_minus_b1,
            k,
            k_end,
            omega,
        })
    }
    // ANCHOR_END: view

    // ANCHOR: abscissa
    /// The abscissa `x` in `[x0, x1]` whose sub-rectangle `[x0, x] x [y0, y1]` has the solid
    /// angle `u Omega`.
    ///
    /// The sub-rectangle's angles at `x` sum to `a = u Omega + k`; with `s = x / sqrt(x^2 +
    /// z0^2)` their cosines are `-b0 s` and `-b1 s`, and eliminating one angle gives
    /// `s = sign(N) D / sqrt(N^2 + b0^2 D^2)`, `N = b0 cos a - b1`, `D = sin a` (the paper's
    /// `f = N / D` without dividing by `sin a`, which is 0 at `a = pi`). Then
    /// `x = -z0 s / sqrt(1 - s^2)`. `u` is clamped to `[0, 1]` and `x` to `[x0, x1]`; where
    /// `s` is `+-1` to rounding (`|x|` beyond about `1e8 |z0|`), `1 - s^2` is 0 and the end
    /// on the side of `s` is returned.
    ///
    /// Seen from just above the light (`|z0|` small, `x0 <= 0 <= x1` and `y0 <= 0 <= y1`),
    /// the spherical rectangle is nearly a hemisphere: `a` runs from near 0 at `u = 0` to
    /// near `2 pi` at `u = 1`, and `b0`, `b1` are both near 1. Near either end `cos a` is near
    /// 1, so `N = b0 cos a - b1` is the difference of two numbers near 1 whose true value is
    /// tiny, and its sign, which places `x` at one end or the other, would be rounding. So
    /// `a` is measured from the nearer end (`2 pi - a = (1 - u) Omega + k_end` for
    /// `u > 1/2`), and `N` is computed as `(b0 - b1) - 2 b0 sin^2(a / 2)` from two small
    /// terms, neither a difference of numbers near 1 (`b0 - b1` as `(1 - b1) - (1 - b0)`):
    /// it keeps its sign and its digits. (In the textbook form `N` rounds to 0 for `|z0|`
    /// below a few times `1e-9` of the light's size, about `1.9e-9` for a unit square seen
    /// from above its centre, and `u` within about `1e-9` of an end, and `x` lands at the
    /// wrong end.) `x` itself still loses digits where `s` is near `+-1`, since
    /// `1 - s^2` carries the rounding of 1: a relative error of about
    /// `1e-16 (x^2 + z0^2) / z0^2`, which misplaces `x` only within a strip holding the
    /// fraction `u` (or `1 - u`) of the solid angle. Beside the light near its plane
    /// (`y0 > 0` or `y1 < 0`), `a` is near `pi`, `b0` near -1 and `b1` near 1, and both forms
    /// of `N` cancel alike.
    pub fn abscissa(&self, u: f64) -> f64 {
        let u = u.clamp(0.0, 1.0);
        let (t, sign) = if u <= 0.5 {
            (u * self.omega + self.k, 1.0)
        } else {
            ((1.0 - u) * self.omega + self.k_end, -1.0)
        };
        // a = t or 2 pi - t: sin a = sign sin t, sin(a / 2) = sin(t / 2).
        let d = sign * t.sin();
        let half = (0.5 * t).sin();
        let n = self.b0_minus_b1 - 2.0 * self.b0 * half * half;
        let s = n.signum() * d / (n * n + self.b0 * self.b0 * d * d).sqrt();
        let one_minus_s2 = (1.0 - s) * (1.0 + s);
        let x = if one_minus_s2 > 0.0 {
            -self.z0 * s / one_minus_s2.sqrt()
        } else if s > 0.0 {
            self.x1
        } else {
            self.x0
        };
        if x.is_nan() {
            return self.x0;
        }
        x.clamp(self.x0, self.x1)
    }
    // ANCHOR_END: abscissa

    // ANCHOR: ordinate
    /// The ordinate `y` in `[y0, y1]` at the abscissa `x` below which the strip at `x` has
    /// the fraction `u` of its solid angle.
    ///
    /// The strip `dx` wide at `x` subtends `|z0| dx / d^2 * dh`, `d^2 = x^2 + z0^2`, with
    /// `h = y / sqrt(d^2 + y^2)`: `h` is drawn uniformly between its ends `h0` and `h1` and
    /// inverted, `y = h d / sqrt(1 - h^2)`. Where `1 - h^2` rounds to 0 (a point almost in
    /// the plane, `d` tiny) the end it is nearest is returned; `u` is clamped to `[0, 1]`
    /// and `y` to `[y0, y1]`.
    pub fn ordinate(&self, x: f64, u: f64) -> f64 {
        let d2 = x * x + self.z0 * self.z0;
        let d = d2.sqrt();
        let h0 = self.y0 / (d2 + self.y0 * self.y0).sqrt();
        let h1 = self.y1 / (d2 + self.y1 * self.y1).sqrt();
        let h = h0 + u.clamp(0.0, 1.0) * (h1 - h0);
        let one_minus_h2 = (1.0 - h) * (1.0 + h);
        let y = if one_minus_h2 > 0.0 {
            h * d / one_minus_h2.sqrt()
        } else if h > 0.0 {
            self.y1
        } else {
            self.y0
        };
        if y.is_nan() {
            return self.y0;
        }
        y.clamp(self.y0, self.y1)
    }
    // ANCHOR_END: ordinate

    /// The point `(x, y)` of the rectangle, in its frame, for `u` in the unit square: uniform
    /// in solid angle as seen from the origin.
    pub fn sample(&self, u: DVec2) -> DVec2 {
        let x = self.abscissa(u.x);
        DVec2::new(x, self.ordinate(x, u.y))
    }
}

/// A rectangular light, one-sided like [`QuadLight`] (emitting on the side of
/// `e1 x e2`), sampled uniformly in the solid angle it subtends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RectangleLight {
    quad: QuadLight,
    /// The unit edges and the unit normal `x x y`.
    x: DVec3,
    y: DVec3,
    z: DVec3,
    /// The edges' lengths.
    lx: f64,
    ly: f64,
}

impl TryFrom<QuadLight> for RectangleLight {
    type Error = LightError;

    /// The quad light as a rectangle light, if its edges are perpendicular.
    fn try_from(quad: QuadLight) -> Result<Self, LightError> {
        let [e1, e2] = quad.shape().edges();
        let (lx, ly) = (e1.length(), e2.length());
        let cos = e1.dot(e2) / (lx * ly);
        if cos.abs() > PERPENDICULAR_TOLERANCE {
            return Err(LightError::NotRectangle(cos));
        }
        let (x, y) = (e1 / lx, e2 / ly);
        Ok(Self {
            quad,
            x,
            y,
            z: quad.normal(),
            lx,
            ly,
        })
    }
}

impl RectangleLight {
    /// The rectangle light with a corner and two perpendicular edges.
    ///
    /// # Errors
    /// Those of [`QuadLight::new`], and [`LightError::NotRectangle`] when the cosine of the
    /// edges' angle exceeds [`PERPENDICULAR_TOLERANCE`] in magnitude.
    pub fn new(corner: DVec3, e1: DVec3, e2: DVec3) -> Result<Self, LightError> {
        QuadLight::new(corner, e1, e2)?.try_into()
    }

    /// The same light as a parallelogram sampled by area.
    pub fn quad(&self) -> &QuadLight {
        &self.quad
    }

    /// The light seen from `p` in its own frame, or `None` where it falls back to sampling
    /// by area (`p` in its plane, or a solid angle below [`MIN_SOLID_ANGLE`]).
    pub fn view(&self, p: DVec3) -> Option<SphericalRectangle> {
        let d = self.quad.shape().corner() - p;
        let (x0, y0, z0) = (d.dot(self.x), d.dot(self.y), d.dot(self.z));
        SphericalRectangle::new(x0, x0 + self.lx, y0, y0 + self.ly, z0)
    }
}

// ANCHOR: light
impl Light for RectangleLight {
    /// Uniform in solid angle, `p_w = 1 / Omega`; where [`RectangleLight::view`] is `None`,
    /// [`QuadLight`]'s sample uniform in area (`None` for `p` in the plane). As for
    /// [`QuadLight`], a point behind the light gets samples too, with `cos_light > 0`: the
    /// caller decides emission by the sign.
    fn sample(&self, p: DVec3, u: DVec2) -> Option<LightSample> {
        let Some(view) = self.view(p) else {
            return self.quad.sample(p, u);
        };
        let xy = view.sample(u);
        let a = ((xy.x - view.x0) / self.lx).clamp(0.0, 1.0);
        let b = ((xy.y - view.y0) / self.ly).clamp(0.0, 1.0);
        let point = self.quad.shape().point(a, b);
        let v = point - p;
        let dist = v.length();
        if dist.is_nan() || dist <= 0.0 {
            return None;
        }
        let dir = v / dist;
        Some(LightSample {
            point,
            dir,
            dist,
            pdf: 1.0 / view.omega,
            cos_light: self.z.dot(dir),
        })
    }

    fn hit(&self, p: DVec3, w: DVec3) -> Option<LightHit> {
        self.quad.hit(p, w)
    }

    /// `1 / Omega` for a direction that meets the light, 0 otherwise (the area pdf where
    /// the sampler falls back to it).
    fn pdf(&self, p: DVec3, w: DVec3) -> f64 {
        match self.view(p) {
            Some(view) => self.hit(p, w).map_or(0.0, |_| 1.0 / view.omega),
            None => self.quad.pdf(p, w),
        }
    }
}
// ANCHOR_END: light
