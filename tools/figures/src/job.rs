//! The job that writes the book's figures and generated tables to `figures/`.
//!
//! Each chapter module of this crate owns the figures of one chapter. Every output is produced
//! into a staging directory first; only when *all* outputs succeeded are they moved into
//! `figures/` (one rename per file), so a failed run leaves the previous figures intact.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, anyhow, bail};
use indicatif::{ProgressBar, ProgressStyle};

use raylemma::output::{self, FileSet};
use raylemma::render::format::fnv1a;
pub use raylemma_values::Record;
use raylemma_values::{Entry, Values, fingerprint};

use crate::{
    accuracy, colour, compare, conformance, coursework, diagram, dispersion, display, emission,
    export, external, frame, fresnel, lambert, limit, mitsuba, rectangle, reflect, roulette,
    sampling, shadow, specular, sphere, stats, tabulated, testing, thinfilm, upsample, wavelength,
};

/// Options shared by all figures.
#[derive(Clone, Debug)]
pub struct Settings {
    /// Fewer samples and shorter timings (for CI); the figures keep their shape.
    pub quick: bool,
    /// Measure the timing outputs again on this machine ([`write_outputs`] keeps them
    /// otherwise, outside quick mode).
    pub timings: bool,
    /// The project root: `scenes/`, `data/` and `figures/` are found under it.
    pub root: PathBuf,
}

/// One output file of the figure job.
pub struct Output {
    /// File name inside `figures/`, e.g. `sphere_far_error.svg`.
    pub file: &'static str,
    /// What it shows, for progress and error messages.
    pub what: &'static str,
    /// Produces the file's bytes, recording the values the book quotes from it.
    pub make: fn(&Settings, &mut Record) -> anyhow::Result<Vec<u8>>,
}

/// What the job prints of an error: its message and then each cause's, `outer: inner`, as
/// anyhow's `{:#}` prints them, leaving out a cause whose message is already in the text
/// (the library's errors that name their source in their own message, such as
/// `ImageError::File`, say it once).
pub fn message(e: &anyhow::Error) -> String {
    let mut text = String::new();
    for cause in e.chain() {
        let m = cause.to_string();
        if text.is_empty() {
            text = m;
        } else if !text.contains(&m) {
            text.push_str(": ");
            text.push_str(&m);
        }
    }
    text
}

/// Every output of every chapter, in book order.
pub fn all() -> Vec<Output> {
    let mut outputs = Vec::new();
    outputs.extend(coursework::outputs());
    outputs.extend(sphere::outputs());
    outputs.extend(stats::outputs());
    outputs.extend(sampling::outputs());
    // The explanatory diagrams, from the cosine-weighted hemisphere to the renderer.
    outputs.extend(diagram::outputs());
    outputs.extend(external::outputs());
    outputs.extend(tabulated::outputs());
    outputs.extend(frame::outputs());
    outputs.extend(reflect::outputs());
    outputs.extend(fresnel::outputs());
    outputs.extend(accuracy::outputs());
    outputs.extend(specular::outputs());
    outputs.extend(dispersion::outputs());
    outputs.extend(thinfilm::outputs());
    outputs.extend(lambert::outputs());
    outputs.extend(roulette::outputs());
    outputs.extend(shadow::outputs());
    outputs.extend(rectangle::outputs());
    outputs.extend(colour::outputs());
    outputs.extend(wavelength::outputs());
    outputs.extend(emission::outputs());
    outputs.extend(display::outputs());
    outputs.extend(upsample::outputs());
    outputs.extend(crate::render::outputs());
    outputs.extend(compare::outputs());
    outputs.extend(conformance::outputs());
    outputs.extend(export::outputs());
    outputs.extend(limit::outputs());
    outputs.extend(mitsuba::outputs());
    outputs.extend(testing::outputs());
    outputs
}

/// The outputs that take seconds to minutes and depend only on the code and the files
/// [`code_version`] hashes: remade only when those changed since they were made (each ends
/// with a comment, invisible in the book, naming the [`code_version`] it was made from), or
/// when the file is gone. Every other output takes about a second or less. A kept output's
/// record in `figures/values.json` stays as it was made (one that records nothing has none).
const KEPT_WHILE_CODE_UNCHANGED: [&str; 10] = [
    "render_compare_calibration.md",
    "conformance_false_alarms.md",
    "render_test_power.md",
    "stats_far_tail.md",
    "stats_pvalues.svg",
    "stats_calibration.md",
    "sampling_power.md",
    "sampling_calibration.svg",
    "sampling_calibration.md",
    "external_sampler.md",
];

