#!/usr/bin/env bash
# Sets up Blender's Cycles for tools/blender (see README.md): a venv with Blender as a Python
# module (`bpy` from PyPI) and numpy, at pinned versions. Idempotent.
#
#   tools/blender/setup.sh          the venv, then a tiny Cycles render as a test
#   tools/blender/setup.sh --no-test
#
# The venv is $RAYLEMMA_BLENDER_VENV, default /root/.cache/raylemma-blender-venv. bpy 5.0.1
# is built for CPython 3.11 only (the wheel's tag is cp311): python3.11 must exist.
set -euo pipefail

BPY_VERSION=5.0.1
NUMPY_VERSION=1.26.4
OPENEXR_VERSION=3.5.3

venv="${RAYLEMMA_BLENDER_VENV:-/root/.cache/raylemma-blender-venv}"
py="$venv/bin/python"
mode=full
case "${1:-}" in
    -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --no-test) mode=notest ;;
    '') ;;
    *) echo "setup.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
esac

python=python3.11
command -v "$python" >/dev/null || python=python3
if [ ! -x "$py" ]; then
    case "$("$python" -c 'import sys; print("%d.%d" % sys.version_info[:2])')" in
        3.11) ;;
        *) echo "setup.sh: bpy $BPY_VERSION needs Python 3.11; $python is not" >&2; exit 1 ;;
    esac
fi
source "$(dirname "$0")/../adapters.sh"
# bpy is about 400 MB.
pinned_venv "$venv" "$python" \
    "bpy==$BPY_VERSION" "numpy==$NUMPY_VERSION" "OpenEXR==$OPENEXR_VERSION"
[ "$mode" = notest ] && exit 0

"$py" - <<'PY'
import time
import bpy
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 4
scene.render.resolution_x = scene.render.resolution_y = 16
t0 = time.perf_counter()
bpy.ops.render.render()
print(f"Blender {bpy.app.version_string}: Cycles rendered an empty 16 x 16 scene in {time.perf_counter() - t0:.2f} s")
PY
