//! The scene format: a small TOML file, read into a checked [`Scene`]. Chapter: *The
//! reference renderer* (`chapters/renderer/renderer.md`), which documents every key so that
//! another implementation can read the same files.
//!
//! Everything is validated before a single ray is traced: a malformed scene is a
//! [`DataError`] naming the file, the line and the problem (a TOML syntax error, an unknown
//! key or material, a negative radius, an index of refraction `<= 0`, a NaN, a degenerate
//! quad, a missing spectrum file, zero samples per pixel).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use glam::DVec3;
use serde::Deserialize;
use toml::Spanned;

use crate::data::DataError;
use crate::geometry::sphere::Sphere;
use crate::optics::dispersion::{self, Sellmeier};
use crate::spectral::emission::{EmissionSampler, WavelengthSample, colour_proposal};
use crate::spectral::spectrum::{self, Spectrum, Table};
use crate::spectral::wavelength::{N, Strategy, Wavelengths, wrap01};
use crate::spectral::{cie, emission};
use crate::transport::shadow::{LightError, QuadLight, SphereLight};

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
    /// The radiance of a constant environment seen by rays that escape (none: black).
    pub environment: Option<Spectrum>,
    /// A 64-bit FNV-1a hash of the scene file's bytes, for the render's sidecar.
    pub hash: u64,
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
    Strategy(Strategy),
    /// Hero lanes from the colour proposal of the scene's one light (its spectrum times
    /// `x̄ + ȳ + z̄`, *Importance-sampled emission spectra*), rotated in sample space: lane
    /// `j` is `P⁻¹((u + j/N) mod 1)` and, alone, has the proposal's density, so each lane
    /// is weighted by its own `p(λ_j)` as in `hero_visible`. Unbiased because no path
    /// carries light at a wavelength where the one light emits nothing.
    Emission(EmissionSampler),
}

