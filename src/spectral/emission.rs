//! Importance-sampled emission spectra. Chapter: *Importance-sampled emission spectra*
//! (`chapters/spectral/emission.md`).
//!
//! Five lamps (amber LED, incandescent, cool white fluorescent, low- and high-pressure
//! sodium), each a piecewise-linear [`Table`] of relative spectral power. A path's
//! wavelength is drawn from the lamp's own spectrum by inverting its CDF
//! ([`EmissionSampler`], built on [`PiecewiseLinear1D`]), and the estimate of the lamp's
//! colour is weighted by `L(λ) / p(λ)`:
//!
//! `X̂ = L(λ) x̄(λ) / (p(λ) ∫ȳ)`, and likewise `Ŷ`, `Ẑ`, with `λ ~ p`,
//!
//! unbiased for the `X, Y, Z` of [`crate::spectral::cie::xyz`].
//!
//! Spectra can also be drawn by hand as images ([`parse_image`], [`write_image`]): one
//! pixel column per whole nanometre from 380 to 830 nm (451 columns), the column's value
//! being the share of its pixels that are dark.

use std::path::{Path, PathBuf};

use glam::DVec3;

use super::spectrum::{Table, builtin};
use super::{cie, display};
use crate::data::DataError;
use crate::image::{ImageError, png};
use crate::sampling::tabulated::{PiecewiseLinear1D, TableError};

// ---------------------------------------------------------------------------------------
// The lamps.

/// Peak wavelength of the amber LED model, nm.
pub const AMBER_PEAK_NM: f64 = 592.0;
/// Ohno's width parameter `Δλ₀.₅` of the amber LED model, nm (the full width at half
/// maximum of the model is `0.92 Δλ₀.₅`, about 16.6 nm).
pub const AMBER_WIDTH_NM: f64 = 18.0;

// ANCHOR: amber
/// The amber LED: Ohno's (2005) model of a single-colour LED spectrum,
///
/// `S(λ) = (g + 2 g⁵) / 3`, `g = exp(−((λ − λ₀) / Δλ₀.₅)²)`,
///
/// a narrow Gaussian core (`g⁵`) on a broad Gaussian base (`g`): a sharper top and heavier
/// skirts than a Gaussian of the same width, peak 1 at `λ₀` (Y. Ohno, "Spectral design
/// considerations for white LED color rendering", *Optical Engineering* 44(11), 111302,
/// 2005). `λ₀ = 592 nm` and `Δλ₀.₅ = 18 nm` are typical of an AlInGaP amber LED.
pub fn amber_led(nm: f64) -> f64 {
    let g = (-((nm - AMBER_PEAK_NM) / AMBER_WIDTH_NM).powi(2)).exp();
    (g + 2.0 * g.powi(5)) / 3.0
}
// ANCHOR_END: amber

/// The amber LED model tabulated at every whole nanometre from 380 to 830 nm (the image
/// grid), linear in between.
pub fn amber_led_table() -> Table {
    let nm = image_wavelengths();
    let values = nm.iter().map(|&l| amber_led(l)).collect();
    Table::new(nm, values).unwrap_or_else(|e| panic!("the amber LED table is valid: {e}"))
}

/// A light source: a name, the stem of its image file in `data/`, and its spectrum.
#[derive(Clone, Debug, PartialEq)]
pub struct Lamp {
    /// Name for tables and figures.
    pub name: &'static str,
    /// Stem of the shipped drawing, `data/<stem>.png`.
    pub stem: &'static str,
    /// Relative spectral power, piecewise linear, zero outside its range.
    pub spectrum: Table,
}

/// The five lamps of the chapter, in the source's order: the amber LED (Ohno's model), and
/// the incandescent, cool white fluorescent, low-pressure sodium and high-pressure sodium
/// lamps measured by the NIST CQS data set (`data/lamp_*.csv`, 380-780 nm at 5 nm).
pub fn lamps() -> Vec<Lamp> {
    vec![
        Lamp {
            name: "amber LED",
            stem: "lamp_amber_led",
            spectrum: amber_led_table(),
        },
        Lamp {
            name: "incandescent",
            stem: "lamp_incandescent",
            spectrum: builtin("lamp_incandescent.csv"),
        },
        Lamp {
            name: "fluorescent (cool white)",
            stem: "lamp_cool_white_fluorescent",
            spectrum: builtin("lamp_cool_white_fluorescent.csv"),
        },
        Lamp {
            name: "low-pressure sodium",
            stem: "lamp_low_pressure_sodium",
            spectrum: builtin("lamp_low_pressure_sodium.csv"),
        },
        Lamp {
            name: "high-pressure sodium",
            stem: "lamp_high_pressure_sodium",
            spectrum: builtin("lamp_high_pressure_sodium.csv"),
        },
    ]
}

