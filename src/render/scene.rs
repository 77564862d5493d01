//! The scene model: a checked [`Scene`] (camera, settings, materials, shapes, lights,
//! environment) and its geometric queries: the first surface along a ray
//! ([`Scene::intersect`]), the point and normal where a ray meets a shape
//! ([`Scene::surface_point`]), and the side an emitter emits to ([`Scene::emits_towards`]).
//! Chapter: *The path tracer* (`chapters/renderer/path-tracer.md`); its file format is in
//! *Reference scenes and interop* (`chapters/renderer/scenes.md`).
//!
//! A `Scene` is made from a file by [`super::format::parse`] (or [`super::format::load`]),
//! which checks everything (`validate`), or built directly by code and tests.

use glam::DVec3;

use crate::geometry::Ray;
use crate::geometry::parallelogram::Parallelogram;
use crate::geometry::sphere::{Sphere, intersect_stable};
use crate::optics::dispersion::Sellmeier;
use crate::spectral::emission::{EmissionSampler, WavelengthSample};
use crate::spectral::spectrum::Spectrum;
use crate::spectral::wavelength::{N, WavelengthStrategy, Wavelengths, rotate01};
use crate::transport::rectangle::RectangleLight;
use crate::transport::shadow::{Heuristic, Light, QuadLight, SphereLight};

/// The strategies of direct lighting: the shadow-ray chapter's
/// ([`crate::transport::shadow::IrradianceStrategy`]), used by the path tracer at every diffuse
/// bounce.
pub use crate::transport::shadow::IrradianceStrategy as DirectLight;

/// The names the `wavelengths` key accepts, with their strategies (and `"emission"`,
/// [`Wavelength::Emission`]).
pub(crate) const WAVELENGTH_STRATEGIES: [(&str, WavelengthStrategy); 5] = [
    ("uniform", WavelengthStrategy::Uniform),
    ("visible", WavelengthStrategy::Visible),
    ("hero-uniform", WavelengthStrategy::HeroUniform),
    ("hero-visible", WavelengthStrategy::HeroVisible),
    ("hero-balance", WavelengthStrategy::HeroBalance),
];

/// The names the `direct` key accepts, with their strategies of direct lighting.
pub(crate) const DIRECT_STRATEGIES: [(&str, DirectLight); 4] = [
    ("mis-power", DirectLight::Mis(Heuristic::Power)),
    ("mis-balance", DirectLight::Mis(Heuristic::Balance)),
    ("light", DirectLight::Light),
    ("bsdf", DirectLight::Bsdf),
];

/// How a rectangular quad light is sampled for next-event estimation (and its pdf for
/// multiple importance sampling evaluated).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightSampling {
    /// Uniformly by area, the density converted to solid angle (chapter *Shadow-ray pdfs*).
    #[default]
    Area,
    /// Uniformly in the solid angle the rectangle subtends (chapter *Sampling a rectangle by
    /// solid angle*); a quad light that is not a rectangle is still sampled by area.
    SolidAngle,
}

/// The names the `light_sampling` key accepts.
pub(crate) const LIGHT_SAMPLINGS: [(&str, LightSampling); 2] = [
    ("area", LightSampling::Area),
    ("solid-angle", LightSampling::SolidAngle),
];

impl LightSampling {
    /// The name the scene format uses.
    pub fn name(self) -> &'static str {
        LIGHT_SAMPLINGS
            .iter()
            .find(|(_, s)| *s == self)
            .map_or("area", |(n, _)| n)
    }
}

/// A checked scene, ready to render.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The camera.
    pub camera: CameraSpec,
    /// Samples per pixel, seed, wavelength strategy, path-length controls.
    pub settings: RenderSettings,
    /// The materials, referred to by index from [`Shape::material`].
    pub materials: Vec<Material>,
    /// The shapes that scatter light.
    pub shapes: Vec<Shape>,
    /// The emitters (non-reflecting).
    pub lights: Vec<Emitter>,
    /// The radiance seen by rays that escape (none: black).
    pub environment: Option<Environment>,
    /// A 64-bit FNV-1a hash of the scene file's bytes, for the render's sidecar.
    pub hash: u64,
    /// The data files the scene file made it read (spectrum tables), in order: with the
    /// scene file, what a render is made from ([`super::provenance`]).
    pub files: Vec<std::path::PathBuf>,
}

