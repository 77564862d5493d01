//! An image's OpenEXR file: [`Image::encode_exr`] and [`Image::write_exr`] write the means
//! and the variances of the means, [`ExrContents::read`] reads them back, or any renderer's
//! plain EXR. Chapters: *The path tracer* (`chapters/renderer/path-tracer.md`, *What a
//! render writes*) and *Comparing images* (`chapters/renderer/compare.md`). The display PNG
//! beside it is written by the renderer (`crate::render::files`), through [`super::png`].
//!
//! # The EXR layout
//!
//! One part, float32, scan lines from the top, channels `R`, `G`, `B` (the pixel means,
//! linear sRGB primaries and D65 white, from CIE XYZ with a constant spectrum 1 at `Y = 1`)
//! and `var.R`, `var.G`, `var.B`: the variance **of the mean** of each pixel (the squared
//! standard error), `s^2 / n` from the `n` samples' sample variance `s^2`; and the header
//! attribute `spp` (an `int`), the `n` behind every mean, from which `compare` knows the
//! degrees of freedom of the variances, `n - 1`.
//!
//! # What `compare` reads
//!
//! [`ExrContents::read`] reads any single-part scan-line or tiled OpenEXR file with channels
//! `R`, `G`, `B` in any order, half or float (other channels are ignored; lacking `R`, `G`,
//! `B`, the channels `X`, `Y`, `Z` are read as CIE XYZ, marked [`ExrContents::from_xyz`],
//! for the caller to convert to linear sRGB with the colour chapter's matrix), with or without
//! the three variance channels and the `spp` attribute: the plain images that Mitsuba,
//! pbrt or a student's renderer write. It refuses, naming the file and the pixel, what no
//! comparison can use: a file that is not OpenEXR (a PNG is named as one), a truncated
//! file, a NaN or infinite mean, a NaN, infinite or negative variance, and variance
//! channels `var.R`, `var.G`, `var.B` beside X, Y, Z means (ambiguous: variances of X, Y,
//! Z could not be carried to sRGB without their covariances).

use std::io::{Read as _, Seek, Write};
use std::path::Path;

use exr::meta::attribute::AttributeValue;
use exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image as ExrImage, Layer, LayerAttributes,
    ReadChannels as _, ReadLayers as _, SmallVec, Text, WritableImage,
};
use glam::DVec3;

use super::{Image, ImageError};
use crate::output::{self, FileError};

/// The channel names of an image file, in the order of [`Image::mean`] then
/// [`Image::var`].
pub const CHANNELS: [&str; 6] = ["R", "G", "B", "var.R", "var.G", "var.B"];

/// The name of the header attribute that holds the samples per pixel (an `int`).
pub(crate) const SPP_ATTRIBUTE: &str = "spp";

/// The first bytes of every OpenEXR file (the magic number 20000630, little-endian).
const EXR_MAGIC: [u8; 4] = [0x76, 0x2f, 0x31, 0x01];

/// The first bytes of a PNG file.
const PNG_MAGIC: [u8; 4] = [0x89, b'P', b'N', b'G'];

