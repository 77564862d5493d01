//! Tests of the chapter *Testing the renderer* (`src/check/render/`): the path tracer
//! against images known exactly, its estimators against one another, and the power of
//! both against planted biases of known size.
//!
//! Statistical tests (3 of the suite's budget): the exact scenes, the agreement of the
//! estimators, the crops of the canonical scenes against their references; each is one
//! verdict whose claims share `test_alpha()` by Šidák, and each has planted twins it must
//! reject (a global and a local bias, a biased estimator). The images are rendered once
//! and shared by a test and its twins.

use std::sync::OnceLock;

use raylemma::check::Options;
use raylemma::check::render::{self, Rendered, judge, ours, planted, pool, references};
use raylemma::stats::test_alpha;

fn exact_images() -> &'static [Rendered] {
    static IMAGES: OnceLock<Vec<Rendered>> = OnceLock::new();
    IMAGES.get_or_init(|| render::render_exact(&ours, &Options::default()))
}

fn reference_images() -> &'static [Rendered] {
    static IMAGES: OnceLock<Vec<Rendered>> = OnceLock::new();
    IMAGES.get_or_init(|| {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        references::render_references(&references::ours_window, root, &Options::default())
            .unwrap_or_else(|e| panic!("{e}"))
    })
}

fn agreement_images() -> &'static [Rendered] {
    static IMAGES: OnceLock<Vec<Rendered>> = OnceLock::new();
    IMAGES.get_or_init(|| render::render_agreement(&ours, &Options::default()))
}

#[test]
fn the_renderer_matches_every_exact_image() {
    let v = judge(
        "renderer against exact images",
        exact_images(),
        test_alpha(),
    );
    println!("{v}");
    v.assert_pass();
}

/// The scenes whose noise allows a half-percent global bias to be seen.
const SENSITIVE: [&str; 5] = [
    "floor under a quad light",
    "floor under a sphere light",
    "glass sphere in a sky",
    "mirror sphere in a sky",
    "thin film in a sky",
];

#[test]
fn exact_images_reject_a_global_bias_of_half_a_percent() {
    let mut images = exact_images().to_vec();
    for r in &mut images {
        planted::brighten(&mut r.image, 0.005);
    }
    let v = judge("planted: 0.5 % brighter", &images, test_alpha());
    for name in SENSITIVE {
        assert!(
            v.failed(&format!("{name}: global")),
            "{name} missed it:\n{v}"
        );
    }
}

#[test]
fn exact_images_reject_a_local_bias_in_one_block() {
    // One block 3 % too bright, the block at the middle of every image.
    let mut images = exact_images().to_vec();
    let b = pool::BLOCK;
    for r in &mut images {
        let at = (r.image.width / 2 / b * b, r.image.height / 2 / b * b);
        planted::brighten_square(&mut r.image, 0.03, at, b);
    }
    let v = judge("planted: one block 3 % brighter", &images, test_alpha());
    for name in SENSITIVE {
        assert!(
            v.failed(&format!("{name}: blocks")),
            "{name} missed it:\n{v}"
        );
    }
}

#[test]
fn every_estimator_of_one_scene_agrees() {
    let v = judge(
        "renderer: every estimator of one scene agrees",
        agreement_images(),
        test_alpha(),
    );
    println!("{v}");
    v.assert_pass();
}

#[test]
fn agreement_rejects_an_estimator_ten_percent_off() {
    let mut images = agreement_images().to_vec();
    for r in &mut images {
        planted::brighten(&mut r.image, 0.10);
    }
    let v = judge(
        "planted: every variant 10 % brighter",
        &images,
        test_alpha(),
    );
    for r in agreement_images() {
        assert!(
            v.failed(&format!("{}: global", r.name)),
            "{} missed it:\n{v}",
            r.name
        );
    }
}

fn depth_images() -> &'static [Rendered] {
    static IMAGES: OnceLock<Vec<Rendered>> = OnceLock::new();
    IMAGES.get_or_init(|| render::render_depths(&ours, &Options::default()))
}

#[test]
fn every_estimator_agrees_at_every_maximum_depth() {
    let v = judge(
        "renderer: every estimator agrees at every maximum depth",
        depth_images(),
        test_alpha(),
    );
    println!("{v}");
    v.assert_pass();
}

#[test]
fn depth_agreement_rejects_light_sampling_at_the_last_vertex() {
    let planted = planted::light_sampling_one_vertex_deeper(&ours);
    let v = render::depths(&planted, &Options::default());
    for depth in render::DEPTHS {
        let name = format!("light sampling only, max_depth {depth}: global");
        assert!(v.failed(&name), "{name} passed:\n{v}");
    }
    for r in depth_images() {
        if !r.name.starts_with("light sampling only") {
            let name = format!("{}: global", r.name);
            assert!(!v.failed(&name), "{name} failed:\n{v}");
        }
    }
}

#[test]
fn every_canonical_scene_matches_its_reference() {
    let v = judge(
        "renderer against the committed references",
        reference_images(),
        test_alpha(),
    );
    println!("{v}");
    v.assert_pass();
}

/// The canonical scenes whose windows' noise lets a 5 % global bias be seen (the caustics
/// of `cornell`, the dispersive sphere and the bubble are too noisy at these samples).
const QUIET_REFERENCES: [&str; 8] = [
    "cornell-diffuse",
    "lamps-amber-led",
    "lamps-incandescent",
    "lamps-cool-white-fluorescent",
    "lamps-low-pressure-sodium",
    "lamps-high-pressure-sodium",
    "furnace",
    "furnace-grey",
];

#[test]
fn references_reject_a_global_bias_of_five_percent() {
    let mut images = reference_images().to_vec();
    for r in &mut images {
        planted::brighten(&mut r.image, 0.05);
    }
    let v = judge("planted: 5 % brighter", &images, test_alpha());
    for name in QUIET_REFERENCES {
        assert!(
            v.failed(&format!("{name}: global")),
            "{name} missed it:\n{v}"
        );
    }
    // The noisy ones see 20 %.
    let mut images = reference_images().to_vec();
    for r in &mut images {
        planted::brighten(&mut r.image, 0.20);
    }
    let v = judge("planted: 20 % brighter", &images, test_alpha());
    for r in reference_images() {
        assert!(
            v.failed(&format!("{}: global", r.name)),
            "{} missed it:\n{v}",
            r.name
        );
    }
}