/// A hash of everything a kept output can depend on: every file of the library's `src/`
/// and `data/`, the scenes (`scenes/`), the example programs in other languages that
/// `external_sampler.md` runs (`tools/examples/`), the figure job's own
/// `tools/figures/src/`, and `Cargo.lock`.
///
/// # Errors
/// If a file cannot be read.
fn code_version(root: &Path) -> anyhow::Result<String> {
    let mut files = raylemma::output::files_under(
        root,
        &[
            "src",
            "data",
            "scenes",
            "tools/examples",
            "tools/figures/src",
        ],
    )?;
    files.push(root.join("Cargo.lock"));
    files.sort();
    let mut all = Vec::new();
    for f in &files {
        all.extend_from_slice(
            f.strip_prefix(root)
                .unwrap_or(f)
                .to_string_lossy()
                .as_bytes(),
        );
        all.extend(std::fs::read(f).with_context(|| f.display().to_string())?);
    }
    Ok(format!("{:016x}", fnv1a(&all)))
}

/// A generated table of a `--quick` run says so, in a comment the book does not show: the
/// book's `{{#claim}}`s over it then warn instead of failing (`tools/book/src/values.rs`),
/// since its numbers are too noisy to quote.
const QUICK_MARK: &[u8] = b"\n<!-- made in quick mode: noisy, not for quoting -->\n";

/// Appends [`QUICK_MARK`] to a markdown output that does not already say "quick mode".
fn mark_quick(file: &str, bytes: &mut Vec<u8>) {
    let says = bytes.windows(10).any(|w| w == b"quick mode");
    if file.ends_with(".md") && !says {
        bytes.extend_from_slice(QUICK_MARK);
    }
}

/// Writes the outputs whose file name contains `only` (all if `None`) into `dir`.
///
/// # Errors
/// If nothing matches `only`, or as [`write_outputs`].
pub fn write_all(
    dir: &Path,
    settings: &Settings,
    only: Option<&str>,
) -> anyhow::Result<Vec<PathBuf>> {
    let outputs: Vec<Output> = all()
        .into_iter()
        .filter(|o| only.is_none_or(|s| o.file.contains(s)))
        .collect();
    if outputs.is_empty() {
        let names: Vec<_> = all().iter().map(|o| o.file).collect();
        bail!(
            "no figure matches {:?}; figures are: {}",
            only.unwrap_or(""),
            names.join(", ")
        );
    }
    write_outputs(dir, &outputs, settings)
}

/// The key of an output's record in `figures/values.json`: its file name without the
/// extension (`fresnel_speed.md` -> `fresnel_speed`).
pub fn stem(file: &str) -> &str {
    file.rsplit_once('.').map_or(file, |(stem, _)| stem)
}

/// The values file of `dir` with `made` (each output's file and its new record) put in,
/// staged in `set`: an output that recorded nothing loses its entry, and entries of outputs
/// whose file is gone from `dir` are dropped. Records of outputs not made now (kept ones,
/// those of `--only`'s other outputs, the references' and the external tools') stay.
///
/// # Errors
/// If the values file cannot be read, or two outputs of one name both record values.
pub fn stage_values(
    dir: &Path,
    mut values: Values,
    made: Vec<(&str, Entry)>,
    set: &mut FileSet,
) -> anyhow::Result<()> {
    for (file, entry) in made {
        let key = stem(file).to_string();
        if entry.values.is_empty() && entry.claims.is_empty() {
            if values.get(&key).is_some_and(|e| e.file == file) {
                values.remove(&key);
            }
            continue;
        }
        if let Some(old) = values.get(&key)
            && old.file != file
            && dir.join(&old.file).exists()
        {
            bail!(
                "{file} and {} both record values under the name {key}: rename one",
                old.file
            );
        }
        values.insert(key, entry);
    }
    let staged: Vec<PathBuf> = set.paths().map(Path::to_path_buf).collect();
    values.retain(|_, e| {
        let path = dir.join(&e.file);
        path.exists() || staged.contains(&path)
    });
    set.write(
        &dir.join(raylemma_values::FILE),
        raylemma_values::to_json(&values).as_bytes(),
    )?;
    Ok(())
}

/// Figures with a time axis of their own, timed in the same run as a table (the table's
/// record key): kept and remade with it, so that a figure and its table always show one
/// machine.
const TIMED_WITH: [(&str, &str); 4] = [
    ("fresnel_speed.svg", "fresnel_speed"),
    ("roulette_efficiency.svg", "roulette_efficiency"),
    ("wavelength_error.svg", "wavelength_efficiency"),
    ("shadow_convergence.svg", "shadow_strategies"),
];

