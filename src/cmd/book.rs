//! `raylemma book`: builds `chapters/` into `book/` with the workspace's book tool
//! (`tools/book/`, the crate `raylemma-book`: mdBook as a library, math as MathML).

use super::{CmdResult, root, run_tool};

/// Builds the book (the first build compiles mdBook and KaTeX, a few minutes). On any
/// error the previous `book/` is left as it was.
pub fn build() -> CmdResult {
    eprintln!("raylemma: building the book tool (the first build compiles mdBook and KaTeX)");
    let done = run_tool("raylemma-book", &[]);
    if done.is_err() {
        eprintln!("raylemma: book/ was left as it was");
        return done;
    }
    eprintln!(
        "raylemma: open {} in a browser",
        root().join("book").join("index.html").display()
    );
    done
}
