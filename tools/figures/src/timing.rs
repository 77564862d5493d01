//! A small timing harness for the speed tables the book prints.
//!
//! `cargo bench -p raylemma-bench` (criterion, `benches/`) gives the careful measurement; this harness
//! gives the same quantity quickly so that `cargo run --release` can regenerate the book's
//! tables on the reader's own machine. It reports the median over repeated batches,
//! which is robust to the occasional interrupted batch.

use std::hint::black_box;
use std::time::Instant;

use raylemma::output::fnv1a;

/// Median nanoseconds per item of `batch`, which processes `items` items per call.
/// Runs a warm-up call, then `reps` timed calls.
pub fn median_ns_per_item(items: usize, reps: usize, mut batch: impl FnMut() -> u64) -> f64 {
    black_box(batch());
    let mut times: Vec<f64> = (0..reps.max(1))
        .map(|_| {
            let start = Instant::now();
            black_box(batch());
            start.elapsed().as_secs_f64() * 1e9 / items as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// A one-line description of the machine, for the caption of a speed table timed on one
/// thread: [`machine_name`] followed by "single thread".
pub fn machine() -> String {
    format!("{}, single thread", machine_name())
}

/// The machine, precisely enough to tell apart two CPUs that report the same (often masked)
/// model string: the model string, its family, model and stepping, the cores and hardware
/// threads, the cache sizes, the clock, and a short fingerprint of all of them and of the
/// CPU's feature flags, e.g. `AMD EPYC (family 26, model 2, stepping 1), 2 cores, 2 threads,
/// L1d 48 KiB, L1i 32 KiB, L2 1 MiB, L3 32 MiB, 2596 MHz, fingerprint 1a2b3c4d`.
///
/// Read from `/proc/cpuinfo` and `/sys/devices/system/cpu/cpu0/cache/`; what a system does
/// not provide is left out (on a system with neither: the architecture and thread count).
/// The book compares numbers of two timing tables only when their fingerprints are equal
/// (chapter *Speed against error*).
pub fn machine_name() -> String {
    let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let caches = read_caches(std::path::Path::new("/sys/devices/system/cpu/cpu0/cache"));
    let max_khz = std::fs::read_to_string("/sys/devices/system/cpu/cpu0/cpufreq/cpuinfo_max_freq")
        .ok()
        .and_then(|s| s.trim().parse::<f64>().ok());
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    describe(&cpuinfo, &caches, max_khz, threads)
}

/// One cache of a CPU: its level, its kind (`d`, `i` or nothing for unified) and size in
/// KiB.
#[derive(Clone, Debug, PartialEq)]
pub struct Cache {
    pub level: u32,
    pub kind: &'static str,
    pub kib: u64,
}

/// The caches of one CPU from its `cache/index*` folders, by level and kind.
fn read_caches(dir: &std::path::Path) -> Vec<Cache> {
    let read = |p: std::path::PathBuf| {
        std::fs::read_to_string(p)
            .ok()
            .map(|s| s.trim().to_string())
    };
    let mut caches: Vec<Cache> = std::fs::read_dir(dir)
        .map(|d| {
            d.filter_map(Result::ok)
                .map(|e| e.path())
                .collect::<Vec<_>>()
        })
        .unwrap_or_default()
        .into_iter()
        .filter(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with("index"))
        })
        .filter_map(|p| {
            let level = read(p.join("level"))?.parse().ok()?;
            let kind = match read(p.join("type"))?.as_str() {
                "Data" => "d",
                "Instruction" => "i",
                _ => "",
            };
            let size = read(p.join("size"))?;
            let kib = parse_size_kib(&size)?;
            Some(Cache { level, kind, kib })
        })
        .collect();
    caches.sort_by(|a, b| (a.level, a.kind).cmp(&(b.level, b.kind)));
    caches
}

/// `48K`, `1024K`, `32M` (sysfs) or `1024 KB` (cpuinfo) in KiB.
fn parse_size_kib(s: &str) -> Option<u64> {
    let s = s.trim();
    let digits: String = s.chars().take_while(char::is_ascii_digit).collect();
    let n: u64 = digits.parse().ok()?;
    match s[digits.len()..].trim().chars().next() {
        Some('K' | 'k') | None => Some(n),
        Some('M') => Some(n * 1024),
        Some('G') => Some(n * 1024 * 1024),
        _ => None,
    }
}

fn show_kib(kib: u64) -> String {
    if kib >= 1024 && kib.is_multiple_of(1024) {
        format!("{} MiB", kib / 1024)
    } else {
        format!("{kib} KiB")
    }
}

/// The description of [`machine_name`] from the text of `/proc/cpuinfo`, the caches of
/// the first CPU, its maximum clock from cpufreq in kHz (if any) and the number of hardware
/// threads available.
pub fn describe(cpuinfo: &str, caches: &[Cache], max_khz: Option<f64>, threads: usize) -> String {
    // The first processor's block.
    let field = |name: &str| {
        cpuinfo
            .lines()
            .take_while(|l| !l.trim().is_empty())
            .find(|l| l.split(':').next().is_some_and(|k| k.trim() == name))
            .and_then(|l| l.split_once(':'))
            .map(|(_, v)| v.trim().to_string())
            .filter(|v| !v.is_empty())
    };
    let model_name = field("model name")
        .or_else(|| field("Hardware"))
        .or_else(|| field("CPU part").map(|p| format!("CPU part {p}")))
        .unwrap_or_else(|| std::env::consts::ARCH.to_string());
    let ids: Vec<String> = [
        ("family", "cpu family"),
        ("model", "model"),
        ("stepping", "stepping"),
    ]
    .iter()
    .filter_map(|(label, key)| field(key).map(|v| format!("{label} {v}")))
    .collect();
    let mut parts = vec![if ids.is_empty() {
        model_name.clone()
    } else {
        format!("{model_name} ({})", ids.join(", "))
    }];
    // Cores: distinct (physical id, core id) pairs, else "cpu cores" of one package.
    let mut cores = std::collections::BTreeSet::new();
    let (mut package, mut core) = (None, None);
    for line in cpuinfo.lines().chain(std::iter::once("")) {
        let (k, v) = line
            .split_once(':')
            .map_or((line.trim(), ""), |(k, v)| (k.trim(), v.trim()));
        match k {
            "physical id" => package = Some(v.to_string()),
            "core id" => core = Some(v.to_string()),
            "" => {
                if let Some(c) = core.take() {
                    cores.insert((package.take(), c));
                }
                package = None;
            }
            _ => {}
        }
    }
    let n_cores = if cores.is_empty() {
        field("cpu cores").and_then(|c| c.parse::<usize>().ok())
    } else {
        Some(cores.len())
    };
    if let Some(c) = n_cores {
        parts.push(format!("{c} {}", if c == 1 { "core" } else { "cores" }));
    }
    parts.push(format!(
        "{threads} {}",
        if threads == 1 { "thread" } else { "threads" }
    ));
    if caches.is_empty()
        && let Some(kib) = field("cache size").as_deref().and_then(parse_size_kib)
    {
        parts.push(format!("cache {}", show_kib(kib)));
    }
    for c in caches {
        parts.push(format!("L{}{} {}", c.level, c.kind, show_kib(c.kib)));
    }
    // The clock: cpufreq's maximum if the system has it (steady), else cpuinfo's current
    // clock rounded to 10 MHz (steady on the virtual machines that lack cpufreq).
    let mhz = max_khz
        .map(|k| k / 1000.0)
        .or_else(|| field("cpu MHz").and_then(|m| m.parse::<f64>().ok()))
        .map(|m| (m / 10.0).round() * 10.0);
    if let Some(m) = mhz {
        parts.push(format!("{m:.0} MHz"));
    }
    // The fingerprint covers what is printed and the feature flags, which are not.
    let flags = field("flags")
        .or_else(|| field("Features"))
        .unwrap_or_default();
    let mut flags: Vec<&str> = flags.split_whitespace().collect();
    flags.sort_unstable();
    let printed = parts.join(", ");
    let print = fnv1a(format!("{printed}\n{}", flags.join(" ")).as_bytes());
    format!(
        "{printed}, fingerprint {:08x}",
        (print >> 32) as u32 ^ print as u32
    )
}

/// Median nanoseconds per call of `f` over `inputs` (see [`median_ns_per_item`]); the
/// results are summed so that the optimiser cannot drop the calls.
pub fn median_ns_per_input(inputs: &[f64], reps: usize, f: impl Fn(f64) -> f64) -> f64 {
    median_ns_per_item(inputs.len(), reps, || {
        let mut acc = 0.0;
        for &u in inputs {
            acc += f(black_box(u));
        }
        acc.to_bits()
    })
}

/// The caption's warning for tables timed in quick mode.
pub fn quick_note(quick: bool) -> &'static str {
    if quick { " (quick mode: noisy)" } else { "" }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CPUINFO: &str = "processor\t: 0\nvendor_id\t: AuthenticAMD\ncpu family\t: 26\nmodel\t\t: 2\n\
        model name\t: AMD EPYC\nstepping\t: 1\ncpu MHz\t\t: 2596.096\ncache size\t: 1024 KB\n\
        physical id\t: 0\nsiblings\t: 2\ncore id\t\t: 0\ncpu cores\t: 2\nflags\t\t: fpu sse2 avx2\n\n\
        processor\t: 1\ncpu family\t: 26\nmodel name\t: AMD EPYC\nphysical id\t: 0\ncore id\t\t: 1\n\
        flags\t\t: fpu sse2 avx2\n\n";

    fn caches() -> Vec<Cache> {
        vec![
            Cache {
                level: 1,
                kind: "d",
                kib: 48,
            },
            Cache {
                level: 1,
                kind: "i",
                kib: 32,
            },
            Cache {
                level: 2,
                kind: "",
                kib: 1024,
            },
            Cache {
                level: 3,
                kind: "",
                kib: 32768,
            },
        ]
    }

    #[test]
    fn the_machine_is_named_with_its_caches_clock_and_fingerprint() {
        let d = describe(CPUINFO, &caches(), None, 2);
        let (text, print) = d.rsplit_once(", fingerprint ").unwrap();
        assert_eq!(
            text,
            "AMD EPYC (family 26, model 2, stepping 1), 2 cores, 2 threads, L1d 48 KiB, L1i 32 KiB, \
             L2 1 MiB, L3 32 MiB, 2600 MHz"
        );
        assert!(
            print.len() == 8 && print.chars().all(|c| c.is_ascii_hexdigit()),
            "{print}"
        );
        assert_eq!(describe(CPUINFO, &caches(), None, 2), d, "deterministic");
    }

    #[test]
    fn cpus_with_the_same_model_string_get_different_fingerprints() {
        let base = describe(CPUINFO, &caches(), None, 2);
        let print = |s: &str| s.rsplit_once("fingerprint ").unwrap().1.to_string();
        let other_stepping = describe(
            &CPUINFO.replace("stepping\t: 1", "stepping\t: 0"),
            &caches(),
            None,
            2,
        );
        let other_flags = describe(&CPUINFO.replace("avx2", "avx512f"), &caches(), None, 2);
        let mut smaller = caches();
        smaller[3].kib = 16384;
        let other_cache = describe(CPUINFO, &smaller, None, 2);
        let other_clock = describe(CPUINFO, &caches(), Some(3_700_000.0), 2);
        for other in [other_stepping, other_flags, other_cache, other_clock] {
            assert_ne!(print(&base), print(&other), "{other}");
        }
        // The clock's last digits do not split one machine in two.
        let jitter = describe(&CPUINFO.replace("2596.096", "2597.350"), &caches(), None, 2);
        assert_eq!(base, jitter);
    }

    #[test]
    fn a_system_without_cpuinfo_still_gets_a_name() {
        let d = describe("", &[], None, 4);
        assert!(
            d.starts_with(&format!(
                "{}, 4 threads, fingerprint ",
                std::env::consts::ARCH
            )),
            "{d}"
        );
        assert_eq!(parse_size_kib("32M"), Some(32768));
        assert_eq!(parse_size_kib("1024 KB"), Some(1024));
    }
}
