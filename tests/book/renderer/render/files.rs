//! The files a render writes: Welford's variance, the EXR round trip, the JSON sidecar, a
//! failed write that leaves the earlier render whole, and bad sidecars refused with their path.

use super::*;

#[test]
fn welford_matches_the_two_pass_variance() {
    let xs: Vec<f64> = (0..1000).map(|i| 1e6 + f64::from(i % 7) * 0.25).collect();
    let mut w = Welford::default();
    for &x in &xs {
        w.push(DVec3::splat(x));
    }
    let n = xs.len() as f64;
    let mean = xs.iter().sum::<f64>() / n;
    let s2 = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    assert!((w.mean().x - mean).abs() <= 1e-9);
    assert!(
        (w.var_of_mean().x - s2 / n).abs() <= 1e-9 * s2 / n,
        "{} vs {}",
        w.var_of_mean().x,
        s2 / n
    );
    let mut one = Welford::default();
    one.push(DVec3::ONE);
    assert!(one.var_of_mean().is_nan(), "one sample has no variance");
}

#[test]
fn exr_round_trip_keeps_every_channel() {
    let s = small(load("cornell-diffuse.toml"), 12, 4);
    let image = render(&s, 4, Progress::Silent);
    let path = tmp("round.exr");
    image.write_exr(&path).unwrap();
    let back = Image::read_exr(&path).unwrap();
    assert_eq!((back.width, back.height), (12, 12));
    for (a, b) in image
        .mean
        .iter()
        .chain(&image.var)
        .zip(back.mean.iter().chain(&back.var))
    {
        let rel = raylemma::check::max_abs((*a - *b).to_array()) / a.abs().max_element().max(1e-30);
        assert!(rel <= 1e-7, "{a} became {b}");
    }
    let missing = Image::read_exr(&tmp("no-such.exr")).unwrap_err();
    assert!(missing.problem.contains("no such file"), "{missing}");
    std::fs::write(tmp("not.exr"), b"not an exr").unwrap();
    let bad = Image::read_exr(&tmp("not.exr")).unwrap_err();
    assert!(bad.problem.contains("OpenEXR"), "{bad}");
}

