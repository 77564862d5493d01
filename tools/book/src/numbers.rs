//! The book's numbers, read from the tables that measure them.
//!
//! Chapters quote measured values and rank methods by them. A number typed into the prose
//! drifts from its table as soon as the table is regenerated (on another machine, after a
//! change of the code); so the prose reads it from the generated file instead, with two
//! directives that this module evaluates over the files of `figures/`:
//!
//! - `{{#value FILE EXPR [as FORMAT]}}` is replaced by the value of `EXPR`: one cell's text
//!   as the table has it, or a number computed from cells, formatted by `FORMAT`.
//! - `{{#claim FILE EXPR}}` states a comparison between cells and renders nothing; the book
//!   fails to build, naming the chapter, its line, the sentence and the cells read, when the
//!   comparison does not hold for the tables as they are now.
//!
//! `FILE` is a file of `figures/` (`sampling_methods.md`); when it holds several tables,
//! `FILE#N` names the N-th (from 1). The expression language:
//!
//! - a **cell** is `"ROW" "COLUMN"`: the row whose first cell is `ROW` (with ` & ` between
//!   parts, `"cornell & 256"`, the row whose first cell is `cornell` and another cell `256`),
//!   and the column whose header is `COLUMN` (or the one header that starts with it; `"#N"`
//!   is the N-th column from 1, for a header that is not unique). Cells
//!   are compared without their backticks and bold marks. `OTHER.md "ROW" "COLUMN"` reads a
//!   cell of another file.
//! - `text("A", "B", …)` is the number that follows `B` after the first `A` in the file's
//!   text (for generated text that is not a table: a checker's verdict, a report).
//! - numbers, strings (`"…"`), `+ - * /`, parentheses, `< <= > >= == !=` (chained:
//!   `a < b < c`), `and`, `or`, `not`;
//! - `max(…)`, `min(…)`, `abs(x)` of expressions or of a **slice**, `column "C"` or `row "R"`
//!   (every numeric cell of it; `except "X", "Y"` leaves some out); `argmax(slice)` and
//!   `argmin(slice)`: the name of the row (or column) holding the extreme;
//! - **quantifiers** over the rows or the columns (the first column, the rows' names, is not
//!   a column here): `every row: …`, `no row: …`, `some row: …`, `count row: …` (how many),
//!   `which row: …` (their names, "a, b and c"), each with an optional `except "X", …`
//!   before the colon. Inside, `@` stands for the row (in a cell's row place) or the column
//!   (in a cell's column place) being visited: `every row: @ "cone" < @ "cap area"`.
//!
//! `FORMAT` is `.N` (N decimals), `sN` (N significant digits), `xN` (TeX scientific
//! notation with N decimals, for use inside `$…$`) or `int`.
//!
//! Two rules keep comparisons honest across regenerations. A directive that reads timing
//! tables measured on different machines (their captions' fingerprints differ, or one has
//! none) is an error: such numbers may not be compared. A claim that fails on a table made by
//! the figure job's `--quick` mode (noisy, for CI; its file says "quick mode") is a warning,
//! not an error, since quick tables are not for quoting.

use std::collections::{BTreeSet, HashMap};
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::sync::LazyLock;

use anyhow::Result;
use regex::Regex;

/// The directives of this module, as mdBook finds its own (`{{#name args}}`, `\{{` escaped).
static DIRECTIVE: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(
        r"(?x)\\\{\{\#.*\}\}|\{\{\s*\#(value|claim)\s+([^}\s]+\.(?:md|txt)(?:\#\d+)?\s[^}]+)\}\}",
    )
    .expect("valid regex")
});
/// A machine's fingerprint in a timing table's caption (`tools/figures/src/timing.rs`).
static FINGERPRINT: LazyLock<Regex> =
    LazyLock::new(|| Regex::new(r"fingerprint `?([0-9a-f]{8})").expect("valid regex"));
/// Captions of timing tables, with or without a fingerprint.
static TIMED: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r"single thread|worker threads?|fingerprint `?[0-9a-f]{8}").expect("valid regex")
});
static NUMBER: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r"^[+-]?(?:\d{1,3}(?: \d{3})+(?:\.\d+)?|\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?")
        .expect("valid regex")
});

/// `{{#value}}` or `{{#claim}}`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Value,
    Claim,
}

/// One directive found in a chapter.
#[derive(Clone, Debug)]
pub struct Directive {
    pub kind: Kind,
    /// What follows the directive's name.
    pub args: String,
    /// Byte range of the whole directive in the chapter.
    pub start: usize,
    pub end: usize,
}

/// The directives of `text`, in order; escaped ones (`\{{#value …}}`) are left out.
pub fn directives(text: &str) -> Vec<Directive> {
    DIRECTIVE
        .captures_iter(text)
        .filter_map(|cap| {
            let whole = cap.get(0)?;
            let kind = match cap.get(1)?.as_str() {
                "value" => Kind::Value,
                _ => Kind::Claim,
            };
            Some(Directive {
                kind,
                args: cap.get(2)?.as_str().to_string(),
                start: whole.start(),
                end: whole.end(),
            })
        })
        .collect()
}

/// One markdown table of a generated file.
#[derive(Debug)]
struct Table {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

/// One generated file of `figures/`, read once.
#[derive(Debug)]
struct Source {
    text: String,
    tables: Vec<Table>,
    /// `Some(fingerprint)` for a timing table that names its machine's fingerprint,
    /// `Some("")` for one that does not, `None` for a file that times nothing.
    machine: Option<String>,
    quick: bool,
}

/// The generated files, read on demand from `figures/`.
pub struct Tables {
    dir: PathBuf,
    cache: HashMap<String, Result<Rc<Source>, String>>,
}

/// What a directive evaluated to.
#[derive(Debug, Clone, PartialEq)]
pub struct Evaluated {
    /// The text that replaces the directive (empty for a claim).
    pub text: String,
    /// For a claim that does not hold: what was read.
    pub failure: Option<String>,
    /// Whether a file it read was made in quick mode.
    pub quick: bool,
}

impl Tables {
    /// The files of `dir` (the project's `figures/`).
    pub fn new(dir: &Path) -> Tables {
        Tables {
            dir: dir.to_path_buf(),
            cache: HashMap::new(),
        }
    }

    fn source(&mut self, file: &str) -> Result<Rc<Source>, String> {
        let dir = &self.dir;
        self.cache
            .entry(file.to_string())
            .or_insert_with(|| {
                if file.contains("..") || file.starts_with('/') {
                    return Err(format!("{file}: name a file of figures/, without a path"));
                }
                match fs::read_to_string(dir.join(file)) {
                    Ok(text) => Ok(Rc::new(parse_source(text))),
                    Err(e) => Err(format!("figures/{file}: {e}")),
                }
            })
            .clone()
    }

