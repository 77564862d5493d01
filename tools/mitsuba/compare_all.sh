#!/usr/bin/env bash
# The renderer chapter's independent check: every canonical scene that Mitsuba 3 can
# express, exported by raylemma, rendered by Mitsuba, compared with its committed reference.
#
#   tools/mitsuba/compare_all.sh [SPP] [PASSES] [VARIANT]
#
# For each scene of scenes/ (defaults: 1024 spp in 16 passes, scalar_spectral):
#   1. `raylemma export SCENE --to mitsuba` and `--to json` (a scene Mitsuba cannot express
#      is refused by the exporter with its line and reason: the table says so);
#   2. render.py renders the XML as exported, PASSES independent passes of SPP/PASSES
#      samples, each a plain linear-sRGB EXR (raylemma's own XYZ -> sRGB matrix);
#   3. `raylemma compare figures/reference/NAME.exr NAME-*.exr`: the passes' spread is the
#      candidate's variance (PASSES - 1 degrees of freedom);
#   4. the table figures/mitsuba_compare.md (verdict, mean z^2, RMSE, the whole image's
#      mean against the reference's, both renderers' time), Mitsuba's cornell as
#      figures/mitsuba_compare_cornell.png and the difference image
#      figures/mitsuba_compare_cornell_diff.png.
# Then once more for furnace-grey with Mitsuba's own hdrfilm instead of the exported
# specfilm: what Mitsuba's colour conversion does to the comparison (one extra row).
# Work files go to ${TMPDIR:-/tmp}/raylemma-mitsuba-compare. The venv is made by setup.sh
# (PyPI once). Nothing here is used by `cargo test`.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
case "${1:-}" in
    -h|--help) sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
esac
spp="${1:-1024}"
passes="${2:-16}"
variant="${3:-scalar_spectral}"
for n in "$spp" "$passes"; do
    case "$n" in
        ''|*[!0-9]*) echo "compare_all.sh: SPP and PASSES must be positive integers (see --help)" >&2; exit 2 ;;
    esac
done
if [ "$passes" -lt 2 ] || [ $((spp % passes)) -ne 0 ]; then
    echo "compare_all.sh: PASSES must be at least 2 and divide SPP (got $spp and $passes)" >&2
    exit 2
fi
work="${TMPDIR:-/tmp}/raylemma-mitsuba-compare"
rm -rf "$work"
mkdir -p "$work"
cd "$root"

echo "== building raylemma (release)"
cargo build --release --quiet -p raylemma
bin="${CARGO_TARGET_DIR:-$root/target}/release/raylemma"
bash "$here/setup.sh" --pip-only
py="${RAYLEMMA_MITSUBA_VENV:-/root/.cache/raylemma-mitsuba-venv}/bin/python"

scenes="cornell cornell-diffuse lamps/amber-led lamps/incandescent lamps/cool-white-fluorescent
lamps/low-pressure-sodium lamps/high-pressure-sodium furnace-grey furnace dispersion bubble"
: > "$work/scenes.txt"
for scene in $scenes; do
    name="${scene//\//-}"
    echo "== $scene"
    if ! "$bin" export "scenes/$scene.toml" --to mitsuba --out "$work/$name.xml" 2> "$work/$name.export.txt"; then
        cat "$work/$name.export.txt"
        echo "$scene $name refused" >> "$work/scenes.txt"
        continue
    fi
    "$bin" export "scenes/$scene.toml" --to json --out "$work/$name.json" 2>/dev/null
    png=()
    [ "$name" = cornell ] && png=(--png "$work/cornell.png")
    "$py" "$here/render.py" "$work/$name.xml" --json "$work/$name.json" --spp "$spp" --passes "$passes" \
        --variant "$variant" --out "$work/$name" "${png[@]}"
    set +e
    "$bin" compare "figures/reference/$name.exr" "$work/$name"-[0-9]*.exr --diff "$work/$name-diff.png" \
        > "$work/$name.compare.txt" 2>&1
    verdict=$?
    set -e
    cat "$work/$name.compare.txt"
    echo "$scene $name $verdict" >> "$work/scenes.txt"
done

echo "== furnace-grey with Mitsuba's hdrfilm"
"$py" "$here/render.py" "$work/furnace-grey.xml" --json "$work/furnace-grey.json" --spp "$spp" --passes "$passes" \
    --variant "$variant" --out "$work/furnace-grey-hdrfilm" --film hdrfilm
set +e
"$bin" compare figures/reference/furnace-grey.exr "$work/furnace-grey-hdrfilm"-[0-9]*.exr \
    > "$work/furnace-grey-hdrfilm.compare.txt" 2>&1
