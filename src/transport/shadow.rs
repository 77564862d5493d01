//! Shadow-ray pdfs: sampling area lights and converting the density from area to solid
//! angle. Chapter: *Shadow-ray pdfs* (`chapters/transport/shadow.md`).
//!
//! A point `q` drawn on a light with density `p_A` per unit area, seen from `p`, is the
//! direction `w = (q - p) / r` with `r = |q - p|`, drawn with density per steradian
//!
//! `p_w = p_A r^2 / |n . w|`,
//!
//! where `n` is the light's normal at `q`. The source notes write `n . w` without the absolute
//! value; for a light that faces `p` that dot product is *negative*, and the pdf with it.
//!
//! Two lights: a parallelogram ([`QuadLight`], one-sided, on the geometry's
//! [`Parallelogram`], which also intersects rays) and a sphere ([`SphereLight`], sampled
//! uniformly over the cap visible from `p`, or uniformly over the cone of directions it
//! subtends, [`SphereCone`]). Every light can be sampled ([`Light::sample`])
//! and asked the pdf of a direction ([`Light::pdf`], by casting the ray). On top of them:
//! irradiance estimators with light sampling, cosine-weighted sampling, and multiple
//! importance sampling ([`estimate_irradiance`]), and the closed forms they are checked
//! against ([`triangle_solid_angle`], [`polygon_irradiance`], [`sphere_irradiance`]).

use std::f64::consts::{FRAC_1_PI, PI, TAU};
use std::fmt;

use glam::{DVec2, DVec3};

use crate::geometry::Ray;
use crate::geometry::parallelogram::{Degenerate, Parallelogram};
use crate::geometry::sphere::{Sphere, intersect_stable};
use crate::sampling::cosine::cosine_malley;
use crate::sampling::frame::Frame;

/// Why a light could not be built.
#[derive(Clone, Debug, PartialEq)]
pub enum LightError {
    /// An input is NaN or infinite.
    NonFinite(&'static str),
    /// An edge of a parallelogram has zero length.
    ZeroLengthEdge(&'static str),
    /// The two edges of a parallelogram are parallel: the light has no area.
    ParallelEdges,
    /// The radius of a sphere is zero, negative or not finite.
    BadRadius(f64),
    /// The edges of a light that must be a rectangle are not perpendicular: the cosine of
    /// their angle (chapter *Sampling a rectangle by solid angle*).
    NotRectangle(f64),
}

impl fmt::Display for LightError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite(what) => write!(f, "the light's {what} is not finite"),
            Self::ZeroLengthEdge(which) => {
                write!(f, "edge {which} of the parallelogram light has zero length")
            }
            Self::ParallelEdges => write!(
                f,
                "the edges of the parallelogram light are parallel: it has no area"
            ),
            Self::BadRadius(r) => write!(
                f,
                "the sphere light's radius {r} is not a positive finite number"
            ),
            Self::NotRectangle(c) => write!(
                f,
                "the light's edges are not perpendicular (the cosine of their angle is {c:e}): \
                 only a rectangle can be sampled by solid angle"
            ),
        }
    }
}

impl std::error::Error for LightError {}

/// A point sampled on a light, as seen from the shading point `p`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// The point `q` on the light.
    pub point: DVec3,
    /// The unit direction `w = (q - p) / r`.
    pub dir: DVec3,
    /// The distance `r = |q - p|`.
    pub dist: f64,
    /// The density of `dir`, per steradian.
    pub pdf: f64,
    /// `n . w`, the light's normal at `q` against the direction *towards* the light (the
    /// source notes' convention): negative when the light faces `p`.
    pub cos_light: f64,
}

// ANCHOR: seen_from
impl LightSample {
    /// The sample at `point` (unit normal `normal`, area density `pdf_area`) as seen from
    /// `p`: its direction, distance and density per steradian. `None` when `p` lies on the
    /// light or the density is zero (an edge-on point).
    pub fn seen_from(p: DVec3, point: DVec3, normal: DVec3, pdf_area: f64) -> Option<Self> {
        let v = point - p;
        let dist = v.length();
        if dist.is_nan() || dist <= 0.0 {
            return None;
        }
        let dir = v / dist;
        let cos_light = normal.dot(dir);
        let pdf = area_to_solid_angle(pdf_area, dist, cos_light);
        (pdf > 0.0).then_some(LightSample {
            point,
            dir,
            dist,
            pdf,
            cos_light,
        })
    }
}
// ANCHOR_END: seen_from

/// Where a ray from `p` first meets a light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightHit {
    /// Distance along the unit direction.
    pub dist: f64,
    /// `n . w` at the hit (negative when the light faces `p`).
    pub cos_light: f64,
}

