//! Expected images known independently of the path tracer. Chapter: *Testing the renderer*
//! (`chapters/renderer/testing.md`).
//!
//! A pixel's expected value is the mean of the radiance over the pixel (the renderer's box
//! filter), in linear sRGB from the CIE integral of the spectral radiance. Both are
//! computed here without the renderer's code: the camera ray from the scene's camera by
//! the pinhole construction, the first surface by the book's intersection routines, and
//! then
//!
//! * for a Lambertian surface lit directly ([`direct`]): the irradiance of each light in
//!   closed form (Lambert's formula for a polygon, `pi L sin^2` for a sphere, chapter
//!   *Shadow-ray pdfs*), so the radiance is `sum_k E_k(x) rgb(rho L_k) / pi`;
//! * for mirrors, glass and thin films in a sky ([`specular`]): every branch of every
//!   Fresnel split followed deterministically, each with its weight, until the weight
//!   left is below `1e-9`, and the sky's radiance summed over the branches' exits (a
//!   thin film's reflectance and transmittance depend on the wavelength, so there the CIE
//!   integral is taken over the branches' spectra).
//!
//! The mean over the pixel is a 4 x 4 Gauss-Legendre rule (2 x 2 for a thin film, whose
//! every point needs a spectral integral). It is exact enough (far below the tests' noise)
//! where the radiance is smooth across the pixel; a pixel whose sample
//! points and corners do not all meet the same surface straddles an edge, and is not
//! tested (`None`).

use glam::DVec3;
use rayon::prelude::*;

use super::pool::Expected;
use crate::geometry::Ray;
use crate::geometry::sphere::{Sphere, intersect_stable};
use crate::optics::fresnel::fresnel_dielectric;
use crate::optics::reflect::{reflect, refract};
use crate::optics::thinfilm::Film;
use crate::render::scene::{CameraSpec, Environment, Geometry, Ior, LightShape, Material, Scene};
use crate::spectral::cie;
use crate::transport::shadow::sphere_irradiance;

/// The nodes and weights of 4-point Gauss-Legendre quadrature on `[0, 1]`.
pub(super) const GAUSS4: [(f64, f64); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_87, 0.326_072_577_431_273_07),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

/// The nodes and weights of 2-point Gauss-Legendre quadrature on `[0, 1]`: exact for
/// cubics, enough for a thin film, whose every sample point needs a spectral integral.
const GAUSS2: [(f64, f64); 2] = [
    (0.211_324_865_405_187_13, 0.5),
    (0.788_675_134_594_812_9, 0.5),
];

/// The ray through the image point `(px, py)` (pixels from the top-left corner) of the
/// pinhole camera `c`: the image plane at unit distance along the view direction, `2
/// tan(fov / 2)` high, its right `forward x up`, its top `up` made perpendicular.
pub fn camera_ray(c: &CameraSpec, px: f64, py: f64) -> (DVec3, DVec3) {
    let forward = (c.look_at - c.position).normalize();
    let right = forward.cross(c.up).normalize();
    let top = right.cross(forward);
    let half_height = (c.fov_y_deg.to_radians() * 0.5).tan();
    let half_width = half_height * f64::from(c.width) / f64::from(c.height);
    let u = (px / f64::from(c.width)) * 2.0 - 1.0;
    let v = 1.0 - (py / f64::from(c.height)) * 2.0;
    let d = forward + right * (u * half_width) + top * (v * half_height);
    (c.position, d.normalize())
}

/// What a ray meets first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum First {
    /// Shape `i` at distance `t`.
    Shape(usize, f64),
    /// Light `k` at distance `t`.
    Light(usize, f64),
    /// Nothing: the ray escapes.
    Sky,
}

