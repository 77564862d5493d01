//! Independent sample dimensions: the renderer's images against renders whose every sample
//! dimension has a stream of its own. Chapter: *Testing the renderer*
//! (`chapters/renderer/testing.md`, *Independent dimensions*).
//!
//! A pixel's estimate is an integral over the point in the pixel, the wavelengths, and at
//! each vertex the light's choice, the point on the light, the next direction and
//! roulette's number. The renderer reads a sample's numbers in order from its pixel's one
//! stream ([`crate::render::pixel_rng`]): the `k`-th number of a sample is its dimension
//! `k` (0 and 1 the jitter, 2 the wavelengths; at a diffuse vertex the light's choice, two
//! for the point on it, two for the direction; at a dielectric or a thin film one, from the
//! third vertex on roulette's one). The estimate is unbiased only if the dimensions of one
//! sample are independent: a sampler that hands one number to two dimensions of a sample
//! (a dimension counter that does not advance) biases edges, colour fringes and the
//! choice between lights while smooth regions stay within noise. (Numbers shared across
//! samples or pixels bias nothing: they keep the error from shrinking and make the
//! variance estimates wrong.)
//!
//! [`Dimensions`] is a source built to be independent: dimension `k` of pixel `i` is drawn
//! from a PCG-64 generator of its own, seeded from `(seed, i, k)` by a mixing function,
//! one number per sample. A render from it is the renderer's code with numbers that are
//! independent by construction, so the renderer's own assignment must agree with it
//! ([`independence`]), on scenes where a dependence shows: the scenes of edges and the floor
//! under two lights. [`Dimensions::reusing`] is the planted twin: a source that gives one
//! dimension the number of another.

use rand::TryRng;
use rand::rand_core::Infallible;
use rand::rand_core::utils::fill_bytes_via_next_word;

use super::pool::{self, Expected};
use super::{
    ExactScene, Options, Rendered, Renderer, SEED, Verdict, edge_scenes, judge, scaled_spp, scenes,
};
use crate::image::Image;
use crate::render::pixel::PixelNumbers;
use crate::render::render_from;
use crate::render::scene::Scene;
use crate::rng::Rng;

/// SplitMix64's finaliser: a bijection of `u64` whose output bits each depend on every
/// input bit (Steele, Lea and Flood 2014, with Stafford's "Mix13" shifts and multipliers,
/// as in Java's `SplittableRandom.mix64`).
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// A pixel's numbers with one stream per sample dimension: dimension `k` of pixel `pixel`
/// for `seed` is drawn from its own PCG-64, whose state and stream are hashes of all
/// three (by SplitMix64's finaliser), so that no two dimensions or pixels share a generator
/// or start from related states. Built by [`Dimensions::reusing`], it is the planted twin
/// instead: one dimension gets the number of another.
#[derive(Clone, Debug)]
pub struct Dimensions {
    seed: u64,
    pixel: u64,
    streams: Vec<Rng>,
    next: usize,
    /// The planted twin's `(from, to)`, and the number `from` drew in this sample.
    reuse: Option<(usize, usize)>,
    kept: u64,
}

impl Dimensions {
    /// The source of pixel `pixel` (its index in the whole image) for `seed`.
    pub fn new(seed: u64, pixel: u64) -> Self {
        Dimensions {
            seed,
            pixel,
            streams: Vec::new(),
            next: 0,
            reuse: None,
            kept: 0,
        }
    }

    /// The planted twin: [`Dimensions::new`] except that dimension `to` gets the number of
    /// dimension `from` (`from < to`) of the same sample, the mistake of a sampler whose
    /// dimension counter does not advance between two uses.
    pub fn reusing(seed: u64, pixel: u64, from: usize, to: usize) -> Self {
        assert!(
            from < to,
            "Dimensions::reusing: dimension {to} can reuse only an earlier one"
        );
        Dimensions {
            reuse: Some((from, to)),
            ..Dimensions::new(seed, pixel)
        }
    }

    /// The generator of dimension `k`.
    fn stream(seed: u64, pixel: u64, k: usize) -> Rng {
        let a = mix(seed ^ mix(pixel ^ mix(k as u64)));
        let b = mix(a ^ 0x9e37_79b9_7f4a_7c15);
        let c = mix(b ^ pixel.rotate_left(17));
        Rng::new(u128::from(a) << 64 | u128::from(b), u128::from(c))
    }

    /// The next number of the sample: its dimension `self.next` (or, for the twin's `to`,
    /// the number its `from` drew).
    fn draw(&mut self) -> u64 {
        let k = self.next;
        while self.streams.len() <= k {
            let n = self.streams.len();
            self.streams.push(Self::stream(self.seed, self.pixel, n));
        }
        self.next += 1;
        let v = rand::Rng::next_u64(&mut self.streams[k]);
        match self.reuse {
            Some((from, _)) if k == from => {
                self.kept = v;
                v
            }
            Some((_, to)) if k == to => self.kept,
            _ => v,
        }
    }
}