// ANCHOR: area_to_solid_angle
// EXERCISE transport/shadow area_to_solid_angle: a density per unit area turned into one per steradian, 0 seen edge-on
/// The change of variables from area to solid angle: a density `pdf_area` per unit area
/// at a point at distance `dist`, whose normal makes `n . w = cos_light` with the
/// direction towards it, is the density `pdf_area dist^2 / |cos_light|` per steradian.
///
/// The absolute value is the point: a light facing the shading point has `n . w < 0`.
/// Seen exactly edge-on (`cos_light = 0`) a patch subtends no solid angle and the
/// density is infinite; that happens with probability zero, and 0 is returned so that
/// callers skip the sample instead of dividing by infinity (as pbrt does).
pub fn area_to_solid_angle(pdf_area: f64, dist: f64, cos_light: f64) -> f64 {
    let pdf = pdf_area * dist * dist / cos_light.abs();
    if pdf.is_finite() { pdf } else { 0.0 }
}
// END EXERCISE
// ANCHOR_END: area_to_solid_angle

/// A light that can be sampled from a point and hit by a ray.
pub trait Light: Sync {
    /// A sampled point and direction for the shading point `p`, from `u` in the unit
    /// square; `None` when the light cannot be seen from `p` at all (`p` on or inside it,
    /// or edge-on).
    fn sample(&self, p: DVec3, u: DVec2) -> Option<LightSample>;
    /// The first point where the ray `p + t w` (`w` of unit length, `t > 0`) meets the light.
    fn hit(&self, p: DVec3, w: DVec3) -> Option<LightHit>;
    /// The density per steradian with which [`Light::sample`] draws the unit direction `w`
    /// (0 where it never does).
    fn pdf(&self, p: DVec3, w: DVec3) -> f64;
}

/// A parallelogram light: the [`Parallelogram`] `corner + a e1 + b e2`, `a, b` in
/// `[0, 1]`, emitting on the side of its normal `n = (e1 x e2) / |e1 x e2|` only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadLight {
    shape: Parallelogram,
    /// The area density of a uniform point, `1 / area`.
    pdf_area: f64,
}

impl From<Degenerate> for LightError {
    fn from(e: Degenerate) -> Self {
        match e {
            Degenerate::NonFinite(what) => Self::NonFinite(what),
            Degenerate::ZeroLengthEdge(which) => Self::ZeroLengthEdge(which),
            Degenerate::ParallelEdges => Self::ParallelEdges,
        }
    }
}

impl From<Parallelogram> for QuadLight {
    /// The parallelogram as a light, emitting on the side of its normal.
    fn from(shape: Parallelogram) -> Self {
        Self {
            pdf_area: 1.0 / shape.area(),
            shape,
        }
    }
}

// ANCHOR: quad_new
impl QuadLight {
    /// The parallelogram light with a corner and two edge vectors
    /// ([`Parallelogram::new`]).
    ///
    /// # Errors
    /// [`LightError::NonFinite`] for a NaN or infinite input, [`LightError::ZeroLengthEdge`]
    /// for a zero edge, [`LightError::ParallelEdges`] when `|e1 x e2|` is below `1e-12`
    /// of `|e1| |e2|` (the edges' angle below about `1e-12` radians).
    pub fn new(corner: DVec3, e1: DVec3, e2: DVec3) -> Result<Self, LightError> {
        Ok(Parallelogram::new(corner, e1, e2)?.into())
    }
    // ANCHOR_END: quad_new

    /// The light's shape.
    pub fn shape(&self) -> &Parallelogram {
        &self.shape
    }

    /// The four corners, counter-clockwise about the normal.
    pub fn vertices(&self) -> [DVec3; 4] {
        self.shape.vertices()
    }

    /// The unit normal, the side the light emits towards.
    pub fn normal(&self) -> DVec3 {
        self.shape.normal()
    }

    /// The area `|e1 x e2|`.
    pub fn area(&self) -> f64 {
        self.shape.area()
    }

    /// The same light scaled by `s` about the origin.
    pub fn scaled(&self, s: f64) -> Result<Self, LightError> {
        Ok(self.shape.scaled(s)?.into())
    }

    /// The subtended solid angle seen from `p` (both sides count), as two triangles
    /// by [`triangle_solid_angle`].
    pub fn solid_angle(&self, p: DVec3) -> f64 {
        let [a, b, c, d] = self.vertices().map(|v| v - p);
        triangle_solid_angle(a, b, c) + triangle_solid_angle(a, c, d)
    }

