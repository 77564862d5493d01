//! The renderer chapter's examples of `raylemma export`: the JSON and the Mitsuba 3 XML of
//! `scenes/furnace-grey.toml`, written by the library's exporter exactly as the command
//! writes them (the chapter includes their first lines).

use super::{Output, Record, Settings};
use crate::plot::BoxError;
use raylemma::render::export::{SceneFile, json, mitsuba};

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
    ]
}

/// The example scene, named as the command line names it from the project root.
fn example(settings: &Settings) -> Result<SceneFile, BoxError> {
    let path = settings.root.join("scenes").join("furnace-grey.toml");
    let mut file = SceneFile::load(&path)?;
    file.file = "scenes/furnace-grey.toml".into();
    Ok(file)
}

fn json_example(settings: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    Ok(json::to_json(&example(settings)?).into_bytes())
}

fn xml_example(settings: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    Ok(mitsuba::to_xml(&example(settings)?)?.into_bytes())
}
