//! Tests of `export` (`src/render/export/`; chapter *Reference scenes and interop*, *Exporting a
//! scene*): the JSON is fully resolved (defaults, 1 nm spectra equal to the data files,
//! explicit transforms); the Mitsuba XML follows the rules checked against Mitsuba in
//! `tools/mitsuba/NOTES.md`; what Mitsuba cannot express is refused with its line and
//! kept by the JSON. Every expected value comes from the data files, the NOTES or
//! arithmetic done here, never from the exporter. That Mitsuba renders the files is the
//! job of `tools/mitsuba/compare_all.sh`, outside `cargo test`. The pbrt-v4 file follows the
//! rules of `tools/pbrt/NOTES.md` (checked against pbrt-v4's source, not by rendering): a
//! small tokenizer here checks its syntax and reads its numbers back.

use std::path::Path;

use raylemma::render::export::{SceneFile, json::to_json, mitsuba::to_xml, pbrt::to_pbrt};
use serde_json::Value;

use crate::support::root;

fn load(name: &str) -> SceneFile {
    SceneFile::load(&root().join("scenes").join(name)).unwrap_or_else(|e| panic!("{e}"))
}

fn json_of(name: &str) -> Value {
    serde_json::from_str(&to_json(&load(name))).unwrap()
}

/// The columns of a CSV of `data/` by name (header, then numbers).
fn csv(file: &str) -> Vec<(String, Vec<f64>)> {
    let text = std::fs::read_to_string(root().join("data").join(file)).unwrap();
    let mut lines = text
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#'));
    let names: Vec<String> = lines
        .next()
        .unwrap()
        .split(',')
        .map(|s| s.trim().to_string())
        .collect();
    let mut cols = vec![Vec::new(); names.len()];
    for l in lines {
        for (c, x) in cols.iter_mut().zip(l.split(',')) {
            c.push(x.trim().parse::<f64>().unwrap());
        }
    }
    names.into_iter().zip(cols).collect()
}

fn column(file: &str, name: &str) -> Vec<f64> {
    csv(file).into_iter().find(|(n, _)| n == name).unwrap().1
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1.0)
}

/// The 1-based line of the first line of `text` containing `needle`.
fn line_with(text: &str, needle: &str) -> usize {
    text.lines().position(|l| l.contains(needle)).unwrap() + 1
}

#[test]
fn json_is_fully_resolved() {
    let j = json_of("cornell.toml");
    assert_eq!(
        (j["format"].as_str(), j["version"].as_u64()),
        (Some("raylemma-scene"), Some(1))
    );
    // Defaults the file does not write.
    let r = &j["render"];
    assert_eq!(
        (
            r["spp"].as_u64(),
            r["seed"].as_u64(),
            r["roulette_depth"].as_u64(),
            r["max_depth"].as_u64()
        ),
        (Some(4096), Some(1), Some(3), Some(1000))
    );
    assert_eq!(
        (r["direct"].as_str(), r["wavelengths"].as_str()),
        (Some("mis-power"), Some("hero-visible"))
    );
    // The camera's frame: looking down +z with up +y, the image's right is -x.
    let c = &j["camera"];
    assert_eq!(floats(&c["forward"]), [0.0, 0.0, 1.0]);
    assert_eq!(floats(&c["right"]), [-1.0, 0.0, 0.0]);
    assert_eq!(floats(&c["image_up"]), [0.0, 1.0, 0.0]);
    let half = (39.3077_f64.to_radians() / 2.0).tan();
    assert!(close(c["half_height"].as_f64().unwrap(), half, 1e-15));
    // Colour: the integral of the 1 nm y-bar (NOTES.md: 106.856914916767) and the sRGB
    // matrix's first row (IEC 61966-2-1 with the D65 white (0.3127, 0.3290)).
    let conv = &j["conventions"];
    // The text inside strings is kept as written (arrays of numbers are put on one line).
    assert!(conv["quad"].as_str().unwrap().contains("a and b in [0, 1]"));
    assert!(close(
        conv["y_integral"].as_f64().unwrap(),
        106.856_914_916_767,
        1e-12
    ));
    let row = floats(&conv["xyz_to_linear_srgb"][0]);
    for (a, b) in row.iter().zip([3.24097, -1.53738, -0.49861]) {
        assert!((a - b).abs() < 5e-6, "{row:?}");
    }
    // A reflectance on the 1 nm grid: the CSV's values at its knots (every 4 nm from 400
    // to 700), linear in between.
    let white = j["materials"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["name"] == "white")
        .unwrap();
    let s = &white["reflectance"];
    assert_eq!(
        (s["kind"].as_str(), s["exact"].as_bool()),
        (Some("table"), Some(true))
    );
    let (nm, values) = (floats(&s["nm"]), floats(&s["values"]));
    assert_eq!((nm.len(), nm[0], nm[300]), (301, 400.0, 700.0));
    let (knots, w) = (
        column("cornell_box_reflectance.csv", "wavelength_nm"),
        column("cornell_box_reflectance.csv", "white"),
    );
    for (k, (&l, &v)) in knots.iter().zip(&w).enumerate() {
        let i = (l - 400.0) as usize;
        assert!(close(values[i], v, 1e-15), "{l} nm: {} vs {v}", values[i]);
        if k + 1 < knots.len() {
            let mid = (v + w[k + 1]) / 2.0;
            assert!(close(values[i + 2], mid, 1e-14), "{} nm", l + 2.0);
        }
    }
    // The light: explicit normal, area and the rectangle matrix Mitsuba was checked with
    // (NOTES.md, section 2).
    let light = &j["lights"][0];
    assert_eq!(floats(&light["normal"]), [0.0, -1.0, 0.0]);
    assert_eq!(light["area"].as_f64(), Some(13650.0));
    assert_eq!(
        floats(&light["to_world"]),
        [
            65.0, 0.0, 0.0, 278.0, 0.0, 0.0, -1.0, 554.0, 0.0, 52.5, 0.0, 279.5, 0.0, 0.0, 0.0, 1.0
        ]
    );
    assert_eq!(floats(&light["emission"]["values"])[100], 8.0);
    // Shapes name their material.
    assert_eq!(j["shapes"][5]["material_name"], "mirror");
    assert_eq!(j["shapes"][6]["type"], "sphere");
}

