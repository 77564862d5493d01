//! Pooled z-tests of an image: against an expected image known exactly, or against another
//! render of the same scene. Chapter: *Testing the renderer*
//! (`chapters/renderer/testing.md`).
//!
//! One pixel's mean after a few dozen samples is not normal (a single wavelength per path
//! gives a skewed colour), and a bias of half a percent is far below one pixel's noise. A
//! region's pixels are therefore pooled: its z-score is
//!
//! `z = sum_i (mean_i - expected_i) / sqrt(sum_i var_i)`,
//!
//! the difference of the region's total from its expected total in units of its standard
//! error (the pixels are independent, so the variances add; for two renders, both images'
//! variances). The regions are the whole tested area, which sees a small bias spread over
//! the image, and blocks of [`BLOCK`] x [`BLOCK`] pixels, which see a larger one in a small
//! part of it. Each region and channel is one two-sided test; Šidák's correction over all
//! of them holds the probability of a false alarm at the level asked for.

use glam::DVec3;

use crate::image::Image;
use crate::spectral::display;
use crate::stats::sidak;
use crate::stats::two_sided_critical;

/// The side of the pooled blocks, pixels.
pub const BLOCK: u32 = 8;

/// What an image is compared with, pixel by pixel: `None` where a pixel is not tested (it
/// straddles an edge whose expected value the quadrature cannot resolve).
#[derive(Clone, Debug, PartialEq)]
pub struct Expected {
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// The expected mean of each pixel, row by row.
    pub mean: Vec<Option<DVec3>>,
    /// The variance of each expected value: zero for an exact answer, the other image's
    /// variance of the mean for a comparison of two renders.
    pub var: Vec<DVec3>,
}

impl Expected {
    /// An exact expected image (no variance).
    pub fn exact(width: u32, height: u32, mean: Vec<Option<DVec3>>) -> Self {
        let n = mean.len();
        Expected {
            width,
            height,
            mean,
            var: vec![DVec3::ZERO; n],
        }
    }

    /// Another render as the expectation, tested where `tested(x, y)`.
    pub fn render(image: &Image, tested: impl Fn(u32, u32) -> bool) -> Self {
        let mean = (0..image.height)
            .flat_map(|y| (0..image.width).map(move |x| (x, y)))
            .map(|(x, y)| tested(x, y).then(|| image.mean[image.index(x, y)]))
            .collect();
        Expected {
            width: image.width,
            height: image.height,
            mean,
            var: image.var.clone(),
        }
    }

    /// How many pixels are tested.
    pub fn tested(&self) -> usize {
        self.mean.iter().filter(|m| m.is_some()).count()
    }
}

/// The outcome of pooling an image against its expectation.
#[derive(Clone, Debug, PartialEq)]
pub struct Pooled {
    /// The whole tested area's `|z|`, in the channel where it is largest.
    pub global_z: f64,
    /// The largest block `|z|`.
    pub block_z: f64,
    /// The top-left pixel of that block.
    pub worst_block: (u32, u32),
    /// The critical `|z|` of every region: Šidák at the level over `3 (blocks + 1)` tests.
    pub critical: f64,
    /// The number of blocks with at least one tested pixel.
    pub blocks: usize,
    /// The number of tested pixels.
    pub pixels: usize,
    /// The side of the blocks.
    pub block: u32,
    /// The whole area's relative difference from the expectation, in luminance:
    /// `(sum mean - sum expected) / sum expected`.
    pub relative_difference: f64,
    /// The whole area's standard error relative to its expected luminance: a global bias
    /// of `(critical + 1.28)` times this is detected nine times in ten.
    pub relative_error: f64,
}

impl Pooled {
    /// True when no region is beyond the critical value (NaN fails).
    pub fn passed(&self) -> bool {
        self.global_z <= self.critical && self.block_z <= self.critical
    }

