//! Checks of a renderer: its images against answers known independently of it. Chapter:
//! *Testing the renderer* (`chapters/renderer/testing.md`).
//!
//! A renderer is any function from a [`Scene`] to an [`Image`] (the means and variances of
//! the pixels); raylemma's own is [`ours`]. Each checker renders the scenes of
//! [`scenes`] and compares the images by the pooled z-tests of [`pool`]:
//!
//! * [`exact()`]: scenes whose expected image is known exactly ([`mod@exact`]): a
//!   Lambertian floor under a quad light, a sphere light and both, and a glass sphere, a
//!   mirror sphere and a thin film in a sky;
//! * [`agreement`]: one scene with every material, two lights and a sky, rendered with
//!   light sampling only, BSDF sampling only and both heuristics of multiple importance
//!   sampling, and with every wavelength strategy: all must have the same expected image;
//! * [`references::render_references`]: a window of every canonical scene against the
//!   committed reference image.
//!
//! Every claim is a statistical test at `options.level` shared by Šidák between the
//! claims of one check, with a fixed seed; the planted twins of [`planted`] are biases of
//! known size that each check must reject.

pub mod edges;
pub mod exact;
pub mod independence;
pub mod pictures;
pub mod planted;
pub mod pool;
pub mod references;
pub mod scenes;

use super::{Finding, Options, Verdict};
use crate::image::Image;
use crate::render::scene::{DirectLight, Scene, Wavelength};
use crate::render::{Progress, render};
use crate::spectral::emission::{EmissionSampler, colour_proposal};
use crate::spectral::spectrum::Spectrum;
use crate::spectral::wavelength::WavelengthStrategy;
use crate::stats::sidak;
use crate::transport::shadow::Heuristic;
use pool::{Expected, Pooled};

/// A renderer under test: the image of a scene at its settings (samples, seed, strategies).
pub type Renderer<'a> = &'a (dyn Fn(&Scene) -> Image + Sync);

/// raylemma's own renderer ([`crate::render::render`]), silently.
pub fn ours(scene: &Scene) -> Image {
    render(scene, scene.settings.spp, Progress::Silent)
}

/// The two findings of one pooled comparison, named `what: global` and `what: blocks`.
fn findings(what: &str, p: &Pooled) -> [Finding; 2] {
    let mut global = Finding::new(
        format!("{what}: global"),
        format!(
            "the mean over the {} tested pixels matches the expected image: |z| <= {:.2} \
             (a global bias of {:.2} % is detected nine times in ten)",
            p.pixels,
            p.critical,
            100.0 * p.detectable_bias()
        ),
    )
    .in_unit("|z|, the standardised difference");
    global.measure(p.global_z, p.critical, || {
        format!(
            "|z| = {:.2}: the image is {:+.3} % off in luminance",
            p.global_z,
            100.0 * p.relative_difference
        )
    });
    let mut blocks = Finding::new(
        format!("{what}: blocks"),
        format!(
            "every one of the {} blocks of {b}x{b} pixels matches: |z| <= {:.2}",
            p.blocks,
            p.critical,
            b = p.block
        ),
    )
    .in_unit("|z|, the standardised difference");
    blocks.measure(p.block_z, p.critical, || {
        format!(
            "the block at pixel ({}, {}) has |z| = {:.2}",
            p.worst_block.0, p.worst_block.1, p.block_z
        )
    });
    [global, blocks]
}

/// One exact scene: its name, the scene (side in pixels, samples per pixel) and how its
/// expected image is computed.
pub struct ExactScene {
    /// For reports.
    pub name: String,
    /// The scene.
    pub scene: Scene,
    /// Its expected image.
    pub expected: fn(&Scene) -> Expected,
    /// The side of its pooled blocks: [`pool::BLOCK`], or [`EDGE_BLOCK`] for the scenes of
    /// edges.
    pub block: u32,
}

/// The side of the pooled blocks of the scenes of edges ([`mod@edges`]): small, so that a
/// block holds a short stretch of one edge, where a footprint's mistake biases every pixel
/// the same way (a block that held both sides of a shape would see the two cancel).
pub const EDGE_BLOCK: u32 = 4;

