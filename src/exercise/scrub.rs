//! The solution-line scrubber: no line of a removed solution may survive anywhere in the
//! hand-out. Chapter: *Coursework* (`chapters/coursework.md`).
//!
//! Every line taken out of a marked body ([`super::stub::Removed`]) is split into its code
//! and its trailing comment, each compared with whitespace collapsed
//! ([`fragments`]); each fragment that is not trivial is searched for, as a substring, in
//! every line of every text file the hand-out ships (sources, tests, chapters, tables,
//! READMEs, doc comments included). One occurrence is a [`Leak`], and the hand-out is not
//! written.
//!
//! **The rule for trivial fragments** ([`is_trivial`]): a fragment is exempt when it has
//! fewer than [`MIN_CHARACTERS`] letters and digits, or when it names fewer than two
//! things: counting its distinct names, a path such as `Refraction::TotalInternalReflection`
//! as one, and leaving out Rust's keywords and the common names of [`COMMON_WORDS`]
//! (`None`, `Some`, `Ok`, `f64`, …). `}`, `} else {`, `None`, `Some(t)`, `0.0`,
//! `return V3::ZERO;`, `Wavelengths {` and `if cos2_t < 0.0 {` say nothing of a solution;
//! `let w = n.cross(t);` names three things, and is searched for.

/// The fewest letters and digits a fragment needs to be searched for.
pub const MIN_CHARACTERS: usize = 8;

/// Words that alone make a fragment trivial: Rust's keywords and the prelude's most
/// common names.
pub const COMMON_WORDS: &[&str] = &[
    "as", "break", "const", "continue", "crate", "else", "false", "fn", "for", "if", "impl", "in",
    "let", "loop", "match", "mut", "pub", "ref", "return", "self", "Self", "static", "super",
    "true", "use", "where", "while", "None", "Some", "Ok", "Err", "Option", "Result", "f32", "f64",
    "usize", "u32", "u64", "i32", "i64",
];

/// A removed line found in a shipped file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Leak {
    /// The exercise whose solution leaks.
    pub exercise: String,
    /// Where the solution line was (file relative to the crate's root, 1-based line).
    pub solution: (String, usize),
    /// The fragment found.
    pub fragment: String,
    /// Where it was found in the hand-out.
    pub found: (String, usize),
}

impl std::fmt::Display for Leak {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{}: `{}` (a line of the solution of exercise `{}`, at {}:{}) is in the hand-out",
            self.found.0,
            self.found.1,
            self.fragment,
            self.exercise,
            self.solution.0,
            self.solution.1
        )
    }
}

/// `line` trimmed, with every run of whitespace made one space.
pub fn normalise(line: &str) -> String {
    line.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The code of `line` and its trailing `//` comment (the comment's text without the
/// slashes), each normalised; empty parts are left out. A `//` inside a string literal
/// does not start a comment.
pub fn fragments(line: &str) -> Vec<String> {
    let bytes = line.as_bytes();
    let (mut in_string, mut escaped) = (false, false);
    let mut split = None;
    for i in 0..bytes.len() {
        let b = bytes[i];
        if in_string {
            match (escaped, b) {
                (true, _) => escaped = false,
                (false, b'\\') => escaped = true,
                (false, b'"') => in_string = false,
                _ => {}
            }
        } else if b == b'"' {
            in_string = true;
        } else if b == b'/' && bytes.get(i + 1) == Some(&b'/') {
            split = Some(i);
            break;
        }
    }
    let (code, comment) = match split {
        Some(i) => (&line[..i], line[i..].trim_start_matches(['/', '!'])),
        None => (line, ""),
    };
    [normalise(code), normalise(comment)]
        .into_iter()
        .filter(|f| !f.is_empty())
        .collect()
}

/// True iff `fragment` is exempt from the search (see the module's rule).
pub fn is_trivial(fragment: &str) -> bool {
    let characters = fragment.chars().filter(|c| c.is_alphanumeric()).count();
    if characters < MIN_CHARACTERS {
        return true;
    }
    names(fragment).len() < 2
}

/// The distinct names of `fragment` outside [`COMMON_WORDS`]: identifiers, a path joined
/// by `::` counting as one; numbers (`0.5`, `1e-3`, `2.0_f64`) are not names.
pub fn names(fragment: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let bytes: Vec<char> = fragment.chars().collect();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        if c.is_ascii_digit() {
            // A number, with its exponent, fraction and suffix.
            while i < bytes.len()
                && (bytes[i].is_alphanumeric() || bytes[i] == '_' || bytes[i] == '.')
            {
                i += 1;
            }
            continue;
        }
        if !(c.is_alphabetic() || c == '_') {
            i += 1;
            continue;
        }
        let mut path = String::new();
        loop {
            let start = i;
            while i < bytes.len() && (bytes[i].is_alphanumeric() || bytes[i] == '_') {
                i += 1;
            }
            let word: String = bytes[start..i].iter().collect();
            if !COMMON_WORDS.contains(&word.as_str()) {
                if !path.is_empty() {
                    path.push_str("::");
                }
                path.push_str(&word);
            }
            let more = i + 2 < bytes.len()
                && bytes[i] == ':'
                && bytes[i + 1] == ':'
                && (bytes[i + 2].is_alphabetic() || bytes[i + 2] == '_');
            if !more {
                break;
            }
            i += 2;
        }
        if !path.is_empty() && !out.contains(&path) {
            out.push(path);
        }
    }
    out
}

/// Every occurrence of a non-trivial fragment of a `removed` line in the `files`
/// (`(path, text)`), in the files' order.
pub fn leaks(removed: &[super::stub::Removed], files: &[(String, String)]) -> Vec<Leak> {
    let mut needles: Vec<(String, &super::stub::Removed)> = Vec::new();
    for r in removed {
        for f in fragments(&r.text) {
            if !is_trivial(&f) && !needles.iter().any(|(n, _)| *n == f) {
                needles.push((f, r));
            }
        }
    }
    let mut out = Vec::new();
    for (path, text) in files {
        for (i, line) in text.lines().enumerate() {
            let line = normalise(line);
            for (needle, r) in &needles {
                if line.contains(needle.as_str()) {
                    out.push(Leak {
                        exercise: r.exercise.clone(),
                        solution: (r.file.clone(), r.line),
                        fragment: needle.clone(),
                        found: (path.clone(), i + 1),
                    });
                }
            }
        }
    }
    out
}
