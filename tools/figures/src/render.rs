//! The renderer chapter's reference images and speed-against-error measurements: every
//! canonical scene rendered into `figures/reference/` (EXR with variance, PNG, JSON), a
//! table of their noise levels, and the `cornell` scene's RMSE against time.
//!
//! Unlike the other figures these are not one file per function: a render makes three
//! files, and the speed series needs the reference. The job still stages everything and
//! moves it into place only when all of it succeeded.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{anyhow, bail};

use super::timing::{machine_name, quick_note};
use super::{Output, Record, Settings, job};
use crate::plot::{self, Panel, Series};
use raylemma::check::render::references::CANONICAL;
use raylemma::conformance::compare::{mse_against, noise_level};
use raylemma::conformance::ladder::{self, LADDER};
use raylemma::image::Image;
use raylemma::output::FileSet;
use raylemma::render::provenance::{self, MadeFrom};
use raylemma::render::scene::Scene;
use raylemma::render::{self, Progress, Sidecar};
use raylemma::spectral::display;

/// Every reference: the name of its files under `figures/reference/`, its scene file under
/// `scenes/`, and the maximum depth it is rendered at (`None`: the scene's own). The
/// canonical scenes (the library's list, which the renderer's tests also read), then each
/// rung of the conformance ladder at each of its depths (`conformance/NN-name`, with
/// `-depthD` for a depth other than the scene's own).
fn scenes() -> Vec<(&'static str, &'static str, Option<u32>)> {
    let mut all: Vec<_> = CANONICAL.iter().map(|c| (c.name, c.file, None)).collect();
    for rung in &LADDER {
        for &depth in rung.depths {
            // A few names, made once for the life of the job.
            let name: &'static str = Box::leak(
                format!("conformance/{}", ladder::reference_name(rung, depth)).into_boxed_str(),
            );
            let file: &'static str =
                Box::leak(format!("conformance/{}", rung.file).into_boxed_str());
            all.push((name, file, depth));
        }
    }
    all
}

/// The samples per pixel of a reference: the scene file's in full mode, a 32nd of it (at
/// least 4) in quick mode.
pub fn reference_spp(scene: &Scene, settings: &Settings) -> u32 {
    if settings.quick {
        (scene.settings.spp / 32).max(4)
    } else {
        scene.settings.spp
    }
}

struct Rendered {
    name: &'static str,
    scene_file: &'static str,
    image: Image,
    sidecar: Sidecar,
}

fn scenes_dir(settings: &Settings) -> PathBuf {
    settings.root.join("scenes")
}

/// What a reference is made from now (its scene at the job's samples per pixel).
fn made_from_now(
    file: &str,
    depth: Option<u32>,
    settings: &Settings,
    code: &(String, usize),
) -> anyhow::Result<(Scene, MadeFrom)> {
    let path = scenes_dir(settings).join(file);
    let mut s = render::load(&path)?;
    s.settings.spp = reference_spp(&s, settings);
    if let Some(d) = depth {
        s.settings.max_depth = d;
    }
    let now = MadeFrom::of(&settings.root, &path, &s, code)?;
    Ok((s, now))
}

/// Why the committed reference `name` must be rendered again (empty when it is current):
/// its files are missing, it has no record of what it was made from, or the record differs.
fn staleness(figures: &Path, name: &str, now: &MadeFrom) -> Vec<String> {
    let refs = figures.join("reference");
    let [exr, png, json] = render::output_paths(&refs, name);
    if !(exr.is_file() && png.is_file() && json.is_file()) {
        return vec!["its files are missing".into()];
    }
    match Sidecar::read(&json) {
        Err(e) => vec![format!("its sidecar cannot be read ({e})")],
        Ok(Sidecar {
            made_from: None, ..
        }) => vec!["its sidecar has no record of what it was made from".into()],
        Ok(Sidecar {
            made_from: Some(recorded),
            ..
        }) => now.differences(&recorded),
    }
}

fn render_one(
    name: &'static str,
    file: &'static str,
    scene: Scene,
    made_from: MadeFrom,
) -> anyhow::Result<Rendered> {
    eprintln!(
        "  {name}: {}x{}, {} spp",
        scene.camera.width, scene.camera.height, scene.settings.spp
    );
    let start = Instant::now();
    let image = render::render(&scene, scene.settings.spp, Progress::Bar);
    let sidecar = Sidecar {
        scene: format!("scenes/{file}"),
        scene_hash: scene.hash,
        spp: scene.settings.spp,
        seed: scene.settings.seed,
        wavelengths: scene.settings.wavelengths.name().to_string(),
        seconds: start.elapsed().as_secs_f64(),
        threads: rayon::current_num_threads(),
        made_from: Some(made_from),
        build: None,
        seeds: Vec::new(),
    };
    Ok(Rendered {
        name,
        scene_file: file,
        image,
        sidecar,
    })
}

