//! Every malformed scene is refused with the file, the line and the reason: syntax, unknown
//! keys, types and names, bad numbers, reflectances over one, degenerate geometry, cameras and
//! lights inside glass, missing and malformed spectrum files.

use super::*;

#[test]
fn syntax_errors_name_their_line() {
    refused_at("radius = 1", "radius = = 1", &[]);
    // An unclosed array is noticed where the next line starts.
    let (text, line) = with("fov_y = 40", "fov_y = [40");
    let e = parse(&text).map(|_| ()).unwrap_err();
    assert_eq!(e.line, line + 1, "{e}");
}

#[test]
fn unknown_keys_types_and_names_are_refused() {
    refused_at("seed = 1", "sed = 1", &["sed"]);
    refused_at(
        "grey = { type = \"lambert\"",
        "grey = { type = \"plastic\", reflectance = 1 }",
        &["plastic", "lambert"],
    );
    refused_at(
        "material = \"grey\"",
        "material = \"gold\"",
        &["gold", "grey", "glass"],
    );
    refused_at("type = \"sphere\"", "type = \"cube\"", &["cube"]);
    refused_at("emission = 10", "emission = \"sun\"", &["sun"]);
    refused_at(
        "glass = {",
        "glass = { type = \"dielectric\", sellmeier = \"unobtainium\" }",
        &["unobtainium", "N-BK7"],
    );
    refused_at(
        "seed = 1",
        "wavelengths = \"rainbow\"",
        &[
            "unknown wavelength strategy \"rainbow\"",
            "hero-visible",
            ", emission)",
        ],
    );
    refused_at(
        "seed = 1",
        "direct = \"guess\"",
        &[
            "unknown direct-lighting strategy \"guess\"",
            "mis-power",
            "bsdf",
        ],
    );
    refused_at(
        "seed = 1",
        "light_sampling = \"cone\"",
        &["unknown light sampling \"cone\"", "area, solid-angle)"],
    );
    // Keys of the other kind of shape, or of another material type.
    refused_at("edge2 = [10, 0, 0]", "radius = 2", &["quad", "radius"]);
    refused_at(
        "glass = {",
        "glass = { type = \"dielectric\", ior = 1.5, reflectance = 0.5 }",
        &["dielectric material", "reflectance"],
    );
}

#[test]
fn bad_numbers_are_refused() {
    refused_at("radius = 1", "radius = -1", &["radius", "-1", "> 0"]);
    refused_at("radius = 1", "radius = 0", &["radius"]);
    refused_at("radius = 1", "radius = nan", &["radius", "NaN"]);
    refused_at("center = [0, 0, 0]", "center = [0, inf, 0]", &["center"]);
    refused_at(
        "glass = {",
        "glass = { type = \"dielectric\", ior = 0 }",
        &["ior", "> 0"],
    );
    refused_at(
        "glass = {",
        "glass = { type = \"dielectric\", ior = -1.5 }",
        &["ior"],
    );
    refused_at("spp = 4", "spp = 0", &["spp", "at least 1"]);
    refused_at("spp = 4", "spp = -3", &["spp"]);
    refused_at("fov_y = 40", "fov_y = 180", &["fov_y"]);
    refused_at(
        "resolution = [16, 16]",
        "resolution = [0, 16]",
        &["resolution"],
    );
    refused_at("emission = 10", "emission = -10", &["emission"]);
}

#[test]
fn an_over_unit_reflectance_is_refused_where_it_is_used() {
    let (text, _) = with("grey = { constant", "grey = { constant = 1.5 }");
    let e = parse(&text).map(|_| ()).unwrap_err();
    let line = GOOD
        .lines()
        .position(|l| l.starts_with("grey = { type"))
        .unwrap()
        + 1;
    assert_eq!(e.line, line, "{e}");
    assert!(e.problem.contains("[0, 1]"), "{e}");
}

