//! One run of a program: its questions written to its standard input, which is then
//! closed; its answers read from its standard output until it exits; its error output
//! passed through. A run that takes longer than the program's timeout is killed, with
//! every process it started. Chapter: *Checks from any language*.

use std::io::{Read, Write};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::mpsc;
use std::thread;
use std::time::{Duration, Instant};

use super::Program;
use crate::data::DataError;

/// The longest answer line read (bytes, without the newline): an answer is at most a few
/// numbers, which need fewer than 100 characters even with every digit of a double.
pub(crate) const MAX_ANSWER_LINE: usize = 1024;

/// Why an output was not read to its end.
struct Overflow {
    /// The line of the output where it went wrong (from 1).
    line: usize,
    problem: String,
}

/// Reads `out` to its end, but no further than its limits allow: at most
/// [`MAX_ANSWER_LINE`] bytes in a line and one line more than the `expected` answers (so
/// that a program writing without end, such as `yes`, or one endless line, costs at most
/// `expected` short lines of memory). An overflow stops the reading.
fn read_bounded(
    out: &mut impl Read,
    expected: usize,
) -> std::io::Result<Result<Vec<u8>, Overflow>> {
    let mut bytes = Vec::new();
    let mut chunk = [0u8; 1 << 16];
    let (mut lines, mut line_len) = (0usize, 0usize);
    loop {
        let n = out.read(&mut chunk)?;
        if n == 0 {
            return Ok(Ok(bytes));
        }
        for &b in &chunk[..n] {
            if b == b'\n' {
                lines += 1;
                line_len = 0;
                if lines > expected {
                    return Ok(Err(Overflow {
                        line: lines,
                        problem: format!(
                            "{expected} questions were asked, but the output goes on past {expected} answers"
                        ),
                    }));
                }
            } else {
                line_len += 1;
                if line_len > MAX_ANSWER_LINE {
                    return Ok(Err(Overflow {
                        line: lines + 1,
                        problem: format!(
                            "a line longer than {MAX_ANSWER_LINE} bytes (an answer is a few numbers)"
                        ),
                    }));
                }
            }
        }
        bytes.extend_from_slice(&chunk[..n]);
    }
}

