//! The book's numbers: named values that the figure job recorded as it computed them.
//!
//! A chapter never types a measured number or ranking. It quotes one with
//! `{{#value OUTPUT.NAME}}`, replaced by the text the figure code recorded under that name
//! (`figures/values.json`, written by `tools/figures` through `raylemma_values::Record`), and
//! states a comparison with `{{#claim OUTPUT.NAME}}`, which renders nothing and holds or
//! not as the figure code decided beside its data. The build fails, naming chapter, line and
//! sentence, on a name that was never recorded or a claim that does not hold; a claim that
//! fails in a record made in `--quick` mode (noisy, for CI) is a warning. A sentence that
//! quotes timings measured on two machines (records whose fingerprints differ) is an error:
//! such numbers may not be set side by side.

use std::collections::BTreeSet;
use std::path::Path;
use std::sync::LazyLock;

use anyhow::{Result, bail};
use mdbook_driver::book::{Book, BookItem};
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};
use raylemma_output::line_of;
use raylemma_values::{Found, Values};
use regex::Regex;

/// `{{#value NAME}}` and `{{#claim NAME}}` (mdBook's own `\{{` escapes one).
static DIRECTIVE: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r"(?x)\\\{\{\#[^}]*\}\}|\{\{\s*\#(value|claim)\s+([^}\s]+)\s*\}\}")
        .expect("valid regex")
});

/// A problem with a directive, or a claim that does not hold.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// 1-based line of the directive in the chapter.
    pub line: usize,
    pub message: String,
    /// A failed claim of a quick-mode record: a warning, not an error.
    pub warning: bool,
}

/// The values of `figures/` under `root`, or the reason they cannot be read.
pub fn read(root: &Path) -> Result<Values, String> {
    raylemma_values::read(&root.join("figures"))
}

/// `text` with its directives replaced, and what went wrong.
pub fn expand(values: &Values, text: &str) -> (String, Vec<Finding>) {
    let mut out = String::with_capacity(text.len());
    let mut findings = Vec::new();
    let mut last = 0;
    // Per sentence (by its start), the machines whose timings it quotes.
    let mut machines: Vec<(usize, String, String, usize)> = Vec::new();
    for cap in DIRECTIVE.captures_iter(text) {
        let (Some(whole), Some(kind), Some(name)) = (cap.get(0), cap.get(1), cap.get(2)) else {
            continue; // escaped
        };
        out.push_str(&text[last..whole.start()]);
        last = whole.end();
        let line = line_of(text, whole.start());
        let (kind, name) = (kind.as_str(), name.as_str());
        let sentence = || sentence_of(text, whole.start(), whole.end());
        let mut fail = |message: String, warning: bool| {
            findings.push(Finding {
                line,
                message,
                warning,
            })
        };
        let Some((entry, found)) = raylemma_values::lookup(values, name) else {
            fail(
                format!(
                    "{{{{#{kind} {name}}}}}: no such name in figures/{}{}\n  in the sentence: {}",
                    raylemma_values::FILE,
                    suggest(values, name),
                    sentence()
                ),
                false,
            );
            continue;
        };
        match (kind, found) {
            ("value", Found::Value(v)) => out.push_str(&v.shown),
            ("claim", Found::Claim(c)) => {
                if !c.holds {
                    let quick = if entry.quick {
                        "\n  (recorded in quick mode, which is not for quoting)"
                    } else {
                        ""
                    };
                    fail(
                        format!(
                            "claim does not hold: {name} ({})\n  in the sentence: {}\n  read: {}{quick}",
                            entry.file,
                            sentence(),
                            c.read
                        ),
                        entry.quick,
                    );
                }
            }
            ("value", Found::Claim(_)) => fail(
                format!("{{{{#value {name}}}}}: {name} is a claim: write {{{{#claim {name}}}}}"),
                false,
            ),
            _ => fail(
                format!(
                    "{{{{#claim {name}}}}}: {name} is a value, not a claim: write {{{{#value {name}}}}}"
                ),
                false,
            ),
        }
        if let Some(m) = &entry.machine {
            let start = sentence_start(text, whole.start());
            machines.push((start, m.clone(), name.to_string(), line));
        }
    }
    out.push_str(&text[last..]);
    for (i, (start, m, name, line)) in machines.iter().enumerate() {
        if let Some((_, other, other_name, _)) = machines[..i]
            .iter()
            .find(|(s, o, _, _)| s == start && o != m)
        {
            findings.push(Finding {
                line: *line,
                message: format!(
                    "{name} (machine fingerprint {m}) and {other_name} (fingerprint {other}) are \
                     timings of two machines in one sentence: remake one, or do not set them side by side\n  in the sentence: {}",
                    sentence_of(text, *start, *start)
                ),
                warning: false,
            });
        }
    }
    // A directive the pattern did not take (a space or `}` inside the name) would be left
    // in the page as text.
    for (i, _) in text.match_indices("{{#") {
        let rest = &text[i + 3..];
        let escaped = i > 0 && text.as_bytes()[i - 1] == b'\\';
        let taken = DIRECTIVE.find_at(text, i).is_some_and(|m| m.start() == i);
        if !escaped && (rest.starts_with("value") || rest.starts_with("claim")) && !taken {
            findings.push(Finding {
                line: line_of(text, i),
                message: "a {{#value}} or {{#claim}} that is not one name closed by `}}`".into(),
                warning: false,
            });
        }
    }
    (out, findings)
}