/// The machine of a timing output to keep rather than measure again, in a full run without
/// `--timings`: the machine its committed record (`before`) names, or for a table that
/// records no values the fingerprint its committed text (`table`) names; never one made in
/// quick mode. A timing is a fact about the machine its caption names; measured again on
/// another, it could turn a claim the book makes about it (one routine faster than
/// another) from true to false, and fail the build of a newcomer's first `cargo run
/// --release`. So it is remade only when asked (`--timings`, or `--only` naming it), in
/// quick mode (CI runs the code that measures it; a failed claim is then a warning), or
/// when its file is gone.
pub fn kept_timing(
    before: Option<&Entry>,
    table: Option<&str>,
    settings: &Settings,
) -> Option<String> {
    if settings.quick || settings.timings || before.is_some_and(|e| e.quick) {
        return None;
    }
    before.and_then(|e| e.machine.clone()).or_else(|| {
        table
            .filter(|t| !t.contains("quick mode"))
            .and_then(fingerprint)
    })
}

/// Produces `outputs` and writes them into `dir` as one set of files
/// ([`raylemma::output::FileSet`]), with their records in `figures/values.json`: each is
/// staged beside its destination, and they are renamed into place only when all succeeded.
///
/// # Errors
/// Names the first output that failed; `dir` is then left exactly as it was.
pub fn write_outputs(
    dir: &Path,
    outputs: &[Output],
    settings: &Settings,
) -> anyhow::Result<Vec<PathBuf>> {
    output::create_dir_all(dir)?;
    let bar = ProgressBar::new(outputs.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{elapsed:>4} [{bar:30}] {pos}/{len} {msg}")?
            .progress_chars("=> "),
    );
    let say = |line: String| {
        if bar.is_hidden() {
            eprintln!("{line}");
        } else {
            bar.println(line);
        }
    };
    let version = code_version(&settings.root)?;
    let before = raylemma_values::read(dir).map_err(anyhow::Error::msg)?;
    let mut made = Vec::new();
    let mut set = FileSet::new();
    for o in outputs {
        bar.set_message(format!("{} ({})", o.file, o.what));
        let path = dir.join(o.file);
        let marker = format!("<!-- made from code version {version} -->\n");
        let kept = KEPT_WHILE_CODE_UNCHANGED.contains(&o.file) && !settings.quick;
        if kept && std::fs::read_to_string(&path).is_ok_and(|t| t.ends_with(&marker)) {
            say(format!(
                "    kept    {} (the code it measures is unchanged; delete the file to remake it)",
                o.file
            ));
            bar.inc(1);
            continue;
        }
        let table = TIMED_WITH
            .iter()
            .find(|(figure, _)| *figure == o.file)
            .map_or(stem(o.file), |(_, table)| table);
        let table_text = std::fs::read_to_string(dir.join(format!("{table}.md"))).ok();
        if let Some(machine) = kept_timing(before.get(table), table_text.as_deref(), settings)
            && path.exists()
        {
            say(format!(
                "    kept    {} (timings of machine {machine}; --timings measures them on this one)",
                o.file
            ));
            bar.inc(1);
            continue;
        }
        let start = Instant::now();
        let mut record = Record::new(o.file);
        let mut bytes = (o.make)(settings, &mut record)
            .with_context(|| format!("figure {} ({}) failed", o.file, o.what))?;
        if kept {
            bytes.extend_from_slice(b"\n");
            bytes.extend_from_slice(marker.as_bytes());
        }
        if settings.quick {
            mark_quick(o.file, &mut bytes);
        }
        let entry = record.finish(&bytes, settings.quick).map_err(|e| {
            anyhow!(
                "figure {} ({}) recorded its values wrongly: {e}",
                o.file,
                o.what
            )
        })?;
        made.push((o.file, entry));
        set.write(&path, &bytes)?;
        say(format!(
            "  {:>6.1} s  {}",
            start.elapsed().as_secs_f64(),
            o.file
        ));
        bar.inc(1);
    }
    stage_values(dir, before, made, &mut set)?;
    bar.finish_with_message("done");
    Ok(set.commit()?)
}

#[cfg(test)]
mod tests {
    use std::fs;

    use super::*;

    #[test]
    fn quick_tables_say_so_and_others_are_untouched() {
        let mut md = b"| a |\n|---|\n| 1 |\n".to_vec();
        mark_quick("t.md", &mut md);
        assert!(md.ends_with(QUICK_MARK));
        let mut noted = b"x (quick mode: noisy)".to_vec();
        mark_quick("t.md", &mut noted);
        assert_eq!(noted, b"x (quick mode: noisy)");
        let mut txt = b"verdict".to_vec();
        mark_quick("v.txt", &mut txt);
        assert_eq!(txt, b"verdict");
    }