#[test]
fn json_keeps_luminance_scaling_sellmeier_films_and_constants() {
    // The lamps are scaled to Y = 12: the exported samples integrate to it against the
    // CIE table (trapezoids on 1 nm: within 0.1 % of the exact product integral).
    let j = json_of("lamps/incandescent.toml");
    let e = &j["lights"][0]["emission"];
    let (nm, values) = (floats(&e["nm"]), floats(&e["values"]));
    let ybar = column("cie1931_2deg_cmf_1nm.csv", "ybar");
    let at = |l: f64| ybar[(l - 360.0) as usize];
    let y: f64 = nm
        .windows(2)
        .zip(values.windows(2))
        .map(|(l, v)| 0.5 * (v[0] * at(l[0]) + v[1] * at(l[1])))
        .sum::<f64>()
        / 106.856_914_916_767;
    assert!((y - 12.0).abs() < 1e-2, "Y = {y}");
    // N-BK7 at 589 nm: 1.5168 to 4 digits (the catalogue's n_d, at 587.6 nm, is 1.5168).
    let j = json_of("dispersion.toml");
    let s = &j["materials"][0]["sellmeier"];
    assert_eq!(s["name"], "N-BK7");
    let n589 = floats(&s["index"])[(589 - 360) as usize];
    assert!((n589 - 1.5168).abs() < 5e-4, "{n589}");
    let j = json_of("bubble.toml");
    let soap = j["materials"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["name"] == "soap")
        .unwrap();
    assert_eq!(soap["type"], "thin-film");
    assert_eq!(soap["ior"].as_f64(), Some(1.33));
    let t = &soap["thickness_nm"];
    assert_eq!(
        (t["bottom"].as_f64(), t["top"].as_f64()),
        (Some(1000.0), Some(100.0))
    );
    assert_eq!(floats(&t["y_range"]), [-1.0, 1.0]);
    let j = json_of("furnace.toml");
    let env = &j["environment"];
    assert_eq!(
        (env["type"].as_str(), env["radiance"]["kind"].as_str()),
        (Some("constant"), Some("constant"))
    );
    assert_eq!(floats(&env["radiance"]["values"]), vec![1.0; 471]);
}

/// A scene file written into a temporary folder (with a spectrum CSV beside it).
fn scene_text(name: &str, text: &str) -> SceneFile {
    let dir = crate::support::scratch_file("export");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("odd.csv"),
        "wavelength_nm,value\n400.5,0.5\n500,1\n600.25,0.5\n",
    )
    .unwrap();
    SceneFile::parse(text, name, &dir).unwrap_or_else(|e| panic!("{e}"))
}

/// A small scene: one sphere of `material`, one light of `light`, and `extra`.
fn small(material: &str, light: &str, extra: &str) -> String {
    format!(
        "[render]\nspp = 4\nroulette_depth = 0\nmax_depth = 7\n\n[camera]\nposition = [0, 0, -5]\nlook_at = [0, 0, 0]\nup = [0, 1, 0]\nfov_y = 40\nresolution = [8, 8]\n\n[materials]\nm = {material}\n\n[[shape]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"m\"\n\n[[light]]\n{light}\n{extra}"
    )
}

const QUAD_LIGHT: &str =
    "type = \"quad\"\ncorner = [-1, 3, -1]\nedge1 = [2, 0, 0]\nedge2 = [0, 0, 2]\nemission = 10";

#[test]
fn json_samples_blackbodies_and_keeps_the_knots_of_odd_tables() {
    let light = QUAD_LIGHT.replace("emission = 10", "emission = { blackbody = 3000 }");
    let f = scene_text(
        "bb.toml",
        &small(
            "{ type = \"lambert\", reflectance = { file = \"odd.csv\" } }",
            &light,
            "",
        ),
    );
    let j: Value = serde_json::from_str(&to_json(&f)).unwrap();
    let e = &j["lights"][0]["emission"];
    assert_eq!(
        (
            e["kind"].as_str(),
            e["exact"].as_bool(),
            e["kelvin"].as_f64()
        ),
        (Some("blackbody"), Some(false), Some(3000.0))
    );
    // Planck's law over its value at Wien's peak: 1 at 2897.771955e-3 / 3000 m = 965.9 nm,
    // beyond the grid, so the values rise to 830 nm.
    let v = floats(&e["values"]);
    assert!(v.windows(2).all(|w| w[1] > w[0]) && v[470] < 1.0);
    // Knots at 400.5 and 600.25 nm: the 1 nm samples (401..600) are not exact; the knots
    // are given.
    let r = &j["materials"][0]["reflectance"];
    assert_eq!(r["exact"].as_bool(), Some(false));
    assert_eq!(floats(&r["nm"])[0], 401.0);
    assert_eq!(floats(&r["knots"]["nm"]), [400.5, 500.0, 600.25]);
    // Mitsuba gets the table's own knots, and the blackbody on the 1 nm grid.
    let x = to_xml(&f).unwrap();
    assert!(
        x.contains("<string name=\"wavelengths\" value=\"400.5, 500, 600.25\"/>"),
        "{x}"
    );
    // raylemma's max_depth 7 is Mitsuba's 8 segments; roulette from bounce 0 is rr_depth 1.
    assert!(x.contains("<integer name=\"max_depth\" value=\"8\"/>"));
    assert!(x.contains("<integer name=\"rr_depth\" value=\"1\"/>"));
}

