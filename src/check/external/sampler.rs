//! Samplers outside Rust, checked by the warp checker ([`crate::check::warp`]) like any
//! other: a program that answers `warp` questions (and `pdf` and `invert` ones) is a
//! [`Warp`] whose methods look up its answers; a file of samples is a [`Warp`] that hands
//! out its rows. Chapter: *Checks from any language*.

use std::fmt;
use std::path::PathBuf;
use std::str::FromStr;
use std::sync::atomic::{AtomicUsize, Ordering};

use glam::{DVec2, DVec3};

use super::Program;
use super::memo::{Ask, Memo, Source, rounds};
use super::text::{as_strs, csv_rows, numbers};
use crate::check::warp::{self, Domain, ToWarpOptions, Warp, WarpOptions, square_point};
use crate::check::{Options, Verdict};
use crate::data::DataError;
use crate::rng::Rng;
use crate::sampling::cosine::cosine_pdf;
use crate::sampling::disc::disc_pdf;
use crate::sampling::sphere::{hemisphere_pdf, sphere_pdf};

/// The densities of the book a sampler can claim by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// `1 / (4 pi)` on the unit sphere (chapter *Uniform sphere and hemisphere*).
    UniformSphere,
    /// `1 / (2 pi)` on the hemisphere `z >= 0` (same chapter).
    UniformHemisphere,
    /// `cos(theta) / pi = z / pi` on the hemisphere `z >= 0` (chapter *Cosine-weighted
    /// hemisphere*).
    CosineHemisphere,
    /// `1 / pi` on the unit disc, points `(x, y, 0)` (chapter *The unit disc*).
    Disc,
    /// 1 on the unit square `[0, 1]^2`, points `(x, y, 0)`.
    Square,
}

impl Target {
    /// Every target, in the order `--help` lists them.
    pub const ALL: [Target; 5] = [
        Target::UniformSphere,
        Target::UniformHemisphere,
        Target::CosineHemisphere,
        Target::Disc,
        Target::Square,
    ];

    /// The target's name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Target::UniformSphere => "uniform-sphere",
            Target::UniformHemisphere => "uniform-hemisphere",
            Target::CosineHemisphere => "cosine-hemisphere",
            Target::Disc => "disc",
            Target::Square => "square",
        }
    }

    /// The domain of its samples.
    pub fn domain(self) -> Domain {
        match self {
            Target::UniformSphere | Target::UniformHemisphere | Target::CosineHemisphere => {
                Domain::Sphere
            }
            Target::Disc => Domain::Disc,
            Target::Square => Domain::Square,
        }
    }

    /// Its domain in its own words, for messages: "the sphere", "the hemisphere", "the
    /// disc", "the square" (a hemisphere's samples are checked on the sphere, with a pdf
    /// of zero below, but a sample off it is outside the hemisphere to its writer).
    pub fn words(self) -> &'static str {
        match self {
            Target::UniformSphere => "the sphere",
            Target::UniformHemisphere | Target::CosineHemisphere => "the hemisphere",
            Target::Disc => "the disc",
            Target::Square => "the square",
        }
    }

    /// Its density at `p` (per steradian on the sphere, per unit area on the disc and the
    /// square), with the library's own pdfs.
    pub fn pdf(self, p: DVec3) -> f64 {
        match self {
            Target::UniformSphere => sphere_pdf(p),
            Target::UniformHemisphere => hemisphere_pdf(p, DVec3::Z),
            Target::CosineHemisphere => cosine_pdf(p),
            Target::Disc => disc_pdf(p),
            Target::Square => {
                let inside = (0.0..=1.0).contains(&p.x) && (0.0..=1.0).contains(&p.y);
                if inside { 1.0 } else { 0.0 }
            }
        }
    }
}

impl fmt::Display for Target {
    fn fmt(&self, out: &mut fmt::Formatter<'_>) -> fmt::Result {
        out.write_str(self.name())
    }
}

impl FromStr for Target {
    type Err = String;
    fn from_str(name: &str) -> Result<Self, String> {
        Target::ALL
            .into_iter()
            .find(|t| t.name() == name)
            .ok_or_else(|| {
                let names: Vec<_> = Target::ALL.iter().map(|t| t.name()).collect();
                format!("unknown target `{name}`: one of {}", names.join(", "))
            })
    }
}

/// A domain by its command-line name: `sphere`, `disc` or `square`.
///
/// # Errors
/// The names it knows, for any other.
pub fn domain_named(name: &str) -> Result<Domain, String> {
    match name {
        "sphere" => Ok(Domain::Sphere),
        "disc" => Ok(Domain::Disc),
        "square" => Ok(Domain::Square),
        _ => Err(format!(
            "unknown domain `{name}`: one of sphere, disc, square"
        )),
    }
}

