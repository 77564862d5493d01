//! Do two renders of the same scene agree within their noise? Chapter: *Comparing
//! images* (`chapters/renderer/compare.md`).
//!
//! Each side of a comparison is an [`Estimate`]: per-pixel means, the estimated variance
//! of each mean, and the degrees of freedom `ν` of that estimate: `n - 1` for a render's
//! own variance channels from `n` samples per pixel ([`Estimate::from_variance`]), `K - 1`
//! for the spread of `K` independent plain images ([`Estimate::from_spread`]), infinite
//! when the variance is taken as exact.
//!
//! Under the hypothesis that both estimate the same expected image, in every pixel and
//! channel the difference `d = a - b` has the estimated variance `v = v_a + v_b`, and
//! `t = d / sqrt(v)` is compared with Student's t: with the smaller of the two sides'
//! degrees of freedom for a pixel (conservative, [`pixel_dof`]), and for the mean of a
//! block of pixels or of the whole image, `d̄ = Σ d_i / n` with `v̄ = Σ v_i / n²` (the
//! pixels are independent), with the Welch–Satterthwaite degrees of freedom of that sum,
//! guarded against a pixel whose variance came out small ([`region_dof`]). Three families
//! of two-sided tests (every pixel and channel, the means of square blocks, the whole
//! image's mean per channel) are held together by Šidák's correction at the chance `alpha`
//! of a false alarm for two correct renders.
//!
//! Normal critical values with a variance from few samples are wrong by orders of
//! magnitude: with `ν = 15` the tail beyond the normal critical value of a million tests
//! is a thousand times the normal one. Each test's p-value is therefore computed from its
//! own `ν`, and reported as the normal `z` with the same p-value, so that `|z|` and the
//! mean of `z²` mean the same whatever the degrees of freedom.

use crate::stats::two_sided_critical;
use glam::{DMat3, DVec3};
use statrs::distribution::{ContinuousCDF, StudentsT};
use statrs::function::erf::erfc;

use crate::image::{Image, ImageError};
use crate::rng::{Rng, standard_normal};
use crate::spectral::display;
use crate::stats::welford::Welford;
use crate::stats::{chi2, sidak, ttest};

/// The side of the blocks whose means are compared, pixels.
pub const BLOCK: u32 = 16;

/// Above this many degrees of freedom a t statistic is taken as normal (the two tails
/// differ by less than `t⁴ / (4ν)`, relatively: 0.1 % at `t = 6`).
pub const NORMAL_DOF: f64 = 1e6;

/// One side of a comparison: means, the estimated variance of each mean, and the degrees
/// of freedom of those estimates.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// The means and their variances (`image.var`).
    pub image: Image,
    /// The degrees of freedom of every variance estimate (`f64::INFINITY`: exact, or from
    /// so many samples that it may be taken as exact).
    pub dof: f64,
    /// Where the variance comes from, in words, for the report.
    pub source: String,
    /// Whether its variances were floored by a reference's ([`Estimate::floor_from_reference`]):
    /// then a region's test needs no guard against an underestimated pixel ([`region_dof`]).
    pub floored: bool,
}

impl Estimate {
    /// An image with its own variance channels, the variances of means of `n` samples:
    /// `n - 1` degrees of freedom when `image.spp` is known, otherwise taken as exact
    /// (many degrees of freedom), which the report says.
    pub fn from_variance(image: Image) -> Estimate {
        let (dof, source) = match image.spp {
            Some(n) if n >= 2 => (
                f64::from(n - 1),
                format!(
                    "its variance channels, from {n} samples per pixel ({} degrees of freedom)",
                    n - 1
                ),
            ),
            _ => (
                f64::INFINITY,
                "its variance channels; samples per pixel unknown (no spp attribute), so the variances are taken as exact (many degrees of freedom)".to_string(),
            ),
        };
        Estimate {
            image,
            dof,
            source,
            floored: false,
        }
    }

    // ANCHOR: spread
    /// The estimate from `K >= 2` independent plain images of one scene (renders with
    /// different seeds), `width` by `height`: per pixel and channel, the mean of the `K`
    /// values and the variance of that mean, `s² / K` with `s²` their sample variance,
    /// with `K - 1` degrees of freedom.
    ///
    /// # Errors
    /// [`ImageError::Mismatch`]: fewer than two images, or an image of another size than
    /// `width` by `height` (its index in `means`).
    pub fn from_spread(
        width: u32,
        height: u32,
        means: &[&[DVec3]],
    ) -> Result<Estimate, ImageError> {
        let k = means.len();
        if k < 2 {
            return Err(ImageError::Mismatch(format!(
                "{k} image: the spread of independent images needs at least 2"
            )));
        }
        let n = width as usize * height as usize;
        if let Some(i) = means.iter().position(|m| m.len() != n) {
            return Err(ImageError::Mismatch(format!(
                "image {} has {} pixels, not {width}x{height}",
                i + 1,
                means[i].len()
            )));
        }
        let mut acc = vec![Welford::<DVec3>::default(); n];
        for image in means {
            for (a, &x) in acc.iter_mut().zip(image.iter()) {
                a.push(x);
            }
        }
        Ok(Estimate {
            image: Image {
                width,
                height,
                mean: acc.iter().map(Welford::mean).collect(),
                var: acc.iter().map(Welford::var_of_mean).collect(),
                spp: None,
            },
            dof: (k - 1) as f64,
            source: format!("the spread of {k} images ({} degrees of freedom)", k - 1),
            floored: false,
        })
    }
    // ANCHOR_END: spread

