//! Images and their files, below everything that reads or writes one: the per-pixel
//! means and variances of a render ([`Image`], accumulated by [`Welford`]), the one error
//! type of images ([`ImageError`]), and the codecs: OpenEXR written and read back
//! ([`exr`]), an EXR header's claims checked before anything is allocated
//! ([`exr_header`]), PNG encoded and decoded ([`png`]). It takes nothing from the rest of
//! the library but the statistics' Welford recurrence and the one writer of files
//! ([`crate::output`]). Chapters: *The path tracer* (`chapters/renderer/path-tracer.md`,
//! *What a render writes*), *Comparing images* (`chapters/renderer/compare.md`), *From
//! spectrum to display* (`chapters/spectral/display.md`, the PNG) and *Bad input*
//! (`chapters/bad-input.md`, the EXR header).

use glam::DVec3;

mod error;
pub mod exr;
pub mod exr_header;
pub mod png;

pub use error::ImageError;
pub use exr::ExrContents;

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
    /// The samples per pixel behind every mean, when known (the EXR's `spp` attribute).
    pub spp: Option<u32>,
}

/// The accumulator of a pixel: the project's one Welford recurrence, on linear sRGB.
pub type Welford = crate::stats::welford::Welford<DVec3>;

impl Image {
    /// The pixel index of `(x, y)`.
    pub fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }
}
