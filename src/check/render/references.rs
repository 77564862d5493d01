//! The canonical scenes against their committed reference images. Chapter: *Testing the
//! renderer* (`chapters/renderer/testing.md`).
//!
//! The reference images in `figures/reference/` are the product other renderers are
//! checked against; this check holds the renderer that made them to them. A window of each
//! canonical scene ([`CANONICAL`]) is rendered with a few samples per pixel and another
//! seed, and compared with the same window of the reference, whose own variance is added
//! to the test image's. A change to the path tracer that biases a canonical scene makes
//! the window's total, or one of its blocks, differ.

use std::path::Path;

use super::Rendered;
use super::pool::Expected;
use crate::check::Options;
use crate::data::DataError;
use crate::image::{Image, ImageError};
use crate::render::driver::Window;
use crate::render::format;
use crate::render::scene::Scene;

/// A canonical scene: the name of its reference files, its scene file under `scenes/`,
/// and the window the check renders.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Canonical {
    /// `figures/reference/NAME.exr`.
    pub name: &'static str,
    /// `scenes/FILE`.
    pub file: &'static str,
    /// The window of the image the check renders.
    pub window: Window,
    /// The side of its pooled blocks.
    pub block: u32,
}

const fn window(x: u32, y: u32, side: u32) -> Window {
    Window {
        x,
        y,
        width: side,
        height: side,
    }
}

/// The canonical scenes, with the window of each that the check renders: where the glass
/// and mirror meet the floor (`cornell`), the light and the ceiling beside it
/// (`cornell-diffuse`: a light that also emitted upwards would light the ceiling there),
/// a sphere's edge and shadow (the lamps), the centre of the dispersive sphere and of the
/// bubble, and the middle of each furnace.
pub const CANONICAL: [Canonical; 11] = [
    Canonical {
        name: "cornell",
        file: "cornell.toml",
        window: window(120, 140, 64),
        block: CAUSTIC_BLOCK,
    },
    Canonical {
        name: "cornell-diffuse",
        file: "cornell-diffuse.toml",
        window: window(96, 8, 64),
        block: BLOCK,
    },
    Canonical {
        name: "lamps-amber-led",
        file: "lamps/amber-led.toml",
        window: window(96, 136, 64),
        block: BLOCK,
    },
    Canonical {
        name: "lamps-incandescent",
        file: "lamps/incandescent.toml",
        window: window(96, 136, 64),
        block: BLOCK,
    },
    Canonical {
        name: "lamps-cool-white-fluorescent",
        file: "lamps/cool-white-fluorescent.toml",
        window: window(96, 136, 64),
        block: BLOCK,
    },
    Canonical {
        name: "lamps-low-pressure-sodium",
        file: "lamps/low-pressure-sodium.toml",
        window: window(96, 136, 64),
        block: BLOCK,
    },
    Canonical {
        name: "lamps-high-pressure-sodium",
        file: "lamps/high-pressure-sodium.toml",
        window: window(96, 136, 64),
        block: BLOCK,
    },
    Canonical {
        name: "dispersion",
        file: "dispersion.toml",
        window: window(96, 96, 64),
        block: BLOCK,
    },
    Canonical {
        name: "bubble",
        file: "bubble.toml",
        window: window(96, 96, 64),
        block: BLOCK,
    },
    Canonical {
        name: "furnace",
        file: "furnace.toml",
        window: window(32, 32, 64),
        block: BLOCK,
    },
    Canonical {
        name: "furnace-grey",
        file: "furnace-grey.toml",
        window: window(32, 32, 64),
        block: BLOCK,
    },
];

/// A renderer of a window of a scene: the pixels of `window` of the scene's image, at the
/// scene's settings.
pub(crate) type WindowRenderer<'a> = &'a (dyn Fn(&Scene, Window) -> Image + Sync);

/// raylemma's own renderer of a window ([`crate::render::render_window`]), silently.
pub fn ours_window(scene: &Scene, window: Window) -> Image {
    let wavelengths = &scene.settings.wavelengths;
    crate::render::render_window(
        scene,
        scene.settings.spp,
        window,
        crate::render::Progress::Silent,
        &|u| wavelengths.sample(u),
    )
}