/// The wavelength strategies of the fluorescent floor: every unbiased strategy of the
/// wavelength chapter, and the emission strategy (the light's colour proposal).
pub fn wavelength_variants() -> Vec<(&'static str, Wavelength)> {
    let mut v: Vec<(&str, Wavelength)> = [
        ("hero, visible pdf", WavelengthStrategy::HeroVisible),
        ("hero, uniform", WavelengthStrategy::HeroUniform),
        ("hero, balance heuristic", WavelengthStrategy::HeroBalance),
        ("one wavelength, visible pdf", WavelengthStrategy::Visible),
        ("one wavelength, uniform", WavelengthStrategy::Uniform),
    ]
    .into_iter()
    .map(|(n, s)| (n, Wavelength::Strategy(s)))
    .collect();
    let proposal = colour_proposal(match &scenes::fluorescent() {
        Spectrum::Table(t) => t,
        _ => unreachable!("the fluorescent spectrum is a table"),
    });
    if let Ok(sampler) = EmissionSampler::new(&proposal) {
        v.push(("emission (colour proposal)", Wavelength::Emission(sampler)));
    }
    v
}

/// The direct-lighting strategies: multiple importance sampling with either heuristic,
/// light sampling only, BSDF sampling only.
pub const DIRECT_VARIANTS: [(&str, DirectLight); 4] = [
    ("MIS, power heuristic", DirectLight::Mis(Heuristic::Power)),
    (
        "MIS, balance heuristic",
        DirectLight::Mis(Heuristic::Balance),
    ),
    ("light sampling only", DirectLight::Light),
    ("BSDF sampling only", DirectLight::Bsdf),
];

/// The exact scenes at the tests' sizes, each at its own samples per pixel (chosen so
/// that a global bias of about half a percent is detected where the noise allows it)
/// times `scale` ([`scaled_spp`]); [`render_exact_of`] sets their seed:
///
/// * the floor under the quad light, under the sphere light, under the sphere light and
///   a quad light that emits away from it, and under both lights with every
///   direct-lighting strategy ([`DIRECT_VARIANTS`]);
/// * the floor under the fluorescent light with every wavelength strategy
///   ([`wavelength_variants`]);
/// * the glass sphere, the mirror sphere and the thin film in the sky;
/// * the scenes of edges ([`edge_scenes`]), and some of them with other strategies
///   ([`edge_strategy_scenes`]).
pub fn exact_scenes(scale: f64) -> Vec<ExactScene> {
    let spp = |own| scaled_spp(own, scale);
    let mut list = vec![
        ExactScene {
            name: "floor under a quad light".into(),
            scene: scenes::floor_under_quad(32, spp(512)),
            expected: exact::direct,
            block: pool::BLOCK,
        },
        ExactScene {
            name: "floor under a sphere light".into(),
            scene: scenes::floor_under_sphere(32, spp(1536)),
            expected: exact::direct,
            block: pool::BLOCK,
        },
        ExactScene {
            name: "floor under a light turned away".into(),
            scene: scenes::floor_under_a_light_turned_away(32, spp(256)),
            expected: exact::direct,
            block: pool::BLOCK,
        },
    ];
    for (name, direct) in DIRECT_VARIANTS {
        let mut scene = scenes::floor_under_two_lights(32, spp(512));
        scene.settings.direct = direct;
        list.push(ExactScene {
            name: format!("floor under two lights, {name}"),
            scene,
            expected: exact::direct,
            block: pool::BLOCK,
        });
    }
    for (name, wavelengths) in wavelength_variants() {
        list.push(ExactScene {
            name: format!("floor under a fluorescent light, {name}"),
            scene: scenes::floor_under_fluorescent(32, spp(64), wavelengths),
            expected: exact::direct,
            block: pool::BLOCK,
        });
    }
    list.extend([
        ExactScene {
            name: "glass sphere in a sky".into(),
            scene: scenes::glass_in_sky(40, spp(256)),
            expected: exact::specular,
            block: pool::BLOCK,
        },
        ExactScene {
            name: "mirror sphere in a sky".into(),
            scene: scenes::mirror_in_sky(32, spp(64)),
            expected: exact::specular,
            block: pool::BLOCK,
        },
        ExactScene {
            name: "thin film in a sky".into(),
            scene: scenes::film_in_sky(16, spp(512)),
            expected: exact::specular,
            block: pool::BLOCK,
        },
    ]);
    list.extend(edge_scenes(scale));
    list.extend(edge_strategy_scenes(scale));
    list
}

/// A scene's own samples per pixel `own` times `scale` (the checks' `options.cases`
/// percentage), rounded, and at least 2 (a variance needs two samples).
pub fn scaled_spp(own: u32, scale: f64) -> u32 {
    ((f64::from(own) * scale).round() as u32).max(2)
}

