//! The pbrt-v4 file: the rules of `tools/pbrt/NOTES.md` read back through the tokenizer of
//! `super`, Sellmeier glass, blackbodies, sphere lights and portrait cameras, and what pbrt-v4
//! cannot express refused with its line.

use super::*;

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
    // One-sided, emitting outwards only, as raylemma's sphere lights.
    let area = ds.iter().find(|d| d.name == "AreaLightSource").unwrap();
    assert!(area.param("twosided").is_none());
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
    // What Mitsuba refuses and pbrt expresses: Sellmeier glass. A camera inside a sphere
    // light both express (in each renderer, and in raylemma, it sees no light from it).
    pbrt_well_formed(&to_pbrt(&load("dispersion.toml")).unwrap());
    let inside = "type = \"sphere\"\ncenter = [0, 0, -5]\nradius = 0.5\nemission = 1";
    let f = scene_text("eye.toml", &small("{ type = \"mirror\" }", inside, ""));
    assert!(to_xml(&f).is_ok());
    pbrt_well_formed(&to_pbrt(&f).unwrap());
}
