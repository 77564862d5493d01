//! A scene as a pbrt-v4 scene file, following the rules checked against pbrt-v4's source
//! and file-format documentation in `tools/pbrt/NOTES.md` (not by rendering: the project
//! has not run pbrt-v4). Chapter: *Reference scenes and interop*
//! (`chapters/renderer/scenes.md`, *Exporting a scene*).
//!
//! * Spectra are inline `"spectrum NAME" [ λ v λ v ... ]`, which pbrt reads as a
//!   `PiecewiseLinearSpectrum`: linear between knots and zero outside, as raylemma's
//!   tables. A table keeps its own knots, a constant is two knots at 300 and 900 nm
//!   (beyond the 360-830 nm that pbrt samples), a blackbody is tabulated at every
//!   nanometre of 360-830.
//! * pbrt divides an emitter's `scale` by `SpectrumToPhotometric(L)`, the sum of `ȳ(λ) L(λ)`
//!   over the whole nanometres of 360-830 (`DiffuseAreaLight::Create`, the `infinite`
//!   light in `Light::Create`). Each emitter is therefore written with `"float scale"` =
//!   that same sum, computed here from the 1 nm CIE table, so that pbrt's radiance is
//!   raylemma's absolute spectrum. An emitter that is zero everywhere is left out (its
//!   shape stays, black); one whose sum is zero but which is not zero is refused.
//! * The film is `"rgb"` with the `cie1931` sensor and `"float iso"` = 100 / raylemma's
//!   `∫ȳ`: pbrt's sensor records `∫ x̄ L dλ` (no normalisation of its own) times
//!   `iso / 100`, so its XYZ is raylemma's. pbrt writes linear sRGB by its own matrix, whose
//!   white is the chromaticity of pbrt's D65 table, (0.312727, 0.329023); raylemma's linear
//!   sRGB is a per-channel factor of it (written in the file's header comment).
//! * The camera is `Scale -1 1 1` then `LookAt` (pbrt's image right is `up x forward`,
//!   raylemma's `forward x up`), `perspective` with `fov` the angle of the shorter image
//!   axis, a box filter of radius 0.5, and the `independent` sampler.
//! * The integrator is `path` with `maxdepth` = raylemma's `max_depth` (pbrt counts
//!   bounces and makes no light sample at the last vertex, as raylemma), `regularize`
//!   false. pbrt's Russian roulette, from the second bounce, cannot be set; it changes the
//!   noise, not the expected image.
//! * Lambertian is `diffuse`, a mirror a `conductor` with `eta` 0 and `k` 1 (reflectance 1
//!   at every angle; pbrt's `reflectance` parameter is clamped to 0.9999), a dielectric
//!   `dielectric` with `"float eta"` or, for Sellmeier glass, `"spectrum eta"` at every
//!   nanometre (pbrt then follows the hero wavelength alone). pbrt's BSDFs are two-sided.
//! * A quad is a `trianglemesh` of the triangles `(c, c+e1, c+e1+e2)`, `(c, c+e1+e2, c+e2)`,
//!   whose normal is `e1 x e2`; a quad light is one-sided towards it, as raylemma's. A
//!   sphere is `Translate` and `Shape "sphere"`; a sphere light is one-sided, emitting
//!   outwards only, as raylemma's. Every light has a black `diffuse` material.
//!
//! Refused, with the line: thin films (no pbrt-v4 material models interference), a
//! gradient sky (pbrt's `infinite` light is one spectrum or an RGB image), and a dielectric
//! quad (pbrt scales radiance by `1/η²` on refraction and raylemma does not, which agree
//! only for closed shapes that paths leave again).

use std::fmt::Write as _;

use glam::{DMat3, DVec2, DVec3};

use super::{SceneFile, grid};
use crate::data::DataError;
use crate::render::scene::{Environment, Geometry, Ior, LightShape, Material};
use crate::spectral::cie;
use crate::spectral::spectrum::Spectrum;

/// The chromaticity of pbrt-v4's D65 table (`stdillum-D65`, its `CIE_Illum_D6500`) under
/// the 1 nm CIE 1931 functions, the white of its sRGB colour space (`RGBColorSpace`'s
/// constructor): computed in `tools/pbrt/NOTES.md`, §6.
pub(crate) const PBRT_D65_WHITE: DVec2 = DVec2::new(0.312_726_932, 0.329_023_222);

/// The matrix taking pbrt's linear sRGB (what its `rgb` film writes) to raylemma's: pbrt's
/// RGB → XYZ (sRGB primaries, [`PBRT_D65_WHITE`]), then raylemma's XYZ → linear sRGB. It
/// is diagonal to rounding (both share the primaries), within 2.5e-4 of the identity.
pub(crate) fn pbrt_to_raylemma_srgb() -> DMat3 {
    cie::xyz_to_linear_srgb_matrix() * cie::rgb_to_xyz_matrix(cie::SRGB_PRIMARIES, PBRT_D65_WHITE)
}