/// Every tag of `xml` is closed in order (`<a ...>` ... `</a>`, `<b .../>`), there is one
/// root, `<scene version="3.0.0">`, and comments hold no `--`.
fn well_formed(xml: &str) {
    let mut stack: Vec<String> = Vec::new();
    let mut rest = xml;
    let mut roots = 0;
    while let Some(i) = rest.find('<') {
        rest = &rest[i..];
        if let Some(body) = rest.strip_prefix("<!--") {
            let end = body.find("-->").expect("an unclosed comment");
            assert!(!body[..end].contains("--"), "-- in a comment");
            rest = &body[end + 3..];
            continue;
        }
        let end = rest.find('>').expect("an unclosed tag");
        let tag = &rest[1..end];
        rest = &rest[end + 1..];
        if tag.starts_with('?') {
            continue;
        }
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(
                stack.pop().as_deref(),
                Some(name),
                "</{name}> closes the wrong tag"
            );
            continue;
        }
        let name = tag
            .split_whitespace()
            .next()
            .unwrap()
            .trim_end_matches('/')
            .to_string();
        if stack.is_empty() {
            roots += 1;
            assert!(tag.starts_with("scene version=\"3.0.0\""), "root <{tag}>");
        }
        if !tag.ends_with('/') {
            stack.push(name);
        }
    }
    assert!(stack.is_empty(), "unclosed: {stack:?}");
    assert_eq!(roots, 1);
}

#[test]
fn mitsuba_xml_follows_the_checked_rules() {
    let x = to_xml(&load("cornell.toml")).unwrap();
    well_formed(&x);
    for (what, needle) in [
        (
            "the integrator",
            "<integrator type=\"path\">\n        <integer name=\"max_depth\" value=\"1001\"/>\n        <integer name=\"rr_depth\" value=\"3\"/>",
        ),
        (
            "the light's matrix (NOTES.md, section 2)",
            "<matrix value=\"65 0 0 278 0 0 -1 554 0 52.5 0 279.5 0 0 0 1\"/>",
        ),
        (
            "the light's spectrum, every knot of the CSV",
            "<string name=\"wavelengths\" value=\"400, 500, 600, 700\"/>\n                <string name=\"values\" value=\"0, 8, 15.6, 18.4\"/>",
        ),
        (
            "a black BSDF on the light",
            "<bsdf type=\"diffuse\">\n            <spectrum name=\"reflectance\" value=\"0\"/>",
        ),
        (
            "glass with ext_ior 1",
            "<float name=\"int_ior\" value=\"1.5\"/>\n        <float name=\"ext_ior\" value=\"1\"/>",
        ),
        (
            "a two-sided perfect mirror",
            "<bsdf type=\"twosided\" id=\"material-2\">\n        <bsdf type=\"conductor\">\n            <string name=\"material\" value=\"none\"/>",
        ),
        (
            "two-sided diffuse walls",
            "<bsdf type=\"twosided\" id=\"material-4\">\n        <bsdf type=\"diffuse\">",
        ),
        (
            "the vertical field of view",
            "<float name=\"fov\" value=\"39.3077\"/>\n        <string name=\"fov_axis\" value=\"y\"/>",
        ),
        (
            "the camera",
            "<lookat origin=\"278, 273, -800\" target=\"278, 273, 0\" up=\"0, 1, 0\"/>",
        ),
        ("a box filter on a specfilm", "<rfilter type=\"box\"/>"),
        ("the spp default", "<default name=\"spp\" value=\"4096\"/>"),
        ("an area emitter", "<emitter type=\"area\">"),
    ] {
        assert!(x.contains(needle), "{what} missing:\n{needle}");
    }
    assert!(x.contains("<film type=\"specfilm\">") && !x.contains("hdrfilm"));
    // The sensor response X at 555 nm is the table's x-bar there over its integral of
    // y-bar.
    let xbar555 = column("cie1931_2deg_cmf_1nm.csv", "xbar")[195];
    let start = x.find("<spectrum name=\"X\"").unwrap();
    let values = &x[start..];
    let values = &values[values.find("name=\"values\" value=\"").unwrap() + 21..];
    let values: Vec<f64> = values[..values.find('"').unwrap()]
        .split(", ")
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(values.len(), 471);
    assert!(close(values[195], xbar555 / 106.856_914_916_767, 1e-12));
    // A constant environment is a constant emitter with a <spectrum>, not a <float> (which
    // would be D65).
    let x = to_xml(&load("furnace-grey.toml")).unwrap();
    well_formed(&x);
    assert!(x.contains(
        "<emitter type=\"constant\">\n        <spectrum name=\"radiance\" type=\"irregular\">"
    ));
    assert!(x.contains("<spectrum name=\"reflectance\" value=\"0.5\"/>"));
}

