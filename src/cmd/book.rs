//! `raylemma book`: builds `chapters/` into `book/` with the workspace's book tool
//! (`tools/book/`, the crate `raylemma-book`: mdBook as a library, math as MathML).

use super::{root, run_tool};

/// Builds the book (the first build compiles mdBook and KaTeX, a few minutes). On any
/// error the previous `book/` is left as it was.
pub fn build() -> Result<(), String> {
    eprintln!("raylemma: building the book tool (the first build compiles mdBook and KaTeX)");
    run_tool("raylemma-book", &[]).map_err(|e| format!("{e}; book/ was left as it was"))?;
    eprintln!(
        "raylemma: open {} in a browser",
        root().join("book").join("index.html").display()
    );
    Ok(())
}
