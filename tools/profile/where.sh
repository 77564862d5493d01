#!/usr/bin/env bash
# Where the renderer's instructions go: builds raylemma with line tables, renders the
# cornell scene (128 x 128, 8 spp, roulette from depth 5, one thread) under callgrind, and
# writes figures/render_profile.md (tools/profile/where.py). Callgrind counts
# instructions, the same on every run of the same binary, whatever else the machine does.
#
#   tools/profile/where.sh
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
command -v valgrind >/dev/null || { echo "where.sh: needs valgrind (apt-get install valgrind)" >&2; exit 2; }
work="${TMPDIR:-/tmp}/raylemma-profile"
mkdir -p "$work"
target="${CARGO_TARGET_DIR:-$root/target}/profile-build"
CARGO_TARGET_DIR="$target" CARGO_PROFILE_RELEASE_DEBUG=line-tables-only \
  cargo build --release --quiet -p raylemma --manifest-path "$root/Cargo.toml"
sed -e 's/^spp = .*/spp = 8\nroulette_depth = 5/' -e 's/^resolution = .*/resolution = [128, 128]/' \
  -e "s#\"\.\./data/#\"$root/data/#g" "$root/scenes/cornell.toml" > "$work/cornell.toml"
valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" \
  "$target/release/raylemma" render "$work/cornell.toml" --threads 1 --out "$work/out" 2> "$work/valgrind.log"
python3 "$here/where.py" "$work/callgrind.out" $((128 * 128 * 8)) > "$work/render_profile.md"
mv "$work/render_profile.md" "$root/figures/render_profile.md"
cat "$root/figures/render_profile.md"
