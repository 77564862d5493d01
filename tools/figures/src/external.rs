//! Figures of the chapter *Checks from any language*: the verdicts that `raylemma check`
//! prints for the Python examples of `tools/examples/`, made by the same library calls.
//!
//! They need `python3`; without it each file says so instead (the rest of the figures do
//! not need it).

use std::fmt::Write as _;
use std::process::{Command, Stdio};

use super::{Output, Record, Settings};
use crate::coursework::{first_failure, number_after, worst_failure};
use raylemma::check::external::{self, Density, Function, Program, Sampler, Target};
use raylemma::check::{Options, Verdict};

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

fn sampler_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
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
        if file == "uniform.py" {
            record_uniform(&verdict, r)?;
        }
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

/// The uniform hemisphere claimed as cosine-weighted: pdf x area element is `2z` (the
/// claimed `z / pi` times `2 pi`) at the Jacobian's first failure and, almost 0, at its worst
/// one on the rim; and how many times their share the chi-squared line's worst cell gets.
fn record_uniform(verdict: &Verdict, r: &mut Record) -> anyhow::Result<()> {
    let jacobian = verdict.finding("jacobian");
    let z_of = ["T(u) = (", ", ", ", "];
    let first = first_failure(jacobian)?;
    let (product, z) = (
        number_after(first, &["product "])?,
        number_after(first, &z_of)?,
    );
    let worst = worst_failure(jacobian)?;
    let (rim_product, rim_z) = (
        number_after(worst, &["product "])?,
        number_after(worst, &z_of)?,
    );
    r.number("uniform.jacobian.first.product", product, ".3");
    r.number("uniform.jacobian.first.z", z, ".3");
    r.claim(
        "uniform.jacobian_product_is_2z_and_almost_0_at_the_rim",
        !jacobian.passed()
            && (product - 2.0 * z).abs() < 1e-5
            && (rim_product - 2.0 * rim_z).abs() < 1e-5
            && rim_z < 0.01
            && rim_product < 0.01,
        format!(
            "jacobian fails {} of {}; first failure: product {product} = 2z = {} within 1e-5; \
             worst failure: z = {rim_z} < 0.01 (the rim), product {rim_product} = 2z = {} \
             within 1e-5 and < 0.01",
            jacobian.failures,
            jacobian.cases,
            2.0 * z,
            2.0 * rim_z
        ),
    );
    let cells = first_failure(verdict.finding("chi_squared"))?;
    let ratio = number_after(cells, &["predicts", "("])?;
    r.number("uniform.chi_squared.worst_cell.ratio", ratio, "int");
    // The worst cell's row: z in [-h, h], across the horizon, where h = 1 / rows (the
    // rows are equal in z, one of them centred on z = 0). Over the upper half of that row
    // the uniform density puts 1 / rows of its samples and the cosine lobe (CDF z^2) only
    // 1 / rows^2: the factor is the number of rows on average, so the worst cell's is at
    // least that.
    let z_of = ["z = cos(theta) in ["];
    let (low, high) = (
        number_after(cells, &z_of)?,
        number_after(cells, &["z = cos(theta) in [", ", "])?,
    );
    let rows = (1.0 / high).round();
    r.number("uniform.chi_squared.rows", rows, "int");
    r.claim(
        "uniform.chi_squared.worst_cell_across_the_horizon_above_the_row_average",
        low == -high && rows > 1.0 && ratio >= rows && ratio > 15.0,
        format!(
            "the worst cell lies in z in [{low}, {high}], across the horizon (1/h = {:.2}, {rows} rows), and gets {ratio} times its share: >= {rows}, the row's average, and > 15",
            1.0 / high
        ),
    );
    Ok(())
}

fn fresnel_md(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
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