    /// Irradiance at `p` on a surface of unit normal `n` from radiance `radiance`
    /// emitted on the normal's side, by Lambert's formula ([`polygon_irradiance`]).
    /// The light must lie entirely above the surface's horizon. 0 when `p` is behind it.
    pub fn irradiance(&self, p: DVec3, n: DVec3, radiance: f64) -> f64 {
        if (p - self.shape.corner()).dot(self.normal()) <= 0.0 {
            return 0.0;
        }
        polygon_irradiance(p, n, &self.vertices(), radiance)
    }
}

// ANCHOR: quad_sample
impl Light for QuadLight {
    /// Uniform in area (`p_A = 1 / area`), converted to solid angle.
    fn sample(&self, p: DVec3, u: DVec2) -> Option<LightSample> {
        let point = self.shape.point(u.x, u.y);
        LightSample::seen_from(p, point, self.normal(), self.pdf_area)
    }
    // ANCHOR_END: quad_sample

    // ANCHOR: quad_hit
    /// The parallelogram's intersection ([`Parallelogram::hit`]), with `n . w` at the hit.
    fn hit(&self, p: DVec3, w: DVec3) -> Option<LightHit> {
        let dist = self.shape.hit(p, w)?;
        Some(LightHit {
            dist,
            cos_light: self.normal().dot(w),
        })
    }

    fn pdf(&self, p: DVec3, w: DVec3) -> f64 {
        self.hit(p, w).map_or(0.0, |h| {
            area_to_solid_angle(self.pdf_area, h.dist, h.cos_light)
        })
    }
    // ANCHOR_END: quad_hit
}

/// A spherical light, emitting outwards everywhere on its surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereLight {
    center: DVec3,
    radius: f64,
}

impl SphereLight {
    /// The sphere of centre `center` and radius `radius`.
    ///
    /// # Errors
    /// [`LightError::NonFinite`] for a non-finite centre, [`LightError::BadRadius`] for a
    /// radius that is not a positive finite number.
    pub fn new(center: DVec3, radius: f64) -> Result<Self, LightError> {
        if !center.is_finite() {
            return Err(LightError::NonFinite("centre"));
        }
        if !(radius > 0.0 && radius.is_finite()) {
            return Err(LightError::BadRadius(radius));
        }
        Ok(Self { center, radius })
    }

    /// The centre.
    pub fn center(&self) -> DVec3 {
        self.center
    }

    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The same light scaled by `s` about the origin.
    pub fn scaled(&self, s: f64) -> Result<Self, LightError> {
        Self::new(self.center * s, self.radius * s)
    }

    /// Whether `p` lies outside the sphere, the only points its light reaches (it emits
    /// outwards only): where [`Light::sample`] gives a point and [`Light::pdf`] a density.
    pub fn is_outside(&self, p: DVec3) -> bool {
        self.outside(p).is_some()
    }

    /// `(d, 1 - R/d)` for the shading point `p` at distance `d` from the centre, or
    /// `None` when `p` is on or inside the sphere.
    fn outside(&self, p: DVec3) -> Option<(f64, f64)> {
        let d = (p - self.center).length();
        (d > self.radius).then(|| (d, (d - self.radius) / d))
    }

    /// `1 - cos(theta_max)` for the cone of directions from `p`, with
    /// `sin(theta_max) = R / d`, computed as `s^2 / (1 + sqrt(1 - s^2))` without
    /// cancellation for small lights.
    pub fn one_minus_cos_max(&self, p: DVec3) -> Option<f64> {
        let (d, _) = self.outside(p)?;
        let s2 = (self.radius / d).powi(2);
        Some(s2 / (1.0 + (1.0 - s2).max(0.0).sqrt()))
    }

    /// The subtended solid angle `2 pi (1 - cos theta_max)` (0 from inside).
    pub fn solid_angle(&self, p: DVec3) -> f64 {
        self.one_minus_cos_max(p).map_or(0.0, |h| TAU * h)
    }

    /// The area of the cap visible from `p`, `2 pi R^2 (1 - R/d)`.
    pub fn visible_area(&self, p: DVec3) -> f64 {
        self.outside(p)
            .map_or(0.0, |(_, h)| TAU * self.radius * self.radius * h)
    }

    fn cast(&self, p: DVec3, w: DVec3) -> Option<LightHit> {
        let sphere = Sphere::new(self.center, self.radius);
        let t = intersect_stable(&Ray::new(p, w), &sphere, 0.0)?;
        let n = (p + t * w - self.center) / self.radius;
        Some(LightHit {
            dist: t,
            cos_light: -n.dot(w).abs(),
        })
    }
}