// ---------------------------------------------------------------------------------------
// Sampling.

/// A wavelength drawn from a lamp's spectrum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WavelengthSample {
    /// The wavelength, nm.
    pub nm: f64,
    /// Its probability density, per nm: positive, and equal to [`EmissionSampler::pdf`].
    pub pdf: f64,
}

/// Draws wavelengths with density proportional to a piecewise-linear spectrum:
/// `p(λ) = L(λ) / ∫L`, by inversion of its CDF (chapter *Tabulated distributions*).
#[derive(Clone, Debug, PartialEq)]
pub struct EmissionSampler {
    dist: PiecewiseLinear1D,
}

impl EmissionSampler {
    // ANCHOR: sampler
    /// The sampler of the spectrum `table`, read exactly as the table is evaluated:
    /// linear between its knots, zero outside.
    ///
    /// # Errors
    /// If the table is zero everywhere (there is nothing to sample), or its integral
    /// overflows.
    pub fn new(table: &Table) -> Result<Self, TableError> {
        let dist = PiecewiseLinear1D::new(table.wavelengths(), table.values())?;
        Ok(Self { dist })
    }

    /// Maps `u` in `[0, 1)` to a wavelength and its pdf. `u = 0` gives the first
    /// wavelength of positive density, `u ≥ 1` is treated as the largest double below 1;
    /// the wavelength never lies where the spectrum is zero. (A NaN `u` is a broken
    /// generator: debug builds stop on it, release builds treat it as 0.)
    pub fn sample(&self, u: f64) -> WavelengthSample {
        let s = self.dist.sample(u);
        WavelengthSample {
            nm: s.x,
            pdf: s.pdf,
        }
    }
    // ANCHOR_END: sampler

    /// The density at `nm`, per nm: `L(nm) / ∫L`, 0 outside the table (and for NaN).
    pub fn pdf(&self, nm: f64) -> f64 {
        self.dist.pdf(nm)
    }

    /// The CDF at `nm` (NaN for NaN).
    pub fn cdf(&self, nm: f64) -> f64 {
        self.dist.cdf(nm)
    }

    /// `∫L`, the integral of the table as given (nm times its unit).
    pub fn integral(&self) -> f64 {
        self.dist.integral()
    }
}

// ANCHOR: estimate
/// One-sample estimate of the XYZ of `spectrum` from the wavelength `nm` drawn with
/// density `pdf`: `L(λ) (x̄, ȳ, z̄)(λ) / (p(λ) ∫ȳ)`. Unbiased whenever `p > 0` wherever
/// `L (x̄ + ȳ + z̄) > 0`; with `p` from the lamp's own [`EmissionSampler`], `L / p` is the
/// constant `∫L` and only the colour-matching functions vary.
pub fn xyz_estimate(spectrum: &Table, nm: f64, pdf: f64) -> DVec3 {
    spectrum.eval(nm) / pdf * cie::cmf(nm) / cie::y_integral()
}
// ANCHOR_END: estimate

// ANCHOR: product
/// A proposal for the lamp's *colour* rather than its power: the table of
/// `L(λ) (x̄ + ȳ + z̄)(λ)` at every whole nanometre of 380-830 nm, linear in between.
/// It is positive wherever the integrands `L x̄`, `L ȳ`, `L z̄` are (between two knots
/// where it is zero, all three integrands are zero too, as the lamp tables' knots fall on
/// these), so [`xyz_estimate`] stays unbiased with it.
pub fn colour_proposal(spectrum: &Table) -> Table {
    let nm = image_wavelengths();
    let values = nm
        .iter()
        .map(|&l| spectrum.eval(l) * cie::cmf(l).element_sum())
        .collect();
    Table::new(nm, values).unwrap_or_else(|e| panic!("products of valid tables: {e}"))
}
// ANCHOR_END: product