/// A pinhole camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSpec {
    /// The centre of projection.
    pub position: DVec3,
    /// A point the camera looks at (the centre of the image).
    pub look_at: DVec3,
    /// The world's up direction (need not be perpendicular to the view direction).
    pub up: DVec3,
    /// The vertical field of view, degrees, in `(0, 180)`.
    pub fov_y_deg: f64,
    /// Width and height in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
}

// ANCHOR: wavelength
/// How a path's wavelengths are drawn.
#[derive(Clone, Debug, PartialEq)]
pub enum Wavelength {
    /// One of the wavelength chapter's strategies.
    Strategy(WavelengthStrategy),
    /// Hero lanes from the colour proposal of the scene's one light (its spectrum times
    /// `x̄ + ȳ + z̄`, *Importance-sampled emission spectra*), rotated in sample space: lane
    /// `j` is `P⁻¹((u + j/N) mod 1)` and, alone, has the proposal's density, so each lane
    /// is weighted by its own `p(λ_j)` as in `hero_visible`. Unbiased because no path
    /// carries light at a wavelength where the one light emits nothing.
    Emission(EmissionSampler),
}

impl Wavelength {
    /// The wavelengths of one path for `u` in `[0, 1)`.
    #[inline]
    pub fn sample(&self, u: f64) -> Wavelengths {
        match self {
            Wavelength::Strategy(s) => s.sample(u),
            Wavelength::Emission(sampler) => {
                let lanes: [WavelengthSample; N] =
                    std::array::from_fn(|j| sampler.sample(rotate01(u, j as f64 / N as f64)));
                Wavelengths {
                    lambda: lanes.map(|l| l.nm),
                    pdf: lanes.map(|l| l.pdf),
                    hero_pdf: lanes[0].pdf,
                }
            }
        }
    }

    /// The name the scene file gives it.
    pub fn name(&self) -> &'static str {
        match self {
            Wavelength::Emission(_) => "emission",
            Wavelength::Strategy(s) => WAVELENGTH_STRATEGIES
                .iter()
                .find(|(_, t)| t == s)
                .map_or("other", |(n, _)| n),
        }
    }
}
// ANCHOR_END: wavelength

// ANCHOR: environment
/// The radiance arriving from infinitely far away along a direction that escapes the scene.
#[derive(Clone, Debug, PartialEq)]
pub enum Environment {
    /// The same spectrum from every direction.
    Constant(Spectrum),
    /// A sky: `above` towards `axis`, `below` away from it, blended linearly in
    /// `c = axis . w`: `L(w) = above (1 + c) / 2 + below (1 - c) / 2`. Smooth, so that the
    /// expected image of a mirror or glass sphere in it is a smooth function a quadrature
    /// computes exactly, and different in every direction, so that a mistake that only
    /// moves light between directions changes the image.
    Gradient {
        /// The unit direction of `above`.
        axis: DVec3,
        /// The spectrum towards `axis`.
        above: Spectrum,
        /// The spectrum away from `axis`.
        below: Spectrum,
    },
}

impl Environment {
    /// The radiance from the unit direction `w` (pointing away from the scene) at `nm`.
    pub fn eval(&self, w: DVec3, nm: f64) -> f64 {
        match self {
            Environment::Constant(s) => s.eval(nm),
            Environment::Gradient { axis, above, below } => {
                let c = axis.dot(w).clamp(-1.0, 1.0);
                0.5 * ((1.0 + c) * above.eval(nm) + (1.0 - c) * below.eval(nm))
            }
        }
    }
}
// ANCHOR_END: environment