/// The density a program's samples are checked against.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Density {
    /// One of the book's, computed by the library.
    Target(Target),
    /// The program's own, answered to `pdf x y z` questions, on this domain.
    Program(Domain),
}

impl Density {
    fn domain(self) -> Domain {
        match self {
            Density::Target(t) => t.domain(),
            Density::Program(domain) => domain,
        }
    }

    /// Its domain in words: the target's own, or the domain's.
    fn words(self) -> String {
        match self {
            Density::Target(t) => t.words().into(),
            Density::Program(domain) => domain.words(),
        }
    }
}

/// A sampler outside Rust.
#[derive(Clone, Debug)]
pub enum Sampler {
    /// A program that answers `warp u1 u2` with its sample `x y z` (and `pdf x y z` with
    /// its density, for [`Density::Program`]; and `invert x y z` with `u1 u2` when
    /// `inverse`): the chi-squared, Jacobian and round-trip claims.
    Program {
        /// The program.
        program: Program,
        /// The density its samples should follow.
        density: Density,
        /// Whether it answers `invert` questions (the round trip).
        inverse: bool,
    },
    /// A CSV file of samples, one `x,y,z` a row (`x,y` on the disc and the square), drawn
    /// however the sampler likes: the chi-squared claim only, since there is no `u` to
    /// differentiate or invert.
    Samples {
        /// The file.
        path: PathBuf,
        /// The density its samples should follow.
        target: Target,
    },
}

/// The answers of a sampler program, one memo per kind of question.
struct Answers {
    warp: Memo<2, DVec3>,
    pdf: Memo<3, f64>,
    invert: Memo<3, DVec2>,
}

impl Answers {
    fn new(domain: Domain) -> Self {
        let flat = domain != Domain::Sphere;
        Self {
            warp: Memo::new("warp", Box::new(move |f| point(f, flat))),
            pdf: Memo::new("pdf", Box::new(|f| numbers::<1>(f, "`p`").map(|[p]| p))),
            invert: Memo::new(
                "invert",
                Box::new(|f| numbers::<2>(f, "`u1 u2`").map(DVec2::from)),
            ),
        }
    }

    fn all(&self) -> [&dyn Ask; 3] {
        [&self.warp, &self.pdf, &self.invert]
    }
}

/// A point: three numbers, or two (`z = 0`) on a flat domain.
fn point(fields: &[&str], flat: bool) -> Result<DVec3, String> {
    if flat && fields.len() == 2 {
        return numbers::<2>(fields, "`x y`").map(|[x, y]| DVec3::new(x, y, 0.0));
    }
    let what = if flat {
        "`x y z` (or `x y`)"
    } else {
        "`x y z`"
    };
    numbers::<3>(fields, what).map(DVec3::from)
}

/// A valid point of `domain`, the stand-in answer to a `warp` question not answered yet.
fn stand_in(domain: Domain) -> DVec3 {
    match domain {
        Domain::Sphere => DVec3::new(0.6, 0.0, 0.8),
        Domain::Disc => DVec3::new(0.5, 0.0, 0.0),
        Domain::Square => DVec3::new(0.5, 0.5, 0.0),
        Domain::Interval { lo, hi } => DVec3::new(0.5 * (lo + hi), 0.0, 0.0),
    }
}

// ANCHOR: program_warp
/// A program as a [`Warp`]: every method is a question to it, answered from the memos.
struct ProgramWarp<'a> {
    name: String,
    density: Density,
    inverse: bool,
    answers: &'a Answers,
}

impl Warp for ProgramWarp<'_> {
    fn name(&self) -> String {
        self.name.clone()
    }
    fn domain(&self) -> Domain {
        self.density.domain()
    }
    fn domain_words(&self) -> String {
        self.density.words()
    }
    /// The warp at a uniform point of the square: the same points, from the same seed, as
    /// a [`warp::SquareWarp`] draws.
    fn sample(&self, rng: &mut Rng) -> DVec3 {
        let u = square_point(rng);
        self.answers.warp.get(u.to_array(), stand_in(self.domain()))
    }
    fn pdf(&self, p: DVec3) -> f64 {
        match self.density {
            Density::Target(t) => t.pdf(p),
            Density::Program(_) => self.answers.pdf.get(p.to_array(), 1.0),
        }
    }
    fn warp(&self, u: DVec2) -> Option<DVec3> {
        Some(self.answers.warp.get(u.to_array(), stand_in(self.domain())))
    }
    fn invert(&self, p: DVec3) -> Option<DVec2> {
        self.inverse
            .then(|| self.answers.invert.get(p.to_array(), DVec2::splat(0.5)))
    }
}
// ANCHOR_END: program_warp