/// A proposal for the lamp's full colour: the table of
/// `L(λ) (x̄/X + ȳ/Y + z̄/Z)(λ)` at every whole nanometre of 380-830 nm, linear in between,
/// with `X, Y, Z = ∫L x̄, ∫L ȳ, ∫L z̄`: the equal mixture of the three channels' own proposals
/// `L x̄ / X`, `L ȳ / Y`, `L z̄ / Z`, so that no channel is starved. Positive wherever
/// [`colour_proposal`] is, so [`xyz_estimate`] stays unbiased with it. (Not yet in the
/// chapter's gain table.)
pub fn balanced_proposal(spectrum: &Table) -> Table {
    let c = cie::xyz(|l| spectrum.eval(l));
    let nm = image_wavelengths();
    let values = nm
        .iter()
        .map(|&l| (spectrum.eval(l) * cie::cmf(l) / c).element_sum())
        .collect();
    Table::new(nm, values).unwrap_or_else(|e| panic!("products of valid tables: {e}"))
}

/// The uniform proposal the gains are measured against: `λ = 380 + 450 u` nm, pdf
/// `1/450` per nm, over the image range.
pub fn uniform_wavelength(u: f64) -> WavelengthSample {
    let width = IMAGE_LAST_NM - IMAGE_FIRST_NM;
    WavelengthSample {
        nm: IMAGE_FIRST_NM + width * u,
        pdf: 1.0 / width,
    }
}

// ---------------------------------------------------------------------------------------
// The image format.

/// The wavelength of the first pixel column, nm.
pub const IMAGE_FIRST_NM: f64 = 380.0;
/// The wavelength of the last pixel column, nm.
pub(crate) const IMAGE_LAST_NM: f64 = 830.0;
/// Columns of a spectrum image: one per whole nanometre, 380..=830.
pub const IMAGE_WIDTH: u32 = 451;
/// Height of the images [`write_image`] draws (the source's drawings are 256 tall).
pub const IMAGE_HEIGHT: u32 = 256;
/// The tallest spectrum image [`parse_image`] reads (16x the source's drawings).
pub const IMAGE_MAX_HEIGHT: u32 = 4096;
/// What decoding one image may allocate: a 451 x 4096 image decodes to at most 7.4 MB
/// (RGBA, 8 bits a channel: 16-bit channels are cut to 8).
const IMAGE_MAX_BYTES: usize = 32 << 20;
/// A pixel is dark when its luma (0-255, the sRGB weights of
/// [`png::decode_png_luma`]) is below this.
pub const DARK_BELOW: u8 = 128;

/// The wavelengths of the image columns: 380, 381, ..., 830 nm.
pub fn image_wavelengths() -> Vec<f64> {
    (0..IMAGE_WIDTH)
        .map(|c| IMAGE_FIRST_NM + f64::from(c))
        .collect()
}

// ANCHOR: parse_image
/// Reads a hand-drawn spectrum: a PNG (grey or colour, at most [`IMAGE_MAX_HEIGHT`] pixels tall), 451 pixel columns
/// for 380, 381, ..., 830 nm. The value at column `c`'s wavelength `380 + c` is the share
/// of the column's pixels that are dark (luma below [`DARK_BELOW`]); where the dark
/// pixels are in the column does not matter. Between columns the spectrum is linear.
/// `file` names the image in errors.
///
/// # Errors
/// A [`DataError`] on line 0 naming the file and the problem: the bytes are not a
/// decodable image, the width is not 451 (with the width found), the height is above
/// [`IMAGE_MAX_HEIGHT`] (judged from the header, before decoding), or no column has a
/// dark pixel (an empty curve has no distribution).
pub fn parse_image(bytes: &[u8], file: &str) -> Result<Table, DataError> {
    let err = |problem: String| DataError::new(file, 0, problem);
    let undecodable = |e: ImageError| err(format!("cannot decode the image: {e}"));
    // The header's size is judged before a pixel is decoded: a few hundred bytes can
    // declare an image of gigabytes.
    let (width, height) = png::png_size(bytes).map_err(undecodable)?;
    if width != IMAGE_WIDTH {
        return Err(err(format!(
            "the image is {width} pixels wide; it must be {IMAGE_WIDTH}, one column per \
             whole nanometre from 380 to 830 nm inclusive{}",
            if width == 450 {
                " (450 columns leave one wavelength out)"
            } else {
                ""
            }
        )));
    }
    if height > IMAGE_MAX_HEIGHT {
        return Err(err(format!(
            "the image is {height} pixels tall; at most {IMAGE_MAX_HEIGHT} are read (a \
             column's value is a share of its pixels: {IMAGE_MAX_HEIGHT} already resolve \
             {:.1e} of the peak)",
            1.0 / f64::from(IMAGE_MAX_HEIGHT)
        )));
    }
    let img = png::decode_png_luma(bytes, IMAGE_MAX_BYTES).map_err(undecodable)?;
    let values: Vec<f64> = (0..width)
        .map(|x| {
            let dark = (0..height)
                .filter(|&y| img.luma[(y * width + x) as usize] < DARK_BELOW)
                .count();
            dark as f64 / f64::from(height)
        })
        .collect();
    if values.iter().all(|&v| v == 0.0) {
        return Err(err(format!(
            "the curve is empty: no pixel of the {width} x {height} image is dark \
             (luma below {DARK_BELOW}), so there is no spectrum to sample"
        )));
    }
    Table::new(image_wavelengths(), values).map_err(err)
}
// ANCHOR_END: parse_image

