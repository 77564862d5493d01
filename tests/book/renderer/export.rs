//! Tests of `export` (`src/conformance/export/`; chapter *Reference scenes and interop*, *Exporting a
//! scene*): the JSON is fully resolved (defaults, 1 nm spectra equal to the data files,
//! explicit transforms); the Mitsuba XML follows the rules checked against Mitsuba in
//! `tools/mitsuba/NOTES.md`; what Mitsuba cannot express is refused with its line and
//! kept by the JSON. Every expected value comes from the data files, the NOTES or
//! arithmetic done here, never from the exporter. That Mitsuba renders the files is the
//! job of `tools/mitsuba/compare_all.sh`, outside `cargo test`. The pbrt-v4 file follows the
//! rules of `tools/pbrt/NOTES.md` (checked against pbrt-v4's source, not by rendering): a
//! small tokenizer here checks its syntax and reads its numbers back.

use std::path::Path;

use raylemma::conformance::export::{SceneFile, json::to_json, mitsuba::to_xml, pbrt::to_pbrt};
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

mod json;
mod mitsuba;
mod pbrt;

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

// ---------------------------------------------------------------------------------------
// pbrt-v4: the tokenizer and the well-formedness check (`renderer::scene` uses it too); the
// tests are in `pbrt`.

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

/// raylemma's `∫ȳ dλ`: the trapezoid rule on the 1 nm table.
fn y_integral() -> f64 {
    let y = column("cie1931_2deg_cmf_1nm.csv", "ybar");
    y.iter().sum::<f64>() - (y[0] + y[y.len() - 1]) / 2.0
}
