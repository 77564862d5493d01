//! Do two renders of the same scene agree within their noise? Chapter: *The reference
//! renderer* (`chapters/renderer/renderer.md`).
//!
//! Each image carries the variance of every pixel's mean. Under the hypothesis that both
//! estimate the same expected image, and with enough samples per pixel for the central
//! limit theorem, `z = (a - b) / sqrt(var_a + var_b)` is standard normal in every pixel
//! and channel. The comparison runs two families of two-sided z-tests: every pixel and
//! channel, and the means over square blocks (which catch a small bias spread over a
//! region, too small to show in one pixel). Šidák's correction over all of them holds the
//! chance of a false alarm, for two correct renders, at `alpha` (1 % by default).

use glam::DVec3;
use statrs::function::erf::erfc_inv;

use super::image::Image;
use crate::spectral::display;
use crate::stats::sidak;

/// The side of the blocks whose means are compared, pixels.
pub const BLOCK: u32 = 16;

/// One region (a block) of the comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Region {
    /// The block's top-left pixel.
    pub x: u32,
    /// The block's top-left pixel.
    pub y: u32,
    /// The block mean's z-score of the channel with the largest `|z|`.
    pub z: f64,
    /// Which channel (0 R, 1 G, 2 B).
    pub channel: usize,
    /// The RMS difference over the block's pixels and channels.
    pub rmse: f64,
}

/// The verdict of [`compare`].
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// The family-wise false-alarm rate.
    pub alpha: f64,
    /// Number of pixel-channel tests.
    pub pixel_tests: usize,
    /// Number of block-channel tests.
    pub block_tests: usize,
    /// The critical `|z|` of each test (Šidák over all of them).
    pub z_critical: f64,
    /// Pixel-channels beyond the critical value: `(x, y, channel, z)`, worst first (at most 20).
    pub pixel_failures: Vec<(u32, u32, usize, f64)>,
    /// How many pixel-channels are beyond it in all.
    pub pixel_failure_count: usize,
    /// The blocks, worst `|z|` first.
    pub regions: Vec<Region>,
    /// How many blocks are beyond the critical value.
    pub block_failure_count: usize,
    /// Root-mean-square difference over all pixels and channels.
    pub rmse: f64,
    /// The mean of `z^2` over pixel-channels: about 1 when the variances are right.
    pub mean_z2: f64,
    /// The share of pixel-channels with `|z| > 1.96`: about 0.05 when the images agree.
    pub share_beyond_95: f64,
}

impl Comparison {
    /// Whether the images agree: no pixel and no block beyond the critical value.
    pub fn agree(&self) -> bool {
        self.pixel_failure_count == 0 && self.block_failure_count == 0
    }

