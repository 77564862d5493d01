//! Tests of the `raylemma` command line. (Chapter: *Introduction*; the program itself is
//! described in README.md.) The figure job's own tests (all-or-nothing writing, unknown
//! figure names) are in its crate, `tools/figures/`.
//!
//! `compare` with plain candidates, as another renderer writes them, and every kind of
//! input it refuses (exit status 2, the file and the reason, no panic); its statistics are
//! tested in `renderer::compare`. One statistical test (of the suite's budget of 200):
//! four plain candidates of the reference's scene agree at `raylemma::stats::test_alpha()`;
//! its twin, the same four 3 % brighter, must differ.

use std::path::{Path, PathBuf};
use std::process::Command;

use glam::DVec3;
use raylemma::render::image::Image;
use raylemma::rng;
use raylemma::stats::null::standard_normal;
use raylemma::stats::test_alpha;

use crate::renderer::compare::{tmp, write_plain};

fn raylemma(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_raylemma"))
        .args(args)
        .output()
        .expect("the binary runs")
}

#[test]
fn help_lists_the_subcommands() {
    let out = raylemma(&["--help"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for word in ["figures", "book", "--quick"] {
        assert!(
            text.contains(word),
            "--help does not mention {word}:\n{text}"
        );
    }
}

#[test]
fn unknown_subcommand_is_a_usage_error_not_a_panic() {
    let out = raylemma(&["frobnicate"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("unrecognized subcommand") && err.contains("Usage"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn unknown_flag_is_a_usage_error() {
    let out = raylemma(&["figures", "--colour"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--colour") && err.contains("Usage"), "{err}");
}

/// The exact image of the synthetic scene of the `compare` tests: 16 x 16 pixels.
fn exact(i: usize) -> DVec3 {
    DVec3::new(0.2 + 0.003 * i as f64, 0.5, 0.1 + 0.001 * (i % 7) as f64)
}

/// Writes the reference (exact values plus noise of variance 1e-6, with its variance
/// channels and `spp` 4096) and `k` plain candidates (noise of variance 1e-4, half floats,
/// channels A, B, G, R) scaled by `gain`; returns their paths.
fn synthetic(stem: &str, k: usize, gain: f64) -> (PathBuf, Vec<PathBuf>) {
    let mut rng = rng::seeded(4242);
    let mut noise = |sd: f64| {
        sd * DVec3::new(
            standard_normal(&mut rng),
            standard_normal(&mut rng),
            standard_normal(&mut rng),
        )
    };
    let reference = Image {
        width: 16,
        height: 16,
        mean: (0..256).map(|i| exact(i) + noise(1e-3)).collect(),
        var: vec![DVec3::splat(1e-6); 256],
        spp: Some(4096),
    };
    let ref_path = tmp(&format!("{stem}-ref.exr"));
    reference.write_exr(&ref_path).unwrap();
    let candidates = (0..k)
        .map(|j| {
            let values: Vec<DVec3> = (0..256).map(|i| gain * exact(i) + noise(1e-2)).collect();
            let path = tmp(&format!("{stem}-{j}.exr"));
            write_plain(&path, (16, 16), &["A", "B", "G", "R"], true, |c, i| {
                if c == 0 { 1.0 } else { values[i][3 - c] as f32 }
            });
            path
        })
        .collect();
    (ref_path, candidates)
}

fn compare_files(reference: &Path, candidates: &[PathBuf], extra: &[&str]) -> std::process::Output {
    let alpha = format!("{}", test_alpha());
    Command::new(env!("CARGO_BIN_EXE_raylemma"))
        .arg("compare")
        .arg(reference)
        .args(candidates)
        .args(["--alpha", &alpha])
        .args(extra)
        .output()
        .expect("the binary runs")
}

/// Exit status 2, the stderr naming `what`, and no panic.
fn refused(out: &std::process::Output, what: &[&str]) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    for w in what {
        assert!(err.contains(w), "{w:?} not in: {err}");
    }
}

#[test]
fn compare_takes_plain_candidates_from_another_renderer() {
    let (reference, four) = synthetic("plain", 4, 1.0);
    let out = compare_files(&reference, &four, &[]);
    let report = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{report}");
    assert!(
        report.contains("the spread of 4 images (3 degrees of freedom)")
            && report.contains("4096 samples per pixel")
            && report.contains("AGREE"),
        "{report}"
    );
    // The planted twin: the same scene 3 % brighter.
    let (reference, bright) = synthetic("bright", 4, 1.03);
    let out = compare_files(&reference, &bright, &[]);
    let report = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{report}");
    assert!(report.contains("DIFFER"), "{report}");
    // The report says how large the difference is, with its sign: the candidate is 3 %
    // brighter.
    let red: f64 = report
        .split("with 95 % intervals: R ")
        .nth(1)
        .and_then(|r| r.split(" %").next())
        .and_then(|r| r.parse().ok())
        .unwrap_or(f64::NAN);
    assert!(
        report.contains("positive where the candidate") && (red - 3.0).abs() < 0.3,
        "{red}: {report}"
    );
}

#[test]
fn compare_refuses_what_it_cannot_judge_with_the_file_and_the_reason() {
    let (reference, two) = synthetic("bad", 2, 1.0);
    let name = |p: &Path| p.file_name().unwrap().to_string_lossy().into_owned();
    // One plain image: it cannot say how noisy it is; the message says what to render.
    let out = compare_files(&reference, &two[..1], &[]);
    refused(&out, &[&name(&two[0]), "only candidate", "different seeds"]);
    // A plain reference.
    let out = compare_files(&two[0], &two[1..], &[]);
    refused(&out, &[&name(&two[0]), "no variance channels"]);
    // The same image twice (renders with one seed): no spread to measure noise by.
    let out = compare_files(&reference, &[two[0].clone(), two[0].clone()], &[]);
    refused(&out, &["these 2 images are identical", "different seed"]);
    let out = compare_files(
        &reference,
        &[two[0].clone(), two[1].clone(), two[0].clone()],
        &[],
    );
    refused(&out, &[&name(&two[0]), "are the same image"]);
    // Another size.
    let small = tmp("bad-small.exr");
    write_plain(&small, (8, 16), &["R", "G", "B"], false, |_, _| 0.5);
    let out = compare_files(&reference, &[two[0].clone(), small.clone()], &[]);
    refused(&out, &[&name(&small), "8x16", "16x16"]);
    // NaN and infinite pixels, a negative variance.
    for (file, channels, at, value, why) in [
        (
            "bad-nan.exr",
            &["R", "G", "B"][..],
            (1, 17),
            f32::NAN,
            "pixel (1, 1) channel G is NaN",
        ),
        (
            "bad-inf.exr",
            &["R", "G", "B"][..],
            (0, 3),
            f32::INFINITY,
            "pixel (3, 0) channel R is inf",
        ),
        (
            "bad-var.exr",
            &["R", "G", "B", "var.R", "var.G", "var.B"][..],
            (3, 0),
            -1.0,
            "channel var.R is -1",
        ),
    ] {
        let path = tmp(file);
        write_plain(&path, (16, 16), channels, false, |c, i| {
            if (c, i) == at { value } else { 0.5 }
        });
        let out = compare_files(&reference, &[two[0].clone(), path.clone()], &[]);
        refused(&out, &[file, why]);
    }
    // A truncated file, a PNG, a missing file.
    let bytes = std::fs::read(&two[1]).unwrap();
    let cut = tmp("bad-cut.exr");
    std::fs::write(&cut, &bytes[..bytes.len() - 40]).unwrap();
    refused(
        &compare_files(&reference, &[two[0].clone(), cut], &[]),
        &["bad-cut.exr", "truncated"],
    );
    let png = tmp("bad.png");
    let bytes = raylemma::spectral::display::encode_png(1, 1, &[0, 0, 0]).unwrap();
    std::fs::write(&png, bytes).unwrap();
    refused(
        &compare_files(&reference, &[two[0].clone(), png], &[]),
        &["bad.png", "a PNG image"],
    );
    refused(
        &compare_files(&reference, &[tmp("bad-none.exr")], &[]),
        &["bad-none.exr", "no such file"],
    );
    // A bad level; a difference image that cannot be written (a folder is in the way).
    let out = Command::new(env!("CARGO_BIN_EXE_raylemma"))
        .arg("compare")
        .arg(&reference)
        .args(&two)
        .args(["--alpha", "1.5"])
        .output()
        .unwrap();
    refused(&out, &["--alpha 1.5"]);
    let folder = tmp("bad-diff.png");
    std::fs::create_dir_all(folder.join("keep")).unwrap();
    refused(
        &compare_files(&reference, &two, &["--diff", folder.to_str().unwrap()]),
        &["bad-diff.png"],
    );
    assert!(
        folder.join("keep").is_dir(),
        "the folder in the way was touched"
    );
}

fn export(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_raylemma"))
        .arg("export")
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

#[test]
fn export_writes_both_formats_and_refuses_bad_input_without_touching_earlier_files() {
    let xml = tmp("cornell.xml");
    let json = tmp("cornell.json");
    for (to, out) in [("mitsuba", &xml), ("json", &json)] {
        let o = export(&[
            "scenes/cornell.toml",
            "--to",
            to,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    assert!(
        std::fs::read_to_string(&xml)
            .unwrap()
            .contains("<scene version=\"3.0.0\">")
    );
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(v["format"], "raylemma-scene");
    let earlier = std::fs::read(&xml).unwrap();
    let out = xml.to_str().unwrap();
    // Sellmeier glass: refused for Mitsuba with the line and the feature; the earlier file
    // is left byte for byte. The JSON export of the same scene works.
    refused(
        &export(&["scenes/dispersion.toml", "--to", "mitsuba", "--out", out]),
        &["scenes/dispersion.toml:22:", "Sellmeier dispersion"],
    );
    refused(
        &export(&["scenes/bubble.toml", "--to", "mitsuba", "--out", out]),
        &["scenes/bubble.toml:25:", "thin film"],
    );
    assert_eq!(
        std::fs::read(&xml).unwrap(),
        earlier,
        "a refused export touched the file"
    );
    let o = export(&[
        "scenes/dispersion.toml",
        "--to",
        "json",
        "--out",
        tmp("d.json").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // A bad scene names its file and line.
    let cornell =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell.toml"))
            .unwrap();
    let line = cornell
        .lines()
        .position(|l| l.starts_with("spp ="))
        .unwrap()
        + 1;
    let bad = tmp("bad-scene.toml");
    std::fs::write(&bad, cornell.replace("spp = 4096", "spp = 0")).unwrap();
    refused(
        &export(&[bad.to_str().unwrap(), "--to", "json", "--out", out]),
        &[&format!("bad-scene.toml:{line}:"), "spp"],
    );
    refused(
        &export(&["scenes/none.toml", "--to", "json", "--out", out]),
        &["scenes/none.toml", "cannot read"],
    );
    assert_eq!(std::fs::read(&xml).unwrap(), earlier);
    // An unknown format is a usage error that lists the formats.
    let o = export(&["scenes/cornell.toml", "--to", "pbrt", "--out", out]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("pbrt") && err.contains("mitsuba") && err.contains("json"),
        "{err}"
    );
    // An --out that cannot be written: its folder is a file.
    let blocker = tmp("a-file");
    std::fs::write(&blocker, b"keep").unwrap();
    let inside = blocker.join("scene.xml");
    refused(
        &export(&[
            "scenes/cornell.toml",
            "--to",
            "mitsuba",
            "--out",
            inside.to_str().unwrap(),
        ]),
        &["a-file"],
    );
    assert_eq!(std::fs::read(&blocker).unwrap(), b"keep");
}

/// The crafted files of `tests/data/exr/` (made by its `make.py`): headers that claim sizes
/// the files cannot back. Each is refused, with exit status 2 and the reason, before the
/// reader allocates anything the header asks for (chapter *Bad input*).
#[test]
fn compare_refuses_headers_that_claim_what_the_file_cannot_hold() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/exr");
    for (file, says) in [
        (
            "huge-100000x100000.exr",
            "claims 100000 x 100000 pixels, more than",
        ),
        (
            "wide-1000000000x1.exr",
            "claims 1000000000 x 1 pixels, more than",
        ),
        ("tall-1x10000000.exr", "claims 10000000 blocks of pixels"),
        (
            "dense-60000x16.exr",
            "more than 4096 times the file's 598 bytes",
        ),
    ] {
        let path = dir.join(file);
        let path = path.to_str().expect("a UTF-8 path");
        for args in [["compare", path, path], ["compare", path, "missing.exr"]] {
            let out = raylemma(&args);
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{file}: {err}");
            assert!(err.contains(file) && err.contains(says), "{file}: {err}");
            assert!(!err.contains("panicked"), "{file}: {err}");
        }
    }
}
