//! Accuracy against exact arithmetic: every numerical routine the book derives, run on a
//! corpus of hard inputs whose exact answers were computed at 256 bits from the same double
//! inputs (`tools/exact`, mpmath), with the problem's condition number at each input.
//! Chapter: *Accuracy against exact arithmetic* (`chapters/checking/accuracy.md`).
//!
//! An answer `y` to a case whose exact answer is `y*` (rounded to the precision: `ŷ`) is off
//! by
//!
//! ```text
//! ulps = |y - ŷ| / ulp(max(|ŷ|, scale))
//! ```
//!
//! units in the last place of the precision (`scale` is the verb's: 0 for a relative
//! measure, 1 for a direction's components or a reflectance, whose absolute error is what
//! matters where the value crosses 0). The problem's condition number `κ` (in the corpus,
//! also measured against `max(|y*|, scale)`) is how much the answer moves, relatively,
//! when the inputs move by one rounding each: a routine whose error is about `κ` ulps is as
//! good as its inputs allow (an ill-conditioned problem); one whose error is far larger
//! loses digits of its own (an unstable algorithm). The claim every routine the renderer
//! uses must meet on every case is
//!
//! ```text
//! ulps <= BOUND * max(κ, 1),   BOUND = 8.
//! ```
//!
//! A form the book keeps to show what goes wrong (a textbook formula) is expected to exceed
//! it somewhere ([`Expect::Exceeds`]); the tests hold both expectations.
//!
//! * [`corpus`]: the file format (`data/corpus/README.md`);
//! * [`forms`]: the crate's routines as answers to each corpus's questions, one file per
//!   corpus;
//! * [`planted`]: answers with the kind of mistake the claim must catch.
//!
//! The same claim is checked on another implementation's answers by `raylemma check
//! corpus --program CMD` ([`check_program`]).

pub mod corpus;
pub mod forms;
pub mod planted;

pub use corpus::{Case, Corpus, Exact, Verb};

use super::external::{Program, text};
use super::{Finding, Verdict};
use crate::data::DataError;

/// The claim's factor: an error of at most `BOUND * max(κ, 1)` ulps.
pub const BOUND: f64 = 8.0;

/// The precision a form computes in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// `f64`.
    Double,
    /// `f32` (a twin of `crate::single`): run only on cases whose inputs are all singles.
    Single,
}

impl Precision {
    /// `"f64"` or `"f32"`.
    pub fn name(self) -> &'static str {
        match self {
            Precision::Double => "f64",
            Precision::Single => "f32",
        }
    }
}

/// What the book says of a form.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expect {
    /// Within the bound on every case of its verb (the forms the renderer uses).
    Within,
    /// Beyond the bound on some case (a textbook form the chapter shows losing digits).
    Exceeds,
}

/// An answer: the outputs, or `None` for "no answer" (a miss, total internal reflection).
pub(crate) type Answer = Option<Vec<f64>>;

/// One form of a routine, as an answer to its verb's questions.
#[derive(Clone, Copy, Debug)]
pub struct Form {
    /// The verb it answers.
    pub verb: &'static str,
    /// Its name in the tables: `"stable"`, `"textbook"`, ...
    pub form: &'static str,
    /// The precision it computes in.
    pub precision: Precision,
    /// What the book says of it.
    pub expect: Expect,
    /// The routine, from the case's arguments (already checked to be singles for
    /// [`Precision::Single`]; the form converts them).
    pub eval: fn(&[f64]) -> Answer,
}

impl Form {
    /// A form of `verb` named `form`, in `precision`, with what the book says of it.
    pub const fn new(
        verb: &'static str,
        form: &'static str,
        precision: Precision,
        expect: Expect,
        eval: fn(&[f64]) -> Answer,
    ) -> Form {
        Form {
            verb,
            form,
            precision,
            expect,
            eval,
        }
    }

    /// The renderer's own routine for `verb`: `"stable"`, in `f64`, held within the bound.
    pub const fn stable(verb: &'static str, eval: fn(&[f64]) -> Answer) -> Form {
        Form::new(verb, "stable", Precision::Double, Expect::Within, eval)
    }

