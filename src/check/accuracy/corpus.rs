//! The file format of a corpus of hard inputs (`data/corpus/*.txt`, described in
//! `data/corpus/README.md`): verbs declared with their arguments, outputs and scale, then
//! cases, each a line saying why it is hard and a line with the question, its exact answer
//! and the problem's condition number. Chapter: *Accuracy against exact arithmetic*.

use std::path::Path;

use crate::data::{DataError, read_text};

/// A routine's question and answer shape, as the corpus declares it:
/// `verb NAME ARG... -> OUT... ; scale S ; what it computes`.
#[derive(Clone, Debug, PartialEq)]
pub struct Verb {
    /// The verb, e.g. `fresnel`.
    pub name: String,
    /// The arguments' names; a last name ending in `...` takes any number of numbers.
    pub args: Vec<String>,
    /// The outputs' names.
    pub outs: Vec<String>,
    /// The output's scale: errors are counted in units in the last place of
    /// `max(|exact|, scale)` (0: of the exact value itself).
    pub scale: f64,
    /// What the routine computes, in words.
    pub doc: String,
}

/// One output's exact answer.
#[derive(Clone, Debug, PartialEq)]
pub struct Exact {
    /// As written (25 significant digits).
    pub text: String,
    /// Rounded to the nearest double.
    pub double: f64,
    /// Rounded to the nearest single.
    pub single: f32,
    /// The problem's condition number for this output: how far (relatively to
    /// `max(|y|, scale)`, in units of the rounding) the exact answer moves when each input
    /// moves by one rounding of a double; for a smooth routine
    /// `sum_i |x_i dy/dx_i| / max(|y|, scale)`. Infinite where one rounding changes the kind
    /// of answer.
    pub condition: f64,
    /// The same for one rounding of a single, when every input is a single.
    pub condition_single: Option<f64>,
}

/// One hard input.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// The line of the question (from 1).
    pub line: usize,
    /// Why the input is hard.
    pub why: String,
    /// The verb.
    pub verb: String,
    /// The question as written: the verb and its numbers, which read back exactly.
    pub question: String,
    /// The arguments.
    pub args: Vec<f64>,
    /// The exact answer, one per output, or `None`: no answer (a miss, total internal
    /// reflection).
    pub exact: Option<Vec<Exact>>,
    /// True when one rounding of an input changes the kind of answer (`none` for a number,
    /// or the reverse): either kind is then a right answer for the rounded inputs.
    pub undecided: bool,
}

/// A corpus file.
#[derive(Clone, Debug, PartialEq)]
pub struct Corpus {
    /// The file's name as given (e.g. `data/corpus/fresnel.txt`).
    pub file: String,
    /// Its name without folder or extension (e.g. `fresnel`).
    pub name: String,
    /// The verbs, in the order declared.
    pub verbs: Vec<Verb>,
    /// The cases, in file order.
    pub cases: Vec<Case>,
}

impl Corpus {
    /// The verb called `name`, if declared.
    pub fn verb(&self, name: &str) -> Option<&Verb> {
        self.verbs.iter().find(|v| v.name == name)
    }

    /// The cases of the verb `name`.
    pub fn cases_of<'c>(&'c self, name: &'c str) -> impl Iterator<Item = &'c Case> + 'c {
        self.cases.iter().filter(move |c| c.verb == name)
    }
}

fn finite(field: &str, what: &str) -> Result<f64, String> {
    match field.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(format!("{what} `{field}` is not a finite number")),
    }
}

fn verb_line(rest: &str) -> Result<Verb, String> {
    let mut parts = rest.splitn(3, " ; ");
    let shape = parts.next().unwrap_or("");
    let scale = parts
        .next()
        .and_then(|s| s.strip_prefix("scale "))
        .ok_or("a verb line is `verb NAME ARG... -> OUT... ; scale S ; what it computes`")?;
    let doc = parts.next().unwrap_or("").to_string();
    let (args, outs) = shape
        .split_once(" -> ")
        .ok_or("a verb line needs ` -> ` between its arguments and its outputs")?;
    let mut args = args.split_whitespace().map(str::to_string);
    let name = args.next().ok_or("a verb line needs a name")?;
    let args: Vec<String> = args.collect();
    let outs: Vec<String> = outs.split_whitespace().map(str::to_string).collect();
    if outs.is_empty() {
        return Err(format!("the verb {name} has no outputs"));
    }
    let scale = finite(scale.trim(), "the scale")?;
    if scale < 0.0 {
        return Err(format!("the verb {name} has a negative scale"));
    }
    Ok(Verb {
        name,
        args,
        outs,
        scale,
        doc,
    })
}

/// A case line's verb, arguments, exact answer and whether the kind of answer is undecided.
type Parsed = (String, Vec<f64>, Option<Vec<Exact>>, bool);

