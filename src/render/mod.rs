//! The reference renderer, and only it. Chapters: *The path tracer*
//! (`chapters/renderer/path-tracer.md`) and *Reference scenes and interop*
//! (`chapters/renderer/scenes.md`). The tools for other renderers (export, the conformance
//! ladder, merge, compare, diagnosis) are [`crate::conformance`], beside it.
//!
//! A scene file goes through these files, in this order:
//!
//! * [`format`](mod@format): the TOML file as written, the entry points [`parse`] and
//!   [`load`], and the scene with the lines of its parts (`SceneFile`);
//! * `raw` (private): serde's raw tables of the file, with byte spans, and the helpers that
//!   read them (the line of a span, the file's hash);
//! * `validate` (private): the checker that turns the raw tables into the model, or
//!   refuses the file with its line and the reason;
//! * [`scene`]: the model, [`Scene`], and its geometric queries (the first surface along a
//!   ray, the point and normal of a hit, the side a light emits to);
//! * [`tracer`]: the scene's surfaces laid out for fast intersection;
//! * [`camera`]: the pinhole camera;
//! * [`integrator`]: the spectral path tracer (next-event estimation with MIS, roulette,
//!   hero wavelengths) and ray offsets;
//! * [`pixel`]: one pixel's generator, samples and colour;
//! * [`driver`]: tiles, threads and progress: [`render`], [`render_with`], [`render_file`];
//! * [`files`]: the three files of a render (EXR, PNG, the JSON [`Sidecar`]), written
//!   together or not at all (the image itself, [`crate::image::Image`], and its codecs
//!   are [`crate::image`], below the renderer);
//! * [`provenance`]: what a reference render was made from (scene, data, code, settings);

pub mod camera;
pub mod driver;
pub mod files;
pub mod format;
pub mod integrator;
pub mod pixel;
pub mod provenance;
mod raw;
pub mod scene;
pub mod tracer;
mod validate;

pub use driver::{
    Progress, TILE, Window, render, render_file, render_from, render_window, render_with,
};
pub use files::{Sidecar, output_paths, stage_outputs, write_outputs};
pub use format::{load, parse};
pub use pixel::{PixelNumbers, WavelengthSampler, pixel_rng, render_pixel, sample_xyz};
pub use scene::Scene;