    /// Its `f32` twin, held within the bound.
    pub const fn single(verb: &'static str, eval: fn(&[f64]) -> Answer) -> Form {
        Form::new(verb, "stable", Precision::Single, Expect::Within, eval)
    }

    /// This form as the textbook formula a chapter keeps to show a loss: named
    /// `"textbook"` and expected to exceed the bound somewhere.
    pub const fn textbook(self) -> Form {
        Form {
            form: "textbook",
            expect: Expect::Exceeds,
            ..self
        }
    }

    /// `"stable, f64"`.
    pub fn label(&self) -> String {
        format!("{}, {}", self.form, self.precision.name())
    }
}

/// The spacing of the precision's numbers at `|v|` (the smallest subnormal at 0).
pub fn ulp(v: f64, precision: Precision) -> f64 {
    let (digits, tiny) = match precision {
        Precision::Double => (52, f64::from_bits(1)),
        Precision::Single => (23, f64::from(f32::from_bits(1))),
    };
    let v = v.abs();
    if !v.is_finite() {
        return f64::NAN;
    }
    if v < f64::MIN_POSITIVE {
        return tiny;
    }
    // The binade of v, 2^e: its exponent field alone (exact, unlike log2), then scaled by
    // 2^-digits, exactly (a power of two at least 2^-1074); `powi` would overflow to 0
    // in 1 / 2^(digits - e) for e below about -970.
    let binade = f64::from_bits(v.to_bits() & (0x7ff << 52));
    (binade * (2f64).powi(-digits)).max(tiny)
}

/// One case's measured error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    /// The case's index in its corpus.
    pub case: usize,
    /// The error in ulps (the worst output's); infinite for a wrong kind of answer (a
    /// number where the exact answer is none, or the reverse) or a NaN.
    pub ulps: f64,
    /// The condition number of that output (0 where both answers are none).
    pub condition: f64,
    /// The largest `ulps / max(κ, 1)` over the outputs: the claim holds iff it is at most
    /// [`BOUND`].
    pub ratio: f64,
}

/// The error of `answer` to `case`, measured in `precision`.
pub fn measure_one(
    case: &Case,
    index: usize,
    verb: &Verb,
    answer: &Answer,
    precision: Precision,
) -> Measured {
    let wrong = Measured {
        case: index,
        ulps: f64::INFINITY,
        condition: f64::INFINITY,
        ratio: f64::INFINITY,
    };
    let right_kind = Measured {
        case: index,
        ulps: 0.0,
        condition: f64::INFINITY,
        ratio: 0.0,
    };
    match (&case.exact, answer) {
        // One rounding of an input changes the kind of answer: both kinds are right.
        (None, Some(_)) | (Some(_), None) if case.undecided => right_kind,
        (None, None) => Measured {
            case: index,
            ulps: 0.0,
            condition: 0.0,
            ratio: 0.0,
        },
        (Some(exact), Some(y)) if exact.len() == y.len() => {
            let mut worst = Measured {
                case: index,
                ulps: 0.0,
                condition: 0.0,
                ratio: 0.0,
            };
            for (e, &y) in exact.iter().zip(y) {
                let rounded = match precision {
                    Precision::Double => e.double,
                    Precision::Single => f64::from(e.single),
                };
                let unit = ulp(rounded.abs().max(verb.scale), precision);
                let ulps = (y - rounded).abs() / unit;
                let ulps = if ulps.is_nan() { f64::INFINITY } else { ulps };
                let condition = match precision {
                    Precision::Double => e.condition,
                    Precision::Single => e.condition_single.unwrap_or(f64::INFINITY),
                };
                let ratio = ulps / condition.max(1.0);
                if ratio > worst.ratio || (ratio == worst.ratio && ulps > worst.ulps) {
                    worst = Measured {
                        case: index,
                        ulps,
                        condition,
                        ratio,
                    };
                }
            }
            worst
        }
        _ => wrong,
    }
}

