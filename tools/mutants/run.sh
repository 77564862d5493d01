#!/usr/bin/env bash
# Mutation testing with cargo-mutants: does some test fail when the code is changed?
#
#   tools/mutants/run.sh [N [SHARD...]]      (default N = 40, SHARD = 0)
#
# Three groups of files (chapter "Tests of the tests"):
#   * the derivation modules (sampling, optics, spectral, transport) and the checkers
#     (src/check/): a systematic sample, cargo-mutants' `--shard K/N --sharding
#     round-robin` for each SHARD K (the mutants K, K + N, K + 2N, ... of the file, in
#     source order; cargo-mutants' default, `slice`, would take the K-th run of
#     consecutive mutants, the top of the file), each mutant tested with the file's own
#     chapter's tests (`cargo test --test book CHAPTER::`): what a student who changed that
#     module would run. The full run (N = 1) is days on 2 cores.
#   * the renderer: tools/mutants/render.sh (its own table, figures/mutants_render.md).
# Mutants are made in place (cargo-mutants --in-place), so that every build after the
# first is incremental: run it in a clean checkout of its own, never in one you are
# editing. A timeout counts as caught (the mutant made a test loop). The summary,
# figures/mutants.md, gives the share caught per group with a 95 % Wilson interval, and
# every surviving mutant. Results accumulate in $OUT (default /tmp/raylemma-mutants-rr; the
# summary reads every run in it, so do not point it at a folder of the older slice runs).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
n="${1:-40}"
shift || true
shards=("${@:-0}")
[ "${#shards[@]}" -gt 0 ] || shards=(0)
out="${OUT:-/tmp/raylemma-mutants-rr}"
cd "$root"
source "$here/common.sh"
# sampled: source file -> its chapter's test module in tests/book/
sampled=(
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
  "src/check/sphere/mod.rs geometry::sphere"
  "src/check/warp/mod.rs checking::warps"
  "src/check/warp/cells.rs checking::warps"
  "src/check/reflect/mod.rs optics::reflect"
  "src/check/fresnel/mod.rs optics::fresnel"
)
for shard in "${shards[@]}"; do
  for entry in "${sampled[@]}"; do
    set -- $entry
    # ".rr": round-robin shards; results of the older slice shards (".sK") are not reused.
    mutate "$(echo "$1" | tr '/' '_').rr.s$shard" "$2::" -f "$1" --shard "$shard/$n" --sharding round-robin
  done
done
python3 "$here/summary.py" "$out" "$n" > "$root/figures/mutants.md"
cat "$root/figures/mutants.md"
