//! The `katex` preprocessor: renders `$…$` and `$$…$$` to MathML at build time.
//!
//! It reuses `mdbook-katex` 0.10 (its `[preprocessor.katex]` configuration and its scanner, which
//! skips code spans/blocks and `\$`) but not its `KatexProcessor`, which logs a warning and keeps
//! the raw TeX when a formula does not parse, and links a KaTeX stylesheet from a CDN. Here an
//! invalid formula is an error naming the chapter file and line, and nothing remote is injected:
//! only `output = "mathml"` is accepted, which needs no KaTeX CSS or fonts to read.

use std::collections::HashMap;
use std::fs;
use std::path::Path;

use anyhow::{Context, Result, bail};
use katex::Opts;
use mdbook_driver::book::{Book, Chapter};
use mdbook_katex::cfg::KatexConfig;
use mdbook_katex::preprocess::{ExtraOpts, Render, get_render_tasks};
use mdbook_katex::scan::Delimiter;
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};

/// mdBook preprocessor rendering math with KaTeX to MathML, failing on invalid formulas.
pub struct KatexMathml;

impl Preprocessor for KatexMathml {
    fn name(&self) -> &str {
        "katex"
    }

    fn run(&self, ctx: &PreprocessorContext, mut book: Book) -> Result<Book> {
        let cfg: KatexConfig = ctx
            .config
            .get("preprocessor.katex")?
            .context("book.toml has no [preprocessor.katex] table (need output = \"mathml\")")?;
        if cfg.output != "mathml" {
            bail!(
                "[preprocessor.katex] output = {:?}: only \"mathml\" is supported (other \
                 outputs need KaTeX's CSS and fonts at read time)",
                cfg.output
            );
        }
        if !cfg.pre_render {
            bail!(
                "[preprocessor.katex] pre-render = false is not supported (needs JS at read time)"
            );
        }
        let macros = load_macros(&ctx.root, cfg.macros.as_deref())?;
        let (inline, display) = cfg.build_opts_from_macros(macros);
        let extra = cfg.build_extra_opts();
        let src_dir = ctx.root.join(&ctx.config.book.src);

        let mut problems = Vec::new();
        book.for_each_chapter_mut(|chapter| {
            match render_chapter(&chapter.content, &inline, &display, &extra) {
                Ok(content) => chapter.content = content,
                Err(errors) => {
                    for (formula, display_mode, message) in errors {
                        let place = locate(&src_dir, chapter, &formula, display_mode, &extra);
                        let formula = formula.split_whitespace().collect::<Vec<_>>().join(" ");
                        problems.push(format!("{place}: invalid formula `{formula}`: {message}"));
                    }
                }
            }
        });
        if !problems.is_empty() {
            bail!(
                "KaTeX could not render {} formula(s):\n{}",
                problems.len(),
                problems.join("\n")
            );
        }
        Ok(book)
    }

    fn supports_renderer(&self, renderer: &str) -> Result<bool> {
        Ok(renderer == "html")
    }
}

/// A formula that failed: its TeX, whether it was display math, KaTeX's message.
type Failure = (String, bool, String);