/// How to render.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderSettings {
    /// Samples per pixel, at least 1.
    pub spp: u32,
    /// The seed of every pixel's generator.
    pub seed: u64,
    /// How a path's wavelengths are drawn.
    pub wavelengths: Wavelength,
    /// How direct light is estimated at a diffuse surface: light sampling, BSDF sampling,
    /// or both with multiple importance sampling (the default, power heuristic). Every
    /// choice has the same expected image; the tests compare them.
    pub direct: DirectLight,
    /// Russian roulette starts after this many bounces.
    pub roulette_depth: u32,
    /// How rectangular lights are sampled: by area (the default) or by solid angle. Both
    /// have the same expected image.
    pub light_sampling: LightSampling,
    /// At most this many bounces, that is paths of at most `max_depth + 1` segments,
    /// whatever the `direct` strategy: the path tracer makes no next-event estimate at the
    /// last vertex, whose BSDF half it never traces. A safety net at its default of 1000:
    /// with roulette, paths this long carry no measurable energy in the canonical scenes.
    pub max_depth: u32,
}

/// The index of refraction of a dielectric.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Ior {
    /// The same at every wavelength (no dispersion).
    Constant(f64),
    /// A Sellmeier fit from `data/sellmeier.csv` (dispersive).
    Sellmeier(&'static Sellmeier),
}

impl Ior {
    /// The index at wavelength `nm`.
    pub fn at(&self, nm: f64) -> f64 {
        match self {
            Ior::Constant(n) => *n,
            Ior::Sellmeier(s) => s.index(nm),
        }
    }
}

/// A film thickness, linear in the world's `y` between two heights and constant beyond.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Thickness {
    /// Thickness (nm) at and below `y[0]`.
    pub bottom_nm: f64,
    /// Thickness (nm) at and above `y[1]`.
    pub top_nm: f64,
    /// The heights between which the thickness varies.
    pub y: [f64; 2],
}

impl Thickness {
    /// The thickness at height `y`, nm.
    pub fn at(&self, y: f64) -> f64 {
        let span = self.y[1] - self.y[0];
        let t = if span > 0.0 {
            ((y - self.y[0]) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        self.bottom_nm + t * (self.top_nm - self.bottom_nm)
    }
}

/// How a surface scatters light.
#[derive(Clone, Debug, PartialEq)]
pub enum Material {
    /// Lambertian, two-sided, with a spectral reflectance in `[0, 1]`.
    Lambert {
        /// The reflectance `rho(lambda)`.
        reflectance: Spectrum,
    },
    /// A perfect mirror (reflectance 1).
    Mirror,
    /// A smooth dielectric boundary between the outside (index 1) and the inside of a
    /// closed shape: exact Fresnel reflection and Snell refraction.
    Dielectric {
        /// The inside's index.
        ior: Ior,
    },
    /// A thin film in air on both sides (a soap bubble's wall): interference reflectance
    /// from the Airy sum; transmitted light goes straight on.
    ThinFilm {
        /// The film's index.
        ior: f64,
        /// Its thickness.
        thickness: Thickness,
    },
}

/// The geometry of a shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Geometry {
    /// A sphere.
    Sphere(Sphere),
    /// A parallelogram `corner + a e1 + b e2`, `a, b` in `[0, 1]`, seen from both sides.
    Quad(Parallelogram),
}

/// A shape with its material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape {
    /// What it is.
    pub geometry: Geometry,
    /// Index into [`Scene::materials`].
    pub material: usize,
}

/// The shape of an emitter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightShape {
    /// A parallelogram, one-sided: emits on the side of `e1 x e2` only.
    Quad(QuadLight),
    /// Emits outwards everywhere.
    Sphere(SphereLight),
}

/// An emitter: a shape that emits a spectral radiance, uniform over it, and reflects nothing.
#[derive(Clone, Debug, PartialEq)]
pub struct Emitter {
    /// Where.
    pub shape: LightShape,
    /// The emitted radiance, per nm.
    pub emission: Spectrum,
    /// The light as a rectangle sampled by solid angle, when it is a quad with
    /// perpendicular edges ([`Emitter::new`] sets it).
    pub rectangle: Option<RectangleLight>,
}

/// What a ray hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Surface {
    /// Index into [`Scene::shapes`].
    Shape(usize),
    /// Index into [`Scene::lights`].
    Light(usize),
}

/// The first surface along a ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance along the unit direction.
    pub t: f64,
    /// Which surface.
    pub surface: Surface,
}

