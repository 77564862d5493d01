//! The scenes chapter's examples of `raylemma export`: the JSON and the Mitsuba 3 XML of
//! `scenes/furnace-grey.toml`, written by the library's exporter exactly as the command
//! writes them (the chapter includes their first lines); and the table of the conformance
//! ladder, read from its scene files' headers.

use super::{Output, Record, Settings};
use raylemma::conformance::export::{SceneFile, json, mitsuba};

/// The outputs of this module.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "export_furnace_grey.json",
            what: "raylemma export scenes/furnace-grey.toml --to json",
            make: json_example,
        },
        Output {
            file: "export_furnace_grey.xml",
            what: "raylemma export scenes/furnace-grey.toml --to mitsuba",
            make: xml_example,
        },
        Output {
            file: "conformance_ladder.md",
            what: "the conformance ladder, from the headers of scenes/conformance/",
            make: ladder_table,
        },
    ]
}

/// The rungs of [`raylemma::conformance::ladder::LADDER`], each with what its file's header says it tests, where it is
/// derived and what a failure there usually means.
fn ladder_table(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    use raylemma::conformance::ladder::{LADDER, header};
    let mut md = String::from(
        "| rung | scene | tests | derived in | a failure here usually means |\n|---:|---|---|---|---|\n",
    );
    for rung in &LADDER {
        let text =
            std::fs::read_to_string(settings.root.join("scenes/conformance").join(rung.file))?;
        let h = header(&text);
        // The scene's own depth: its `max_depth`, or unbounded (the default, 1000).
        let own = text
            .lines()
            .find_map(|l| l.trim().strip_prefix("max_depth = "))
            .map_or("unbounded (its own)".to_string(), |d| {
                format!("{d} (its own)")
            });
        let depths: Vec<String> = rung
            .depths
            .iter()
            .map(|d| d.map_or(own.clone(), |d| d.to_string()))
            .collect();
        let depth_note = if rung.depths.len() > 1 {
            format!(" (references at depths {})", depths.join(", "))
        } else {
            String::new()
        };
        let spectral = if rung.spectral_only {
            " (spectral renderers only)"
        } else {
            ""
        };
        md += &format!(
            "| {} | `{}`: {}{depth_note}{spectral} | {} | {} | {} |\n",
            rung.number, rung.file, h.title, h.tests, h.chapter, h.failure
        );
    }
    r.number("rungs", LADDER.len() as f64, "int");
    md += "\n*Read from the header comments of `scenes/conformance/*.toml` by `tools/figures/src/export.rs`.*\n";
    Ok(md.into_bytes())
}

/// The example scene, named as the command line names it from the project root.
fn example(settings: &Settings) -> anyhow::Result<SceneFile> {
    let path = settings.root.join("scenes").join("furnace-grey.toml");
    let mut file = SceneFile::load(&path)?;
    file.file = "scenes/furnace-grey.toml".into();
    Ok(file)
}

fn json_example(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    Ok(json::to_json(&example(settings)?).into_bytes())
}

fn xml_example(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    Ok(mitsuba::to_xml(&example(settings)?)?.into_bytes())
}
