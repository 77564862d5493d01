//! Tests of `export` (`src/render/export/`; chapter *Reference scenes and interop*, *Exporting a
//! scene*): the JSON is fully resolved (defaults, 1 nm spectra equal to the data files,
//! explicit transforms); the Mitsuba XML follows the rules checked against Mitsuba in
//! `tools/mitsuba/NOTES.md`; what Mitsuba cannot express is refused with its line and
//! kept by the JSON. Every expected value comes from the data files, the NOTES or
//! arithmetic done here, never from the exporter. That Mitsuba renders the files is the
//! job of `tools/mitsuba/compare_all.sh`, outside `cargo test`.

use std::path::{Path, PathBuf};

use raylemma::render::export::{SceneFile, json::to_json, mitsuba::to_xml};
use serde_json::Value;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

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
    let dir = std::env::temp_dir().join(format!("raylemma-export-{}", std::process::id()));
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