// ANCHOR: sphere_sample
impl Light for SphereLight {
    /// Uniform in area over the cap visible from `p`: around the axis `(p - C) / d`, the
    /// cap's polar angle has `cos(alpha)` uniform in `[R/d, 1]`, so
    /// `p_A = 1 / (2 pi R^2 (1 - R/d))`. Sampling the whole sphere instead would put more
    /// than half of the points, the fraction `(1 + R/d) / 2`, outside the visible cap, where
    /// a shadow ray is blocked.
    fn sample(&self, p: DVec3, u: DVec2) -> Option<LightSample> {
        let (d, h) = self.outside(p)?;
        let axis = (p - self.center) / d;
        let one_minus_cos = u.x * h;
        let cos_a = 1.0 - one_minus_cos;
        let sin_a = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
        let phi = TAU * u.y;
        let local = DVec3::new(sin_a * phi.cos(), sin_a * phi.sin(), cos_a);
        let normal = Frame::from_normal(axis).to_world(local);
        let point = self.center + self.radius * normal;
        let pdf_area = 1.0 / (TAU * self.radius * self.radius * h);
        LightSample::seen_from(p, point, normal, pdf_area)
    }
    // ANCHOR_END: sphere_sample

    fn hit(&self, p: DVec3, w: DVec3) -> Option<LightHit> {
        self.outside(p)?;
        self.cast(p, w)
    }

    fn pdf(&self, p: DVec3, w: DVec3) -> f64 {
        let Some((_, h)) = self.outside(p) else {
            return 0.0;
        };
        self.cast(p, w).map_or(0.0, |hit| {
            let pdf_area = 1.0 / (TAU * self.radius * self.radius * h);
            area_to_solid_angle(pdf_area, hit.dist, hit.cos_light)
        })
    }
}

/// A sphere light sampled uniformly over the cone of directions it subtends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereCone(pub SphereLight);

// ANCHOR: cone_sample
impl Light for SphereCone {
    /// `cos(theta)` uniform in `[cos(theta_max), 1]` around the direction to the centre:
    /// `p_w = 1 / (2 pi (1 - cos theta_max))`, the same for every direction of the cone.
    /// The point is where the direction meets the sphere; a direction that grazes it and
    /// misses by rounding takes the point of closest approach.
    fn sample(&self, p: DVec3, u: DVec2) -> Option<LightSample> {
        let light = &self.0;
        let h = light.one_minus_cos_max(p)?;
        let to_center = light.center - p;
        let axis = to_center / to_center.length();
        let one_minus_cos = u.x * h;
        let sin_t = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
        let phi = TAU * u.y;
        let local = DVec3::new(sin_t * phi.cos(), sin_t * phi.sin(), 1.0 - one_minus_cos);
        let dir = Frame::from_normal(axis).to_world(local);
        let hit = light.cast(p, dir).unwrap_or_else(|| {
            let t = dir.dot(to_center);
            let n = (p + t * dir - light.center).normalize_or_zero();
            LightHit {
                dist: t,
                cos_light: -n.dot(dir).abs(),
            }
        });
        Some(LightSample {
            point: p + hit.dist * dir,
            dir,
            dist: hit.dist,
            pdf: 1.0 / (TAU * h),
            cos_light: hit.cos_light,
        })
    }
    // ANCHOR_END: cone_sample

    fn hit(&self, p: DVec3, w: DVec3) -> Option<LightHit> {
        self.0.hit(p, w)
    }

    fn pdf(&self, p: DVec3, w: DVec3) -> f64 {
        match (self.0.one_minus_cos_max(p), self.0.cast(p, w)) {
            (Some(h), Some(_)) => 1.0 / (TAU * h),
            _ => 0.0,
        }
    }
}

// ANCHOR: closed_forms
/// The solid angle of the triangle with vertices `a, b, c` (relative to the viewpoint),
/// by Van Oosterom and Strackee (1983):
/// `tan(Omega / 2) = |a . (b x c)| / (abc + (a.b) c + (a.c) b + (b.c) a)`,
/// with `a = |a|` and so on; `atan2` keeps the right branch when the denominator is
/// negative (solid angles above `pi`).
pub fn triangle_solid_angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let num = a.dot(b.cross(c)).abs();
    let den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    2.0 * num.atan2(den)
}

