#!/usr/bin/env bash
# Mutation testing of the derivation modules (sampling, optics, spectral, transport) with
# cargo-mutants: does some test fail when the code is changed?
#
#   tools/mutants/run.sh [N [SHARD...]]      (default N = 40, SHARD = 0)
#
# Every source file is mutated with cargo-mutants' systematic samples `--shard K/N` for each
# SHARD K (every N-th mutant of the file, starting at the K-th: about 1/N of all per shard),
# and each mutant is tested with the file's own
# chapter tests plus the library's unit tests (`cargo test --lib --test CHAPTER`), not the
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
# source file -> its chapter's test files
map=(
  "src/sampling/sphere.rs sampling_sphere"
  "src/sampling/disc.rs disc"
  "src/sampling/cosine.rs cosine"
  "src/sampling/importance.rs importance"
  "src/sampling/tabulated.rs tabulated"
  "src/sampling/frame.rs frame"
  "src/optics/reflect.rs reflect"
  "src/optics/fresnel.rs fresnel"
  "src/optics/specular.rs specular"
  "src/optics/dispersion.rs dispersion"
  "src/optics/thinfilm.rs thinfilm"
  "src/spectral/spectrum.rs colour"
  "src/spectral/cie.rs colour"
  "src/spectral/wavelength.rs wavelength"
  "src/spectral/emission.rs emission"
  "src/spectral/display.rs display"
  "src/spectral/upsample.rs upsample"
  "src/transport/lambert.rs lambert"
  "src/transport/roulette.rs roulette"
  "src/transport/shadow.rs shadow"
)
cd "$root"
for shard in "${shards[@]}"; do
for entry in "${map[@]}"; do
  set -- $entry
  file="$1"; shift
  name="$(echo "$file" | tr '/' '_').s$shard"
  [ -f "$out/$name/mutants.out/outcomes.json" ] && { echo "== $file shard $shard: done before"; continue; }
  # -C restricts the build as well as the run to the unit tests and these test files.
  args=(-C --lib)
  for t in "$@"; do args+=(-C "--test=$t"); done
  echo "== $file shard $shard/$n (tests: $*)"
  cargo mutants --no-shuffle -f "$file" --shard "$shard/$n" --baseline skip \
    --timeout 300 --build-timeout 900 -o "$out/$name" "${args[@]}" || true
done
done
python3 "$here/summary.py" "$out" "$n" > "$root/figures/mutants.md"
cat "$root/figures/mutants.md"
