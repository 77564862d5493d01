//! `raylemma render SCENE`: renders a scene file into `SCENE.exr` (linear sRGB and the
//! variance of each pixel's mean), `SCENE.png` and `SCENE.json`, written together or not
//! at all. A bad scene is refused with file, line and reason before anything is written.

use std::path::{Path, PathBuf};

use clap::Args;
use raylemma::render;

use super::{CmdResult, Failure, done};

/// `raylemma render`.
#[derive(Args, Debug)]
pub struct RenderArgs {
    /// The scene file (TOML; see scenes/ and the renderer chapter).
    pub scene: PathBuf,
    /// Samples per pixel (overrides the scene's `spp`).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub spp: Option<u32>,
    /// The seed (overrides the scene's `seed`).
    #[arg(long)]
    pub seed: Option<u64>,
    /// The folder to write into (created if needed).
    #[arg(long, default_value = "renders")]
    pub out: PathBuf,
    /// Worker threads (default: all cores). The image does not depend on it.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub threads: Option<u32>,
}

/// Runs `raylemma render`: a scene that cannot be rendered, or an output folder that cannot
/// be written, is bad input (exit status 2).
pub fn run(args: &RenderArgs) -> CmdResult {
    done(render_scene(
        &args.scene,
        args.spp,
        args.seed,
        &args.out,
        args.threads,
    ))
}

fn render_scene(
    scene: &Path,
    spp: Option<u32>,
    seed: Option<u64>,
    out: &Path,
    threads: Option<u32>,
) -> Result<(), Failure> {
    if let Some(t) = threads {
        rayon::ThreadPoolBuilder::new()
            .num_threads(t as usize)
            .build_global()
            .map_err(|e| Failure::BadInput(format!("cannot start {t} threads: {e}")))?;
    }
    let stem = scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .ok_or_else(|| Failure::BadInput(format!("{}: not a file name", scene.display())))?;
    eprintln!("raylemma: rendering {}", scene.display());
    let (_, image, mut sidecar) = render::render_file(scene, spp, seed, render::Progress::Bar)?;
    sidecar.build = render::files::build_id();
    let files = render::write_outputs(out, &stem, &image, &sidecar)?;
    eprintln!(
        "raylemma: {} spp in {:.2} s ({:.3e} pixel samples per second, {} threads)",
        sidecar.spp,
        sidecar.seconds,
        f64::from(image.width) * f64::from(image.height) * f64::from(sidecar.spp) / sidecar.seconds,
        sidecar.threads
    );
    for f in files {
        eprintln!("raylemma: wrote {}", f.display());
    }
    Ok(())
}
