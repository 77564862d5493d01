//! The surfaces of a scene laid out for fast intersection. Chapter: *The path
//! tracer* (`chapters/renderer/path-tracer.md`, *Speed against error*).
//!
//! [`super::scene::Scene::intersect`] is the book's form: a loop over the shapes and the
//! lights, each matched by kind. Most of a path's time goes there, so the renderer traces
//! through a [`Tracer`], made once per render, which keeps every parallelogram (shape or
//! light) in flat arrays of its plane and dual basis (the same numbers
//! [`crate::geometry::parallelogram::Parallelogram::hit_before`] uses, by the same
//! formulas), a box's walls, whose normal and edges lie along the axes, in the cheaper
//! form of `AxisQuad`, and every sphere in another array. It finds the same first
//! surface as the book's loop at the same distance to within rounding (but for rays that
//! graze a parallelogram's edge to within rounding): `tests/book/renderer/render/tracer.rs`
//! compares the two on many rays.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

use glam::DVec3;

use super::scene::{Geometry, Hit, LightShape, Material, Scene, Surface};
use crate::geometry::Ray;
use crate::geometry::parallelogram::Parallelogram;
use crate::geometry::sphere::{Sphere, intersect_stable};
use crate::spectral::spectrum::{Dense, Spectrum, WholeNm};

/// The parallelograms of a scene, one array per number: plane `n . p = plane`, corner
/// `c`, the edges across scaled by the area, `-e2 / A` and `e1 / A`, that read the edge
/// coordinates off `(o - c) x d` ([`crate::geometry::parallelogram::Parallelogram`]).
#[derive(Clone, Debug, Default)]
struct Quads {
    n: Vec<DVec3>,
    plane: Vec<f64>,
    corner: Vec<DVec3>,
    across_a: Vec<DVec3>,
    across_b: Vec<DVec3>,
    surface: Vec<Surface>,
}

impl Quads {
    /// The hit of the ray from `o` along `d` with parallelogram `i`, if nearer than
    /// `nearest` ([`Parallelogram::hit_before`]'s test on the arrays' numbers).
    #[inline]
    fn hit(&self, i: usize, o: DVec3, d: DVec3, nearest: f64) -> Option<f64> {
        let n = self.n[i];
        let nd = n.dot(d);
        let t = (self.plane[i] - n.dot(o)) / nd;
        if !(t > 0.0 && t < nearest && t.is_finite()) {
            return None;
        }
        let s = (o - self.corner[i]).cross(d);
        let (a, b) = (s.dot(self.across_a[i]) / nd, s.dot(self.across_b[i]) / nd);
        ((0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b)).then_some(t)
    }
}

// ANCHOR: axis_quad
/// One of the three axes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Axis {
    X,
    Y,
    Z,
}

impl Axis {
    /// The axis of `v` if `v` lies along one (exactly one non-zero component).
    fn of(v: DVec3) -> Option<Axis> {
        match (v.x != 0.0, v.y != 0.0, v.z != 0.0) {
            (true, false, false) => Some(Axis::X),
            (false, true, false) => Some(Axis::Y),
            (false, false, true) => Some(Axis::Z),
            _ => None,
        }
    }

    /// The component of `v` along this axis.
    #[inline]
    fn of_vec(self, v: DVec3) -> f64 {
        match self {
            Axis::X => v.x,
            Axis::Y => v.y,
            Axis::Z => v.z,
        }
    }
}

/// A parallelogram whose normal and edges lie along the axes (a wall of a box): the plane
/// `p[k] = at`, and the box `lo <= p <= hi` around the rectangle (infinite along `k`). The
/// ray meets the plane at `t = (at - o[k]) / d[k]` (the general form's `t`: the normal is
/// `e_k` exactly), and is inside when `o + t d` is inside the box: comparisons instead of
/// two dot products.
#[derive(Clone, Copy, Debug, PartialEq)]
struct AxisQuad {
    k: Axis,
    at: f64,
    lo: DVec3,
    hi: DVec3,
    surface: Surface,
}

impl AxisQuad {
    /// The axis-aligned form of `q`, if it has one: its normal and both edges along axes.
    /// Those are three different axes, since a [`Parallelogram`] is never degenerate (its
    /// edges are not parallel, and its normal is their cross product's direction).
    fn of(q: &Parallelogram, surface: Surface) -> Option<Self> {
        let [e1, e2] = q.edges();
        let (k, _, _) = (Axis::of(q.normal())?, Axis::of(e1)?, Axis::of(e2)?);
        let (c, far) = (q.corner(), q.corner() + e1 + e2);
        let unbounded = |v: DVec3, inf: f64| match k {
            Axis::X => DVec3::new(inf, v.y, v.z),
            Axis::Y => DVec3::new(v.x, inf, v.z),
            Axis::Z => DVec3::new(v.x, v.y, inf),
        };
        Some(AxisQuad {
            k,
            at: k.of_vec(c),
            lo: unbounded(c.min(far), f64::NEG_INFINITY),
            hi: unbounded(c.max(far), f64::INFINITY),
            surface,
        })
    }