    /// Evaluates the arguments of one directive.
    pub fn evaluate(&mut self, kind: Kind, args: &str) -> Result<Evaluated, String> {
        let tokens = lex(args)?;
        let mut p = Parser { t: tokens, i: 0 };
        let Some(Tok::Path(file)) = p.next() else {
            return Err(
                "a directive starts with the file it reads, e.g. `sampling_methods.md`".into(),
            );
        };
        let expr = p.quantified()?;
        let format = match p.next() {
            None => None,
            Some(Tok::Format(f)) => Some(f),
            Some(t) => return Err(format!("unexpected {} after the expression", t.show())),
        };
        let mut cx = Context {
            tables: self,
            default: file,
            row: None,
            col: None,
            read: Vec::new(),
            files: BTreeSet::new(),
        };
        let value = cx.eval(&expr)?;
        cx.check_machines()?;
        let quick = cx.quick();
        let read = cx.read_list();
        match kind {
            Kind::Claim => {
                if format.is_some() {
                    return Err("a claim renders nothing: leave out `as …`".into());
                }
                match value {
                    Val::Bool(true) => Ok(Evaluated {
                        text: String::new(),
                        failure: None,
                        quick,
                    }),
                    Val::Bool(false) => Ok(Evaluated {
                        text: String::new(),
                        failure: Some(read),
                        quick,
                    }),
                    other => Err(format!(
                        "a claim must be a comparison, not {}",
                        other.describe()
                    )),
                }
            }
            Kind::Value => Ok(Evaluated {
                text: render(&value, &expr, format.as_deref())?,
                failure: None,
                quick,
            }),
        }
    }
}

fn parse_source(text: String) -> Source {
    let lines: Vec<&str> = text.lines().collect();
    let mut tables = Vec::new();
    let mut i = 0;
    let mut in_code = false;
    while i < lines.len() {
        let line = lines[i].trim();
        if line.starts_with("```") {
            in_code = !in_code;
        }
        if !in_code
            && line.starts_with('|')
            && i + 1 < lines.len()
            && is_separator(lines[i + 1].trim())
        {
            let header = split_row(line);
            let mut rows = Vec::new();
            i += 2;
            while i < lines.len() && lines[i].trim().starts_with('|') {
                rows.push(split_row(lines[i].trim()));
                i += 1;
            }
            tables.push(Table { header, rows });
            continue;
        }
        i += 1;
    }
    let machine = if TIMED.is_match(&text) {
        let prints: BTreeSet<&str> = FINGERPRINT
            .captures_iter(&text)
            .filter_map(|c| c.get(1).map(|m| m.as_str()))
            .collect();
        Some(if prints.len() == 1 {
            prints.into_iter().next().unwrap_or_default().to_string()
        } else {
            String::new()
        })
    } else {
        None
    };
    let quick = text.contains("quick mode");
    Source {
        text,
        tables,
        machine,
        quick,
    }
}

fn is_separator(line: &str) -> bool {
    line.starts_with('|')
        && line.contains('-')
        && line.chars().all(|c| matches!(c, '|' | '-' | ':' | ' '))
}

/// The cells of a table row, split at unescaped `|`, with `\|` unescaped.
fn split_row(line: &str) -> Vec<String> {
    let inner = line.strip_prefix('|').unwrap_or(line);
    let inner = inner.strip_suffix('|').unwrap_or(inner);
    let mut cells = Vec::new();
    let mut cell = String::new();
    let mut chars = inner.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                cell.push('|');
                chars.next();
            }
            '|' => cells.push(std::mem::take(&mut cell).trim().to_string()),
            _ => cell.push(c),
        }
    }
    cells.push(cell.trim().to_string());
    cells
}

