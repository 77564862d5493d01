//! Checkers: the coursework interface.
//!
//! A checker takes *any* implementation of a derivation (a closure or function with the
//! right signature), runs the numerical checks of its chapter on it, and returns a
//! [`Verdict`]: one [`Finding`] per claim, each saying how many cases were tried, how many
//! failed, the worst error against its bound, and the first counterexample.
//!
//! Every checker is called the same way, with the implementation under test and one
//! [`Options`]:
//!
//! ```rust,ignore
//! use raylemma::check::{self, Options};
//! check::sphere::intersection(&my_intersect, &Options::default()).assert_pass();
//! check::sphere::far(&my_intersect, &Options::default()).assert_pass();
//! check::warp::check(&my_sampler, &Options::default().cases(400_000)).assert_pass();
//! check::reflect::reflection(&my_reflect, &Options::default()).assert_pass();
//! check::reflect::refraction(&my_refract, &Options::default().seed(7)).assert_pass();
//! check::fresnel::reflectance(&my_fresnel, &Options::default()).assert_pass();
//! ```
//!
//! One module per concept checked, each with its planted bugs beside it (`planted`):
//!
//! * [`accuracy`]: every numerical routine on a corpus of hard inputs against exact
//!   arithmetic (*Accuracy against exact arithmetic*; `raylemma check corpus`);
//! * [`sphere`]: ray-sphere intersection (*Ray-sphere intersection*);
//! * [`warp`]: any sampler and the pdf it claims (*Checking a sampler*);
//! * [`reflect`]: mirror reflection and Snell refraction (*Reflection and refraction*);
//! * [`fresnel`]: dielectric reflectance (*Fresnel and Schlick*);
//! * [`single`]: the single-precision accuracy of a warp (the `f32` columns of the
//!   sampling chapters);
//! * [`external`]: the same checkers on an implementation outside Rust, a program that
//!   answers questions over a pipe or a file of values (*Checks from any language*;
//!   `raylemma check`).
//! * [`importance`]: the importance-sampling estimator (*Importance sampling*);
//! * [`tabulated`]: the inverse CDF of a piecewise-constant table (*Tabulated
//!   distributions*);
//! * [`specular`]: a narrow lobe standing in for the mirror's delta (*The missing cosine*);
//! * [`dispersion`]: the Sellmeier equation (*Dispersion*);
//! * [`thinfilm`]: the Airy sum (*Thin-film interference*);
//! * [`lambert`]: the Lambertian BRDF (*Lambertian reflectance*);
//! * [`roulette`]: Russian roulette (*Russian roulette*);
//! * [`shadow`]: the change of variables from area to solid angle (*Shadow-ray pdfs*);
//! * [`wavelength`]: uniform hero wavelengths (*Wavelength sampling*);
//! * [`display`]: the sRGB transfer curve (*From spectrum to display*);
//! * [`render`]: the path tracer against images known exactly, its estimators against one
//!   another, its canonical scenes against their references (*Testing the renderer*,
//!   *Reference scenes and interop*; the conformance ladder is [`crate::conformance`]).
//!
//! [`max_abs`] is shared by all of them. The sphere checker's [`crate::real::Real`] (a
//! scalar, `f32` or `f64`, with its vector, ray and sphere, so that one checker serves both
//! precisions) lives beside the precisions it chooses between.
//!
//! The report card of the student edition ([`crate::exercise::card`]) runs these on the
//! crate's own functions, one exercise at a time.
//!
//! The project's own tests call the same checkers on the project's code (which must pass)
//! and on the planted bugs (which must fail), so a student's implementation is held to
//! exactly the standard the book's code is.

pub mod accuracy;
pub mod dispersion;
pub mod display;
pub mod external;
pub mod fresnel;
pub mod importance;
pub mod lambert;
pub mod pictures;
pub mod reflect;
pub mod render;
pub mod roulette;
pub mod shadow;
pub mod single;
pub mod specular;
pub mod sphere;
pub mod tabulated;
pub mod thinfilm;
pub mod warp;
pub mod wavelength;

/// Re-exported from [`crate::numeric`], where the derivations find it too.
pub use crate::numeric::max_abs;

use std::fmt;

