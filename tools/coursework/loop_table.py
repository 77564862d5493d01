"""Writes figures/coursework_loop.md and its values from the times tools/coursework/loop.sh
measured (ROOT TIMES MACHINE NOT_STARTED_LINES FAILING_TESTS: of the first run, the lines that
are stubs' messages and the tests that failed)."""
import statistics
import sys

sys.path.insert(0, f"{sys.argv[1]}/tools/values")
from values import Record  # noqa: E402

root, times, machine = sys.argv[1], sys.argv[2], open(sys.argv[3]).read().strip()
not_started, failing = int(sys.argv[4]), int(sys.argv[5])
rows = {}
for line in open(times):
    name, seconds, status, lines = line.split()
    rows.setdefault(name, []).append((float(seconds), int(status), int(lines)))

what = {
    "first": "the hand-out's first `cargo test` (every dependency, the library, the test binary, the run)",
    "card": "after an edit of `disc_polar`: `cargo run -- card disc_polar`",
    "chapter": "after an edit: `cargo test --test book sampling::disc`",
    "whole": "after an edit: `cargo test` (every test, then the card)",
}
r = Record("coursework_loop.md")
table = [
    f"Measured on {machine} by `tools/coursework/loop.sh` (idle; its own target folder; median of the runs).",
    "",
    "| step | runs | seconds (median) | exit status | lines printed |",
    "|---|---:|---:|---:|---:|",
]
for name in ["first", "card", "chapter", "whole"]:
    runs = rows[name]
    median = statistics.median(s for s, _, _ in runs)
    status = runs[-1][1]
    lines = runs[-1][2]
    shown = r.number(f"{name}_seconds", median, ".1" if median < 100 else "int")
    r.number(f"{name}_lines", lines, "int")
    table.append(f"| {what[name]} | {len(runs)} | {shown} | {status} | {lines} |")
r.number("first_not_started_lines", not_started, "int")
r.number("first_failing_tests", failing, "int")
r.number("first_minutes", statistics.median(s for s, _, _ in rows["first"]) / 60, ".1")
text = "\n".join(table) + "\n"
open(f"{root}/figures/coursework_loop.md", "w").write(text)
r.write(root, text)
print(text)