#[test]
fn degenerate_geometry_is_refused() {
    // Parallel edges: the quad has no area.
    let (text, _) = with("edge2 = [10, 0, 0]", "edge2 = [0, 0, 20]");
    let e = parse(&text).map(|_| ()).unwrap_err();
    assert!(
        e.problem.contains("degenerate") && e.problem.contains("parallel"),
        "{e}"
    );
    assert!(
        e.line > 0 && GOOD.lines().nth(e.line - 1).is_some_and(|l| !l.is_empty()),
        "{e}"
    );
    refused_at("edge1 = [0, 0, 10]", "edge1 = [0, 0, 0]", &[]);
    // A camera looking along its up direction has no image plane.
    refused_at("up = [0, 1, 0]", "up = [0, 0, 1]", &["parallel"]);
    refused_at("look_at = [0, 0, 0]", "look_at = [0, 0, -5]", &["look_at"]);
}

#[test]
fn a_camera_or_light_inside_glass_is_refused() {
    // The path tracer leaves out the radiance factor η² of refraction, which cancels only for
    // paths that leave every dielectric they enter: a camera or a light inside glass would be
    // rendered wrong by η², so the scene is refused (chapter *The path tracer*).
    let line = |text: &str, start: &str| {
        text.lines()
            .position(|l| l.starts_with(start))
            .unwrap_or_else(|| panic!("no line {start:?}"))
            + 1
    };
    let glass = GOOD.replacen("material = \"grey\"", "material = \"glass\"", 1);
    assert!(
        parse(&glass).is_ok(),
        "a glass sphere with everything outside"
    );
    let eye = glass.replace("position = [0, 0, -5]", "position = [0, 0.5, -0.2]");
    let e = parse(&eye).map(|_| ()).unwrap_err();
    assert_eq!(e.line, line(&eye, "position"), "{e}");
    assert!(
        e.problem
            .contains("camera is inside shape 1, a dielectric sphere")
            && e.problem.contains("η²"),
        "{e}"
    );
    // A quad light with one corner inside, and a sphere light whose centre is inside.
    let quad = glass.replace("corner = [-1, 3, -1]", "corner = [-0.2, 0.5, -0.2]");
    let e = parse(&quad).map(|_| ()).unwrap_err();
    assert_eq!(e.line, line(&quad, "corner = [-0.2"), "{e}");
    assert!(e.problem.contains("light 1 is inside shape 1"), "{e}");
    let sphere = glass.replace(
        "type = \"quad\"\ncorner = [-1, 3, -1]\nedge1 = [2, 0, 0]\nedge2 = [0, 0, 2]",
        "type = \"sphere\"\ncenter = [0, 0.3, 0]\nradius = 0.2",
    );
    let e = parse(&sphere).map(|_| ()).unwrap_err();
    assert_eq!(e.line, line(&sphere, "center = [0, 0.3"), "{e}");
    assert!(e.problem.contains("light 1 is inside shape 1"), "{e}");
    // Only a dielectric needs it: the same camera inside the Lambertian sphere is accepted.
    let lambert = GOOD.replace("position = [0, 0, -5]", "position = [0, 0.5, -0.2]");
    assert!(
        parse(&lambert).is_ok(),
        "a camera inside a Lambertian sphere"
    );
}

#[test]
fn a_missing_spectrum_file_is_refused_with_its_path() {
    refused_at(
        "grey = { constant",
        "grey = { file = \"no-such.csv\" }",
        &["no-such.csv", "does not exist"],
    );
    // A file that exists but lacks the column.
    refused_at(
        "grey = { constant",
        "grey = { file = \"../data/cornell_box_reflectance.csv\", column = \"blue\" }",
        &["blue", "white"],
    );
}

#[test]
fn a_malformed_spectrum_file_names_its_own_line() {
    let dir = crate::support::scratch("scene-spectrum-file");
    std::fs::write(
        dir.join("bad.csv"),
        "wavelength_nm,value\n400,0.5\n500,oops\n",
    )
    .unwrap();
    let (text, _) = with("grey = { constant", "grey = { file = \"bad.csv\" }");
    let e = render::parse(&text, "test.toml", &dir)
        .map(|_| ())
        .unwrap_err();
    assert!(e.file.ends_with("bad.csv") && e.line == 3, "{e}");
}