/// True iff every argument of `case` is a single (so that an `f32` form answers the same
/// question).
pub(crate) fn single_inputs(case: &Case) -> bool {
    case.args.iter().all(|&x| f64::from(x as f32) == x)
}

/// The errors of `answer` on the cases of `verb` in `corpus` (for [`Precision::Single`],
/// those whose inputs are singles).
pub fn measure(
    corpus: &Corpus,
    verb: &str,
    precision: Precision,
    answer: impl Fn(&Case) -> Answer,
) -> Vec<Measured> {
    let Some(v) = corpus.verb(verb) else {
        return Vec::new();
    };
    corpus
        .cases
        .iter()
        .enumerate()
        .filter(|(_, c)| c.verb == verb)
        .filter(|(_, c)| precision == Precision::Double || single_inputs(c))
        .map(|(i, c)| measure_one(c, i, v, &answer(c), precision))
        .collect()
}

/// The errors of `form` on its verb's cases.
pub fn measure_form(corpus: &Corpus, form: &Form) -> Vec<Measured> {
    measure(corpus, form.verb, form.precision, |c| (form.eval)(&c.args))
}

/// A table row's numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Summary {
    /// Cases measured.
    pub cases: usize,
    /// The median error (ulps).
    pub median: f64,
    /// The worst error (ulps) and where.
    pub worst: Measured,
    /// The worst `ulps / max(κ, 1)` and where.
    pub worst_ratio: Measured,
}

/// The summary of `measured` (`None` if empty).
pub fn summarize(measured: &[Measured]) -> Option<Summary> {
    let mut ulps: Vec<f64> = measured.iter().map(|m| m.ulps).collect();
    ulps.sort_by(f64::total_cmp);
    let median = *ulps.get(ulps.len() / 2)?;
    let by = |key: fn(&Measured) -> f64| {
        *measured
            .iter()
            .max_by(|a, b| key(a).total_cmp(&key(b)))
            .expect("not empty")
    };
    Some(Summary {
        cases: measured.len(),
        median,
        worst: by(|m| m.ulps),
        worst_ratio: by(|m| m.ratio),
    })
}

/// `[1, 2, 3]` as `1 2 3` with every digit; `none` for no answer.
pub(crate) fn answer_text(answer: &Answer) -> String {
    match answer {
        None => "none".to_string(),
        Some(y) => y
            .iter()
            .map(|v| format!("{v:?}"))
            .collect::<Vec<_>>()
            .join(" "),
    }
}

fn exact_text(case: &Case) -> String {
    match &case.exact {
        None => "none".to_string(),
        Some(e) => e
            .iter()
            .map(|e| e.text.as_str())
            .collect::<Vec<_>>()
            .join(" "),
    }
}

/// The finding of the claim on the cases of `verb` answered by `answer`.
fn finding(
    corpus: &Corpus,
    name: String,
    verb: &str,
    precision: Precision,
    answer: impl Fn(&Case) -> Answer,
) -> Finding {
    let mut f = Finding::new(
        name,
        format!(
            "on every hard input of {} the error is at most {BOUND} ulps times the problem's \
             condition number (at least 1), against the exact answer",
            corpus.file
        ),
    )
    .in_unit("ulps per unit of condition number");
    for m in measure(corpus, verb, precision, &answer) {
        let case = &corpus.cases[m.case];
        f.measure(m.ratio, BOUND, || {
            format!(
                "{}:{} ({}): `{}` answered {}, exact {}: {:.3e} ulps, condition {:.3e}",
                corpus.file,
                case.line,
                case.why,
                case.question,
                answer_text(&answer(case)),
                exact_text(case),
                m.ulps,
                m.condition
            )
        });
    }
    f
}

/// The claim on the crate's `forms` (each a finding named `verb/form, precision`).
pub fn check_forms(corpus: &Corpus, forms: &[Form]) -> Verdict {
    let mut verdict = Verdict::new(format!("accuracy on {}", corpus.file));
    for form in forms {
        verdict.findings.push(finding(
            corpus,
            format!("{}/{}", form.verb, form.label()),
            form.verb,
            form.precision,
            |c| (form.eval)(&c.args),
        ));
    }
    verdict
}

