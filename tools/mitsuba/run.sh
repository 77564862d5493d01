#!/usr/bin/env bash
# Independent validation render of the Cornell box with Mitsuba 3 (see README.md).
#
#   tools/mitsuba/run.sh [SPP] [OUT.exr] [more cornell.py options...]
#
# SPP defaults to 1024, OUT to /tmp/mitsuba/cornell_mitsuba_SPP.exr; anything
# after them goes to cornell.py (e.g. --passes 16 --threads 1 --png FILE.png).
# Creates (or reuses) the venv $RAYLEMMA_MITSUBA_VENV, default
# /root/.cache/raylemma-mitsuba-venv, with the packages pinned in setup.sh.
# Nothing here is used by `cargo test`.
set -euo pipefail

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

# The venv and the pinned packages (mitsuba, drjit, numpy) are made by setup.sh.
bash "$here/setup.sh" --pip-only

mkdir -p "$(dirname "$out")"
exec "$py" "$here/cornell.py" --spp "$spp" --out "$out" "$@"