/// Renders every formula of one chapter; all failures are returned, not just the first.
fn render_chapter(
    content: &str,
    inline: &Opts,
    display: &Opts,
    extra: &ExtraOpts,
) -> Result<String, Vec<Failure>> {
    let mut out = String::with_capacity(content.len() * 2);
    let mut failures = Vec::new();
    for task in get_render_tasks(content, "", extra) {
        let (tex, opts, display_mode) = match task {
            Render::Text(text) => {
                out.push_str(text);
                continue;
            }
            Render::InlineTask(tex) => (tex, inline, false),
            Render::DisplayTask(tex) => (tex, display, true),
        };
        match katex::render_with_opts(tex, opts) {
            Ok(html) => {
                let html = shield_from_markdown(&html);
                if extra.include_src {
                    out.push_str(r#"<data class="katex-src" value=""#);
                    out.push_str(&tex.replace('"', "&quot;").replace('\n', "&#10;"));
                    out.push_str(r#"">"#);
                    out.push_str(&html);
                    out.push_str("</data>");
                } else {
                    out.push_str(&html);
                }
            }
            Err(e) => {
                let message = match e {
                    katex::Error::JsExecError(m) => clean_js_message(&m),
                    other => other.to_string(),
                };
                failures.push((tex.to_owned(), display_mode, message));
            }
        }
    }
    if failures.is_empty() {
        Ok(out)
    } else {
        Err(failures)
    }
}

/// KaTeX's exception as QuickJS reports it is a Rust `Debug` string (`String("ParseError: …")`);
/// this unquotes it and keeps the first line.
fn clean_js_message(raw: &str) -> String {
    let Some(inner) = raw
        .strip_prefix("String(\"")
        .and_then(|r| r.strip_suffix("\")"))
    else {
        return raw.trim().to_owned();
    };
    let mut out = String::new();
    let mut chars = inner.chars();
    while let Some(c) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        match chars.next() {
            Some('n') => out.push('\n'),
            Some('t') => out.push('\t'),
            Some('u') => {
                let hex: String = chars.by_ref().skip(1).take_while(|&c| c != '}').collect();
                if let Some(c) = u32::from_str_radix(&hex, 16).ok().and_then(char::from_u32) {
                    out.push(c);
                }
            }
            Some(other) => out.push(other),
            None => {}
        }
    }
    out.lines().next().unwrap_or("").trim().to_owned()
}

/// Makes KaTeX's HTML pass through Markdown unchanged. The rendered formula is inline HTML in
/// a paragraph, and Markdown still parses the text *between* tags: `\,` in the TeX annotation
/// would lose its backslash, `*`/`_` could become emphasis, `|` a table cell, `'` a curly
/// quote. So ASCII punctuation in text (outside tags; except `&`, `#`, `;`, which make up
/// KaTeX's own entities) becomes a numeric character reference, which Markdown treats as
/// literal text. Newlines become spaces so that display math stays within one paragraph.
fn shield_from_markdown(html: &str) -> String {
    let mut out = String::with_capacity(html.len() + html.len() / 4);
    let mut in_tag = false;
    for c in html.chars() {
        match c {
            '<' => in_tag = true,
            '>' => in_tag = false,
            _ => {}
        }
        if c == '\n' {
            out.push(' ');
        } else if !in_tag && c != '>' && c.is_ascii_punctuation() && !matches!(c, '&' | '#' | ';') {
            out.push_str(&format!("&#{};", c as u32));
        } else {
            out.push(c);
        }
    }
    out
}

/// `chapters/x.md:LINE` for a formula found verbatim in the chapter's source file, else the
/// chapter file alone (e.g. for formulas that came from an `{{#include}}`).
fn locate(
    src_dir: &Path,
    chapter: &Chapter,
    formula: &str,
    display_mode: bool,
    extra: &ExtraOpts,
) -> String {
    let Some(source) = chapter.source_path.as_ref().or(chapter.path.as_ref()) else {
        return format!("chapter '{}'", chapter.name);
    };
    let file = Path::new(src_dir.file_name().unwrap_or_default()).join(source);
    let Delimiter { left, right } = if display_mode {
        &extra.block_delimiter
    } else {
        &extra.inline_delimiter
    };
    let needle = format!("{left}{formula}{right}");
    let line = fs::read_to_string(src_dir.join(source))
        .ok()
        .and_then(|text| {
            text.find(&needle)
                .map(|i| text[..i].matches('\n').count() + 1)
        });
    let line = line.map(|l| format!(":{l}")).unwrap_or_default();
    format!("{}{line}", file.display())
}

/// Loads the `macros` file of `[preprocessor.katex]` (lines `\name:expansion`), as mdbook-katex
/// does, but with errors instead of panics.
fn load_macros(root: &Path, path: Option<&str>) -> Result<HashMap<String, String>> {
    let mut map = HashMap::new();
    let Some(path) = path else {
        return Ok(map);
    };
    let file = root.join(path);
    let text = fs::read_to_string(&file)
        .with_context(|| format!("reading KaTeX macros file {}", file.display()))?;
    for (i, line) in text.lines().enumerate() {
        if !line.starts_with('\\') {
            continue;
        }
        let Some((name, expansion)) = line.split_once(':') else {
            bail!("{}:{}: macro line without ':'", file.display(), i + 1);
        };
        map.insert(name.to_owned(), expansion.to_owned());
    }
    Ok(map)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn js_messages_are_unquoted() {
        assert_eq!(
            clean_js_message(r#"String("ParseError: at \\text{a_\u{332}b}\n")"#),
            "ParseError: at \\text{a_\u{332}b}"
        );
        assert_eq!(clean_js_message("plain"), "plain");
    }

    #[test]
    fn markdown_shield_escapes_text_only() {
        let html = "<math display=\"block\"><mo>*</mo><annotation a=\"x_y\">x\\,d_x &amp; y</annotation>\n</math>";
        assert_eq!(
            shield_from_markdown(html),
            "<math display=\"block\"><mo>&#42;</mo><annotation a=\"x_y\">x&#92;&#44;d&#95;x &amp; y</annotation> </math>"
        );
    }
}