impl Wavelength {
    /// The wavelengths of one path for `u` in `[0, 1)`.
    pub fn sample(&self, u: f64) -> Wavelengths {
        match self {
            Wavelength::Strategy(s) => s.sample(u),
            Wavelength::Emission(sampler) => {
                let lanes: [WavelengthSample; N] =
                    std::array::from_fn(|j| sampler.sample(wrap01(u + j as f64 / N as f64)));
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

/// How to render.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderSettings {
    /// Samples per pixel, at least 1.
    pub spp: u32,
    /// The seed of every pixel's generator.
    pub seed: u64,
    /// How a path's wavelengths are drawn.
    pub wavelengths: Wavelength,
    /// Russian roulette starts after this many bounces.
    pub roulette_depth: u32,
    /// A hard limit on the number of bounces (a safety net; with roulette, paths this long
    /// carry no measurable energy in the canonical scenes).
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
    /// A parallelogram `corner + a e1 + b e2`, `a, b` in `[0, 1]` (the light chapter's
    /// [`QuadLight`] serves as its geometry; a scattering quad is seen from both sides).
    Quad(QuadLight),
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
    /// One-sided: emits on the side of `e1 x e2` only.
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
}

// ---------------------------------------------------------------------------------------
// The file as written (before checking).

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScene {
    render: Spanned<RawRender>,
    camera: Spanned<RawCamera>,
    #[serde(default)]
    spectra: BTreeMap<String, Spanned<toml::Value>>,
    #[serde(default)]
    materials: BTreeMap<String, Spanned<RawMaterial>>,
    #[serde(default)]
    shape: Vec<Spanned<RawShape>>,
    #[serde(default)]
    light: Vec<Spanned<RawShape>>,
    environment: Option<Spanned<RawEnvironment>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRender {
    spp: Spanned<i64>,
    seed: Option<Spanned<i64>>,
    wavelengths: Option<Spanned<String>>,
    roulette_depth: Option<Spanned<i64>>,
    max_depth: Option<Spanned<i64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCamera {
    position: Spanned<[f64; 3]>,
    look_at: Spanned<[f64; 3]>,
    up: Spanned<[f64; 3]>,
    fov_y: Spanned<f64>,
    resolution: Spanned<[i64; 2]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMaterial {
    #[serde(rename = "type")]
    kind: Spanned<String>,
    reflectance: Option<Spanned<toml::Value>>,
    ior: Option<Spanned<f64>>,
    sellmeier: Option<Spanned<String>>,
    thickness_nm: Option<Spanned<toml::Value>>,
    y_range: Option<Spanned<[f64; 2]>>,
}

/// A `[[shape]]` or a `[[light]]`: the keys a sphere or a quad can have.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawShape {
    #[serde(rename = "type")]
    kind: Spanned<String>,
    center: Option<Spanned<[f64; 3]>>,
    radius: Option<Spanned<f64>>,
    corner: Option<Spanned<[f64; 3]>>,
    edge1: Option<Spanned<[f64; 3]>>,
    edge2: Option<Spanned<[f64; 3]>>,
    material: Option<Spanned<String>>,
    emission: Option<Spanned<toml::Value>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawEnvironment {
    emission: Spanned<toml::Value>,
}

/// An inline or named spectrum definition: exactly one of the kinds.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSpectrum {
    constant: Option<f64>,
    file: Option<String>,
    column: Option<String>,
    blackbody: Option<f64>,
    peak: Option<f64>,
    lamp: Option<String>,
    scale: Option<f64>,
    luminance: Option<f64>,
}

// ---------------------------------------------------------------------------------------
// Checking.

/// The names the `wavelengths` key accepts, with their strategies.
pub const WAVELENGTH_STRATEGIES: [(&str, Strategy); 5] = [
    ("uniform", Strategy::Uniform),
    ("visible", Strategy::Visible),
    ("hero-uniform", Strategy::HeroUniform),
    ("hero-visible", Strategy::HeroVisible),
    ("hero-balance", Strategy::HeroBalance),
];

/// The largest accepted image side, in pixels.
pub const MAX_RESOLUTION: i64 = 16_384;

struct Checker<'a> {
    file: &'a str,
    text: &'a str,
    dir: PathBuf,
}

impl Checker<'_> {
    fn line(&self, span: std::ops::Range<usize>) -> usize {
        let end = span.start.min(self.text.len());
        self.text.as_bytes()[..end]
            .iter()
            .filter(|&&b| b == b'\n')
            .count()
            + 1
    }

    fn err<T>(
        &self,
        span: std::ops::Range<usize>,
        problem: impl Into<String>,
    ) -> Result<T, DataError> {
        Err(DataError::new(self.file, self.line(span), problem))
    }

    fn finite(&self, x: &Spanned<f64>, what: &str) -> Result<f64, DataError> {
        let v = *x.get_ref();
        if v.is_finite() {
            Ok(v)
        } else {
            self.err(x.span(), format!("{what} is {v}, not a finite number"))
        }
    }

    fn vec3(&self, x: &Spanned<[f64; 3]>, what: &str) -> Result<DVec3, DataError> {
        let v = DVec3::from_array(*x.get_ref());
        if v.is_finite() {
            Ok(v)
        } else {
            self.err(
                x.span(),
                format!("{what} {v} has a component that is not finite"),
            )
        }
    }

    /// Refuses the first of `keys` that is given: `(name, its span if present)`.
    fn refuse_keys<'k>(
        &self,
        keys: impl IntoIterator<Item = &'k (&'k str, Option<std::ops::Range<usize>>)>,
        what: &str,
        kind: &str,
    ) -> Result<(), DataError> {
        for (key, span) in keys {
            if let Some(span) = span {
                return self.err(span.clone(), format!("{what}: a {kind} has no key `{key}`"));
            }
        }
        Ok(())
    }

    fn required<'b, T>(
        &self,
        x: &'b Option<Spanned<T>>,
        outer: std::ops::Range<usize>,
        what: &str,
    ) -> Result<&'b Spanned<T>, DataError> {
        match x {
            Some(v) => Ok(v),
            None => self.err(outer, format!("missing key `{what}`")),
        }
    }

    fn non_negative_int(&self, x: &Spanned<i64>, what: &str, min: i64) -> Result<u64, DataError> {
        let v = *x.get_ref();
        if v >= min {
            Ok(v as u64)
        } else {
            self.err(
                x.span(),
                format!("{what} is {v}; it must be at least {min}"),
            )
        }
    }

    /// A spectrum: a number (constant), the name of an entry of `[spectra]`, or an inline
    /// table.
    fn spectrum(
        &self,
        v: &Spanned<toml::Value>,
        named: &BTreeMap<String, Spectrum>,
        what: &str,
    ) -> Result<Spectrum, DataError> {
        let span = v.span();
        match v.get_ref() {
            toml::Value::Float(x) => self.constant(*x, span, what),
            toml::Value::Integer(x) => self.constant(*x as f64, span, what),
            toml::Value::String(name) => named.get(name).cloned().map_or_else(
                || {
                    let known: Vec<&str> = named.keys().map(String::as_str).collect();
                    self.err(
                        span,
                        format!(
                            "{what}: no spectrum called {name:?} in [spectra] (there are: {})",
                            if known.is_empty() {
                                "none".to_string()
                            } else {
                                known.join(", ")
                            }
                        ),
                    )
                },
                Ok,
            ),
            toml::Value::Table(_) => self.spectrum_table(v, what),
            other => self.err(
                span,
                format!(
                    "{what} must be a number, a spectrum's name or a table, not a {}",
                    other.type_str()
                ),
            ),
        }
    }

    fn constant(
        &self,
        x: f64,
        span: std::ops::Range<usize>,
        what: &str,
    ) -> Result<Spectrum, DataError> {
        if x.is_finite() && x >= 0.0 {
            Ok(Spectrum::Constant(x))
        } else {
            self.err(
                span,
                format!("{what} is {x}; a spectrum's value must be finite and >= 0"),
            )
        }
    }

    /// An inline table: one kind, then `scale`, or `luminance` (the factor that gives the
    /// spectrum's CIE `Y`, [`cie::xyz`], that value).
    fn spectrum_table(&self, v: &Spanned<toml::Value>, what: &str) -> Result<Spectrum, DataError> {
        let span = v.span();
        let raw: RawSpectrum = v
            .get_ref()
            .clone()
            .try_into()
            .or_else(|e: toml::de::Error| {
                self.err(span.clone(), format!("{what}: {}", e.message()))
            })?;
        let Some(lum) = raw.luminance else {
            return self.spectrum_kind(&raw, span, what);
        };
        if raw.scale.is_some() {
            return self.err(
                span,
                format!("{what}: give `scale` or `luminance`, not both"),
            );
        }
        if !(lum.is_finite() && lum >= 0.0) {
            return self.err(
                span,
                format!("{what}: luminance {lum} must be finite and >= 0"),
            );
        }
        let s = self.spectrum_kind(&raw, span.clone(), what)?;
        let y = cie::xyz(|nm| s.eval(nm)).y;
        if y.is_nan() || y <= 0.0 {
            return self.err(
                span,
                format!(
                    "{what}: the spectrum is black in 360-830 nm; it has no luminance to scale"
                ),
            );
        }
        let k = lum / y;
        Ok(match s {
            Spectrum::Constant(c) => Spectrum::Constant(c * k),
            Spectrum::Table(t) => Spectrum::Table(t.scaled(k)),
            Spectrum::Blackbody { kelvin, peak } => Spectrum::Blackbody {
                kelvin,
                peak: peak * k,
            },
        })
    }

    fn spectrum_kind(
        &self,
        raw: &RawSpectrum,
        span: std::ops::Range<usize>,
        what: &str,
    ) -> Result<Spectrum, DataError> {
        let kinds = [
            raw.constant.is_some(),
            raw.file.is_some(),
            raw.blackbody.is_some(),
            raw.lamp.is_some(),
        ];
        if kinds.iter().filter(|&&k| k).count() != 1 {
            return self.err(
                span,
                format!("{what}: give exactly one of `constant`, `file`, `blackbody`, `lamp`"),
            );
        }
        let scale = raw.scale.unwrap_or(1.0);
        if !(scale.is_finite() && scale >= 0.0) {
            return self.err(
                span,
                format!("{what}: scale {scale} must be finite and >= 0"),
            );
        }
        if raw.column.is_some() && raw.file.is_none() {
            return self.err(span, format!("{what}: `column` belongs with `file`"));
        }
        if raw.peak.is_some() && raw.blackbody.is_none() {
            return self.err(span, format!("{what}: `peak` belongs with `blackbody`"));
        }
        if let Some(c) = raw.constant {
            return self.constant(c * scale, span, what);
        }
        if let Some(kelvin) = raw.blackbody {
            let peak = raw.peak.unwrap_or(1.0) * scale;
            if !(kelvin.is_finite() && kelvin > 0.0) {
                return self.err(
                    span,
                    format!("{what}: blackbody temperature {kelvin} K must be > 0"),
                );
            }
            if !(peak.is_finite() && peak >= 0.0) {
                return self.err(span, format!("{what}: peak {peak} must be finite and >= 0"));
            }
            return Ok(Spectrum::Blackbody { kelvin, peak });
        }
        if let Some(name) = &raw.lamp {
            let lamps = emission::lamps();
            return match lamps.iter().find(|l| l.name == name || l.stem == name) {
                Some(l) => Ok(Spectrum::Table(l.spectrum.scaled(scale))),
                None => {
                    let names: Vec<&str> = lamps.iter().map(|l| l.name).collect();
                    self.err(
                        span,
                        format!("{what}: no lamp {name:?} (there are: {})", names.join(", ")),
                    )
                }
            };
        }
        let file = raw.file.as_deref().unwrap_or_default();
        let path = self.dir.join(file);
        if !path.is_file() {
            return self.err(
                span,
                format!("{what}: spectrum file {} does not exist", path.display()),
            );
        }
        let tables = spectrum::load_csv(&path)?;
        let table: Table = match &raw.column {
            Some(c) => spectrum::column(&tables, c, &path.display().to_string())
                .or_else(|e| self.err(span.clone(), format!("{what}: {}", e.problem)))?,
            None => tables[0].1.clone(),
        };
        Ok(Spectrum::Table(table.scaled(scale)))
    }

    fn render(&self, r: &Spanned<RawRender>) -> Result<RenderSettings, DataError> {
        let r = r.get_ref();
        let spp = self.non_negative_int(&r.spp, "spp (samples per pixel)", 1)?;
        let spp = u32::try_from(spp).or_else(|_| self.err(r.spp.span(), "spp is too large"))?;
        let seed = match &r.seed {
            Some(s) => self.non_negative_int(s, "seed", 0)?,
            None => 0,
        };
        let wavelengths = match &r.wavelengths {
            None => Wavelength::Strategy(Strategy::HeroVisible),
            // Resolved once the lights are known.
            Some(w) if w.get_ref() == "emission" => Wavelength::Strategy(Strategy::HeroVisible),
            Some(w) => match WAVELENGTH_STRATEGIES.iter().find(|(n, _)| n == w.get_ref()) {
                Some((_, s)) => Wavelength::Strategy(*s),
                None => {
                    let names: Vec<&str> = WAVELENGTH_STRATEGIES.iter().map(|(n, _)| *n).collect();
                    return self.err(
                        w.span(),
                        format!(
                            "unknown wavelength strategy {:?} (there are: {}, emission)",
                            w.get_ref(),
                            names.join(", ")
                        ),
                    );
                }
            },
        };
        let depth =
            |x: &Option<Spanned<i64>>, what: &str, default: u32| -> Result<u32, DataError> {
                match x {
                    None => Ok(default),
                    Some(v) => {
                        let d = self.non_negative_int(v, what, 0)?;
                        u32::try_from(d)
                            .or_else(|_| self.err(v.span(), format!("{what} is too large")))
                    }
                }
            };
        Ok(RenderSettings {
            spp,
            seed,
            wavelengths,
            roulette_depth: depth(&r.roulette_depth, "roulette_depth", 3)?,
            max_depth: depth(&r.max_depth, "max_depth", 1000)?,
        })
    }

    fn camera(&self, c: &Spanned<RawCamera>) -> Result<CameraSpec, DataError> {
        let c = c.get_ref();
        let position = self.vec3(&c.position, "camera position")?;
        let look_at = self.vec3(&c.look_at, "camera look_at")?;
        let up = self.vec3(&c.up, "camera up")?;
        let fov = self.finite(&c.fov_y, "fov_y")?;
        if !(fov > 0.0 && fov < 180.0) {
            return self.err(
                c.fov_y.span(),
                format!("fov_y is {fov} degrees; it must be in (0, 180)"),
            );
        }
        let forward = look_at - position;
        if forward.length() == 0.0 {
            return self.err(
                c.look_at.span(),
                "camera look_at is the camera position: no view direction",
            );
        }
        if forward.normalize().cross(up).length() < 1e-9 * up.length() || up.length() == 0.0 {
            return self.err(
                c.up.span(),
                "camera up is zero or parallel to the view direction",
            );
        }
        let [w, h] = *c.resolution.get_ref();
        if !(1..=MAX_RESOLUTION).contains(&w) || !(1..=MAX_RESOLUTION).contains(&h) {
            return self.err(
                c.resolution.span(),
                format!("resolution {w} x {h}: each side must be in 1..={MAX_RESOLUTION}"),
            );
        }
        Ok(CameraSpec {
            position,
            look_at,
            up,
            fov_y_deg: fov,
            width: w as u32,
            height: h as u32,
        })
    }

    fn material(
        &self,
        name: &str,
        m: &Spanned<RawMaterial>,
        spectra: &BTreeMap<String, Spectrum>,
    ) -> Result<Material, DataError> {
        let span = m.span();
        let m = m.get_ref();
        let what = format!("material {name:?}");
        let allowed: &[&str] = match m.kind.get_ref().as_str() {
            "lambert" => &["reflectance"],
            "mirror" => &[],
            "dielectric" => &["ior", "sellmeier"],
            "thin-film" => &["ior", "thickness_nm", "y_range"],
            other => {
                return self.err(
                    m.kind.span(),
                    format!("{what}: unknown material type {other:?} (there are: lambert, mirror, dielectric, thin-film)"),
                );
            }
        };
        let given = [
            ("reflectance", m.reflectance.as_ref().map(Spanned::span)),
            ("ior", m.ior.as_ref().map(Spanned::span)),
            ("sellmeier", m.sellmeier.as_ref().map(Spanned::span)),
            ("thickness_nm", m.thickness_nm.as_ref().map(Spanned::span)),
            ("y_range", m.y_range.as_ref().map(Spanned::span)),
        ];
        self.refuse_keys(
            given.iter().filter(|(key, _)| !allowed.contains(key)),
            &what,
            &format!("{} material", m.kind.get_ref()),
        )?;
        let ior = |x: &Spanned<f64>| -> Result<f64, DataError> {
            let n = self.finite(x, &format!("{what}: ior"))?;
            if n > 0.0 {
                Ok(n)
            } else {
                self.err(x.span(), format!("{what}: ior is {n}; it must be > 0"))
            }
        };
        match m.kind.get_ref().as_str() {
            "lambert" => {
                let r = self.required(&m.reflectance, span, "reflectance")?;
                let reflectance = self.spectrum(r, spectra, &format!("{what}: reflectance"))?;
                if let Some(bad) = reflectance_above_one(&reflectance) {
                    return self.err(
                        r.span(),
                        format!("{what}: reflectance is {bad} somewhere; a Lambertian surface needs values in [0, 1]"),
                    );
                }
                Ok(Material::Lambert { reflectance })
            }
            "mirror" => Ok(Material::Mirror),
            "dielectric" => match (&m.ior, &m.sellmeier) {
                (Some(n), None) => Ok(Material::Dielectric {
                    ior: Ior::Constant(ior(n)?),
                }),
                (None, Some(s)) => match dispersion::catalogue().get(s.get_ref()) {
                    Some(fit) => Ok(Material::Dielectric {
                        ior: Ior::Sellmeier(fit),
                    }),
                    None => {
                        let names: Vec<&str> = dispersion::catalogue()
                            .materials
                            .iter()
                            .map(|m| m.name.as_str())
                            .collect();
                        self.err(
                            s.span(),
                            format!(
                                "{what}: no Sellmeier fit {:?} (there are: {})",
                                s.get_ref(),
                                names.join(", ")
                            ),
                        )
                    }
                },
                _ => self.err(
                    span,
                    format!("{what}: a dielectric needs exactly one of `ior` and `sellmeier`"),
                ),
            },
            _ => {
                let n = ior(self.required(&m.ior, span.clone(), "ior")?)?;
                let t = self.required(&m.thickness_nm, span, "thickness_nm")?;
                let thickness = self.thickness(t, m.y_range.as_ref(), &what)?;
                Ok(Material::ThinFilm { ior: n, thickness })
            }
        }
    }

    fn thickness(
        &self,
        t: &Spanned<toml::Value>,
        y_range: Option<&Spanned<[f64; 2]>>,
        what: &str,
    ) -> Result<Thickness, DataError> {
        let num = |v: &toml::Value| match v {
            toml::Value::Float(x) => Some(*x),
            toml::Value::Integer(x) => Some(*x as f64),
            _ => None,
        };
        let (bottom, top) = match t.get_ref() {
            toml::Value::Array(a) if a.len() == 2 => match (num(&a[0]), num(&a[1])) {
                (Some(b), Some(t)) => (b, t),
                _ => return self.err(t.span(), format!("{what}: thickness_nm must hold numbers")),
            },
            v => match num(v) {
                Some(x) => (x, x),
                None => {
                    return self.err(
                        t.span(),
                        format!("{what}: thickness_nm must be a number or [bottom, top]"),
                    );
                }
            },
        };
        for d in [bottom, top] {
            if !(d.is_finite() && d >= 0.0) {
                return self.err(
                    t.span(),
                    format!("{what}: thickness {d} nm must be finite and >= 0"),
                );
            }
        }
        let y = match y_range {
            Some(r) => {
                let [a, b] = *r.get_ref();
                if !(a.is_finite() && b.is_finite() && a < b) {
                    return self.err(
                        r.span(),
                        format!("{what}: y_range [{a}, {b}] must be finite and increasing"),
                    );
                }
                [a, b]
            }
            None if bottom == top => [0.0, 0.0],
            None => {
                return self.err(
                    t.span(),
                    format!("{what}: a varying thickness needs `y_range`"),
                );
            }
        };
        Ok(Thickness {
            bottom_nm: bottom,
            top_nm: top,
            y,
        })
    }

    fn sphere(
        &self,
        s: &RawShape,
        span: std::ops::Range<usize>,
        what: &str,
    ) -> Result<(DVec3, f64), DataError> {
        let c = self.vec3(
            self.required(&s.center, span.clone(), "center")?,
            &format!("{what} center"),
        )?;
        let r = self.required(&s.radius, span, "radius")?;
        let radius = self.finite(r, &format!("{what} radius"))?;
        if radius <= 0.0 {
            return self.err(
                r.span(),
                format!("{what} radius is {radius}; it must be > 0"),
            );
        }
        Ok((c, radius))
    }

    fn quad(
        &self,
        s: &RawShape,
        span: std::ops::Range<usize>,
        what: &str,
    ) -> Result<QuadLight, DataError> {
        let corner = self.vec3(
            self.required(&s.corner, span.clone(), "corner")?,
            &format!("{what} corner"),
        )?;
        let e1 = self.vec3(
            self.required(&s.edge1, span.clone(), "edge1")?,
            &format!("{what} edge1"),
        )?;
        let e2 = self.vec3(
            self.required(&s.edge2, span.clone(), "edge2")?,
            &format!("{what} edge2"),
        )?;
        QuadLight::new(corner, e1, e2).or_else(|e| {
            // Point at the edge that makes the quad degenerate.
            let at = match e {
                LightError::ZeroLengthEdge("e1") => s.edge1.as_ref(),
                LightError::ZeroLengthEdge(_) | LightError::ParallelEdges => s.edge2.as_ref(),
                _ => None,
            };
            self.err(
                at.map_or(span, Spanned::span),
                format!("{what} is degenerate: {e}"),
            )
        })
    }

    /// Refuses an unknown `type`, and keys that belong to the other kind of shape (or
    /// `emission` on a shape, `material` on a light: `extra` is the one allowed).
    fn keys_for(&self, s: &RawShape, kind: &str, what: &str, extra: &str) -> Result<(), DataError> {
        if kind != "sphere" && kind != "quad" {
            let noun = if extra == "material" {
                "shape"
            } else {
                "light"
            };
            return self.err(
                s.kind.span(),
                format!("unknown {noun} type {kind:?} (there are: sphere, quad)"),
            );
        }
        let sphere = [
            ("center", s.center.as_ref().map(Spanned::span)),
            ("radius", s.radius.as_ref().map(Spanned::span)),
        ];
        let quad = [
            ("corner", s.corner.as_ref().map(Spanned::span)),
            ("edge1", s.edge1.as_ref().map(Spanned::span)),
            ("edge2", s.edge2.as_ref().map(Spanned::span)),
        ];
        let other = [
            ("material", s.material.as_ref().map(Spanned::span)),
            ("emission", s.emission.as_ref().map(Spanned::span)),
        ];
        let wrong = if kind == "sphere" {
            &quad[..]
        } else {
            &sphere[..]
        };
        self.refuse_keys(
            wrong
                .iter()
                .chain(other.iter().filter(|(k, _)| *k != extra)),
            what,
            kind,
        )
    }
}

