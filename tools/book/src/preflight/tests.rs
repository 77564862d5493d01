//! Tests of the whole preflight check, on throw-away project trees.

use std::fs;
use std::path::PathBuf;

use super::{check_chapters, line_of};

/// A throw-away project tree under the system temp dir, removed on drop.
struct Tree(PathBuf);

impl Tree {
    fn new(name: &str) -> Tree {
        let dir =
            std::env::temp_dir().join(format!("raylemma-book-test-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        Tree(dir)
    }
    fn write(&self, rel: &str, contents: &str) {
        let p = self.0.join(rel);
        fs::create_dir_all(p.parent().unwrap()).unwrap();
        fs::write(p, contents).unwrap();
    }
    fn check(&self) -> Vec<String> {
        check_chapters(&self.0, &self.0.join("chapters"))
            .unwrap()
            .iter()
            .map(ToString::to_string)
            .collect()
    }
}

impl Drop for Tree {
    fn drop(&mut self) {
        let _ = fs::remove_dir_all(&self.0);
    }
}

const CODE: &str = "fn a() {}\n// ANCHOR: foo\nfn foo() {}\n// ANCHOR_END: foo\n\
                    // ANCHOR: open\nfn open() {}\n";

#[test]
fn valid_includes_and_images_pass() {
    let t = Tree::new("valid");
    t.write("src/lib.rs", "mod x;\n");
    t.write("src/x.rs", CODE);
    t.write("figures/plot.png", "png");
    t.write("chapters/local.png", "png");
    t.write(
        "chapters/geometry/sphere.md",
        "# Sphere\n\n```rust\n{{#include ../../src/x.rs:foo}}\n```\n\
         {{#rustdoc_include ../../src/x.rs:2:3}}\n{{#include ../../src/x.rs}}\n\
         ![plot](../figures/plot.png \"title\")\n![l](../local.png)\n\
         ![remote](https://example.com/x.png)\n<img alt=\"a plot\" src=\"../figures/plot.png\">\n\
         \\{{#include missing.rs}} is escaped\n",
    );
    t.write(
        "chapters/intro.md",
        "![p](figures/plot.png) {{ #include ../src/x.rs:foo }}",
    );
    assert_eq!(t.check(), Vec::<String>::new());
}

#[test]
fn images_without_alt_text_are_reported() {
    let t = Tree::new("alt");
    t.write("figures/plot.svg", "<svg/>");
    t.write(
        "chapters/a.md",
        "![](figures/plot.svg)\n\n![ ](figures/plot.svg)\n\n![`code` alt](figures/plot.svg)\n\n\
         <img src=\"figures/plot.svg\">\n\n<img alt='' src=\"figures/plot.svg\">\n",
    );
    assert_eq!(
        t.check(),
        [
            "chapters/a.md:1: image figures/plot.svg: no alt text (write ![what it shows](figures/plot.svg))",
            "chapters/a.md:3: image figures/plot.svg: no alt text (write ![what it shows](figures/plot.svg))",
            "chapters/a.md:7: <img> without alt text (add alt=\"what it shows\")",
            "chapters/a.md:9: <img> without alt text (add alt=\"what it shows\")",
        ]
    );
}

#[test]
fn missing_anchor_is_reported_with_file_and_line() {
    let t = Tree::new("anchor");
    t.write("src/x.rs", CODE);
    t.write(
        "chapters/geometry/sphere.md",
        "a\nb\n{{#include ../../src/x.rs:bar}}\n{{#rustdoc_include ../../src/x.rs:open}}\n",
    );
    assert_eq!(
        t.check(),
        vec![
            "chapters/geometry/sphere.md:3: include ../../src/x.rs:bar: \
             anchor 'bar' not found in src/x.rs",
            "chapters/geometry/sphere.md:4: rustdoc_include ../../src/x.rs:open: \
             anchor 'open' (line 5) has no 'ANCHOR_END: open' after it in src/x.rs",
        ]
    );
}

#[test]
fn missing_files_and_images_are_all_collected() {
    let t = Tree::new("missing");
    t.write("figures/plot.png", "png");
    t.write(
        "chapters/geometry/sphere.md",
        "{{#include ../../src/nope.rs}}\n\n![a](../figures/none.png)\n\n\
         ![b](../../figures/plot.png)\n\n![c](/figures/plot.png)\n\n\
         {{#playground ../../examples/missing.rs editable}}\n",
    );
    t.write("chapters/a.md", "![x](y%20z.png)\n");
    assert_eq!(
        t.check(),
        vec![
            "chapters/a.md:1: image y%20z.png: not found: chapters/y z.png",
            "chapters/geometry/sphere.md:1: include ../../src/nope.rs: \
             file not found: src/nope.rs",
            "chapters/geometry/sphere.md:3: image ../figures/none.png: \
             not found: figures/none.png",
            "chapters/geometry/sphere.md:5: image ../../figures/plot.png: \
             points outside the built book; figures are copied to the book's root, \
             so from this chapter write '../figures/plot.png'",
            "chapters/geometry/sphere.md:7: image /figures/plot.png: \
             absolute path; use a path relative to the chapter page",
            "chapters/geometry/sphere.md:9: playground ../../examples/missing.rs: \
             file not found: examples/missing.rs",
        ]
    );
}

#[test]
fn pasted_or_uncompiled_rust_is_refused() {
    let t = Tree::new("rust");
    t.write(
        "src/lib.rs",
        "pub mod a;\n#[cfg(test)]\nmod inline {\n    mod b;\n}\n",
    );
    t.write("src/a/mod.rs", "#[path = \"odd_name.rs\"]\nmod c;\n");
    t.write("src/a/odd_name.rs", CODE);
    t.write("src/inline/b.rs", CODE);
    t.write("src/orphan.rs", CODE);
    t.write("tests/book/main.rs", "mod part;\n");
    t.write("tests/book/part/mod.rs", "mod t;\n");
    t.write("tests/book/part/t.rs", CODE);
    t.write(
        "chapters/a.md",
        "```rust\n{{#include ../src/a/odd_name.rs:foo}}\n```\n\
         ```rust,ignore\n{{#include ../src/inline/b.rs:foo}}\n\n{{#include ../tests/book/part/t.rs}}\n```\n\
         ```rust\n{{#include ../src/orphan.rs:foo}}\n```\n\
         ```rust\nfn pasted() {}\nfn more() {}\n```\n\
         ```text\nfn not_rust() {}\n```\n",
    );
    assert_eq!(
        t.check(),
        vec![
            "chapters/a.md:10: src/orphan.rs is shown as Rust but no crate of the project \
             compiles it (no `mod` of a crate root reaches it)",
            "chapters/a.md:13: the rust block of line 12 holds pasted code, which nothing \
             compiles: include it by anchor from a file of src/ or tests/",
        ]
    );
}

#[test]
fn math_in_other_delimiters_is_refused() {
    let t = Tree::new("math");
    t.write(
        "chapters/a.md",
        "An answer \\\\(y\\\\) is fine as $y$.\n\\\\[ e = 1 \\\\]\n\
         $$\n\\begin{aligned} a \\\\[2pt] b \\end{aligned}\n$$\n\
         `\\\\(` in code\n```text\n\\\\(x\\\\)\n```\n",
    );
    let found = t.check();
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(
        found[0].starts_with("chapters/a.md:1: math delimited"),
        "{found:?}"
    );
    assert!(
        found[1].starts_with("chapters/a.md:2: math delimited"),
        "{found:?}"
    );
}

#[test]
fn control_characters_are_refused_with_what_they_were() {
    let t = Tree::new("control");
    t.write(
        "chapters/a.md",
        "Fine: $\\rho$.\nBroken: $\u{8}ar L$ and $2 \times 3$.\n$\rho$\n",
    );
    // One problem per line, for its first control character: line 2's backspace (and
    // not its tab), line 3's carriage return.
    let found = t.check();
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(
        found[0].starts_with("chapters/a.md:2: control character U+0008")
            && found[0].contains("\\bar"),
        "{found:?}"
    );
    assert!(
        found[1].starts_with("chapters/a.md:3: control character U+000D")
            && found[1].contains("\\rho"),
        "{found:?}"
    );
}

#[test]
fn numbers_are_checked_against_what_the_figure_job_recorded() {
    let t = Tree::new("numbers");
    t.write(
        "figures/values.json",
        r#"{"t": {"file": "t.md", "values": {"x.b": {"shown": "1", "number": 1.0}},
            "claims": {"x_above_2": {"holds": false, "read": "1 > 2"}}}}"#,
    );
    t.write(
        "chapters/a.md",
        "x is {{#value t.x.b}}.\n\nIt is above 2{{#claim t.x_above_2}}.\n\n\
         {{#value t.y.b}}\n",
    );
    let problems = t.check();
    assert_eq!(problems.len(), 2, "{problems:?}");
    assert!(
        problems[0].starts_with("chapters/a.md:3: claim does not hold: t.x_above_2")
            && problems[0].contains("read: 1 > 2"),
        "{problems:?}"
    );
    assert!(
        problems[1].starts_with("chapters/a.md:5: {{#value t.y.b}}: no such name")
            && problems[1].contains("t.x.b"),
        "{problems:?}"
    );
}

#[test]
fn line_numbers_are_one_based() {
    assert_eq!(line_of("abc", 0), 1);
    assert_eq!(line_of("a\nb\nc", 4), 3);
    assert_eq!(line_of("a\n", 99), 2);
}