    /// The hit of the ray from `o` along `d`, `inv_d` the reciprocals of its direction's
    /// components (computed once per ray: a multiplication per wall instead of a
    /// division; `t` may then differ from the general form's in the last bit). A NaN or
    /// infinite `t` fails the comparisons with `0` and `nearest`.
    #[inline]
    fn hit(&self, o: DVec3, d: DVec3, inv_d: DVec3, nearest: f64) -> Option<f64> {
        let t = (self.at - self.k.of_vec(o)) * self.k.of_vec(inv_d);
        if !(t > 0.0 && t < nearest) {
            return None;
        }
        let p = o + t * d;
        (p.cmpge(self.lo) & p.cmple(self.hi)).all().then_some(t)
    }
}
// ANCHOR_END: axis_quad

/// A spectrum as the tracer reads it: a table with whole-nanometre knots in its dense
/// form ([`Dense`], the same function read by index), anything else as it is.
#[derive(Clone, Debug)]
enum Lookup {
    Dense(Dense),
    As(Spectrum),
}

impl Lookup {
    fn of(s: &Spectrum) -> Self {
        match s {
            Spectrum::Table(t) => {
                Dense::of_table(t).map_or_else(|| Lookup::As(s.clone()), Lookup::Dense)
            }
            other => Lookup::As(other.clone()),
        }
    }

    /// The values at every wavelength of `nm` (one match for all of them; a dense table
    /// read from each wavelength's whole-nanometre split).
    #[inline]
    fn eval_all<const K: usize>(&self, nm: &[WholeNm; K]) -> [f64; K] {
        let mut out = [0.0; K];
        match self {
            Lookup::Dense(d) => {
                for (o, &w) in out.iter_mut().zip(nm) {
                    *o = d.eval_whole(w);
                }
            }
            Lookup::As(s) => {
                for (o, w) in out.iter_mut().zip(nm) {
                    *o = s.eval(w.nm);
                }
            }
        }
        out
    }
}

/// Whether rays are being counted ([`count_rays`]); off unless the figure job asks.
static COUNTING: AtomicBool = AtomicBool::new(false);
/// The rays traced while counting.
static RAYS: AtomicU64 = AtomicU64::new(0);

/// Starts counting the rays (closest-hit and shadow) traced through any [`Tracer`], from
/// zero, and returns the count of the previous period: the figure job's estimate of the
/// renderer's limit divides by it. A load and a predictable branch per ray while off.
pub fn count_rays(on: bool) -> u64 {
    COUNTING.store(on, Ordering::Relaxed);
    RAYS.swap(0, Ordering::Relaxed)
}

/// A scene's surfaces for tracing, and the scene.
#[derive(Clone, Debug)]
pub struct Tracer<'a> {
    /// The scene (materials, lights, settings).
    pub scene: &'a Scene,
    /// The reflectance of each material (`None` for those that are not Lambertian).
    reflectance: Vec<Option<Lookup>>,
    /// The emission of each light.
    emission: Vec<Lookup>,
    axis_quads: Vec<AxisQuad>,
    quads: Quads,
    spheres: Vec<(Sphere, Surface)>,
}

impl<'a> Tracer<'a> {
    /// The tracer of `scene`: its shapes, then its lights, in the scene's order.
    pub fn new(scene: &'a Scene) -> Self {
        let mut quads = Quads::default();
        let mut axis_quads = Vec::new();
        let mut spheres = Vec::new();
        let mut add_quad = |q: &Parallelogram, s| {
            if let Some(a) = AxisQuad::of(q, s) {
                axis_quads.push(a);
                return;
            }
            let (n, plane, across_a, across_b) = q.plane_and_across();
            quads.n.push(n);
            quads.plane.push(plane);
            quads.corner.push(q.corner());
            quads.across_a.push(across_a);
            quads.across_b.push(across_b);
            quads.surface.push(s);
        };
        for (i, s) in scene.shapes.iter().enumerate() {
            match &s.geometry {
                Geometry::Quad(q) => add_quad(q, Surface::Shape(i)),
                Geometry::Sphere(sp) => spheres.push((*sp, Surface::Shape(i))),
            }
        }
        for (i, l) in scene.lights.iter().enumerate() {
            match &l.shape {
                LightShape::Quad(q) => add_quad(q.shape(), Surface::Light(i)),
                LightShape::Sphere(sp) => {
                    spheres.push((Sphere::new(sp.center(), sp.radius()), Surface::Light(i)))
                }
            }
        }
        Tracer {
            scene,
            reflectance: scene
                .materials
                .iter()
                .map(|m| match m {
                    Material::Lambert { reflectance } => Some(Lookup::of(reflectance)),
                    _ => None,
                })
                .collect(),
            emission: scene
                .lights
                .iter()
                .map(|l| Lookup::of(&l.emission))
                .collect(),
            axis_quads,
            quads,
            spheres,
        }
    }

