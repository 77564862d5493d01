//! `raylemma render` refuses a bad scene before it writes anything, leaving earlier outputs
//! untouched; zero spp and a missing scene; a render then `compare` from the command line;
//! emission wavelengths that need one tabulated light and no environment.

use super::*;

#[test]
fn render_refuses_a_bad_scene_and_keeps_earlier_outputs() {
    let dir = out_dir("bad");
    let (text, line) = with("radius = 1", "radius = -2");
    let scene = dir.join("tiny.toml");
    std::fs::write(&scene, text).unwrap();
    // An earlier render's files, which must survive.
    for ext in ["exr", "png", "json"] {
        std::fs::write(dir.join(format!("tiny.{ext}")), b"earlier").unwrap();
    }
    let out = raylemma()
        .arg("render")
        .arg(&scene)
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(&format!("tiny.toml:{line}:")) && err.contains("radius"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
    for ext in ["exr", "png", "json"] {
        assert_eq!(
            std::fs::read(dir.join(format!("tiny.{ext}"))).unwrap(),
            b"earlier",
            "tiny.{ext} was touched"
        );
    }
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(left.len(), 4, "stray files: {left:?}");
}

#[test]
fn render_refuses_zero_spp_and_a_missing_scene() {
    let dir = out_dir("flags");
    let out = raylemma()
        .args(["render", "scenes/cornell.toml", "--spp", "0", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("--spp"));
    let out = raylemma()
        .args(["render", "no/such/scene.toml", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no/such/scene.toml"));
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
}

#[test]
fn render_then_compare_from_the_command_line() {
    let dir = out_dir("ok");
    let scene = dir.join("tiny.toml");
    std::fs::write(&scene, GOOD).unwrap();
    let render = |seed: &str, sub: &str| {
        let out = raylemma()
            .arg("render")
            .arg(&scene)
            .args(["--spp", "16", "--seed", seed, "--out"])
            .arg(dir.join(sub))
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        dir.join(sub).join("tiny.exr")
    };
    let (a, b) = (render("1", "a"), render("2", "b"));
    let json = std::fs::read_to_string(dir.join("a").join("tiny.json")).unwrap();
    for key in [
        "\"scene_hash\"",
        "\"spp\": 16",
        "\"seed\": 1",
        "\"seconds\"",
        "\"renderer\": \"raylemma",
    ] {
        assert!(json.contains(key), "{key} missing from {json}");
    }
    assert!(Path::new(&dir.join("a").join("tiny.png")).is_file());
    let diff = dir.join("diff.png");
    let out = raylemma()
        .arg("compare")
        .arg(&a)
        .arg(&b)
        .arg("--diff")
        .arg(&diff)
        .output()
        .unwrap();
    let report = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{report}");
    assert!(report.contains("AGREE") && diff.is_file(), "{report}");
    // A missing file is bad input: exit 2 and the path named.
    let out = raylemma()
        .arg("compare")
        .arg(&a)
        .arg(dir.join("nope.exr"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("nope.exr"));
}

#[test]
fn emission_wavelengths_need_one_tabulated_light_and_no_environment() {
    let (text, line) = with("seed = 1", "wavelengths = \"emission\"");
    let e = parse(&text).map(|_| ()).unwrap_err();
    assert!(e.line == line && e.problem.contains("not a table"), "{e}");
    let text = text.replace("emission = 10", "emission = { lamp = \"incandescent\" }");
    assert!(parse(&text).is_ok());
    let e = parse(&(text + "\n[environment]\nemission = 1\n"))
        .map(|_| ())
        .unwrap_err();
    assert!(e.line == line && e.problem.contains("environment"), "{e}");
}