/// The scenes of edges ([`mod@edges`]) at the tests' sizes, each at its own samples per
/// pixel times `scale`: two lights seen directly, a red quad in a sky, the shadows of two
/// lights.
pub fn edge_scenes(scale: f64) -> Vec<ExactScene> {
    let spp = |own| scaled_spp(own, scale);
    vec![
        ExactScene {
            name: "edges of two lights seen directly".into(),
            scene: scenes::lights_seen_directly(32, spp(256)),
            expected: edges::flat,
            block: EDGE_BLOCK,
        },
        ExactScene {
            name: "edges of a red quad in a sky".into(),
            scene: scenes::coloured_quad_in_sky(32, spp(2048)),
            expected: edges::flat,
            block: EDGE_BLOCK,
        },
        ExactScene {
            name: "shadows of two lights".into(),
            scene: scenes::shadows_of_two_lights(32, spp(256)),
            expected: edges::shadow,
            block: EDGE_BLOCK,
        },
    ]
}

/// The scenes of edges with other strategies, in the exact set only: the shadows of two
/// lights by light sampling alone and by MIS with the balance heuristic (the choice between
/// two lights and the strategies' weights, at every shadow's edge; the scene's own is MIS
/// with the power heuristic; BSDF sampling alone would meet lights this small in too few
/// samples to test), and the
/// red quad with the hero's four wavelengths (the scene's own is one wavelength), each at
/// its own samples per pixel times `scale`.
pub fn edge_strategy_scenes(scale: f64) -> Vec<ExactScene> {
    let spp = |own| scaled_spp(own, scale);
    let mut list = Vec::new();
    for (name, direct, own) in [
        ("light sampling only", DirectLight::Light, 256),
        (
            "MIS, balance heuristic",
            DirectLight::Mis(Heuristic::Balance),
            256,
        ),
    ] {
        let mut scene = scenes::shadows_of_two_lights(32, spp(own));
        scene.settings.direct = direct;
        list.push(ExactScene {
            name: format!("shadows of two lights, {name}"),
            scene,
            expected: edges::shadow,
            block: EDGE_BLOCK,
        });
    }
    let mut scene = scenes::coloured_quad_in_sky(32, spp(512));
    scene.settings.wavelengths = Wavelength::Strategy(WavelengthStrategy::HeroVisible);
    list.push(ExactScene {
        name: "edges of a red quad in a sky, hero".into(),
        scene,
        expected: edges::flat,
        block: EDGE_BLOCK,
    });
    list
}

/// The default seed of the renderer checks.
pub const SEED: u64 = 0x5ce9e;

/// One rendered comparison: what was rendered, the image, and what it is compared with.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// For reports.
    pub name: String,
    /// The image under test.
    pub image: Image,
    /// What it must match.
    pub expected: Expected,
    /// The side of the pooled blocks ([`pool::BLOCK`], or larger for scenes with rare
    /// bright paths).
    pub block: u32,
}

/// The two findings of each of `rendered`, the claims sharing the level `level` by Šidák.
pub fn judge(subject: &str, rendered: &[Rendered], level: f64) -> Verdict {
    let level = sidak(level, rendered.len().max(1) as u32);
    let mut verdict = Verdict::new(subject);
    for r in rendered {
        let p = pool::pool_blocks(&r.image, &r.expected, level, r.block);
        verdict.findings.extend(findings(&r.name, &p));
    }
    verdict
}

/// The exact scenes ([`exact_scenes`], `options.cases` percent of their samples, default
/// 100) rendered by `renderer`, each with its expected image.
pub fn render_exact(renderer: Renderer, options: &Options) -> Vec<Rendered> {
    let list = exact_scenes(options.cases_or(100) as f64 / 100.0);
    render_exact_of(renderer, list, options)
}

/// The exact scenes `list` rendered by `renderer` at seed `options.seed` (default
/// [`SEED`]), each with its expected image, in the list's order. The scenes are taken one
/// per task: an expected image is made on one thread, and the next scene's render keeps
/// the other cores busy meanwhile (every image is the same in any order).
pub fn render_exact_of(
    renderer: Renderer,
    list: Vec<ExactScene>,
    options: &Options,
) -> Vec<Rendered> {
    use rayon::prelude::*;
    let seed = options.seed_or(SEED);
    list.into_par_iter()
        .map(|mut s| {
            s.scene.settings.seed = seed;
            s
        })
        .map(|s| Rendered {
            image: renderer(&s.scene),
            expected: (s.expected)(&s.scene),
            name: s.name,
            block: s.block,
        })
        .collect()
}