impl Checker<'_> {
    /// The emission strategy: needs one light with a tabulated spectrum and no environment.
    fn emission_sampling(
        &self,
        span: std::ops::Range<usize>,
        lights: &[Emitter],
        environment: bool,
    ) -> Result<Wavelength, DataError> {
        let why = match (lights, environment) {
            (_, true) => "an environment also emits",
            ([one], false) => match &one.emission {
                Spectrum::Table(t) => {
                    return EmissionSampler::new(&colour_proposal(t))
                        .map(Wavelength::Emission)
                        .or_else(|e| self.err(span, format!("wavelengths = \"emission\": {e}")));
                }
                _ => "its light's spectrum is not a table (a file or a lamp)",
            },
            _ => "it needs exactly one light",
        };
        self.err(
            span,
            format!("wavelengths = \"emission\" cannot be used here: {why}"),
        )
    }
}

/// The largest value of a spectrum above 1, if any (a table's knots, a constant, a
/// blackbody's peak).
fn reflectance_above_one(s: &Spectrum) -> Option<f64> {
    let max = match s {
        Spectrum::Constant(c) => *c,
        Spectrum::Table(t) => t.values().iter().copied().fold(0.0, f64::max),
        Spectrum::Blackbody { peak, .. } => *peak,
    };
    (max > 1.0).then_some(max)
}

