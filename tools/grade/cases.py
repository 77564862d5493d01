"""Writes the grader's planted submissions (chapter Coursework, "Grading"): copies of the
solutions edition SOLUTIONS with one kind of mistake each, into OUT/NAME, and prints what
`raylemma grade` must give each with tools/grade/weights.toml (max 27 points: 22
exercises at 1, disc_polar at 3, srgb_encode at 2).

  planted   disc_polar samples r = u1 (not uniform on the disc) and srgb_encode is
            x^(1/2.2) above the break (the linear segment kept): 22 of 27, those two failing;
  looping   disc_polar never returns: 24 of 27, disc_polar failing for its time limit;
  loophole  disc_polar samples r = u1 and the same file's disc_pdf (1/(2 pi r)) and
            disc_polar_invert (r instead of r^2) are changed to match, so that the
            submission's own card passes it: the grader puts back the edition's disc_pdf
            and inverse, 24 of 27;
  escape    the escape of issue 40: a wrong amplitudes whose body ends with
            `} #[cfg(any())] mod hidden { fn h() {`, and fresnel_transmittance's body that
            closes it and redefines the edition's fresnel_polarized and fresnel_dielectric
            (which the card judges amplitudes by) between: both bodies are refused for
            brackets that do not balance and graded as their stubs (not started), 25 of 27;
  exit      disc_polar's body, when it runs in the card (whose command line has `--json
            FILE`), writes a card of its own with every exercise passing to FILE and calls
            std::process::exit(0) before the card writes its own: without the grader's
            check of the bodies, 27 of 27; its body is refused for reaching std::env,
            std::fs and std::process and graded as its stub, 24 of 27;
  include   srgb_encode's body is `include!("srgb_answer.rs")`, a file the submission adds
            next to it (its code is then not between the markers, and could be anything
            the grader's machine holds): refused, graded as its stub, 25 of 27.

It also writes OUT/expected.json, the marks and failing exercises CI requires.

Usage: python3 tools/grade/cases.py SOLUTIONS OUT   (standard library only)
"""
import json
import pathlib
import shutil
import sys

solutions, out = map(pathlib.Path, sys.argv[1:3])


def edit(root: pathlib.Path, path: str, old: str, new: str) -> None:
    f = root / path
    text = f.read_text()
    if text.count(old) != 1:
        sys.exit(f"{f}: expected exactly one {old!r} to replace; the solutions changed")
    f.write_text(text.replace(old, new))


def case(name: str) -> pathlib.Path:
    dest = out / name
    if dest.exists():
        shutil.rmtree(dest)
    shutil.copytree(solutions, dest, ignore=shutil.ignore_patterns("target"))
    return dest


NON_UNIFORM = ("    let r = u.x.sqrt();\n    let phi = consts::TAU * u.y;",
               "    let r = u.x;\n    let phi = consts::TAU * u.y;")
DISC = "src/sampling/disc.rs"

d = case("planted")
edit(d, DISC, *NON_UNIFORM)
edit(d, "src/spectral/display.rs", "1.055 * x.powf(1.0 / 2.4) - 0.055", "x.powf(1.0 / 2.2)")

d = case("looping")
edit(d, DISC, "    let r = u.x.sqrt();\n    let phi = consts::TAU * u.y;\n    V3::new(r * phi.cos(), r * phi.sin(), 0.0)",
     "    loop {\n        std::hint::spin_loop();\n    }")

d = case("loophole")
edit(d, DISC, *NON_UNIFORM)
edit(d, DISC, "    V2::new(p.x * p.x + p.y * p.y, phi / consts::TAU)",
     "    V2::new((p.x * p.x + p.y * p.y).sqrt(), phi / consts::TAU)")
edit(d, DISC, "    if p.x * p.x + p.y * p.y <= 1.0 {\n        DISC_PDF",
     "    if p.x * p.x + p.y * p.y <= 1.0 {\n        1.0 / (consts::TAU * (p.x * p.x + p.y * p.y).sqrt())")

FRESNEL = "src/optics/fresnel.rs"
AMPLITUDES_END = "        t_p: 2.0 * a / (d + e),\n        cos_t,\n    })\n"
TRANSMITTANCE_START = "    if n1 == n2 {\n        return Polarized { s: 1.0, p: 1.0 };\n    }\n"
d = case("escape")
edit(d, FRESNEL, "        r_s: (a - b) / (a + b),\n", "        r_s: 0.5 * (a - b) / (a + b), // wrong\n")
edit(d, FRESNEL, AMPLITUDES_END, AMPLITUDES_END
     + "}\n#[cfg(any())]\nmod hidden {\n    fn h() {\n")
edit(d, FRESNEL, TRANSMITTANCE_START, """        unreachable!()
    }
}
pub fn fresnel_polarized(cos_i: f64, n1: f64, n2: f64) -> Polarized {
    let c = clamp_cos(cos_i);
    if n1 == n2 {
        return Polarized { s: 0.0, p: 0.0 };
    }
    let Some(cos_t) = cos_transmitted(c, n1, n2) else {
        return Polarized { s: 1.0, p: 1.0 };
    };
    let rs = (n1 * c - n2 * cos_t) / (n1 * c + n2 * cos_t);
    let rp = (n2 * c - n1 * cos_t) / (n2 * c + n1 * cos_t);
    Polarized { s: rs * rs, p: rp * rp }
}
pub fn fresnel_dielectric(cos_i: f64, n1: f64, n2: f64) -> f64 {
    fresnel_polarized(cos_i, n1, n2).unpolarized()
}
pub fn fresnel_transmittance(cos_i: f64, n1: f64, n2: f64) -> Polarized {
""" + TRANSMITTANCE_START)

d = case("exit")
edit(d, DISC, "    let r = u.x.sqrt();\n    let phi = consts::TAU * u.y;", """    let args: Vec<String> = std::env::args().collect();
    if let Some(i) = args.iter().position(|a| a == "--json") {
        let markers = crate::exercise::edition::markers_under(std::path::Path::new(".")).unwrap();
        let card = crate::exercise::card::run_with(&markers, |_| crate::exercise::card::Status::Passing);
        std::fs::write(&args[i + 1], serde_json::to_string(&card.report()).unwrap()).unwrap();
        std::process::exit(0);
    }
    let r = u.x.sqrt();
    let phi = consts::TAU * u.y;""")

SRGB = "src/spectral/display.rs"
SRGB_BODY = """    if x > SRGB_LINEAR_BREAK {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    } else if x > 0.0 {
        12.92 * x
    } else {
        0.0
    }
"""
d = case("include")
edit(d, SRGB, "pub fn srgb_encode(x: f64) -> f64 {\n" + SRGB_BODY,
     "pub fn srgb_encode(x: f64) -> f64 {\n    include!(\"srgb_answer.rs\")\n")
(d / "src/spectral/srgb_answer.rs").write_text("{\n" + SRGB_BODY + "}\n")

expected = {
    "solutions": {"score": 27, "failing": []},
    "handout": {"score": 0, "failing": []},
    "planted": {"score": 22, "failing": ["disc_polar", "srgb_encode"]},
    "looping": {"score": 24, "failing": ["disc_polar"]},
    "loophole": {"score": 24, "failing": ["disc_polar"]},
    "escape": {"score": 25, "failing": []},
    "exit": {"score": 24, "failing": []},
    "include": {"score": 25, "failing": []},
}
(out / "expected.json").write_text(json.dumps(expected, indent=2) + "\n")
print(f"planted submissions written to {out}: planted, looping, loophole, escape, exit, include")