/// Renders every exact scene ([`exact_scenes`]) with `renderer` and compares each image
/// with its expected image, globally and in blocks.
pub fn exact(renderer: Renderer, options: &Options) -> Verdict {
    judge(
        "renderer against exact images",
        &render_exact(renderer, options),
        options.level(),
    )
}

/// The variants of [`agreement`]: every direct-lighting strategy but the first, and every
/// unbiased wavelength strategy but hero-visible.
pub fn variants() -> Vec<(String, DirectLight, Wavelength)> {
    let hero = Wavelength::Strategy(WavelengthStrategy::HeroVisible);
    let power = DirectLight::Mis(Heuristic::Power);
    let mut v: Vec<(String, DirectLight, Wavelength)> = DIRECT_VARIANTS[1..]
        .iter()
        .map(|&(name, d)| (name.to_string(), d, hero.clone()))
        .collect();
    for (name, s) in [
        ("one uniform wavelength", WavelengthStrategy::Uniform),
        ("one visible wavelength", WavelengthStrategy::Visible),
        ("hero, uniform", WavelengthStrategy::HeroUniform),
        ("hero, balance heuristic", WavelengthStrategy::HeroBalance),
    ] {
        v.push((name.to_string(), power, Wavelength::Strategy(s)));
    }
    v
}

/// The scene of everything ([`scenes::everything`], 32 x 32 pixels, `options.cases`
/// samples per pixel, default 64) rendered by `renderer` with MIS (power heuristic) and
/// hero-visible wavelengths, and with each of [`variants`] (each with its own seed), each
/// variant compared with the first render.
pub fn render_agreement(renderer: Renderer, options: &Options) -> Vec<Rendered> {
    let spp = options.cases_or(64) as u32;
    let seed = options.seed_or(SEED);
    let mut base = scenes::everything(32, spp);
    base.settings.seed = seed;
    let reference = renderer(&base);
    let expected = Expected::render(&reference, |_, _| true);
    variants()
        .into_iter()
        .enumerate()
        .map(|(k, (name, direct, wavelengths))| {
            let mut s = base.clone();
            s.settings.direct = direct;
            s.settings.wavelengths = wavelengths;
            s.settings.seed = seed + 1 + k as u64;
            Rendered {
                name,
                image: renderer(&s),
                expected: expected.clone(),
                block: pool::BLOCK,
            }
        })
        .collect()
}

/// The maximum depths at which [`render_depths`] compares the estimators: direct light
/// only, one indirect bounce, two.
pub const DEPTHS: [u32; 3] = [1, 2, 3];

/// The scene of everything ([`scenes::everything`], 32 x 32 pixels, `options.cases`
/// samples per pixel, default 64) at each maximum depth of [`DEPTHS`], rendered by
/// `renderer` with MIS (power heuristic) and with each other direct-lighting strategy of
/// [`DIRECT_VARIANTS`] (each with its own seed), each compared with the MIS render of its
/// depth: a path of at most `max_depth` bounces has one expectation whichever strategy
/// found its light, so a strategy that counts a light the others cannot reach at that depth
/// (next-event estimation at the last vertex) differs.
pub fn render_depths(renderer: Renderer, options: &Options) -> Vec<Rendered> {
    let spp = options.cases_or(64) as u32;
    let seed = options.seed_or(SEED) + 100;
    let mut out = Vec::new();
    for (d, &depth) in DEPTHS.iter().enumerate() {
        let mut base = scenes::everything(32, spp);
        base.settings.max_depth = depth;
        base.settings.seed = seed + 10 * d as u64;
        let expected = Expected::render(&renderer(&base), |_, _| true);
        for (k, &(name, direct)) in DIRECT_VARIANTS[1..].iter().enumerate() {
            let mut s = base.clone();
            s.settings.direct = direct;
            s.settings.seed = base.settings.seed + 1 + k as u64;
            out.push(Rendered {
                name: format!("{name}, max_depth {depth}"),
                image: renderer(&s),
                expected: expected.clone(),
                block: pool::BLOCK,
            });
        }
    }
    out
}

/// Every estimator agrees at every maximum depth: [`render_depths`], judged.
pub fn depths(renderer: Renderer, options: &Options) -> Verdict {
    judge(
        "renderer: every estimator agrees at every maximum depth",
        &render_depths(renderer, options),
        options.level(),
    )
}

/// Every estimator of one scene agrees: [`render_agreement`], judged.
pub fn agreement(renderer: Renderer, options: &Options) -> Verdict {
    judge(
        "renderer: every estimator of one scene agrees",
        &render_agreement(renderer, options),
        options.level(),
    )
}
