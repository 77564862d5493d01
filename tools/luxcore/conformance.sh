#!/usr/bin/env bash
# LuxCoreRender on the conformance ladder: the card of every rung through
# `raylemma conformance --format json` and tools/luxcore/candidate.py, then, for each
# comparison that differs, raylemma's prediction of the RGB image (tools/blender/predict_rgb.py)
# and the comparisons that explain it (tools/blender/ladder_table.py). Writes
# figures/conformance_luxcore.md and its named values into figures/values.json.
#
#     tools/luxcore/conformance.sh [SPP [RUNS]]          (default 256 spp, 4 runs a rung, as Cycles')
#     tools/luxcore/conformance.sh --table [SPP [RUNS]]  (the table again from the last card)
#
# Work files: ${TMPDIR:-/tmp}/raylemma-conformance-luxcore. The caption gives the wall time.
# The table and predictions run in the LuxCore venv's Python (they need numpy and OpenEXR only).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
source "$root/tools/adapters.sh"
ladder_options 256 "$@"
work="${TMPDIR:-/tmp}/raylemma-conformance-luxcore"
venv="${RAYLEMMA_LUXCORE_VENV:-/root/.cache/raylemma-luxcore-venv}"
bash "$root/tools/luxcore/setup.sh" >&2
py="$venv/bin/python"
RAYLEMMA="$(raylemma_release "$root")"
export RAYLEMMA

t0=$(date +%s)
if [ "$table_only" = 0 ]; then
    json_card "$root" "$work" \
        "$py $root/tools/luxcore/candidate.py {scene} {out} --spp {spp} --seed {seed}"
    echo "$(( $(date +%s) - t0 ))" > "$work/seconds.txt"
fi
version="$("$py" -c 'import importlib.metadata as m; print(m.version("pyluxcore"))')"
cpu="$(machine_cpu)"
minutes=$(( ($(cat "$work/seconds.txt") + 59) / 60 ))
caption="*\`tools/luxcore/conformance.sh $spp $runs\` on $(date -u +%Y-%m-%d), $cpu, $(nproc) cores, \
$minutes minutes for the card: LuxCoreRender $version (\`pyluxcore\` from PyPI, PATHCPU) through \
\`raylemma conformance --format json\` with $runs runs of $spp spp per rung and depth, each rung exported \
and built by \`tools/luxcore/candidate.py\` (box filter of one pixel, RANDOM sampler without adaptivity, \
clamping off, every path depth = max_depth + 1, light sampling of emitting meshes ENABLED, the screen \
window moved up one row). Where the card says *differs*, \`tools/blender/predict_rgb.py\` renders \
raylemma's prediction of the RGB image (4096 spp a channel, negative colours clamped to 0 as LuxCore \
does); the block is the 16 × 16 block and channel where that prediction is furthest from the spectral \
reference, and the last column is \`raylemma compare PREDICTION.exr RUN-*.exr\`.*"
"$py" "$root/tools/blender/ladder_table.py" --name luxcore --label LuxCore --card "$work/card.json" \
    --work "$work" --figure conformance_luxcore.md --caption "$caption" --clamp-negative
echo "conformance.sh: $(( $(date +%s) - t0 )) s" >&2
