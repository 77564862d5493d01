//! The Mitsuba XML: well-formed, following the rules checked against Mitsuba
//! (`tools/mitsuba/NOTES.md`), and what Mitsuba cannot express refused with its line (and
//! kept by the JSON).

use super::*;

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
    // A camera inside a sphere light: both renderers' sphere lights emit outwards only.
    let f = scene_text(
        "eye.toml",
        &small("{ type = \"mirror\" }", sphere_light, ""),
    );
    well_formed(&to_xml(&f).unwrap());
    // A bad scene is the parser's error, with its line.
    let bad = small("{ type = \"lambert\", reflectance = 2 }", QUAD_LIGHT, "");
    let dir: &Path = &std::env::temp_dir();
    let e = SceneFile::parse(&bad, "bad.toml", dir).unwrap_err();
    assert_eq!(e.line, line_with(&bad, "reflectance = 2"), "{e}");
}