impl Program {
    /// Runs the program once on `questions` (one line each, without the newline) and
    /// returns its answers, exactly one line per question (a `\r` before the newline is
    /// dropped). `run` numbers the run in messages.
    ///
    /// # Errors
    /// A [`DataError`] naming the program: it cannot be started, exits with a status other
    /// than 0 or by a signal, does not finish within its timeout, writes text that is not
    /// UTF-8, or writes fewer or more lines than questions (with the line).
    pub(crate) fn ask(&self, questions: &[String], run: usize) -> Result<Vec<String>, DataError> {
        let command = &self.command;
        let whole = |problem: String| DataError::new(command, 0, problem);
        let mut input = String::with_capacity(questions.iter().map(|q| q.len() + 1).sum());
        for q in questions {
            input.push_str(q);
            input.push('\n');
        }
        let mut child = spawn(command, self.dir.as_deref()).map_err(|e| {
            let place = self.dir.as_ref().map(|d| format!(" in {}", d.display()));
            whole(format!(
                "cannot start `sh -c`{}: {e}",
                place.unwrap_or_default()
            ))
        })?;
        let (Some(mut stdin), Some(mut stdout)) = (child.stdin.take(), child.stdout.take()) else {
            kill(&mut child);
            return Err(whole(
                "cannot connect to its standard input and output".into(),
            ));
        };
        // Writing and reading on their own threads: a program that answers as it reads
        // fills its output pipe long before it has read every question.
        thread::spawn(move || {
            // A program that stops reading early closes the pipe: its answers say the rest.
            let _ = stdin.write_all(input.as_bytes());
        });
        let (sender, receiver) = mpsc::channel();
        let expected = questions.len();
        thread::spawn(move || {
            let _ = sender.send(read_bounded(&mut stdout, expected));
        });
        let started = Instant::now();
        let deadline = started + self.timeout;
        let late = |what: &str| {
            whole(format!(
                "{what} after {:.1} s, in run {run} ({} questions): killed it (a slow program may \
                 need a longer --timeout)",
                self.timeout.as_secs_f64(),
                questions.len()
            ))
        };
        let bytes = match receiver.recv_timeout(self.timeout) {
            Ok(Ok(Ok(bytes))) => bytes,
            Ok(Ok(Err(Overflow { line, problem }))) => {
                kill(&mut child);
                return Err(DataError::new(
                    &self.output_name(),
                    line,
                    format!("{problem} (run {run}): stopped reading and killed it"),
                ));
            }
            Ok(Err(e)) => {
                kill(&mut child);
                return Err(whole(format!("cannot read its standard output: {e}")));
            }
            Err(_) => {
                kill(&mut child);
                return Err(late("did not finish answering"));
            }
        };
        let Some(status) = wait_until(&mut child, deadline) else {
            kill(&mut child);
            return Err(late("closed its output but did not exit"));
        };
        let text = String::from_utf8(bytes).map_err(|e| {
            let line = 1 + e.as_bytes()[..e.utf8_error().valid_up_to()]
                .iter()
                .filter(|&&b| b == b'\n')
                .count();
            DataError::new(&self.output_name(), line, "the answer is not UTF-8 text")
        })?;
        let answers = lines(&text);
        if !status.success() {
            let next = questions
                .get(answers.len())
                .map(|q| format!("; the first unanswered was `{q}`"))
                .unwrap_or_default();
            return Err(whole(format!(
                "{} after answering {} of the {} questions of run {run}{}{next}",
                describe(status),
                answers.len().min(questions.len()),
                questions.len(),
                hint(status),
            )));
        }
        if answers.len() < questions.len() {
            return Err(DataError::new(
                &self.output_name(),
                answers.len() + 1,
                format!(
                    "the output ends after {} answers to the {} questions of run {run}: no answer \
                     to `{}`",
                    answers.len(),
                    questions.len(),
                    questions[answers.len()]
                ),
            ));
        }
        if answers.len() > questions.len() {
            return Err(DataError::new(
                &self.output_name(),
                questions.len() + 1,
                format!(
                    "{} questions were asked in run {run}, but the output goes on: `{}`",
                    questions.len(),
                    answers[questions.len()]
                ),
            ));
        }
        Ok(answers.into_iter().map(String::from).collect())
    }

    /// The name of the program's answers in messages: `COMMAND (stdout)`.
    pub(crate) fn output_name(&self) -> String {
        format!("{} (stdout)", self.command)
    }
}

/// The lines of `text`, without their `\n` (or `\r\n`); a last line without a newline
/// counts.
fn lines(text: &str) -> Vec<&str> {
    if text.is_empty() {
        return Vec::new();
    }
    let body = text.strip_suffix('\n').unwrap_or(text);
    body.split('\n')
        .map(|l| l.strip_suffix('\r').unwrap_or(l))
        .collect()
}

/// `sh -c COMMAND` with piped standard input and output, its error output passed through,
/// in a process group of its own (so that a timeout kills whatever it started), in `dir`
/// if given.
fn spawn(command: &str, dir: Option<&std::path::Path>) -> std::io::Result<Child> {
    let mut sh = Command::new("sh");
    if let Some(dir) = dir {
        sh.current_dir(dir);
    }
    sh.arg("-c")
        .arg(command)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit());
    #[cfg(unix)]
    std::os::unix::process::CommandExt::process_group(&mut sh, 0);
    sh.spawn()
}

/// Why a program run by [`run_logged`] did not succeed: the one error type of a program
/// run whole (a renderer run by `raylemma conformance`), as opposed to a program that
/// answers the protocol's questions, whose bad answers are a [`DataError`] on their line.
#[derive(Debug)]
pub enum ProgramError {
    /// The log file cannot be created.
    Log {
        /// The log file.
        path: std::path::PathBuf,
        /// Why not.
        source: std::io::Error,
    },
    /// The shell cannot be started.
    Start(std::io::Error),
    /// The command ended with a status other than 0 (or was killed by a signal).
    Status {
        /// The command, as given.
        command: String,
        /// How it ended.
        status: ExitStatus,
    },
    /// The command did not finish in its time, and was killed with every process it
    /// started.
    Timeout {
        /// The command, as given.
        command: String,
        /// Its time.
        timeout: Duration,
    },
}