    // ANCHOR: floor
    /// Raises every variance of this estimate (a candidate's) to at least the variance a
    /// mean of `samples` samples would have if each sample were as spread as the
    /// reference's: `σ̂²_R / N`, with `σ̂²_R = n_R v_R` the reference's per-sample variance
    /// (its variance of the mean `v_R` times its `n_R` samples per pixel) and `N` the
    /// candidate's samples per pixel in all (`K x n` for `K` images of `n`). Returns
    /// whether it could: not when the reference's samples per pixel are unknown.
    ///
    /// Why: a candidate's own estimate of its variance misses what its samples missed. On a
    /// sliver of lit floor at a sphere's edge that one sample in fifty reaches, four
    /// renders of 64 samples all read exactly 0 with probability `0.98^256`, about 0.6 %:
    /// their spread is 0, and a t-test with no spread is no test (any difference at all is infinitely many standard errors).
    /// Under the hypothesis that both renders estimate the same image with samples equally
    /// spread, `σ̂²_R / N` is the candidate's variance, estimated from the reference's
    /// thousands of samples; a candidate noisier than the reference keeps its own larger
    /// spread. Raising a variance only shrinks `|t|`, and a pixel's degrees of freedom can
    /// only fall (to the candidate's, `K - 1` or `n - 1`), so every pixel test stays at least
    /// as conservative as before; a region's degrees of freedom are computed again from the
    /// floored variances, without the guard against a pixel whose variance came out small
    /// ([`region_dof`]), and can rise where the floor evens out its pixels' shares.
    pub fn floor_from_reference(&mut self, reference: &Estimate, samples: u64) -> bool {
        let Some(n_ref) = reference.image.spp.filter(|&n| n >= 2) else {
            return false;
        };
        let scale = f64::from(n_ref) / samples.max(1) as f64;
        for (v, v_ref) in self.image.var.iter_mut().zip(&reference.image.var) {
            *v = v.max(*v_ref * scale);
        }
        self.source += &format!(
            "; raised where smaller to the reference's per-sample variance over {samples} samples per pixel"
        );
        self.floored = true;
        true
    }
    // ANCHOR_END: floor
}

/// The variance of the rounding of `v` to a half float: `ulp²/12`, that of an error spread
/// evenly over one unit in the last place (`ulp = 2^(e - 10)` for `2^e <= |v| < 2^(e+1)`,
/// `2^-24` among the subnormals below `2^-14`).
pub(crate) fn half_rounding_variance(v: f64) -> f64 {
    let v = v.abs();
    let ulp = if v < 2f64.powi(-14) {
        2f64.powi(-24)
    } else {
        let e = ((v.to_bits() >> 52) & 0x7ff) as i32 - 1023;
        2f64.powi(e - 10)
    };
    ulp * ulp / 12.0
}

/// Adds the rounding of half-float means to an estimate's variances: every value of a
/// half-float file is off by up to half an ulp, and the images of a candidate round alike
/// wherever their values are close, so that their spread can be zero where their noise is
/// not (a few half-float renders of a smooth region often agree to the last bit). The
/// rounding of the mean of `K` such images is not divided by `K` (the roundings of equal
/// values are the same): `ulp²/12` is added to each mean's variance, whatever `K`.
///
/// The rounding happens in the file's own channels. For a file of X, Y, Z converted to
/// linear sRGB by `to_rgb` (`M`), each of its values `X = M⁻¹ m` is rounded with its own
/// ulp, and the three independent roundings reach R, G, B through `M`'s squared entries,
/// `Σ_k M_ck² ulp(X_k)²/12`: far more than `ulp(m_c)²/12` where a saturated colour makes a
/// channel of `m` small while X, Y and Z are not.
pub fn add_half_rounding(estimate: &mut Estimate, to_rgb: Option<DMat3>) {
    // The matrix's squared entries and its inverse, once.
    let through = to_rgb.map(|m| {
        let squared = DMat3::from_cols(
            m.x_axis * m.x_axis,
            m.y_axis * m.y_axis,
            m.z_axis * m.z_axis,
        );
        (squared, m.inverse())
    });
    let image = &mut estimate.image;
    for (m, v) in image.mean.iter().zip(image.var.iter_mut()) {
        *v += match through {
            None => m.map(half_rounding_variance),
            Some((squared, to_file)) => squared * (to_file * *m).map(half_rounding_variance),
        };
    }
    estimate.source += "; plus the half floats' rounding, ulp²/12 a value";
}

/// One region (a block, or the whole image) of the comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Region {
    /// The region's top-left pixel.
    pub x: u32,
    /// The region's top-left pixel.
    pub y: u32,
    /// The region mean's z (the normal z with the same p-value as its t) of the channel
    /// with the largest `|z|`: positive where the second image (the candidate) is brighter.
    pub z: f64,
    /// Which channel (0 R, 1 G, 2 B).
    pub channel: usize,
    /// The z of every channel.
    pub zs: DVec3,
    /// The degrees of freedom of that channel's test ([`region_dof`]).
    pub dof: f64,
    /// That channel's difference relative to the first image's mean over the region, and
    /// the half-width of its 95 % interval.
    pub relative: (f64, f64),
    /// The RMS difference over the region's pixels and channels.
    pub rmse: f64,
}