/// The recorded names of the same output that begin like `name`, or the outputs there are.
fn suggest(values: &Values, name: &str) -> String {
    let Some((output, rest)) = name.split_once('.') else {
        return " (a name is OUTPUT.NAME)".into();
    };
    let Some(entry) = values.get(output) else {
        let near: Vec<&str> = values
            .keys()
            .map(String::as_str)
            .filter(|k| k.split('_').next() == output.split('_').next())
            .collect();
        return format!(
            " (no output {output:?} recorded values{}; was its output made? the references' \
             tables are made by `references`, Mitsuba's by tools/mitsuba)",
            if near.is_empty() {
                String::new()
            } else {
                format!("; of its kind: {}", near.join(", "))
            }
        );
    };
    let first = rest.split('.').next().unwrap_or(rest);
    let all: BTreeSet<&str> = entry
        .values
        .keys()
        .chain(entry.claims.keys())
        .map(String::as_str)
        .collect();
    let near: Vec<&str> = all
        .iter()
        .copied()
        .filter(|n| n.starts_with(first))
        .collect();
    let shown = if near.is_empty() {
        all.into_iter().collect()
    } else {
        near
    };
    let mut list = shown
        .iter()
        .take(12)
        .map(|n| format!("{output}.{n}"))
        .collect::<Vec<_>>()
        .join(", ");
    if shown.len() > 12 {
        list.push_str(", …");
    }
    format!(" ({} records: {list})", entry.file)
}

fn paragraph(text: &str, start: usize, end: usize) -> (usize, usize) {
    let s = text[..start].rfind("\n\n").map_or(0, |i| i + 2);
    let e = text[end..].find("\n\n").map_or(text.len(), |i| end + i);
    (s, e)
}

/// Where the sentence around byte `at` begins.
fn sentence_start(text: &str, at: usize) -> usize {
    let (p, _) = paragraph(text, at, at);
    let before = &text[p..at];
    before
        .rfind(". ")
        .or_else(|| before.rfind(".\n"))
        .map_or(p, |i| p + i + 2)
}

/// The sentence of `text` around the byte range `start..end`, its claims left out.
fn sentence_of(text: &str, start: usize, end: usize) -> String {
    let (_, para_end) = paragraph(text, start, end);
    let s = sentence_start(text, start);
    let after = &text[end..para_end];
    let e = after
        .find(". ")
        .or_else(|| after.find(".\n"))
        .map_or(para_end, |i| end + i + 1);
    let sentence = DIRECTIVE.replace_all(&text[s..e], |c: &regex::Captures<'_>| {
        if c.get(1).is_some_and(|k| k.as_str() == "claim") {
            String::new()
        } else {
            c[0].to_string()
        }
    });
    let flat = sentence.split_whitespace().collect::<Vec<_>>().join(" ");
    if flat.chars().count() > 400 {
        format!("{}…", flat.chars().take(400).collect::<String>())
    } else {
        flat
    }
}

/// mdBook preprocessor replacing `{{#value}}` and failing on `{{#claim}}`s that do not hold.
/// It runs before mdBook's `links`, on the chapters' own text, so lines are the files' own.
pub struct Numbers;

impl Preprocessor for Numbers {
    fn name(&self) -> &str {
        "values"
    }

