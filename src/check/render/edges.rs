//! Expected images across edges: the pixels a sharp boundary crosses, whose box-filtered
//! values are known in closed form. Chapter: *Testing the renderer*
//! (`chapters/renderer/testing.md`, *Edges*).
//!
//! The exact images of [`mod@super::exact`] leave out every pixel an edge crosses. A mistake
//! in a pixel's footprint (the jitter's distribution, the filter's width) moves a pixel by
//! about half the radiance's change across it, or by its curvature: little where the
//! radiance varies slowly. One that ties the point in the pixel to another sample
//! dimension (the wavelengths drawn from the jitter's number) changes nothing where the
//! radiance does not change across the pixel. At an edge both change the pixel, and there
//! the expected value is computed exactly:
//!
//! * where flat polygons of uniform radiance lie over a uniform background ([`flat`]: two
//!   lights seen directly against black, a coloured Lambertian quad in a constant sky), a
//!   pixel's mean (but where a polygon's corner barely touches it, [`SLIVER_HITS`]) is `sum_k c_k L_k + (1 - sum_k c_k) L_background`, with `c_k` the share
//!   of the pixel's square that polygon `k`'s image covers. A pinhole maps straight lines
//!   to straight lines ([`image_point`] is the camera's inverse), so the image of a
//!   parallelogram is a convex quadrilateral; clipped to the pixel's square
//!   (Sutherland-Hodgman, [`clip`]), its area is the shoelace formula's ([`area`]).
//! * on a floor under horizontal rectangular lights with one horizontal rectangular
//!   occluder between ([`shadow`]), the part of light `k` that a floor point `x` sees is its
//!   rectangle less the occluder's shadow on the light's plane. A central projection
//!   between parallel planes only scales, so that shadow is a rectangle too
//!   ([`occluder_on_light`]), and the irradiance is Lambert's formula for the light less
//!   Lambert's formula for the overlap. The radiance is continuous across a penumbra, with
//!   kinks; its mean over a pixel is a composite rule (the pixel cut into 6 x 6 squares,
//!   each with 4 x 4 Gauss-Legendre points), whose error the tests measure against a rule
//!   twice as fine. The pixels that the occluder's own outline crosses are not tested, nor
//!   those whose lights the renderer's light samples would meet only a handful of times.

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use super::exact::{First, camera_ray, first, rgb};
use super::pool::Expected;
use crate::geometry::parallelogram::Parallelogram;
use crate::render::scene::{CameraSpec, Environment, Geometry, LightShape, Material, Scene};
use crate::spectral::spectrum::Spectrum;
use crate::transport::shadow::polygon_irradiance;

/// Where the point `p` appears in the image of the pinhole camera `c`, in pixels from the
/// image's top-left corner: the inverse of [`camera_ray`]. `None` for a point not in
/// front of the camera.
pub fn image_point(c: &CameraSpec, p: DVec3) -> Option<DVec2> {
    let forward = (c.look_at - c.position).normalize();
    let right = forward.cross(c.up).normalize();
    let top = right.cross(forward);
    let half_height = (c.fov_y_deg.to_radians() * 0.5).tan();
    let half_width = half_height * f64::from(c.width) / f64::from(c.height);
    let v = p - c.position;
    let depth = v.dot(forward);
    if depth.is_nan() || depth <= 0.0 {
        return None;
    }
    let u = v.dot(right) / depth / half_width;
    let w = v.dot(top) / depth / half_height;
    Some(DVec2::new(
        (u + 1.0) * 0.5 * f64::from(c.width),
        (1.0 - w) * 0.5 * f64::from(c.height),
    ))
}

/// The part of the polygon `poly` (its vertices in order) on the side `inside` of a line,
/// where `side(p)` is a signed distance from it: one step of Sutherland-Hodgman.
fn clip_by(poly: &[DVec2], side: impl Fn(DVec2) -> f64) -> Vec<DVec2> {
    let mut out = Vec::with_capacity(poly.len() + 2);
    for (i, &a) in poly.iter().enumerate() {
        let b = poly[(i + 1) % poly.len()];
        let (sa, sb) = (side(a), side(b));
        if sa >= 0.0 {
            out.push(a);
        }
        if (sa >= 0.0) != (sb >= 0.0) {
            out.push(a + (b - a) * (sa / (sa - sb)));
        }
    }
    out
}