/// The claim on an answer given as a closure (for a Rust implementation of some verbs of
/// a corpus): one finding per verb in `verbs`.
pub fn check(
    corpus: &Corpus,
    verbs: &[&str],
    precision: Precision,
    answer: impl Fn(&Case) -> Answer,
) -> Verdict {
    let mut verdict = Verdict::new(format!("accuracy on {}", corpus.file));
    for verb in verbs {
        verdict.findings.push(finding(
            corpus,
            (*verb).to_string(),
            verb,
            precision,
            &answer,
        ));
    }
    verdict
}

/// Reads a program's answer line: `none`, or one number per output (the protocol's
/// fields and numbers, [`super::external`]).
fn read_answer(line: &str, verb: &Verb) -> Result<Answer, String> {
    let fields = text::fields(line);
    if fields == ["none"] {
        return Ok(None);
    }
    if fields.len() != verb.outs.len() {
        return Err(format!(
            "`{line}` should be `none` or {} number(s) ({})",
            verb.outs.len(),
            verb.outs.join(" ")
        ));
    }
    fields
        .iter()
        .map(|f| text::number(f).map_err(|e| format!("`{line}` {e}")))
        .collect::<Result<Vec<f64>, String>>()
        .map(Some)
}

/// The claim on a program's answers: every case of the corpus's `verbs` (all, if empty) is
/// asked in one run, the question as the corpus writes it (`fresnel 0.5 1.0 1.5`); the
/// program answers `none` or the outputs, one line per question.
///
/// # Errors
/// A [`DataError`]: an unknown verb, a program that cannot be run, or an answer that cannot
/// be read (naming the question's corpus line).
pub fn check_program(
    corpus: &Corpus,
    verbs: &[String],
    program: &Program,
) -> Result<Verdict, DataError> {
    let chosen: Vec<&Verb> = if verbs.is_empty() {
        corpus.verbs.iter().collect()
    } else {
        let mut chosen = Vec::new();
        for v in verbs {
            let verb = corpus.verb(v).ok_or_else(|| {
                let known: Vec<&str> = corpus.verbs.iter().map(|v| v.name.as_str()).collect();
                DataError::new(
                    &corpus.file,
                    0,
                    format!("no verb `{v}` in this corpus (it has {})", known.join(", ")),
                )
            })?;
            chosen.push(verb);
        }
        chosen
    };
    let asked: Vec<usize> = (0..corpus.cases.len())
        .filter(|&i| chosen.iter().any(|v| v.name == corpus.cases[i].verb))
        .collect();
    let questions: Vec<String> = asked
        .iter()
        .map(|&i| corpus.cases[i].question.clone())
        .collect();
    let lines = program.ask(&questions, 1)?;
    let mut answers: Vec<Option<Answer>> = vec![None; corpus.cases.len()];
    for (&i, line) in asked.iter().zip(&lines) {
        let case = &corpus.cases[i];
        let verb = corpus.verb(&case.verb).expect("declared");
        let answer = read_answer(line, verb).map_err(|e| {
            DataError::new(
                &program.output_name(),
                0,
                format!(
                    "the answer to `{}` ({}:{}): {e}",
                    case.question, corpus.file, case.line
                ),
            )
        })?;
        answers[i] = Some(answer);
    }
    let names: Vec<&str> = chosen.iter().map(|v| v.name.as_str()).collect();
    // Cases are told apart by their line, which is unique in a corpus.
    let by_line: std::collections::HashMap<usize, Answer> = corpus
        .cases
        .iter()
        .zip(answers)
        .filter_map(|(c, a)| a.map(|a| (c.line, a)))
        .collect();
    let mut verdict = check(corpus, &names, Precision::Double, |c| {
        by_line.get(&c.line).cloned().flatten()
    });
    verdict.subject = format!("accuracy of `{}` on {}", program.command, corpus.file);
    Ok(verdict)
}