/// The largest term of `m` off its diagonal, in magnitude.
fn off_diagonal(m: DMat3) -> f64 {
    let mut big: f64 = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            if i != j {
                big = big.max(m.col(j)[i].abs());
            }
        }
    }
    big
}

/// A number as pbrt reads it (the shortest decimal that reads back as the same double).
fn num(x: f64) -> String {
    format!("{x}")
}

fn vec3(v: DVec3) -> String {
    format!("{} {} {}", num(v.x), num(v.y), num(v.z))
}

/// A name fit for a `#` comment (one line).
fn comment(s: &str) -> String {
    s.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

/// The knots pbrt gets for `s`: a table's own, a constant at 300 and 900 nm, a blackbody
/// at every nanometre of 360-830.
pub fn knots(s: &Spectrum) -> (Vec<f64>, Vec<f64>) {
    match s {
        Spectrum::Constant(c) => (vec![300.0, 900.0], vec![*c, *c]),
        Spectrum::Table(t) => (t.wavelengths().to_vec(), t.values().to_vec()),
        Spectrum::Blackbody { .. } => {
            let nm: Vec<f64> = grid().collect();
            let values = nm.iter().map(|&l| s.eval(l)).collect();
            (nm, values)
        }
    }
}

/// `"spectrum NAME" [ λ v ... ]`, eight pairs a line.
fn spectrum_param(name: &str, nm: &[f64], values: &[f64], indent: &str) -> String {
    let pairs: Vec<String> = nm
        .iter()
        .zip(values)
        .map(|(&l, &v)| format!("{} {}", num(l), num(v)))
        .collect();
    let lines: Vec<String> = pairs.chunks(8).map(|c| c.join("  ")).collect();
    if lines.len() == 1 {
        format!("{indent}\"spectrum {name}\" [ {} ]\n", lines[0])
    } else {
        format!(
            "{indent}\"spectrum {name}\" [\n{indent}    {}\n{indent}]\n",
            lines.join(&format!("\n{indent}    "))
        )
    }
}

fn spectrum(name: &str, s: &Spectrum, indent: &str) -> String {
    let (nm, values) = knots(s);
    spectrum_param(name, &nm, &values, indent)
}

/// pbrt's `SpectrumToPhotometric` of `s` as pbrt evaluates the written spectrum: the sum
/// of `ȳ(λ) s(λ)` over the whole nanometres of 360-830 (the CIE table at 1 nm).
pub fn photometric(s: &Spectrum) -> f64 {
    grid()
        .enumerate()
        .map(|(i, l)| cie::cmf_row(i).y * s.eval(l))
        .sum()
}

/// Whether `s` is zero at every wavelength.
fn is_zero(s: &Spectrum) -> bool {
    match s {
        Spectrum::Constant(c) => *c == 0.0,
        Spectrum::Table(t) => t.values().iter().all(|&v| v == 0.0),
        Spectrum::Blackbody { .. } => false,
    }
}

/// The `"float scale"` that makes pbrt emit `s` itself, or `None` if `s` is zero
/// everywhere (the emitter is left out); refused if pbrt would divide by zero.
fn scale(f: &SceneFile, s: &Spectrum, line: usize, what: &str) -> Result<Option<f64>, DataError> {
    if is_zero(s) {
        return Ok(None);
    }
    let k = photometric(s);
    if k > 0.0 && k.is_finite() {
        Ok(Some(k))
    } else {
        Err(f.error(
            line,
            format!(
                "{what} has no luminance at the whole nanometres of 360-830 nm (the sum of ȳ L is {k}) but is not zero: pbrt-v4 divides an emitter by that sum and keeps its spectrum only at whole nanometres; {BEYOND}"
            ),
        ))
    }
}

const BEYOND: &str = "pbrt-v4 cannot express it the same way (export --to json keeps it)";

/// Refuses what pbrt-v4 cannot express the same way, with the line where it is written.
fn check(f: &SceneFile) -> Result<(), DataError> {
    let s = &f.scene;
    for (m, (name, line)) in s.materials.iter().zip(&f.materials) {
        if let Material::ThinFilm { .. } = m {
            return Err(f.error(
                *line,
                format!(
                    "material {name:?} is a thin film with interference: no pbrt-v4 material models thin-film interference (thindielectric is an incoherent slab); {BEYOND}"
                ),
            ));
        }
    }
    if let Some(Environment::Gradient { .. }) = &s.environment {
        return Err(f.error(
            f.environment_line,
            format!(
                "the environment is a gradient sky: pbrt-v4's infinite light is one spectrum for every direction, or an RGB image; {BEYOND}"
            ),
        ));
    }
    for (m, (name, line)) in s.materials.iter().zip(&f.materials) {
        if let Material::Dielectric {
            ior: Ior::Sellmeier(fit),
        } = m
            && let Some(l) = grid().find(|&l| !(fit.index(l) > 0.0 && fit.index(l).is_finite()))
        {
            return Err(f.error(
                *line,
                format!(
                    "material {name:?}: the Sellmeier fit {} has no finite positive index at {l} nm, which pbrt-v4's spectral eta needs at every nanometre of 360-830; {BEYOND}",
                    fit.name
                ),
            ));
        }
    }
    for (i, sh) in s.shapes.iter().enumerate() {
        if let Geometry::Quad(_) = sh.geometry
            && matches!(s.materials[sh.material], Material::Dielectric { .. })
        {
            return Err(f.error(
                f.shape_lines[i],
                format!(
                    "shape {} is a dielectric quad: pbrt-v4 scales radiance by 1/η² on refraction and raylemma does not, which agree only for closed shapes that every path leaves again (spheres); {BEYOND}",
                    i + 1
                ),
            ));
        }
    }
    Ok(())
}

fn material(m: &Material, id: &str, name: &str) -> String {
    let head = format!(
        "# material {:?}\nMakeNamedMaterial \"{id}\"\n",
        comment(name)
    );
    let body = match m {
        Material::Lambert { reflectance } => format!(
            "    \"string type\" [ \"diffuse\" ]\n{}",
            spectrum("reflectance", reflectance, "    ")
        ),
        // eta 0, k 1: both Fresnel ratios have numerator and denominator of equal modulus.
        Material::Mirror => format!(
            "    \"string type\" [ \"conductor\" ]\n{}{}    \"float roughness\" [ 0 ]\n",
            spectrum_param("eta", &[300.0, 900.0], &[0.0, 0.0], "    "),
            spectrum_param("k", &[300.0, 900.0], &[1.0, 1.0], "    ")
        ),
        Material::Dielectric { ior } => {
            let eta = match ior {
                Ior::Constant(n) => format!("    \"float eta\" [ {} ]\n", num(*n)),
                Ior::Sellmeier(fit) => {
                    let nm: Vec<f64> = grid().collect();
                    let values: Vec<f64> = nm.iter().map(|&l| fit.index(l)).collect();
                    format!(
                        "    # Sellmeier {}, at every nanometre\n{}",
                        comment(&fit.name),
                        spectrum_param("eta", &nm, &values, "    ")
                    )
                }
            };
            format!("    \"string type\" [ \"dielectric\" ]\n{eta}    \"float roughness\" [ 0 ]\n")
        }
        // `check` has refused thin films.
        Material::ThinFilm { .. } => String::new(),
    };
    head + &body + "\n"
}

/// The two triangles of the quad `corner + a e1 + b e2`, wound so that pbrt's normal
/// (`Cross(p1 - p0, p2 - p0)`, `Triangle::Sample`) is along `e1 x e2`.
pub(crate) fn quad_mesh(corner: DVec3, e1: DVec3, e2: DVec3) -> ([DVec3; 4], [usize; 6]) {
    (
        [corner, corner + e1, corner + e1 + e2, corner + e2],
        [0, 1, 2, 0, 2, 3],
    )
}

fn mesh(corner: DVec3, e1: DVec3, e2: DVec3) -> String {
    let (p, idx) = quad_mesh(corner, e1, e2);
    let points: Vec<String> = p.iter().map(|&v| vec3(v)).collect();
    let idx: Vec<String> = idx.iter().map(usize::to_string).collect();
    format!(
        "    Shape \"trianglemesh\"\n        \"point3 P\" [ {} ]\n        \"integer indices\" [ {} ]\n",
        points.join("  "),
        idx.join(" ")
    )
}

fn sphere(center: DVec3, radius: f64) -> String {
    format!(
        "    Translate {}\n    Shape \"sphere\" \"float radius\" [ {} ]\n",
        vec3(center),
        num(radius)
    )
}

// ANCHOR: to_pbrt
/// The scene as a pbrt-v4 scene file (see the module's documentation).
///
/// # Errors
/// What pbrt-v4 cannot express the same way, as a [`DataError`] with the line where it is
/// written.
pub fn to_pbrt(f: &SceneFile) -> Result<String, DataError> {
    check(f)?;
    let s = &f.scene;
    let set = &s.settings;
    let cam = &s.camera;
    let c = pbrt_to_raylemma_srgb();
    let mut x = String::new();
    let _ = write!(
        x,
        "# Exported by raylemma {} from {} (scene hash {:016x}).\n\
         # Render it with: pbrt --spp {} --seed {} --outfile OUT.exr FILE.pbrt\n\
         # (--seed sets the sampler's seed: the file does not, so that runs can differ.)\n\
         # OUT.exr has channels R, G, B: linear sRGB by pbrt's matrix, whose white is its D65 table's\n\
         # (0.312727, 0.329023), of raylemma's CIE XYZ (1 nm CIE 1931 / its integral of y-bar, {}).\n\
         # raylemma's linear sRGB is R x {}, G x {}, B x {} (its other terms are at most {:.1e}).\n\
         # raylemma's wavelength strategy ({}), direct lighting ({}) and roulette depth ({}) change\n\
         # the noise, not the expected image. Rules: tools/pbrt/NOTES.md in raylemma's repository.\n\n",
        env!("CARGO_PKG_VERSION"),
        comment(&f.file),
        s.hash,
        set.spp,
        set.seed,
        num(cie::y_integral()),
        num(c.x_axis.x),
        num(c.y_axis.y),
        num(c.z_axis.z),
        off_diagonal(c),
        set.wavelengths.name(),
        super::direct_name(set.direct),
        set.roulette_depth,
    );
    // pbrt's shorter image axis spans the `fov`.
    let half = (cam.fov_y_deg.to_radians() / 2.0).tan();
    let fov = if cam.width < cam.height {
        (2.0 * (half * f64::from(cam.width) / f64::from(cam.height)).atan()).to_degrees()
    } else {
        cam.fov_y_deg
    };
    let _ = write!(
        x,
        "# The camera: pbrt's image right is up x forward, raylemma's forward x up.\n\
         Scale -1 1 1\n\
         LookAt {}\n       {}\n       {}\n\
         Camera \"perspective\" \"float fov\" [ {} ]\n\
         Sampler \"independent\" \"integer pixelsamples\" [ {} ]\n\
         PixelFilter \"box\" \"float xradius\" [ 0.5 ] \"float yradius\" [ 0.5 ]\n\
         Film \"rgb\"\n    \"integer xresolution\" [ {} ]\n    \"integer yresolution\" [ {} ]\n    \
         \"string sensor\" [ \"cie1931\" ]\n    \"float iso\" [ {} ]\n    \"bool savefp16\" [ false ]\n\
         Integrator \"path\" \"integer maxdepth\" [ {} ] \"bool regularize\" [ false ]\n\n\
         WorldBegin\n\n",
        vec3(cam.position),
        vec3(cam.look_at),
        vec3(cam.up),
        num(fov),
        set.spp,
        cam.width,
        cam.height,
        num(100.0 / cie::y_integral()),
        set.max_depth,
    );
    for (i, (m, (name, _))) in s.materials.iter().zip(&f.materials).enumerate() {
        x += &material(m, &format!("material-{i}"), name);
    }
    for (i, sh) in s.shapes.iter().enumerate() {
        let _ = writeln!(x, "# shape {}\nAttributeBegin", i + 1);
        let _ = writeln!(x, "    NamedMaterial \"material-{}\"", sh.material);
        match sh.geometry {
            Geometry::Quad(q) => {
                let [e1, e2] = q.edges();
                x += &mesh(q.corner(), e1, e2);
            }
            Geometry::Sphere(sp) => x += &sphere(sp.center, sp.radius),
        }
        x += "AttributeEnd\n\n";
    }
    for (i, l) in s.lights.iter().enumerate() {
        let line = f.light_lines.get(i).copied().unwrap_or(0);
        let k = scale(f, &l.emission, line, &format!("light {}", i + 1))?;
        let (geometry, sides) = match &l.shape {
            LightShape::Quad(q) => {
                let [e1, e2] = q.shape().edges();
                (
                    mesh(q.shape().corner(), e1, e2),
                    "one-sided, towards edge1 x edge2",
                )
            }
            LightShape::Sphere(sp) => (sphere(sp.center(), sp.radius()), "one-sided: outwards"),
        };
        let _ = writeln!(
            x,
            "# light {}: {sides}; reflects nothing\nAttributeBegin",
            i + 1
        );
        x += "    Material \"diffuse\" \"spectrum reflectance\" [ 300 0 900 0 ]\n";
        if let Some(k) = k {
            x += "    AreaLightSource \"diffuse\"\n";
            x += &spectrum("L", &l.emission, "        ");
            let _ = writeln!(x, "        \"float scale\" [ {} ]", num(k));
        }
        x += &geometry;
        x += "AttributeEnd\n\n";
    }
    if let Some(Environment::Constant(e)) = &s.environment
        && let Some(k) = scale(f, e, f.environment_line, "the environment")?
    {
        x +=
            "# the environment: the same spectrum from every direction\nLightSource \"infinite\"\n";
        x += &spectrum("L", e, "    ");
        let _ = writeln!(x, "    \"float scale\" [ {} ]", num(k));
    }
    Ok(x)
}
// ANCHOR_END: to_pbrt
