#!/usr/bin/env bash
# A reference rendered as independent jobs and merged (chapter *Reference scenes and
# interop*, *References beyond one machine*): JOBS renders of SCENE at SPP samples per
# pixel, seeds 1..JOBS, run at most PARALLEL at a time (GNU parallel if installed, else
# xargs -P), merged with `raylemma merge`; then one render of JOBS x SPP samples with
# another seed, compared with the merge: they must agree within their noise.
#
# Usage: tools/merge/local.sh SCENE SPP JOBS [PARALLEL] [DIR]
#   e.g. tools/merge/local.sh scenes/cornell.toml 16 4 2
# Environment: RAYLEMMA (default: cargo run --release --quiet --).
# Exit status: compare's (0 agree, 1 differ, 2 bad input).
set -euo pipefail
scene="$1" spp="$2" jobs="$3" parallel="${4:-2}" dir="${5:-$(mktemp -d)}"
read -r -a raylemma <<<"${RAYLEMMA:-cargo run --release --quiet --}"
name="$(basename "$scene" .toml)"
RAYLEMMA_CMD="${raylemma[*]}"
if command -v parallel >/dev/null; then
    seq 1 "$jobs" | parallel -j "$parallel" \
        "$RAYLEMMA_CMD render '$scene' --spp $spp --seed {} --threads 1 --out '$dir/part-{}'"
else
    seq 1 "$jobs" | xargs -P "$parallel" -I{} \
        sh -c "$RAYLEMMA_CMD render '$scene' --spp $spp --seed {} --threads 1 --out '$dir/part-{}'"
fi
parts=()
for k in $(seq 1 "$jobs"); do parts+=("$dir/part-$k/$name.exr"); done
"${raylemma[@]}" merge "${parts[@]}" --out "$dir/merged/$name.exr"
"${raylemma[@]}" render "$scene" --spp $((spp * jobs)) --seed $((jobs + 1000)) --out "$dir/single"
"${raylemma[@]}" compare "$dir/single/$name.exr" "$dir/merged/$name.exr"
