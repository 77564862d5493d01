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
use raylemma::image::Image;
use raylemma::rng;
use raylemma::rng::standard_normal;
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
            && report.contains("pass --spp")
            && report.contains("AGREE"),
        "{report}"
    );
    // Floored, as the planted twin below is: agree too.
    let out = compare_files(&reference, &four, &["--spp", "41"]);
    let report = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{report}");
    assert!(report.contains("raised where smaller"), "{report}");
    // The planted twin: the same scene 3 % brighter, with the candidates' samples per
    // pixel (a reference of 4096 with a hundredth of a candidate's variance: 41), which
    // turns the floor on; without it, four images leave the region tests no power.
    let (reference, bright) = synthetic("bright", 4, 1.03);
    let out = compare_files(&reference, &bright, &["--spp", "41"]);
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
    let bytes = raylemma::image::png::encode_png(1, 1, &[0, 0, 0]).unwrap();
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
fn export_writes_every_format_and_refuses_bad_input_without_touching_earlier_files() {
    let xml = tmp("cornell.xml");
    let json = tmp("cornell.json");
    let pbrt = tmp("cornell.pbrt");
    for (to, out) in [("mitsuba", &xml), ("json", &json), ("pbrt", &pbrt)] {
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
        std::fs::read_to_string(crate::support::root().join("scenes/cornell.toml")).unwrap();
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
    // pbrt-v4: the Cornell box is written; a thin film is refused with its line, and the
    // earlier file is left byte for byte.
    let earlier = std::fs::read(&pbrt).unwrap();
    assert!(String::from_utf8_lossy(&earlier).contains("\nWorldBegin\n"));
    refused(
        &export(&[
            "scenes/bubble.toml",
            "--to",
            "pbrt",
            "--out",
            pbrt.to_str().unwrap(),
        ]),
        &["scenes/bubble.toml:25:", "thin film", "pbrt-v4"],
    );
    assert_eq!(
        std::fs::read(&pbrt).unwrap(),
        earlier,
        "a refused export touched the file"
    );
    // An unknown format is a usage error that lists the formats.
    let o = export(&["scenes/cornell.toml", "--to", "povray", "--out", out]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("povray")
            && err.contains("pbrt")
            && err.contains("mitsuba")
            && err.contains("json"),
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
    let dir = crate::support::root().join("tests/data/exr");
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

/// `k` plain float candidates of the synthetic scene (as [`synthetic`]'s, seed `seed`),
/// each pixel put through `to_file` and written as the channels `names`.
fn candidates_as(
    stem: &str,
    k: usize,
    names: [&str; 3],
    to_file: impl Fn(DVec3) -> DVec3,
) -> Vec<PathBuf> {
    let mut rng = rng::seeded(99);
    (0..k)
        .map(|j| {
            let values: Vec<DVec3> = (0..256)
                .map(|i| {
                    let n = DVec3::new(
                        standard_normal(&mut rng),
                        standard_normal(&mut rng),
                        standard_normal(&mut rng),
                    );
                    to_file(exact(i) + 1e-2 * n)
                })
                .collect();
            let path = tmp(&format!("{stem}-{j}.exr"));
            write_plain(&path, (16, 16), &names, false, |c, i| values[i][c] as f32);
            path
        })
        .collect()
}

/// Candidates written as CIE XYZ, as Mitsuba's spectral films write them: read by their
/// channel names X, Y, Z and converted to linear sRGB, they agree; the same values under
/// the names R, G, B (XYZ mistaken for sRGB) differ, and the report's hint names the
/// matrix; ordinary sRGB candidates 3 % too bright differ with no such hint.
#[test]
fn compare_reads_xyz_channels_and_hints_at_xyz_written_as_rgb() {
    use raylemma::spectral::cie::linear_srgb_to_xyz;
    let (reference, _) = synthetic("xyz", 1, 1.0);
    // Each candidate with the samples per pixel of its noise (see `synthetic`): floored.
    let spp: &[&str] = &["--spp", "41"];
    let xyz = candidates_as("xyz-named", 4, ["X", "Y", "Z"], linear_srgb_to_xyz);
    let out = compare_files(&reference, &xyz, spp);
    let report = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{report}");
    assert!(
        report.contains("X, Y, Z (CIE XYZ) converted to linear sRGB"),
        "{report}"
    );
    let mislabelled = candidates_as("xyz-as-rgb", 4, ["R", "G", "B"], linear_srgb_to_xyz);
    let out = compare_files(&reference, &mislabelled, spp);
    let report = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{report}");
    assert!(
        report.contains("hint:") && report.contains("taken as CIE XYZ"),
        "{report}"
    );
    let bright = candidates_as("xyz-bright", 4, ["R", "G", "B"], |v| 1.03 * v);
    let out = compare_files(&reference, &bright, spp);
    let report = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{report}");
    assert!(!report.contains("hint:"), "{report}");
}

/// The difference image outlines a failed block in yellow even where no pixel fails: a
/// candidate 1 % brighter (a tenth of a pixel's sd, far beyond a 16 x 16 block's) fails the
/// block and the whole image but hardly a pixel; the agreeing candidates get no outline.
#[test]
fn the_difference_image_outlines_failed_blocks() {
    let (reference, _) = synthetic("blocks", 1, 1.0);
    let png_of = |candidates: &[PathBuf], name: &str| {
        let png = tmp(name);
        let out = compare_files(&reference, candidates, &["--diff", png.to_str().unwrap()]);
        (out.status.code(), crate::support::read_png(&png))
    };
    let yellow = |p: [u8; 3]| p[0] > 200 && p[1] > 180 && p[2] < 60;
    let (status, ok) = png_of(
        &candidates_as("blocks-ok", 8, ["R", "G", "B"], |v| v),
        "ok.png",
    );
    assert_eq!(status, Some(0));
    assert!(!ok.pixels().any(yellow), "an outline where nothing failed");
    let bright = candidates_as("blocks-bright", 8, ["R", "G", "B"], |v| 1.01 * v);
    let (status, diff) = png_of(&bright, "bright.png");
    assert_eq!(status, Some(1));
    for (x, y) in [(0, 0), (15, 0), (0, 15), (15, 15), (7, 0), (0, 9)] {
        assert!(
            yellow(diff.pixel(x, y)),
            "({x}, {y}): {:?}",
            diff.pixel(x, y)
        );
    }
    assert!(
        !yellow(diff.pixel(7, 7)),
        "the block's inside is its pixels' colours"
    );
}

/// `check sampler --failure-images DIR` writes the failure images into DIR, and the
/// message names it: a file of uniform hemisphere samples claimed as cosine-weighted.
#[test]
fn check_sampler_writes_failure_images_where_it_is_told() {
    use raylemma::check::warp::{self, planted};
    let dir = tmp("failure-images");
    let _ = std::fs::remove_dir_all(&dir);
    let mut rng = rng::seeded(5);
    let mut text = String::from("x,y,z\n");
    for _ in 0..20_000 {
        let p = planted::hemisphere_uniform(warp::square_point(&mut rng));
        text.push_str(&format!("{:?},{:?},{:?}\n", p.x, p.y, p.z));
    }
    let samples = tmp("uniform-as-cosine.csv");
    std::fs::write(&samples, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_raylemma"))
        .args([
            "check",
            "sampler",
            "--target",
            "cosine-hemisphere",
            "--samples",
        ])
        .arg(&samples)
        .arg("--failure-images")
        .arg(&dir)
        .output()
        .expect("the binary runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(1),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.contains(&format!("images in {}", dir.display())),
        "{text}"
    );
    let written: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(written.len(), 1, "{text}");
    let folder = written[0].as_ref().unwrap().path();
    for f in ["observed.png", "expected.png", "difference.png"] {
        assert!(
            folder.join(f).is_file(),
            "{f} missing in {}",
            folder.display()
        );
    }
}

/// `raylemma conformance` with raylemma itself as the renderer passes rung 1 (exit 0, the
/// card as JSON and JUnit); the same renderer with its light 5 % too bright fails it and the
/// card's first failing rung names what it tests; a renderer that writes nothing is an
/// error on the rung (exit 1) and the suite goes on; an unknown rung is a usage error.
#[test]
fn conformance_passes_raylemma_and_points_at_a_fault() {
    let bin = env!("CARGO_BIN_EXE_raylemma");
    let work = tmp("conformance");
    let _ = std::fs::remove_dir_all(&work);
    let run = |renderer: &str, extra: &[&str]| {
        Command::new(bin)
            .args([
                "conformance",
                "--format",
                "toml",
                "--rungs",
                "1",
                "--runs",
                "3",
                "--spp",
                "16",
            ])
            .arg("--renderer")
            .arg(renderer)
            .arg("--work")
            .arg(&work)
            .args(extra)
            .output()
            .expect("the binary runs")
    };
    let ours = format!("{bin} render {{scene}} --spp {{spp}} --seed {{seed}} --out {{outdir}}");
    let (json, junit) = (tmp("card.json"), tmp("card.xml"));
    let out = run(
        &ours,
        &[
            "--json",
            json.to_str().unwrap(),
            "--junit",
            junit.to_str().unwrap(),
        ],
    );
    let card = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{card}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(card.contains("every rung AGREES"), "{card}");
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(v["rungs"][0]["verdict"], "agree", "{v}");
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(
        xml.contains("tests=\"1\" failures=\"0\" errors=\"0\""),
        "{xml}"
    );
    // The planted fault: every emitter 5 % too bright.
    let bright = format!(
        "sed 's/^emission = 10$/emission = 10.5/' {{scene}} > {{outdir}}/b.toml && {bin} render {{outdir}}/b.toml --spp {{spp}} --seed {{seed}} --out {{outdir}} && mv {{outdir}}/b.exr {{out}}"
    );
    let out = run(&bright, &[]);
    let card = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{card}");
    assert!(
        card.contains("first differing: rung 1")
            && card.contains("what failed: ")
            && card.contains("the whole image's mean in R")
            && card.contains("a failure here usually means")
            && card.contains("differ"),
        "{card}"
    );
    // A renderer that fails is not physics: the card names the command, how it ended, the
    // last lines of its output and the image it was to write, and no physical cause.
    let out = run("true", &[]);
    let card = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{card}");
    assert!(
        card.contains("error") && card.contains("wrote no image") && card.contains("FAILED"),
        "{card}"
    );
    let out = run("echo cannot read {scene} >&2; exit 3", &[]);
    let card = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{card}");
    for needed in [
        "exited with status 3",
        "| cannot read ",
        "command: echo cannot read ",
        "the image it was to write: ",
        "no verdict on its physics",
    ] {
        assert!(card.contains(needed), "{needed} missing from {card}");
    }
    assert!(
        !card.contains("usually means") && !card.contains("DIFFERS"),
        "{card}"
    );
    let out = run(&ours, &["--rungs", "99"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no rung 99"));
    // A rung the format's export refuses is skipped with the refusal, file and line, and
    // its renderer is never run (here one that would fail).
    let out = Command::new(bin)
        .args([
            "conformance",
            "--format",
            "pbrt",
            "--rungs",
            "10",
            "--runs",
            "2",
        ])
        .args(["--renderer", "false", "--work"])
        .arg(&work)
        .output()
        .expect("the binary runs");
    let card = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{card}");
    assert!(
        card.contains("skipped")
            && card.contains("10-thin-film.toml:")
            && card.contains("thin film"),
        "{card}"
    );
}

/// `card` judges the code compiled into its binary, so this crate's binary run inside a
/// hand-out would judge the solved code here and print *passing*: it refuses (exit status 2),
/// naming the hand-out and the crate it was built from, and says what to run instead
/// (chapter *Coursework*, *The report card*).
#[test]
fn card_refuses_to_judge_a_crate_other_than_its_own() {
    let dir = crate::support::scratch("card-elsewhere");
    let hand_out = dir.join("hand-out");
    std::fs::create_dir_all(hand_out.join("src")).unwrap();
    std::fs::write(
        hand_out.join("Cargo.toml"),
        "[package]\nname = \"raylemma-hand-out\"\n",
    )
    .unwrap();
    std::fs::write(
        hand_out.join(".raylemma-edition"),
        "raylemma student edition: hand-out\n",
    )
    .unwrap();
    for cwd in [hand_out.clone(), hand_out.join("src")] {
        let out = Command::new(env!("CARGO_BIN_EXE_raylemma"))
            .arg("card")
            .current_dir(&cwd)
            .output()
            .expect("the binary runs");
        let hand_out = std::fs::canonicalize(&hand_out).unwrap();
        refused(
            &out,
            &[
                &format!("is in the hand-out edition at {}", hand_out.display()),
                &format!(
                    "built from {}",
                    std::fs::canonicalize(crate::support::root())
                        .unwrap()
                        .display()
                ),
                "run `cargo run -- card` inside the crate",
            ],
        );
        assert!(
            out.stdout.is_empty(),
            "{}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
}

/// `card` and `grade` refuse what they cannot use with exit status 2 and the reason: an
/// exercise that does not exist, a folder that is not an edition, a weights file with an
/// exercise that does not exist (its line), before anything is built or written. (The
/// grading itself builds a crate, and is run by CI on five submissions.)
#[test]
fn card_and_grade_refuse_bad_input_before_building_anything() {
    refused(
        &raylemma(&["card", "disc_polr"]),
        &["no exercise is called `disc_polr`", "disc_polar"],
    );
    let dir = crate::support::scratch("grade-cli");
    std::fs::create_dir_all(dir.join("submission")).unwrap();
    let submission = dir.join("submission");
    let out = dir.join("grade");
    let args = |extra: &[&str]| {
        let mut a = vec![
            "grade".to_string(),
            submission.display().to_string(),
            "--out".into(),
            out.display().to_string(),
            "--work".into(),
            dir.join("work").display().to_string(),
        ];
        a.extend(extra.iter().map(|s| s.to_string()));
        a
    };
    let run = |a: Vec<String>| raylemma(&a.iter().map(String::as_str).collect::<Vec<_>>());
    refused(
        &run(args(&[])),
        &["not a raylemma edition", ".raylemma-edition"],
    );
    std::fs::write(
        submission.join(".raylemma-edition"),
        "raylemma student edition: hand-out\n",
    )
    .unwrap();
    let weights = dir.join("weights.toml");
    std::fs::write(&weights, "default = 1\n[points]\ndisc_polr = 2\n").unwrap();
    let w = weights.display().to_string();
    refused(
        &run(args(&["--weights", &w])),
        &["weights.toml:3:", "no exercise is called `disc_polr`"],
    );
    assert!(
        !out.exists() && !dir.join("work").exists(),
        "something was written"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A closed pipe is not an error: `raylemma check corpus | head -1` ends quietly with status
/// 0 once its reader is gone, never with a panic (status 101).
#[test]
fn a_closed_pipe_ends_quietly_with_status_zero() {
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_raylemma"))
        .args(["check", "corpus"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    // The reader goes away before the first line (the corpora take a while to check), so
    // the first line written meets a closed pipe.
    drop(child.stdout.take());
    let out = child.wait_with_output().expect("it ends");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}
