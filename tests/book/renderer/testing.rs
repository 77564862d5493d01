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
use raylemma::check::render::{self, Rendered, judge, ours, pictures, planted, pool, references};
use raylemma::stats::test_alpha;

fn exact_images() -> &'static [Rendered] {
    static IMAGES: OnceLock<Vec<Rendered>> = OnceLock::new();
    IMAGES.get_or_init(|| render::render_exact(&ours, &Options::default()))
}

fn reference_images() -> &'static [Rendered] {
    static IMAGES: OnceLock<Vec<Rendered>> = OnceLock::new();
    IMAGES.get_or_init(|| {
        let root = crate::support::root();
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
    assert_pass_with_pictures(&v, exact_images());
}

/// Passes if `v` does; else draws each failing scene (render, expected, difference) into
/// `results/renderer/` of the crate and fails, naming the folder.
fn assert_pass_with_pictures(v: &raylemma::check::Verdict, rendered: &[Rendered]) {
    if v.passed() {
        return;
    }
    let dir = crate::support::root().join(pictures::results_dir());
    let files = pictures::write_failed(&dir, rendered, v);
    panic!(
        "{v}\npictures of the failing scenes (your render, the expected image, 4 x their difference): {}",
        files
            .iter()
            .map(|f| f.display().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    );
}

/// The scenes whose noise allows a half-percent global bias to be seen.
const SENSITIVE: [&str; 5] = [
    "floor under a quad light",
    "floor under a sphere light",
    "glass sphere in a sky",
    "mirror sphere in a sky",
    "thin film in a sky",
];

/// The planted biases of this file's twins, each at least twice the smallest bias its check
/// detects for nine seeds in ten (the power table, `figures/render_test_power.md`; the test
/// `planted_biases_are_twice_their_thresholds` holds them to it), so that a twin fails for
/// its bias and not for the luck of one seed.
const EXACT_GLOBAL: f64 = 0.01;
const EXACT_LOCAL: f64 = 0.03;
const AGREEMENT: f64 = 0.30;
const QUIET_REFERENCE: f64 = 0.05;
const NOISY_REFERENCE: f64 = 0.20;

#[test]
fn exact_images_reject_a_global_bias_of_one_percent() {
    let mut images = exact_images().to_vec();
    for r in &mut images {
        planted::brighten(&mut r.image, EXACT_GLOBAL);
    }
    let v = judge("planted: 1 % brighter", &images, test_alpha());
    for name in SENSITIVE {
        assert!(
            v.failed(&format!("{name}: global")),
            "{name} missed it:\n{v}"
        );
    }
    // The pictures a failure leaves: one per failing scene, its three panels side by side.
    let dir = crate::support::scratch("renderer-pictures");
    let files = pictures::write_failed(dir.as_path(), &images, &v);
    assert!(files.len() >= SENSITIVE.len(), "{files:?}");
    let quad = images
        .iter()
        .find(|r| r.name == SENSITIVE[0])
        .map(|r| (r.image.width, r.image.height));
    let png = crate::support::read_png(&dir.as_path().join("floor-under-a-quad-light.png"));
    assert_eq!(quad, Some(((png.width - 8) / 3, png.height)));
}

#[test]
fn exact_images_reject_a_local_bias_in_one_block() {
    // One block 3 % too bright, the block at the middle of every image.
    let mut images = exact_images().to_vec();
    let b = pool::BLOCK;
    for r in &mut images {
        let at = (r.image.width / 2 / b * b, r.image.height / 2 / b * b);
        planted::brighten_square(&mut r.image, EXACT_LOCAL, at, b);
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
fn agreement_rejects_an_estimator_thirty_percent_off() {
    let mut images = agreement_images().to_vec();
    for r in &mut images {
        planted::brighten(&mut r.image, AGREEMENT);
    }
    let v = judge(
        "planted: every variant 30 % brighter",
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
    assert_pass_with_pictures(&v, reference_images());
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
        planted::brighten(&mut r.image, QUIET_REFERENCE);
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
        planted::brighten(&mut r.image, NOISY_REFERENCE);
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

/// Each twin's planted bias is at least twice the nine-in-ten threshold that the power table
/// measured for every row it asserts on (`render_test_power` in `figures/values.json`): a
/// twin asserting at its threshold would fail one seed in ten for no fault of the image.
#[test]
fn planted_biases_are_twice_their_thresholds() {
    let figures = crate::support::root().join("figures");
    let values = raylemma_values::read(&figures).unwrap_or_else(|e| panic!("{e}"));
    let power = &values["render_test_power"].values;
    let threshold = |check: &str, name: &str| {
        let key = format!("{check}.{}.smallest_global", raylemma_values::slug(name));
        // A row whose bias is not detected even at 50 % has no value: infinite.
        power
            .get(&key)
            .and_then(|v| v.number)
            .map_or(f64::INFINITY, |p| p / 100.0)
    };
    let mut rows: Vec<(&str, String, f64)> = Vec::new();
    rows.extend(
        SENSITIVE
            .iter()
            .map(|n| ("exact", n.to_string(), EXACT_GLOBAL)),
    );
    rows.extend(
        agreement_images()
            .iter()
            .map(|r| ("agreement", r.name.clone(), AGREEMENT)),
    );
    rows.extend(
        QUIET_REFERENCES
            .iter()
            .map(|n| ("references", n.to_string(), QUIET_REFERENCE)),
    );
    rows.extend(
        reference_images()
            .iter()
            .map(|r| ("references", r.name.clone(), NOISY_REFERENCE)),
    );
    for (check, name, planted) in rows {
        let t = threshold(check, &name);
        assert!(
            planted >= 2.0 * t,
            "{check} {name}: planted {planted}, threshold {t} (render_test_power)"
        );
    }
}

// ---- Edges (`src/check/render/edges.rs`) ----

use glam::{DVec2, DVec3};
use raylemma::check::render::{EDGE_BLOCK, edges, exact, independence, scenes};
use raylemma::render::scene::LightShape;

/// The exact scenes whose every pixel, edges included, is tested.
const EDGES: [&str; 3] = [
    "edges of two lights seen directly",
    "edges of a red quad in a sky",
    "shadows of two lights",
];

#[test]
fn coverage_of_a_triangle_is_its_area_in_each_pixel() {
    // The triangle (0, 0), (2, 0), (0, 2): pixel (0, 0) whole, (1, 0) and (0, 1) half,
    // (1, 1) touched at a corner only. Both orientations.
    let t = [DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(0.0, 2.0)];
    let mut reversed = t;
    reversed.reverse();
    for poly in [&t[..], &reversed[..]] {
        let got =
            [(0, 0), (1, 0), (0, 1), (1, 1), (2, 0)].map(|(x, y)| edges::coverage(poly, x, y));
        assert_eq!(got, [1.0, 0.5, 0.5, 0.0, 0.0], "{poly:?}");
    }
    // A thin sliver across a pixel: 0.1 x 1 at a slant of 1 in 4.
    let sliver = [
        DVec2::new(0.3, -1.0),
        DVec2::new(0.4, -1.0),
        DVec2::new(0.9, 3.0),
        DVec2::new(0.8, 3.0),
    ];
    let c = edges::coverage(&sliver, 0, 0);
    assert!((c - 0.1).abs() < 1e-15, "sliver: {c}");
}

/// The edges of the lights and of the quad are turned against the pixel grid: every edge's
/// image at least 10 degrees from the image's rows and columns (the chapter: 14 to 40), so
/// that the pixels along it are covered in many shares.
#[test]
fn the_flat_scenes_edges_are_turned_against_the_pixel_grid() {
    use raylemma::render::scene::Geometry;
    let mut angles = Vec::new();
    let lights = scenes::lights_seen_directly(32, 1);
    let quad = scenes::coloured_quad_in_sky(32, 1);
    let mut polygons: Vec<Vec<DVec2>> = lights
        .lights
        .iter()
        .map(|l| match &l.shape {
            LightShape::Quad(q) => edges::image_of(&lights.camera, q.shape()),
            LightShape::Sphere(_) => unreachable!("the lights are parallelograms"),
        })
        .collect();
    if let Geometry::Quad(q) = &quad.shapes[0].geometry {
        polygons.push(edges::image_of(&quad.camera, q));
    }
    assert_eq!(polygons.len(), 3);
    for poly in &polygons {
        for i in 0..poly.len() {
            let d = poly[(i + 1) % poly.len()] - poly[i];
            let degrees = d.y.atan2(d.x).to_degrees().rem_euclid(90.0);
            angles.push(degrees.min(90.0 - degrees));
        }
    }
    let least = angles.iter().copied().fold(f64::INFINITY, f64::min);
    // NaN-safe: a NaN angle is caught by the `all`.
    assert!(
        angles.iter().all(|a| *a >= 10.0) && least >= 14.0,
        "edges at {angles:?} degrees from the pixel grid"
    );
}

#[test]
fn image_point_inverts_the_camera_ray() {
    let scene = scenes::lights_seen_directly(32, 1);
    let mut misses = Vec::new();
    for (px, py) in [
        (0.0, 0.0),
        (31.999, 0.5),
        (13.25, 7.75),
        (32.0, 32.0),
        (5.5, 30.1),
    ] {
        let (o, d) = exact::camera_ray(&scene.camera, px, py);
        let p = edges::image_point(&scene.camera, o + 3.7 * d).unwrap_or(DVec2::NAN);
        misses.extend((p - DVec2::new(px, py)).to_array());
    }
    // `max_abs` keeps a NaN (a point wrongly refused), which then fails the bound.
    let worst = raylemma::check::max_abs(misses);
    assert!(worst <= 1e-12, "image_point misses by {worst} pixels");
    let behind = scene.camera.position - (scene.camera.look_at - scene.camera.position);
    assert_eq!(edges::image_point(&scene.camera, behind), None);
}

/// The irradiance from a rectangle part of which an occluder hides, by brute force: the
/// light's area cut into `n x n` cells, each cell's centre tested against the occluder's
/// rectangle by the segment's crossing of its plane, `cos cos' / r^2` summed.
fn brute_force_irradiance(p: DVec3, light: &edges::Rect, occ: &edges::Rect, n: u32) -> f64 {
    let (dx, dz) = (
        (light.x[1] - light.x[0]) / f64::from(n),
        (light.z[1] - light.z[0]) / f64::from(n),
    );
    let mut sum = 0.0;
    for i in 0..n {
        for j in 0..n {
            let q = DVec3::new(
                light.x[0] + (f64::from(i) + 0.5) * dx,
                light.y,
                light.z[0] + (f64::from(j) + 0.5) * dz,
            );
            let s = (occ.y - p.y) / (q.y - p.y);
            let cross = p + s * (q - p);
            let hidden = (occ.x[0]..=occ.x[1]).contains(&cross.x)
                && (occ.z[0]..=occ.z[1]).contains(&cross.z);
            if !hidden {
                let v = q - p;
                let r2 = v.length_squared();
                let cos = v.y / r2.sqrt();
                sum += cos * cos / r2 * dx * dz;
            }
        }
    }
    sum
}

#[test]
fn the_shadow_s_irradiance_matches_a_brute_force_sum_across_the_penumbra() {
    let scene = scenes::shadows_of_two_lights(32, 1);
    let rect = |k: usize| match &scene.lights[k].shape {
        LightShape::Quad(q) => edges::Rect::of(q.shape()),
        LightShape::Sphere(_) => unreachable!("the scene's lights are rectangles"),
    };
    let occ = match &scene.shapes[1].geometry {
        raylemma::render::scene::Geometry::Quad(q) => edges::Rect::of(q),
        raylemma::render::scene::Geometry::Sphere(_) => unreachable!("the occluder is a quad"),
    };
    let mut partly = 0;
    for k in 0..2 {
        let light = rect(k);
        // A line of floor points across both shadows.
        for step in 0..=40 {
            let p = DVec3::new(-0.6 + 0.03 * f64::from(step), 0.0, 0.55);
            let exact = edges::unoccluded_irradiance(p, &light, &occ);
            let whole = edges::unoccluded_irradiance(
                p,
                &light,
                &edges::Rect {
                    x: [9.0, 9.5],
                    z: [9.0, 9.5],
                    y: occ.y,
                },
            );
            // The cells the shadow's outline crosses are all in or all out: an error of
            // about one cell's side along it, relative.
            let brute = brute_force_irradiance(p, &light, &occ, 400);
            assert!(
                (exact - brute).abs() <= 2.5e-3 * whole,
                "light {k} at {p}: Lambert less the overlap {exact}, brute force {brute}"
            );
            if exact > 0.05 * whole && exact < 0.95 * whole {
                partly += 1;
            }
        }
    }
    assert!(
        partly >= 6,
        "only {partly} points in a penumbra: the line misses the shadows"
    );
}

#[test]
fn the_shadow_s_quadrature_is_far_below_the_noise() {
    // The composite rule of the tests (6 x 6 squares) against one twice as fine, in units
    // of each pixel's standard error at the tests' samples.
    let scene = &exact_images()
        .iter()
        .find(|r| r.name == "shadows of two lights")
        .unwrap_or_else(|| panic!("no shadow scene"));
    let list = render::edge_scenes(1.0);
    let s = &list
        .iter()
        .find(|s| s.name == "shadows of two lights")
        .unwrap_or_else(|| panic!("no shadow scene"))
        .scene;
    // The coarse rule is the tests' own (`edges::shadow` is `shadow_with(_, 6)`): the shared
    // exact images hold it already for this scene, computed by the same function.
    let coarse = &scene.expected;
    let fine = edges::shadow_with(s, 12);
    // Each channel's difference in units of that channel's standard error; a channel of
    // zero variance (the umbra's black) must not differ at all.
    let mut ratios = Vec::new();
    let mut tested = 0;
    for i in 0..coarse.mean.len() {
        if let (Some(a), Some(b)) = (coarse.mean[i], fine.mean[i]) {
            for c in 0..3 {
                let (d, var) = ((a[c] - b[c]).abs(), scene.image.var[i][c]);
                ratios.push(if var > 0.0 {
                    d / var.sqrt()
                } else if d == 0.0 {
                    0.0
                } else {
                    f64::INFINITY
                });
            }
            tested += 1;
        }
    }
    let worst = raylemma::check::max_abs(ratios);
    assert!(tested > 900, "only {tested} pixels tested");
    assert!(
        worst <= 0.02,
        "the rule moves a pixel by {worst} standard errors"
    );
}

/// The scenes of edges rendered by `planted` must each fail their block test. Rendered as
/// `render::render_exact_of` renders them (at its seed), each against the expected image the
/// shared exact images hold for it (the same function of the same scene: the expected
/// images do not depend on the renderer, and the shadow's quadrature is not made again for
/// each twin).
fn assert_edges_reject(planted: render::Renderer, what: &str) {
    let images: Vec<Rendered> = render::edge_scenes(1.0)
        .into_iter()
        .map(|mut s| {
            s.scene.settings.seed = render::SEED;
            let shared = exact_images()
                .iter()
                .find(|r| r.name == s.name)
                .unwrap_or_else(|| panic!("{}: not among the exact images", s.name));
            assert_eq!(shared.block, s.block, "{}", s.name);
            Rendered {
                image: planted(&s.scene),
                expected: shared.expected.clone(),
                name: s.name,
                block: s.block,
            }
        })
        .collect();
    let v = judge(&format!("planted: {what}"), &images, test_alpha());
    for name in EDGES {
        assert!(
            v.failed(&format!("{name}: blocks")),
            "{name} missed it:\n{v}"
        );
    }
}

#[test]
fn edges_reject_a_footprint_half_a_pixel_off() {
    assert_edges_reject(
        &planted::shifted_half_a_pixel(&ours),
        "footprint half a pixel off",
    );
}

#[test]
fn edges_reject_a_footprint_twice_as_wide() {
    assert_edges_reject(&planted::twice_as_wide(&ours), "footprint twice as wide");
}

// ---- Independent dimensions (`src/check/render/independence.rs`) ----

fn independence_images() -> &'static [Rendered] {
    static IMAGES: OnceLock<Vec<Rendered>> = OnceLock::new();
    IMAGES.get_or_init(|| independence::render_independence(&ours, &Options::default()))
}

#[test]
fn the_renderer_s_sample_dimensions_are_independent() {
    let v = judge(
        "renderer: its sample dimensions are independent",
        independence_images(),
        test_alpha(),
    );
    println!("{v}");
    v.assert_pass();
}

#[test]
fn independence_rejects_a_dimension_that_reuses_another() {
    // Each twin must fail on the scenes where its dependence shows. (The hero's four
    // lanes make it nearly blind to the first: the red quad has one wavelength per path.)
    let shows: [&[&str]; 2] = [
        &["edges of a red quad in a sky"],
        &["shadows of two lights", "floor under two lights"],
    ];
    let mut missed = Vec::new();
    for ((what, from, to), scenes) in independence::TWINS.into_iter().zip(shows) {
        let twin = independence::reused(from, to);
        let mine: Vec<Rendered> = independence_images()
            .iter()
            .filter(|r| scenes.contains(&r.name.as_str()))
            .cloned()
            .collect();
        let again = independence::rejudge(&twin, &mine, &Options::default());
        // At the level of the whole check, as the power table judges it.
        let level = raylemma::stats::sidak(test_alpha(), independence_images().len() as u32);
        let level = 1.0 - (1.0 - level).powi(mine.len() as i32);
        let v = judge("planted: a reused dimension", &again, level);
        for name in scenes {
            if !(v.failed(&format!("{name}: global")) || v.failed(&format!("{name}: blocks"))) {
                missed.push(format!("{what}: {name} missed it:\n{v}"));
            }
        }
    }
    assert!(missed.is_empty(), "{}", missed.join("\n"));
}

/// Every pixel of the scenes of edges is tested but the occluder's outline and the slivers
/// a polygon's corner barely touches (`edges::SLIVER_HITS`): at least 95 % of each image.
#[test]
fn edge_scenes_test_nearly_every_pixel() {
    for s in render::edge_scenes(1.0) {
        let e = (s.expected)(&s.scene);
        let n = (e.width * e.height) as usize;
        assert!(
            e.tested() >= n * 19 / 20,
            "{}: {} of {n} pixels tested",
            s.name,
            e.tested()
        );
        assert_eq!(s.block, EDGE_BLOCK);
    }
}

/// The twins of the edge and independence checks are rejected in every seed of the power
/// table (`render_test_power` in `figures/values.json`, its second table: 10 seeds, 2 in a
/// `--quick` run such as CI's throwaway one), each with its largest `|z|` at least 1.5
/// times the critical value in the least of them: the fixed seeds of the tests above cannot
/// be the lucky ones.
#[test]
fn planted_mistakes_are_rejected_in_every_seed_of_the_power_table() {
    let figures = crate::support::root().join("figures");
    let values = raylemma_values::read(&figures).unwrap_or_else(|e| panic!("{e}"));
    let power = &values["render_test_power"].values;
    // A ratio shown as "inf" (a pixel of zero variance off its expected value) is infinite.
    let number = |key: &str| match power.get(key) {
        Some(v) if v.shown == "inf" => f64::INFINITY,
        Some(v) => v.number.unwrap_or(f64::NAN),
        None => f64::NAN,
    };
    let mut asserted: Vec<(&str, &str)> = Vec::new();
    for twin in ["footprint half a pixel off", "footprint twice as wide"] {
        asserted.extend(EDGES.iter().map(|&s| (twin, s)));
    }
    let [(first, ..), (second, ..)] = independence::TWINS;
    asserted.push((first, "edges of a red quad in a sky"));
    asserted.push((second, "shadows of two lights"));
    asserted.push((second, "floor under two lights"));
    let seeds = number("twins.seeds");
    // The committed table is a full run's; NaN-safe: a missing count fails here.
    assert!(
        seeds >= 10.0 || (values["render_test_power"].quick && seeds >= 2.0),
        "the power table's twins ran {seeds} seeds"
    );
    for (twin, scene) in asserted {
        let key = format!(
            "twins.{}.{}",
            raylemma_values::slug(twin),
            raylemma_values::slug(scene)
        );
        let (rejected, ratio) = (
            number(&format!("{key}.rejected")),
            number(&format!("{key}.least_ratio")),
        );
        assert!(
            rejected == seeds && ratio >= 1.5,
            "{twin} on {scene}: rejected in {rejected} of {seeds} seeds, least |z| / critical {ratio}"
        );
    }
}