impl Image {
    // ANCHOR: write_exr
    /// Encodes the six channels ([`CHANNELS`]) as float32 OpenEXR (ZIP compressed) into
    /// `out`, with the samples per pixel as the header attribute `spp` when known.
    ///
    /// # Errors
    /// The encoder's or the writer's error ([`ImageError::Encode`]).
    pub fn encode_exr(&self, out: impl Write + Seek) -> Result<(), ImageError> {
        let channel = |k: usize| -> Vec<f32> {
            let src = if k < 3 { &self.mean } else { &self.var };
            src.iter().map(|v| v[k % 3] as f32).collect()
        };
        let list: SmallVec<[AnyChannel<FlatSamples>; 4]> = CHANNELS
            .iter()
            .enumerate()
            .map(|(k, name)| AnyChannel::new(*name, FlatSamples::F32(channel(k))))
            .collect();
        let mut attributes = LayerAttributes::default();
        if let Some(spp) = self.spp.and_then(|n| i32::try_from(n).ok()) {
            attributes
                .other
                .insert(Text::from(SPP_ATTRIBUTE), AttributeValue::I32(spp));
        }
        let layer = Layer::new(
            (self.width as usize, self.height as usize),
            attributes,
            Encoding::SMALL_LOSSLESS,
            AnyChannels::sort(list),
        );
        ExrImage::from_layer(layer)
            .write()
            .to_unbuffered(out)
            .map_err(|e| ImageError::Encode(format!("OpenEXR: {e}")))
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
    /// channels: `R`, `G`, `B`, and `var.R`, `var.G`, `var.B`; any order, half or float),
    /// as [`ExrContents::read`] does, and requires the variance channels.
    ///
    /// # Errors
    /// As [`ExrContents::read`], and a [`FileError`] naming `path` when a variance channel
    /// is missing (the message lists the channels there are).
    pub fn read_exr(path: &Path) -> Result<Image, FileError> {
        let contents = ExrContents::read(path)?;
        let channels = contents.channels.join(", ");
        contents.into_image().ok_or_else(|| {
            FileError::new(
                path,
                format!(
                    "no channel \"var.R\"; the file has {channels} (a raylemma image has R, G, B, var.R, var.G, var.B)"
                ),
            )
        })
    }
}

/// What an OpenEXR file holds, as `compare` reads it: the means, the variances of the means
/// if the file has them, and the samples per pixel if its header says.
#[derive(Clone, Debug, PartialEq)]
pub struct ExrContents {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `R`, `G`, `B` of each pixel, row-major from the top-left pixel; `X`, `Y`, `Z` when
    /// [`ExrContents::from_xyz`] (until [`ExrContents::converted`]).
    pub mean: Vec<DVec3>,
    /// `var.R`, `var.G`, `var.B`, when the file has all three.
    pub var: Option<Vec<DVec3>>,
    /// The header attribute `spp`, when present.
    pub spp: Option<u32>,
    /// Every channel's name, in the file's order (for messages).
    pub channels: Vec<String>,
    /// Whether the means are stored as half floats (11 significant bits): their rounding
    /// is then part of their error (the comparison adds it).
    pub half: bool,
    /// Whether the means were read from channels `X`, `Y`, `Z` (CIE XYZ, as Mitsuba's
    /// spectral films write), for lack of `R`, `G`, `B`: [`ExrContents::converted`] makes
    /// them linear sRGB.
    pub from_xyz: bool,
}

impl ExrContents {
    /// Reads the first layer of the OpenEXR file `path` (see the module's documentation):
    /// channels `R`, `G`, `B` by name in any order, half or float; `var.R`, `var.G`,
    /// `var.B` if all three are there; the `spp` attribute if it is a positive integer.
    ///
    /// # Errors
    /// A [`FileError`] naming `path`: missing, not OpenEXR (a PNG is called one), truncated
    /// or otherwise unreadable, no `R`, `G` or `B` channel (the message lists the
    /// channels), a channel of integers, only some of the variance channels, variance
    /// channels beside X, Y, Z means, a mean that is NaN or infinite or a variance that is
    /// NaN, infinite or negative (the first such pixel, its channel and value).
    pub fn read(path: &Path) -> Result<ExrContents, FileError> {
        let err = |problem: String| FileError::new(path, problem);
        if !path.is_file() {
            return Err(err("no such file".into()));
        }
        let mut magic = [0u8; 4];
        let read = std::fs::File::open(path)
            .and_then(|mut f| f.read(&mut magic))
            .map_err(|e| err(format!("cannot read the file: {e}")))?;
        if read < 4 || magic != EXR_MAGIC {
            let what = if magic == PNG_MAGIC {
                "a PNG image, not an OpenEXR file: compare needs linear floating-point pixels (an .exr, as `raylemma render` or any renderer writes)"
            } else {
                "not an OpenEXR file (it does not start with the OpenEXR magic number)"
            };
            return Err(err(what.into()));
        }
        // The header's claimed sizes, checked against the file before the reader allocates.
        super::exr_header::check_file(path).map_err(|e| match e {
            ImageError::File(e) => e,
            e => err(e.to_string()),
        })?;
        let image = exr::prelude::read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .first_valid_layer()
            .all_attributes()
            .pedantic()
            .from_file(path)
            .map_err(|e| {
                err(format!(
                    "not a readable OpenEXR file (truncated or damaged?): {e}"
                ))
            })?;
        let layer = &image.layer_data;
        let (w, h) = (layer.size.0, layer.size.1);
        let width = u32::try_from(w).map_err(|_| err("too wide".into()))?;
        let height = u32::try_from(h).map_err(|_| err("too tall".into()))?;
        let list = &layer.channel_data.list;
        let channels: Vec<String> = list.iter().map(|c| c.name.to_string()).collect();
        let find = |name: &str| -> Result<Option<Vec<f64>>, FileError> {
            let Some(c) = list.iter().find(|c| c.name.to_string() == name) else {
                return Ok(None);
            };
            if let FlatSamples::U32(_) = c.sample_data {
                return Err(err(format!(
                    "channel {name} holds unsigned integers, not colours (half or float needed)"
                )));
            }
            Ok(Some(c.sample_data.values_as_f32().map(f64::from).collect()))
        };
        let has = |name: &str| list.iter().any(|c| c.name.to_string() == name);
        let from_xyz =
            !CHANNELS[..3].iter().all(|n| has(n)) && ["X", "Y", "Z"].iter().all(|n| has(n));
        let names: [&str; 3] = if from_xyz {
            ["X", "Y", "Z"]
        } else {
            ["R", "G", "B"]
        };
        let half = list.iter().any(|c| {
            names.contains(&c.name.to_string().as_str())
                && matches!(c.sample_data, FlatSamples::F16(_))
        });
        let mut rgb = Vec::new();
        for name in names {
            match find(name)? {
                Some(values) => rgb.push(values),
                None => {
                    return Err(err(format!(
                        "no channel {name:?}; the file has {} (compare needs R, G, B: linear sRGB, or X, Y, Z: CIE XYZ)",
                        channels.join(", ")
                    )));
                }
            }
        }
        let mut var = Vec::new();
        for name in &CHANNELS[3..] {
            if let Some(values) = find(name)? {
                var.push(values);
            }
        }
        if !var.is_empty() && var.len() < 3 {
            return Err(err(format!(
                "only some of the variance channels var.R, var.G, var.B: the file has {}",
                channels.join(", ")
            )));
        }
        if from_xyz && !var.is_empty() {
            // Ambiguous: the variances of X, Y and Z could not be carried to sRGB without
            // their covariances (strongly correlated in a render), which no file carries,
            // and variances of R, G, B would not be of these means. No renderer known here
            // writes such a file, so it is refused wherever it is given.
            return Err(err(format!(
                "the means are X, Y, Z but the variance channels are var.R, var.G, var.B: the file does not say whether they are variances of X, Y, Z (which cannot be carried to sRGB without their covariances) or of R, G, B; it has {} (write R, G, B with var.R, var.G, var.B, or X, Y, Z without variance channels and compare several such files)",
                channels.join(", ")
            )));
        }
        let pixels = |d: &[Vec<f64>]| -> Vec<DVec3> {
            (0..w * h)
                .map(|i| DVec3::new(d[0][i], d[1][i], d[2][i]))
                .collect()
        };
        let contents = ExrContents {
            width,
            height,
            mean: pixels(&rgb),
            var: (!var.is_empty()).then(|| pixels(&var)),
            spp: spp_attribute(&image.attributes.other)
                .or_else(|| spp_attribute(&layer.attributes.other)),
            channels,
            half,
            from_xyz,
        };
        contents.check().map_err(|e| err(e.to_string()))?;
        Ok(contents)
    }