    /// A report for people, several lines.
    pub fn report(&self) -> String {
        let mut s = format!(
            "{} pixel and {} block z-tests, Šidák-corrected to a {:.3} % chance of a false alarm: |z| > {:.3} fails\n",
            self.pixel_tests,
            self.block_tests,
            100.0 * self.alpha,
            self.z_critical
        );
        s += &format!(
            "RMSE {:.6e}; mean z^2 {:.4} (1 if the variances are right); |z| > 1.96 in {:.3} % of pixel-channels (5 % expected)\n",
            self.rmse,
            self.mean_z2,
            100.0 * self.share_beyond_95
        );
        s += &format!(
            "pixels beyond: {}; blocks ({BLOCK}x{BLOCK}) beyond: {}\n",
            self.pixel_failure_count, self.block_failure_count
        );
        for (x, y, c, z) in self.pixel_failures.iter().take(5) {
            s += &format!(
                "  pixel ({x}, {y}) channel {}: z = {z:.2}\n",
                ["R", "G", "B"][*c]
            );
        }
        s += "worst regions:\n";
        for r in self.regions.iter().take(5) {
            s += &format!(
                "  block at ({}, {}) channel {}: z = {:.2}, RMSE {:.4e}\n",
                r.x,
                r.y,
                ["R", "G", "B"][r.channel],
                r.z,
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

/// `z = d / sqrt(v)`, with 0 for `d = 0` and an infinite `z` for a difference where both
/// variances are 0.
fn z_score(d: f64, v: f64) -> f64 {
    if d == 0.0 { 0.0 } else { d / v.sqrt() }
}

/// The two-sided critical value `z` with `P(|Z| > z) = level` for a standard normal `Z`:
/// `sqrt(2) erfc^-1(level)`.
pub fn two_sided_critical(level: f64) -> f64 {
    std::f64::consts::SQRT_2 * erfc_inv(level)
}

// ANCHOR: compare
/// Compares `a` and `b` at family-wise level `alpha`.
///
/// # Errors
/// If the sizes differ, or a variance is NaN, negative or infinite (a render with one
/// sample per pixel has no variance), or a mean is not finite.
pub fn compare(a: &Image, b: &Image, alpha: f64) -> Result<Comparison, String> {
    if (a.width, a.height) != (b.width, b.height) {
        return Err(format!(
            "the images have different sizes: {}x{} and {}x{}",
            a.width, a.height, b.width, b.height
        ));
    }
    if !(alpha > 0.0 && alpha < 1.0) {
        return Err(format!("alpha = {alpha} must be in (0, 1)"));
    }
    for (name, img) in [("first", a), ("second", b)] {
        for (i, (m, v)) in img.mean.iter().zip(&img.var).enumerate() {
            let (x, y) = (i as u32 % img.width, i as u32 / img.width);
            if !m.is_finite() {
                return Err(format!(
                    "the {name} image's pixel ({x}, {y}) is {m}, not finite"
                ));
            }
            if !(v.is_finite() && v.min_element() >= 0.0) {
                return Err(format!(
                    "the {name} image's pixel ({x}, {y}) has variance {v}: a variance image needs at least 2 samples per pixel"
                ));
            }
        }
    }
    let (w, h) = (a.width, a.height);
    let (bw, bh) = (w.div_ceil(BLOCK), h.div_ceil(BLOCK));
    let pixel_tests = 3 * a.mean.len();
    let block_tests = 3 * (bw * bh) as usize;
    let level = sidak(alpha, (pixel_tests + block_tests) as u32);
    let z_critical = two_sided_critical(level);

    let mut failures = Vec::new();
    let (mut sum_d2, mut sum_z2, mut beyond_95) = (0.0, 0.0, 0usize);
    let mut block_d = vec![DVec3::ZERO; (bw * bh) as usize];
    let mut block_v = vec![DVec3::ZERO; (bw * bh) as usize];
    let mut block_n = vec![0u32; (bw * bh) as usize];
    for y in 0..h {
        for x in 0..w {
            let i = a.index(x, y);
            let d = a.mean[i] - b.mean[i];
            let v = a.var[i] + b.var[i];
            let k = ((y / BLOCK) * bw + x / BLOCK) as usize;
            block_d[k] += d;
            block_v[k] += v;
            block_n[k] += 1;
            for c in 0..3 {
                let z = z_score(d[c], v[c]);
                sum_d2 += d[c] * d[c];
                sum_z2 += if z.is_finite() { z * z } else { 0.0 };
                if z.abs() > 1.96 {
                    beyond_95 += 1;
                }
                // NaN-safe: a NaN z (impossible after the checks above) would also fail.
                if z.abs() > z_critical || z.is_nan() {
                    failures.push((x, y, c, z));
                }
            }
        }
    }
    failures.sort_by(|p, q| q.3.abs().total_cmp(&p.3.abs()));
    let pixel_failure_count = failures.len();
    failures.truncate(20);
    let mut regions: Vec<Region> = (0..block_d.len())
        .map(|k| {
            let n = f64::from(block_n[k]);
            let (d, v) = (block_d[k] / n, block_v[k] / (n * n));
            let zs = DVec3::new(z_score(d.x, v.x), z_score(d.y, v.y), z_score(d.z, v.z));
            let channel = (0..3)
                .max_by(|&p, &q| zs[p].abs().total_cmp(&zs[q].abs()))
                .unwrap_or(0);
            let (x, y) = ((k as u32 % bw) * BLOCK, (k as u32 / bw) * BLOCK);
            let mut d2 = 0.0;
            for yy in y..(y + BLOCK).min(h) {
                for xx in x..(x + BLOCK).min(w) {
                    let i = a.index(xx, yy);
                    d2 += (a.mean[i] - b.mean[i]).length_squared();
                }
            }
            Region {
                x,
                y,
                z: zs[channel],
                channel,
                rmse: (d2 / (3.0 * n)).sqrt(),
            }
        })
        .collect();
    regions.sort_by(|p, q| q.z.abs().total_cmp(&p.z.abs()));
    let block_failure_count = regions
        .iter()
        .filter(|r| r.z.abs() > z_critical || r.z.is_nan())
        .count();
    let m = pixel_tests as f64;
    Ok(Comparison {
        alpha,
        pixel_tests,
        block_tests,
        z_critical,
        pixel_failures: failures,
        pixel_failure_count,
        regions,
        block_failure_count,
        rmse: (sum_d2 / m).sqrt(),
        mean_z2: sum_z2 / m,
        share_beyond_95: beyond_95 as f64 / m,
    })
}
// ANCHOR_END: compare

/// The difference image: each pixel coloured by the z-score of its channel with the
/// largest `|z|`: red where the first image is brighter, blue where it is darker, brighter
/// in proportion to `|z| / z_critical`, white beyond `z_critical` (a failed test), black
/// where the images agree exactly. 8-bit sRGB bytes, row-major.
pub fn difference_rgb8(a: &Image, b: &Image, z_critical: f64) -> Vec<u8> {
    let mut out = Vec::with_capacity(3 * a.mean.len());
    for i in 0..a.mean.len() {
        let d = a.mean[i] - b.mean[i];
        let v = a.var[i] + b.var[i];
        let zs = DVec3::new(z_score(d.x, v.x), z_score(d.y, v.y), z_score(d.z, v.z));
        let c = (0..3)
            .max_by(|&p, &q| zs[p].abs().total_cmp(&zs[q].abs()))
            .unwrap_or(0);
        let t = (zs[c].abs() / z_critical).min(1.0);
        let t = if t.is_nan() { 1.0 } else { t };
        let rgb = if zs[c] >= 0.0 {
            DVec3::new(t, 0.25 * t, 0.25 * t)
        } else {
            DVec3::new(0.25 * t, 0.25 * t, t)
        };
        let rgb = if zs[c].abs() > z_critical {
            DVec3::ONE
        } else {
            rgb
        };
        out.extend([
            display::srgb8(rgb.x),
            display::srgb8(rgb.y),
            display::srgb8(rgb.z),
        ]);
    }
    out
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