/// Lambert's formula for the irradiance at `p` (unit normal `n`) from a polygon of
/// uniform radiance: `E = (L / 2) |sum_i Gamma_i . n|`, with
/// `Gamma_i = theta_i (v_i x v_{i+1}) / |v_i x v_{i+1}|`, `v_i` the unit vectors to the
/// vertices and `theta_i` the angle between consecutive ones. The polygon must lie
/// entirely above the horizon of `n` (clip it first otherwise).
pub fn polygon_irradiance(p: DVec3, n: DVec3, vertices: &[DVec3], radiance: f64) -> f64 {
    let k = vertices.len();
    let mut sum = 0.0;
    for i in 0..k {
        let vi = (vertices[i] - p).normalize();
        let vj = (vertices[(i + 1) % k] - p).normalize();
        let c = vi.cross(vj);
        let theta = c.length().atan2(vi.dot(vj));
        if c.length() > 0.0 {
            sum += theta * c.normalize().dot(n);
        }
    }
    0.5 * radiance * sum.abs()
}

/// Irradiance at `p` (unit normal `n`) from a sphere of uniform radiance seen entirely
/// above the horizon: `E = L pi sin^2(theta_max) cos(theta)`, `sin(theta_max) = R / d`,
/// `theta` the angle between `n` and the direction to the centre.
pub fn sphere_irradiance(p: DVec3, n: DVec3, light: &SphereLight, radiance: f64) -> f64 {
    let v = light.center() - p;
    let d = v.length();
    radiance * PI * (light.radius() / d).powi(2) * n.dot(v / d)
}
// ANCHOR_END: closed_forms

/// How to weight two sampling strategies in multiple importance sampling.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Heuristic {
    /// `w_a = p_a / (p_a + p_b)`.
    Balance,
    /// `w_a = p_a^2 / (p_a^2 + p_b^2)`.
    Power,
}

impl Heuristic {
    /// The weight of a sample drawn with density `pa` when the other strategy would have
    /// drawn it with density `pb` (0 when both are 0).
    ///
    /// Computed from the ratio `r <= 1` of the smaller density to the larger, as
    /// `q / (1 + q)` or `1 / (1 + q)` with `q = r` or `r^2`: written as `pa^2 / (pa^2 + pb^2)`
    /// the power heuristic is NaN once the squares overflow (densities above about
    /// `1.3e154`, a tiny light seen edge-on) and 0 where they underflow, and the balance
    /// heuristic is 0 where the sum overflows.
    pub fn weight(self, pa: f64, pb: f64) -> f64 {
        let (small, large) = if pa <= pb { (pa, pb) } else { (pb, pa) };
        if !(large > 0.0 && small >= 0.0) {
            return 0.0;
        }
        let r = small / large;
        let q = match self {
            Self::Balance => r,
            Self::Power => r * r,
        };
        let of_large = 1.0 / (1.0 + q);
        if pa <= pb { q * of_large } else { of_large }
    }
}

/// How to estimate the irradiance at a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IrradianceStrategy {
    /// Sample the light (one sample).
    Light,
    /// Sample the cosine-weighted hemisphere and cast the ray (one sample).
    Bsdf,
    /// One sample of each, weighted.
    Mis(Heuristic),
}

// ANCHOR: estimate
/// A one-sample (two for MIS) estimate of the irradiance at `p`, unit normal `n`, from a
/// light of uniform radiance `radiance` (emitted where the light faces `p`:
/// `cos_light < 0`). `u_light` drives the light sample, `u_bsdf` the cosine sample.
/// Lights below the horizon or facing away contribute 0, never NaN.
pub fn estimate_irradiance(
    light: &dyn Light,
    p: DVec3,
    n: DVec3,
    radiance: f64,
    strategy: IrradianceStrategy,
    u_light: DVec2,
    u_bsdf: DVec2,
) -> f64 {
    let mut e = 0.0;
    if strategy != IrradianceStrategy::Bsdf
        && let Some(s) = light.sample(p, u_light)
    {
        let cos = n.dot(s.dir);
        if cos > 0.0 && s.cos_light < 0.0 {
            let w = match strategy {
                IrradianceStrategy::Mis(h) => h.weight(s.pdf, cos * FRAC_1_PI),
                _ => 1.0,
            };
            e += w * radiance * cos / s.pdf;
        }
    }
    if strategy != IrradianceStrategy::Light {
        let local = cosine_malley(u_bsdf);
        let dir = Frame::from_normal(n).to_world(local);
        let pdf = local.z * FRAC_1_PI;
        if pdf > 0.0
            && let Some(hit) = light.hit(p, dir)
            && hit.cos_light < 0.0
        {
            let w = match strategy {
                IrradianceStrategy::Mis(h) => h.weight(pdf, light.pdf(p, dir)),
                _ => 1.0,
            };
            e += w * radiance * local.z / pdf;
        }
    }
    e
}
// ANCHOR_END: estimate