impl TryRng for Dimensions {
    type Error = Infallible;

    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        Ok((self.draw() >> 32) as u32)
    }

    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        Ok(self.draw())
    }

    fn try_fill_bytes(&mut self, dst: &mut [u8]) -> Result<(), Infallible> {
        fill_bytes_via_next_word(dst, || Ok(self.draw()))
    }
}

impl PixelNumbers for Dimensions {
    fn start_sample(&mut self) {
        self.next = 0;
    }
}

/// The renderer's code with independent dimensions ([`Dimensions`]).
pub fn independent(scene: &Scene) -> Image {
    render_from(scene, scene.settings.spp, &Dimensions::new)
}

/// The renderer's code with dimension `to` reusing dimension `from`
/// ([`Dimensions::reusing`]).
pub fn reused(from: usize, to: usize) -> impl Fn(&Scene) -> Image + Sync {
    move |scene| {
        render_from(scene, scene.settings.spp, &|seed, pixel| {
            Dimensions::reusing(seed, pixel, from, to)
        })
    }
}

/// The sample dimensions of the planted twins: the wavelengths' number (2) reusing the
/// jitter's first (0); the point on the light's first coordinate (4) reusing the light's
/// choice (3) at the first diffuse vertex.
pub const TWINS: [(&str, usize, usize); 2] = [
    ("the wavelengths reuse the jitter's x", 0, 2),
    ("the point on the light reuses the light's choice", 3, 4),
];

/// The scenes of the independence check at `scale` times their samples: the scenes of
/// edges ([`edge_scenes`]) and the floor under two lights.
pub fn independence_scenes(scale: f64) -> Vec<ExactScene> {
    let mut list = edge_scenes(scale);
    list.push(ExactScene {
        name: "floor under two lights".into(),
        scene: scenes::floor_under_two_lights(32, scaled_spp(512, scale)),
        expected: super::exact::direct,
        block: pool::BLOCK,
    });
    list
}

/// The seeds of the reference (independent dimensions) and of the candidate for
/// `options.seed` (default [`SEED`]) `s`: `2 (s + 200)` and `2 (s + 200) + 1`, so that
/// no two values of `s` share a seed (with `s` and `s + 1` the candidate of one would be
/// the reference of the next, and their verdicts would not be independent trials).
fn seeds(options: &Options) -> (u64, u64) {
    let s = 2 * (options.seed_or(SEED) + 200);
    (s, s + 1)
}

/// Each scene of [`independence_scenes`] (`options.cases` percent of its samples, default
/// 100) rendered with independent dimensions ([`independent`]) and by `renderer`, with
/// the two seeds of `seeds`, the second compared with the first.
pub fn render_independence(renderer: Renderer, options: &Options) -> Vec<Rendered> {
    let (reference_seed, seed) = seeds(options);
    independence_scenes(options.cases_or(100) as f64 / 100.0)
        .into_iter()
        .map(|mut s| {
            s.scene.settings.seed = reference_seed;
            let reference = independent(&s.scene);
            s.scene.settings.seed = seed;
            Rendered {
                name: s.name,
                image: renderer(&s.scene),
                expected: Expected::render(&reference, |_, _| true),
                block: s.block,
            }
        })
        .collect()
}

/// The comparisons `rendered` (of [`render_independence`], at the same `options`) again,
/// with `renderer` as the candidate: each scene rendered by it at the candidate's seed and
/// compared with the same render from independent dimensions. A planted twin needs only
/// its own renders this way.
///
/// # Panics
/// If a name of `rendered` is not one of [`independence_scenes`].
pub fn rejudge(renderer: Renderer, rendered: &[Rendered], options: &Options) -> Vec<Rendered> {
    let (_, seed) = seeds(options);
    let scenes = independence_scenes(options.cases_or(100) as f64 / 100.0);
    rendered
        .iter()
        .map(|r| {
            let s = scenes
                .iter()
                .find(|s| s.name == r.name)
                .unwrap_or_else(|| panic!("rejudge: no scene {:?}", r.name));
            let mut scene = s.scene.clone();
            scene.settings.seed = seed;
            Rendered {
                image: renderer(&scene),
                ..r.clone()
            }
        })
        .collect()
}

/// The renderer's own assignment of numbers to dimensions agrees with independent
/// dimensions: [`render_independence`], judged.
pub fn independence(renderer: Renderer, options: &Options) -> Verdict {
    judge(
        "renderer: its sample dimensions are independent",
        &render_independence(renderer, options),
        options.level(),
    )
}
