//! The accuracy tables of chapter *Accuracy against exact arithmetic*: every form of every
//! routine on its corpus of hard inputs (`data/corpus/*.txt`), against the exact answers
//! made by `tools/exact` ([`raylemma::check::accuracy`]).

use std::fmt::Write as _;

use anyhow::Context;
use raylemma::check::accuracy::{self, BOUND, Expect, corpus, forms};
use raylemma_values::slug;

use crate::job::{Output, Record, Settings};

/// One table per corpus of [`forms::CORPORA`] (`accuracy_NAME.md`, the corpus named by its
/// file), and the summary of them all.
pub fn outputs() -> Vec<Output> {
    let mut outputs: Vec<Output> = forms::CORPORA
        .iter()
        .map(|name| Output {
            // A few names, made once for the life of the job.
            file: Box::leak(format!("accuracy_{name}.md").into_boxed_str()),
            what: "accuracy against exact arithmetic: one corpus",
            make: table,
        })
        .collect();
    outputs.push(Output {
        file: "accuracy_summary.md",
        what: "accuracy against exact arithmetic: every corpus",
        make: summary,
    });
    outputs
}

/// The corpus a table's file is for: `accuracy_NAME.md` is `NAME`.
fn corpus_of(r: &Record) -> anyhow::Result<&'static str> {
    let file = r.file();
    let name = file
        .strip_prefix("accuracy_")
        .and_then(|f| f.strip_suffix(".md"))
        .with_context(|| format!("{file} is not an accuracy table's file"))?;
    Ok(*forms::CORPORA
        .iter()
        .find(|c| **c == name)
        .with_context(|| format!("no corpus named {name}"))?)
}

/// Per corpus, in book order: its cases and routines, its forms and how many of the
/// renderer's are within the bound, the worst ratio among them, and the forms kept to show
/// a loss (which exceed it). The claim `every_shipped_form_within` covers every corpus.
fn summary(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::from(
        "| corpus | chapter | cases | routines | forms | forms held to the bound: within | their largest ulps / max(κ, 1) | forms that exceed (kept to show the loss) |\n|---|---|---:|---:|---:|---:|---:|---|\n",
    );
    let (mut all_within, mut cases) = (true, 0usize);
    for name in forms::CORPORA {
        let path = settings.root.join(format!("data/corpus/{name}.txt"));
        let corpus = corpus::load(&path)?;
        // The chapter, from the file's second line: `# Chapter: NAME (chapters/...)`.
        let text = std::fs::read_to_string(&path)?;
        let chapter = text
            .lines()
            .find_map(|l| l.strip_prefix("# Chapter: "))
            .and_then(|l| l.split(" (").next())
            .unwrap_or("?")
            .to_string();
        let forms =
            forms::of(name).with_context(|| format!("no forms answer the corpus {name}"))?;
        let (mut shipped, mut within, mut worst) = (0, 0, 0.0_f64);
        let mut exceed = Vec::new();
        for form in &forms {
            let s = accuracy::summarize(&accuracy::measure_form(&corpus, form))
                .with_context(|| format!("{name}: no case of {}", form.verb))?;
            let ok = s.worst_ratio.ratio <= BOUND;
            match form.expect {
                Expect::Within => {
                    shipped += 1;
                    within += usize::from(ok);
                    worst = worst.max(s.worst_ratio.ratio);
                }
                Expect::Exceeds => exceed.push(format!("`{}` {}", form.verb, form.label())),
            }
        }
        all_within &= within == shipped;
        cases += corpus.cases.len();
        writeln!(
            md,
            "| `{name}` | {chapter} | {} | {} | {} | {within} of {shipped} | {} | {} |",
            corpus.cases.len(),
            corpus.verbs.len(),
            forms.len(),
            ratio(r, &format!("{name}.worst_ratio"), worst),
            if exceed.is_empty() {
                "none".to_string()
            } else {
                exceed.join("; ")
            },
        )?;
    }
    r.number("cases", cases as f64, "int");
    r.number("corpora", forms::CORPORA.len() as f64, "int");
    r.claim(
        "every_shipped_form_within",
        all_within,
        format!("every form the renderer uses, in every corpus, within {BOUND} ulps × max(κ, 1)"),
    );
    writeln!(
        md,
        "\nThe corpora `data/corpus/*.txt` ({cases} cases in all); each corpus's own table is in its chapter."
    )?;
    Ok(md.into_bytes())
}