impl std::fmt::Display for ProgramError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ProgramError::Log { path, source } => write!(f, "{}: {source}", path.display()),
            ProgramError::Start(e) => write!(f, "cannot start `sh -c`: {e}"),
            ProgramError::Status { command, status } => {
                write!(f, "`{command}` {}{}", describe(*status), hint(*status))
            }
            ProgramError::Timeout { command, timeout } => write!(
                f,
                "`{command}` did not finish in {:.0} s: killed it",
                timeout.as_secs_f64()
            ),
        }
    }
}

impl std::error::Error for ProgramError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ProgramError::Log { source, .. } | ProgramError::Start(source) => Some(source),
            ProgramError::Status { .. } | ProgramError::Timeout { .. } => None,
        }
    }
}

/// Runs `command` by `sh -c` in a process group of its own, its standard output and error
/// into the file `log`, for at most `timeout` (then it is killed, with every process it
/// started): a renderer run by `raylemma conformance`.
///
/// # Errors
/// The command cannot be started, fails (its status), or does not finish in time
/// ([`ProgramError`]).
pub fn run_logged(
    command: &str,
    log: &std::path::Path,
    timeout: Duration,
) -> Result<(), ProgramError> {
    let cannot_log = |source| ProgramError::Log {
        path: log.to_path_buf(),
        source,
    };
    let out = std::fs::File::create(log).map_err(cannot_log)?;
    let err = out.try_clone().map_err(cannot_log)?;
    let mut sh = Command::new("sh");
    sh.arg("-c")
        .arg(command)
        .stdin(Stdio::null())
        .stdout(out)
        .stderr(err);
    #[cfg(unix)]
    std::os::unix::process::CommandExt::process_group(&mut sh, 0);
    let mut child = sh.spawn().map_err(ProgramError::Start)?;
    match wait_until(&mut child, Instant::now() + timeout) {
        Some(status) if status.success() => Ok(()),
        Some(status) => Err(ProgramError::Status {
            command: command.to_string(),
            status,
        }),
        None => {
            kill(&mut child);
            Err(ProgramError::Timeout {
                command: command.to_string(),
                timeout,
            })
        }
    }
}

/// Waits for `child` to exit until `deadline`; `None` if it is still running then.
fn wait_until(child: &mut Child, deadline: Instant) -> Option<ExitStatus> {
    loop {
        match child.try_wait() {
            Ok(Some(status)) => return Some(status),
            Ok(None) if Instant::now() < deadline => thread::sleep(Duration::from_millis(1)),
            _ => return None,
        }
    }
}

/// Kills `child` and its process group (the shell forks the command it runs: killing the
/// shell alone would leave the program running), then reaps it.
fn kill(child: &mut Child) {
    #[cfg(unix)]
    {
        // The standard library cannot signal a group; the POSIX `kill` utility can.
        let _ = Command::new("kill")
            .args(["-s", "KILL", "--", &format!("-{}", child.id())])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status();
    }
    let _ = child.kill();
    let _ = child.wait();
}

/// How a program ended, in words, with what the shell's own statuses mean: "exited with
/// status 127 (127: the shell found no such command)".
pub fn ended(status: ExitStatus) -> String {
    format!("{}{}", describe(status), hint(status))
}

/// "exited with status 3", "was killed by signal 9".
fn describe(status: ExitStatus) -> String {
    match status.code() {
        Some(code) => format!("exited with status {code}"),
        None => format!("ended abnormally ({status})"),
    }
}

/// What the shell's own statuses mean.
fn hint(status: ExitStatus) -> &'static str {
    match status.code() {
        Some(127) => " (127: the shell found no such command)",
        Some(126) => " (126: the shell could not execute it)",
        _ => "",
    }
}