#[test]
fn mitsuba_refuses_what_it_cannot_express_with_the_line_and_json_keeps_it() {
    let scenes = root().join("scenes");
    let text = |f: &str| std::fs::read_to_string(scenes.join(f)).unwrap();
    for (file, needle, feature) in [
        (
            "dispersion.toml",
            "sellmeier = \"N-BK7\"",
            "Sellmeier dispersion",
        ),
        (
            "furnace.toml",
            "sellmeier = \"N-BK7\"",
            "Sellmeier dispersion",
        ),
        ("bubble.toml", "type = \"thin-film\"", "thin film"),
    ] {
        let f = load(file);
        let e = to_xml(&f).unwrap_err();
        assert_eq!(e.line, line_with(&text(file), needle), "{e}");
        assert!(e.file.ends_with(file) && e.problem.contains(feature), "{e}");
        assert!(serde_json::from_str::<Value>(&to_json(&f)).is_ok());
    }
    let sky = "\n[environment]\nabove = 1\nbelow = 0.5\n";
    let dielectric = "{ type = \"dielectric\", ior = 1.5 }";
    let sphere_light = "type = \"sphere\"\ncenter = [0, 0, -5]\nradius = 0.5\nemission = 1";
    let quad = "\n[[shape]]\ntype = \"quad\"\ncorner = [-5, -1, -5]\nedge1 = [0, 0, 10]\nedge2 = [10, 0, 0]\nmaterial = \"m\"\n";
    let inside_glass = "type = \"sphere\"\ncenter = [0, 0.2, 0]\nradius = 0.1\nemission = 1";
    for (name, text, needle, feature) in [
        (
            "sky.toml",
            small("{ type = \"mirror\" }", QUAD_LIGHT, sky),
            "[environment]",
            "gradient sky",
        ),
        (
            "quad.toml",
            small(dielectric, QUAD_LIGHT, quad),
            "[[shape]]\ntype = \"quad\"\ncorner = [-5",
            "dielectric quad",
        ),
        (
            "eye.toml",
            small("{ type = \"mirror\" }", sphere_light, ""),
            "[camera]",
            "camera is inside a sphere light",
        ),
    ] {
        let f = scene_text(name, &text);
        let e = to_xml(&f).unwrap_err();
        let line = text[..text.find(needle).unwrap()].matches('\n').count() + 1;
        assert_eq!((e.file.as_str(), e.line), (name, line), "{e}");
        assert!(e.problem.contains(feature), "{e}");
        assert!(serde_json::from_str::<Value>(&to_json(&f)).is_ok());
    }
    // A light inside a glass sphere, where the η² of refraction would not cancel, is not the
    // exporter's to refuse: the scene's own checks refuse it, for every renderer.
    let lamp = small(dielectric, inside_glass, "");
    let e = SceneFile::parse(&lamp, "lamp.toml", &std::env::temp_dir()).unwrap_err();
    assert!(
        e.problem.contains("inside shape 1, a dielectric sphere"),
        "{e}"
    );
    let f = scene_text("fine.toml", &small("{ type = \"mirror\" }", QUAD_LIGHT, ""));
    well_formed(&to_xml(&f).unwrap());
    // A bad scene is the parser's error, with its line.
    let bad = small("{ type = \"lambert\", reflectance = 2 }", QUAD_LIGHT, "");
    let dir: &Path = &std::env::temp_dir();
    let e = SceneFile::parse(&bad, "bad.toml", dir).unwrap_err();
    assert_eq!(e.line, line_with(&bad, "reflectance = 2"), "{e}");
}

// ---------------------------------------------------------------------------------------
// pbrt-v4

/// A value of a pbrt-v4 file: a number (read back from its text), a quoted string or a
/// bare `true` / `false`.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum PbrtValue {
    Num(f64),
    Str(String),
    Bool(bool),
}

/// One directive: its name, its positional arguments (`LookAt`'s nine numbers, `Shape`'s
/// type) and its `"type name" [ values ]` parameters.
#[derive(Debug)]
pub(super) struct Directive {
    pub name: String,
    pub args: Vec<PbrtValue>,
    pub params: Vec<(String, String, Vec<PbrtValue>)>,
}

impl Directive {
    /// The values of parameter `name`, with its type.
    pub fn param(&self, name: &str) -> Option<(&str, &[PbrtValue])> {
        self.params
            .iter()
            .find(|(_, n, _)| n == name)
            .map(|(t, _, v)| (t.as_str(), v.as_slice()))
    }

    /// The numbers of parameter `name` (panics if it is missing or not numbers).
    pub fn nums(&self, name: &str) -> Vec<f64> {
        let (_, v) = self
            .param(name)
            .unwrap_or_else(|| panic!("{} has no {name}: {self:?}", self.name));
        v.iter()
            .map(|x| match x {
                PbrtValue::Num(n) => *n,
                other => panic!("{name}: {other:?} is not a number"),
            })
            .collect()
    }

    /// The one string of parameter `name`, or the first positional string.
    pub fn string(&self, name: Option<&str>) -> String {
        let v = match name {
            Some(n) => self.param(n).map(|(_, v)| v.to_vec()).unwrap_or_default(),
            None => self.args.clone(),
        };
        match v.as_slice() {
            [PbrtValue::Str(s), ..] => s.clone(),
            other => panic!("{}: no string {name:?}: {other:?}", self.name),
        }
    }
}

#[derive(Debug)]
enum Token {
    Word(String),
    Value(PbrtValue),
    Open,
    Close,
}

/// The tokens of a pbrt-v4 file: `#` comments to the end of the line, quoted strings,
/// brackets, and bare words, each number of which must read back as the text written
/// (the shortest decimal of a finite double: NaN and infinities are refused).
fn pbrt_tokens(text: &str) -> Vec<Token> {
    let mut out = Vec::new();
    let mut chars = text.chars().peekable();
    while let Some(&c) = chars.peek() {
        if c.is_whitespace() {
            chars.next();
        } else if c == '#' {
            while chars.peek().is_some_and(|&c| c != '\n') {
                chars.next();
            }
        } else if c == '"' {
            chars.next();
            let s: String = chars.by_ref().take_while(|&c| c != '"').collect();
            assert!(!s.contains('\n'), "a string over a line end: {s:?}");
            out.push(Token::Value(PbrtValue::Str(s)));
        } else if c == '[' || c == ']' {
            chars.next();
            out.push(if c == '[' { Token::Open } else { Token::Close });
        } else {
            let mut w = String::new();
            while let Some(&c) = chars.peek() {
                if c.is_whitespace() || "[]\"#".contains(c) {
                    break;
                }
                w.push(c);
                chars.next();
            }
            out.push(match w.as_str() {
                "true" => Token::Value(PbrtValue::Bool(true)),
                "false" => Token::Value(PbrtValue::Bool(false)),
                _ if w.starts_with(|c: char| c.is_ascii_uppercase()) => Token::Word(w),
                _ => {
                    let x: f64 = w.parse().unwrap_or_else(|_| panic!("not a number: {w:?}"));
                    assert!(x.is_finite(), "{w}");
                    assert_eq!(format!("{x}"), w, "the number does not round-trip");
                    Token::Value(PbrtValue::Num(x))
                }
            });
        }
    }
    out
}