/// The verdict of [`compare`].
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// The images' width and height in pixels.
    pub size: (u32, u32),
    /// The family-wise false-alarm rate.
    pub alpha: f64,
    /// Number of pixel-channel tests.
    pub pixel_tests: usize,
    /// Number of block-channel tests.
    pub block_tests: usize,
    /// The level of each test (Šidák over all of them, the three image tests included).
    pub level: f64,
    /// The critical `|z|` of each test: a test fails when its p-value is below `level`,
    /// which is when its normal-equivalent `|z|` exceeds this.
    pub z_critical: f64,
    /// Where each side's variance comes from.
    pub sources: [String; 2],
    /// The smallest and the median degrees of freedom of the pixel tests.
    pub pixel_dof: (f64, f64),
    /// Pixel-channels beyond the critical value: `(x, y, channel, z)`, worst first (at most 20).
    pub pixel_failures: Vec<(u32, u32, usize, f64)>,
    /// How many pixel-channels are beyond it in all.
    pub pixel_failure_count: usize,
    /// The normal-equivalent z of every pixel and channel, row-major.
    pub z: Vec<DVec3>,
    /// The blocks, worst `|z|` first.
    pub regions: Vec<Region>,
    /// How many blocks are beyond the critical value.
    pub block_failure_count: usize,
    /// The whole image's mean, per channel: its z (positive: the second image, the
    /// candidate, is brighter), degrees of freedom, and relative difference with the
    /// half-width of its 95 % interval.
    pub image: [(f64, f64, (f64, f64)); 3],
    /// Root-mean-square difference over all pixels and channels.
    pub rmse: f64,
    /// The mean of `z²` over pixel-channels: about 1 when the variances are right.
    pub mean_z2: f64,
    /// The share of pixel-channels with `|z| > 1.96`: about 0.05 when the images agree.
    pub share_beyond_95: f64,
}

impl Comparison {
    /// How many of the three whole-image tests fail.
    pub(crate) fn image_failure_count(&self) -> usize {
        self.image
            .iter()
            .filter(|(z, _, _)| fails(*z, self.z_critical))
            .count()
    }

    /// Whether the images agree: no pixel, no block and no whole-image mean beyond the
    /// critical value.
    pub fn agree(&self) -> bool {
        self.pixel_failure_count == 0
            && self.block_failure_count == 0
            && self.image_failure_count() == 0
    }

    /// A report for people, several lines; `names` are the two sides (file names).
    pub fn report(&self, names: [&str; 2]) -> String {
        let rgb = ["R", "G", "B"];
        let mut s = String::new();
        for (name, source) in names.iter().zip(&self.sources) {
            s += &format!("{name}: variance from {source}\n");
        }
        s += &format!(
            "{} pixel, {} block and 3 whole-image tests, Šidák-corrected to a {:.3} % chance of a false alarm: a test fails when p < {:.3e} (|z| > {:.3})\n",
            self.pixel_tests,
            self.block_tests,
            100.0 * self.alpha,
            self.level,
            self.z_critical
        );
        let (lo, median) = self.pixel_dof;
        if median.is_finite() {
            s += &format!(
                "pixel tests: Student's t with {median:.0} degrees of freedom (the smaller side's; smallest {lo:.0}): |t| > {:.3} fails\n",
                t_critical(self.level, median)
            );
        } else {
            s += "pixel tests: normal (both variances taken as exact)\n";
        }
        s += &format!(
            "RMSE {:.6e}; mean z^2 {:.4} (1 if the variances are right); |z| > 1.96 in {:.3} % of pixel-channels (near 5 % when both sides have many degrees of freedom, fewer with few: a pixel test takes the smaller side's)\n",
            self.rmse,
            self.mean_z2,
            100.0 * self.share_beyond_95
        );
        s += "the sign of every z and difference: positive where the candidate (the second) is brighter than the reference; pixels and blocks at (x, y) from the top-left pixel (0, 0), y down\n";
        s += &format!(
            "whole image: z = {:.2} (R), {:.2} (G), {:.2} (B)\n",
            self.image[0].0, self.image[1].0, self.image[2].0
        );
        s += &format!(
            "whole image, candidate against reference, with 95 % intervals: R {}, G {}, B {}\n",
            percent(self.image[0].2),
            percent(self.image[1].2),
            percent(self.image[2].2)
        );
        s += &format!(
            "pixels beyond: {}; blocks ({BLOCK}x{BLOCK}) beyond: {}; whole-image means beyond: {}\n",
            self.pixel_failure_count,
            self.block_failure_count,
            self.image_failure_count()
        );
        for (x, y, c, z) in self.pixel_failures.iter().take(5) {
            s += &format!("  pixel ({x}, {y}) channel {}: z = {z:.2}\n", rgb[*c]);
        }
        s += "worst regions:\n";
        for r in self.regions.iter().take(5) {
            s += &format!(
                "  block at ({}, {}) channel {}: z = {:.2} ({:.0} degrees of freedom), {}, RMSE {:.4e}\n",
                r.x,
                r.y,
                rgb[r.channel],
                r.z,
                r.dof,
                percent(r.relative),
                r.rmse
            );
        }
        s += if self.agree() {
            "verdict: the images AGREE within their noise\n"
        } else {
            "verdict: the images DIFFER\n"
        };
        s
    }
}

