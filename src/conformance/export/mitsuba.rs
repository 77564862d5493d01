//! A scene as a Mitsuba 3 XML file (`<scene version="3.0.0">`) that `mitsuba.load_file`
//! renders unchanged in a spectral variant, following the rules checked against Mitsuba
//! 3.9.1 in `tools/mitsuba/NOTES.md`. Chapter: *Reference scenes and interop*
//! (`chapters/renderer/scenes.md`, *Exporting a scene*).
//!
//! * Spectra are written inline as `irregular` spectra with every knot (a constant as a
//!   `uniform` value, a blackbody tabulated at 1 nm): linear between knots and zero
//!   outside, as raylemma's tables. An emitter's radiance is always a `<spectrum>` (a
//!   `<float>` or `<rgb>` would become Mitsuba's D65 illuminant).
//! * A quad is a `rectangle` whose `to_world` matrix has the columns
//!   `[e1/2 | e2/2 | n | c + (e1 + e2)/2]`, `n` the unit `e1 x e2`; a light quad has an
//!   `area` emitter, one-sided towards `n` as raylemma's, and a black `diffuse`.
//! * Lambertian is `twosided(diffuse)`, a mirror `twosided(conductor, material = none)`
//!   (reflectance exactly 1), a dielectric `int_ior` = its index with `ext_ior` = 1 (the
//!   default is air's 1.000277).
//! * The integrator is `path` with `rr_depth` = raylemma's `roulette_depth` (at least 1)
//!   and `max_depth` = raylemma's `max_depth + 1` (Mitsuba counts segments, raylemma
//!   bounces; both sample a light only where the next segment is traced too, so the two
//!   count the same paths).
//! * The camera is `perspective` with `fov_axis = "y"`, a box filter, and far enough a far
//!   clip; the film is a `specfilm` whose three sensor responses are the 1 nm CIE 1931
//!   functions divided by raylemma's `∫ȳ`, so that its channels `X`, `Y`, `Z` are
//!   raylemma's XYZ exactly; linear sRGB is raylemma's matrix times them (written in the
//!   file's header comment).
//!
//! Refused, with the line: Sellmeier dispersion and thin films (no Mitsuba BSDF has
//! them), a gradient sky, and a dielectric quad (Mitsuba scales radiance by `1/η²` on
//! refraction and raylemma does not: the two agree only for closed shapes that paths
//! leave again). A sphere light emits outwards only in both renderers, and its black
//! `diffuse` reflects nothing on either side, so what lies inside one needs no refusal.
//! A camera or a light inside a dielectric sphere, where the `η²` would not cancel
//! either, never reaches the exporter: the scene's checks refuse it.

use std::fmt::Write as _;

use glam::DVec3;

use super::{SceneFile, extent};
use crate::data::DataError;
use crate::render::scene::{Environment, Geometry, Ior, LightShape, Material};
use crate::spectral::cie;
use crate::spectral::spectrum::Spectrum;

/// A number as Mitsuba reads it (the shortest decimal that reads back as the same
/// double).
fn num(x: f64) -> String {
    format!("{x}")
}

fn vec3(v: DVec3) -> String {
    format!("{}, {}, {}", num(v.x), num(v.y), num(v.z))
}

/// A name fit for an XML comment (no `--`).
fn comment(s: &str) -> String {
    s.replace("--", "- -")
}

/// `<spectrum name="NAME" .../>`: a constant as a uniform value, a table with every knot,
/// a blackbody at every nanometre.
fn spectrum(name: &str, s: &Spectrum, indent: &str) -> String {
    let (nm, values): (Vec<f64>, Vec<f64>) = match s {
        Spectrum::Constant(c) => {
            return format!(
                "{indent}<spectrum name=\"{name}\" value=\"{}\"/>\n",
                num(*c)
            );
        }
        Spectrum::Table(t) => (t.wavelengths().to_vec(), t.values().to_vec()),
        Spectrum::Blackbody { .. } => {
            let nm: Vec<f64> = super::grid().collect();
            let values = nm.iter().map(|&l| s.eval(l)).collect();
            (nm, values)
        }
    };
    irregular(name, &nm, &values, indent)
}

fn irregular(name: &str, nm: &[f64], values: &[f64], indent: &str) -> String {
    let join = |xs: &[f64]| xs.iter().map(|&x| num(x)).collect::<Vec<_>>().join(", ");
    format!(
        "{indent}<spectrum name=\"{name}\" type=\"irregular\">\n{indent}    <string name=\"wavelengths\" value=\"{}\"/>\n{indent}    <string name=\"values\" value=\"{}\"/>\n{indent}</spectrum>\n",
        join(nm),
        join(values)
    )
}

