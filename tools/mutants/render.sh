#!/usr/bin/env bash
# Mutation testing of the path tracer (chapter "Tests of the tests", the renderer's row):
# cargo-mutants' mutants of the renderer's files, a systematic sample of 1 in N of each
# file (`--shard K/N --sharding round-robin`: the mutants K, K + N, K + 2N, ... of the
# file in source order), each tested with the renderer's tests (`cargo test --test book
# renderer::`). Writes figures/mutants_render.md: per file, mutants tested, caught, missed,
# timeouts (counted as caught), unviable, the caught share with its 95 % Wilson interval,
# and every surviving mutant.
#
#   tools/mutants/render.sh [N [SHARD...]]     (default N = 8, SHARD = 0)
#
# Files: $RENDER_FILES (default: integrator, tracer, camera, pixel, driver); the table is
# written to $TABLE (default figures/mutants_render.md). The pixel's footprint, every mutant:
#   RENDER_FILES="src/render/pixel.rs src/render/camera.rs src/render/driver.rs" \
#   TABLE=figures/mutants_footprint.md OUT=/tmp/raylemma-mutants-footprint tools/mutants/render.sh 1
# N = 1 is
# every mutant: some 300 for the default files, hours on 2 cores. Mutants are made in place
# (--in-place) so that builds are incremental: run it in a clean checkout of its own
# (git worktree add), never in one you are editing. Results accumulate in $OUT (default
# ${TMPDIR:-/tmp}/raylemma-mutants-render-rr; the table reads every run in it, so do not
# point it at a folder of the older slice runs); a file done before is not redone.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
n="${1:-8}"
shift || true
shards=("${@:-0}")
out="${OUT:-${TMPDIR:-/tmp}/raylemma-mutants-render-rr}"
read -r -a files <<< "${RENDER_FILES:-src/render/integrator.rs src/render/tracer.rs src/render/camera.rs src/render/pixel.rs src/render/driver.rs}"
cd "$root"
source "$here/common.sh"
for shard in "${shards[@]}"; do
  for file in "${files[@]}"; do
    # ".rr": round-robin shards; results of the older slice shards are not reused.
    mutate "$(echo "$file" | tr '/' '_').rr.s$shard-of-$n" "renderer::" -f "$file" --shard "$shard/$n" --sharding round-robin
  done
done
export TABLE="${TABLE:-figures/mutants_render.md}"
table="$root/$TABLE"
files_env="${RENDER_FILES:-}"
python3 - "$here" "$out" "$n" "${shards[*]}" "$files_env" > "$table.tmp" <<'PY'
import os
import sys
from collections import defaultdict
sys.path.insert(0, sys.argv[1])
from summary import outcomes, wilson  # the derivations' table's own reading and interval
out, n, shards = sys.argv[2], int(sys.argv[3]), sys.argv[4].split()
counts = defaultdict(lambda: defaultdict(int))
missed = []
for _, file, summary, name in outcomes(out):
    counts[file][summary] += 1
    if summary == "MissedMutant":
        missed.append(name)
print("| file | tested | caught | missed | timeouts | unviable | caught share | 95 % interval |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
tot = defaultdict(int)
for s in counts.values():
    for k, v in s.items():
        tot[k] += v
for f, s in list(sorted(counts.items())) + [("**all**", tot)]:
    c, m, t, u = s["CaughtMutant"], s["MissedMutant"], s["Timeout"], s["Unviable"]
    v = c + m + t
    lo, hi = wilson(c + t, v)
    name = f if f.startswith("**") else f"`{f}`"
    print(f"| {name} | {v} | {c} | {m} | {t} | {u} | {100 * (c + t) / max(v, 1):.0f} % | {100 * lo:.0f}–{100 * hi:.0f} % |")
print()
sample = ("every mutant of each file" if n == 1 and shards == ["0"] else
          f"{len(shards)} of every {n} mutants of each file (`--shard K/{n} --sharding round-robin`, "
          f"K in {', '.join(shards)}: the mutants K, K + {n}, K + {2 * n}, … of each file in source order)")
files = sys.argv[5] or "the path tracer's files"
table = os.environ.get("TABLE", "")
again = (f"`RENDER_FILES=\"{sys.argv[5]}\" TABLE={table} " if sys.argv[5] else "`") + \
    f"tools/mutants/render.sh {n} {' '.join(shards)}`"
print(f"*cargo-mutants on {files}: {sample}, each tested with `cargo test --test book renderer::`; "
      f"a timeout counts as caught. Regenerate with {again} in a clean checkout.*")
if missed:
    print()
    print("Surviving mutants:")
    print()
    for m in missed:
        print(f"- `{m}`")
PY
mv "$table.tmp" "$table"
cat "$table"