    /// The smallest global bias (relative, in luminance) detected nine times in ten:
    /// `(critical + z_0.9) relative_error`, with `z_0.9 = 1.2816`.
    pub(crate) fn detectable_bias(&self) -> f64 {
        (self.critical + 1.2816) * self.relative_error
    }
}

/// The largest of three `|z|`, or NaN if any is NaN (a NaN pixel must fail, not vanish).
fn max_abs3(v: DVec3) -> f64 {
    crate::check::max_abs(v.to_array())
}

/// `d / sqrt(v)` in each channel, where a zero variance gives 0 for no difference and an
/// infinite `|z|` for any difference (an exact zero expected and observed is agreement).
fn z_of(d: DVec3, v: DVec3) -> DVec3 {
    DVec3::from_array(std::array::from_fn(|c| {
        let (d, v) = (d[c], v[c]);
        if v > 0.0 {
            d / v.sqrt()
        } else if d == 0.0 {
            0.0
        } else {
            f64::INFINITY * d.signum() + d // NaN stays NaN
        }
    }))
}

/// Pools `image` against `expected` (the same size) in the whole tested area and in
/// blocks of [`BLOCK`]² pixels, at the level `level` for all of them together.
///
/// # Panics
/// If the sizes differ (a programming error in a test).
pub fn pool(image: &Image, expected: &Expected, level: f64) -> Pooled {
    pool_blocks(image, expected, level, BLOCK)
}

// ANCHOR: pool
/// [`pool`] with blocks of `block`² pixels. Larger blocks hold more samples, which a scene
/// with rare bright paths (caustics, a light seen through glass) needs before a block's
/// total is normal.
///
/// # Panics
/// If the sizes differ, or `block` is 0.
pub fn pool_blocks(image: &Image, expected: &Expected, level: f64, block: u32) -> Pooled {
    let b = block;
    assert!(b > 0, "pool: blocks of side 0");
    assert!(
        image.width == expected.width && image.height == expected.height,
        "pool: image {}x{} against an expectation of {}x{}",
        image.width,
        image.height,
        expected.width,
        expected.height
    );
    let bw = image.width.div_ceil(b);
    let nb = (bw * image.height.div_ceil(b)) as usize;
    let mut diff = vec![DVec3::ZERO; nb];
    let mut var = vec![DVec3::ZERO; nb];
    let mut count = vec![0usize; nb];
    let (mut observed_y, mut expected_y) = (0.0, 0.0);
    for y in 0..image.height {
        for x in 0..image.width {
            let i = image.index(x, y);
            let Some(e) = expected.mean[i] else { continue };
            let k = ((y / b) * bw + x / b) as usize;
            diff[k] += image.mean[i] - e;
            var[k] += image.var[i] + expected.var[i];
            count[k] += 1;
            observed_y += display::luminance(image.mean[i]);
            expected_y += display::luminance(e);
        }
    }
    let blocks: Vec<usize> = (0..nb).filter(|&k| count[k] > 0).collect();
    let critical = two_sided_critical(sidak(level, 3 * (blocks.len() as u32 + 1)));
    let (mut block_z, mut worst_block) = (0.0, (0, 0));
    for &k in &blocks {
        let z = max_abs3(z_of(diff[k], var[k]));
        // Larger, or NaN, which then stays.
        if z > block_z || z.is_nan() {
            block_z = z;
            worst_block = ((k as u32 % bw) * b, (k as u32 / bw) * b);
            if z.is_nan() {
                break;
            }
        }
    }
    let total_diff: DVec3 = diff.iter().sum();
    let total_var: DVec3 = var.iter().sum();
    let se_y = display::LUMA.dot(total_var.map(|v| v.max(0.0).sqrt()));
    Pooled {
        global_z: max_abs3(z_of(total_diff, total_var)),
        block_z,
        worst_block,
        critical,
        blocks: blocks.len(),
        pixels: count.iter().sum(),
        block: b,
        relative_difference: (observed_y - expected_y) / expected_y,
        relative_error: se_y / expected_y,
    }
}
// ANCHOR_END: pool