/// The tests of a [`Comparison`] that failed: how many of each kind, and the worst of each.
#[derive(Clone, Debug, PartialEq)]
pub struct Failures {
    /// The critical `|z|` every test was held to.
    pub z_critical: f64,
    /// How many pixel-channel tests failed, and the worst: `(x, y, channel, z)`.
    pub pixels: (usize, Option<(u32, u32, usize, f64)>),
    /// How many block tests failed, and the worst.
    pub blocks: (usize, Option<Region>),
    /// The whole image's failed channel means: `(channel, z)`.
    pub image: Vec<(usize, f64)>,
}

impl Failures {
    /// Whether no test failed.
    pub fn is_empty(&self) -> bool {
        self.pixels.0 == 0 && self.blocks.0 == 0 && self.image.is_empty()
    }

    /// In words: `3 pixel tests (worst: pixel (12, 40) G, z = 7.2), 1 block test (worst:
    /// the block at (16, 16) B, z = -5.9), the whole image's mean in R (z = 6.3), beyond
    /// |z| > 5.31`; empty when none failed.
    pub fn text(&self) -> String {
        let rgb = ["R", "G", "B"];
        let plural =
            |n: usize, what: &str| format!("{n} {what} test{}", if n == 1 { "" } else { "s" });
        let mut parts = Vec::new();
        if let (n, Some((x, y, c, z))) = self.pixels {
            parts.push(format!(
                "{} (worst: pixel ({x}, {y}) {}, z = {z:.1})",
                plural(n, "pixel"),
                rgb[c]
            ));
        }
        if let (n, Some(r)) = self.blocks {
            parts.push(format!(
                "{} (worst: the {BLOCK}x{BLOCK} block at ({}, {}) {}, z = {:.1})",
                plural(n, "block"),
                r.x,
                r.y,
                rgb[r.channel],
                r.z
            ));
        }
        if !self.image.is_empty() {
            let channels: Vec<String> = self
                .image
                .iter()
                .map(|(c, z)| format!("{} (z = {z:.1})", rgb[*c]))
                .collect();
            parts.push(format!("the whole image's mean in {}", channels.join(", ")));
        }
        if parts.is_empty() {
            return String::new();
        }
        format!("{}, beyond |z| > {:.2}", parts.join(", "), self.z_critical)
    }
}

impl Comparison {
    /// The tests that failed ([`Failures`]).
    pub fn failures(&self) -> Failures {
        Failures {
            z_critical: self.z_critical,
            pixels: (
                self.pixel_failure_count,
                self.pixel_failures.first().copied(),
            ),
            blocks: (
                self.block_failure_count,
                self.regions
                    .iter()
                    .find(|r| fails(r.z, self.z_critical))
                    .copied(),
            ),
            image: (0..3)
                .filter(|&c| fails(self.image[c].0, self.z_critical))
                .map(|c| (c, self.image[c].0))
                .collect(),
        }
    }
}

/// A relative difference and the half-width of its interval, in percent.
fn percent((r, h): (f64, f64)) -> String {
    format!("{:+.3} % ± {:.3} %", 100.0 * r, 100.0 * h)
}

/// Whether a test with normal-equivalent `z` fails at `z_critical` (NaN fails).
fn fails(z: f64, z_critical: f64) -> bool {
    z.abs() > z_critical || z.is_nan()
}

/// The two-sided critical `|t|` at `level` for Student's t with `dof` degrees of freedom
/// (normal above [`NORMAL_DOF`]).
pub fn t_critical(level: f64, dof: f64) -> f64 {
    if dof > NORMAL_DOF {
        return two_sided_critical(level);
    }
    StudentsT::new(0.0, 1.0, dof).map_or(f64::NAN, |t| t.inverse_cdf(1.0 - level / 2.0))
}

// ANCHOR: equivalent_z
/// The test of a difference `d` with estimated variance `v` and `dof` degrees of freedom:
/// `t = d / sqrt(v)`, its two-sided p-value `P(|T_ν| >= |t|)` (normal above
/// [`NORMAL_DOF`]), returned as the normal z with the same p-value and the sign of `d`.
/// `d = 0` gives 0; a difference with `v = 0` an infinite z.
pub fn equivalent_z(d: f64, v: f64, dof: f64) -> f64 {
    if d == 0.0 {
        return 0.0;
    }
    let t = d / v.sqrt();
    if t.is_nan() || dof.is_nan() {
        return f64::NAN;
    }
    if t.is_infinite() || dof > NORMAL_DOF {
        return t;
    }
    let p = ttest::two_sided_p(t, dof);
    if p > 0.0 {
        t.signum() * two_sided_critical(p)
    } else if p == 0.0 {
        // Beyond the smallest double: the t itself (larger than the z) stands in.
        t
    } else {
        f64::NAN
    }
}
// ANCHOR_END: equivalent_z

// ANCHOR: dof
/// The degrees of freedom of one pixel's test, whose variance `v_a + v_b` sums two
/// estimates: the smaller of their degrees of freedom (of those that are not 0). Always
/// conservative: `t = d / sqrt(v̂)` has a tail no heavier than Student's with that many,
/// whatever the two variances' shares (`(1 - w) + w X` is less spread than `X`, in the
/// convex order, for `X = χ²_ν / ν`, and `P(Z² > c y)` is convex in `y`). The plug-in
/// Welch–Satterthwaite value is not: with two images its estimate of `ν` is large exactly
/// when the candidate's variance happens to come out small.
pub fn pixel_dof(terms: [(f64, f64); 2]) -> f64 {
    terms
        .iter()
        .filter(|(v, _)| *v > 0.0)
        .map(|(_, dof)| *dof)
        .fold(f64::INFINITY, f64::min)
}