/// The `to_world` of a `rectangle` ([-1, 1]² in local xy, normal +z) onto the quad
/// `corner + a e1 + b e2`: the columns `e1/2`, `e2/2`, the unit normal, the centre; the 16
/// numbers row by row.
pub(crate) fn rectangle_matrix(corner: DVec3, e1: DVec3, e2: DVec3) -> [f64; 16] {
    let n = e1.cross(e2).normalize();
    let c = corner + 0.5 * (e1 + e2);
    let cols = [0.5 * e1, 0.5 * e2, n, c];
    let mut m = [0.0; 16];
    for (j, col) in cols.iter().enumerate() {
        for i in 0..3 {
            m[4 * i + j] = col[i];
        }
    }
    m[15] = 1.0;
    m
}

fn rectangle(corner: DVec3, e1: DVec3, e2: DVec3, indent: &str) -> String {
    let m = rectangle_matrix(corner, e1, e2);
    let values: Vec<String> = m.iter().map(|&x| num(x)).collect();
    format!(
        "{indent}<transform name=\"to_world\">\n{indent}    <matrix value=\"{}\"/>\n{indent}</transform>\n",
        values.join(" ")
    )
}

fn sphere(center: DVec3, radius: f64, indent: &str) -> String {
    format!(
        "{indent}<point name=\"center\" x=\"{}\" y=\"{}\" z=\"{}\"/>\n{indent}<float name=\"radius\" value=\"{}\"/>\n",
        num(center.x),
        num(center.y),
        num(center.z),
        num(radius)
    )
}

/// Refuses what Mitsuba cannot express, with the line where it is written.
fn check(f: &SceneFile) -> Result<(), DataError> {
    let s = &f.scene;
    let beyond = "Mitsuba 3 cannot express it (export --to json keeps it)";
    for (m, (name, line)) in s.materials.iter().zip(&f.materials) {
        match m {
            Material::Dielectric {
                ior: Ior::Sellmeier(fit),
            } => {
                return Err(f.error(
                    *line,
                    format!(
                        "material {name:?} has Sellmeier dispersion ({}): Mitsuba's dielectrics have one index of refraction for all wavelengths; {beyond}",
                        fit.name
                    ),
                ));
            }
            Material::ThinFilm { .. } => {
                return Err(f.error(
                    *line,
                    format!(
                        "material {name:?} is a thin film with interference: no Mitsuba BSDF models thin-film interference (thindielectric is an incoherent slab); {beyond}"
                    ),
                ));
            }
            _ => {}
        }
    }
    if let Some(Environment::Gradient { .. }) = &s.environment {
        return Err(f.error(
            f.environment_line,
            format!("the environment is a gradient sky: Mitsuba's constant emitter is one spectrum, and an envmap is an RGB image; {beyond}"),
        ));
    }
    let dielectric = |i: usize| matches!(s.materials[i], Material::Dielectric { .. });
    for (i, sh) in s.shapes.iter().enumerate() {
        if matches!(sh.geometry, Geometry::Quad(_)) && dielectric(sh.material) {
            return Err(f.error(
                f.shape_lines[i],
                format!("shape {} is a dielectric quad: Mitsuba scales radiance by 1/η² on refraction and raylemma does not, which agree only for closed shapes that every path leaves again (spheres); {beyond}", i + 1),
            ));
        }
    }
    Ok(())
}

fn bsdf(m: &Material, id: &str, name: &str) -> String {
    let head = format!("    <!-- material {:?} -->\n", comment(name));
    head + &match m {
        Material::Lambert { reflectance } => format!(
            "    <bsdf type=\"twosided\" id=\"{id}\">\n        <bsdf type=\"diffuse\">\n{}        </bsdf>\n    </bsdf>\n",
            spectrum("reflectance", reflectance, "            ")
        ),
        Material::Mirror => format!(
            "    <bsdf type=\"twosided\" id=\"{id}\">\n        <bsdf type=\"conductor\">\n            <string name=\"material\" value=\"none\"/>\n        </bsdf>\n    </bsdf>\n"
        ),
        Material::Dielectric { ior } => format!(
            "    <bsdf type=\"dielectric\" id=\"{id}\">\n        <float name=\"int_ior\" value=\"{}\"/>\n        <float name=\"ext_ior\" value=\"1\"/>\n    </bsdf>\n",
            num(ior.at(550.0))
        ),
        // `check` has refused thin films.
        Material::ThinFilm { .. } => String::new(),
    }
}