/// The polygon `poly` clipped to the convex polygon `window` (counter-clockwise or
/// clockwise, either way): Sutherland-Hodgman, one edge of `window` at a time.
pub fn clip(poly: &[DVec2], window: &[DVec2]) -> Vec<DVec2> {
    let turn = area_signed(window).signum();
    let mut out = poly.to_vec();
    for (i, &a) in window.iter().enumerate() {
        let b = window[(i + 1) % window.len()];
        if out.is_empty() {
            break;
        }
        let e = b - a;
        out = clip_by(&out, |p| turn * e.perp_dot(p - a));
    }
    out
}

/// The signed area of a polygon (positive counter-clockwise in a right-handed plane): the
/// shoelace formula.
fn area_signed(poly: &[DVec2]) -> f64 {
    let n = poly.len();
    0.5 * (0..n)
        .map(|i| poly[i].perp_dot(poly[(i + 1) % n]))
        .sum::<f64>()
}

/// The area of a polygon, whichever its orientation.
pub fn area(poly: &[DVec2]) -> f64 {
    area_signed(poly).abs()
}

/// The share of the pixel `(x, y)` (the unit square from that corner) that the convex
/// polygon `poly` covers. The polygon is moved to the pixel's corner first, so that the
/// clipping works with small numbers; a share within `1e-12` of 0 or 1 (an edge on the
/// pixel's boundary, to rounding) is 0 or 1.
///
/// # Panics
/// If the share is not finite (a vertex that is not).
pub fn coverage(poly: &[DVec2], x: u32, y: u32) -> f64 {
    let corner = DVec2::new(f64::from(x), f64::from(y));
    let moved: Vec<DVec2> = poly.iter().map(|&p| p - corner).collect();
    let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
    let share = area(&clip(&moved, &square));
    assert!(
        share.is_finite(),
        "coverage: a share of {share} at pixel ({x}, {y})"
    );
    if share < 1e-12 {
        0.0
    } else if share > 1.0 - 1e-12 {
        1.0
    } else {
        share
    }
}

/// The image of the parallelogram `q` in the camera `c`: a convex quadrilateral.
///
/// # Panics
/// If a vertex is not in front of the camera.
pub fn image_of(c: &CameraSpec, q: &Parallelogram) -> Vec<DVec2> {
    q.vertices()
        .iter()
        .map(|&v| {
            image_point(c, v)
                .unwrap_or_else(|| panic!("edges: the vertex {v} is behind the camera"))
        })
        .collect()
}

/// Linear sRGB of a spectrum.
fn colour(s: &Spectrum) -> DVec3 {
    rgb(|nm| s.eval(nm))
}

/// The fewest samples expected to meet a polygon in a tested pixel. A pixel that a
/// polygon's corner barely touches sees it in a sample or two, or in none: its mean is far
/// from normal and its observed variance often zero, and a block made of such pixels and
/// black ones would raise false alarms (an expected value of 0.003 against one lucky
/// sample). [`flat`] therefore leaves out a pixel a polygon covers in a share below
/// `SLIVER_HITS / spp`.
pub const SLIVER_HITS: f64 = 20.0;

