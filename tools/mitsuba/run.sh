#!/usr/bin/env bash
# Independent validation render of the Cornell box with Mitsuba 3 (see README.md).
#
#   tools/mitsuba/run.sh [SPP] [OUT.exr] [more cornell.py options...]
#
# SPP defaults to 1024, OUT to /tmp/mitsuba/cornell_mitsuba_SPP.exr; anything
# after them goes to cornell.py (e.g. --passes 16 --threads 1 --png FILE.png).
# Creates (or reuses) the venv $RAYLEMMA_MITSUBA_VENV, default
# /root/.cache/raylemma-mitsuba-venv, with the pinned packages below.
# Nothing here is used by `cargo test`.
set -euo pipefail

MITSUBA_VERSION=3.9.1
DRJIT_VERSION=1.5.0
NUMPY_VERSION=2.4.6

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
venv="${RAYLEMMA_MITSUBA_VENV:-/root/.cache/raylemma-mitsuba-venv}"
py="$venv/bin/python"

case "${1:-}" in
    -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
esac
spp="${1:-1024}"
case "$spp" in
    ''|*[!0-9]*) echo "run.sh: SPP must be a positive integer, got '$spp' (see --help)" >&2; exit 2 ;;
esac
out="${2:-/tmp/mitsuba/cornell_mitsuba_${spp}.exr}"
shift $(($# < 2 ? $# : 2))

if [ ! -x "$py" ]; then
    echo "creating venv $venv" >&2
    python3 -m venv "$venv"
fi

have="$("$py" -c 'import importlib.metadata as m
try:
    print(m.version("mitsuba"), m.version("drjit"), m.version("numpy"))
except m.PackageNotFoundError:
    print("")' 2>/dev/null || true)"
if [ "$have" != "$MITSUBA_VERSION $DRJIT_VERSION $NUMPY_VERSION" ]; then
    echo "installing mitsuba==$MITSUBA_VERSION drjit==$DRJIT_VERSION numpy==$NUMPY_VERSION into $venv" >&2
    "$py" -m pip install --quiet --disable-pip-version-check \
        "mitsuba==$MITSUBA_VERSION" "drjit==$DRJIT_VERSION" "numpy==$NUMPY_VERSION"
fi

mkdir -p "$(dirname "$out")"
exec "$py" "$here/cornell.py" --spp "$spp" --out "$out" "$@"
