//! What an OpenEXR header claims, checked against the file before anything is allocated
//! (chapter *Bad input*). A header is a list of attributes whose words the file's author
//! chooses: a 600-byte file may claim 100000 x 100000 pixels, and a reader that believes it
//! allocates 40 GB before it finds that the pixels are not there. [`check`] reads only the
//! header's bytes, with its own bounds, and refuses a claim the file cannot back:
//!
//! - more than [`MAX_PIXELS`] pixels in a part;
//! - an offset table (8 bytes per chunk of scan lines or tiles) longer than the file;
//! - decoded pixels more than [`MAX_RATIO`] times the file's length (no OpenEXR
//!   compression packs more: deflate's limit is about 1032 to 1).
//!
//! The layout read (OpenEXR's file format, version 2): the magic number, a version word
//! whose bit 9 marks a single tiled part, bit 11 deep data and bit 12 several parts, then
//! each part's attributes (`name\0type\0`, a little-endian `i32` size, the value), the
//! header ending at an empty name.

use std::io::Read;
use std::path::Path;

use super::ImageError;

/// The most pixels a part of an image may claim (8192 x 8192).
pub const MAX_PIXELS: u64 = 1 << 26;
/// The most decoded bytes an image may claim per byte of its file.
pub const MAX_RATIO: u64 = 4096;
/// The most bytes a header may take (its attributes, before the offset table).
pub(crate) const MAX_HEADER: usize = 1 << 20;

/// The size of one part as its header states it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Part {
    pub width: u64,
    pub height: u64,
    /// Bytes of one pixel over all channels, decoded (2 for half, 4 for float or uint).
    pub pixel_bytes: u64,
    /// Chunks in the offset table (scan-line blocks or tiles of the largest level).
    pub chunks: u64,
}

/// Reads the header of the file `path` (at most [`MAX_HEADER`] bytes of it) and checks it
/// with [`check`].
///
/// # Errors
/// The reason ([`ImageError::Header`], or [`ImageError::File`] if the file cannot be
/// read), for a message that names the file.
pub(crate) fn check_file(path: &Path) -> Result<Vec<Part>, ImageError> {
    let cannot = |e: std::io::Error| {
        ImageError::File(crate::output::FileError::new(
            path,
            format!("cannot read the file: {e}"),
        ))
    };
    let file = std::fs::File::open(path).map_err(cannot)?;
    let len = file.metadata().map_err(cannot)?.len();
    let mut head = Vec::new();
    file.take(MAX_HEADER as u64)
        .read_to_end(&mut head)
        .map_err(cannot)?;
    check(&head, len)
}

/// Checks the header at the start of `head` (the first bytes of a file of `len` bytes):
/// every part's claimed size against [`MAX_PIXELS`], the file's length and [`MAX_RATIO`].
///
/// # Errors
/// What the header claims that the file cannot back, or where the header is malformed
/// ([`ImageError::Header`]).
pub fn check(head: &[u8], len: u64) -> Result<Vec<Part>, ImageError> {
    let mut r = Reader { head, at: 0 };
    if r.bytes(4)? != [0x76, 0x2f, 0x31, 0x01] {
        return Err(header(
            "not an OpenEXR file (it does not start with the OpenEXR magic number)",
        ));
    }
    let version = r.u32()?;
    if version & 0x800 != 0 {
        return Err(header(
            "deep data (bit 11 of the version): compare reads flat images only",
        ));
    }
    let (tiled_single, multipart) = (version & 0x200 != 0, version & 0x1000 != 0);
    let mut parts = Vec::new();
    loop {
        let part = r.part(tiled_single)?;
        parts.push(part);
        if !multipart || r.peek()? == 0 {
            break;
        }
    }
    let mut decoded = 0u64;
    let mut chunks = 0u64;
    for p in &parts {
        let pixels = p.width.saturating_mul(p.height);
        if pixels > MAX_PIXELS {
            return Err(header(format!(
                "the header claims {} x {} pixels, more than the {MAX_PIXELS} a part may have here",
                p.width, p.height
            )));
        }
        decoded = decoded.saturating_add(pixels.saturating_mul(p.pixel_bytes));
        chunks = chunks.saturating_add(p.chunks);
    }
    if chunks.saturating_mul(8) > len {
        return Err(header(format!(
            "the header claims {chunks} blocks of pixels, whose offsets alone need {} bytes, but the file has {len}: truncated or damaged",
            chunks.saturating_mul(8)
        )));
    }
    if decoded > len.saturating_mul(MAX_RATIO) {
        return Err(header(format!(
            "the header claims {decoded} bytes of pixels, more than {MAX_RATIO} times the file's {len} bytes that any OpenEXR compression could hold: truncated or damaged"
        )));
    }
    Ok(parts)
}