/// The degrees of freedom of a region's mean, whose variance sums many independent
/// estimates `v_k` with `ν_k` degrees of freedom each, given as `(v_k, ν_k, u_k)` with
/// `u_k` the term's [`upper_limit`]. Welch–Satterthwaite's `(Σ σ²)² / Σ (σ_k⁴ / ν_k)`
/// with both parts estimated without bias: `S = Σ v_k² / (ν_k + 2)` (a variance
/// estimate's square overestimates the variance's square by `1 + 2 / ν`) and
/// `(Σ v)² - 2S` (the square of a sum overestimates by the sum's variance), so
/// `(Σ v)² / S - 2`, exactly `ν` for a single term. The plug-in value is not safe where one
/// pixel carries most of the region's variance: when that pixel's estimate comes out
/// small, the shares look even and the degrees of freedom many, just when the region's
/// `t` is large. So each term in turn is raised to its upper confidence limit `u_k v_k`
/// and the smallest result is kept. The result is never below the smallest `ν_k`, which
/// bounds the true value from below (`Σ v_k² / (ν_k + 2) <= (Σ v)² / (ν_min + 2)`); the
/// final `max` only keeps rounding from crossing it. Computed with the shares `v_k / Σ v`, so that tiny variances
/// cannot underflow; infinite when every estimate is exact, or when the sum is 0.
pub fn region_dof(terms: impl Iterator<Item = (f64, f64, f64)> + Clone) -> f64 {
    let total: f64 = terms.clone().map(|(v, _, _)| v).sum();
    if total.is_nan() || total <= 0.0 {
        return f64::INFINITY;
    }
    let positive = terms.filter(|&(v, _, _)| v > 0.0);
    let (s, least) = positive
        .clone()
        .fold((0.0, f64::INFINITY), |(s, least), (v, dof, _)| {
            let share = if dof.is_finite() {
                (v / total).powi(2) / (dof + 2.0)
            } else {
                0.0
            };
            (s + share, least.min(dof))
        });
    let estimated = positive.filter(|&(_, dof, _)| dof.is_finite());
    // Term k raised by the factor u: the sum grows by (u - 1) w, S by (u² - 1) w² / (ν + 2).
    let guarded = estimated.fold(1.0 / s - 2.0, |dof, (v, nu, u)| {
        let w = v / total;
        let sum = 1.0 + (u - 1.0) * w;
        dof.min(sum * sum / (s + (u * u - 1.0) * w * w / (nu + 2.0)) - 2.0)
    });
    guarded.max(least)
}

/// The upper confidence limit at one-sided level `level` of a variance estimated with
/// `dof` degrees of freedom, as a multiple of the estimate: `ν / χ²_ν(level)`, with
/// `χ²_ν(level)` the chi-squared distribution's lower `level` quantile (a variance exceeds
/// its estimate that many times with probability `level`, for normal samples), at most
/// `1e100`; 1 for an estimate taken as exact (above [`NORMAL_DOF`]).
pub fn upper_limit(dof: f64, level: f64) -> f64 {
    if dof > NORMAL_DOF {
        return 1.0;
    }
    (dof / chi2::lower_quantile(level, dof)).min(1e100)
}

/// The chance that a 16 x 16 block's test at `level` fails, for a bias of `bias` standard
/// errors of the block's mean (0: a false alarm), with the candidate's every pixel variance
/// estimated with `nu` degrees of freedom and not floored, against an exact reference with
/// a sixteenth of that variance, one pixel carrying `rho` times the others' variance; the
/// degrees of freedom [`region_dof`]'s, `guarded` or the plug-in ones (every
/// [`upper_limit`] 1). The case the guard is for, measured in chapter *Comparing images*.
///
/// Nothing is drawn for the block's mean: given the variance estimates, its difference is
/// normal, and the chance that `|t| = |bias + Z| sqrt(V / V̂)` exceeds Student's critical
/// value `c` is `P(|bias + Z| > c sqrt(V̂ / V))` exactly (Rao–Blackwell), for normal
/// samples. The carrying pixel's estimate, which sets the tail, is taken at the middle of
/// 100 slices of probability spread evenly in logarithm from `1e-12` to `1e-2` and 200
/// even slices from `1e-2` to 1, each weighted by its slice (what lies below `1e-12` adds
/// at most `1e-12`); the other pixels' estimates, `χ²_ν / ν` as sums of `ν` squared
/// normals, are drawn afresh for each: where no pixel carries the block, the chance is a
/// Monte Carlo average over about 200 such draws, good to about 1 %.
pub fn block_chance(nu: u32, rho: f64, bias: f64, guarded: bool, level: f64, rng: &mut Rng) -> f64 {
    let n = (BLOCK * BLOCK) as usize;
    let dof = f64::from(nu);
    let u = if guarded {
        upper_limit(dof, level)
    } else {
        1.0
    };
    let upper_tail = |x: f64| 0.5 * erfc(x / std::f64::consts::SQRT_2);
    let (logarithmic, even) = (100, 200);
    let edge = |j: i32| {
        if j <= logarithmic {
            10f64.powf(-12.0 + 10.0 * f64::from(j) / f64::from(logarithmic))
        } else {
            1e-2 + 0.99 * f64::from(j - logarithmic) / f64::from(even)
        }
    };
    let truth = (rho + (n - 1) as f64) * (1.0 + 1.0 / 16.0);
    let mut chance = 0.0;
    let mut terms = Vec::with_capacity(2 * n);
    for j in 0..logarithmic + even {
        let (lo, hi) = (edge(j), edge(j + 1));
        terms.clear();
        for k in 0..n {
            let (sigma2, x) = if k == 0 {
                (rho, chi2::lower_quantile(0.5 * (lo + hi), dof) / dof)
            } else {
                let sum: f64 = (0..nu).map(|_| standard_normal(rng).powi(2)).sum();
                (1.0, sum / dof)
            };
            terms.push((sigma2 * x, dof, u));
            terms.push((sigma2 / 16.0, f64::INFINITY, 1.0));
        }
        let estimate: f64 = terms.iter().map(|t| t.0).sum();
        let c = t_critical(level, region_dof(terms.iter().copied()));
        let r = c * (estimate / truth).sqrt();
        chance += (hi - lo) * (upper_tail(r - bias) + upper_tail(r + bias));
    }
    chance
}
// ANCHOR_END: dof

