#!/usr/bin/env bash
# The speed chapter's Mitsuba row, in one run on one machine:
#   1. raylemma renders scenes/cornell.toml at SPP samples per pixel;
#   2. Mitsuba 3 (scalar_spectral) renders the same scene at SPP, as `raylemma export`
#      writes it (render.py: 16 passes, each a plain EXR);
#   3. `raylemma compare` tests the passes against raylemma's render within their noise;
#   4. the table figures/mitsuba_cornell.md (time, pixel samples per second, the
#      throughput ratio, peak memory, the compare report), the difference image
#      figures/mitsuba_cornell_diff.png and Mitsuba's picture figures/mitsuba_cornell.png.
#
#   tools/mitsuba/compare.sh [SPP]      (default 1024; needs the network for PyPI once)
#
# Python and Mitsuba are used here only; `cargo test` never needs them. The renderer
# chapter's comparison of every scene against its reference is compare_all.sh.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
spp="${1:-1024}"
work="${TMPDIR:-/tmp}/raylemma-mitsuba-compare"
rm -rf "$work"
mkdir -p "$work/raylemma" "$work/mitsuba"
cd "$root"

echo "== building raylemma (release)"
cargo build --release --quiet -p raylemma
bin="${CARGO_TARGET_DIR:-$root/target}/release/raylemma"
bash "$here/setup.sh" --pip-only
py="${RAYLEMMA_MITSUBA_VENV:-/root/.cache/raylemma-mitsuba-venv}/bin/python"
"$bin" export scenes/cornell.toml --to mitsuba --out "$work/cornell.xml"
"$bin" export scenes/cornell.toml --to json --out "$work/cornell.json"

echo "== raylemma: cornell at $spp spp"
/usr/bin/time -f "%M" -o "$work/raylemma.rss" \
    "$bin" render scenes/cornell.toml --spp "$spp" --seed 12345 --out "$work/raylemma"

echo "== Mitsuba 3: cornell at $spp spp"
/usr/bin/time -f "%M" -o "$work/mitsuba.rss" \
    "$py" "$here/render.py" "$work/cornell.xml" --json "$work/cornell.json" --spp "$spp" --passes 16 \
    --out "$work/mitsuba/cornell" --png "$work/mitsuba/cornell.png"

echo "== raylemma compare"
set +e
"$bin" compare "$work/raylemma/cornell.exr" "$work/mitsuba/cornell"-[0-9]*.exr \
    --diff "$work/diff.png" > "$work/compare.txt"
verdict=$?
set -e
cat "$work/compare.txt"

python3 - "$work" "$spp" "$verdict" > "$work/mitsuba_cornell.md" <<'PY'
import json, sys, platform, os
work, spp, verdict = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
ours = json.load(open(f"{work}/raylemma/cornell.json"))
theirs = json.load(open(f"{work}/mitsuba/cornell-mitsuba.json"))
rss = {k: int(open(f"{work}/{k}.rss").read().split()[-1]) for k in ("raylemma", "mitsuba")}
cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), platform.machine())
ratio = ours["pixel_samples_per_second"] / theirs["pixel_samples_per_second"]
print("| renderer | spp | threads | seconds | pixel samples / s | peak memory (MiB) |")
print("|---|---:|---:|---:|---:|---:|")
print(f"| {ours['renderer']} | {ours['spp']} | {ours['threads']} | {ours['seconds']:.1f} | {ours['pixel_samples_per_second']:.3e} | {rss['raylemma']/1024:.0f} |")
print(f"| {theirs['renderer']} | {theirs['spp']} | {theirs['threads']} | {theirs['seconds']:.1f} | {theirs['pixel_samples_per_second']:.3e} | {rss['mitsuba']/1024:.0f} |")
print()
print(f"**Throughput ratio raylemma / Mitsuba: {ratio:.2f}**, measured one after the other in one run of "
      f"`tools/mitsuba/compare.sh {spp}` on {cpu}, {os.cpu_count()} cores. Peak memory is the whole process's "
      "maximum resident set (Mitsuba's includes the Python interpreter and its libraries).")
print()
print("`raylemma compare` of the two images (exit status "
      f"{verdict}: {'they agree' if verdict == 0 else 'they differ' if verdict == 1 else 'error'}):")
print()
print("```text")
# The difference image is copied into figures/ below: name it there, not in the work folder.
report = open(f"{work}/compare.txt").read().rstrip()
print(report.replace(f"{work}/diff.png", "figures/mitsuba_cornell_diff.png"))
print("```")
PY
cp "$work/mitsuba_cornell.md" "$root/figures/mitsuba_cornell.md"
cp "$work/diff.png" "$root/figures/mitsuba_cornell_diff.png"
cp "$work/mitsuba/cornell.png" "$root/figures/mitsuba_cornell.png"
echo "== wrote figures/mitsuba_cornell.md, figures/mitsuba_cornell_diff.png, figures/mitsuba_cornell.png"
cat "$root/figures/mitsuba_cornell.md"
