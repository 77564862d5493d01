#!/usr/bin/env bash
# The fair speed comparison of raylemma with Mitsuba 3 (the renderer chapter and the speed
# chapter's table figures/mitsuba_speed.md), in one run on one machine:
#
#   1. the `cornell` scene with every setting made explicit (RES x RES pixels, SPP samples
#      per pixel, Russian roulette from depth 5, the scene's maximum depth), exported by
#      `raylemma export` for Mitsuba (rr_depth 5) and as JSON;
#   2. an untimed warm-up of each renderer (Dr.Jit compiles and caches its kernels then);
#   3. RUNS rounds, each rendering with raylemma, Mitsuba `scalar_spectral` and Mitsuba
#      `llvm_ad_spectral`, one after the other, all on every core; Mitsuba in PASSES
#      independent passes of SPP / PASSES samples (their spread is its variance);
#   4. per renderer the median over the rounds of: render seconds (scene loading left out,
#      for both), pixel samples per second, the mean per-pixel variance of the mean, the
#      efficiency 1 / (variance x seconds), the whole process's wall time and peak memory;
#   5. `raylemma compare` of each Mitsuba variant's passes against raylemma's image (the
#      renders must agree for their speeds to be compared), and the sentences that compare
#      the renderers, written from the medians (tools/mitsuba/speed.py);
#   6. this machine's line in the table of every machine measured
#      (figures/mitsuba_speed_machines.md: the efficiency ratio against the fastest
#      variant, with its range over the rounds), in place of its earlier line.
#
#   tools/mitsuba/speed.sh [SPP [RES [RUNS [PASSES]]]]     (default 256 256 3 16)
#
# Needs the network once (Mitsuba from PyPI, libLLVM from Debian: setup.sh). Python and
# Mitsuba are used here only; `cargo test` never needs them. A partial run writes nothing
# into figures/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
spp="${1:-256}"
res="${2:-256}"
runs="${3:-3}"
passes="${4:-16}"
work="${TMPDIR:-/tmp}/raylemma-mitsuba-speed"
rm -rf "$work"
mkdir -p "$work"
cd "$root"
command -v /usr/bin/time >/dev/null || {
    echo "speed.sh: needs /usr/bin/time (apt-get install time) for peak memory" >&2
    exit 2
}

echo "== building raylemma (release)"
cargo build --release --quiet -p raylemma -p raylemma-figures
bin="${CARGO_TARGET_DIR:-$root/target}/release/raylemma"
# The machine as the figure job's timing captions name it (the same fingerprint).
"${CARGO_TARGET_DIR:-$root/target}/release/raylemma-figures" machine > "$work/machine"
bash "$here/setup.sh" --no-test
py="${RAYLEMMA_MITSUBA_VENV:-/root/.cache/raylemma-mitsuba-venv}/bin/python"

# The scene with its settings explicit: spp, roulette depth 5 and the resolution written
# into the file, the data paths absolute (the copy lives outside scenes/).
sed -e "s/^spp = .*/spp = $spp\nroulette_depth = 5/" \
    -e "s/^resolution = .*/resolution = [$res, $res]/" \
    -e "s#\"\.\./data/#\"$root/data/#g" scenes/cornell.toml > "$work/cornell.toml"
grep -q '^roulette_depth = 5$' "$work/cornell.toml"
"$bin" export "$work/cornell.toml" --to mitsuba --out "$work/cornell.xml"
"$bin" export "$work/cornell.toml" --to json --out "$work/cornell.json"
grep -q '<integer name="rr_depth" value="5"/>' "$work/cornell.xml"

ours() { # ours DIR SPP
    mkdir -p "$1"
    /usr/bin/time -f "%e %M" -o "$1/process" \
        "$bin" render "$work/cornell.toml" --spp "$2" --seed "$((12345 + ${3:-0}))" --out "$1" > "$1/log"
}
theirs() { # theirs VARIANT DIR SPP ROUND
    mkdir -p "$2"
    /usr/bin/time -f "%e %M" -o "$2/process" \
        "$py" "$here/render.py" "$work/cornell.xml" --json "$work/cornell.json" --variant "$1" \
        --spp "$3" --passes "$passes" --seed "$((1000 * ${4:-0}))" --out "$2/cornell" > "$2/log"
}

echo "== warm-up (untimed): each renderer at $passes spp"
ours "$work/warm/raylemma" "$passes"
theirs scalar_spectral "$work/warm/scalar" "$passes"
theirs llvm_ad_spectral "$work/warm/llvm" "$passes"

for r in $(seq 1 "$runs"); do
    echo "== round $r of $runs: cornell, ${res}x${res}, $spp spp, roulette from depth 5"
    ours "$work/r$r/raylemma" "$spp" "$r"
    echo "   raylemma: $(cat "$work/r$r/raylemma/process") (wall s, peak KiB)"
    for v in scalar_spectral llvm_ad_spectral; do
        theirs "$v" "$work/r$r/$v" "$spp" "$r"
        echo "   $v: $(cat "$work/r$r/$v/process") (wall s, peak KiB)"
    done
done

echo "== raylemma compare: each Mitsuba variant's passes against raylemma's image (round 1)"
for v in scalar_spectral llvm_ad_spectral; do
    set +e
    "$bin" compare "$work/r1/raylemma/cornell.exr" "$work/r1/$v/cornell"-[0-9]*.exr \
        --diff "$work/diff-$v.png" > "$work/compare-$v.txt"
    echo $? > "$work/compare-$v.status"
    set -e
    tail -n 1 "$work/compare-$v.txt"
done

cp "$root/figures/mitsuba_speed_machines.md" "$work/mitsuba_speed_machines.md" 2>/dev/null || true
"$py" "$here/speed.py" "$work" --spp "$spp" --res "$res" --runs "$runs" --passes "$passes" \
    --png "$work/mitsuba_cornell.png" --machines "$work/mitsuba_speed_machines.md" \
    > "$work/mitsuba_speed.md"
cp "$work/mitsuba_speed.md" "$root/figures/mitsuba_speed.md"
cp "$work/mitsuba_speed_machines.md" "$root/figures/mitsuba_speed_machines.md"
cp "$work/diff-llvm_ad_spectral.png" "$root/figures/mitsuba_cornell_diff.png"
cp "$work/mitsuba_cornell.png" "$root/figures/mitsuba_cornell.png"
echo "== wrote figures/mitsuba_speed.md, figures/mitsuba_speed_machines.md, figures/mitsuba_cornell.png, figures/mitsuba_cornell_diff.png"
cat "$root/figures/mitsuba_speed.md"