// ANCHOR: compare
/// Compares `a` and `b` at family-wise level `alpha`: every pixel and channel, the means
/// of [`BLOCK`] x [`BLOCK`] blocks and the whole image's mean, each a two-sided test of
/// `t = d / sqrt(v_a + v_b)` against Student's t with its degrees of
/// freedom ([`pixel_dof`] for a pixel, [`region_dof`] for a region), Šidák-corrected over
/// all of them.
///
/// # Errors
/// If the sizes differ ([`ImageError::Mismatch`]), `alpha` is not in (0, 1) or a degree
/// of freedom is not positive ([`ImageError::Parameter`]), a mean is not finite or a
/// variance is NaN, negative or infinite (a render with one sample per pixel has no
/// variance; [`ImageError::Pixels`]).
pub fn compare(a: &Estimate, b: &Estimate, alpha: f64) -> Result<Comparison, ImageError> {
    check_inputs(a, b, alpha)?;
    let (ia, ib) = (&a.image, &b.image);
    let (w, h) = (ia.width, ia.height);
    let (bw, bh) = (w.div_ceil(BLOCK), h.div_ceil(BLOCK));
    let pixel_tests = 3 * ia.mean.len();
    let block_tests = 3 * (bw * bh) as usize;
    let level = test_level(w, h, alpha);
    let z_critical = two_sided_critical(level);
    let (na, nb) = (a.dof, b.dof);

    // Pixels.
    let mut failures = Vec::new();
    let mut zs = Vec::with_capacity(ia.mean.len());
    let mut dofs = Vec::with_capacity(pixel_tests);
    let (mut sum_d2, mut sum_z2, mut beyond_95) = (0.0, 0.0, 0usize);
    for i in 0..ia.mean.len() {
        let (x, y) = (i as u32 % w, i as u32 / w);
        let d = ib.mean[i] - ia.mean[i];
        let mut z = DVec3::ZERO;
        for c in 0..3 {
            let (va, vb) = (ia.var[i][c], ib.var[i][c]);
            let dof = pixel_dof([(va, na), (vb, nb)]);
            z[c] = equivalent_z(d[c], va + vb, dof);
            dofs.push(dof);
            sum_d2 += d[c] * d[c];
            sum_z2 += if z[c].is_finite() { z[c] * z[c] } else { 0.0 };
            if z[c].abs() > 1.96 {
                beyond_95 += 1;
            }
            if fails(z[c], z_critical) {
                failures.push((x, y, c, z[c]));
            }
        }
        zs.push(z);
    }
    failures.sort_by(|p, q| q.3.abs().total_cmp(&p.3.abs()));
    let pixel_failure_count = failures.len();
    failures.truncate(20);
    dofs.sort_by(f64::total_cmp);

    // Blocks, and the whole image as one region.
    let limits = region_limits(a, b, level);
    let regions = block_regions(a, b, limits);
    let block_failure_count = regions.iter().filter(|r| fails(r.z, z_critical)).count();
    let image = image_means(a, b, limits);
    let m = pixel_tests as f64;
    Ok(Comparison {
        size: (w, h),
        alpha,
        pixel_tests,
        block_tests,
        level,
        z_critical,
        sources: [a.source.clone(), b.source.clone()],
        pixel_dof: (dofs[0], dofs[dofs.len() / 2]),
        pixel_failures: failures,
        pixel_failure_count,
        z: zs,
        regions,
        block_failure_count,
        image,
        rmse: (sum_d2 / m).sqrt(),
        mean_z2: sum_z2 / m,
        share_beyond_95: beyond_95 as f64 / m,
    })
}
// ANCHOR_END: compare

/// The blocks' tests of [`compare`] alone, the same regions in the same order (the
/// largest `|z|` first), for a search that weighs many hypotheses by the blocks and reads
/// no pixel's test: the pixels' tests are most of the cost of a comparison.
///
/// # Errors
/// As [`compare`].
pub fn compare_blocks(a: &Estimate, b: &Estimate, alpha: f64) -> Result<Vec<Region>, ImageError> {
    check_inputs(a, b, alpha)?;
    let level = test_level(a.image.width, a.image.height, alpha);
    Ok(block_regions(a, b, region_limits(a, b, level)))
}

/// The level of each test of [`compare`] of two `width` x `height` images at family-wise
/// level `alpha`: Šidák over every pixel-channel, every block-channel and the whole
/// image's three channels.
pub fn test_level(width: u32, height: u32, alpha: f64) -> f64 {
    let pixels = width as usize * height as usize;
    let blocks = width.div_ceil(BLOCK) as usize * height.div_ceil(BLOCK) as usize;
    sidak(alpha, (3 * (pixels + blocks + 1)) as u32)
}