// ANCHOR: flat
/// The expected image of flat polygons of uniform radiance over a uniform background,
/// edges included: either lights seen directly against black (no
/// shapes, no environment), or one Lambertian quad in a constant sky (no lights), whose
/// radiance is `rho(lambda) L(lambda)` (the quad sees nothing but the sky). A pixel's mean
/// is `sum_k c_k rgb(L_k) + (1 - sum_k c_k) rgb(L_background)`, `c_k` the share of the
/// pixel covered by polygon `k` ([`coverage`]); a pixel that a polygon covers in a share
/// below `SLIVER_HITS / spp` is not tested ([`SLIVER_HITS`]).
///
/// # Panics
/// If the scene is not of that kind, a light does not face the camera, or two polygons'
/// images overlap.
pub fn flat(scene: &Scene) -> Expected {
    let c = &scene.camera;
    let (background, polygons): (DVec3, Vec<(Vec<DVec2>, DVec3)>) = match &scene.environment {
        None => {
            assert!(scene.shapes.is_empty(), "flat: shapes without a sky");
            let lights = scene.lights.iter().map(|l| {
                let LightShape::Quad(q) = &l.shape else {
                    panic!("flat: a light that is not a parallelogram")
                };
                assert!(
                    q.normal().dot(c.position - q.vertices()[0]) > 0.0,
                    "flat: a light turned away from the camera"
                );
                (image_of(c, q.shape()), colour(&l.emission))
            });
            (DVec3::ZERO, lights.collect())
        }
        Some(Environment::Constant(sky)) => {
            assert!(scene.lights.is_empty(), "flat: lights in the sky scene");
            assert!(scene.shapes.len() == 1, "flat: the sky scene has one quad");
            let s = &scene.shapes[0];
            let (Geometry::Quad(q), Material::Lambert { reflectance }) =
                (&s.geometry, &scene.materials[s.material])
            else {
                panic!("flat: the sky scene's shape is a Lambertian parallelogram");
            };
            let lit = rgb(|nm| reflectance.eval(nm) * sky.eval(nm));
            (colour(sky), vec![(image_of(c, q), lit)])
        }
        Some(_) => panic!("flat: a sky that is not constant"),
    };
    for (i, (a, _)) in polygons.iter().enumerate() {
        for (b, _) in &polygons[i + 1..] {
            assert!(
                area(&clip(a, b)) == 0.0,
                "flat: two polygons' images overlap"
            );
        }
    }
    let sliver = SLIVER_HITS / f64::from(scene.settings.spp.max(1));
    let mean = (0..c.height)
        .flat_map(|y| (0..c.width).map(move |x| (x, y)))
        .map(|(x, y)| {
            let mut covered = 0.0;
            let mut sum = DVec3::ZERO;
            let mut tested = true;
            for (poly, col) in &polygons {
                let share = coverage(poly, x, y);
                tested &= share == 0.0 || share >= sliver;
                covered += share;
                sum += share * *col;
            }
            tested.then_some(sum + (1.0 - covered) * background)
        })
        .collect();
    Expected::exact(c.width, c.height, mean)
}
// ANCHOR_END: flat

/// An axis-aligned rectangle of a horizontal plane: `x` in `[x0, x1]`, `z` in `[z0, z1]`,
/// at height `y`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// The least and greatest `x`.
    pub x: [f64; 2],
    /// The least and greatest `z`.
    pub z: [f64; 2],
    /// The height.
    pub y: f64,
}

impl Rect {
    /// The rectangle of a horizontal parallelogram whose edges lie along `x` and `z`.
    ///
    /// # Panics
    /// If `q` is not such a parallelogram.
    pub fn of(q: &Parallelogram) -> Self {
        let [e1, e2] = q.edges();
        let along_axes = |e: DVec3| e.y == 0.0 && (e.x == 0.0 || e.z == 0.0);
        assert!(
            along_axes(e1) && along_axes(e2),
            "shadow: a parallelogram that is not a horizontal rectangle along x and z"
        );
        let v = q.vertices();
        let (xs, zs) = (v.map(|p| p.x), v.map(|p| p.z));
        let lo = |a: [f64; 4]| a.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = |a: [f64; 4]| a.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Rect {
            x: [lo(xs), hi(xs)],
            z: [lo(zs), hi(zs)],
            y: v[0].y,
        }
    }

    /// The overlap of two rectangles of one plane, or `None`.
    fn and(&self, other: &Rect) -> Option<Rect> {
        let x = [self.x[0].max(other.x[0]), self.x[1].min(other.x[1])];
        let z = [self.z[0].max(other.z[0]), self.z[1].min(other.z[1])];
        (x[0] < x[1] && z[0] < z[1]).then_some(Rect { x, z, y: self.y })
    }

