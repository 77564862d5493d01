//! `raylemma-book --root <project root> [--out <dir>]`: builds raylemma's book to HTML with
//! mdBook used as a library, math pre-rendered to MathML, readable with no network.
//!
//! Steps: preflight check of includes, images, pasted code and the numbers the chapters read
//! recorded by the figure job ([`preflight`], [`values`]), mdBook build into a staging
//! directory beside the output, copy of `<root>/figures/` into it, check that no page needs a
//! remote script or stylesheet, then swap the staging directory into place. On any failure the
//! staging directory is removed and the previous output is left untouched.

mod dedent;
mod logging;
mod markers;
mod math;

mod preflight;
mod values;

use std::ffi::OsString;
use std::fs;
use std::io;
use std::panic;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::{LazyLock, Mutex};

use anyhow::{Context, Result, anyhow, bail};
use mdbook_driver::MDBook;
use mdbook_driver::book::BookItem;
use mdbook_driver::config::Config;
use raylemma_output::StagedDir;
use regex::Regex;

const USAGE: &str =
    "usage: raylemma-book --root <project root dir> [--out <dir, default <root>/book>]";

/// Parsed command line.
struct Args {
    root: PathBuf,
    out: Option<PathBuf>,
}

fn main() -> ExitCode {
    let args = match parse_args(std::env::args_os().skip(1)) {
        Ok(Some(args)) => args,
        Ok(None) => {
            println!("{USAGE}");
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            eprintln!("error: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    logging::init();
    match build(&args) {
        Ok(index) => {
            eprintln!("book written to {}", index.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: building the book failed: {e}");
            for cause in e.chain().skip(1) {
                eprintln!("  caused by: {cause}");
            }
            ExitCode::FAILURE
        }
    }
}

/// Parses `--root DIR [--out DIR]` (also `--root=DIR`); `Ok(None)` for `--help`.
fn parse_args(mut args: impl Iterator<Item = OsString>) -> Result<Option<Args>> {
    let (mut root, mut out) = (None, None);
    while let Some(arg) = args.next() {
        let text = arg.to_string_lossy();
        let (flag, inline) = match text.split_once('=') {
            Some((f, v)) if f.starts_with("--") => (f.to_owned(), Some(OsString::from(v))),
            _ => (text.into_owned(), None),
        };
        let slot = match flag.as_str() {
            "-h" | "--help" => return Ok(None),
            "--root" => &mut root,
            "--out" => &mut out,
            _ => bail!("unexpected argument '{flag}'"),
        };
        let value = inline
            .or_else(|| args.next())
            .with_context(|| format!("{flag} needs a value"))?;
        *slot = Some(PathBuf::from(value));
    }
    let root = root.context("--root is required")?;
    Ok(Some(Args { root, out }))
}

/// Runs the whole build; returns the absolute path of the written `index.html`.
fn build(args: &Args) -> Result<PathBuf> {
    let root = fs::canonicalize(&args.root)
        .with_context(|| format!("project root {}", args.root.display()))?;
    let book_toml = root.join("book.toml");
    let mut config = Config::from_disk(&book_toml)
        .with_context(|| format!("reading {}", book_toml.display()))?;
    config.update_from_env()?;
    let src_dir = root.join(&config.book.src);

    eprintln!("checking includes, images, code blocks and numbers…");
    let problems = preflight::check_chapters(&root, &src_dir)
        .with_context(|| format!("scanning {}", src_dir.display()))?;
    if !problems.is_empty() {
        for p in &problems {
            eprintln!("{p}");
        }
        bail!(
            "{} problem(s) with includes, images, code blocks or numbers in {}",
            problems.len(),
            src_dir.strip_prefix(&root).unwrap_or(&src_dir).display()
        );
    }

    let out = match &args.out {
        Some(out) => std::path::absolute(out)?,
        None => root.join(&config.build.build_dir),
    };
    let staging = StagedDir::beside(&out)?;
    config.build.build_dir = staging.path().to_path_buf();

    let mut md = MDBook::load_with_config(&root, config).context("loading the book")?;
    md.with_preprocessor(values::Numbers);
    md.with_preprocessor(dedent::Dedent);
    md.with_preprocessor(math::KatexMathml);
    let chapters = md
        .iter()
        .filter(|item| matches!(item, BookItem::Chapter(c) if c.path.is_some()))
        .count();
    eprintln!("rendering {chapters} chapters…");
    catch_panic(|| md.build())?.context("running mdBook")?;
    if logging::error_count() > 0 {
        bail!(
            "mdBook reported {} error(s), see above",
            logging::error_count()
        );
    }

    let html_dir = md.build_dir_for("html");
    let figures = root.join("figures");
    if figures.is_dir() {
        copy_dir(&figures, &html_dir.join("figures"))
            .with_context(|| format!("copying {}", figures.display()))?;
    }
    let remote = remote_assets(&html_dir)?;
    if !remote.is_empty() {
        bail!(
            "the book would need the network to display:\n{}",
            remote.join("\n")
        );
    }
    let index_rel = html_dir.strip_prefix(staging.path())?.join("index.html");
    if !html_dir.join("index.html").is_file() {
        bail!("mdBook wrote no index.html");
    }

    let out = staging.replace()?;
    Ok(out.join(index_rel))
}

/// Runs `f`, turning a panic (in mdBook or a preprocessor) into an error with its message.
fn catch_panic<T>(f: impl FnOnce() -> T) -> Result<T> {
    static LAST_PANIC: LazyLock<Mutex<Option<String>>> = LazyLock::new(|| Mutex::new(None));
    let previous = panic::take_hook();
    panic::set_hook(Box::new(|info| {
        if let Ok(mut slot) = LAST_PANIC.lock() {
            *slot = Some(info.to_string());
        }
    }));
    let result = panic::catch_unwind(panic::AssertUnwindSafe(f));
    panic::set_hook(previous);
    result.map_err(|_| {
        let message = LAST_PANIC.lock().ok().and_then(|mut s| s.take());
        anyhow!(
            "internal panic: {}",
            message.unwrap_or_else(|| "(no message)".into())
        )
    })
}

/// Copies the directory tree `from` into `to` (created); refuses to overwrite a file, which
/// would mean the same figure path exists both in `figures/` and in the chapters directory.
fn copy_dir(from: &Path, to: &Path) -> io::Result<()> {
    fs::create_dir_all(to)?;
    for entry in fs::read_dir(from)? {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.path().is_dir() {
            copy_dir(&entry.path(), &target)?;
        } else if target.exists() {
            return Err(io::Error::new(
                io::ErrorKind::AlreadyExists,
                format!(
                    "{} exists both in figures/ and in the chapters directory",
                    entry.path().display()
                ),
            ));
        } else {
            fs::copy(entry.path(), &target)?;
        }
    }
    Ok(())
}

/// Remote resources the built pages would load at read time: scripts and stylesheets
/// (`<script src>`, `<link href>`) and `url(...)` in CSS, pointing at `http(s)://` or `//`.
/// Remote *images* written in a chapter are the author's choice and only warned about.
fn remote_assets(dir: &Path) -> Result<Vec<String>> {
    static TAG: LazyLock<Regex> = LazyLock::new(|| {
        Regex::new(
            r#"(?is)<(script|link|img|iframe|source|video|audio|embed)\b[^>]*?\b(?:src|href)\s*=\s*["']?((?:https?:)?//[^"'\s>]+)"#,
        )
        .expect("valid regex")
    });
    static CSS_URL: LazyLock<Regex> = LazyLock::new(|| {
        Regex::new(r#"(?i)(?:url\(|@import)\s*["']?((?:https?:)?//[^"')\s]+)"#)
            .expect("valid regex")
    });
    let mut found = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in fs::read_dir(&d)? {
            let path = entry?.path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
            if !matches!(ext, "html" | "css") {
                continue;
            }
            let text = fs::read_to_string(&path)?;
            let rel = path
                .strip_prefix(dir)
                .unwrap_or(&path)
                .display()
                .to_string();
            if ext == "html" {
                for cap in TAG.captures_iter(&text) {
                    let (tag, url) = (&cap[1], &cap[2]);
                    if matches!(tag.to_ascii_lowercase().as_str(), "script" | "link") {
                        found.push(format!("{rel}: <{tag}> {url}"));
                    } else {
                        eprintln!("warning: {rel}: <{tag}> loads a remote {url}");
                    }
                }
            }
            for cap in CSS_URL.captures_iter(&text) {
                found.push(format!("{rel}: {}", &cap[0]));
            }
        }
    }
    found.sort();
    found.dedup();
    Ok(found)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(args: &[&str]) -> Result<Option<Args>> {
        parse_args(args.iter().map(OsString::from))
    }

    #[test]
    fn arguments() {
        let a = parse(&["--root", "/r", "--out=/o"]).unwrap().unwrap();
        assert_eq!((a.root, a.out), ("/r".into(), Some("/o".into())));
        assert!(parse(&["--help"]).unwrap().is_none());
        assert!(parse(&[]).is_err());
        assert!(parse(&["--root"]).is_err());
        assert!(parse(&["--root", "/r", "extra"]).is_err());
    }
}