#[test]
fn sidecar_strings_are_valid_json() {
    let image = Image {
        width: 2,
        height: 1,
        mean: vec![DVec3::ZERO; 2],
        var: vec![DVec3::ZERO; 2],
        spp: None,
    };
    let keys = [
        "renderer",
        "scene",
        "scene_hash",
        "width",
        "height",
        "spp",
        "seed",
        "wavelengths",
        "seconds",
        "threads",
        "pixel_samples_per_second",
    ];
    // Plain text, quotes, a backslash and a newline, a non-ASCII letter, a control character.
    for (scene, written) in [
        ("plain", r#""plain""#),
        ("a\"b\\c\nd", r#""a\"b\\c\nd""#),
        ("λ", r#""λ""#),
        ("bell\u{7}", r#""bell\u0007""#),
    ] {
        let sidecar = Sidecar {
            scene: scene.into(),
            scene_hash: 0x0123_4567_89ab_cdef,
            spp: 16,
            seed: 1,
            wavelengths: "hero-visible".into(),
            seconds: 0.25,
            threads: 2,
            made_from: None,
            build: None,
            seeds: Vec::new(),
        };
        let text = sidecar.to_json(&image);
        assert!(text.contains(&format!("\"scene\": {written}")), "{text}");
        assert!(text.ends_with("}\n"), "{text}");
        let v: serde_json::Value =
            serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}:\n{text}"));
        let obj = v.as_object().unwrap();
        assert_eq!(obj.keys().collect::<Vec<_>>().len(), keys.len(), "{text}");
        for key in keys {
            assert!(obj.contains_key(key), "{key} missing from {text}");
        }
        assert_eq!(v["scene"], scene);
        assert_eq!(v["scene_hash"], "0123456789abcdef");
        assert_eq!(v["width"], 2);
        assert_eq!(v["height"], 1);
        assert_eq!(v["spp"], 16);
        assert_eq!(v["seed"], 1);
        assert_eq!(v["wavelengths"], "hero-visible");
        assert_eq!(v["seconds"], 0.25);
        assert_eq!(v["threads"], 2);
        assert_eq!(v["pixel_samples_per_second"], 128);
        assert!(
            v["renderer"]
                .as_str()
                .is_some_and(|r| r.starts_with("raylemma ")),
            "{text}"
        );
    }
}

#[test]
fn a_failed_write_leaves_the_earlier_render_whole() {
    let dir = tmp("atomic-render");
    let _ = std::fs::remove_dir_all(&dir);
    let s = small(load("cornell.toml"), 8, 2);
    let sidecar = |seed| Sidecar {
        scene: "cornell.toml".into(),
        scene_hash: s.hash,
        spp: 2,
        seed,
        wavelengths: "hero-visible".into(),
        seconds: 1.0,
        threads: 1,
        made_from: None,
        build: None,
        seeds: Vec::new(),
    };
    let first = render(&s, 2, Progress::Silent);
    let [exr, png, json] = write_outputs(&dir, "tiny", &first, &sidecar(1)).unwrap();
    let earlier = [std::fs::read(&exr).unwrap(), std::fs::read(&png).unwrap()];
    // Something in the way of the last file: its rename fails after the EXR and the PNG
    // of the new render have landed; both are put back.
    std::fs::remove_file(&json).unwrap();
    std::fs::create_dir(&json).unwrap();
    std::fs::write(json.join("keep"), b"keep").unwrap();
    let mut other = s.clone();
    other.settings.seed += 1;
    let second = render(&other, 2, Progress::Silent);
    let e = write_outputs(&dir, "tiny", &second, &sidecar(2)).unwrap_err();
    assert!(e.to_string().contains("tiny.json"), "{e}");
    assert_eq!(std::fs::read(&exr).unwrap(), earlier[0], "tiny.exr changed");
    assert_eq!(std::fs::read(&png).unwrap(), earlier[1], "tiny.png changed");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, ["tiny.exr", "tiny.json", "tiny.png"], "stray files");
    // With the way clear, the new render lands whole.
    std::fs::remove_dir_all(&json).unwrap();
    write_outputs(&dir, "tiny", &second, &sidecar(2)).unwrap();
    assert_ne!(
        std::fs::read(&exr).unwrap(),
        earlier[0],
        "the new EXR did not land"
    );
    assert!(
        std::fs::read_to_string(&json)
            .unwrap()
            .contains("\"seed\": 2")
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A sidecar that is not one is refused with its path and the reason, never read as zeros
/// (the reader of `references`; the fuzz target `sidecar` runs it on any bytes).
#[test]
fn a_bad_sidecar_is_refused_with_its_path() {
    let dir = tmp("bad-sidecar");
    std::fs::create_dir_all(&dir).unwrap();
    let image = render(&small(load("cornell.toml"), 4, 1), 1, Progress::Silent);
    let good = Sidecar {
        scene: "cornell.toml".into(),
        scene_hash: 0xabc,
        spp: 2,
        seed: 1,
        wavelengths: "hero-visible".into(),
        seconds: 1.0,
        threads: 1,
        made_from: None,
        build: None,
        seeds: Vec::new(),
    }
    .to_json(&image);
    let path = dir.join("s.json");
    std::fs::write(&path, &good).unwrap();
    assert_eq!(Sidecar::read(&path).unwrap().scene_hash, 0xabc);
    for (text, words) in [
        ("{", "not a render's sidecar"),
        ("", "not a render's sidecar"),
        (
            &good.replace("\"spp\": 2", "\"spp\": -2")[..],
            "not a render's sidecar",
        ),
        (&good.replace("abc", "xyz")[..], "scene_hash"),
    ] {
        std::fs::write(&path, text).unwrap();
        let e = Sidecar::read(&path).unwrap_err().to_string();
        assert!(e.contains("s.json") && e.contains(words), "{text:?}: {e}");
    }
    let e = Sidecar::read(&dir.join("missing.json"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("missing.json") && e.contains("cannot read"),
        "{e}"
    );
}
