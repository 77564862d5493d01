//! The judge of a submission: the graded copy (the edition's code with the submission's
//! bodies, written under `--work`) built with its own target folder and its report card
//! run, read back as data ([`judge`]). The first submission builds the dependencies; the
//! next ones only the library. Chapter: *Coursework* (`chapters/coursework.md`).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::exercise::card::Report;

/// `raylemma-grade` in the cache folder (`$XDG_CACHE_HOME`, else `~/.cache`, else the
/// system's temporary folder): where the graded copy is kept unless `--work` says.
pub fn default_work() -> PathBuf {
    std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
        .unwrap_or_else(std::env::temp_dir)
        .join("raylemma-grade")
}

/// Builds the graded copy at `copy` (target folder `$CARGO_TARGET_DIR` or `work/target`:
/// its package, `raylemma-graded`, keeps its build apart from the other editions') and
/// runs its card;
/// the card as data, or why there is none (the compiler's errors, a time-out).
pub fn judge(copy: &Path, work: &Path, limit: Duration) -> Result<Report, String> {
    let json = work.join("card.json");
    let log = work.join("build.log");
    let _ = std::fs::remove_file(&json);
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let log_file =
        std::fs::File::create(&log).map_err(|e| format!("cannot write {}: {e}", log.display()))?;
    eprintln!(
        "raylemma: building the graded copy (the first submission builds the dependencies, minutes; later ones only the library) and running its card; cargo's output goes to {}",
        log.display()
    );
    let mut child = Command::new(&cargo)
        .args([
            "run",
            "--profile",
            "test",
            "--quiet",
            "--bin",
            "raylemma",
            "--",
            "card",
        ])
        .arg("--json")
        .arg(&json)
        .current_dir(copy)
        .env(
            "CARGO_TARGET_DIR",
            std::env::var_os("CARGO_TARGET_DIR").unwrap_or_else(|| work.join("target").into()),
        )
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(log_file)
        .spawn()
        .map_err(|e| format!("cannot start cargo: {e}"))?;
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if start.elapsed() >= limit => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!(
                    "the build and the card did not finish within {} s (--limit)",
                    limit.as_secs()
                ));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(200)),
            Err(e) => return Err(format!("cannot wait for cargo: {e}")),
        }
    };
    match std::fs::read_to_string(&json) {
        // The card ends with 0 or 1 after writing its JSON: a JSON file with any other end
        // (a signal, an abort, an exit of a status of the body's choosing) is not the card's.
        Ok(_) if !matches!(status.code(), Some(0 | 1)) => Err(format!(
            "the graded copy's card ended with {status} after its JSON was written, not as the card ends (0 or 1): the JSON is not trusted; the end of {}:\n{}",
            log.display(),
            tail(&std::fs::read_to_string(&log).unwrap_or_default(), 20)
        )),
        Ok(text) => serde_json::from_str(&text)
            .map_err(|e| format!("the card's JSON ({}) cannot be read: {e}", json.display())),
        Err(_) => {
            let said = std::fs::read_to_string(&log).unwrap_or_default();
            let errors: Vec<&str> = said
                .lines()
                .skip_while(|l| !l.starts_with("error"))
                .take(40)
                .collect();
            Err(if errors.is_empty() {
                format!(
                    "the graded copy's card did not finish ({status}); the end of {}:\n{}",
                    log.display(),
                    tail(&said, 20)
                )
            } else {
                errors.join("\n")
            })
        }
    }
}

/// The last `n` lines of `text`.
fn tail(text: &str, n: usize) -> String {
    let lines: Vec<&str> = text.lines().collect();
    lines[lines.len().saturating_sub(n)..].join("\n")
}
