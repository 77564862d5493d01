//! `raylemma check sampler|fresnel|refraction|corpus`: the book's checkers on an implementation
//! outside Rust, a program that answers questions over a pipe or a file of values (the
//! protocol: `raylemma::check::external`; chapter *Checks from any language*). Prints the
//! checker's verdict; exit status 0 if it passes, 1 if it fails, 2 for bad input (a file
//! or an answer that cannot be read, with its line; a program that cannot be run, ends
//! early, fails or hangs).

use std::path::PathBuf;
use std::time::Duration;

use clap::{Args, Subcommand};
use raylemma::check::external::{self, Checked, FunctionCheck, SamplerCheck, Target};
use raylemma::check::warp::Domain;

use super::{CmdResult, Failure, Outcome};

/// `raylemma check`.
#[derive(Subcommand, Debug)]
pub enum CheckCmd {
    /// A sampler: its samples in a CSV file (chi-squared), or a program that answers
    /// `warp u1 u2` with `x y z` (chi-squared, Jacobian, and with --inverse the round trip).
    #[command(
        after_help = "Example:\n  raylemma check sampler --target cosine-hemisphere --inverse --program \"python3 tools/examples/cosine.py\""
    )]
    Sampler(SamplerArgs),
    /// An unpolarised Fresnel reflectance: a program that answers `fresnel cos_i n1 n2`
    /// with `R`, or a table of rows `cos_i,n1,n2,R`.
    #[command(
        after_help = "Example:\n  raylemma check fresnel --program \"python3 tools/examples/fresnel.py\""
    )]
    Fresnel(FresnelArgs),
    /// A refraction: a program that answers `refract wi_x wi_y wi_z n_x n_y n_z n1 n2`
    /// with `t_x t_y t_z` or `tir`, or a table of those rows.
    #[command(
        after_help = "Example:\n  raylemma check refraction --program \"python3 tools/examples/refract.py\""
    )]
    Refraction(RefractionArgs),
    /// Accuracy on the corpora of hard inputs (data/corpus/*.txt): a program answers each
    /// case's question (`fresnel 0.5 1.0 1.5`) with `none` or its outputs, and every error
    /// must be at most 8 ulps times the problem's condition number. Without --program, the
    /// crate's own routines are checked.
    #[command(
        after_help = "Example:\n  raylemma check corpus data/corpus/fresnel.txt --verbs fresnel --program \"python3 tools/examples/fresnel.py\""
    )]
    Corpus(CorpusArgs),
}

/// `raylemma check corpus`.
#[derive(Args, Debug)]
pub struct CorpusArgs {
    /// The corpus files [default: every data/corpus/*.txt under the current folder].
    pub files: Vec<PathBuf>,
    /// The program, run by `sh -c`, that answers the questions.
    #[arg(long)]
    pub program: Option<String>,
    /// Only these verbs, comma-separated (e.g. fresnel,schlick); every corpus named must
    /// have them [default: every verb].
    #[arg(long, value_delimiter = ',')]
    pub verbs: Vec<String>,
    /// Seconds one run of the program may take [default: 120].
    #[arg(long, value_parser = parse_seconds, requires = "program")]
    pub timeout: Option<Duration>,
}

/// `raylemma check sampler`.
#[derive(Args, Debug)]
#[command(group = clap::ArgGroup::new("from").required(true).multiple(false))]
#[command(group = clap::ArgGroup::new("density").required(true).multiple(false))]
pub struct SamplerArgs {
    /// The sampler program, run by `sh -c` (e.g. "python3 my_sampler.py").
    #[arg(long, group = "from")]
    pub program: Option<String>,
    /// A CSV file of samples, one `x,y,z` a row (`x,y` on the disc and the square).
    #[arg(long, group = "from", conflicts_with_all = ["cases", "seed", "inverse", "domain"])]
    pub samples: Option<PathBuf>,
    /// The density the samples should follow: uniform-sphere, uniform-hemisphere,
    /// cosine-hemisphere, disc or square.
    #[arg(long, group = "density", value_parser = parse_target)]
    pub target: Option<Target>,
    /// Instead of --target: the program states its own density, answering `pdf x y z`
    /// with `p`, on this domain (sphere, disc or square).
    #[arg(long, group = "density", value_parser = parse_domain)]
    pub domain: Option<Domain>,
    /// The program answers `invert x y z` with `u1 u2` (adds the round-trip claim).
    #[arg(long)]
    pub inverse: bool,
    /// Samples drawn from the program [default: 400000].
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
    pub cases: Option<u64>,
    /// Seed of the points of the square the program is asked about.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Significance level of the chi-squared test [default: the suite's, about 5e-5].
    #[arg(long, value_parser = parse_alpha)]
    pub alpha: Option<f64>,
    /// Seconds one run of the program may take [default: 120].
    #[arg(long, value_parser = parse_seconds)]
    pub timeout: Option<Duration>,
    /// Where the failure images go (observed, expected and difference counts per cell,
    /// written when the chi-squared test fails) [default: warp-failures/ in the working
    /// directory].
    #[arg(long, value_name = "DIR")]
    pub failure_images: Option<PathBuf>,
}