/// Reads the spectrum image at `path` (see [`parse_image`]).
///
/// # Errors
/// If the file cannot be read (line 0), or as [`parse_image`].
pub fn load_image(path: &Path) -> Result<Table, DataError> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path)
        .map_err(|e| DataError::new(&name, 0, format!("cannot read the file: {e}")))?;
    parse_image(&bytes, &name)
}

// ANCHOR: write_image
/// Draws `table` as a spectrum image `height` pixels tall (grey PNG): column `c` holds
/// `round(height L(380 + c) / max L)` black pixels from the bottom up, the rest white.
/// [`parse_image`] reads it back to `L / max L` within `1 / (2 height)` per column.
///
/// # Errors
/// If `height` is 0, the table is zero at every whole nanometre of 380-830 nm, or the PNG
/// encoder fails ([`ImageError::Encode`]).
pub fn write_image(table: &Table, height: u32) -> Result<Vec<u8>, ImageError> {
    if height == 0 {
        return Err(ImageError::Encode(
            "an image needs a height of at least 1 pixel".into(),
        ));
    }
    let values: Vec<f64> = image_wavelengths().iter().map(|&l| table.eval(l)).collect();
    let max = values.iter().copied().fold(0.0, f64::max);
    if max <= 0.0 {
        return Err(ImageError::Encode(
            "the spectrum is zero at every whole nanometre of 380-830 nm".into(),
        ));
    }
    let h = f64::from(height);
    let mut grey = vec![255u8; (IMAGE_WIDTH * height) as usize];
    for (x, v) in (0..IMAGE_WIDTH).zip(&values) {
        // v / max is in [0, 1], so the count is in 0..=height.
        let dark = (h * v / max).round() as u32;
        for y in height - dark..height {
            grey[(y * IMAGE_WIDTH + x) as usize] = 0;
        }
    }
    png::encode_grey_png(IMAGE_WIDTH, height, &grey)
}
// ANCHOR_END: write_image

/// Writes `<stem>.png` for every lamp of [`lamps`] into `dir` (the shipped `data/`
/// drawings are made by this; `tests/book/spectral/emission/image_format.rs` regenerates them
/// when the environment
/// variable `RAYLEMMA_WRITE_DATA` is set), all together or none ([`crate::output::FileSet`]).
/// Returns the paths written.
///
/// # Errors
/// If an image cannot be drawn or written; the earlier drawings are then left as they were.
pub fn write_lamp_images(dir: &Path) -> Result<Vec<PathBuf>, ImageError> {
    let mut files = crate::output::FileSet::new();
    for lamp in lamps() {
        let bytes = write_image(&lamp.spectrum, IMAGE_HEIGHT).map_err(|e| e.about(lamp.name))?;
        let path = dir.join(format!("{}.png", lamp.stem));
        files.write(&path, &bytes)?;
    }
    Ok(files.commit()?)
}

/// The XYZ of a lamp, normalised to `Y = 1`.
pub fn xyz_unit(t: &Table) -> DVec3 {
    let xyz = cie::xyz(|nm| t.eval(nm));
    xyz / xyz.y
}

// ANCHOR: display
/// A display colour for a swatch: linear sRGB of the lamp at `Y = 1`, negative
/// components clipped to 0 (out of gamut), scaled so that the largest component is 1,
/// then encoded with the exact sRGB transfer function ([`display::srgb8`], chapter *From
/// spectrum to display*).
pub fn swatch_rgb8(t: &Table) -> [u8; 3] {
    let rgb = cie::xyz_to_linear_srgb(xyz_unit(t)).max(DVec3::ZERO);
    let rgb = rgb / rgb.max_element();
    [
        display::srgb8(rgb.x),
        display::srgb8(rgb.y),
        display::srgb8(rgb.z),
    ]
}
// ANCHOR_END: display
