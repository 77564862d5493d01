//! Figures of the chapter *Checks from any language*: the verdicts that `raylemma check`
//! prints for the Python examples of `tools/examples/`, made by the same library calls.
//!
//! They need `python3`; without it each file says so instead (the rest of the figures do
//! not need it).

use std::fmt::Write as _;
use std::process::{Command, Stdio};

use super::{Output, Record, Settings};
use crate::plot::BoxError;
use raylemma::check::Options;
use raylemma::check::external::{self, Density, Function, Program, Sampler, Target};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "external_sampler.md",
            what: "verdicts on the Python samplers",
            make: sampler_md,
        },
        Output {
            file: "external_fresnel.md",
            what: "verdicts on the Python Fresnel",
            make: fresnel_md,
        },
    ]
}

fn python() -> bool {
    Command::new("python3")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

const NO_PYTHON: &str = "*`python3` was not found when the figures were made: run the \
    commands above to see the verdicts.*\n";

/// `python3 tools/examples/FILE` run in the project root.
fn example(settings: &Settings, args: &str) -> Program {
    Program::new(format!("python3 tools/examples/{args}")).in_dir(&settings.root)
}

/// The verdict as `raylemma check` prints it, in a text block, with the folder of the
/// failure images shortened to what follows the target folder (it is machine-specific).
fn block(md: &mut String, command: &str, verdict: &str) -> std::fmt::Result {
    let verdict = match verdict.split_once("; images in ") {
        Some((before, after)) => {
            let rest = after.find("warp-failures").map_or(after, |k| &after[k..]);
            format!("{before}; images in …/{rest}")
        }
        None => verdict.to_string(),
    };
    writeln!(md, "```text\n$ {command}\n{verdict}```\n")
}

fn sampler_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    if !python() {
        return Ok(NO_PYTHON.as_bytes().to_vec());
    }
    let samples = if settings.quick {
        20_000
    } else {
        external::SAMPLES
    };
    let options = Options::default().cases(samples);
    let cases: [(&str, bool, &str); 2] =
        [("cosine.py", true, " --inverse"), ("uniform.py", false, "")];
    let mut md = String::new();
    for (file, inverse, flag) in cases {
        let sampler = Sampler::Program {
            program: example(settings, file),
            density: Density::Target(Target::CosineHemisphere),
            inverse,
        };
        let verdict = external::sampler(&sampler, &options)?;
        let command = format!(
            "raylemma check sampler --target cosine-hemisphere{flag} \\\n    --program \"python3 tools/examples/{file}\""
        );
        block(&mut md, &command, &verdict.to_string())?;
    }
    if settings.quick {
        writeln!(md, "*(quick mode: {samples} samples)*")?;
    }
    Ok(md.into_bytes())
}

fn fresnel_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    if !python() {
        return Ok(NO_PYTHON.as_bytes().to_vec());
    }
    let mut md = String::new();
    for args in ["fresnel.py", "fresnel.py schlick"] {
        let function = Function::Program(example(settings, args));
        let verdict = external::fresnel(&function, &Options::default())?;
        let command = format!("raylemma check fresnel --program \"python3 tools/examples/{args}\"");
        block(&mut md, &command, &verdict.to_string())?;
    }
    Ok(md.into_bytes())
}