    /// The corners in order.
    fn corners(&self) -> [DVec3; 4] {
        let (x, z, y) = (self.x, self.z, self.y);
        [
            DVec3::new(x[0], y, z[0]),
            DVec3::new(x[1], y, z[0]),
            DVec3::new(x[1], y, z[1]),
            DVec3::new(x[0], y, z[1]),
        ]
    }
}

/// The shadow of the rectangle `occluder` cast from the point `p` onto the plane of the
/// rectangle `light` (both horizontal, `p` below both): the central projection from `p`
/// between parallel planes scales every offset from `p` by `(y_light - p.y) / (y_occluder
/// - p.y)`, so the shadow is a rectangle.
pub fn occluder_on_light(p: DVec3, occluder: &Rect, light: &Rect) -> Rect {
    let s = (light.y - p.y) / (occluder.y - p.y);
    Rect {
        x: occluder.x.map(|x| p.x + s * (x - p.x)),
        z: occluder.z.map(|z| p.z + s * (z - p.z)),
        y: light.y,
    }
}

/// The part of the rectangle `light` that `occluder` hides from the floor point `p`: the
/// overlap of the light and the occluder's shadow on it ([`occluder_on_light`]), or
/// `None`.
fn hidden(p: DVec3, light: &Rect, occluder: &Rect) -> Option<Rect> {
    light.and(&occluder_on_light(p, occluder, light))
}

/// The irradiance at the floor point `p` (normal `+y`) from the rectangle `light` of unit
/// radiance, less what `occluder` hides: Lambert's formula for the light, less Lambert's
/// formula for the overlap of the light and the occluder's shadow on it.
pub fn unoccluded_irradiance(p: DVec3, light: &Rect, occluder: &Rect) -> f64 {
    let whole = polygon_irradiance(p, DVec3::Y, &light.corners(), 1.0);
    let hidden = hidden(p, light, occluder)
        .map_or(0.0, |o| polygon_irradiance(p, DVec3::Y, &o.corners(), 1.0));
    whole - hidden
}

/// The share of the area of the rectangle `light` that the floor point `p` sees past
/// `occluder`.
pub fn visible_share(p: DVec3, light: &Rect, occluder: &Rect) -> f64 {
    let size = |r: &Rect| (r.x[1] - r.x[0]) * (r.z[1] - r.z[0]);
    let hidden = hidden(p, light, occluder).map_or(0.0, |o| size(&o));
    1.0 - hidden / size(light)
}

/// The nodes and weights on `[0, 1]` of `parts` equal sub-intervals, each with 4-point
/// Gauss-Legendre.
pub(crate) fn composite_gauss4(parts: u32) -> Vec<(f64, f64)> {
    let h = 1.0 / f64::from(parts);
    (0..parts)
        .flat_map(|k| {
            super::exact::GAUSS4
                .iter()
                .map(move |&(x, w)| ((f64::from(k) + x) * h, w * h))
        })
        .collect()
}