    /// How many of the scene's parallelograms take the axis-aligned form (`AxisQuad`), of
    /// how many: a box's walls should all take it (the renderer's tests check that the
    /// `cornell` box's do, since the general form gives the same hits, only slower).
    pub fn axis_aligned_quads(&self) -> (usize, usize) {
        let n = self.axis_quads.len();
        (n, n + self.quads.n.len())
    }

    /// The reflectance of material `m` (a Lambertian one) at the wavelengths `nm` (each
    /// with its [`WholeNm`] split): its spectrum's values, read from the dense form where
    /// it has one.
    #[inline]
    pub fn reflectance<const K: usize>(&self, m: usize, nm: &[WholeNm; K]) -> [f64; K] {
        match &self.reflectance[m] {
            Some(r) => r.eval_all(nm),
            None => [0.0; K],
        }
    }

    /// The emission of light `k` at the wavelengths `nm`, likewise.
    #[inline]
    pub fn emission<const K: usize>(&self, k: usize, nm: &[WholeNm; K]) -> [f64; K] {
        self.emission[k].eval_all(nm)
    }

    /// The first surface along the ray from `o` in the unit direction `d`.
    pub fn intersect(&self, o: DVec3, d: DVec3) -> Option<Hit> {
        self.intersect_before(o, d, f64::INFINITY)
    }

    /// The first surface along the ray nearer than `t_max` ([`Scene::intersect_before`],
    /// the same answer).
    #[inline]
    pub fn intersect_before(&self, o: DVec3, d: DVec3, t_max: f64) -> Option<Hit> {
        count_ray();
        let inv_d = DVec3::ONE / d;
        let mut nearest = t_max;
        let mut hit = None;
        for a in &self.axis_quads {
            if let Some(t) = a.hit(o, d, inv_d, nearest) {
                nearest = t;
                hit = Some(Hit {
                    t,
                    surface: a.surface,
                });
            }
        }
        let q = &self.quads;
        let mut best = usize::MAX;
        for i in 0..q.n.len() {
            if let Some(t) = q.hit(i, o, d, nearest) {
                nearest = t;
                best = i;
            }
        }
        if best != usize::MAX {
            hit = Some(Hit {
                t: nearest,
                surface: q.surface[best],
            });
        }
        let ray = Ray::new(o, d);
        for (sphere, surface) in &self.spheres {
            if let Some(t) = intersect_stable(&ray, sphere, 0.0).filter(|&t| t > 0.0 && t < nearest)
            {
                nearest = t;
                hit = Some(Hit {
                    t,
                    surface: *surface,
                });
            }
        }
        hit
    }

    // ANCHOR: occluded
    /// Whether any surface lies along the ray nearer than `t_max`: the shadow ray's
    /// question, `self.intersect_before(o, d, t_max).is_some()` (the same answer, a test
    /// checks it), answered at the first surface found instead of the nearest one. The
    /// spheres go first, since in a box they are what blocks a shadow ray, and a ray that
    /// nothing blocks is tested against every surface, as before.
    #[inline]
    pub fn occluded(&self, o: DVec3, d: DVec3, t_max: f64) -> bool {
        count_ray();
        let ray = Ray::new(o, d);
        let before = |t: f64| t > 0.0 && t < t_max;
        if self
            .spheres
            .iter()
            .any(|(sphere, _)| intersect_stable(&ray, sphere, 0.0).is_some_and(before))
        {
            return true;
        }
        let q = &self.quads;
        if (0..q.n.len()).any(|i| q.hit(i, o, d, t_max).is_some()) {
            return true;
        }
        let inv_d = DVec3::ONE / d;
        self.axis_quads
            .iter()
            .any(|a| a.hit(o, d, inv_d, t_max).is_some())
    }
    // ANCHOR_END: occluded
}

/// Counts one ray if [`count_rays`] is on.
#[inline]
fn count_ray() {
    if COUNTING.load(Ordering::Relaxed) {
        RAYS.fetch_add(1, Ordering::Relaxed);
    }
}