/// The [`upper_limit`] of each side's variances at the test's `level`, once a comparison:
/// 1 for a floored side, whose variances are the reference's where they could have come out
/// small.
fn region_limits(a: &Estimate, b: &Estimate, level: f64) -> (f64, f64) {
    let limit = |e: &Estimate| {
        if e.floored {
            1.0
        } else {
            upper_limit(e.dof, level)
        }
    };
    (limit(a), limit(b))
}

/// One channel's terms of a region's variance, `(v_k, ν_k, u_k)` for [`region_dof`]: every
/// pixel's variance on both sides, each with its side's degrees of freedom and limit
/// ([`region_limits`]).
fn region_terms<'a>(
    a: &'a Estimate,
    b: &'a Estimate,
    (ua, ub): (f64, f64),
    c: usize,
    pixels: impl Iterator<Item = usize> + Clone + 'a,
) -> impl Iterator<Item = (f64, f64, f64)> + Clone + 'a {
    pixels.flat_map(move |i| {
        [
            (a.image.var[i][c], a.dof, ua),
            (b.image.var[i][c], b.dof, ub),
        ]
    })
}

/// The errors of [`compare`]: sizes that differ, `alpha` outside (0, 1), a degree of
/// freedom that is not positive, a value [`check_values`] refuses.
fn check_inputs(a: &Estimate, b: &Estimate, alpha: f64) -> Result<(), ImageError> {
    let (ia, ib) = (&a.image, &b.image);
    if (ia.width, ia.height) != (ib.width, ib.height) {
        return Err(ImageError::Mismatch(format!(
            "the images have different sizes: {}x{} and {}x{}",
            ia.width, ia.height, ib.width, ib.height
        )));
    }
    if !(alpha > 0.0 && alpha < 1.0) {
        return Err(ImageError::Parameter(format!(
            "alpha = {alpha} must be in (0, 1)"
        )));
    }
    for (name, e) in [("first", a), ("second", b)] {
        if e.dof.is_nan() || e.dof <= 0.0 {
            return Err(ImageError::Parameter(format!(
                "the {name} image's degrees of freedom, {}, must be > 0",
                e.dof
            )));
        }
        check_values(&e.image, name)?;
    }
    Ok(())
}

/// The test of each [`BLOCK`] x [`BLOCK`] block's mean, the largest `|z|` first: per
/// channel, `t = d / sqrt(v)` of the mean difference `d` with the variance `v` of the
/// pixels' sum over `n²`, and [`region_dof`] degrees of freedom; the block's z is its
/// channel with the largest `|z|`.
fn block_regions(a: &Estimate, b: &Estimate, limits: (f64, f64)) -> Vec<Region> {
    let (ia, ib) = (&a.image, &b.image);
    let (w, h) = (ia.width, ia.height);
    let (bw, bh) = (w.div_ceil(BLOCK), h.div_ceil(BLOCK));
    let region = |x0: u32, y0: u32, rw: u32, rh: u32| -> Region {
        let pixels = || {
            (y0..(y0 + rh).min(h))
                .flat_map(move |y| (x0..(x0 + rw).min(w)).map(move |x| ia.index(x, y)))
        };
        let n = pixels().count() as f64;
        let mut best = (0.0_f64, 0usize, f64::INFINITY, (0.0, 0.0));
        let mut zs = DVec3::ZERO;
        for c in 0..3 {
            let d: f64 = pixels().map(|i| ib.mean[i][c] - ia.mean[i][c]).sum::<f64>() / n;
            let base: f64 = pixels().map(|i| ia.mean[i][c]).sum::<f64>() / n;
            let terms = region_terms(a, b, limits, c, pixels());
            let v = terms.clone().map(|(v, _, _)| v).sum::<f64>() / (n * n);
            let dof = region_dof(terms);
            let z = equivalent_z(d, v, dof);
            zs[c] = z;
            if c == 0 || z.abs() > best.0.abs() || z.is_nan() {
                best = (z, c, dof, relative(d, v, dof, base));
            }
        }
        let d2: f64 = pixels()
            .map(|i| (ia.mean[i] - ib.mean[i]).length_squared())
            .sum();
        Region {
            x: x0,
            y: y0,
            z: best.0,
            channel: best.1,
            zs,
            dof: best.2,
            relative: best.3,
            rmse: (d2 / (3.0 * n)).sqrt(),
        }
    };
    let mut regions: Vec<Region> = (0..bw * bh)
        .map(|k| region((k % bw) * BLOCK, (k / bw) * BLOCK, BLOCK, BLOCK))
        .collect();
    regions.sort_by(|p, q| q.z.abs().total_cmp(&p.z.abs()));
    regions
}

/// The relative difference `d / |base|` and the half-width of its 95 % interval (Student's
/// t with `dof` degrees of freedom on the variance `v` of `d`); NaN where `base` is 0.
fn relative(d: f64, v: f64, dof: f64, base: f64) -> (f64, f64) {
    let half = t_critical(0.05, dof) * v.sqrt();
    (d / base.abs(), half / base.abs())
}

