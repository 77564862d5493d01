#!/usr/bin/env bash
# Sets up LuxCoreRender for tools/luxcore (see README.md): a venv with pyluxcore, numpy and
# OpenEXR at pinned versions. Idempotent. The candidate also imports tools/blender's colour
# code (plain numpy; no Blender needed).
#
#   tools/luxcore/setup.sh
#
# The venv is $RAYLEMMA_LUXCORE_VENV, default /root/.cache/raylemma-luxcore-venv.
set -euo pipefail

PYLUXCORE_VERSION=2.11.2
NUMPY_VERSION=2.4.6
OPENEXR_VERSION=3.5.3

venv="${RAYLEMMA_LUXCORE_VENV:-/root/.cache/raylemma-luxcore-venv}"
py="$venv/bin/python"
case "${1:-}" in
    -h|--help) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    '') ;;
    *) echo "setup.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
esac
source "$(dirname "$0")/../adapters.sh"
pinned_venv "$venv" python3 \
    "pyluxcore==$PYLUXCORE_VERSION" "numpy==$NUMPY_VERSION" "OpenEXR==$OPENEXR_VERSION"