fn case_line(line: &str, verbs: &[Verb]) -> Result<Parsed, String> {
    let (question, answer) = line
        .split_once(" = ")
        .ok_or("a case is `VERB X... = Y... @ C...` or `VERB X... = none`")?;
    let mut fields = question.split_whitespace();
    let name = fields.next().unwrap_or("");
    let verb = verbs
        .iter()
        .find(|v| v.name == name)
        .ok_or_else(|| format!("`{name}` is not a verb declared above this line"))?;
    let args = fields
        .map(|f| finite(f, "the argument"))
        .collect::<Result<Vec<f64>, String>>()?;
    let variadic = verb.args.last().is_some_and(|a| a.ends_with("..."));
    let fixed = verb.args.len() - usize::from(variadic);
    if args.len() < fixed || (!variadic && args.len() != fixed) {
        return Err(format!(
            "{name} takes {} argument{} ({}), this case has {}",
            verb.args.len(),
            if verb.args.len() == 1 { "" } else { "s" },
            verb.args.join(" "),
            args.len()
        ));
    }
    match answer.trim() {
        "none" => return Ok((name.to_string(), args, None, false)),
        "none @ inf" => return Ok((name.to_string(), args, None, true)),
        _ => {}
    }
    let mut groups = answer.split(" @ ");
    let values: Vec<&str> = groups.next().unwrap_or("").split_whitespace().collect();
    let conds: Vec<&str> = groups
        .next()
        .ok_or("an answer is `Y... @ C...`: the exact outputs, then their condition numbers")?
        .split_whitespace()
        .collect();
    let singles: Option<Vec<&str>> = groups.next().map(|g| g.split_whitespace().collect());
    if groups.next().is_some() {
        return Err("an answer has at most two groups of condition numbers".into());
    }
    let outs = verb.outs.len();
    if values.len() != outs
        || conds.len() != outs
        || singles.as_ref().is_some_and(|s| s.len() != outs)
    {
        return Err(format!(
            "{name} has {outs} output{} ({}), this case gives {} value(s) and {} condition number(s)",
            if outs == 1 { "" } else { "s" },
            verb.outs.join(" "),
            values.len(),
            conds.len()
        ));
    }
    let condition = |c: &str| match c {
        "inf" => Ok(f64::INFINITY),
        c => finite(c, "the condition number").and_then(|x| {
            if x < 0.0 {
                Err(format!("the condition number `{c}` is negative"))
            } else {
                Ok(x)
            }
        }),
    };
    let mut exact = Vec::new();
    for (k, (v, c)) in values.iter().zip(&conds).enumerate() {
        let double = finite(v, "the exact value")?;
        let single: f32 = v
            .parse()
            .map_err(|_| format!("the exact value `{v}` is not a number"))?;
        exact.push(Exact {
            text: (*v).to_string(),
            double,
            single,
            condition: condition(c)?,
            condition_single: singles.as_ref().map(|s| condition(s[k])).transpose()?,
        });
    }
    let undecided = exact
        .iter()
        .any(|e| e.condition.is_infinite() || e.condition_single.is_some_and(f64::is_infinite));
    Ok((name.to_string(), args, Some(exact), undecided))
}

/// Reads a corpus from its text; `file` names it in errors.
///
/// # Errors
/// A [`DataError`] with the line: a verb line or a case that does not parse, a case of an
/// undeclared verb or with the wrong number of arguments or outputs, a number that is not
/// finite, a case without a `#` line before it saying why it is hard, or no case at all.
pub fn parse(text: &str, file: &str) -> Result<Corpus, DataError> {
    let name = Path::new(file)
        .file_stem()
        .map_or_else(|| file.to_string(), |s| s.to_string_lossy().into_owned());
    let mut corpus = Corpus {
        file: file.to_string(),
        name,
        verbs: Vec::new(),
        cases: Vec::new(),
    };
    let mut why: Option<String> = None;
    for (i, line) in text.lines().enumerate() {
        let at = |problem: String| DataError::new(file, i + 1, problem);
        let line = line.trim_end();
        if line.is_empty() {
            why = None;
        } else if let Some(comment) = line.strip_prefix('#') {
            why = Some(comment.trim().to_string());
        } else if let Some(rest) = line.strip_prefix("verb ") {
            let verb = verb_line(rest).map_err(at)?;
            if corpus.verb(&verb.name).is_some() {
                return Err(at(format!("the verb {} is declared twice", verb.name)));
            }
            corpus.verbs.push(verb);
        } else {
            let (verb, args, exact, undecided) = case_line(line, &corpus.verbs).map_err(at)?;
            let why = why.take().ok_or_else(|| {
                at(
                    "a case needs a `# ...` line just before it saying why the input is hard"
                        .into(),
                )
            })?;
            let question = line.split(" = ").next().unwrap_or("").to_string();
            corpus.cases.push(Case {
                line: i + 1,
                why,
                verb,
                question,
                args,
                exact,
                undecided,
            });
        }
    }
    if corpus.cases.is_empty() {
        return Err(DataError::new(file, 0, "the corpus has no case"));
    }
    Ok(corpus)
}

/// Reads the corpus at `path`.
///
/// # Errors
/// As [`parse`], and if the file cannot be read.
pub fn load(path: &Path) -> Result<Corpus, DataError> {
    let (text, name) = read_text(path)?;
    parse(&text, &name)
}

/// The corpora of the project (`data/corpus/*.txt` under `root`), sorted by name.
///
/// # Errors
/// If the folder or a file cannot be read or parsed.
pub fn load_all(root: &Path) -> Result<Vec<Corpus>, DataError> {
    let dir = root.join("data/corpus");
    let name = dir.display().to_string();
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .map_err(|e| DataError::new(&name, 0, format!("cannot read the folder: {e}")))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "txt"))
        .collect();
    paths.sort();
    paths.iter().map(|p| load(p)).collect()
}