    /// The first pixel whose mean is not finite or whose variance is not a finite number
    /// `>= 0` ([`ImageError::Pixels`]).
    fn check(&self) -> Result<(), ImageError> {
        let at = |i: usize| (i as u32 % self.width.max(1), i as u32 / self.width.max(1));
        for (i, m) in self.mean.iter().enumerate() {
            if let Some(c) = (0..3).find(|&c| !m[c].is_finite()) {
                let (x, y) = at(i);
                return Err(ImageError::Pixels(format!(
                    "pixel ({x}, {y}) channel {} is {}, not a finite number",
                    CHANNELS[c], m[c]
                )));
            }
        }
        for (i, v) in self.var.iter().flatten().enumerate() {
            if let Some(c) = (0..3).find(|&c| !(v[c].is_finite() && v[c] >= 0.0)) {
                let (x, y) = at(i);
                let why = if v[c].is_nan() {
                    " (a render with one sample per pixel has no variance: it needs at least 2 samples per pixel)"
                } else {
                    ""
                };
                return Err(ImageError::Pixels(format!(
                    "pixel ({x}, {y}) channel {} is {}: a variance must be a finite number >= 0{why}",
                    CHANNELS[c + 3],
                    v[c]
                )));
            }
        }
        Ok(())
    }

    /// The contents with means read from `X`, `Y`, `Z` ([`ExrContents::from_xyz`]) turned
    /// into linear sRGB by `xyz_to_rgb` (the colour chapter's
    /// `spectral::cie::xyz_to_linear_srgb_matrix`); contents read from `R`, `G`, `B` are
    /// returned as they are. The flag stays, so a report can say what was converted.
    pub fn converted(mut self, xyz_to_rgb: glam::DMat3) -> ExrContents {
        if self.from_xyz {
            for v in &mut self.mean {
                *v = xyz_to_rgb * *v;
            }
        }
        self
    }

    /// The image, if the file has variance channels.
    pub fn into_image(self) -> Option<Image> {
        let var = self.var?;
        Some(Image {
            width: self.width,
            height: self.height,
            mean: self.mean,
            var,
            spp: self.spp,
        })
    }
}

/// The `spp` attribute among a header's custom attributes, if it is a positive integer
/// (an `int`, or a `float` or `double` with an integer value).
fn spp_attribute(other: &std::collections::HashMap<Text, AttributeValue>) -> Option<u32> {
    let value = match other.get(&Text::from(SPP_ATTRIBUTE))? {
        AttributeValue::I32(n) => f64::from(*n),
        AttributeValue::F32(x) => f64::from(*x),
        AttributeValue::F64(x) => *x,
        _ => return None,
    };
    (value >= 1.0 && value.fract() == 0.0 && value <= f64::from(u32::MAX)).then_some(value as u32)
}