/// A cell or name as it is matched: without backticks and bold marks, spaces collapsed.
fn normal(s: &str) -> String {
    s.replace("**", "")
        .replace('`', "")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// The number a cell or text starts with (`42.4 %` is 42.4, `1 (1.7 %)` is 1, `10 000`
/// is 10000, `−3` is −3, `inf`), if any.
pub fn leading_number(s: &str) -> Option<f64> {
    let s = normal(s).replace('\u{2212}', "-");
    let s = s.trim_start_matches(['~', '≈', '$']).trim_start();
    for (word, value) in [
        ("inf", f64::INFINITY),
        ("-inf", f64::NEG_INFINITY),
        ("NaN", f64::NAN),
    ] {
        if s.starts_with(word) && !s[word.len()..].starts_with(|c: char| c.is_alphanumeric()) {
            return Some(value);
        }
    }
    let m = NUMBER.find(s)?;
    m.as_str().replace(' ', "").parse().ok()
}

// ---------------------------------------------------------------------------------------
// Tokens and syntax

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Str(String),
    Num(f64),
    Word(String),
    Path(String),
    Op(&'static str),
    At,
    Format(String),
}

impl Tok {
    fn show(&self) -> String {
        match self {
            Tok::Str(s) => format!("\"{s}\""),
            Tok::Num(x) => format!("{x}"),
            Tok::Word(w) | Tok::Path(w) => format!("`{w}`"),
            Tok::Op(o) => format!("`{o}`"),
            Tok::At => "`@`".into(),
            Tok::Format(f) => format!("`as {f}`"),
        }
    }
}

static PATH: LazyLock<Regex> = LazyLock::new(|| {
    Regex::new(r"^[A-Za-z0-9_][A-Za-z0-9_.-]*\.(?:md|txt)(?:#[0-9]+)?").expect("valid regex")
});

fn lex(s: &str) -> Result<Vec<Tok>, String> {
    let mut out = Vec::new();
    let mut rest = s.trim_start();
    while !rest.is_empty() {
        let c = rest.chars().next().unwrap_or(' ');
        if c == '"' {
            let mut text = String::new();
            let mut chars = rest[1..].char_indices();
            let mut end = None;
            while let Some((i, ch)) = chars.next() {
                match ch {
                    '\\' => {
                        if let Some((_, n)) = chars.next() {
                            text.push(n);
                        }
                    }
                    '"' => {
                        end = Some(i + 2);
                        break;
                    }
                    _ => text.push(ch),
                }
            }
            let end = end.ok_or("a string is not closed with `\"`")?;
            out.push(Tok::Str(text));
            rest = &rest[end..];
        } else if let Some(m) = PATH.find(rest) {
            out.push(Tok::Path(m.as_str().to_string()));
            rest = &rest[m.end()..];
        } else if c.is_ascii_digit()
            || (c == '.' && rest[1..].starts_with(|d: char| d.is_ascii_digit()))
        {
            let m = NUMBER.find(rest).ok_or("a malformed number")?;
            let x: f64 = m
                .as_str()
                .replace(' ', "")
                .parse()
                .map_err(|_| "a malformed number")?;
            out.push(Tok::Num(x));
            rest = &rest[m.end()..];
        } else if c.is_ascii_alphabetic() {
            let end = rest
                .find(|ch: char| !(ch.is_ascii_alphanumeric() || ch == '_'))
                .unwrap_or(rest.len());
            let word = &rest[..end];
            if word == "as" {
                let format = rest[end..].trim();
                if format.is_empty() {
                    return Err("`as` needs a format: .N, sN, xN or int".into());
                }
                out.push(Tok::Format(format.to_string()));
                break;
            }
            out.push(Tok::Word(word.to_string()));
            rest = &rest[end..];
        } else if c == '@' {
            out.push(Tok::At);
            rest = &rest[1..];
        } else {
            let op = [
                "<=", ">=", "==", "!=", "<", ">", "+", "-", "*", "/", "(", ")", ",", ":",
            ]
            .into_iter()
            .find(|op| rest.starts_with(op))
            .ok_or_else(|| format!("unexpected character `{c}`"))?;
            out.push(Tok::Op(op));
            rest = &rest[op.len()..];
        }
        rest = rest.trim_start();
    }
    Ok(out)
}

/// A row or column named in a cell or slice: by name, or `@`, the one being visited.
#[derive(Clone, Debug)]
enum Sel {
    Name(String),
    Visited,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Axis {
    Row,
    Column,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Quant {
    Every,
    No,
    Some,
    Count,
    Which,
}

#[derive(Clone, Debug)]
enum Expr {
    Num(f64),
    Str(String),
    Cell {
        file: Option<String>,
        row: Sel,
        col: Sel,
    },
    Text {
        file: Option<String>,
        anchors: Vec<String>,
    },
    Neg(Box<Expr>),
    Arith(Box<Expr>, char, Box<Expr>),
    Compare(Vec<Expr>, Vec<&'static str>),
    And(Vec<Expr>),
    Or(Vec<Expr>),
    Not(Box<Expr>),
    Func(String, Vec<Arg>),
    Quantified {
        quant: Quant,
        axis: Axis,
        except: Vec<String>,
        body: Box<Expr>,
    },
}

#[derive(Clone, Debug)]
enum Arg {
    Expr(Expr),
    Slice {
        file: Option<String>,
        axis: Axis,
        sel: Sel,
        except: Vec<String>,
    },
}

struct Parser {
    t: Vec<Tok>,
    i: usize,
}

impl Parser {
    fn peek(&self) -> Option<&Tok> {
        self.t.get(self.i)
    }
    fn peek_at(&self, k: usize) -> Option<&Tok> {
        self.t.get(self.i + k)
    }
    fn next(&mut self) -> Option<Tok> {
        let t = self.t.get(self.i).cloned();
        self.i += 1;
        t
    }
    fn eat_op(&mut self, op: &str) -> bool {
        if matches!(self.peek(), Some(Tok::Op(o)) if *o == op) {
            self.i += 1;
            true
        } else {
            false
        }
    }
    fn eat_word(&mut self, w: &str) -> bool {
        if matches!(self.peek(), Some(Tok::Word(x)) if x == w) {
            self.i += 1;
            true
        } else {
            false
        }
    }
    fn expect_op(&mut self, op: &str) -> Result<(), String> {
        if self.eat_op(op) {
            Ok(())
        } else {
            Err(format!("expected `{op}`, found {}", self.found()))
        }
    }
    fn found(&self) -> String {
        self.peek().map_or("the end".into(), Tok::show)
    }

    /// A quantifier, or an expression.
    fn quantified(&mut self) -> Result<Expr, String> {
        let quant = match self.peek() {
            Some(Tok::Word(w)) => match w.as_str() {
                "every" => Some(Quant::Every),
                "no" => Some(Quant::No),
                "some" => Some(Quant::Some),
                "count" => Some(Quant::Count),
                "which" => Some(Quant::Which),
                _ => None,
            },
            _ => None,
        };
        let Some(quant) = quant else {
            return self.or();
        };
        self.i += 1;
        let axis = self.axis()?;
        let except = self.except()?;
        self.expect_op(":")?;
        let body = self.quantified()?;
        Ok(Expr::Quantified {
            quant,
            axis,
            except,
            body: Box::new(body),
        })
    }

    fn axis(&mut self) -> Result<Axis, String> {
        if self.eat_word("row") || self.eat_word("rows") {
            Ok(Axis::Row)
        } else if self.eat_word("column") || self.eat_word("columns") {
            Ok(Axis::Column)
        } else {
            Err(format!(
                "expected `row` or `column`, found {}",
                self.found()
            ))
        }
    }

    fn except(&mut self) -> Result<Vec<String>, String> {
        let mut names = Vec::new();
        if self.eat_word("except") {
            loop {
                match self.next() {
                    Some(Tok::Str(s)) => names.push(s),
                    t => {
                        return Err(format!(
                            "`except` takes names in quotes, found {}",
                            t.map_or("the end".into(), |t| t.show())
                        ));
                    }
                }
                if !self.eat_op(",") {
                    break;
                }
            }
        }
        Ok(names)
    }

    fn or(&mut self) -> Result<Expr, String> {
        let mut items = vec![self.and()?];
        while self.eat_word("or") {
            items.push(self.and()?);
        }
        Ok(if items.len() == 1 {
            items.pop().expect("one")
        } else {
            Expr::Or(items)
        })
    }

    fn and(&mut self) -> Result<Expr, String> {
        let mut items = vec![self.not()?];
        while self.eat_word("and") {
            items.push(self.not()?);
        }
        Ok(if items.len() == 1 {
            items.pop().expect("one")
        } else {
            Expr::And(items)
        })
    }

    fn not(&mut self) -> Result<Expr, String> {
        if self.eat_word("not") {
            return Ok(Expr::Not(Box::new(self.not()?)));
        }
        self.compare()
    }

    fn compare(&mut self) -> Result<Expr, String> {
        let mut items = vec![self.sum()?];
        let mut ops = Vec::new();
        while let Some(Tok::Op(o)) = self.peek() {
            let o = *o;
            if !matches!(o, "<" | "<=" | ">" | ">=" | "==" | "!=") {
                break;
            }
            self.i += 1;
            ops.push(o);
            items.push(self.sum()?);
        }
        Ok(if ops.is_empty() {
            items.pop().expect("one")
        } else {
            Expr::Compare(items, ops)
        })
    }

    fn sum(&mut self) -> Result<Expr, String> {
        let mut left = self.product()?;
        loop {
            let op = if self.eat_op("+") {
                '+'
            } else if self.eat_op("-") {
                '-'
            } else {
                return Ok(left);
            };
            left = Expr::Arith(Box::new(left), op, Box::new(self.product()?));
        }
    }

    fn product(&mut self) -> Result<Expr, String> {
        let mut left = self.unary()?;
        loop {
            let op = if self.eat_op("*") {
                '*'
            } else if self.eat_op("/") {
                '/'
            } else {
                return Ok(left);
            };
            left = Expr::Arith(Box::new(left), op, Box::new(self.unary()?));
        }
    }

    fn unary(&mut self) -> Result<Expr, String> {
        if self.eat_op("-") {
            return Ok(Expr::Neg(Box::new(self.unary()?)));
        }
        self.atom()
    }

    fn sel(&mut self) -> Option<Sel> {
        match self.peek() {
            Some(Tok::Str(s)) => {
                let s = s.clone();
                self.i += 1;
                Some(Sel::Name(s))
            }
            Some(Tok::At) => {
                self.i += 1;
                Some(Sel::Visited)
            }
            _ => None,
        }
    }

    fn atom(&mut self) -> Result<Expr, String> {
        let file = match self.peek() {
            Some(Tok::Path(p)) => {
                let p = p.clone();
                self.i += 1;
                Some(p)
            }
            _ => None,
        };
        if file.is_some() && self.eat_word("text") {
            return self.text(file);
        }
        let starts_cell = matches!(self.peek(), Some(Tok::Str(_) | Tok::At))
            && matches!(self.peek_at(1), Some(Tok::Str(_) | Tok::At));
        if starts_cell {
            let row = self.sel().expect("checked");
            let col = self.sel().expect("checked");
            return Ok(Expr::Cell { file, row, col });
        }
        if file.is_some() {
            return Err(format!(
                "after a file name, expected a cell (\"ROW\" \"COLUMN\") or text(…), found {}",
                self.found()
            ));
        }
        match self.next() {
            Some(Tok::Num(x)) => Ok(Expr::Num(x)),
            Some(Tok::Str(s)) => Ok(Expr::Str(s)),
            Some(Tok::At) => Err("`@` alone: a cell needs a row and a column".into()),
            Some(Tok::Op("(")) => {
                let e = self.quantified()?;
                self.expect_op(")")?;
                Ok(e)
            }
            Some(Tok::Word(w)) if w == "text" => self.text(None),
            Some(Tok::Word(w))
                if matches!(w.as_str(), "max" | "min" | "abs" | "argmax" | "argmin") =>
            {
                self.expect_op("(")?;
                let mut args = Vec::new();
                if !self.eat_op(")") {
                    loop {
                        args.push(self.arg()?);
                        if self.eat_op(")") {
                            break;
                        }
                        self.expect_op(",")?;
                    }
                }
                Ok(Expr::Func(w, args))
            }
            Some(t) => Err(format!("unexpected {}", t.show())),
            None => Err("the expression ends too early".into()),
        }
    }

    fn text(&mut self, file: Option<String>) -> Result<Expr, String> {
        self.expect_op("(")?;
        let mut anchors = Vec::new();
        loop {
            match self.next() {
                Some(Tok::Str(s)) => anchors.push(s),
                t => {
                    return Err(format!(
                        "text(…) takes strings, found {}",
                        t.map_or("the end".into(), |t| t.show())
                    ));
                }
            }
            if self.eat_op(")") {
                break;
            }
            self.expect_op(",")?;
        }
        Ok(Expr::Text { file, anchors })
    }

    fn arg(&mut self) -> Result<Arg, String> {
        let file = match (self.peek(), self.peek_at(1)) {
            (Some(Tok::Path(p)), Some(Tok::Word(w))) if w == "row" || w == "column" => {
                let p = p.clone();
                self.i += 1;
                Some(p)
            }
            _ => None,
        };
        let axis = if self.eat_word("row") {
            Some(Axis::Row)
        } else if self.eat_word("column") {
            Some(Axis::Column)
        } else {
            None
        };
        let Some(axis) = axis else {
            return Ok(Arg::Expr(self.quantified()?));
        };
        let sel = self
            .sel()
            .ok_or_else(|| format!("a slice names its row or column, found {}", self.found()))?;
        let except = self.except()?;
        Ok(Arg::Slice {
            file,
            axis,
            sel,
            except,
        })
    }
}

// ---------------------------------------------------------------------------------------
// Evaluation

#[derive(Clone, Debug)]
enum Val {
    /// A number, with the cell's own text when it is one cell.
    Num(f64, Option<String>),
    Str(String),
    Bool(bool),
    Names(Vec<String>),
}

impl Val {
    fn describe(&self) -> String {
        match self {
            Val::Num(x, _) => format!("the number {x}"),
            Val::Str(s) => format!("the text \"{s}\""),
            Val::Bool(b) => format!("{b}"),
            Val::Names(n) => format!("the names {n:?}"),
        }
    }
    fn num(&self) -> Result<f64, String> {
        match self {
            Val::Num(x, _) => Ok(*x),
            other => Err(format!("expected a number, found {}", other.describe())),
        }
    }
    fn bool(&self) -> Result<bool, String> {
        match self {
            Val::Bool(b) => Ok(*b),
            other => Err(format!("expected a comparison, found {}", other.describe())),
        }
    }
}

struct Context<'a> {
    tables: &'a mut Tables,
    default: String,
    row: Option<String>,
    col: Option<String>,
    /// Cells read, for the report of a failed claim.
    read: Vec<String>,
    /// Files read (names as written, `#N` removed).
    files: BTreeSet<String>,
}

impl Context<'_> {
    fn file_of<'f>(&'f self, file: &'f Option<String>) -> &'f str {
        file.as_deref().unwrap_or(&self.default)
    }

    fn open(&mut self, file: &str) -> Result<Rc<Source>, String> {
        let name = file.split('#').next().unwrap_or(file);
        let source = self.tables.source(name)?;
        self.files.insert(name.to_string());
        Ok(source)
    }

    fn table(&mut self, file: &str) -> Result<(Rc<Source>, usize), String> {
        let (name, index) = match file.split_once('#') {
            Some((n, k)) => (
                n,
                Some(
                    k.parse::<usize>()
                        .map_err(|_| format!("{file}: bad table number"))?,
                ),
            ),
            None => (file, None),
        };
        let source = self.open(name)?;
        let n = source.tables.len();
        let k = match index {
            Some(k) if k >= 1 && k <= n => k - 1,
            Some(k) => return Err(format!("figures/{name} has {n} table(s), not a table {k}")),
            None if n == 1 => 0,
            None if n == 0 => return Err(format!("figures/{name} holds no table")),
            None => {
                return Err(format!(
                    "figures/{name} holds {n} tables: name one, as {name}#1 to {name}#{n}"
                ));
            }
        };
        Ok((source, k))
    }

    fn name(&self, sel: &Sel, axis: Axis) -> Result<String, String> {
        match sel {
            Sel::Name(s) => Ok(s.clone()),
            Sel::Visited => {
                let bound = match axis {
                    Axis::Row => &self.row,
                    Axis::Column => &self.col,
                };
                bound.clone().ok_or_else(|| {
                    format!(
                        "`@` in a {} place, but no `every {}` (or count, which…) visits one",
                        if axis == Axis::Row { "row" } else { "column" },
                        if axis == Axis::Row { "row" } else { "column" }
                    )
                })
            }
        }
    }

    fn cell(&mut self, file: &str, row: &str, col: &str) -> Result<String, String> {
        let (source, k) = self.table(file)?;
        let table = &source.tables[k];
        let r = find_row(table, row).map_err(|e| format!("figures/{file}: {e}"))?;
        let c = find_column(table, col).map_err(|e| format!("figures/{file}: {e}"))?;
        let text = table.rows[r].get(c).cloned().unwrap_or_default();
        let entry = format!("figures/{file}: \"{row}\" \"{}\" = {text}", table.header[c]);
        if !self.read.contains(&entry) {
            self.read.push(entry);
        }
        Ok(text)
    }

    fn eval(&mut self, e: &Expr) -> Result<Val, String> {
        match e {
            Expr::Num(x) => Ok(Val::Num(*x, None)),
            Expr::Str(s) => Ok(Val::Str(s.clone())),
            Expr::Cell { file, row, col } => {
                let file = self.file_of(file).to_string();
                let row = self.name(row, Axis::Row)?;
                let col = self.name(col, Axis::Column)?;
                let text = self.cell(&file, &row, &col)?;
                Ok(match leading_number(&text) {
                    Some(x) => Val::Num(x, Some(text)),
                    None => Val::Str(text),
                })
            }
            Expr::Text { file, anchors } => {
                let file = self.file_of(file).to_string();
                let source = self.open(&file)?;
                let (x, shown) = text_number(&source.text, anchors)
                    .map_err(|e| format!("figures/{file}: {e}"))?;
                self.read
                    .push(format!("figures/{file}: text({anchors:?}) = {shown}"));
                Ok(Val::Num(x, Some(shown)))
            }
            Expr::Neg(a) => Ok(Val::Num(-self.eval(a)?.num()?, None)),
            Expr::Arith(a, op, b) => {
                let (a, b) = (self.eval(a)?.num()?, self.eval(b)?.num()?);
                Ok(Val::Num(
                    match op {
                        '+' => a + b,
                        '-' => a - b,
                        '*' => a * b,
                        _ => a / b,
                    },
                    None,
                ))
            }
            Expr::Compare(items, ops) => {
                let vals = items
                    .iter()
                    .map(|i| self.eval(i))
                    .collect::<Result<Vec<_>, _>>()?;
                for (k, op) in ops.iter().enumerate() {
                    if !compare(&vals[k], op, &vals[k + 1])? {
                        return Ok(Val::Bool(false));
                    }
                }
                Ok(Val::Bool(true))
            }
            Expr::And(items) => {
                let mut all = true;
                for i in items {
                    all &= self.eval(i)?.bool()?;
                }
                Ok(Val::Bool(all))
            }
            Expr::Or(items) => {
                let mut any = false;
                for i in items {
                    any |= self.eval(i)?.bool()?;
                }
                Ok(Val::Bool(any))
            }
            Expr::Not(a) => Ok(Val::Bool(!self.eval(a)?.bool()?)),
            Expr::Func(name, args) => self.func(name, args),
            Expr::Quantified {
                quant,
                axis,
                except,
                body,
            } => self.quantify(*quant, *axis, except, body),
        }
    }

    /// The names a quantifier or slice visits in the directive's table.
    fn names(&mut self, file: &str, axis: Axis, except: &[String]) -> Result<Vec<String>, String> {
        let (source, k) = self.table(file)?;
        let table = &source.tables[k];
        let all: Vec<String> = match axis {
            // A row is visited by a name that finds it alone: its first cell, with as many
            // of its other cells (`"a & b"`) as it takes when the first is not unique.
            Axis::Row => (0..table.rows.len())
                .map(|i| unique_row_name(table, i))
                .collect(),
            Axis::Column => table.header.iter().skip(1).cloned().collect(),
        };
        for x in except {
            if !all.iter().any(|n| normal(n) == normal(x)) {
                return Err(format!(
                    "figures/{file}: `except \"{x}\"`: no such {} (there are: {})",
                    if axis == Axis::Row { "row" } else { "column" },
                    all.join("; ")
                ));
            }
        }
        Ok(all
            .into_iter()
            .filter(|n| !except.iter().any(|x| normal(x) == normal(n)))
            .collect())
    }

    fn quantify(
        &mut self,
        quant: Quant,
        axis: Axis,
        except: &[String],
        body: &Expr,
    ) -> Result<Val, String> {
        let file = self.default.clone();
        let names = self.names(&file, axis, except)?;
        let mut holds = Vec::new();
        let mut fails = Vec::new();
        for n in names {
            let saved = match axis {
                Axis::Row => self.row.replace(n.clone()),
                Axis::Column => self.col.replace(n.clone()),
            };
            let v = self.eval(body);
            match axis {
                Axis::Row => self.row = saved,
                Axis::Column => self.col = saved,
            }
            if v?.bool()? {
                holds.push(n);
            } else {
                fails.push(n);
            }
        }
        let what = if axis == Axis::Row { "row" } else { "column" };
        Ok(match quant {
            Quant::Every => {
                if !fails.is_empty() {
                    self.read
                        .push(format!("fails for {what}(s): {}", fails.join("; ")));
                }
                Val::Bool(fails.is_empty())
            }
            Quant::No => {
                if !holds.is_empty() {
                    self.read
                        .push(format!("holds for {what}(s): {}", holds.join("; ")));
                }
                Val::Bool(holds.is_empty())
            }
            Quant::Some => Val::Bool(!holds.is_empty()),
            Quant::Count => Val::Num(holds.len() as f64, None),
            Quant::Which => Val::Names(holds),
        })
    }

    /// The (name, value) pairs of a slice: its numeric cells.
    fn slice(
        &mut self,
        file: &Option<String>,
        axis: Axis,
        sel: &Sel,
        except: &[String],
    ) -> Result<Vec<(String, f64)>, String> {
        let file = self.file_of(file).to_string();
        // A column slice runs down the rows; a row slice across the columns.
        let fixed = self.name(sel, axis)?;
        let across = if axis == Axis::Column {
            Axis::Row
        } else {
            Axis::Column
        };
        let names = self.names(&file, across, except)?;
        let mut out = Vec::new();
        for n in names {
            let (row, col) = if axis == Axis::Column {
                (&n, &fixed)
            } else {
                (&fixed, &n)
            };
            let text = self.cell(&file, row, col)?;
            if let Some(x) = leading_number(&text) {
                out.push((n, x));
            }
        }
        if out.is_empty() {
            return Err(format!(
                "figures/{file}: no number in {} \"{fixed}\"",
                if axis == Axis::Column {
                    "column"
                } else {
                    "row"
                }
            ));
        }
        Ok(out)
    }

    fn func(&mut self, name: &str, args: &[Arg]) -> Result<Val, String> {
        let mut items: Vec<(Option<String>, f64)> = Vec::new();
        for a in args {
            match a {
                Arg::Expr(e) => items.push((None, self.eval(e)?.num()?)),
                Arg::Slice {
                    file,
                    axis,
                    sel,
                    except,
                } => {
                    for (n, x) in self.slice(file, *axis, sel, except)? {
                        items.push((Some(n), x));
                    }
                }
            }
        }
        if items.is_empty() {
            return Err(format!("{name}() of nothing"));
        }
        let pick = |better: fn(f64, f64) -> bool| {
            let mut best = 0;
            for (k, item) in items.iter().enumerate() {
                if better(item.1, items[best].1) {
                    best = k;
                }
            }
            best
        };
        match name {
            "abs" if items.len() == 1 => Ok(Val::Num(items[0].1.abs(), None)),
            "abs" => Err("abs() takes one number".into()),
            "max" => Ok(Val::Num(items[pick(|a, b| a > b)].1, None)),
            "min" => Ok(Val::Num(items[pick(|a, b| a < b)].1, None)),
            _ => {
                let k = if name == "argmax" {
                    pick(|a, b| a > b)
                } else {
                    pick(|a, b| a < b)
                };
                let x = items[k].1;
                let ties = items.iter().filter(|i| i.1 == x).count();
                if ties > 1 {
                    return Err(format!(
                        "{name}(): {ties} cells share the extreme value {x}"
                    ));
                }
                items[k]
                    .0
                    .clone()
                    .map(Val::Str)
                    .ok_or_else(|| format!("{name}() needs a slice (column \"C\" or row \"R\")"))
            }
        }
    }

    fn check_machines(&mut self) -> Result<(), String> {
        let mut timed = Vec::new();
        for f in &self.files {
            let source = self.tables.source(f)?;
            if let Some(m) = &source.machine {
                timed.push((f.clone(), m.clone()));
            }
        }
        let differ = timed.len() > 1
            && (timed.iter().any(|(_, m)| m.is_empty())
                || timed.iter().any(|(_, m)| *m != timed[0].1));
        if differ {
            let list: Vec<String> = timed
                .iter()
                .map(|(f, m)| {
                    if m.is_empty() {
                        format!("figures/{f} (no machine fingerprint)")
                    } else {
                        format!("figures/{f} (fingerprint {m})")
                    }
                })
                .collect();
            return Err(format!(
                "reads timing tables that were not measured on one identified machine, so may \
                 not be compared: {}; regenerate them in one run",
                list.join(", ")
            ));
        }
        Ok(())
    }

    fn quick(&mut self) -> bool {
        let files: Vec<String> = self.files.iter().cloned().collect();
        files
            .iter()
            .any(|f| self.tables.source(f).is_ok_and(|s| s.quick))
    }

    fn read_list(&self) -> String {
        self.read
            .iter()
            .take(16)
            .map(|r| format!("\n    {r}"))
            .collect()
    }
}

fn compare(a: &Val, op: &str, b: &Val) -> Result<bool, String> {
    match (a, b) {
        (Val::Num(x, _), Val::Num(y, _)) => Ok(match op {
            "<" => x < y,
            "<=" => x <= y,
            ">" => x > y,
            ">=" => x >= y,
            "==" => x == y,
            _ => x != y,
        }),
        (Val::Str(x), Val::Str(y)) if op == "==" => Ok(normal(x) == normal(y)),
        (Val::Str(x), Val::Str(y)) if op == "!=" => Ok(normal(x) != normal(y)),
        _ => Err(format!(
            "cannot compare {} {op} {}",
            a.describe(),
            b.describe()
        )),
    }
}

fn find_row(table: &Table, name: &str) -> Result<usize, String> {
    let parts: Vec<String> = name.split(" & ").map(normal).collect();
    let hits: Vec<usize> = table
        .rows
        .iter()
        .enumerate()
        .filter(|(_, cells)| {
            cells.first().is_some_and(|c| normal(c) == parts[0])
                && parts[1..]
                    .iter()
                    .all(|p| cells.iter().skip(1).any(|c| normal(c) == *p))
        })
        .map(|(i, _)| i)
        .collect();
    // Else the one row whose first cell starts with the name, as for columns.
    let hits = if hits.is_empty() && parts.len() == 1 {
        table
            .rows
            .iter()
            .enumerate()
            .filter(|(_, cells)| {
                cells
                    .first()
                    .is_some_and(|c| normal(c).starts_with(&parts[0]))
            })
            .map(|(i, _)| i)
            .collect()
    } else {
        hits
    };
    match hits.as_slice() {
        [one] => Ok(*one),
        [] => Err(format!(
            "no row \"{name}\" (rows: {})",
            table
                .rows
                .iter()
                .map(|r| r.first().map_or("", |c| c.as_str()))
                .collect::<Vec<_>>()
                .join("; ")
        )),
        _ => Err(format!(
            "{} rows match \"{name}\": add another cell of the row, \"{name} & …\"",
            hits.len()
        )),
    }
}

/// The shortest `"first & other & …"` name that [`find_row`] resolves to row `i` alone.
fn unique_row_name(table: &Table, i: usize) -> String {
    let cells = &table.rows[i];
    let mut name = cells.first().cloned().unwrap_or_default();
    for extra in cells.iter().skip(1) {
        if find_row(table, &name) == Ok(i) {
            break;
        }
        if !extra.is_empty() && !extra.contains(" & ") {
            name = format!("{name} & {extra}");
        }
    }
    name
}

fn find_column(table: &Table, name: &str) -> Result<usize, String> {
    if let Some(n) = name.strip_prefix('#').and_then(|n| n.parse::<usize>().ok()) {
        return if (1..=table.header.len()).contains(&n) {
            Ok(n - 1)
        } else {
            Err(format!(
                "no column #{n}: the table has {}",
                table.header.len()
            ))
        };
    }
    let want = normal(name);
    if let Some(i) = table.header.iter().position(|h| normal(h) == want) {
        return Ok(i);
    }
    let starts: Vec<usize> = table
        .header
        .iter()
        .enumerate()
        .filter(|(_, h)| normal(h).starts_with(&want))
        .map(|(i, _)| i)
        .collect();
    match starts.as_slice() {
        [one] => Ok(*one),
        [] => Err(format!(
            "no column \"{name}\" (columns: {})",
            table.header.join("; ")
        )),
        _ => Err(format!("{} columns start with \"{name}\"", starts.len())),
    }
}

/// The number that follows the last of `anchors`, each searched after the previous one.
fn text_number(text: &str, anchors: &[String]) -> Result<(f64, String), String> {
    let mut at = 0;
    for a in anchors {
        match text[at..].find(a.as_str()) {
            Some(i) => at += i + a.len(),
            None => return Err(format!("text \"{a}\" not found (after {anchors:?} so far)")),
        }
    }
    let rest = text[at..].trim_start();
    let m = NUMBER
        .find(rest)
        .ok_or_else(|| format!("no number after {anchors:?}"))?;
    let shown = m.as_str().to_string();
    let x = shown
        .replace(' ', "")
        .parse()
        .map_err(|_| format!("no number after {anchors:?}"))?;
    Ok((x, shown))
}

fn render(value: &Val, expr: &Expr, format: Option<&str>) -> Result<String, String> {
    let one_cell = matches!(expr, Expr::Cell { .. } | Expr::Text { .. });
    match (value, format) {
        (Val::Num(_, Some(text)), None) if one_cell => Ok(text.clone()),
        (Val::Num(x, _), Some(f)) => format_number(*x, f),
        (Val::Num(x, _), None) => {
            if x.fract() == 0.0 && x.abs() < 1e15 {
                Ok(format!("{x:.0}"))
            } else {
                format_number(*x, "s3")
            }
        }
        (Val::Str(s), None) => Ok(s.clone()),
        (Val::Names(names), None) => Ok(join_names(names)),
        (Val::Bool(_), _) => Err("a comparison is a claim: write {{#claim …}}".into()),
        (_, Some(f)) => Err(format!("`as {f}` formats numbers only")),
    }
}

fn join_names(names: &[String]) -> String {
    match names {
        [] => "none".into(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// `x` as `FORMAT` says (see the module documentation).
pub fn format_number(x: f64, format: &str) -> Result<String, String> {
    let bad = || format!("unknown format `{format}`: .N, sN, xN or int");
    if !x.is_finite() {
        return Ok(if x.is_nan() {
            "NaN".into()
        } else if x > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        });
    }
    let digits = |s: &str| s.parse::<usize>().map_err(|_| bad());
    let out = if format == "int" {
        format!("{x:.0}")
    } else if let Some(n) = format.strip_prefix('.') {
        format!("{x:.*}", digits(n)?)
    } else if let Some(n) = format.strip_prefix('s') {
        let n = digits(n)?.max(1);
        if x == 0.0 {
            "0".into()
        } else {
            let e = x.abs().log10().floor() as i32;
            let decimals = (n as i32 - 1 - e).max(0) as usize;
            let scale = 10f64.powi(e - n as i32 + 1);
            let rounded = (x / scale).round() * scale;
            format!("{rounded:.decimals$}")
        }
    } else if let Some(n) = format.strip_prefix('x') {
        let s = format!("{x:.*e}", digits(n)?);
        let (m, e) = s.split_once('e').ok_or_else(bad)?;
        let e: i32 = e.parse().map_err(|_| bad())?;
        if e == 0 {
            m.to_string()
        } else {
            format!("{m}\\times10^{{{e}}}")
        }
    } else {
        return Err(bad());
    };
    Ok(out)
}

// ---------------------------------------------------------------------------------------
// Chapters

/// A problem with a directive, or a claim that does not hold.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// 1-based line of the directive in the chapter.
    pub line: usize,
    pub message: String,
    /// A failed claim over a quick-mode table: a warning, not an error.
    pub warning: bool,
}

/// `text` with its directives replaced, and what went wrong.
pub fn expand(tables: &mut Tables, text: &str) -> (String, Vec<Finding>) {
    let mut out = String::with_capacity(text.len());
    let mut findings = Vec::new();
    let mut last = 0;
    for d in directives(text) {
        out.push_str(&text[last..d.start]);
        last = d.end;
        let line = text[..d.start].matches('\n').count() + 1;
        let shown = text[d.start..d.end]
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        match tables.evaluate(d.kind, &d.args) {
            Ok(ev) => {
                out.push_str(&ev.text);
                if let Some(read) = ev.failure {
                    let sentence = sentence_of(text, d.start, d.end);
                    let mut message = format!(
                        "claim does not hold: {shown}\n  in the sentence: {sentence}\n  read:{read}"
                    );
                    if ev.quick {
                        let _ = write!(
                            message,
                            "\n  (a table made in quick mode, which is not for quoting)"
                        );
                    }
                    findings.push(Finding {
                        line,
                        message,
                        warning: ev.quick,
                    });
                }
            }
            Err(e) => findings.push(Finding {
                line,
                message: format!("{shown}: {e}"),
                warning: false,
            }),
        }
    }
    out.push_str(&text[last..]);
    // A directive the pattern did not take (a `}` inside it ends it early) would be left in
    // the page as text.
    for (i, _) in text.match_indices("{{#") {
        let rest = &text[i + 3..];
        let escaped = i > 0 && text.as_bytes()[i - 1] == b'\\';
        let named = rest
            .split_whitespace()
            .nth(1)
            .is_some_and(|t| !t.contains(".md") && !t.contains(".txt"));
        if !escaped
            && !named
            && (rest.starts_with("value") || rest.starts_with("claim"))
            && !directives(text).iter().any(|d| d.start == i)
        {
            findings.push(Finding {
                line: text[..i].matches('\n').count() + 1,
                message:
                    "a {{#value}} or {{#claim}} that is not closed by `}}` before its first `}`: \
                          no `}` may appear inside one (name a row by the start of its first cell)"
                        .into(),
                warning: false,
            });
        }
    }
    (out, findings)
}

/// The sentence of `text` around the byte range `start..end`, its claims left out.
fn sentence_of(text: &str, start: usize, end: usize) -> String {
    let para_start = text[..start].rfind("\n\n").map_or(0, |i| i + 2);
    let para_end = text[end..].find("\n\n").map_or(text.len(), |i| end + i);
    let before = &text[para_start..start];
    let s = before
        .rfind(". ")
        .or_else(|| before.rfind(".\n"))
        .map_or(para_start, |i| para_start + i + 2);
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

/// MIGRATION (removed with this module): checks a mapping of old table directives to named
/// values, one `CHAPTER<TAB>OLD<TAB>NEW` per line: each old `{{#value}}` must show the same
/// text as its new one, each old `{{#claim}}` must hold exactly when its new one does.
/// Prints every mismatch; returns how many there were.
pub fn migrate_check(root: &Path, mapping: &Path) -> Result<usize> {
    let text = fs::read_to_string(mapping)?;
    let mut tables = Tables::new(&root.join("figures"));
    let values = crate::values::read(root).map_err(|e| anyhow::anyhow!(e))?;
    let mut bad = 0;
    for (i, line) in text.lines().enumerate() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let parts: Vec<&str> = line.split('\t').collect();
        if parts.len() != 3 {
            eprintln!(
                "{}:{}: expected CHAPTER<TAB>OLD<TAB>NEW",
                mapping.display(),
                i + 1
            );
            bad += 1;
            continue;
        }
        let (old, new) = (parts[1], parts[2]);
        let (old_out, old_f) = expand(&mut tables, old);
        let (new_out, new_f) = crate::values::expand(&values, new);
        let old_err: Vec<_> = old_f
            .iter()
            .filter(|f| !f.warning)
            .map(|f| f.message.clone())
            .collect();
        let new_err: Vec<_> = new_f
            .iter()
            .filter(|f| !f.warning)
            .map(|f| f.message.clone())
            .collect();
        let is_claim = old.contains("{{#claim");
        let same = if is_claim {
            old_err.is_empty() == new_err.is_empty()
        } else {
            old_out == new_out && new_err.is_empty()
        };
        if !same || !new_err.is_empty() {
            bad += 1;
            eprintln!(
                "{}:{} ({}):\n  old {old}\n   -> {old_out:?} {old_err:?}\n  new {new}\n   -> {new_out:?} {new_err:?}",
                mapping.display(),
                i + 1,
                parts[0]
            );
        }
    }
    Ok(bad)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A figures directory under the system temp dir, removed on drop.
    struct Dir(PathBuf);

    impl Dir {
        fn new(name: &str) -> Dir {
            let dir = std::env::temp_dir().join(format!(
                "raylemma-numbers-test-{}-{name}",
                std::process::id()
            ));
            let _ = fs::remove_dir_all(&dir);
            fs::create_dir_all(&dir).unwrap();
            Dir(dir)
        }
        fn write(&self, file: &str, text: &str) {
            fs::write(self.0.join(file), text).unwrap();
        }
        fn tables(&self) -> Tables {
            Tables::new(&self.0)
        }
    }

    impl Drop for Dir {
        fn drop(&mut self) {
            let _ = fs::remove_dir_all(&self.0);
        }
    }

    const SAMPLERS: &str = "| sampler | ns per sample | worst \\| \\|w\\| − 1 \\| |\n\
        |---|---:|---:|\n\
        | sphere, inverse CDF | 40.9 | 2.2e-16 |\n\
        | `cosine, seed Cartesian` | 40.7 | 0.79 |\n\
        | **cosine, Malley** | 45.4 | n/a (not a warp) |\n\
        \n*AMD EPYC, 2 cores, single thread (fingerprint 0a1b2c3d).*\n";

    fn value(t: &mut Tables, args: &str) -> Result<String, String> {
        t.evaluate(Kind::Value, args).map(|e| e.text)
    }

    fn claim(t: &mut Tables, args: &str) -> Result<bool, String> {
        t.evaluate(Kind::Claim, args).map(|e| e.failure.is_none())
    }

    #[test]
    fn a_value_is_the_cell_as_the_table_has_it() {
        let d = Dir::new("value");
        d.write("s.md", SAMPLERS);
        let mut t = d.tables();
        assert_eq!(
            value(&mut t, "s.md \"cosine, Malley\" \"ns per sample\"").unwrap(),
            "45.4"
        );
        // Backticks and bold marks are not part of the name; a header prefix names its column.
        assert_eq!(
            value(&mut t, "s.md \"cosine, seed Cartesian\" \"worst | |w|\"").unwrap(),
            "0.79"
        );
        assert_eq!(
            value(&mut t, "s.md \"cosine, Malley\" \"worst\"").unwrap(),
            "n/a (not a warp)"
        );
        assert_eq!(
            value(&mut t, "s.md \"cosine, Malley\" \"#3\"").unwrap(),
            "n/a (not a warp)"
        );
        assert!(value(&mut t, "s.md \"cosine, Malley\" \"#4\"").is_err());
        // Computed values are formatted.
        assert_eq!(
            value(&mut t, "s.md \"cosine, Malley\" \"ns per sample\" / \"cosine, seed Cartesian\" \"ns per sample\" as .2").unwrap(),
            "1.12"
        );
        assert_eq!(
            value(&mut t, "s.md \"sphere, inverse CDF\" \"worst\" as x1").unwrap(),
            "2.2\\times10^{-16}"
        );
        assert_eq!(
            value(&mut t, "s.md argmin(column \"ns per sample\")").unwrap(),
            "`cosine, seed Cartesian`"
        );
        assert_eq!(
            value(&mut t, "s.md max(column \"ns per sample\") as int").unwrap(),
            "45"
        );
        assert_eq!(
            value(&mut t, "s.md which row: @ \"ns per sample\" < 41").unwrap(),
            "sphere, inverse CDF and `cosine, seed Cartesian`"
        );
        assert_eq!(
            value(
                &mut t,
                "s.md count row except \"sphere, inverse CDF\": @ \"ns per sample\" > 0"
            )
            .unwrap(),
            "2"
        );
    }

    #[test]
    fn claims_hold_or_fail_with_the_cells_they_read() {
        let d = Dir::new("claim");
        d.write("s.md", SAMPLERS);
        let mut t = d.tables();
        assert!(
            claim(
                &mut t,
                "s.md \"cosine, Malley\" \"ns\" > \"cosine, seed Cartesian\" \"ns\""
            )
            .unwrap()
        );
        let ev = t
            .evaluate(
                Kind::Claim,
                "s.md \"cosine, Malley\" \"ns\" <= \"cosine, seed Cartesian\" \"ns\"",
            )
            .unwrap();
        let read = ev.failure.expect("fails");
        assert!(
            read.contains("\"cosine, Malley\" \"ns per sample\" = 45.4"),
            "{read}"
        );
        assert!(read.contains("= 40.7"), "{read}");
        // Chains, arithmetic, quantifiers.
        assert!(
            claim(
                &mut t,
                "s.md 40 < \"sphere, inverse CDF\" \"ns\" < 41 and not 1 > 2"
            )
            .unwrap()
        );
        assert!(claim(&mut t, "s.md every row: @ \"ns\" > 40").unwrap());
        assert!(
            !claim(
                &mut t,
                "s.md every row except \"cosine, Malley\": @ \"ns\" > 40.8"
            )
            .unwrap()
        );
        assert!(claim(&mut t, "s.md no row: @ \"ns\" > 50").unwrap());
        assert!(claim(&mut t, "s.md argmax(column \"ns\") == \"cosine, Malley\"").unwrap());
        // Rows whose first cells repeat are visited by a name that finds each alone.
        d.write(
            "dup.md",
            "| scene | n | x |\n|---|---|---|\n| a | 1 | 5 |\n| a | 2 | 7 |\n| b | 1 | 9 |\n",
        );
        assert!(claim(&mut t, "dup.md every row: @ \"x\" >= 5").unwrap());
        assert_eq!(
            value(&mut t, "dup.md which row: @ \"x\" > 6").unwrap(),
            "a & 2 and b"
        );
        assert_eq!(
            value(&mut t, "dup.md (count row: @ \"x\" > 6) + 1 as int").unwrap(),
            "3"
        );
    }

    #[test]
    fn mistakes_are_errors_that_name_what_is_missing() {
        let d = Dir::new("errors");
        d.write("s.md", SAMPLERS);
        d.write(
            "two.md",
            "| a | b |\n|---|---|\n| x | 1 |\n\n| a | b |\n|---|---|\n| x | 2 |\n",
        );
        let mut t = d.tables();
        let err = |t: &mut Tables, a: &str| t.evaluate(Kind::Value, a).unwrap_err();
        assert!(err(&mut t, "missing.md \"a\" \"b\"").contains("figures/missing.md"));
        let e = err(&mut t, "s.md \"disc\" \"ns\"");
        assert!(
            e.contains("no row \"disc\"") && e.contains("sphere, inverse CDF"),
            "{e}"
        );
        assert!(err(&mut t, "s.md \"cosine, Malley\" \"us\"").contains("no column \"us\""));
        assert!(err(&mut t, "two.md \"x\" \"b\"").contains("two.md#1 to two.md#2"));
        assert_eq!(value(&mut t, "two.md#2 \"x\" \"b\"").unwrap(), "2");
        assert!(err(&mut t, "s.md \"cosine, Malley\" \"worst\" + 1").contains("expected a number"));
        assert!(err(&mut t, "s.md @ \"ns\"").contains("no `every row`"));
        assert!(
            t.evaluate(Kind::Claim, "s.md \"cosine, Malley\" \"ns\"")
                .unwrap_err()
                .contains("comparison")
        );
        assert!(err(&mut t, "s.md 1 < 2").contains("claim"));
    }

    #[test]
    fn timing_tables_of_different_machines_are_not_compared() {
        let d = Dir::new("machines");
        d.write("s.md", SAMPLERS);
        d.write("u.md", &SAMPLERS.replace("0a1b2c3d", "99999999"));
        d.write("old.md", &SAMPLERS.replace(" (fingerprint 0a1b2c3d)", ""));
        d.write("same.md", SAMPLERS);
        d.write("untimed.md", "| a | b |\n|---|---|\n| x | 40 |\n");
        let mut t = d.tables();
        let across =
            |f: &str| format!("s.md \"cosine, Malley\" \"ns\" > {f} \"cosine, Malley\" \"ns\" - 1");
        assert!(claim(&mut t, &across("same.md")).unwrap());
        assert!(
            t.evaluate(Kind::Claim, &across("u.md"))
                .unwrap_err()
                .contains("fingerprint 99999999")
        );
        assert!(
            t.evaluate(Kind::Claim, &across("old.md"))
                .unwrap_err()
                .contains("no machine fingerprint")
        );
        assert!(
            claim(
                &mut t,
                "s.md \"cosine, Malley\" \"ns\" > untimed.md \"x\" \"b\""
            )
            .unwrap()
        );
    }

    #[test]
    fn text_numbers_and_quick_tables() {
        let d = Dir::new("text");
        d.write("v.txt", "FAIL\n  [FAIL] jacobian 1/2 cases; first failure: at u = (0.396, 0.7), |dT/du| = 2.487961e0\n");
        d.write(
            "q.md",
            "| a | b |\n|---|---|\n| x | 1 |\n\n*(quick mode: noisy)*\n",
        );
        let mut t = d.tables();
        assert_eq!(
            value(&mut t, "v.txt text(\"jacobian\", \"|dT/du| = \") as .3").unwrap(),
            "2.488"
        );
        assert_eq!(value(&mut t, "v.txt text(\"u = (\")").unwrap(), "0.396");
        let ev = t.evaluate(Kind::Claim, "q.md \"x\" \"b\" > 1").unwrap();
        assert!(ev.failure.is_some() && ev.quick);
    }

    #[test]
    fn chapters_are_expanded_and_failures_name_line_and_sentence() {
        let d = Dir::new("expand");
        d.write("s.md", SAMPLERS);
        let mut t = d.tables();
        let text = "# T\n\nIntro. Malley costs {{#value s.md \"cosine, Malley\" \"ns\"}} ns,\nless than \
                    the seed's form{{#claim s.md \"cosine, Malley\" \"ns\" < \"cosine, seed Cartesian\" \"ns\"}}. \
                    Next.\n\n\\{{#value s.md \"x\" \"y\"}} is how it is written.\n";
        let (out, findings) = expand(&mut t, text);
        assert!(
            out.contains("Malley costs 45.4 ns,\nless than the seed's form. Next."),
            "{out}"
        );
        assert!(
            out.contains("\\{{#value s.md \"x\" \"y\"}}"),
            "escaped directives are left alone"
        );
        assert_eq!(findings.len(), 1);
        assert_eq!(findings[0].line, 4);
        let (_, open) = expand(&mut t, "a {{#value s.md \"{x}\" \"ns\"}} b\n");
        assert!(
            open.iter().any(|f| f.message.contains("not closed")),
            "{open:?}"
        );
        assert_eq!(
            value(&mut t, "s.md \"cosine, seed\" \"ns\"").unwrap(),
            "40.7"
        );
        assert!(!findings[0].warning);
        let m = &findings[0].message;
        assert!(m.contains("in the sentence: Malley costs {{#value s.md \"cosine, Malley\" \"ns\"}} ns, less than the seed's form."), "{m}");
        assert!(m.contains("figures/s.md"), "{m}");
    }

    #[test]
    fn numbers_are_read_and_formatted() {
        assert_eq!(leading_number("42.4 %"), Some(42.4));
        assert_eq!(leading_number("1 (1.7 %)"), Some(1.0));
        assert_eq!(leading_number("10 000"), Some(10000.0));
        assert_eq!(leading_number("−3.5e-2"), Some(-0.035));
        assert_eq!(leading_number("**2.35**"), Some(2.35));
        assert_eq!(leading_number("inf"), Some(f64::INFINITY));
        assert_eq!(leading_number("n/a"), None);
        assert_eq!(format_number(0.000050250, "s3").unwrap(), "0.0000503");
        assert_eq!(format_number(46.97, "s2").unwrap(), "47");
        assert_eq!(format_number(1234.5, "s2").unwrap(), "1200");
        assert_eq!(format_number(-0.5, ".2").unwrap(), "-0.50");
        assert_eq!(format_number(6.034e14, "x1").unwrap(), "6.0\\times10^{14}");
        assert_eq!(format_number(3.0, "x1").unwrap(), "3.0");
        assert!(format_number(1.0, "q").is_err());
    }
}