verdict=$?
set -e
cat "$work/furnace-grey-hdrfilm.compare.txt"
echo "furnace-grey furnace-grey-hdrfilm $verdict" >> "$work/scenes.txt"

"$py" - "$work" "$root" "$spp" "$passes" "$variant" > "$work/mitsuba_compare.md" <<'PY'
import glob, json, os, re, sys
import numpy as np
import mitsuba as mi
mi.set_variant("scalar_rgb")
work, root, spp, passes, variant = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "unknown CPU")

def channels(path):
    b = mi.Bitmap(path)
    names = [f.name for f in b.struct_()]
    a = np.array(b, dtype=np.float64)
    return np.stack([a[:, :, names.index(c)] for c in "RGB"], axis=-1)

rows = [l.split() for l in open(f"{work}/scenes.txt")]
print("| scene | verdict | mean z² | RMSE | whole image, (Mitsuba − raylemma) / |raylemma|: R, G, B (z) | raylemma: reference "
      f"| Mitsuba 3: {spp} spp in {passes} passes | pixel samples / s, raylemma / Mitsuba |")
print("|---|---|---:|---:|---:|---:|---:|---:|")
refused = []
for scene, name, verdict in rows:
    if verdict == "refused":
        msg = open(f"{work}/{name}.export.txt").read().strip()
        refused.append((scene, msg.removeprefix("raylemma: error: ")))
        continue
    report = open(f"{work}/{name}.compare.txt").read()
    base = name.removesuffix("-hdrfilm")
    ref = json.load(open(f"{root}/figures/reference/{base}.json"))
    mit = json.load(open(f"{work}/{name}-mitsuba.json"))
    m = re.search(r"RMSE ([0-9.e+-]+); mean z\^2 ([0-9.]+)", report)
    zs = re.search(r"whole image: z = (\S+) \(R\), (\S+) \(G\), (\S+) \(B\)", report).groups()
    r = channels(f"{root}/figures/reference/{base}.exr").reshape(-1, 3).mean(axis=0)
    c = np.mean([channels(p).reshape(-1, 3).mean(axis=0) for p in sorted(glob.glob(f"{work}/{name}-[0-9]*.exr"))], axis=0)
    # compare's z is reference minus candidate: the candidate's excess is -z.
    rel = ", ".join(f"{100 * (c[i] - r[i]) / abs(r[i]):+.3f} % ({-float(zs[i]):+.1f})" for i in range(3))
    word = {"0": "agree", "1": "**differ**"}.get(verdict, f"error ({verdict})")
    label = f"`{scene}`" + (", Mitsuba's own `hdrfilm`" if name.endswith("-hdrfilm") else "")
    ratio = ref["pixel_samples_per_second"] / mit["pixel_samples_per_second"]
    print(f"| {label} | {word} | {float(m.group(2)):.3f} | {float(m.group(1)):.3e} | {rel} "
          f"| {ref['spp']} spp, {ref['seconds']:.1f} s ({ref['threads']} threads) "
          f"| {mit['seconds']:.1f} s ({mit['threads']} threads) | {ratio:.2f} |")
for scene, msg in refused:
    print(f"| `{scene}` | not exported | | | | | | |")
print()
print(f"*`tools/mitsuba/compare_all.sh {spp} {passes} {variant}` on {cpu}, {os.cpu_count()} cores, "
      f"shared with other work: Mitsuba 3.9.1 `{variant}` renders each scene as `raylemma export` wrote it, "
      f"{passes} passes of {spp // passes} spp with independent seeds, and `raylemma compare` tests the passes "
      "against the committed reference `figures/reference/NAME.exr` at `--alpha 0.01` (the passes' spread is the "
      f"candidate's variance, {passes - 1} degrees of freedom; the reference's own, from its `spp`). The whole "
      "image's mean is the passes' against the reference's, with compare's z of that difference. The `hdrfilm` row "
      "renders the same file with Mitsuba's own film in place of the exported `specfilm`. raylemma's time "
      "is its reference's render, from its JSON sidecar; the throughputs were measured at different times under "
      "different loads, so their ratio is indicative only.*")
if refused:
    print()
    print("Not exported (the exporter's message):")
    print()
    for scene, msg in refused:
        print(f"- `{scene}`: {msg}")
PY
cp "$work/mitsuba_compare.md" "$root/figures/mitsuba_compare.md"
cp "$work/cornell.png" "$root/figures/mitsuba_compare_cornell.png"
cp "$work/cornell-diff.png" "$root/figures/mitsuba_compare_cornell_diff.png"
echo "== wrote figures/mitsuba_compare.md, figures/mitsuba_compare_cornell.png, figures/mitsuba_compare_cornell_diff.png"
cat "$root/figures/mitsuba_compare.md"
