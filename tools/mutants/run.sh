#!/usr/bin/env bash
# Mutation testing of the derivation modules (sampling, optics, spectral, transport) with
# cargo-mutants: does some test fail when the code is changed?
#
#   tools/mutants/run.sh [N [SHARD...]]      (default N = 40, SHARD = 0)
#
# Every source file is mutated with cargo-mutants' systematic samples `--shard K/N` for each
# SHARD K (every N-th mutant of the file, starting at the K-th: about 1/N of all per shard),
# and each mutant is tested with the file's own
# chapter's tests (`cargo test --test book CHAPTER::`), not the
# whole suite: that is what a student sees, and it keeps one mutant under a minute on 2
# cores. The full run (N = 1) is some 3600 mutants, days on this machine. The summary,
# figures/mutants.md, gives the share caught per group with a 95 % Wilson interval, and
# every surviving mutant. Results accumulate in $OUT (default /tmp/raylemma-mutants).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
n="${1:-40}"
shift || true
shards=("${@:-0}")
[ "${#shards[@]}" -gt 0 ] || shards=(0)
out="${OUT:-/tmp/raylemma-mutants}"
command -v cargo-mutants >/dev/null || cargo install cargo-mutants --locked --version 27.1.0
mkdir -p "$out"
# source file -> its chapter's test module in tests/book/
map=(
  "src/sampling/sphere.rs sampling::sphere"
  "src/sampling/disc.rs sampling::disc"
  "src/sampling/cosine.rs sampling::cosine"
  "src/sampling/importance.rs sampling::importance"
  "src/sampling/tabulated.rs sampling::tabulated"
  "src/sampling/frame.rs sampling::frame"
  "src/optics/reflect.rs optics::reflect"
  "src/optics/fresnel.rs optics::fresnel"
  "src/optics/specular.rs optics::specular"
  "src/optics/dispersion.rs optics::dispersion"
  "src/optics/thinfilm.rs optics::thinfilm"
  "src/spectral/spectrum.rs spectral::colour"
  "src/spectral/cie.rs spectral::colour"
  "src/spectral/wavelength.rs spectral::wavelength"
  "src/spectral/emission.rs spectral::emission"
  "src/spectral/display.rs spectral::display"
  "src/spectral/upsample.rs spectral::upsample"
  "src/transport/lambert.rs transport::lambert"
  "src/transport/roulette.rs transport::roulette"
  "src/transport/shadow.rs transport::shadow"
)
cd "$root"
for shard in "${shards[@]}"; do
for entry in "${map[@]}"; do
  set -- $entry
  file="$1"; shift
  name="$(echo "$file" | tr '/' '_').s$shard"
  [ -f "$out/$name/mutants.out/outcomes.json" ] && { echo "== $file shard $shard: done before"; continue; }
  # -C restricts the build to the book's test binary; the module path after `--` restricts
  # the run to this chapter's tests.
  echo "== $file shard $shard/$n (tests: $*)"
  cargo mutants --no-shuffle -f "$file" --shard "$shard/$n" --baseline skip \
    --timeout 300 --build-timeout 900 -o "$out/$name" -C --test=book -- "$1::" || true
done
done
python3 "$here/summary.py" "$out" "$n" > "$root/figures/mutants.md"
cat "$root/figures/mutants.md"