// ANCHOR: shadow
/// The expected image of a Lambertian floor (the plane `y = 0`, `shapes[0]`) under
/// horizontal rectangular lights facing down, with one black horizontal rectangle
/// (`shapes[1]`) between them and the floor, by the composite rule of `parts` x `parts`
/// squares of 4 x 4 Gauss-Legendre points per pixel: a floor point `x` has radiance
/// `sum_k E_k(x) rgb(rho L_k) / pi`, with `E_k` the irradiance of the part of light `k`
/// that the occluder does not hide ([`unoccluded_irradiance`]). A point of the occluder
/// is black; a pixel whose points do not all meet one surface is not tested, nor one
/// whose centre sees so little of the lights that fewer than [`SLIVER_HITS`] light
/// samples would meet them there ([`visible_share`]).
///
/// # Panics
/// If the scene is not of that kind.
pub fn shadow_with(scene: &Scene, parts: u32) -> Expected {
    assert!(scene.environment.is_none(), "shadow: the scene has a sky");
    assert!(scene.shapes.len() == 2, "shadow: a floor and one occluder");
    let rect = |i: usize| match &scene.shapes[i].geometry {
        Geometry::Quad(q) => Rect::of(q),
        Geometry::Sphere(_) => panic!("shadow: a sphere"),
    };
    let (floor, occluder) = (rect(0), rect(1));
    assert!(floor.y == 0.0, "shadow: the floor is at y = 0");
    let reflectance = |i: usize| match &scene.materials[scene.shapes[i].material] {
        Material::Lambert { reflectance } => reflectance.clone(),
        other => panic!("shadow: {other:?} is not Lambertian"),
    };
    let (rho, black) = (reflectance(0), reflectance(1));
    assert!(
        (360..=830).all(|nm| black.eval(f64::from(nm)) == 0.0),
        "shadow: the occluder is not black"
    );
    let lights: Vec<(Rect, DVec3)> = scene
        .lights
        .iter()
        .map(|l| {
            let LightShape::Quad(q) = &l.shape else {
                panic!("shadow: a light that is not a rectangle")
            };
            assert!(
                q.normal().y < 0.0,
                "shadow: a light that does not face down"
            );
            let r = Rect::of(q.shape());
            assert!(
                r.y > occluder.y && occluder.y > 0.0,
                "shadow: the occluder is not between"
            );
            let l_rho = rgb(|nm| rho.eval(nm) * l.emission.eval(nm));
            (r, l_rho * std::f64::consts::FRAC_1_PI)
        })
        .collect();
    let rule = composite_gauss4(parts);
    let c = &scene.camera;
    let spp = f64::from(scene.settings.spp.max(1));
    let pixel = |x: u32, y: u32| {
        let at = |dx: f64, dy: f64| {
            let (o, d) = camera_ray(c, f64::from(x) + dx, f64::from(y) + dy);
            (o, d, first(scene, o, d))
        };
        let (_, _, reference) = at(0.5, 0.5);
        let mut sum = DVec3::ZERO;
        for &(gx, wx) in &rule {
            for &(gy, wy) in &rule {
                let (o, d, hit) = at(gx, gy);
                let radiance = match (hit, reference) {
                    (First::Shape(0, t), First::Shape(0, _)) => {
                        let p = o + t * d;
                        lights
                            .iter()
                            .map(|(r, col)| unoccluded_irradiance(p, r, &occluder) * *col)
                            .sum()
                    }
                    (First::Shape(1, _), First::Shape(1, _)) => DVec3::ZERO,
                    _ => return None,
                };
                sum += wx * wy * radiance;
            }
        }
        let corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
        let one_surface = corners
            .iter()
            .all(|&(dx, dy)| at(dx, dy).2.same_surface(reference));
        // A floor point that sees only slivers of the lights: the renderer's light
        // samples (one light of the n chosen per sample) meet them in a handful of its
        // samples, as at a polygon's corner in `flat`.
        let lit = match reference {
            First::Shape(0, t) => {
                let (o, d) = camera_ray(c, f64::from(x) + 0.5, f64::from(y) + 0.5);
                let p = o + t * d;
                let seen: f64 = lights
                    .iter()
                    .map(|(r, _)| visible_share(p, r, &occluder))
                    .sum();
                seen == 0.0 || seen * spp / lights.len() as f64 >= SLIVER_HITS
            }
            _ => true,
        };
        (one_surface && lit).then_some(sum)
    };
    let mean = (0..c.height)
        .into_par_iter()
        .flat_map_iter(|y| (0..c.width).map(move |x| pixel(x, y)).collect::<Vec<_>>())
        .collect();
    Expected::exact(c.width, c.height, mean)
}
// ANCHOR_END: shadow

/// [`shadow_with`] at the tests' rule: 6 x 6 squares of 4 x 4 points per pixel.
pub fn shadow(scene: &Scene) -> Expected {
    shadow_with(scene, 6)
}
