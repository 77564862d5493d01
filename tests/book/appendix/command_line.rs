//! Tests of the appendix *The command line* (`chapters/appendix/command-line.md`): the page
//! is every subcommand's `--help`, as the binary prints it, so it cannot drift from the
//! program. When a subcommand's help changes, this test fails and says how to write the
//! page again.

use std::process::Command;

use super::super::support::generated;

/// The page's path, from the crate's root.
const PAGE: &str = "chapters/appendix/command-line.md";
/// Set to write the page instead of checking it.
const WRITE: &str = "RAYLEMMA_WRITE_COMMAND_LINE";

/// What `raylemma ARGS --help` prints.
fn help(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_raylemma"))
        .args(args)
        .arg("--help")
        .output()
        .expect("raylemma runs");
    assert!(out.status.success(), "raylemma {args:?} --help failed");
    String::from_utf8(out.stdout).expect("help is UTF-8")
}

/// The subcommands a help text lists under `Commands:` (without `help`).
fn subcommands(help: &str) -> Vec<String> {
    help.lines()
        .skip_while(|l| l.trim() != "Commands:")
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next())
        .filter(|name| *name != "help")
        .map(str::to_string)
        .collect()
}

/// Every command (`[]` for `raylemma` itself, `["check", "sampler"]`) with its help, in the
/// order `--help` lists them, a subcommand's own subcommands after it.
fn helps() -> Vec<(Vec<String>, String)> {
    let mut all = Vec::new();
    let mut queue: Vec<Vec<String>> = vec![Vec::new()];
    while let Some(args) = queue.pop() {
        let argv: Vec<&str> = args.iter().map(String::as_str).collect();
        let text = help(&argv);
        // Depth first, in the listed order.
        for sub in subcommands(&text).into_iter().rev() {
            let mut next = args.clone();
            next.push(sub);
            queue.push(next);
        }
        all.push((args, text));
    }
    all
}

/// The page: an introduction, then each command's help ([`helps`]).
fn page() -> String {
    let mut text = String::from(
        "# The command line\n\n\
         <!-- Written by `RAYLEMMA_WRITE_COMMAND_LINE=1 cargo test --test book appendix::command_line`\n\
         from the binary's own help; do not edit: edit the doc comments in src/main.rs and src/cmd/. -->\n\n\
         Every subcommand of `raylemma`, as `raylemma SUBCOMMAND --help` prints it (`cargo run\n\
         --release -- SUBCOMMAND --help` in a clone). This page is that text: `cargo test` fails\n\
         when it is not. Every subcommand ends by one rule: exit status **0** for success (agree,\n\
         pass, done), **1** for a negative verdict or a job that failed on good input, **2** for bad\n\
         input or usage, with the file, the line and the problem. Two ends bypass it: a panic (such\n\
         as an exercise of the student hand-out not yet started) ends with Rust's status 101, and a\n\
         reader that closes the pipe early (`| head`) gets 0.\n",
    );
    for (args, help) in helps() {
        let title = std::iter::once("raylemma")
            .chain(args.iter().map(String::as_str))
            .collect::<Vec<_>>()
            .join(" ");
        text.push_str(&format!(
            "\n## `{title}`\n\n```text\n{}\n```\n",
            help.trim_end()
        ));
    }
    text
}

#[test]
fn the_command_line_page_is_every_subcommand_s_help() {
    generated(PAGE, &page(), WRITE);
}

#[test]
fn every_subcommand_s_help_ends_with_an_example() {
    // Every command that is run (one without subcommands of its own), `raylemma` aside.
    let missing: Vec<String> = helps()
        .into_iter()
        .filter(|(args, help)| !args.is_empty() && subcommands(help).is_empty())
        .filter(|(_, help)| !help.contains("Example"))
        .map(|(args, _)| args.join(" "))
        .collect();
    assert!(missing.is_empty(), "no example in the help of: {missing:?}");
}