// ANCHOR: options
/// How thoroughly to check: the one options value every checker takes.
///
/// Each field left unset takes the checker's own documented default, so that
/// `Options::default()` runs every checker at its documented settings:
///
/// * `cases`: the number of cases per claim (for a statistical claim, the number of
///   samples). Defaults: [`sphere::CASES`], [`sphere::FAR_RAYS`],
///   [`sphere::SELF_HIT_RAYS`], [`warp::SAMPLES`], [`reflect::CASES`], [`fresnel::ANGLES`],
///   [`single::POINTS`]. The renderer's checks render images instead of drawing cases,
///   and there `cases` is how many samples: a percentage of each scene's own samples per
///   pixel for the exact images and the independence check ([`render::exact()`],
///   [`render::independence::independence`]: default 100), the samples per pixel
///   themselves for the comparisons of estimators and of the references' windows
///   ([`render::agreement`], [`render::depths`]: 64; [`render::references`]: 32).
/// * `seed`: the seed of the random cases. Defaults: [`sphere::SEED`],
///   [`sphere::SELF_HIT_SEED`], [`warp::SEED`], [`reflect::REFLECTION_SEED`],
///   [`reflect::REFRACTION_SEED`], [`single::SEED`]; the Fresnel sweep is deterministic
///   and has none.
/// * `alpha`: the significance level of the statistical claims (the warp checker's
///   chi-squared test). Default: the suite's Šidák-corrected level,
///   [`crate::stats::test_alpha`].
///
/// Built with `Options::default().cases(20_000).seed(3)`; read by each checker with
/// [`cases_or`](Options::cases_or), [`seed_or`](Options::seed_or) and
/// [`level`](Options::level).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Options {
    cases: Option<usize>,
    seed: Option<u64>,
    alpha: Option<f64>,
}
// ANCHOR_END: options

impl Options {
    /// Every field at the checker's default (the same as [`Options::default`], usable in a
    /// `const`).
    pub const fn new() -> Self {
        Self {
            cases: None,
            seed: None,
            alpha: None,
        }
    }

    /// The number of cases per claim (samples, for a statistical claim).
    pub const fn cases(mut self, cases: usize) -> Self {
        self.cases = Some(cases);
        self
    }

    /// The seed of the random cases.
    pub const fn seed(mut self, seed: u64) -> Self {
        self.seed = Some(seed);
        self
    }

    /// The significance level of the statistical claims.
    pub const fn alpha(mut self, alpha: f64) -> Self {
        self.alpha = Some(alpha);
        self
    }

    /// The number of cases, or the checker's `default`.
    pub fn cases_or(&self, default: usize) -> usize {
        self.cases.unwrap_or(default)
    }

    /// The seed, or the checker's `default`.
    pub fn seed_or(&self, default: u64) -> u64 {
        self.seed.unwrap_or(default)
    }

    /// The significance level: the one set, or the suite's [`crate::stats::test_alpha`].
    pub fn level(&self) -> f64 {
        self.alpha.unwrap_or_else(crate::stats::test_alpha)
    }
}

/// The outcome of one claim checked over many cases.
#[derive(Clone, Debug)]
pub struct Finding {
    /// Short identifier, e.g. `"hits"`; tests refer to findings by it.
    pub name: String,
    /// The claim, in words, as the chapter states it.
    pub claim: String,
    /// Number of cases tried.
    pub cases: usize,
    /// Number of cases that violated the claim.
    pub failures: usize,
    /// Worst measured error and its bound, when the claim is quantitative.
    pub worst: Option<(f64, f64)>,
    /// The first counterexample, described so a student can reproduce it.
    pub example: Option<String>,
    /// For a quantitative claim, the counterexample with the largest error (when it is not
    /// the first): the case that shows best how far off an implementation is.
    pub worst_example: Option<String>,
    /// The error of `worst_example`.
    worst_failure: f64,
    /// What `worst` and its bound measure, in words (`"relative error"`, `"multiples of
    /// machine epsilon"`); empty when the claim is not quantitative or its words say it.
    pub unit: &'static str,
    /// A picture of the failure that the checker wrote (the warp checker's folder of
    /// images), for the report card to name.
    pub picture: Option<String>,
}

