//! Images: every local image of a chapter exists in the built book and has alt text saying
//! what it shows (`![what it shows](path)`, `<img alt="...">`).

use std::path::Path;
use std::sync::LazyLock;

use pulldown_cmark::{Event, Options, Parser, Tag, TagEnd};
use regex::Regex;

use super::paths::{normalize, normalize_within, percent_decode, to_url};
use super::{Checker, Problem, line_of};

static IMG_SRC: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r#"(?is)<img\b[^>]*?\bsrc\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s>]+))"#)
        .expect("valid regex")
});
static IMG_TAG: LazyLock<Regex> =
    LazyLock::new(|| Regex::new(r"(?is)<img\b[^>]*>").expect("valid regex"));
static IMG_ALT: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r#"(?is)\balt\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s>]+))"#).expect("valid regex")
});
static SCHEME: LazyLock<Regex> =
    LazyLock::new(|| Regex::new(r"^[a-zA-Z][a-zA-Z0-9+.-]*:").expect("valid regex"));

impl Checker {
    pub(super) fn check_images(&self, file: &Path, text: &str, problems: &mut Vec<Problem>) {
        let mut opts = Options::empty();
        opts.insert(Options::ENABLE_TABLES);
        opts.insert(Options::ENABLE_FOOTNOTES);
        opts.insert(Options::ENABLE_STRIKETHROUGH);
        opts.insert(Options::ENABLE_TASKLISTS);
        opts.insert(Options::ENABLE_HEADING_ATTRIBUTES);
        // The image being read: its URL, where it starts, and its alt text so far.
        let mut image: Option<(String, usize, String)> = None;
        for (event, range) in Parser::new_ext(text, opts).into_offset_iter() {
            match event {
                Event::Start(Tag::Image { dest_url, .. }) => {
                    if let Some(message) = self.check_image(file, &dest_url) {
                        problems.push(Problem {
                            file: self.display_path(file),
                            line: line_of(text, range.start),
                            message: format!("image {dest_url}: {message}"),
                        });
                    }
                    image = Some((dest_url.to_string(), range.start, String::new()));
                }
                Event::Text(t) | Event::Code(t) if image.is_some() => {
                    if let Some((_, _, alt)) = image.as_mut() {
                        alt.push_str(&t);
                    }
                }
                Event::End(TagEnd::Image) => {
                    if let Some((url, start, alt)) = image.take()
                        && alt.trim().is_empty()
                    {
                        problems.push(Problem {
                            file: self.display_path(file),
                            line: line_of(text, start),
                            message: format!(
                                "image {url}: no alt text (write ![what it shows]({url}))"
                            ),
                        });
                    }
                }
                Event::Html(html) | Event::InlineHtml(html) => {
                    for tag in IMG_TAG.find_iter(&html) {
                        let alt = IMG_ALT
                            .captures(tag.as_str())
                            .and_then(|c| c.get(1).or(c.get(2)).or(c.get(3)))
                            .map_or("", |m| m.as_str());
                        if alt.trim().is_empty() {
                            let offset = range.start + tag.start();
                            problems.push(Problem {
                                file: self.display_path(file),
                                line: line_of(text, offset.min(text.len())),
                                message: "<img> without alt text (add alt=\"what it shows\")"
                                    .into(),
                            });
                        }
                    }
                    for cap in IMG_SRC.captures_iter(&html) {
                        let Some(src) = cap.get(1).or(cap.get(2)).or(cap.get(3)) else {
                            continue;
                        };
                        if let Some(message) = self.check_image(file, src.as_str()) {
                            let offset = range.start + html[..src.start()].len();
                            problems.push(Problem {
                                file: self.display_path(file),
                                line: line_of(text, offset.min(text.len())),
                                message: format!("image {}: {message}", src.as_str()),
                            });
                        }
                    }
                }
                _ => {}
            }
        }
    }

    /// Resolves an image link of the chapter `file` in the built book; `None` if it will load.
    fn check_image(&self, file: &Path, url: &str) -> Option<String> {
        if url.is_empty() || url.starts_with('#') || url.starts_with("//") || SCHEME.is_match(url) {
            return None; // remote (or not a file): not checked here
        }
        let path = percent_decode(url.split(['?', '#']).next().unwrap_or(""));
        if path.starts_with('/') {
            return Some("absolute path; use a path relative to the chapter page".into());
        }
        let chapter_dir = file
            .parent()
            .and_then(|d| d.strip_prefix(&self.src_dir).ok())
            .unwrap_or(Path::new(""));
        let depth = chapter_dir.components().count();
        let Some(in_book) = normalize_within(&chapter_dir.join(&path)) else {
            // Points above the book's root: a path valid on disk (e.g. ../../figures/x.png)
            // does not exist in the output. Suggest the right one if it is a figure.
            let on_disk = normalize(&file.parent().unwrap_or(Path::new("")).join(&path));
            let hint = on_disk
                .strip_prefix(self.root.join("figures"))
                .ok()
                .map(|rest| {
                    format!(
                        "; figures are copied to the book's root, so from this chapter write \
                         '{}figures/{}'",
                        "../".repeat(depth),
                        to_url(rest)
                    )
                })
                .unwrap_or_default();
            return Some(format!("points outside the built book{hint}"));
        };
        if self.src_dir.join(&in_book).is_file() {
            return None;
        }
        if let Ok(rest) = in_book.strip_prefix("figures")
            && self.root.join("figures").join(rest).is_file()
        {
            return None;
        }
        let looked = match in_book.strip_prefix("figures") {
            Ok(rest) => self.display_path(&self.root.join("figures").join(rest)),
            Err(_) => self.display_path(&self.src_dir.join(&in_book)),
        };
        Some(format!("not found: {}", looked.display()))
    }
}
