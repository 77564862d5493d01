//! The one error type of images: why an image could not be read, encoded, drawn or merged.
//! Chapters: *Comparing images* (`chapters/renderer/compare.md`) and *Bad input*
//! (`chapters/bad-input.md`).

use crate::output::FileError;

/// Why an image could not be read, encoded, drawn or merged: the one error type of the
/// images (OpenEXR headers and pixels, PNG, a render's sidecar). Each variant says what a
/// user needs: the file when one is known, and what is wrong with it.
#[derive(Clone, Debug, PartialEq)]
pub enum ImageError {
    /// A file that cannot be read or written, or whose contents are wrong: the file named.
    File(FileError),
    /// The sidecar (`SCENE.json`) beside a render to merge cannot be read.
    Sidecar(FileError),
    /// An OpenEXR header that is malformed, or claims more than its file can back
    /// ([`super::exr_header::check`]; the caller names the file).
    Header(String),
    /// A pixel whose mean is not finite or whose variance is not a finite number `>= 0`,
    /// or a buffer of pixels that does not fit the image's size.
    Pixels(String),
    /// The OpenEXR or PNG encoder failed, or there is nothing to draw.
    Encode(String),
    /// A PNG that cannot be decoded, or would take more memory than allowed (the
    /// decoder's message).
    Decode(String),
    /// Images that do not go together (a window outside its image, a reference of another
    /// size than its scene), renders that cannot be merged (different scenes, sizes,
    /// builds or seeds in common, or too few of them), or images that cannot be compared
    /// (of different sizes, a reference without its variance, a single plain candidate,
    /// candidates that are the same image).
    Mismatch(String),
    /// A parameter of a computation on images outside its range: a comparison's level
    /// `alpha` not in (0, 1), an estimate's degrees of freedom not `> 0`.
    Parameter(String),
}

impl ImageError {
    /// The same error, its message prefixed with `what: ` (a lamp's name, say); a file's
    /// error already names its file and is left as it is.
    pub fn about(self, what: &str) -> Self {
        let prefix = |m: String| format!("{what}: {m}");
        match self {
            ImageError::Header(m) => ImageError::Header(prefix(m)),
            ImageError::Pixels(m) => ImageError::Pixels(prefix(m)),
            ImageError::Encode(m) => ImageError::Encode(prefix(m)),
            ImageError::Decode(m) => ImageError::Decode(prefix(m)),
            ImageError::Mismatch(m) => ImageError::Mismatch(prefix(m)),
            ImageError::Parameter(m) => ImageError::Parameter(prefix(m)),
            e @ (ImageError::File(_) | ImageError::Sidecar(_)) => e,
        }
    }
}

impl std::fmt::Display for ImageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ImageError::File(e) => write!(f, "{e}"),
            ImageError::Sidecar(e) => write!(
                f,
                "{e} (a render to merge needs its sidecar, which `raylemma render` writes beside it)"
            ),
            ImageError::Header(m)
            | ImageError::Pixels(m)
            | ImageError::Encode(m)
            | ImageError::Decode(m)
            | ImageError::Mismatch(m)
            | ImageError::Parameter(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for ImageError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ImageError::File(e) | ImageError::Sidecar(e) => Some(e),
            _ => None,
        }
    }
}

impl From<FileError> for ImageError {
    fn from(e: FileError) -> Self {
        ImageError::File(e)
    }
}