    fn run(&self, ctx: &PreprocessorContext, mut book: Book) -> Result<Book> {
        let values = match read(&ctx.root) {
            Ok(v) => v,
            Err(e) => bail!("{e}"),
        };
        let src = ctx.config.book.src.clone();
        let mut errors = Vec::new();
        book.for_each_mut(|item| {
            let BookItem::Chapter(chapter) = item else {
                return;
            };
            let (content, findings) = expand(&values, &chapter.content);
            chapter.content = content;
            let file = chapter
                .source_path
                .as_ref()
                .or(chapter.path.as_ref())
                .map(|p| src.join(p).display().to_string())
                .unwrap_or_else(|| chapter.name.clone());
            for f in findings {
                let text = format!("{file}:{}: {}", f.line, f.message);
                if f.warning {
                    eprintln!("warning: {text}");
                } else {
                    errors.push(text);
                }
            }
        });
        if !errors.is_empty() {
            bail!(
                "{} number(s) or claim(s) of the chapters do not match what the figure job recorded:\n{}",
                errors.len(),
                errors.join("\n")
            );
        }
        Ok(book)
    }

    fn supports_renderer(&self, _renderer: &str) -> Result<bool> {
        Ok(true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylemma_values::Record;

    fn values() -> Values {
        let mut values = Values::new();
        let mut r = Record::new("speed.md");
        r.number("malley.ns", 45.44, ".1");
        r.number("seed.ns", 40.7, ".1");
        r.claim("malley_slower", true, "45.4 > 40.7");
        r.claim("malley_faster", false, "45.4 < 40.7");
        let timed = b"*AMD EPYC, single thread (fingerprint 0a1b2c3d).*";
        values.insert("speed".into(), r.finish(timed, false).unwrap());
        let mut r = Record::new("other.md");
        r.number("ns", 12.0, "int");
        values.insert(
            "other".into(),
            r.finish(b"(fingerprint 99999999)", false).unwrap(),
        );
        let mut r = Record::new("q.md");
        r.claim("noisy", false, "1 > 2");
        values.insert("q".into(), r.finish(b"", true).unwrap());
        values
    }

    #[test]
    fn values_are_shown_and_claims_vanish() {
        let text = "# T\n\nMalley costs {{#value speed.malley.ns}} ns, more than the seed's \
                    form{{#claim speed.malley_slower}}. Next.\n\n\\{{#value speed.x}} is how it is written.\n";
        let (out, findings) = expand(&values(), text);
        assert!(findings.is_empty(), "{findings:?}");
        assert!(
            out.contains("Malley costs 45.4 ns, more than the seed's form. Next."),
            "{out}"
        );
        assert!(
            out.contains("\\{{#value speed.x}}"),
            "escaped directives stay"
        );
    }

    #[test]
    fn unknown_names_and_false_claims_name_line_and_sentence() {
        let text = "Intro.\n\nIt costs {{#value speed.malley.us}} ns.\n\nFaster{{#claim speed.malley_faster}}. \
                    {{#value nothing.x}} {{#claim speed.malley.ns}}\n\nQuick{{#claim q.noisy}}.\n";
        let (_, f) = expand(&values(), text);
        assert_eq!(f.len(), 5, "{f:?}");
        assert_eq!(f[0].line, 3);
        assert!(
            f[0].message.contains("no such name")
                && f[0].message.contains("speed.malley.ns")
                && f[0].message.contains("in the sentence: It costs"),
            "{}",
            f[0].message
        );
        assert!(
            f[1].message
                .contains("claim does not hold: speed.malley_faster")
                && f[1].message.contains("read: 45.4 < 40.7")
                && !f[1].warning,
            "{}",
            f[1].message
        );
        assert!(
            f[2].message.contains("no output \"nothing\""),
            "{}",
            f[2].message
        );
        assert!(
            f[3].message.contains("is a value, not a claim"),
            "{}",
            f[3].message
        );
        assert!(
            f[4].warning && f[4].message.contains("quick mode"),
            "{:?}",
            f[4]
        );
    }

    #[test]
    fn timings_of_two_machines_are_not_set_side_by_side() {
        let (_, f) = expand(
            &values(),
            "A {{#value speed.malley.ns}} against {{#value other.ns}}.\n",
        );
        assert_eq!(f.len(), 1, "{f:?}");
        assert!(f[0].message.contains("two machines"), "{}", f[0].message);
        let (_, f) = expand(
            &values(),
            "A {{#value speed.malley.ns}}. Then {{#value other.ns}}.\n",
        );
        assert!(f.is_empty(), "two sentences may: {f:?}");
    }

    #[test]
    fn a_malformed_directive_is_reported() {
        let (_, f) = expand(&values(), "a {{#value speed.malley ns}} b\n");
        assert!(
            f.iter().any(|f| f.message.contains("not one name")),
            "{f:?}"
        );
    }
}