/// The first surface along the ray, by the book's routines (the stable ray-sphere
/// intersection and the parallelogram's), each surface tried and the nearest kept.
pub fn first(scene: &Scene, o: DVec3, d: DVec3) -> First {
    let ray = Ray::new(o, d);
    let mut best = First::Sky;
    let mut nearest = f64::INFINITY;
    for (i, s) in scene.shapes.iter().enumerate() {
        let t = match &s.geometry {
            Geometry::Sphere(sp) => intersect_stable(&ray, sp, 0.0),
            Geometry::Quad(q) => q.hit(o, d),
        };
        if let Some(t) = t.filter(|&t| t > 0.0 && t < nearest) {
            (best, nearest) = (First::Shape(i, t), t);
        }
    }
    for (k, l) in scene.lights.iter().enumerate() {
        let t = match &l.shape {
            LightShape::Quad(q) => q.shape().hit(o, d),
            LightShape::Sphere(s) => {
                intersect_stable(&ray, &Sphere::new(s.center(), s.radius()), 0.0)
            }
        };
        if let Some(t) = t.filter(|&t| t > 0.0 && t < nearest) {
            (best, nearest) = (First::Light(k, t), t);
        }
    }
    best
}

impl First {
    /// The same surface (or both the sky), for deciding whether a pixel straddles an edge.
    pub(crate) fn same_surface(self, other: First) -> bool {
        match (self, other) {
            (First::Shape(i, _), First::Shape(j, _)) | (First::Light(i, _), First::Light(j, _)) => {
                i == j
            }
            (First::Sky, First::Sky) => true,
            _ => false,
        }
    }
}

/// Linear sRGB of the spectrum `s(lambda)` (CIE 1931, a constant 1 has `Y = 1`).
pub fn rgb(s: impl Fn(f64) -> f64) -> DVec3 {
    cie::xyz_to_linear_srgb(cie::xyz(s))
}

/// The expected image of `scene`: the mean of `radiance` over each pixel by the product
/// rule `rule` (Gauss-Legendre nodes and weights on `[0, 1]`), `None` where the pixel's
/// sample points and corners do not all meet the same surface.
fn expected_image(
    scene: &Scene,
    rule: &[(f64, f64)],
    radiance: impl Fn(DVec3, DVec3, First) -> DVec3 + Sync,
) -> Expected {
    let c = &scene.camera;
    let pixel = |x: u32, y: u32| {
        let at = |dx: f64, dy: f64| {
            let (o, d) = camera_ray(c, f64::from(x) + dx, f64::from(y) + dy);
            (o, d, first(scene, o, d))
        };
        let (_, _, reference) = at(0.5, 0.5);
        let corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
        let mut smooth = corners
            .iter()
            .all(|&(dx, dy)| at(dx, dy).2.same_surface(reference));
        let mut sum = DVec3::ZERO;
        for &(gx, wx) in rule {
            for &(gy, wy) in rule {
                let (o, d, hit) = at(gx, gy);
                smooth &= hit.same_surface(reference);
                sum += wx * wy * radiance(o, d, hit);
            }
        }
        smooth.then_some(sum)
    };
    let mean = (0..c.height)
        .into_par_iter()
        .flat_map_iter(|y| {
            (0..c.width)
                .map(move |x| (x, y))
                .map(|(x, y)| pixel(x, y))
                .collect::<Vec<_>>()
        })
        .collect();
    Expected::exact(c.width, c.height, mean)
}

