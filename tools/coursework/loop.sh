#!/usr/bin/env bash
# The student's loop, measured (chapter Coursework, "How long it takes"): a fresh hand-out
# built in a target folder of its own, so that nothing is reused from this repository's
# builds, then:
#   1. its first `cargo test` (every dependency, the library, the test binary, the run),
#      with how many lines it prints and its exit status;
#   2. disc_polar's body written (the solution), then `cargo run -- card disc_polar`;
#   3. the body touched again, then `cargo test --test book sampling::disc`;
#   4. touched again, `cargo test` (the whole warm run).
# Each step REPEATS times (default 1 for step 1, 3 for the others; the median is shown),
# on an idle machine. Writes figures/coursework_loop.md with the machine's fingerprint
# (as every timing table of the figure job names it) and its values into figures/values.json.
#
# Usage: tools/coursework/loop.sh [REPEATS]    (about 6 minutes on 2 cores)
set -euo pipefail
unset RUST_BACKTRACE # a student's shell does not set it
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
repeats="${1:-3}"
cd "$root"
cargo build --release --quiet -p raylemma -p raylemma-figures
bin="${CARGO_TARGET_DIR:-$root/target}/release"
work="$(mktemp -d "${TMPDIR:-/tmp}/raylemma-loop.XXXXXX")"
trap 'rm -rf "$work"' EXIT
"$bin/raylemma-figures" machine > "$work/machine"
"$bin/raylemma" exercises "$work/handout" 2>/dev/null
export CARGO_TARGET_DIR="$work/target"
cd "$work/handout"
times="$work/times"
step() { # step NAME COMMAND...: one timed run, appended to $times as NAME SECONDS STATUS LINES
    local name="$1"; shift
    local start end status=0
    start=$(date +%s.%N)
    "$@" > "$work/out" 2>&1 || status=$?
    end=$(date +%s.%N)
    echo "$name $(echo "$end - $start" | bc) $status $(wc -l < "$work/out")" >> "$times"
    echo "  $name: $(echo "$end - $start" | bc) s, exit status $status" >&2
}
echo "== the first cargo test of a fresh hand-out (own target folder)" >&2
step first cargo test
# Lines that are stubs' messages (none: a whole run keeps them quiet), and failing tests.
{ grep -c 'is not started' "$work/out" || true; grep -c -- ' FAILED$' "$work/out" || true; } > "$work/first_counts"
sed -i 's/crate::exercise::todo("disc_polar")/let r = u.x.sqrt();\n    let phi = consts::TAU * u.y;\n    V3::new(r * phi.cos(), r * phi.sin(), 0.0)/' src/sampling/disc.rs
for i in $(seq "$repeats"); do
    touch src/sampling/disc.rs
    step card cargo run --quiet -- card disc_polar
done
for i in $(seq "$repeats"); do
    touch src/sampling/disc.rs
    step chapter cargo test --test book sampling::disc
done
for i in $(seq "$repeats"); do
    touch src/sampling/disc.rs
    step whole cargo test
done
python3 "$here/loop_table.py" "$root" "$times" "$work/machine" $(cat "$work/first_counts")