impl Finding {
    /// Starts a finding with no cases yet.
    pub fn new(name: impl Into<String>, claim: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            claim: claim.into(),
            cases: 0,
            failures: 0,
            worst: None,
            example: None,
            worst_example: None,
            worst_failure: f64::NEG_INFINITY,
            unit: "",
            picture: None,
        }
    }

    /// The same finding, its errors measured in `unit` (words: `"relative error"`).
    pub fn in_unit(mut self, unit: &'static str) -> Self {
        self.unit = unit;
        self
    }

    /// Records one case; `describe` is called only for the first failure.
    pub fn record(&mut self, ok: bool, describe: impl FnOnce() -> String) {
        self.cases += 1;
        if !ok {
            self.failures += 1;
            if self.example.is_none() {
                self.example = Some(describe());
            }
        }
    }

    /// Records one quantitative case: passes iff `error <= bound` (NaN fails).
    pub fn measure(&mut self, error: f64, bound: f64, describe: impl FnOnce() -> String) {
        let worst = match self.worst {
            // A NaN anywhere stays visible in the report.
            Some((w, _)) if w.is_nan() || error.is_nan() => f64::NAN,
            Some((w, _)) => w.max(error),
            None => error,
        };
        self.worst = Some((worst, bound));
        if error <= bound {
            self.record(true, describe);
            return;
        }
        // A failure: describe it once, as the first and/or the worst counterexample.
        let first = self.example.is_none();
        let new_worst = !first
            && (error > self.worst_failure || error.is_nan())
            && !self.worst_failure.is_nan();
        if first || new_worst {
            let text = describe();
            if first {
                self.example = Some(text);
            } else {
                self.worst_example = Some(text);
            }
            self.worst_failure = error;
        }
        self.cases += 1;
        self.failures += 1;
    }

    /// A claim passes when it was tried at least once and never violated: a check that
    /// ran no case is a failure, never a silent pass.
    pub fn passed(&self) -> bool {
        self.cases > 0 && self.failures == 0
    }
}

/// The findings of one checker run on one implementation.
#[derive(Clone, Debug)]
pub struct Verdict {
    /// What was checked, e.g. `"sphere intersection (f32)"`.
    pub subject: String,
    /// One finding per claim.
    pub findings: Vec<Finding>,
}

impl Verdict {
    /// An empty verdict about `subject`.
    pub fn new(subject: impl Into<String>) -> Self {
        Self {
            subject: subject.into(),
            findings: Vec::new(),
        }
    }

    /// True iff every finding passed (and there is at least one).
    pub fn passed(&self) -> bool {
        !self.findings.is_empty() && self.findings.iter().all(Finding::passed)
    }

    /// The finding called `name`.
    ///
    /// # Panics
    /// If there is no such finding (a typo in a test should not pass silently).
    pub fn finding(&self, name: &str) -> &Finding {
        self.findings
            .iter()
            .find(|f| f.name == name)
            .unwrap_or_else(|| panic!("no finding named {name:?} in verdict on {}", self.subject))
    }

    /// True iff the finding called `name` failed.
    pub fn failed(&self, name: &str) -> bool {
        !self.finding(name).passed()
    }

    /// Panics with the whole report unless every finding passed. Use in tests.
    #[track_caller]
    pub fn assert_pass(&self) {
        assert!(self.passed(), "\n{self}");
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, out: &mut fmt::Formatter<'_>) -> fmt::Result {
        let verdict = if self.passed() { "PASS" } else { "FAIL" };
        writeln!(out, "{verdict}: {}", self.subject)?;
        for f in &self.findings {
            let mark = if f.passed() { "ok  " } else { "FAIL" };
            write!(
                out,
                "  [{mark}] {:<14} {:>6}/{:<6} cases failed",
                f.name, f.failures, f.cases
            )?;
            if let Some((worst, bound)) = f.worst {
                write!(out, "; worst error {worst:.3e} (bound {bound:.3e})")?;
                if !f.unit.is_empty() {
                    write!(out, ", as {}", f.unit)?;
                }
            }
            writeln!(out)?;
            writeln!(out, "         claim: {}", f.claim)?;
            if let Some(example) = &f.example {
                writeln!(out, "         first failure: {example}")?;
            }
            if let Some(example) = &f.worst_example {
                writeln!(out, "         worst failure: {example}")?;
            }
        }
        Ok(())
    }
}