/// The committed reference `name`, read back.
fn read_one(figures: &Path, name: &'static str, file: &'static str) -> anyhow::Result<Rendered> {
    let [exr, _, json] = render::output_paths(&figures.join("reference"), name);
    Ok(Rendered {
        name,
        scene_file: file,
        image: Image::read_exr(&exr)?,
        sidecar: Sidecar::read(&json)?,
    })
}

/// The canonical scenes whose committed references are out of date, each with why.
///
/// # Errors
/// A scene file or data file that cannot be read.
pub fn stale_references(
    figures: &Path,
    settings: &Settings,
) -> anyhow::Result<Vec<(&'static str, Vec<String>)>> {
    let code = provenance::code_version(&settings.root)?;
    let mut stale = Vec::new();
    for (name, file, depth) in scenes() {
        let (_, now) = made_from_now(file, depth, settings, &code)?;
        let why = staleness(figures, name, &now);
        if !why.is_empty() {
            stale.push((name, why));
        }
    }
    Ok(stale)
}

/// The cornell scene at increasing sample counts: `(spp, seconds, RMSE)` against the
/// reference (a different seed, so that the errors are independent).
fn speed_series(reference: &Image, settings: &Settings) -> anyhow::Result<Vec<(u32, f64, f64)>> {
    let mut s = render::load(&scenes_dir(settings).join("cornell.toml"))?;
    s.settings.seed = 1_000_003;
    let top = if settings.quick { 8 } else { 128 };
    let mut out = Vec::new();
    let mut spp = 1;
    while spp <= top {
        let start = Instant::now();
        let image = render::render(&s, spp, Progress::Silent);
        let seconds = start.elapsed().as_secs_f64();
        out.push((spp, seconds, mse_against(&image, reference).max(0.0).sqrt()));
        spp *= 2;
    }
    Ok(out)
}

fn references_md(rendered: &[Rendered], settings: &Settings) -> String {
    let mut md = String::from(
        "| scene | file | size | spp | seconds | pixel samples / s | RMS standard error of a pixel's luminance | relative to the mean |\n|---|---|---|---:|---:|---:|---:|---:|\n",
    );
    for r in rendered {
        let (rms, rel) = noise_level(&r.image);
        let samples =
            f64::from(r.image.width) * f64::from(r.image.height) * f64::from(r.sidecar.spp);
        let _ = writeln!(
            md,
            "| {} | `scenes/{}` | {}x{} | {} | {:.1} | {:.3e} | {:.2e} | {:.2} % |",
            r.name,
            r.scene_file,
            r.image.width,
            r.image.height,
            r.sidecar.spp,
            r.sidecar.seconds,
            samples / r.sidecar.seconds,
            rms,
            100.0 * rel
        );
    }
    let _ = write!(
        md,
        "\n*Rendered by `cargo run --release` on {} ({} worker threads){}.*\n",
        machine_name(),
        rayon::current_num_threads(),
        quick_note(settings.quick)
    );
    md
}

fn speed_md(
    series: &[(u32, f64, f64)],
    reference: &Rendered,
    settings: &Settings,
    r: &mut Record,
) -> String {
    let pixels = f64::from(reference.image.width) * f64::from(reference.image.height);
    let mut md = String::from(
        "| spp | seconds | pixel samples / s | RMSE | RMSE² × seconds |\n|---:|---:|---:|---:|---:|\n",
    );
    for &(spp, s, e) in series {
        let _ = writeln!(
            md,
            "| {spp} | {s:.3} | {:.3e} | {e:.3e} | {:.3e} |",
            pixels * f64::from(spp) / s,
            e * e * s
        );
    }
    let work: Vec<f64> = series.iter().map(|&(_, s, e)| e * e * s).collect();
    r.number(
        "work.min",
        work.iter().copied().fold(f64::INFINITY, f64::min),
        "s2",
    );
    r.number("work.max", work.iter().copied().fold(0.0, f64::max), "s2");
    let spp = |f: fn(u32, u32) -> u32| series.iter().map(|x| x.0).reduce(f).unwrap_or(1);
    r.number("spp_range", f64::from(spp(u32::max) / spp(u32::min)), "int");
    let _ = write!(
        md,
        "\n*`cornell`, 256x256, against the reference of {} spp (another seed; its own variance subtracted); {} worker threads on {}{}.*\n",
        reference.sidecar.spp,
        rayon::current_num_threads(),
        machine_name(),
        quick_note(settings.quick)
    );
    md
}