/// Where a function's answers come from, and the list of questions for a table.
#[derive(Args, Debug)]
#[command(group = clap::ArgGroup::new("from").required(true).multiple(true))]
pub struct FunctionArgs {
    /// The program, run by `sh -c` (e.g. "python3 my_fresnel.py").
    #[arg(long, group = "from", conflicts_with_all = ["table", "questions"])]
    pub program: Option<String>,
    /// A CSV table: one row a question's numbers followed by its answer.
    #[arg(long, group = "from")]
    pub table: Option<PathBuf>,
    /// Write the questions the table (if any) does not answer yet to this CSV file,
    /// instead of checking.
    #[arg(long, group = "from")]
    pub questions: Option<PathBuf>,
    /// Seconds one run of the program may take [default: 120].
    #[arg(long, value_parser = parse_seconds)]
    pub timeout: Option<Duration>,
}

/// `raylemma check fresnel`.
#[derive(Args, Debug)]
pub struct FresnelArgs {
    #[command(flatten)]
    pub from: FunctionArgs,
    /// Evenly spaced angles of incidence from 0 to 90 degrees [default: 361].
    #[arg(long, value_parser = clap::value_parser!(u64).range(2..))]
    pub cases: Option<u64>,
}

/// `raylemma check refraction`.
#[derive(Args, Debug)]
pub struct RefractionArgs {
    #[command(flatten)]
    pub from: FunctionArgs,
    /// Random incident directions [default: 20000].
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
    pub cases: Option<u64>,
    /// Seed of the directions.
    #[arg(long)]
    pub seed: Option<u64>,
}

fn parse_target(name: &str) -> Result<Target, String> {
    name.parse()
}

fn parse_domain(name: &str) -> Result<Domain, String> {
    external::domain_named(name)
}

fn parse_alpha(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(a) if a > 0.0 && a < 1.0 => Ok(a),
        _ => Err(format!("`{text}` is not a level between 0 and 1")),
    }
}

fn parse_seconds(text: &str) -> Result<Duration, String> {
    text.parse::<f64>()
        .ok()
        .filter(|s| *s > 0.0)
        .and_then(|s| Duration::try_from_secs_f64(s).ok())
        .ok_or_else(|| format!("`{text}` is not a positive number of seconds"))
}

impl FunctionArgs {
    /// The flags as the library's [`FunctionCheck`].
    fn check(&self) -> FunctionCheck<'_> {
        FunctionCheck {
            program: self.program.as_deref(),
            table: self.table.as_deref(),
            questions: self.questions.as_deref(),
            timeout: self.timeout,
        }
    }
}

/// Runs `raylemma check`: pass (0), fail (1), bad input (2).
pub fn run(command: &CheckCmd) -> CmdResult {
    let checked = match command {
        CheckCmd::Sampler(args) => external::check_sampler(&SamplerCheck {
            program: args.program.as_deref(),
            samples: args.samples.as_deref(),
            target: args.target,
            domain: args.domain,
            inverse: args.inverse,
            cases: args.cases,
            seed: args.seed,
            alpha: args.alpha,
            timeout: args.timeout,
            failure_images: args.failure_images.as_deref(),
        })
        .map_err(Failure::from),
        CheckCmd::Fresnel(args) => {
            external::check_fresnel(&args.from.check(), args.cases).map_err(Failure::from)
        }
        CheckCmd::Corpus(args) => external::check_corpora(
            &args.files,
            args.program.as_deref(),
            &args.verbs,
            args.timeout,
        )
        .map_err(Failure::from),
        CheckCmd::Refraction(args) => {
            external::check_refraction(&args.from.check(), args.cases, args.seed)
                .map_err(Failure::from)
        }
    }?;
    Ok(match checked {
        Checked::Passed | Checked::QuestionsWritten => Outcome::Done,
        Checked::Failed => Outcome::Negative,
    })
}