/// An error in ulps: with one decimal below 10⁵, in scientific notation above.
fn ulps(r: &mut Record, name: &str, x: f64) -> String {
    if x < 1e5 {
        r.number(name, x, ".1")
    } else {
        r.text(name, format!("{x:.2e}"))
    }
}

/// A ratio `ulps / max(κ, 1)`: with two decimals below 10⁵, in scientific notation above
/// (a textbook form's can be 10⁴⁰, or infinite).
fn ratio(r: &mut Record, name: &str, x: f64) -> String {
    if x < 1e5 {
        r.number(name, x, ".2")
    } else {
        r.text(name, format!("{x:.2e}"))
    }
}

/// `κ` as the table prints it.
fn kappa(c: f64) -> String {
    if c.is_infinite() {
        "∞".to_string()
    } else {
        format!("{c:.2e}")
    }
}

/// The table of one corpus ([`corpus_of`] the record's file): per verb and form, the cases, the median
/// and worst errors (ulps), the input of the worst and the condition number there, and
/// the largest error divided by `max(κ, 1)` over the cases, which the claim holds to at
/// most [`BOUND`], with its case's line (often not the worst error's case).
fn table(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let name = corpus_of(r)?;
    let corpus = corpus::load(&settings.root.join(format!("data/corpus/{name}.txt")))?;
    let forms = forms::of(name).with_context(|| format!("no forms answer the corpus {name}"))?;
    let mut md = String::new();
    writeln!(
        md,
        "| routine | form | cases | median (ulps) | worst (ulps) | worst at | κ there | largest ulps / max(κ, 1) | at |"
    )?;
    writeln!(md, "|---|---|---:|---:|---:|---|---:|---:|---|")?;
    let mut all_within = true;
    for form in &forms {
        let measured = accuracy::measure_form(&corpus, form);
        let s = accuracy::summarize(&measured)
            .with_context(|| format!("{name}: no case of {} for {}", form.verb, form.label()))?;
        let key = format!("{}.{}", form.verb, slug(&form.label()));
        let worst_case = &corpus.cases[s.worst.case];
        let within = s.worst_ratio.ratio <= BOUND;
        if form.expect == Expect::Within {
            all_within &= within;
        }
        r.claim(
            &format!("{key}.within"),
            within,
            format!("worst ulps / max(κ, 1) = {} ≤ {BOUND}", s.worst_ratio.ratio),
        );
        let failures = measured.iter().filter(|m| m.ratio > BOUND).count();
        r.number(&format!("{key}.failures"), failures as f64, "int");
        let kappa_max = measured
            .iter()
            .map(|m| m.condition)
            .filter(|c| c.is_finite())
            .fold(0.0, f64::max);
        r.text(&format!("{key}.kappa_max"), format!("{kappa_max:.1e}"));
        r.claim(
            &format!("{key}.exceeds"),
            !within,
            format!("worst ulps / max(κ, 1) = {} > {BOUND}", s.worst_ratio.ratio),
        );
        writeln!(
            md,
            "| `{}` | {} | {} | {} | {} | {} (line {}) | {} | {} | line {} |",
            form.verb,
            form.label(),
            r.number(&format!("{key}.cases"), s.cases as f64, "int"),
            ulps(r, &format!("{key}.median"), s.median),
            ulps(r, &format!("{key}.worst"), s.worst.ulps),
            worst_case.why,
            worst_case.line,
            kappa(s.worst.condition),
            ratio(r, &format!("{key}.ratio"), s.worst_ratio.ratio),
            corpus.cases[s.worst_ratio.case].line,
        )?;
    }
    r.claim(
        "every_shipped_form_within",
        all_within,
        format!("every form expected within {BOUND} ulps × max(κ, 1) is"),
    );
    writeln!(
        md,
        "\nCorpus `data/corpus/{name}.txt` ({} cases); exact answers by `tools/exact` (mpmath, 256 bits).",
        corpus.cases.len()
    )?;
    Ok(md.into_bytes())
}