/// The parameter types of pbrt-v4's format (`ParsedParameter`, pbrt.org/fileformat-v4).
const PBRT_TYPES: [&str; 13] = [
    "integer",
    "float",
    "point2",
    "vector2",
    "point3",
    "vector3",
    "normal",
    "normal3",
    "spectrum",
    "rgb",
    "blackbody",
    "bool",
    "string",
];

/// The directives of a pbrt-v4 file, checked: known names, the options before one
/// `WorldBegin` and the world after it, balanced attribute blocks with a material before
/// every shape, spectra of increasing wavelengths, triangle meshes whose indices name
/// their points, integers that are integers, no parameter given twice.
pub(super) fn pbrt_well_formed(text: &str) -> Vec<Directive> {
    let mut tokens = pbrt_tokens(text).into_iter().peekable();
    let mut out: Vec<Directive> = Vec::new();
    while let Some(t) = tokens.next() {
        let Token::Word(name) = t else {
            panic!("a value outside a directive: {t:?}")
        };
        let mut d = Directive {
            name,
            args: Vec::new(),
            params: Vec::new(),
        };
        while let Some(Token::Value(_)) = tokens.peek() {
            let Some(Token::Value(v)) = tokens.next() else {
                unreachable!()
            };
            let param = match &v {
                PbrtValue::Str(s) => s
                    .split_once(' ')
                    .filter(|(ty, _)| PBRT_TYPES.contains(ty))
                    .map(|(ty, n)| (ty.to_string(), n.to_string())),
                _ => None,
            };
            let Some((ty, pname)) = param else {
                assert!(
                    d.params.is_empty(),
                    "{}: {v:?} after the parameters",
                    d.name
                );
                d.args.push(v);
                continue;
            };
            let values = match tokens.next() {
                Some(Token::Open) => {
                    let mut vs = Vec::new();
                    loop {
                        match tokens.next() {
                            Some(Token::Value(x)) => vs.push(x),
                            Some(Token::Close) => break,
                            other => panic!("{pname}: {other:?} in a list"),
                        }
                    }
                    vs
                }
                Some(Token::Value(x)) => vec![x],
                other => panic!("{pname}: {other:?} instead of its values"),
            };
            assert!(!values.is_empty(), "{pname} has no values");
            let all = |f: fn(&PbrtValue) -> bool| values.iter().all(f);
            match ty.as_str() {
                "integer" => assert!(all(|v| matches!(v, PbrtValue::Num(x) if x.fract() == 0.0))),
                "bool" => assert!(all(|v| matches!(v, PbrtValue::Bool(_)))),
                "string" => assert!(all(|v| matches!(v, PbrtValue::Str(_)))),
                _ => assert!(
                    all(|v| matches!(v, PbrtValue::Num(_))),
                    "{pname}: {values:?}"
                ),
            }
            if ty == "spectrum" {
                let x: Vec<f64> = values
                    .iter()
                    .map(|v| match v {
                        PbrtValue::Num(x) => *x,
                        _ => unreachable!(),
                    })
                    .collect();
                assert!(
                    x.len() >= 4 && x.len().is_multiple_of(2),
                    "{pname}: {} numbers",
                    x.len()
                );
                let nm: Vec<f64> = x.iter().step_by(2).copied().collect();
                assert!(
                    nm.windows(2).all(|w| w[1] > w[0]),
                    "{pname}: wavelengths {nm:?}"
                );
            }
            assert!(
                !d.params.iter().any(|(_, n, _)| *n == pname),
                "{}: {pname} twice",
                d.name
            );
            d.params.push((ty, pname, values));
        }
        out.push(d);
    }
    let world = out
        .iter()
        .position(|d| d.name == "WorldBegin")
        .expect("no WorldBegin");
    let options = [
        "Scale",
        "LookAt",
        "Camera",
        "Sampler",
        "PixelFilter",
        "Film",
        "Integrator",
    ];
    for name in ["Camera", "Sampler", "PixelFilter", "Film", "Integrator"] {
        assert_eq!(
            out[..world].iter().filter(|d| d.name == name).count(),
            1,
            "{name}"
        );
    }
    assert!(
        out[..world]
            .iter()
            .all(|d| options.contains(&d.name.as_str()))
    );
    let scene = [
        "MakeNamedMaterial",
        "NamedMaterial",
        "Material",
        "AttributeBegin",
        "AttributeEnd",
        "AreaLightSource",
        "Translate",
        "Shape",
        "LightSource",
    ];
    let mut depth = 0;
    let mut has_material = false;
    for d in &out[world + 1..] {
        assert!(scene.contains(&d.name.as_str()), "{} in the world", d.name);
        match d.name.as_str() {
            "AttributeBegin" => {
                depth += 1;
                has_material = false;
            }
            "AttributeEnd" => depth -= 1,
            "NamedMaterial" | "Material" => has_material = true,
            "Shape" => assert!(
                depth == 1 && has_material,
                "a shape outside a block or without a material"
            ),
            _ => {}
        }
        assert!((0..=1).contains(&depth), "unbalanced AttributeBegin/End");
        if d.name == "Shape" && d.string(None) == "trianglemesh" {
            let p = d.nums("P");
            let idx = d.nums("indices");
            assert!(p.len().is_multiple_of(3) && idx.len().is_multiple_of(3) && !idx.is_empty());
            assert!(idx.iter().all(|&i| i >= 0.0 && (i as usize) < p.len() / 3));
        }
        if d.name == "MakeNamedMaterial" {
            assert!(d.param("type").is_some(), "{d:?}");
        }
    }
    assert_eq!(depth, 0, "unbalanced AttributeBegin/End");
    out
}

/// The attribute blocks of the world, each as its directives.
fn blocks(ds: &[Directive]) -> Vec<&[Directive]> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, d) in ds.iter().enumerate() {
        match d.name.as_str() {
            "AttributeBegin" => start = Some(i + 1),
            "AttributeEnd" => out.push(&ds[start.take().unwrap()..i]),
            _ => {}
        }
    }
    out
}