/// `cornell` as the renderer's speed tables time it: `side` by `side` pixels, Russian
/// roulette from depth 5 (as `tools/mitsuba/speed.sh` renders it).
pub fn cornell_timed(settings: &Settings, side: u32) -> anyhow::Result<Scene> {
    let mut scene = render::load(&settings.root.join("scenes").join("cornell.toml"))?;
    scene.camera.width = side;
    scene.camera.height = side;
    scene.settings.roulette_depth = 5;
    Ok(scene)
}

/// The figure job's output made from a table of the references: the RMSE against time,
/// drawn from the committed `render_speed.md` (no rendering).
pub fn outputs() -> Vec<Output> {
    vec![Output {
        file: "render_error_time.svg",
        what: "RMSE against render time, from render_speed.md",
        make: error_time_svg,
    }]
}

fn error_time_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let path = settings.root.join("figures").join("render_speed.md");
    let md = std::fs::read_to_string(&path)
        .map_err(|e| anyhow!("{}: {e} (`references` writes it)", path.display()))?;
    let series = parse_speed_md(&md);
    if series.is_empty() {
        bail!("{}: no rows of spp, seconds and RMSE", path.display());
    }
    speed_svg(&series)
}

/// The rows `(spp, seconds, RMSE)` of a table written by [`speed_md`].
fn parse_speed_md(md: &str) -> Vec<(u32, f64, f64)> {
    md.lines()
        .filter_map(|line| {
            let cells: Vec<&str> = line
                .trim()
                .trim_matches('|')
                .split('|')
                .map(str::trim)
                .collect();
            match cells[..] {
                [spp, seconds, _, rmse, _] => {
                    Some((spp.parse().ok()?, seconds.parse().ok()?, rmse.parse().ok()?))
                }
                _ => None,
            }
        })
        .collect()
}

fn speed_svg(series: &[(u32, f64, f64)]) -> anyhow::Result<Vec<u8>> {
    let measured = Series::measured(
        "raylemma, cornell 256x256",
        series.iter().map(|&(_, s, e)| (s, e)).collect(),
    );
    let (s0, e0) = (series[0].1, series[0].2);
    let slope = Series::line(
        "slope −1/2 (unbiased Monte Carlo)",
        series
            .iter()
            .map(|&(_, s, _)| (s, e0 * (s0 / s).sqrt()))
            .collect(),
    );
    plot::chart(
        &[Panel::new(
            "RMSE against render time",
            "seconds",
            "RMSE (linear sRGB)",
            vec![measured, slope],
        )
        .log_x()
        .log_y()],
        1,
    )
}

/// The standard error of each pixel's luminance, as a grey image scaled so that the
/// image's 99th percentile is white.
fn stderr_png(image: &Image) -> anyhow::Result<Vec<u8>> {
    let se: Vec<f64> = image
        .var
        .iter()
        .map(|v| display::LUMA.dot(v.map(|x| x.max(0.0).sqrt())))
        .collect();
    let mut sorted = se.clone();
    sorted.sort_by(f64::total_cmp);
    let top = sorted[(sorted.len() * 99) / 100].max(1e-30);
    let rgb: Vec<u8> = se
        .iter()
        .flat_map(|&s| [display::srgb8(s / top); 3])
        .collect();
    plot::encode_png(image.width, image.height, rgb)
}