// ANCHOR: to_xml
/// The scene as a Mitsuba 3 XML file (see the module's documentation).
///
/// # Errors
/// What Mitsuba cannot express, as a [`DataError`] with the line where it is written.
pub fn to_xml(f: &SceneFile) -> Result<String, DataError> {
    check(f)?;
    let s = &f.scene;
    let set = &s.settings;
    let cam = &s.camera;
    let m = cie::xyz_to_linear_srgb_matrix();
    let row = |i: usize| {
        format!(
            "[{}, {}, {}]",
            num(m.row(i).x),
            num(m.row(i).y),
            num(m.row(i).z)
        )
    };
    let mut x = String::new();
    let _ = write!(
        x,
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n\
         <!-- Exported by raylemma {} from {} (scene hash {:016x}).\n     \
         Render it with mitsuba.load_file(path, spp=N, seed=S) in a spectral variant (scalar_spectral, llvm_ad_spectral).\n     \
         The film's channels X, Y, Z are raylemma's CIE XYZ (the 1 nm CIE 1931 table / its integral of y-bar, {}):\n     \
         linear sRGB = M (X, Y, Z) with M = [{}, {}, {}] (rows).\n     \
         raylemma's wavelength strategy ({}) and direct lighting ({}) change the noise, not the expected image. -->\n\
         <scene version=\"3.0.0\">\n",
        env!("CARGO_PKG_VERSION"),
        comment(&f.file),
        s.hash,
        num(cie::y_integral()),
        row(0),
        row(1),
        row(2),
        set.wavelengths.name(),
        super::direct_name(set.direct),
    );
    let _ = write!(
        x,
        "    <default name=\"spp\" value=\"{}\"/>\n    <default name=\"seed\" value=\"{}\"/>\n\n",
        set.spp, set.seed
    );
    let _ = write!(
        x,
        "    <integrator type=\"path\">\n        <integer name=\"max_depth\" value=\"{}\"/>\n        <integer name=\"rr_depth\" value=\"{}\"/>\n    </integrator>\n\n",
        u64::from(set.max_depth) + 1,
        set.roulette_depth.max(1)
    );
    let distance = (cam.look_at - cam.position).length();
    let far = (10.0 * extent(s, cam.position)).max(1e4);
    let near = (1e-3 * distance).min(1e-2);
    let _ = write!(
        x,
        "    <sensor type=\"perspective\">\n        <float name=\"fov\" value=\"{}\"/>\n        <string name=\"fov_axis\" value=\"y\"/>\n        <float name=\"near_clip\" value=\"{}\"/>\n        <float name=\"far_clip\" value=\"{}\"/>\n        <transform name=\"to_world\">\n            <lookat origin=\"{}\" target=\"{}\" up=\"{}\"/>\n        </transform>\n        <sampler type=\"independent\">\n            <integer name=\"sample_count\" value=\"$spp\"/>\n            <integer name=\"seed\" value=\"$seed\"/>\n        </sampler>\n        <film type=\"specfilm\">\n            <integer name=\"width\" value=\"{}\"/>\n            <integer name=\"height\" value=\"{}\"/>\n            <string name=\"component_format\" value=\"float32\"/>\n            <rfilter type=\"box\"/>\n",
        num(cam.fov_y_deg),
        num(near),
        num(far),
        vec3(cam.position),
        vec3(cam.look_at),
        vec3(cam.up),
        cam.width,
        cam.height
    );
    let nm: Vec<f64> = super::grid().collect();
    let k = 1.0 / cie::y_integral();
    for (c, name) in ["X", "Y", "Z"].iter().enumerate() {
        let values: Vec<f64> = (0..nm.len()).map(|i| cie::cmf_row(i)[c] * k).collect();
        x += &irregular(name, &nm, &values, "            ");
    }
    x += "        </film>\n    </sensor>\n\n";
    for (i, (mat, (name, _))) in s.materials.iter().zip(&f.materials).enumerate() {
        x += &bsdf(mat, &format!("material-{i}"), name);
    }
    x += "\n";
    for (i, sh) in s.shapes.iter().enumerate() {
        let r = format!(
            "        <ref id=\"material-{}\"/>\n    </shape>\n",
            sh.material
        );
        let _ = writeln!(x, "    <!-- shape {} -->", i + 1);
        match sh.geometry {
            Geometry::Quad(q) => {
                let [e1, e2] = q.edges();
                x += "    <shape type=\"rectangle\">\n";
                x += &rectangle(q.corner(), e1, e2, "        ");
            }
            Geometry::Sphere(sp) => {
                x += "    <shape type=\"sphere\">\n";
                x += &sphere(sp.center, sp.radius, "        ");
            }
        }
        x += &r;
    }
    for (i, l) in s.lights.iter().enumerate() {
        let _ = writeln!(
            x,
            "    <!-- light {}: emits on the side of its normal, reflects nothing -->",
            i + 1
        );
        match &l.shape {
            LightShape::Quad(q) => {
                let [e1, e2] = q.shape().edges();
                x += "    <shape type=\"rectangle\">\n";
                x += &rectangle(q.shape().corner(), e1, e2, "        ");
            }
            LightShape::Sphere(sp) => {
                x += "    <shape type=\"sphere\">\n";
                x += &sphere(sp.center(), sp.radius(), "        ");
            }
        }
        x += "        <bsdf type=\"diffuse\">\n            <spectrum name=\"reflectance\" value=\"0\"/>\n        </bsdf>\n";
        x += "        <emitter type=\"area\">\n";
        x += &spectrum("radiance", &l.emission, "            ");
        x += "        </emitter>\n    </shape>\n";
    }
    if let Some(Environment::Constant(e)) = &s.environment {
        x += "\n    <emitter type=\"constant\">\n";
        x += &spectrum("radiance", e, "        ");
        x += "    </emitter>\n";
    }
    x += "</scene>\n";
    Ok(x)
}
// ANCHOR_END: to_xml