fn find<'a>(block: &'a [Directive], name: &str) -> Option<&'a Directive> {
    block.iter().find(|d| d.name == name)
}

/// `"spectrum"` values as (nm, value) pairs.
fn pairs(x: &[f64]) -> Vec<(f64, f64)> {
    x.chunks(2).map(|c| (c[0], c[1])).collect()
}

/// A piecewise-linear spectrum at `l`: linear between knots, 0 outside (pbrt's
/// `PiecewiseLinearSpectrum::operator()`).
fn linear(knots: &[(f64, f64)], l: f64) -> f64 {
    if l < knots[0].0 || l > knots[knots.len() - 1].0 {
        return 0.0;
    }
    let i = knots
        .iter()
        .rposition(|k| k.0 <= l)
        .unwrap()
        .min(knots.len() - 2);
    let ((a, va), (b, vb)) = (knots[i], knots[i + 1]);
    va + (l - a) / (b - a) * (vb - va)
}

/// pbrt's `SpectrumToPhotometric`: the sum of ȳ(λ) L(λ) over λ = 360, 361, ..., 830 nm,
/// with ȳ from the data file.
fn photometric(knots: &[(f64, f64)]) -> f64 {
    let ybar = column("cie1931_2deg_cmf_1nm.csv", "ybar");
    (0..471)
        .map(|i| ybar[i] * linear(knots, 360.0 + i as f64))
        .sum()
}

/// The triangles of a mesh: their unit normals `Cross(p1 - p0, p2 - p0)` (pbrt's
/// `Triangle::Sample`) and their areas.
fn triangles(d: &Directive) -> Vec<([f64; 3], f64)> {
    let p = d.nums("P");
    let at = |i: f64| {
        [
            p[3 * i as usize],
            p[3 * i as usize + 1],
            p[3 * i as usize + 2],
        ]
    };
    d.nums("indices")
        .chunks(3)
        .map(|t| {
            let (a, b, c) = (at(t[0]), at(t[1]), at(t[2]));
            let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            let n = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            ([n[0] / len, n[1] / len, n[2] / len], len / 2.0)
        })
        .collect()
}

/// raylemma's `∫ȳ dλ`: the trapezoid rule on the 1 nm table.
fn y_integral() -> f64 {
    let y = column("cie1931_2deg_cmf_1nm.csv", "ybar");
    y.iter().sum::<f64>() - (y[0] + y[y.len() - 1]) / 2.0
}