/// The 64-bit FNV-1a hash of `bytes`.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

// ANCHOR: parse
/// Reads a scene from the TOML text `text` of the file `file`; relative spectrum file
/// paths are resolved against `dir` (the scene file's folder).
///
/// # Errors
/// A [`DataError`] with the file, the line and the problem, for anything that is not a
/// valid scene; nothing is rendered or written before this succeeds.
pub fn parse(text: &str, file: &str, dir: &Path) -> Result<Scene, DataError> {
    let ck = Checker {
        file,
        text,
        dir: dir.to_path_buf(),
    };
    let raw: RawScene = toml::from_str(text).map_err(|e: toml::de::Error| {
        let line = e.span().map_or(0, |s| ck.line(s));
        DataError::new(file, line, e.message().to_string())
    })?;
    let settings = ck.render(&raw.render)?;
    let camera = ck.camera(&raw.camera)?;
    let mut spectra = BTreeMap::new();
    for (name, v) in &raw.spectra {
        let s = ck.spectrum(v, &spectra, &format!("spectrum {name:?}"))?;
        spectra.insert(name.clone(), s);
    }
    let mut names = Vec::new();
    let mut materials = Vec::new();
    for (name, m) in &raw.materials {
        materials.push(ck.material(name, m, &spectra)?);
        names.push(name.clone());
    }
    let mut shapes = Vec::new();
    for (i, s) in raw.shape.iter().enumerate() {
        let span = s.span();
        let s = s.get_ref();
        let what = format!("shape {} ({})", i + 1, s.kind.get_ref());
        ck.keys_for(s, s.kind.get_ref(), &what, "material")?;
        let geometry = match s.kind.get_ref().as_str() {
            "sphere" => {
                let (c, r) = ck.sphere(s, span.clone(), &what)?;
                Geometry::Sphere(Sphere::new(c, r))
            }
            // keys_for has refused any other type.
            _ => Geometry::Quad(ck.quad(s, span.clone(), &what)?),
        };
        let m = ck.required(&s.material, span, "material")?;
        let Some(material) = names.iter().position(|n| n == m.get_ref()) else {
            return ck.err(
                m.span(),
                format!(
                    "{what}: unknown material {:?} (there are: {})",
                    m.get_ref(),
                    if names.is_empty() {
                        "none".into()
                    } else {
                        names.join(", ")
                    }
                ),
            );
        };
        shapes.push(Shape { geometry, material });
    }
    let mut lights = Vec::new();
    for (i, l) in raw.light.iter().enumerate() {
        let span = l.span();
        let l = l.get_ref();
        let what = format!("light {} ({})", i + 1, l.kind.get_ref());
        ck.keys_for(l, l.kind.get_ref(), &what, "emission")?;
        let shape = match l.kind.get_ref().as_str() {
            "sphere" => {
                let (c, r) = ck.sphere(l, span.clone(), &what)?;
                LightShape::Sphere(
                    SphereLight::new(c, r)
                        .or_else(|e| ck.err(span.clone(), format!("{what}: {e}")))?,
                )
            }
            _ => LightShape::Quad(ck.quad(l, span.clone(), &what)?),
        };
        let e = ck.required(&l.emission, span, "emission")?;
        let emission = ck.spectrum(e, &spectra, &format!("{what} emission"))?;
        lights.push(Emitter { shape, emission });
    }
    let environment = match &raw.environment {
        Some(env) => {
            Some(ck.spectrum(&env.get_ref().emission, &spectra, "environment emission")?)
        }
        None => None,
    };
    let mut settings = settings;
    if let Some(w) = &raw.render.get_ref().wavelengths
        && w.get_ref() == "emission"
    {
        settings.wavelengths = ck.emission_sampling(w.span(), &lights, environment.is_some())?;
    }
    if shapes.is_empty() && lights.is_empty() {
        return Err(DataError::new(
            file,
            0,
            "the scene has no shape and no light",
        ));
    }
    Ok(Scene {
        camera,
        settings,
        materials,
        shapes,
        lights,
        environment,
        hash: fnv1a(text.as_bytes()),
    })
}
// ANCHOR_END: parse

/// Reads the scene file at `path`.
///
/// # Errors
/// If the file cannot be read, or as [`parse`].
pub fn load(path: &Path) -> Result<Scene, DataError> {
    let (text, name) = crate::data::read_text(path)?;
    let dir = path
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    parse(&text, &name, &dir)
}