// ANCHOR: direct
/// The expected image of a scene of Lambertian shapes lit directly: each visible point `x`
/// (normal `n` turned towards the camera) has radiance `sum_k E_k(x) rgb(rho L_k) / pi`,
/// with the irradiance `E_k` of light `k` for unit radiance in closed form. A light seen
/// directly has its own radiance on its emitting side and none on the other (a quad's
/// back, a sphere's inside: [`Scene::emits_towards`]).
///
/// # Panics
/// If the scene is not of that kind: a material other than Lambert, an environment, or a
/// point where a light is not wholly above the horizon (the closed forms need it).
pub fn direct(scene: &Scene) -> Expected {
    assert!(
        scene.environment.is_none(),
        "direct: the scene has an environment"
    );
    // rgb(rho L_k) for every material and light, and rgb(L_k).
    let rho_l: Vec<Vec<DVec3>> = scene
        .materials
        .iter()
        .map(|m| match m {
            Material::Lambert { reflectance } => scene
                .lights
                .iter()
                .map(|l| rgb(|nm| reflectance.eval(nm) * l.emission.eval(nm)))
                .collect(),
            other => panic!("direct: {other:?} is not Lambertian"),
        })
        .collect();
    let seen: Vec<DVec3> = scene
        .lights
        .iter()
        .map(|l| rgb(|nm| l.emission.eval(nm)))
        .collect();
    expected_image(scene, &GAUSS4, |o, d, hit| match hit {
        First::Sky => DVec3::ZERO,
        First::Light(k, _) if scene.emits_towards(k, o, d) => seen[k],
        First::Light(..) => DVec3::ZERO,
        First::Shape(i, t) => {
            let x = o + t * d;
            let n = match &scene.shapes[i].geometry {
                Geometry::Quad(q) => q.normal(),
                Geometry::Sphere(s) => (x - s.center).normalize(),
            };
            let n = if n.dot(d) < 0.0 { n } else { -n };
            let material = scene.shapes[i].material;
            scene
                .lights
                .iter()
                .enumerate()
                .map(|(k, l)| {
                    // The closed forms need the whole light in view: check the lines to
                    // its centre and corners.
                    let targets: Vec<DVec3> = match &l.shape {
                        LightShape::Quad(q) => {
                            let v = q.vertices();
                            let mid = (v[0] + v[2]) / 2.0;
                            v.iter()
                                .map(|c| mid + 0.999 * (*c - mid))
                                .chain([mid])
                                .collect()
                        }
                        LightShape::Sphere(s) => vec![s.center()],
                    };
                    let from = x + n * 1e-9 * (1.0 + x.abs().max_element());
                    for t in targets {
                        let dir = (t - from).normalize();
                        assert!(
                            matches!(first(scene, from, dir), First::Light(j, _) if j == k),
                            "direct: something hides light {k} from {x}"
                        );
                    }
                    let e = match &l.shape {
                        LightShape::Quad(q) => {
                            assert!(
                                q.vertices().iter().all(|v| (*v - x).dot(n) > 0.0),
                                "direct: light {k} is not above the horizon of {x}"
                            );
                            q.irradiance(x, n, 1.0)
                        }
                        LightShape::Sphere(s) => {
                            assert!(
                                (s.center() - x).dot(n) > s.radius(),
                                "direct: light {k} is not above the horizon of {x}"
                            );
                            sphere_irradiance(x, n, s, 1.0)
                        }
                    };
                    e * std::f64::consts::FRAC_1_PI * rho_l[material][k]
                })
                .sum()
        }
    })
}
// ANCHOR_END: direct

/// The exits of the ray from `o` along `d` with weight `w` through mirrors and
/// constant-index dielectrics: `exit(direction, weight)` for each branch that escapes.
/// Both branches of every Fresnel split are followed (reflection with `F`, refraction with
/// `1 - F`, total internal reflection in full) until a branch's weight is below `1e-9` or
/// it has made `depth` bounces.
fn split(scene: &Scene, o: DVec3, d: DVec3, w: f64, depth: u32, exit: &mut dyn FnMut(DVec3, f64)) {
    if w < 1e-9 || depth == 0 {
        return;
    }
    let First::Shape(i, t) = first(scene, o, d) else {
        // Lights are not part of these scenes; the sky is.
        exit(d, w);
        return;
    };
    let p = o + t * d;
    let n = match &scene.shapes[i].geometry {
        Geometry::Sphere(s) => (p - s.center).normalize(),
        Geometry::Quad(q) => q.normal(),
    };
    // Leave the surface on the side the new ray goes, by a relative 1e-9 (as the renderer).
    let leave = |dir: DVec3| p + n * (1e-9 * (1.0 + p.abs().max_element()) * dir.dot(n).signum());
    match &scene.materials[scene.shapes[i].material] {
        Material::Mirror => {
            let r = reflect(d, n);
            split(scene, leave(r), r, w, depth - 1, exit);
        }
        Material::Dielectric {
            ior: Ior::Constant(eta),
        } => {
            let (n1, n2) = if d.dot(n) < 0.0 {
                (1.0, *eta)
            } else {
                (*eta, 1.0)
            };
            let f = fresnel_dielectric(d.dot(n).abs(), n1, n2);
            let r = reflect(d, n);
            match refract(d, n, n1, n2).transmitted() {
                Some(tr) => {
                    split(scene, leave(r), r, w * f, depth - 1, exit);
                    split(scene, leave(tr), tr, w * (1.0 - f), depth - 1, exit);
                }
                None => split(scene, leave(r), r, w, depth - 1, exit),
            }
        }
        other => panic!("specular: {other:?} is not a mirror or a constant-index dielectric"),
    }
}