struct Reader<'a> {
    head: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn bytes(&mut self, n: usize) -> Result<&[u8], ImageError> {
        let end = self.at.checked_add(n).filter(|&e| e <= self.head.len());
        let Some(end) = end else {
            return Err(header(if self.head.len() >= MAX_HEADER {
                format!("the header is longer than {MAX_HEADER} bytes")
            } else {
                "the header ends before its last attribute: truncated".into()
            }));
        };
        let b = &self.head[self.at..end];
        self.at = end;
        Ok(b)
    }

    fn peek(&self) -> Result<u8, ImageError> {
        self.head
            .get(self.at)
            .copied()
            .ok_or_else(|| header("the header ends early: truncated"))
    }

    fn u32(&mut self) -> Result<u32, ImageError> {
        let b = self.bytes(4)?;
        Ok(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    }

    fn i32(&mut self) -> Result<i32, ImageError> {
        self.u32().map(|u| u as i32)
    }

    /// A null-terminated name of at most 255 bytes.
    fn name(&mut self) -> Result<String, ImageError> {
        let rest = &self.head[self.at.min(self.head.len())..];
        let Some(end) = rest.iter().take(256).position(|&b| b == 0) else {
            return Err(header(
                "an attribute name longer than 255 bytes, or a truncated header",
            ));
        };
        let name = String::from_utf8_lossy(&rest[..end]).into_owned();
        self.at += end + 1;
        Ok(name)
    }

    /// One part's header, up to and including its terminating empty name.
    fn part(&mut self, tiled_single: bool) -> Result<Part, ImageError> {
        let (mut window, mut pixel_bytes, mut compression, mut tiles, mut tiled) =
            (None, None, 0u8, None, tiled_single);
        loop {
            let name = self.name()?;
            if name.is_empty() {
                break;
            }
            let kind = self.name()?;
            let size = self.i32()?;
            let size = usize::try_from(size)
                .map_err(|_| header(format!("attribute {name:?} has a negative size")))?;
            let value = self.bytes(size)?;
            let int = |k: usize| {
                value
                    .get(4 * k..4 * k + 4)
                    .map(|b| i64::from(i32::from_le_bytes([b[0], b[1], b[2], b[3]])))
                    .ok_or_else(|| header(format!("attribute {name:?} is too short")))
            };
            match (name.as_str(), kind.as_str()) {
                ("dataWindow", "box2i") => {
                    let (x0, y0, x1, y1) = (int(0)?, int(1)?, int(2)?, int(3)?);
                    if x1 < x0 || y1 < y0 {
                        return Err(header(format!(
                            "the data window ({x0}, {y0})-({x1}, {y1}) is empty or inverted"
                        )));
                    }
                    window = Some(((x1 - x0 + 1) as u64, (y1 - y0 + 1) as u64));
                }
                ("channels", "chlist") => pixel_bytes = Some(channel_bytes(value)?),
                ("compression", "compression") => compression = value.first().copied().unwrap_or(0),
                ("tiles", "tiledesc") => {
                    tiles = Some((int(0)?.max(1) as u64, int(1)?.max(1) as u64))
                }
                ("type", "string") => tiled = value.starts_with(b"tiled"),
                _ => {}
            }
        }
        let (width, height) = window.ok_or_else(|| header("the header has no dataWindow"))?;
        let pixel_bytes = pixel_bytes.ok_or_else(|| header("the header has no channel list"))?;
        let chunks = match (tiled, tiles) {
            (true, Some((tx, ty))) => width.div_ceil(tx).saturating_mul(height.div_ceil(ty)),
            (true, None) => return Err(header("a tiled part without a tile description")),
            (false, _) => height.div_ceil(lines_per_chunk(compression)),
        };
        Ok(Part {
            width,
            height,
            pixel_bytes,
            chunks,
        })
    }
}

/// A malformed or unbacked header, in words.
fn header(problem: impl Into<String>) -> ImageError {
    ImageError::Header(problem.into())
}

/// Scan lines per chunk of each compression (OpenEXR's table).
fn lines_per_chunk(compression: u8) -> u64 {
    match compression {
        3 | 5 => 16,     // ZIP, PXR24
        4 | 6..=8 => 32, // PIZ, B44, B44A, DWAA
        9 => 256,        // DWAB
        _ => 1,          // none, RLE, ZIPS
    }
}

/// Decoded bytes of one pixel over the channels of a `chlist` value: per channel its name,
/// a pixel type (0 uint, 1 half, 2 float), 12 bytes of layout; an empty name ends it.
fn channel_bytes(list: &[u8]) -> Result<u64, ImageError> {
    let mut r = Reader { head: list, at: 0 };
    let mut bytes = 0u64;
    let mut count = 0;
    loop {
        let name = r.name()?;
        if name.is_empty() {
            return Ok(bytes);
        }
        count += 1;
        if count > 1024 {
            return Err(header("more than 1024 channels"));
        }
        bytes += match r.i32()? {
            1 => 2,
            0 | 2 => 4,
            t => {
                return Err(header(format!(
                    "channel {name:?} has the unknown pixel type {t}"
                )));
            }
        };
        r.bytes(12)?;
    }
}