impl Emitter {
    /// The emitter of a shape and a radiance, with its solid-angle sampler if it is a
    /// rectangle.
    pub fn new(shape: LightShape, emission: Spectrum) -> Self {
        let rectangle = match shape {
            LightShape::Quad(q) => RectangleLight::try_from(q).ok(),
            LightShape::Sphere(_) => None,
        };
        Self {
            shape,
            emission,
            rectangle,
        }
    }

    /// The emitter as a light sampled as `sampling` says: a rectangle by solid angle under
    /// [`LightSampling::SolidAngle`], everything else as [`Emitter::light`].
    pub fn light_with(&self, sampling: LightSampling) -> &dyn Light {
        match (&self.rectangle, sampling) {
            (Some(r), LightSampling::SolidAngle) => r,
            _ => self.light(),
        }
    }

    /// The emitter as a sampleable light (a quad sampled by area).
    pub fn light(&self) -> &dyn Light {
        match &self.shape {
            LightShape::Quad(q) => q,
            LightShape::Sphere(s) => s,
        }
    }
}

impl Scene {
    // ANCHOR: intersect
    /// The first shape or light along the ray from `o` in the unit direction `d`.
    /// A linear loop: the canonical scenes have at most a dozen surfaces.
    pub fn intersect(&self, o: DVec3, d: DVec3) -> Option<Hit> {
        self.intersect_before(o, d, f64::INFINITY)
    }

    /// The first shape or light along the ray nearer than `t_max`. Each parallelogram is
    /// tested only against the nearest hit found so far ([`Parallelogram::hit_before`]),
    /// so that one behind it costs a single dot product and a division.
    pub fn intersect_before(&self, o: DVec3, d: DVec3, t_max: f64) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut nearest = t_max;
        let ray = Ray::new(o, d);
        for (i, s) in self.shapes.iter().enumerate() {
            let t = match &s.geometry {
                Geometry::Sphere(sp) => intersect_stable(&ray, sp, 0.0),
                Geometry::Quad(q) => q.hit_before(o, d, nearest),
            };
            if let Some(t) = t.filter(|&t| t > 0.0 && t < nearest) {
                nearest = t;
                best = Some(Hit {
                    t,
                    surface: Surface::Shape(i),
                });
            }
        }
        for (i, l) in self.lights.iter().enumerate() {
            let t = match &l.shape {
                LightShape::Sphere(sp) => {
                    intersect_stable(&ray, &Sphere::new(sp.center(), sp.radius()), 0.0)
                }
                LightShape::Quad(q) => q.shape().hit_before(o, d, nearest),
            };
            if let Some(t) = t.filter(|&t| t > 0.0 && t < nearest) {
                nearest = t;
                best = Some(Hit {
                    t,
                    surface: Surface::Light(i),
                });
            }
        }
        best
    }
    // ANCHOR_END: intersect

    /// The point and unit geometric normal where the ray from `o` along `d` meets shape
    /// `i` at distance `t`. A sphere's point is projected back onto the sphere, which
    /// removes most of the rounding of `o + t d` (the offset then needs no error bound).
    pub fn surface_point(&self, i: usize, o: DVec3, d: DVec3, t: f64) -> (DVec3, DVec3) {
        let p = o + t * d;
        match &self.shapes[i].geometry {
            Geometry::Sphere(s) => {
                let n = (p - s.center).normalize();
                (s.center + s.radius * n, n)
            }
            Geometry::Quad(q) => (p, q.normal()),
        }
    }

    /// Whether emitter `light` emits towards a ray from `o` travelling along `d` that hits
    /// it: a quad on the side of its normal only (`n . d < 0`), a sphere outwards only (`o`
    /// outside it, [`SphereLight::is_outside`]), so that nothing inside a sphere light is
    /// lit by it. A sphere light's sampler and pdf give no point and no density to a point
    /// on or inside it, by the same test, so every strategy of direct light finds the same
    /// emission.
    pub fn emits_towards(&self, light: usize, o: DVec3, d: DVec3) -> bool {
        match &self.lights[light].shape {
            LightShape::Quad(q) => q.normal().dot(d) < 0.0,
            LightShape::Sphere(s) => s.is_outside(o),
        }
    }
}