/// The whole image's mean difference per channel: its z, degrees of freedom, and the
/// relative difference with the half-width of its 95 % interval ([`relative`]).
fn image_means(a: &Estimate, b: &Estimate, limits: (f64, f64)) -> [(f64, f64, (f64, f64)); 3] {
    let (ia, ib) = (&a.image, &b.image);
    let n = ia.mean.len() as f64;
    std::array::from_fn(|c| {
        let d = ia
            .mean
            .iter()
            .zip(&ib.mean)
            .map(|(p, q)| q[c] - p[c])
            .sum::<f64>()
            / n;
        let base = ia.mean.iter().map(|p| p[c]).sum::<f64>() / n;
        let terms = region_terms(a, b, limits, c, 0..ia.mean.len());
        let v = terms.clone().map(|(v, _, _)| v).sum::<f64>() / (n * n);
        let dof = region_dof(terms);
        (equivalent_z(d, v, dof), dof, relative(d, v, dof, base))
    })
}

/// Refuses an image with a mean that is not finite or a variance that is not a finite
/// number `>= 0`, naming the first such pixel.
fn check_values(img: &Image, name: &str) -> Result<(), ImageError> {
    for (i, (m, v)) in img.mean.iter().zip(&img.var).enumerate() {
        let (x, y) = (i as u32 % img.width, i as u32 / img.width);
        if !m.is_finite() {
            return Err(ImageError::Pixels(format!(
                "the {name} image's pixel ({x}, {y}) is {m}, not finite"
            )));
        }
        if !(v.is_finite() && v.min_element() >= 0.0) {
            return Err(ImageError::Pixels(format!(
                "the {name} image's pixel ({x}, {y}) has variance {v}: a variance image needs at least 2 samples per pixel"
            )));
        }
    }
    Ok(())
}

/// Compares two renders that carry their own variances ([`Estimate::from_variance`] of
/// each): the comparison of two raylemma renders.
///
/// # Errors
/// As [`compare`].
pub fn compare_images(a: &Image, b: &Image, alpha: f64) -> Result<Comparison, ImageError> {
    compare(
        &Estimate::from_variance(a.clone()),
        &Estimate::from_variance(b.clone()),
        alpha,
    )
}

/// The difference image of a comparison: each pixel coloured by the z of its channel with
/// the largest `|z|`: red where the candidate (the second image) is brighter, blue where it
/// is darker, brighter in proportion to `|z| / z_critical`, white beyond `z_critical` (a
/// failed pixel test), black where the images agree exactly; and the outline of every
/// failed block (a [`BLOCK`]-pixel square whose mean differs beyond `z_critical`) in
/// yellow, drawn over the pixels at its edge, so that a difference too small for any
/// pixel to fail is still seen where it is. 8-bit sRGB bytes, row-major.
pub fn difference_rgb8(c: &Comparison) -> Vec<u8> {
    let mut rgb: Vec<DVec3> =
        c.z.iter()
            .map(|zs| {
                let k = (0..3)
                    .max_by(|&p, &q| zs[p].abs().total_cmp(&zs[q].abs()))
                    .unwrap_or(0);
                let t = (zs[k].abs() / c.z_critical).min(1.0);
                let t = if t.is_nan() { 1.0 } else { t };
                if fails(zs[k], c.z_critical) {
                    DVec3::ONE
                } else if zs[k] >= 0.0 {
                    DVec3::new(t, 0.25 * t, 0.25 * t)
                } else {
                    DVec3::new(0.25 * t, 0.25 * t, t)
                }
            })
            .collect();
    let (w, h) = c.size;
    for r in c.regions.iter().filter(|r| fails(r.z, c.z_critical)) {
        let (x1, y1) = ((r.x + BLOCK).min(w) - 1, (r.y + BLOCK).min(h) - 1);
        for y in r.y..=y1 {
            for x in r.x..=x1 {
                if x == r.x || x == x1 || y == r.y || y == y1 {
                    rgb[(y * w + x) as usize] = DVec3::new(1.0, 0.85, 0.0);
                }
            }
        }
    }
    rgb.iter()
        .flat_map(|p| {
            [
                display::srgb8(p.x),
                display::srgb8(p.y),
                display::srgb8(p.z),
            ]
        })
        .collect()
}

/// The noise of an image: the RMS over pixels of the standard error of a pixel's
/// luminance, and that divided by the mean luminance. The channels' errors are correlated
/// (one path makes all three) and the image keeps no covariances, so a pixel's luminance
/// error is bounded by the weighted sum of its channels' standard errors (exact when they
/// are perfectly correlated): the levels quoted are upper bounds.
pub fn noise_level(image: &Image) -> (f64, f64) {
    let n = image.mean.len() as f64;
    let se = |v: DVec3| display::LUMA.dot(v.map(|x| x.max(0.0).sqrt()));
    let rms = (image.var.iter().map(|&v| se(v).powi(2)).sum::<f64>() / n).sqrt();
    let mean = image
        .mean
        .iter()
        .map(|&m| display::luminance(m))
        .sum::<f64>()
        / n;
    (rms, rms / mean)
}

/// The mean squared error of `image` against `reference`, less the reference's own mean
/// variance (an unbiased estimate of the error against the exact image), per channel.
pub fn mse_against(image: &Image, reference: &Image) -> f64 {
    let n = 3.0 * image.mean.len() as f64;
    let d2: f64 = image
        .mean
        .iter()
        .zip(&reference.mean)
        .map(|(a, b)| (*a - *b).length_squared())
        .sum();
    let v: f64 = reference.var.iter().map(|v| v.x + v.y + v.z).sum();
    (d2 - v) / n
}