/// Renders every canonical scene whose committed reference is out of date (all of them
/// with `force`), saying which it skips and why, then the speed series and the tables, and
/// writes the results into `figures/reference/` and `figures/` as one set of files, which
/// lands only when all succeeded. When every reference is current, nothing is rendered
/// and the tables made from the renders are kept. The speed table `render_speed.md` is also
/// kept when the speed series shows the committed errors and its timings are of a machine
/// ([`job::kept_timing`]: not in quick mode, not with `--timings`), as the figure job keeps
/// its timing tables: re-rendering references after a change that leaves every image the
/// same should not re-time the table under whatever load the machine has then.
///
/// # Errors
/// The scene or file that failed; `figures/` is then unchanged.
pub fn write_references(
    figures: &Path,
    settings: &Settings,
    force: bool,
) -> anyhow::Result<Vec<PathBuf>> {
    let code = provenance::code_version(&settings.root)?;
    eprintln!(
        "  the renderer's code version: {} ({} files of src/ and data/, and Cargo.lock)",
        code.0, code.1
    );
    let mut rendered = Vec::new();
    let mut fresh = Vec::new();
    for (name, file, depth) in scenes() {
        let (scene, now) = made_from_now(file, depth, settings, &code)?;
        let why = staleness(figures, name, &now);
        if why.is_empty() && !force {
            eprintln!(
                "  {name}: current (its scene, data, the renderer's code and the settings are as recorded): kept"
            );
            rendered.push(read_one(figures, name, file)?);
        } else {
            let why = if force {
                "--force".to_string()
            } else {
                why.join("; ")
            };
            eprintln!("  {name}: rendering ({why})");
            fresh.push(name);
            rendered.push(render_one(name, file, scene, now)?);
        }
    }
    if fresh.is_empty() {
        eprintln!(
            "  every reference is current: the noise table and the RMSE against time are kept (`references --force` renders them all)"
        );
        return Ok(Vec::new());
    }
    eprintln!("  cornell: RMSE against time");
    let series = speed_series(&rendered[0].image, settings)?;
    let mut files = FileSet::new();
    let refs = figures.join("reference");
    raylemma::output::create_dir_all(&refs.join("conformance"))?;
    for r in rendered.iter().filter(|r| fresh.contains(&r.name)) {
        render::stage_outputs(&mut files, &refs, r.name, &r.image, &r.sidecar)?;
    }
    let values = raylemma_values::read(figures).map_err(anyhow::Error::msg)?;
    let flat = [
        (
            "render_references.md",
            references_md(&rendered, settings).into_bytes(),
        ),
        ("render_cornell_stderr.png", stderr_png(&rendered[0].image)?),
    ];
    for (name, bytes) in &flat {
        files.write(&figures.join(name), bytes)?;
    }
    let committed = std::fs::read_to_string(figures.join("render_speed.md")).ok();
    let kept = committed
        .as_deref()
        .filter(|md| same_errors(md, &series))
        .and_then(|md| job::kept_timing(values.get("render_speed"), Some(md), settings));
    let mut made = Vec::new();
    if let Some(machine) = kept {
        eprintln!(
            "  render_speed.md: kept (the same errors to the digits shown, so the renderer's estimates are unchanged; timings of machine {machine}; --timings measures them on this one)"
        );
    } else {
        let mut record = Record::new("render_speed.md");
        let speed = speed_md(&series, &rendered[0], settings, &mut record).into_bytes();
        files.write(&figures.join("render_speed.md"), &speed)?;
        let entry = record
            .finish(&speed, settings.quick)
            .map_err(anyhow::Error::msg)?;
        made.push(("render_speed.md", entry));
    }
    job::stage_values(figures, values, made, &mut files)?;
    Ok(files.commit()?)
}

/// Whether the committed speed table `md` shows the errors of `series`, spp for spp, to
/// the digits it prints: the renderer's estimates are then unchanged, and only its timings
/// would differ if measured again.
fn same_errors(md: &str, series: &[(u32, f64, f64)]) -> bool {
    let shown = |e: f64| format!("{e:.3e}").parse::<f64>().ok();
    let committed = parse_speed_md(md);
    committed.len() == series.len()
        && committed
            .iter()
            .zip(series)
            .all(|(&(spp, _, e), &(now, _, f))| spp == now && Some(e) == shown(f))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_speed_table_is_kept_only_for_the_same_errors() {
        let md = "| spp | seconds | pixel samples / s | RMSE | RMSE² × seconds |\n|---:|---:|---:|---:|---:|\n| 1 | 0.042 | 1.568e6 | 4.500e-1 | 7.880e-3 |\n| 2 | 0.075 | 1.741e6 | 3.091e-1 | 7.192e-3 |\n";
        assert!(same_errors(md, &[(1, 0.05, 0.450_02), (2, 0.09, 0.309_11)]));
        assert!(!same_errors(md, &[(1, 0.05, 0.4502), (2, 0.09, 0.309_11)]));
        assert!(!same_errors(md, &[(1, 0.05, 0.450_02)]));
        assert!(!same_errors(
            md,
            &[(1, 0.05, 0.450_02), (4, 0.09, 0.309_11)]
        ));
    }

    #[test]
    fn the_speed_table_reads_back_as_written() {
        let md = "| spp | seconds | pixel samples / s | RMSE | RMSE² × seconds |\n|---:|---:|---:|---:|---:|\n| 1 | 0.042 | 1.568e6 | 4.5e-1 | 7.880e-3 |\n| 2 | 0.075 | 1.741e6 | 3.091e-1 | 7.192e-3 |\n\n*note*\n";
        assert_eq!(parse_speed_md(md), [(1, 0.042, 0.45), (2, 0.075, 0.3091)]);
    }
}
