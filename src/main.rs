//! `raylemma`: renders and compares scenes; regenerates the book's figures and builds the
//! book.
//!
//! `cargo run --release` with no subcommand regenerates the figures and reference images
//! and builds the book; see `--help`. The figures and the book are made by two tools of
//! this workspace (`tools/figures/`, `tools/book/`), which this program runs with cargo,
//! so that the library never compiles their dependencies.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

use clap::{Parser, Subcommand};
use raylemma::render::{self, compare, image::Image};

/// Regenerate raylemma's figures and build its book.
///
/// With no subcommand: `figures`, `references`, then `book`.
#[derive(Parser, Debug)]
#[command(name = "raylemma", version, about, long_about = None)]
struct Cli {
    /// Fewer samples and shorter timings (for CI); figures keep their shape.
    #[arg(long, global = true)]
    quick: bool,
    #[command(subcommand)]
    command: Option<Cmd>,
}

#[derive(Subcommand, Debug)]
enum Cmd {
    /// Regenerate every figure and generated table into figures/.
    Figures {
        /// Only outputs whose file name contains this text (e.g. `sphere_speed`).
        #[arg(long)]
        only: Option<String>,
    },
    /// Render every canonical scene into figures/reference/ (EXR, PNG, JSON), with the
    /// noise-level table and the cornell scene's RMSE against time.
    References,
    /// Build the HTML book from chapters/ into book/ (mdBook as a library, math as MathML).
    Book,
    /// Render a scene file: SCENE.exr (linear sRGB and the variance of each pixel's mean),
    /// SCENE.png (display) and SCENE.json (scene hash, spp, seed, time, version) in --out.
    Render {
        /// The scene file (TOML; see scenes/ and the renderer chapter).
        scene: PathBuf,
        /// Samples per pixel (overrides the scene's `spp`).
        #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
        spp: Option<u32>,
        /// The seed (overrides the scene's `seed`).
        #[arg(long)]
        seed: Option<u64>,
        /// The folder to write into (created if needed).
        #[arg(long, default_value = "renders")]
        out: PathBuf,
        /// Worker threads (default: all cores). The image does not depend on it.
        #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
        threads: Option<u32>,
    },
    /// Do two renders (EXR with variance channels) agree within their noise? Exit status 0
    /// if they agree, 1 if they differ, 2 for bad input.
    Compare {
        /// The first image.
        a: PathBuf,
        /// The second image.
        b: PathBuf,
        /// The family-wise false-alarm rate of the z-tests.
        #[arg(long, default_value_t = 0.01)]
        alpha: f64,
        /// Where to write the difference image (PNG).
        #[arg(long)]
        diff: Option<PathBuf>,
    },
}

/// The project root: this binary is built from it.
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs the workspace tool `package` (`raylemma-figures` or `raylemma-book`) with `args`,
/// compiling it first if needed (cargo shows its own progress).
fn run_tool(package: &str, args: &[&str]) -> Result<(), String> {
    let root = root();
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let status = Command::new(&cargo)
        .args(["run", "--release", "--quiet", "-p", package, "--"])
        .args(args)
        .arg("--root")
        .arg(&root)
        .current_dir(&root)
        .status()
        .map_err(|e| format!("cannot start {}: {e}", Path::new(&cargo).display()))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("{package} failed ({status})"))
    }
}

/// Regenerates the figures (all, or those whose name contains `only`).
fn run_figures(quick: bool, only: Option<&str>) -> Result<(), String> {
    let mut args = vec!["figures"];
    if let Some(name) = only {
        args.extend(["--only", name]);
    }
    if quick {
        args.push("--quick");
    }
    run_tool("raylemma-figures", &args)
}

/// Renders the reference images.
fn run_references(quick: bool) -> Result<(), String> {
    let mut args = vec!["references"];
    if quick {
        args.push("--quick");
    }
    run_tool("raylemma-figures", &args)
}

/// Builds the book (the first build compiles mdBook and KaTeX, a few minutes).
fn run_book() -> Result<(), String> {
    eprintln!("raylemma: building the book tool (the first build compiles mdBook and KaTeX)");
    run_tool("raylemma-book", &[]).map_err(|e| format!("{e}; book/ was left as it was"))?;
    eprintln!(
        "raylemma: open {} in a browser",
        root().join("book").join("index.html").display()
    );
    Ok(())
}

fn run_render(
    scene: &Path,
    spp: Option<u32>,
    seed: Option<u64>,
    out: &Path,
    threads: Option<u32>,
) -> Result<(), String> {
    if let Some(t) = threads {
        rayon::ThreadPoolBuilder::new()
            .num_threads(t as usize)
            .build_global()
            .map_err(|e| format!("cannot start {t} threads: {e}"))?;
    }
    let stem = scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .ok_or_else(|| format!("{}: not a file name", scene.display()))?;
    eprintln!("raylemma: rendering {}", scene.display());
    let (_, image, sidecar) = render::render_file(scene, spp, seed, render::Progress::Bar)?;
    let files = render::write_outputs(out, &stem, &image, &sidecar).map_err(|e| e.to_string())?;
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

/// 0: agree, 1: differ; an error is returned for bad input (exit status 2).
fn run_compare(a: &Path, b: &Path, alpha: f64, diff: Option<&Path>) -> Result<bool, String> {
    let ia = Image::read_exr(a).map_err(|e| e.to_string())?;
    let ib = Image::read_exr(b).map_err(|e| e.to_string())?;
    let c = compare::compare(&ia, &ib, alpha)
        .map_err(|e| format!("{} vs {}: {e}", a.display(), b.display()))?;
    print!("{}", c.report());
    if let Some(path) = diff {
        let bytes = compare::difference_rgb8(&ia, &ib, c.z_critical);
        raylemma::spectral::display::write_png(path, ia.width, ia.height, &bytes)
            .map_err(|e| e.to_string())?;
        println!("difference image: {}", path.display());
    }
    Ok(c.agree())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let quick = cli.quick;
    let result = match &cli.command {
        None => run_figures(quick, None)
            .and_then(|()| run_references(quick))
            .and_then(|()| run_book()),
        Some(Cmd::References) => run_references(quick),
        Some(Cmd::Figures { only }) => run_figures(quick, only.as_deref()),
        Some(Cmd::Book) => run_book(),
        Some(Cmd::Render {
            scene,
            spp,
            seed,
            out,
            threads,
        }) => run_render(scene, *spp, *seed, out, *threads),
        Some(Cmd::Compare { a, b, alpha, diff }) => {
            match run_compare(a, b, *alpha, diff.as_deref()) {
                Ok(true) => Ok(()),
                Ok(false) => return ExitCode::from(1),
                Err(e) => {
                    eprintln!("raylemma: error: {e}");
                    return ExitCode::from(2);
                }
            }
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("raylemma: error: {e}");
            ExitCode::FAILURE
        }
    }
}