#[test]
fn pbrt_follows_the_checked_rules() {
    let text = to_pbrt(&load("cornell.toml")).unwrap();
    let ds = pbrt_well_formed(&text);
    let get = |name: &str| ds.iter().find(|d| d.name == name).unwrap();
    let args = |name: &str| -> Vec<f64> {
        get(name)
            .args
            .iter()
            .map(|a| match a {
                PbrtValue::Num(x) => *x,
                other => panic!("{other:?}"),
            })
            .collect()
    };
    // The camera: mirrored in x first (pbrt's image right is up x forward), then LookAt
    // with cornell.toml's numbers; the picture is square, so fov is fov_y.
    let scale = ds.iter().position(|d| d.name == "Scale").unwrap();
    assert_eq!(ds[scale + 1].name, "LookAt");
    assert_eq!(args("Scale"), [-1.0, 1.0, 1.0]);
    assert_eq!(
        args("LookAt"),
        [278.0, 273.0, -800.0, 278.0, 273.0, 0.0, 0.0, 1.0, 0.0]
    );
    assert_eq!(get("Camera").string(None), "perspective");
    assert_eq!(get("Camera").nums("fov"), [39.3077]);
    let sampler = get("Sampler");
    assert_eq!(sampler.string(None), "independent");
    assert_eq!(sampler.nums("pixelsamples"), [4096.0]);
    // No seed in the file: pbrt's --seed would be overridden by it.
    assert!(sampler.param("seed").is_none());
    assert_eq!(get("PixelFilter").string(None), "box");
    assert_eq!(get("PixelFilter").nums("xradius"), [0.5]);
    assert_eq!(get("PixelFilter").nums("yradius"), [0.5]);
    let film = get("Film");
    assert_eq!(film.string(None), "rgb");
    assert_eq!(
        (film.nums("xresolution"), film.nums("yresolution")),
        (vec![256.0], vec![256.0])
    );
    assert_eq!(film.string(Some("sensor")), "cie1931");
    assert_eq!(
        film.param("savefp16"),
        Some(("bool", &[PbrtValue::Bool(false)][..]))
    );
    // iso / 100 is the imaging ratio: 1 / ∫ȳ makes pbrt's ∫ x̄ L dλ raylemma's X.
    assert!(close(film.nums("iso")[0], 100.0 / y_integral(), 1e-12));
    let integrator = get("Integrator");
    assert_eq!(integrator.string(None), "path");
    // raylemma's default max_depth, 1000 bounces, is pbrt's maxdepth as it is.
    assert_eq!(integrator.nums("maxdepth"), [1000.0]);
    assert_eq!(
        integrator.param("regularize"),
        Some(("bool", &[PbrtValue::Bool(false)][..]))
    );
    // Materials by name, in the order the exporter wrote them.
    let world = ds.iter().position(|d| d.name == "WorldBegin").unwrap();
    let materials: Vec<&Directive> = ds
        .iter()
        .filter(|d| d.name == "MakeNamedMaterial")
        .collect();
    let of_type = |t: &str| -> Vec<&&Directive> {
        materials
            .iter()
            .filter(|m| m.string(Some("type")) == t)
            .collect()
    };
    let glass = of_type("dielectric");
    assert_eq!(glass.len(), 1);
    assert_eq!(glass[0].nums("eta"), [1.5]);
    assert_eq!(glass[0].param("eta").unwrap().0, "float");
    assert_eq!(glass[0].nums("roughness"), [0.0]);
    let mirror = of_type("conductor");
    assert_eq!(mirror.len(), 1);
    assert_eq!(mirror[0].nums("eta"), [300.0, 0.0, 900.0, 0.0]);
    assert_eq!(mirror[0].nums("k"), [300.0, 1.0, 900.0, 1.0]);
    assert!(
        mirror[0].param("reflectance").is_none(),
        "clamped to 0.9999 by pbrt"
    );
    // The walls' reflectances: every knot of the CSV, exactly.
    let nm = column("cornell_box_reflectance.csv", "wavelength_nm");
    let diffuse: Vec<Vec<f64>> = of_type("diffuse")
        .iter()
        .map(|m| m.nums("reflectance"))
        .collect();
    for colour in ["white", "red", "green"] {
        let want: Vec<f64> = nm
            .iter()
            .zip(column("cornell_box_reflectance.csv", colour))
            .flat_map(|(&l, v)| [l, v])
            .collect();
        assert!(
            diffuse.contains(&want),
            "{colour}'s reflectance is not written as in the CSV"
        );
    }
    // The shapes: five walls (two triangles each, facing one way), two spheres, one light.
    let bs = blocks(&ds[world + 1..]);
    assert_eq!(bs.len(), 8);
    let spheres: Vec<(Vec<f64>, Vec<f64>)> = bs
        .iter()
        .filter_map(|b| {
            let s = find(b, "Shape")?;
            (s.string(None) == "sphere").then(|| {
                let t = find(b, "Translate").unwrap();
                let c = t.args.iter().map(|a| match a {
                    PbrtValue::Num(x) => *x,
                    _ => f64::NAN,
                });
                (c.collect(), s.nums("radius"))
            })
        })
        .collect();
    assert_eq!(
        spheres,
        [
            (vec![390.0, 100.0, 370.0], vec![100.0]),
            (vec![170.0, 100.0, 190.0], vec![100.0])
        ]
    );
    for b in &bs {
        let s = find(b, "Shape").unwrap();
        if s.string(None) == "trianglemesh" {
            let t = triangles(s);
            assert_eq!(t.len(), 2);
            assert!(
                t[0].0 == t[1].0,
                "the two triangles of a quad face apart: {t:?}"
            );
        }
    }
    // The light: cornell_box_light.csv's knots, the scale that undoes pbrt's division by
    // Σ ȳ L, one-sided (no twosided), black, its triangles facing edge1 x edge2 =
    // (130, 0, 0) x (0, 0, 105) = -y, its corners those of cornell.toml.
    let lights: Vec<&&[Directive]> = bs
        .iter()
        .filter(|b| find(b, "AreaLightSource").is_some())
        .collect();
    assert_eq!(lights.len(), 1);
    let area = find(lights[0], "AreaLightSource").unwrap();
    assert_eq!(area.string(None), "diffuse");
    let knots: Vec<f64> = column("cornell_box_light.csv", "wavelength_nm")
        .into_iter()
        .zip(column("cornell_box_light.csv", "radiance"))
        .flat_map(|(l, v)| [l, v])
        .collect();
    assert_eq!(area.nums("L"), knots);
    let sum = photometric(&pairs(&knots));
    assert!(
        close(area.nums("scale")[0], sum, 1e-12),
        "{} against {sum}",
        area.nums("scale")[0]
    );
    assert!(area.param("twosided").is_none());
    let black = find(lights[0], "Material").unwrap();
    assert_eq!(black.string(None), "diffuse");
    assert!(pairs(&black.nums("reflectance")).iter().all(|p| p.1 == 0.0));
    let mesh = find(lights[0], "Shape").unwrap();
    let t = triangles(mesh);
    for (n, _) in &t {
        assert_eq!(
            *n,
            [0.0, -1.0, 0.0],
            "the light's triangles do not face edge1 x edge2"
        );
    }
    assert!(close(t[0].1 + t[1].1, 130.0 * 105.0, 1e-12));
    let mut corners: Vec<Vec<f64>> = mesh.nums("P").chunks(3).map(<[f64]>::to_vec).collect();
    corners.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(
        corners,
        [
            [213.0, 554.0, 227.0],
            [213.0, 554.0, 332.0],
            [343.0, 554.0, 227.0],
            [343.0, 554.0, 332.0]
        ]
    );
    // The header says what the channels are.
    assert!(text.contains("channels R, G, B") && text.contains("--seed 1"));
    // A constant environment: an infinite light with its own scale; a constant reflectance
    // as two knots beyond 360-830 nm.
    let text = to_pbrt(&load("furnace-grey.toml")).unwrap();
    let ds = pbrt_well_formed(&text);
    let env = ds.iter().find(|d| d.name == "LightSource").unwrap();
    assert_eq!(env.string(None), "infinite");
    let d65: Vec<(f64, f64)> = column("cie_illuminant_D65.csv", "wavelength_nm")
        .into_iter()
        .zip(
            column("cie_illuminant_D65.csv", "value")
                .into_iter()
                .map(|v| v * 0.01),
        )
        .collect();
    let written = pairs(&env.nums("L"));
    assert_eq!(written.len(), d65.len());
    assert!(
        written
            .iter()
            .zip(&d65)
            .all(|(a, b)| a.0 == b.0 && close(a.1, b.1, 1e-15))
    );
    assert!(close(env.nums("scale")[0], photometric(&written), 1e-12));
    let grey = ds.iter().find(|d| d.name == "MakeNamedMaterial").unwrap();
    assert_eq!(grey.nums("reflectance"), [300.0, 0.5, 900.0, 0.5]);
}