/// Samples read from a file, handed out in order; the density is a named target's.
struct SampleTable {
    name: String,
    target: Target,
    samples: Vec<DVec3>,
    next: AtomicUsize,
}

impl Warp for SampleTable {
    fn name(&self) -> String {
        self.name.clone()
    }
    fn domain(&self) -> Domain {
        self.target.domain()
    }
    fn domain_words(&self) -> String {
        self.target.words().into()
    }
    fn sample(&self, _rng: &mut Rng) -> DVec3 {
        let k = self.next.fetch_add(1, Ordering::Relaxed);
        self.samples.get(k).copied().unwrap_or(DVec3::NAN)
    }
    fn pdf(&self, p: DVec3) -> f64 {
        self.target.pdf(p)
    }
}

/// Reads a file of samples: one point a row, three numbers (two on the disc and the
/// square, for `z = 0`).
fn read_samples(path: &std::path::Path, target: Target) -> Result<SampleTable, DataError> {
    let (name, rows) = csv_rows(path)?;
    let flat = target.domain() != Domain::Sphere;
    let samples = rows
        .iter()
        .map(|(line, row)| {
            point(&as_strs(row), flat)
                .map_err(|why| DataError::new(&name, *line, format!("the sample {why}")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(SampleTable {
        name: format!("{name} ({target})"),
        target,
        samples,
        next: AtomicUsize::new(0),
    })
}

// ANCHOR: sampler
/// Checks a sampler outside Rust with the warp checker, [`warp::check`]: the same claims
/// and the same verdict as for a Rust sampler.
///
/// A [`Sampler::Program`] is asked `warp` questions at the points of the square the
/// checker chooses, from `options`' seed: the chi-squared samples (as many as `options`
/// says; `raylemma check` asks for [`SAMPLES`](super::SAMPLES)
/// unless told), the Jacobian's
/// central differences and the round trip's points; and `pdf` and `invert` questions as
/// its [`Density`] and `inverse` say. Every question the checker asks goes to the program
/// in a few runs (`rounds`, in `memo.rs`), and the verdict is the checker's on the
/// program's answers alone.
///
/// A [`Sampler::Samples`] file gets the chi-squared claim only, with its rows as the
/// samples (the number of samples is the number of rows, and the grid is the one the rule
/// of [`WarpOptions`] gives it; the level is `options`').
///
/// # Errors
/// A [`DataError`] for bad input: a row or an answer that is not a point or a number
/// (with its file or program and line), a program that cannot be run, ends early, fails
/// or hangs.
pub fn sampler(sampler: &Sampler, options: &impl ToWarpOptions) -> Result<Verdict, DataError> {
    let options = options.to_warp_options();
    match sampler {
        Sampler::Program {
            program,
            density,
            inverse,
        } => {
            let answers = Answers::new(density.domain());
            // One line, whatever the command's layout.
            let command = program
                .command
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" ");
            let name = match density {
                Density::Target(t) => format!("{command} ({t})"),
                Density::Program(d) => {
                    format!("{command} (its own pdf on {})", d.words())
                }
            };
            let warp = ProgramWarp {
                name,
                density: *density,
                inverse: *inverse,
                answers: &answers,
            };
            let source = Source::Program(program);
            // Collect the answers with the claims' side-effect-free parts, then the verdict
            // (whose failure images must show the program's answers, never a stand-in).
            rounds(&source, &answers.all(), || {
                let _ = warp::chi_squared(&warp, &options);
                let _ = warp::jacobian(&warp, &options);
                let _ = warp::round_trip(&warp, &options);
            })?;
            rounds(&source, &answers.all(), || warp::check(&warp, &options))
        }
        Sampler::Samples { path, target } => {
            let table = read_samples(path, *target)?;
            let rule = WarpOptions::from(&Options::new().cases(table.samples.len()));
            let options = WarpOptions {
                seed: options.seed,
                alpha: options.alpha,
                ..rule
            };
            let verdict = warp::check(&table, &options);
            let too_few = verdict.findings.iter().any(|f| {
                f.name == "chi_squared"
                    && f.example
                        .as_deref()
                        .is_some_and(|e| e.contains(crate::stats::error::DRAW_MORE))
            });
            if too_few {
                return Err(DataError::new(
                    &path.display().to_string(),
                    0,
                    format!(
                        "{} samples are too few to test: every cell of the chi-squared grid expects fewer than 5 of them; write more samples (a few thousand at least, {} by default)",
                        table.samples.len(),
                        super::SAMPLES
                    ),
                ));
            }
            Ok(verdict)
        }
    }
}
// ANCHOR_END: sampler