/// The sky's radiance spectrum towards `d`.
fn sky_at<'a>(env: &'a Environment, d: DVec3) -> impl Fn(f64) -> f64 + 'a {
    move |nm| env.eval(d, nm)
}

/// The linear sRGB colours of the sky: the sky is linear in `c = axis . d`, so its colour
/// towards `d` is the same blend of its two spectra's colours ([`SkyColour::towards`]).
struct SkyColour {
    axis: DVec3,
    above: DVec3,
    below: DVec3,
}

impl SkyColour {
    fn of(env: &Environment) -> Self {
        match env {
            Environment::Constant(s) => {
                let c = rgb(|nm| s.eval(nm));
                SkyColour {
                    axis: DVec3::Y,
                    above: c,
                    below: c,
                }
            }
            Environment::Gradient { axis, above, below } => SkyColour {
                axis: *axis,
                above: rgb(|nm| above.eval(nm)),
                below: rgb(|nm| below.eval(nm)),
            },
        }
    }

    fn towards(&self, d: DVec3) -> DVec3 {
        let c = self.axis.dot(d).clamp(-1.0, 1.0);
        0.5 * ((1.0 + c) * self.above + (1.0 - c) * self.below)
    }
}

// ANCHOR: specular
/// The expected image of mirrors and constant-index glass in a sky: the sum over every
/// Fresnel branch of its weight times the sky's colour where it leaves; and of one thin
/// film in the sky: `R(lambda) L(reflected) + T(lambda) L(straight on)`, integrated against
/// the colour-matching functions per pixel sample (a film's colours are its interference).
///
/// # Panics
/// If the scene has lights, no environment, or a material other than those.
pub fn specular(scene: &Scene) -> Expected {
    assert!(scene.lights.is_empty(), "specular: the scene has lights");
    let env = scene
        .environment
        .as_ref()
        .unwrap_or_else(|| panic!("specular: the scene has no sky"));
    let colour = SkyColour::of(env);
    let film = scene
        .materials
        .iter()
        .any(|m| matches!(m, Material::ThinFilm { .. }));
    let rule: &[(f64, f64)] = if film { &GAUSS2 } else { &GAUSS4 };
    expected_image(scene, rule, |o, d, hit| match hit {
        First::Shape(i, t) => match &scene.materials[scene.shapes[i].material] {
            Material::ThinFilm { ior, thickness } => {
                let p = o + t * d;
                let n = match &scene.shapes[i].geometry {
                    Geometry::Quad(q) => q.normal(),
                    Geometry::Sphere(s) => (p - s.center).normalize(),
                };
                let film = Film::new(1.0, *ior, 1.0, thickness.at(p.y));
                let cos = d.dot(n).abs().min(1.0);
                let (up, on) = (sky_at(env, reflect(d, n)), sky_at(env, d));
                rgb(|nm| {
                    let r = film.response_cos(nm, cos);
                    r.reflectance() * up(nm) + r.transmittance() * on(nm)
                })
            }
            _ => {
                let mut sum = DVec3::ZERO;
                split(scene, o, d, 1.0, scene.settings.max_depth, &mut |dir, w| {
                    sum += w * colour.towards(dir);
                });
                sum
            }
        },
        _ => colour.towards(d),
    })
}
// ANCHOR_END: specular
