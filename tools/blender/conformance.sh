#!/usr/bin/env bash
# Blender's Cycles on the conformance ladder: the card of every rung through
# `raylemma conformance --format json` and tools/blender/candidate.py, then, for each
# comparison that differs, raylemma's prediction of the RGB image (predict_rgb.py) and the
# comparisons that explain it (ladder_table.py). Writes figures/conformance_cycles.md and its
# named values into figures/values.json.
#
#     tools/blender/conformance.sh [SPP [RUNS]]          (default 256 spp, 4 runs a rung)
#     tools/blender/conformance.sh --table [SPP [RUNS]]  (the table again from the last card)
#
# Work files: ${TMPDIR:-/tmp}/raylemma-conformance-cycles. About 10 minutes on 2 cores.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
source "$root/tools/adapters.sh"
ladder_options 256 "$@"
work="${TMPDIR:-/tmp}/raylemma-conformance-cycles"
venv="${RAYLEMMA_BLENDER_VENV:-/root/.cache/raylemma-blender-venv}"
bash "$root/tools/blender/setup.sh" --no-test >&2
py="$venv/bin/python"
RAYLEMMA="$(raylemma_release "$root")"
export RAYLEMMA

t0=$(date +%s)
if [ "$table_only" = 0 ]; then
    json_card "$root" "$work" \
        "$py -W ignore $root/tools/blender/candidate.py {scene} {out} --spp {spp} --seed {seed}"
fi
version="$("$py" -c 'import bpy; print(bpy.app.version_string)' 2>/dev/null | tail -n 1)"
cpu="$(machine_cpu)"
caption="*\`tools/blender/conformance.sh $spp $runs\` on $(date -u +%Y-%m-%d), $cpu, $(nproc) cores: \
Cycles $version (\`bpy\` from PyPI, CPU) through \`raylemma conformance --format json\` with $runs runs of \
$spp spp per rung and depth, each rung exported and built by \`tools/blender/candidate.py\` (box filter of \
one pixel, clamping, light threshold, light tree, adaptive sampling, denoising and Filter Glossy off, \
bounces = max_depth − 1). Where the card says *differs*, \`predict_rgb.py\` renders raylemma's prediction \
of the RGB image (4096 spp a channel, negative colours clamped to 0 as Cycles does); the block is the 16 × 16 block and channel where that prediction is \
furthest from the spectral reference, and the last column is \`raylemma compare PREDICTION.exr RUN-*.exr\`.*"
"$py" "$root/tools/blender/ladder_table.py" --name cycles --label Cycles --card "$work/card.json" \
    --work "$work" --figure conformance_cycles.md --caption "$caption" --clamp-negative
echo "conformance.sh: $(( $(date +%s) - t0 )) s" >&2