/// N-BK7's index from the Sellmeier coefficients of `data/sellmeier.csv`, computed here.
fn n_bk7(nm: f64) -> f64 {
    let row = std::fs::read_to_string(root().join("data/sellmeier.csv"))
        .unwrap()
        .lines()
        .find(|l| l.starts_with("N-BK7,"))
        .unwrap()
        .to_string();
    let c: Vec<f64> = row
        .split(',')
        .skip(3)
        .take(6)
        .map(|x| x.parse().unwrap())
        .collect();
    let l2 = (nm / 1000.0).powi(2);
    (1.0 + (0..3)
        .map(|i| c[2 * i] * l2 / (l2 - c[2 * i + 1]))
        .sum::<f64>())
    .sqrt()
}

#[test]
fn pbrt_writes_sellmeier_glass_blackbodies_sphere_lights_and_portrait_cameras() {
    // Sellmeier glass: a spectral eta at every nanometre (pbrt then follows the hero
    // wavelength alone), equal to the CSV's fit; at the d line, SCHOTT's n_d = 1.5168.
    let ds = pbrt_well_formed(&to_pbrt(&load("dispersion.toml")).unwrap());
    let glass = ds
        .iter()
        .find(|d| d.name == "MakeNamedMaterial" && d.string(Some("type")) == "dielectric")
        .unwrap();
    assert_eq!(glass.param("eta").unwrap().0, "spectrum");
    let eta = pairs(&glass.nums("eta"));
    assert_eq!(eta.len(), 471);
    for (i, &(l, n)) in eta.iter().enumerate() {
        assert_eq!(l, 360.0 + i as f64);
        assert!(
            close(n, n_bk7(l), 1e-12),
            "{l} nm: {n} against {}",
            n_bk7(l)
        );
    }
    assert!((linear(&eta, 587.5618) - 1.5168).abs() < 5e-5);
    // A blackbody sphere light, seen by a portrait camera.
    let light =
        "type = \"sphere\"\ncenter = [0, 3, 0]\nradius = 0.5\nemission = { blackbody = 3000 }";
    let text = small("{ type = \"mirror\" }", light, "").replace("[8, 8]", "[8, 16]");
    let ds = pbrt_well_formed(&to_pbrt(&scene_text("bb.toml", &text)).unwrap());
    let camera = ds.iter().find(|d| d.name == "Camera").unwrap();
    // The shorter axis is the width: tan(fov/2) = tan(40°/2) × 8/16.
    let fov = 2.0 * (20f64.to_radians().tan() * 0.5).atan().to_degrees();
    assert!(close(camera.nums("fov")[0], fov, 1e-12));
    let film = ds.iter().find(|d| d.name == "Film").unwrap();
    assert_eq!(
        (film.nums("xresolution"), film.nums("yresolution")),
        (vec![8.0], vec![16.0])
    );
    assert_eq!(
        ds.iter()
            .find(|d| d.name == "Integrator")
            .unwrap()
            .nums("maxdepth"),
        [7.0]
    );
    let area = ds.iter().find(|d| d.name == "AreaLightSource").unwrap();
    assert_eq!(
        area.param("twosided"),
        Some(("bool", &[PbrtValue::Bool(true)][..]))
    );
    let l = pairs(&area.nums("L"));
    assert_eq!(l.len(), 471);
    // Planck's law: the ratio of two samples, from the physical constants here (CODATA).
    let (h, c, k) = (6.626_070_15e-34, 299_792_458.0, 1.380_649e-23);
    let planck = |nm: f64| {
        let m = nm * 1e-9;
        1.0 / (m.powi(5) * ((h * c / (m * k * 3000.0)).exp() - 1.0))
    };
    assert!(close(
        l[140].1 / l[240].1,
        planck(500.0) / planck(600.0),
        1e-6
    ));
    assert!(close(area.nums("scale")[0], photometric(&l), 1e-12));
    assert_eq!(ds.iter().filter(|d| d.name == "Translate").count(), 2);
}

#[test]
fn pbrt_refuses_what_it_cannot_express_with_the_line() {
    let scenes = root().join("scenes");
    let text = |f: &str| std::fs::read_to_string(scenes.join(f)).unwrap();
    let f = load("bubble.toml");
    let e = to_pbrt(&f).unwrap_err();
    assert_eq!(
        e.line,
        line_with(&text("bubble.toml"), "type = \"thin-film\""),
        "{e}"
    );
    assert!(
        e.file.ends_with("bubble.toml") && e.problem.contains("thin film"),
        "{e}"
    );
    let sky = "\n[environment]\nabove = 1\nbelow = 0.5\n";
    let dielectric = "{ type = \"dielectric\", ior = 1.5 }";
    let quad = "\n[[shape]]\ntype = \"quad\"\ncorner = [-5, -1, -5]\nedge1 = [0, 0, 10]\nedge2 = [10, 0, 0]\nmaterial = \"m\"\n";
    for (name, text, needle, feature) in [
        (
            "sky.toml",
            small("{ type = \"mirror\" }", QUAD_LIGHT, sky),
            "[environment]",
            "gradient sky",
        ),
        (
            "quad.toml",
            small(dielectric, QUAD_LIGHT, quad),
            "[[shape]]\ntype = \"quad\"\ncorner = [-5",
            "dielectric quad",
        ),
    ] {
        let f = scene_text(name, &text);
        let e = to_pbrt(&f).unwrap_err();
        let line = text[..text.find(needle).unwrap()].matches('\n').count() + 1;
        assert_eq!((e.file.as_str(), e.line), (name, line), "{e}");
        assert!(e.problem.contains(feature), "{e}");
        assert!(serde_json::from_str::<Value>(&to_json(&f)).is_ok());
    }
    // What Mitsuba refuses and pbrt expresses: Sellmeier glass, and a camera inside a sphere
    // light (pbrt's twosided area light emits inwards too).
    pbrt_well_formed(&to_pbrt(&load("dispersion.toml")).unwrap());
    let inside = "type = \"sphere\"\ncenter = [0, 0, -5]\nradius = 0.5\nemission = 1";
    let f = scene_text("eye.toml", &small("{ type = \"mirror\" }", inside, ""));
    assert!(to_xml(&f).is_err());
    pbrt_well_formed(&to_pbrt(&f).unwrap());
}
