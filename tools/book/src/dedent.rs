//! mdBook preprocessor that removes the common indentation of each fenced code block.
//!
//! Chapters show code from `src/` by anchor (`{{#include ../src/x.rs:anchor}}`); mdBook
//! keeps the included lines' indentation, so code inside an `impl` block or a macro that
//! writes a function for both precisions would appear shifted right. Removing the
//! indentation common to all non-blank lines of a block never changes what the code says.
//!
//! The same pass first leaves out the exercise markers of the student edition
//! ([`crate::markers`]), which the included code carries.

use anyhow::Result;
use mdbook_driver::book::{Book, BookItem};
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};

/// See the module documentation.
pub struct Dedent;

impl Preprocessor for Dedent {
    fn name(&self) -> &str {
        "dedent"
    }

    fn run(&self, _ctx: &PreprocessorContext, mut book: Book) -> Result<Book> {
        book.for_each_mut(|item| {
            if let BookItem::Chapter(chapter) = item {
                let content = crate::markers::drop_exercise_markers(&chapter.content);
                chapter.content = dedent_code_blocks(&content);
            }
        });
        Ok(book)
    }

    fn supports_renderer(&self, _renderer: &str) -> Result<bool> {
        Ok(true)
    }
}

/// `text` with every fenced code block (between lines starting with three backticks)
/// shifted left by the smallest indentation of its non-blank lines.
pub fn dedent_code_blocks(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut block: Option<Vec<&str>> = None;
    for line in text.split_inclusive('\n') {
        let fence = line.trim_start().starts_with("```");
        match (&mut block, fence) {
            (None, true) => {
                out.push_str(line);
                block = Some(Vec::new());
            }
            (None, false) => out.push_str(line),
            (Some(lines), false) => lines.push(line),
            (Some(lines), true) => {
                let indent = lines
                    .iter()
                    .filter(|l| !l.trim().is_empty())
                    .map(|l| l.len() - l.trim_start_matches(' ').len())
                    .min()
                    .unwrap_or(0);
                for l in lines.iter() {
                    out.push_str(if l.trim().is_empty() {
                        l.trim_start_matches(' ')
                    } else {
                        &l[indent..]
                    });
                }
                out.push_str(line);
                block = None;
            }
        }
    }
    // An unclosed block is left as it was.
    if let Some(lines) = block {
        for l in lines {
            out.push_str(l);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::dedent_code_blocks;

    #[test]
    fn removes_only_the_common_indentation_of_code() {
        let text = "Text\n    indented prose\n```rust\n        fn f() {\n            1\n\n        }\n```\n  after\n";
        let want = "Text\n    indented prose\n```rust\nfn f() {\n    1\n\n}\n```\n  after\n";
        assert_eq!(dedent_code_blocks(text), want);
    }

    #[test]
    fn leaves_unindented_and_unclosed_blocks_alone() {
        let text = "```\nfn f() {}\n```\n```\n    open\n";
        assert_eq!(dedent_code_blocks(text), text);
    }
}
