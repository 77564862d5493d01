//! Tests of the scene format (`src/render/format.rs`, checked by `src/render/validate/`;
//! chapter *Reference scenes and interop*):
//! every canonical scene reads; every malformed scene is refused with the file, the line
//! and the reason; random corruptions of real scenes never panic; and `raylemma render`
//! refuses a bad scene before it writes anything, leaving earlier outputs untouched.

use std::path::{Path, PathBuf};
use std::process::Command;

use raylemma::data::DataError;
use raylemma::render;
use raylemma::render::scene::{self, Material};
use raylemma::rng;

use crate::support::root;

fn scenes_dir() -> PathBuf {
    root().join("scenes")
}

/// A minimal valid scene; tests change one line of it.
const GOOD: &str = r#"[render]
spp = 4
seed = 1

[camera]
position = [0, 0, -5]
look_at = [0, 0, 0]
up = [0, 1, 0]
fov_y = 40
resolution = [16, 16]

[spectra]
grey = { constant = 0.5 }

[materials]
grey = { type = "lambert", reflectance = "grey" }
glass = { type = "dielectric", ior = 1.5 }

[[shape]]
type = "sphere"
center = [0, 0, 0]
radius = 1
material = "grey"

[[shape]]
type = "quad"
corner = [-5, -1, -5]
edge1 = [0, 0, 10]
edge2 = [10, 0, 0]
material = "glass"

[[light]]
type = "quad"
corner = [-1, 3, -1]
edge1 = [2, 0, 0]
edge2 = [0, 0, 2]
emission = 10
"#;

fn parse(text: &str) -> Result<scene::Scene, DataError> {
    render::parse(text, "test.toml", &scenes_dir())
}

/// `GOOD` with the line that starts with `old` replaced by `new`; the 1-based line.
fn with(old: &str, new: &str) -> (String, usize) {
    let lines: Vec<&str> = GOOD.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.starts_with(old))
        .unwrap_or_else(|| panic!("no line {old:?}"));
    let mut out: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
    out[at] = new.to_string();
    (out.join("\n") + "\n", at + 1)
}

/// The scene with `old` replaced by `new` must be refused at that line, with a message
/// containing every one of `words`.
fn refused_at(old: &str, new: &str, words: &[&str]) {
    let (text, line) = with(old, new);
    let e = parse(&text).map(|_| ()).unwrap_err();
    assert_eq!(
        (e.file.as_str(), e.line),
        ("test.toml", line),
        "{new:?}: {e}"
    );
    for w in words {
        assert!(e.problem.contains(w), "{new:?}: {e:?} does not say {w:?}");
    }
}

#[test]
fn every_canonical_scene_reads() {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(scenes_dir())
        .unwrap()
        .chain(std::fs::read_dir(scenes_dir().join("lamps")).unwrap())
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 11, "{paths:?}");
    for p in &paths {
        let s = render::load(p).unwrap_or_else(|e| panic!("{e}"));
        assert!(
            s.settings.spp >= 1 && !s.shapes.is_empty(),
            "{}",
            p.display()
        );
    }
    assert!(parse(GOOD).is_ok());
}

#[test]
fn the_cornell_box_is_the_one_the_issue_specifies() {
    let s = render::load(&scenes_dir().join("cornell.toml")).unwrap();
    assert_eq!((s.camera.width, s.camera.height), (256, 256));
    assert_eq!(s.camera.fov_y_deg, 39.3077);
    assert_eq!(s.camera.position, glam::DVec3::new(278.0, 273.0, -800.0));
    assert_eq!(s.shapes.len(), 7);
    assert_eq!(s.lights.len(), 1);
    let scene::LightShape::Quad(q) = s.lights[0].shape else {
        panic!("the light is a quad")
    };
    assert_eq!(
        q.normal(),
        glam::DVec3::new(0.0, -1.0, 0.0),
        "the light must face down"
    );
    assert_eq!(q.area(), 130.0 * 105.0);
    let glass = s
        .materials
        .iter()
        .filter(|m| matches!(m, Material::Dielectric { .. }))
        .count();
    assert_eq!(glass, 1);
}

mod card;
mod command_line;
mod corruptions;
mod ladder;
mod merge;
mod refused;

fn raylemma() -> Command {
    Command::new(env!("CARGO_BIN_EXE_raylemma"))
}

fn out_dir(name: &str) -> crate::support::Scratch {
    crate::support::scratch(&format!("cli-{name}"))
}
