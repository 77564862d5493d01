//! Fresnel reflectance and Snell refraction outside Rust, checked by the optics checkers
//! ([`crate::check::fresnel::reflectance`], [`crate::check::reflect::refraction`]) like any
//! other routine: a closure that looks up the program's or the table's answers. Chapter:
//! *Checks from any language*.

use std::path::{Path, PathBuf};

use glam::DVec3;

use super::Program;
use super::memo::{Ask, Memo, Source, rounds, unanswered};
use super::text::{as_strs, csv_rows, numbers};
use crate::check::{Options, Verdict, fresnel, reflect};
use crate::data::DataError;
use crate::optics::reflect::Refraction;

/// A function outside Rust: a program that answers questions, or a table of answers.
#[derive(Clone, Debug)]
pub enum Function {
    /// A program, asked in runs.
    Program(Program),
    /// A CSV file: one row a question, its numbers followed by the answer.
    Table(PathBuf),
}

/// `fresnel cos_i n1 n2` -> `R`.
fn fresnel_memo() -> Memo<3, f64> {
    Memo::new("fresnel", Box::new(|f| numbers::<1>(f, "`R`").map(|[r]| r)))
}

/// The columns of a Fresnel question, for tables.
const FRESNEL_COLUMNS: &str = "cos_i,n1,n2";

/// `refract wi_x wi_y wi_z n_x n_y n_z n1 n2` -> `t_x t_y t_z` or `tir`.
fn refraction_memo() -> Memo<8, Refraction> {
    Memo::new(
        "refract",
        Box::new(|f| {
            if let [word] = f
                && word.eq_ignore_ascii_case("tir")
            {
                return Ok(Refraction::TotalInternalReflection);
            }
            numbers::<3>(f, "`t_x t_y t_z` (or the word `tir`)")
                .map(|t| Refraction::Transmitted(DVec3::from(t)))
        }),
    )
}

/// The columns of a refraction question, for tables.
const REFRACTION_COLUMNS: &str = "wi_x,wi_y,wi_z,n_x,n_y,n_z,n1,n2";

/// Reads a table into `memo`: each row is a question's `N` numbers and its answer.
fn load<const N: usize, A: Copy + PartialEq>(
    path: &Path,
    memo: &Memo<N, A>,
    columns: &str,
) -> Result<String, DataError> {
    let (name, rows) = csv_rows(path)?;
    for (line, row) in &rows {
        let error = |why: String| DataError::new(&name, *line, why);
        let fields = as_strs(row);
        if fields.len() <= N {
            return Err(error(format!(
                "the row should be a question `{columns}` followed by its answer, but has {} \
                 field{}",
                fields.len(),
                if fields.len() == 1 { "" } else { "s" }
            )));
        }
        let question =
            numbers::<N>(&fields[..N], "").map_err(|why| error(format!("the row {why}")))?;
        let answer = memo
            .read(&fields[N..])
            .map_err(|why| error(format!("the row's answer {why}")))?;
        memo.insert(question, answer).map_err(|_| {
            error("the row answers the question of an earlier row differently".into())
        })?;
    }
    Ok(name)
}

/// Runs `check` on the answers of `function`, read into `memo`.
fn run<const N: usize, A: Copy + PartialEq + Send>(
    function: &Function,
    memo: &Memo<N, A>,
    columns: &str,
    check: impl FnMut() -> Verdict,
) -> Result<Verdict, DataError> {
    match function {
        Function::Program(program) => rounds(&Source::Program(program), &[memo], check),
        Function::Table(path) => {
            let name = load(path, memo, columns)?;
            rounds(&Source::Table(&name), &[memo], check)
        }
    }
}

// ANCHOR: optics
/// Checks a reflectance routine outside Rust with [`fresnel::reflectance`] (the same sweep,
/// claims and verdict as for a Rust routine): a program asked `fresnel cos_i n1 n2`
/// questions, or a table of rows `cos_i,n1,n2,R` that must answer every question of the
/// sweep ([`fresnel_questions`] lists them).
///
/// # Errors
/// A [`DataError`] for bad input: an answer or a row that is not a number (with its
/// program or file and line), a question the table has no row for, a program that cannot
/// be run, ends early, fails or hangs.
pub fn fresnel(function: &Function, options: &Options) -> Result<Verdict, DataError> {
    let memo = fresnel_memo();
    let f = |cos_i, n1, n2| memo.get([cos_i, n1, n2], 0.5);
    run(function, &memo, FRESNEL_COLUMNS, || {
        fresnel::reflectance(&f, options)
    })
}

/// Checks a refraction routine outside Rust with [`reflect::refraction`]: a program asked
/// `refract wi_x wi_y wi_z n_x n_y n_z n1 n2` questions, or a table of rows of those eight
/// numbers followed by `t_x,t_y,t_z` or `tir` ([`refraction_questions`] lists the rows it
/// still needs: the round trip's questions depend on the answers, so a table is written
/// in two rounds).
///
/// # Errors
/// As [`fresnel()`].
pub fn refraction(function: &Function, options: &Options) -> Result<Verdict, DataError> {
    let memo = refraction_memo();
    let f = |w: DVec3, n: DVec3, n1, n2| {
        let question = [w.x, w.y, w.z, n.x, n.y, n.z, n1, n2];
        memo.get(question, Refraction::TotalInternalReflection)
    };
    run(function, &memo, REFRACTION_COLUMNS, || {
        reflect::refraction(&f, options)
    })
}
// ANCHOR_END: optics

/// The questions of the Fresnel checker that `table` (if any) does not answer yet: a CSV
/// text, the header `cos_i,n1,n2` then one question a row, for a table to be written
/// (each row followed by its `R`).
///
/// # Errors
/// A [`DataError`] for a malformed table.
pub fn fresnel_questions(table: Option<&Path>, options: &Options) -> Result<String, DataError> {
    let memo = fresnel_memo();
    if let Some(path) = table {
        load(path, &memo, FRESNEL_COLUMNS)?;
    }
    let f = |cos_i, n1, n2| memo.get([cos_i, n1, n2], 0.5);
    let waiting = unanswered(&[&memo], || {
        fresnel::reflectance(&f, options);
    });
    Ok(csv(FRESNEL_COLUMNS, &waiting))
}

/// The questions of the refraction checker that `table` (if any) does not answer yet, as
/// [`fresnel_questions`] (header `wi_x,wi_y,wi_z,n_x,n_y,n_z,n1,n2`; each row to be
/// followed by `t_x,t_y,t_z` or `tir`). Run it again on the table with those answers for
/// the round trip's questions.
///
/// # Errors
/// A [`DataError`] for a malformed table.
pub fn refraction_questions(table: Option<&Path>, options: &Options) -> Result<String, DataError> {
    let memo = refraction_memo();
    if let Some(path) = table {
        load(path, &memo, REFRACTION_COLUMNS)?;
    }
    let f = |w: DVec3, n: DVec3, n1, n2| {
        let question = [w.x, w.y, w.z, n.x, n.y, n.z, n1, n2];
        memo.get(question, Refraction::TotalInternalReflection)
    };
    let waiting = unanswered(&[&memo as &dyn Ask], || {
        reflect::refraction(&f, options);
    });
    Ok(csv(REFRACTION_COLUMNS, &waiting))
}

/// Protocol lines (`verb x1 ... xN`) as CSV rows `x1,...,xN` under `header`.
fn csv(header: &str, questions: &[String]) -> String {
    let mut out = format!("{header}\n");
    for q in questions {
        let numbers: Vec<&str> = q.split(' ').skip(1).collect();
        out.push_str(&numbers.join(","));
        out.push('\n');
    }
    out
}
