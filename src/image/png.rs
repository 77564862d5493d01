//! PNG files: 8-bit sRGB or grey pixels encoded ([`encode_png`], [`write_png`],
//! [`encode_grey_png`]) and any PNG decoded to 8-bit luma within a memory limit
//! ([`png_size`], [`decode_png_luma`]). The codes come from the display chapter's pipeline
//! (`crate::spectral::display::to_display_rgb8`); the spectra drawn as images are decoded
//! here (`crate::spectral::emission::parse_image`). Chapter: *From spectrum to display*
//! (`chapters/spectral/display.md`, *Writing the PNG*).

use std::path::Path;

use super::ImageError;
use crate::output::{self, FileError};

// ANCHOR: write_png
/// Encodes `rgb8` (`3 w h` bytes, row-major, sRGB-encoded) as the bytes of a PNG file.
///
/// # Errors
/// A wrong buffer size, zero or too large dimensions ([`ImageError::Pixels`]), or a
/// failure of the encoder ([`ImageError::Encode`]).
pub fn encode_png(w: u32, h: u32, rgb8: &[u8]) -> Result<Vec<u8>, ImageError> {
    encode(w, h, png::ColorType::Rgb, rgb8)
}
/// Writes `rgb8` as a PNG at `path`. The image is encoded in memory, then written by the
/// project's one writer ([`crate::output::write_file`]): to a temporary file beside
/// `path`, renamed over it, so a failure never leaves a partial file where a good one was.
///
/// # Errors
/// A [`FileError`] naming `path`: wrong buffer size, zero or too large dimensions, or an
/// I/O failure (missing directory, no permission, `path` is a directory...).
pub fn write_png(path: &Path, w: u32, h: u32, rgb8: &[u8]) -> Result<(), FileError> {
    let bytes = encode_png(w, h, rgb8).map_err(|e| FileError::new(path, e.to_string()))?;
    output::write_file(path, &bytes)
}
// ANCHOR_END: write_png

/// Encodes `grey8` (`w h` bytes, row-major) as the bytes of a greyscale PNG file.
///
/// # Errors
/// As [`encode_png`].
pub fn encode_grey_png(w: u32, h: u32, grey8: &[u8]) -> Result<Vec<u8>, ImageError> {
    encode(w, h, png::ColorType::Grayscale, grey8)
}

/// The one PNG encoder: 8 bits per channel, the `png` crate's balanced compression and
/// adaptive filtering.
fn encode(w: u32, h: u32, color: png::ColorType, pixels: &[u8]) -> Result<Vec<u8>, ImageError> {
    let channels = color.samples() as u64;
    let expected = channels * u64::from(w) * u64::from(h);
    if w == 0 || h == 0 || pixels.len() as u64 != expected {
        return Err(ImageError::Pixels(format!(
            "{} bytes for a {w}x{h} image; it needs {channels} x {w} x {h} = {expected} (and w, h > 0)",
            pixels.len()
        )));
    }
    let failed = |e: png::EncodingError| ImageError::Encode(format!("cannot encode the PNG: {e}"));
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, w, h);
    encoder.set_color(color);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Balanced);
    encoder.set_filter(png::Filter::Adaptive);
    let mut writer = encoder.write_header().map_err(failed)?;
    writer.write_image_data(pixels).map_err(failed)?;
    writer.finish().map_err(failed)?;
    Ok(bytes)
}

fn decode_error(e: png::DecodingError) -> ImageError {
    ImageError::Decode(e.to_string())
}

/// A decoded PNG: its size and one 8-bit luma per pixel, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Luma8 {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width height` lumas, row-major from the top.
    pub luma: Vec<u8>,
}

/// The size a PNG's header declares, read before any pixel is decoded.
///
/// # Errors
/// [`ImageError::Decode`]: the bytes are not a PNG, or its header is malformed.
pub fn png_size(bytes: &[u8]) -> Result<(u32, u32), ImageError> {
    let reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .map_err(decode_error)?;
    Ok(reader.info().size())
}

/// Decodes a PNG of any colour type and bit depth into 8-bit luma, allocating at most
/// `max_bytes`: palettes and low bit depths are expanded, 16 bits cut to 8, alpha ignored,
/// and colour made luma as `(2126 R + 7152 G + 722 B) / 10000`, rounded down (the sRGB
/// primaries' luminance weights in 8-bit integers).
///
/// # Errors
/// [`ImageError::Decode`]: the bytes are not a decodable PNG, or decoding it would
/// allocate more than `max_bytes`.
pub fn decode_png_luma(bytes: &[u8], max_bytes: usize) -> Result<Luma8, ImageError> {
    let limits = png::Limits { bytes: max_bytes };
    let mut decoder = png::Decoder::new_with_limits(std::io::Cursor::new(bytes), limits);
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info().map_err(decode_error)?;
    let size = reader
        .output_buffer_size()
        .filter(|&n| n <= max_bytes)
        .ok_or_else(|| {
            ImageError::Decode(format!("the image would need more than {max_bytes} bytes"))
        })?;
    let mut buf = vec![0; size];
    let frame = reader.next_frame(&mut buf).map_err(decode_error)?;
    let pixels = &buf[..frame.buffer_size()];
    let luma = |p: &[u8]| {
        let [r, g, b] = [p[0], p[1], p[2]].map(u32::from);
        ((2126 * r + 7152 * g + 722 * b) / 10000) as u8
    };
    let luma: Vec<u8> = match frame.color_type {
        png::ColorType::Grayscale => pixels.to_vec(),
        png::ColorType::GrayscaleAlpha => pixels.chunks_exact(2).map(|p| p[0]).collect(),
        png::ColorType::Rgb => pixels.chunks_exact(3).map(luma).collect(),
        png::ColorType::Rgba => pixels.chunks_exact(4).map(luma).collect(),
        png::ColorType::Indexed => {
            return Err(ImageError::Decode(
                "a palette the decoder did not expand".into(),
            ));
        }
    };
    Ok(Luma8 {
        width: frame.width,
        height: frame.height,
        luma,
    })
}
