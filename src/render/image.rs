//! A rendered image: per-pixel means and the variance of each mean, in linear sRGB
//! ([`Welford`] accumulates them), and its two image files: OpenEXR with the variances
//! (written and read back) and the display PNG. The sidecar, and the writing of a render's
//! three files as one set, are in [`super::files`]. Chapter: *The reference renderer*
//! (`chapters/renderer/renderer.md`).
//!
//! # The EXR layout
//!
//! One part, float32, scan lines from the top, channels `R`, `G`, `B` (the pixel means,
//! linear sRGB primaries and D65 white, from CIE XYZ with a constant spectrum 1 at `Y = 1`)
//! and `var.R`, `var.G`, `var.B`: the variance **of the mean** of each pixel (the squared
//! standard error), `s^2 / n` from the `n` samples' sample variance `s^2`. Another renderer
//! writes the same six channels to be compared by `raylemma compare`.

use std::io::{Seek, Write};
use std::path::Path;

use exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image as ExrImage, Layer, LayerAttributes,
    SmallVec, WritableImage,
};
use glam::DVec3;

use crate::output::{self, FileError};
use crate::spectral::display;

/// The channel names of an image file, in the order of [`Image::mean`] then
/// [`Image::var`].
pub const CHANNELS: [&str; 6] = ["R", "G", "B", "var.R", "var.G", "var.B"];

/// Per-pixel means and variances of the means, row-major from the top-left pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The mean of each pixel, linear sRGB.
    pub mean: Vec<DVec3>,
    /// The variance of each pixel's mean (NaN where it is unknown: one sample).
    pub var: Vec<DVec3>,
}

/// The accumulator of a pixel: the project's one Welford recurrence, on linear sRGB.
pub type Welford = crate::stats::welford::Welford<DVec3>;

impl Image {
    /// The pixel index of `(x, y)`.
    pub fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    // ANCHOR: write_exr
    /// Encodes the six channels ([`CHANNELS`]) as float32 OpenEXR (ZIP compressed) into
    /// `out`.
    ///
    /// # Errors
    /// The encoder's or the writer's error, in words.
    pub fn encode_exr(&self, out: impl Write + Seek) -> Result<(), String> {
        let channel = |k: usize| -> Vec<f32> {
            let src = if k < 3 { &self.mean } else { &self.var };
            src.iter().map(|v| v[k % 3] as f32).collect()
        };
        let list: SmallVec<[AnyChannel<FlatSamples>; 4]> = CHANNELS
            .iter()
            .enumerate()
            .map(|(k, name)| AnyChannel::new(*name, FlatSamples::F32(channel(k))))
            .collect();
        let layer = Layer::new(
            (self.width as usize, self.height as usize),
            LayerAttributes::default(),
            Encoding::SMALL_LOSSLESS,
            AnyChannels::sort(list),
        );
        ExrImage::from_layer(layer)
            .write()
            .to_unbuffered(out)
            .map_err(|e| format!("OpenEXR: {e}"))
    }

    /// Writes the image as OpenEXR ([`Image::encode_exr`]) to `path`, atomically
    /// ([`output::write_file_with`]: a temporary file beside it, renamed over it).
    ///
    /// # Errors
    /// A [`FileError`] naming `path` when the file cannot be written.
    pub fn write_exr(&self, path: &Path) -> Result<(), FileError> {
        output::write_file_with(path, |f| self.encode_exr(f))
    }
    // ANCHOR_END: write_exr

    /// Reads an EXR written by [`Image::write_exr`] (or by another renderer with the same
    /// channels: `R`, `G`, `B`, and `var.R`, `var.G`, `var.B`; any sample type).
    ///
    /// # Errors
    /// A [`FileError`] naming `path`: not readable, not an EXR, or a channel missing
    /// (the message lists the channels there are).
    pub fn read_exr(path: &Path) -> Result<Image, FileError> {
        let err = |problem: String| FileError::new(path, problem);
        if !path.is_file() {
            return Err(err("no such file".into()));
        }
        let image = exr::prelude::read_first_flat_layer_from_file(path)
            .map_err(|e| err(format!("not a readable OpenEXR file: {e}")))?;
        let layer = &image.layer_data;
        let (w, h) = (layer.size.0, layer.size.1);
        let names: Vec<String> = layer
            .channel_data
            .list
            .iter()
            .map(|c| c.name.to_string())
            .collect();
        let mut data: Vec<Vec<f64>> = Vec::new();
        for name in CHANNELS {
            let Some(c) = layer
                .channel_data
                .list
                .iter()
                .find(|c| c.name.to_string() == name)
            else {
                return Err(err(format!(
                    "no channel {name:?}; the file has {} (a raylemma image has R, G, B, var.R, var.G, var.B)",
                    names.join(", ")
                )));
            };
            data.push(c.sample_data.values_as_f32().map(f64::from).collect());
        }
        let pixel = |k: usize| -> Vec<DVec3> {
            (0..w * h)
                .map(|i| DVec3::new(data[k][i], data[k + 1][i], data[k + 2][i]))
                .collect()
        };
        Ok(Image {
            width: u32::try_from(w).map_err(|_| err("too wide".into()))?,
            height: u32::try_from(h).map_err(|_| err("too tall".into()))?,
            mean: pixel(0),
            var: pixel(3),
        })
    }

    /// The means as the bytes of an 8-bit sRGB PNG, through the display chapter's rules
    /// (exposure `2^stops`, fit to gamut, the sRGB curve).
    ///
    /// # Errors
    /// As [`display::encode_png`].
    pub fn encode_png(&self, stops: f64) -> Result<Vec<u8>, String> {
        display::encode_png(
            self.width,
            self.height,
            &display::to_display_rgb8(&self.mean, stops),
        )
    }

    /// Writes the means as an 8-bit sRGB PNG ([`Image::encode_png`]), atomically.
    ///
    /// # Errors
    /// As [`display::write_png`].
    pub fn write_png(&self, path: &Path, stops: f64) -> Result<(), FileError> {
        display::write_png(
            path,
            self.width,
            self.height,
            &display::to_display_rgb8(&self.mean, stops),
        )
    }
}
