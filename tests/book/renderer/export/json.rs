//! The JSON: fully resolved (defaults, 1 nm spectra equal to the data files, explicit
//! transforms), keeping luminance scaling, Sellmeier glasses, films, constants, blackbodies
//! and the knots of odd tables.

use super::*;

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

/// `max_depth` counts bounces and the file says so beside it, in words an implementer of a
/// segment-counting renderer cannot misread: direct light only is 1, paths of two segments,
/// and Mitsuba's `max_depth` is one more (chapter *Reference scenes and interop*, *Exporting
/// a scene*).
#[test]
fn json_says_what_max_depth_counts() {
    for (scene, depth) in [
        ("cornell.toml", 1000),
        ("conformance/01-direct-quad.toml", 1),
    ] {
        let j = json_of(scene);
        let r = &j["render"];
        assert_eq!(r["max_depth"].as_u64(), Some(depth), "{scene}");
        let counts = r["max_depth_counts"].as_str().unwrap_or_default();
        for words in [
            "bounces",
            "at most max_depth + 1 segments",
            "1 is direct light only (paths of two segments",
            "Mitsuba's max_depth) uses max_depth + 1",
        ] {
            assert!(
                counts.contains(words),
                "{scene}: {counts:?} lacks {words:?}"
            );
        }
    }
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