/// The seed of the windows (not the references').
pub const SEED: u64 = 0x7e57;

/// The side of the pooled blocks of most windows: 16 pixels. Caustics and lights seen
/// through glass are rare bright paths, and a block's total is normal only once it holds
/// enough of them: with 8 x 8 blocks at a few dozen samples per pixel the `cornell` window
/// raises false alarms, and even 16 x 16 ones do there (the calibration of the chapter),
/// so `cornell`'s blocks are 32 x 32 ([`CAUSTIC_BLOCK`]).
pub const BLOCK: u32 = 16;

/// The side of the blocks of `cornell`'s window, whose caustics need more samples a block.
pub const CAUSTIC_BLOCK: u32 = 32;

/// The window of `image` (the whole image's pixels `window`).
///
/// # Errors
/// If the window does not lie inside the image ([`ImageError::Mismatch`]).
pub fn crop(image: &Image, window: Window) -> Result<Image, ImageError> {
    if window.x + window.width > image.width || window.y + window.height > image.height {
        return Err(ImageError::Mismatch(format!(
            "the window {}x{} at ({}, {}) is outside the {}x{} image",
            window.width, window.height, window.x, window.y, image.width, image.height
        )));
    }
    let mut out = Image {
        width: window.width,
        height: window.height,
        mean: Vec::with_capacity((window.width * window.height) as usize),
        var: Vec::with_capacity((window.width * window.height) as usize),
        spp: image.spp,
    };
    for y in window.y..window.y + window.height {
        for x in window.x..window.x + window.width {
            let i = image.index(x, y);
            out.mean.push(image.mean[i]);
            out.var.push(image.var[i]);
        }
    }
    Ok(out)
}

/// Every canonical scene's window, rendered by `renderer` at `options.cases` samples per
/// pixel (default 32) with seed `options.seed` (default [`SEED`]), each with the window of
/// its reference under `root/figures/reference/` as the expectation.
///
/// # Errors
/// A scene file ([`ReferenceError::Scene`]) or reference image
/// ([`ReferenceError::Image`]) that cannot be read, named with the problem (the references
/// are regenerated by `cargo run --release -- references`).
pub fn render_references(
    renderer: WindowRenderer,
    root: &Path,
    options: &Options,
) -> Result<Vec<Rendered>, ReferenceError> {
    let spp = options.cases_or(32) as u32;
    let seed = options.seed_or(SEED);
    CANONICAL
        .iter()
        .map(|c| {
            let mut scene = format::load(&root.join("scenes").join(c.file))?;
            scene.settings.spp = spp;
            scene.settings.seed = seed;
            let path = root
                .join("figures")
                .join("reference")
                .join(format!("{}.exr", c.name));
            let reference = Image::read_exr(&path).map_err(ImageError::File)?;
            if (reference.width, reference.height) != (scene.camera.width, scene.camera.height) {
                return Err(ImageError::Mismatch(format!(
                    "{}: {}x{}, but the scene renders {}x{}",
                    path.display(),
                    reference.width,
                    reference.height,
                    scene.camera.width,
                    scene.camera.height
                ))
                .into());
            }
            let reference = crop(&reference, c.window)?;
            Ok(Rendered {
                name: c.name.to_string(),
                image: renderer(&scene, c.window),
                expected: Expected::render(&reference, |_, _| true),
                block: c.block,
            })
        })
        .collect()
}

/// Why the canonical scenes cannot be checked against their references: a scene file that
/// cannot be loaded, or a reference image that cannot be read or does not fit its scene.
#[derive(Clone, Debug, PartialEq)]
pub enum ReferenceError {
    /// The scene file's problem.
    Scene(DataError),
    /// The reference image's problem.
    Image(ImageError),
}

impl std::fmt::Display for ReferenceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ReferenceError::Scene(e) => write!(f, "{e}"),
            ReferenceError::Image(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ReferenceError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ReferenceError::Scene(e) => Some(e),
            ReferenceError::Image(e) => Some(e),
        }
    }
}

impl From<DataError> for ReferenceError {
    fn from(e: DataError) -> Self {
        ReferenceError::Scene(e)
    }
}

impl From<ImageError> for ReferenceError {
    fn from(e: ImageError) -> Self {
        ReferenceError::Image(e)
    }
}