    fn settings() -> Settings {
        Settings {
            quick: true,
            timings: false,
            root: PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../.."),
        }
    }

    #[test]
    fn a_timing_is_kept_unless_asked_for_in_quick_mode_or_with_timings() {
        let timing = Entry {
            file: "t_speed.md".into(),
            machine: Some("3cfca2e9".into()),
            quick: false,
            values: Default::default(),
            claims: Default::default(),
        };
        let full = Settings {
            quick: false,
            ..settings()
        };
        assert_eq!(
            kept_timing(Some(&timing), None, &full).as_deref(),
            Some("3cfca2e9")
        );
        let timings = Settings {
            timings: true,
            ..full.clone()
        };
        assert_eq!(kept_timing(Some(&timing), None, &timings), None);
        assert_eq!(kept_timing(Some(&timing), None, &settings()), None);
        let quick_made = Entry {
            quick: true,
            ..timing.clone()
        };
        assert_eq!(kept_timing(Some(&quick_made), None, &full), None);
        let untimed = Entry {
            machine: None,
            ..timing
        };
        assert_eq!(kept_timing(Some(&untimed), None, &full), None);
        assert_eq!(kept_timing(None, None, &full), None);
        // A table that records no values, kept by the fingerprint of its caption.
        let caption = "Measured on a CPU, fingerprint 77117322, single thread.\n| a |";
        assert_eq!(
            kept_timing(None, Some(caption), &full).as_deref(),
            Some("77117322")
        );
        let quick = format!("{caption}\n<!-- made in quick mode: noisy, not for quoting -->");
        assert_eq!(kept_timing(None, Some(&quick), &full), None);
        assert_eq!(kept_timing(None, Some("| no caption |"), &full), None);
    }

    #[test]
    fn a_cause_already_in_the_message_is_not_repeated() {
        let e = anyhow::anyhow!("a.exr: no such file").context("a.exr: no such file");
        assert_eq!(message(&e), "a.exr: no such file");
        let e = e.context("figure a.svg (a) failed");
        assert_eq!(message(&e), "figure a.svg (a) failed: a.exr: no such file");
    }

    #[test]
    fn unknown_figure_name_is_reported_with_the_list() {
        let dir =
            std::env::temp_dir().join(format!("raylemma-figures-only-{}", std::process::id()));
        let err = write_all(&dir, &settings(), Some("no_such_figure"))
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("no_such_figure") && err.contains("sphere_far_error.svg"),
            "{err}"
        );
        assert!(!dir.exists(), "nothing is written for an unknown name");
    }

    fn good(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
        Ok(b"new".to_vec())
    }

    fn bad(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
        bail!("planted failure")
    }

    #[test]
    fn a_failed_figure_leaves_the_previous_figures_intact() {
        let dir =
            std::env::temp_dir().join(format!("raylemma-figures-test-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        fs::write(dir.join("a.md"), "old").unwrap();
        let outputs = [
            Output {
                file: "a.md",
                what: "good",
                make: good,
            },
            Output {
                file: "b.md",
                what: "bad",
                make: bad,
            },
        ];
        let err = message(&write_outputs(&dir, &outputs, &settings()).unwrap_err());
        assert_eq!(err, "figure b.md (bad) failed: planted failure");
        assert_eq!(fs::read_to_string(dir.join("a.md")).unwrap(), "old");
        assert!(!dir.join("b.md").exists());
        // And when every output succeeds, all are written.
        let ok = [Output {
            file: "a.md",
            what: "good",
            make: good,
        }];
        write_outputs(&dir, &ok, &settings()).unwrap();
        // (The test's settings are quick, so the table says so.)
        let quick_mark = String::from_utf8_lossy(QUICK_MARK);
        assert_eq!(
            fs::read_to_string(dir.join("a.md")).unwrap(),
            format!("new{quick_mark}")
        );
        let mut names: Vec<_> = fs::read_dir(&dir)
            .unwrap()
            .filter_map(Result::ok)
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        // The output and the values file (empty: `good` records nothing), nothing else.
        assert_eq!(
            names,
            ["a.md", "values.json"],
            "temporary files left behind"
        );
        assert_eq!(
            raylemma_values::read(&dir).unwrap(),
            raylemma_values::Values::new()
        );
        fs::remove_dir_all(&dir).unwrap();
    }
}
