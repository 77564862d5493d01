#!/usr/bin/env bash
# The renderer chapter's independent check: every canonical scene that Mitsuba 3 can
# express, exported by raylemma, rendered by Mitsuba, compared with its committed reference.
#
#   tools/mitsuba/compare_all.sh [--reuse] [SPP] [PASSES] [VARIANT]
#
# For each scene of scenes/ (defaults: 1024 spp in 16 passes, scalar_spectral):
#   1. `raylemma export SCENE --to mitsuba` and `--to json` (a scene Mitsuba cannot express
#      is refused by the exporter with its line and reason: the table says so);
#   2. render.py renders the XML as exported, PASSES independent passes of SPP/PASSES
#      samples, each a plain linear-sRGB EXR (raylemma's own XYZ -> sRGB matrix);
#   3. `raylemma compare figures/reference/NAME.exr NAME-*.exr`: the passes' spread is the
#      candidate's variance (PASSES - 1 degrees of freedom); and the same passes made 3 %
#      brighter, which must differ;
#   4. the control: raylemma itself, PASSES renders of SPP/PASSES samples with other seeds
#      than the reference's, compared the same way (what the comparison says of a renderer
#      known to agree, at the same samples);
#   5. the table figures/mitsuba_compare.md, Mitsuba's cornell as
#      figures/mitsuba_compare_cornell.png and its difference image
#      figures/mitsuba_compare_cornell_diff.png.
# Then once more for furnace-grey with Mitsuba's own hdrfilm instead of the exported
# specfilm: what Mitsuba's colour conversion does to the comparison (one extra row).
# --reuse keeps the renders of an earlier run with the same SPP, PASSES and VARIANT in the
# work folder, ${TMPDIR:-/tmp}/raylemma-mitsuba-compare (checking that the exports are
# still the files rendered), and redoes the comparisons and the table. The venv is made
# by setup.sh (PyPI once). Nothing here is used by `cargo test`.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
reuse=0
case "${1:-}" in
    -h|--help) sed -n '2,27p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --reuse) reuse=1; shift ;;
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
per_pass=$((spp / passes))
work="${TMPDIR:-/tmp}/raylemma-mitsuba-compare"
if [ "$reuse" = 1 ]; then
    if [ "$(cat "$work/settings.txt" 2>/dev/null)" != "$spp $passes $variant" ]; then
        echo "compare_all.sh: --reuse: $work holds no run of $spp spp in $passes passes ($variant)" >&2
        exit 2
    fi
else
    rm -rf "$work"
    mkdir -p "$work"
    echo "$spp $passes $variant" > "$work/settings.txt"
fi
mkdir -p "$work/bright" "$work/control"
cd "$root"

echo "== building raylemma (release)"
cargo build --release --quiet -p raylemma
bin="${CARGO_TARGET_DIR:-$root/target}/release/raylemma"
bash "$here/setup.sh" --pip-only
py="${RAYLEMMA_MITSUBA_VENV:-/root/.cache/raylemma-mitsuba-venv}/bin/python"

# compare OUT REFERENCE CANDIDATES...: the report into OUT, the exit status into OUT.rc.
compare() {
    local out="$1"
    shift
    set +e
    "$bin" compare "$@" > "$out" 2>&1
    echo $? > "$out.rc"
    set -e
}

# brighten SRC DST: every pass SRC-NN.exr times 1.03 as DST-NN.exr.
brighten() {
    "$py" - "$1" "$2" <<'PY'
import glob, sys
import numpy as np
import mitsuba as mi
mi.set_variant("scalar_rgb")
src, dst = sys.argv[1:]
for p in sorted(glob.glob(src + "-[0-9]*.exr")):
    a = np.array(mi.Bitmap(p), dtype=np.float32) * np.float32(1.03)
    mi.Bitmap(a, pixel_format=mi.Bitmap.PixelFormat.RGB).write(dst + p[len(src):])
PY
}

scenes="cornell cornell-diffuse lamps/amber-led lamps/incandescent lamps/cool-white-fluorescent
lamps/low-pressure-sodium lamps/high-pressure-sodium furnace-grey furnace dispersion bubble"
: > "$work/scenes.txt"
for scene in $scenes; do
    name="${scene//\//-}"
    echo "== $scene"
    if ! "$bin" export "scenes/$scene.toml" --to mitsuba --out "$work/$name.export.xml" 2> "$work/$name.export.txt"; then
        cat "$work/$name.export.txt"
        echo "$scene $name refused" >> "$work/scenes.txt"
        continue
    fi
    "$bin" export "scenes/$scene.toml" --to json --out "$work/$name.json" 2>/dev/null
    if [ "$reuse" = 1 ]; then
        cmp -s "$work/$name.export.xml" "$work/$name.xml" \
            || { echo "compare_all.sh: --reuse: $name's export is not the file rendered" >&2; exit 2; }
    else
        mv "$work/$name.export.xml" "$work/$name.xml"
        png=()
        [ "$name" = cornell ] && png=(--png "$work/cornell.png")
        "$py" "$here/render.py" "$work/$name.xml" --json "$work/$name.json" --spp "$spp" --passes "$passes" \
            --variant "$variant" --out "$work/$name" "${png[@]}"
    fi
    compare "$work/$name.compare.txt" "figures/reference/$name.exr" "$work/$name"-[0-9]*.exr \
        --diff "$work/$name-diff.png"
    cat "$work/$name.compare.txt"
    brighten "$work/$name" "$work/bright/$name"
    compare "$work/$name.bright.txt" "figures/reference/$name.exr" "$work/bright/$name"-[0-9]*.exr
    # The control: raylemma's own renders, seeds 1000 + k (the references use the scenes' seeds).
    for k in $(seq 0 $((passes - 1))); do
        file="$work/control/$name-$(printf %02d "$k").exr"
        if [ ! -f "$file" ]; then
            "$bin" render "scenes/$scene.toml" --spp "$per_pass" --seed $((1000 + k)) --out "$work/control/run" 2>/dev/null
            mv "$work/control/run/$(basename "$scene").exr" "$file"
        fi
    done
    compare "$work/$name.control.txt" "figures/reference/$name.exr" "$work/control/$name"-[0-9]*.exr
    echo "$scene $name $(cat "$work/$name.compare.txt.rc")" >> "$work/scenes.txt"
done

echo "== furnace-grey with Mitsuba's hdrfilm"
if [ "$reuse" = 0 ]; then
    "$py" "$here/render.py" "$work/furnace-grey.xml" --json "$work/furnace-grey.json" --spp "$spp" --passes "$passes" \
        --variant "$variant" --out "$work/furnace-grey-hdrfilm" --film hdrfilm
fi
compare "$work/furnace-grey-hdrfilm.compare.txt" figures/reference/furnace-grey.exr "$work/furnace-grey-hdrfilm"-[0-9]*.exr
cat "$work/furnace-grey-hdrfilm.compare.txt"
echo "furnace-grey furnace-grey-hdrfilm $(cat "$work/furnace-grey-hdrfilm.compare.txt.rc")" >> "$work/scenes.txt"

"$py" - "$work" "$root" "$spp" "$passes" "$variant" > "$work/mitsuba_compare.md" <<'PY'
import glob, json, os, re, sys
import numpy as np
import mitsuba as mi
mi.set_variant("scalar_rgb")
work, root, spp, passes, variant = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
sys.path.insert(0, os.path.join(root, "tools", "values"))
from values import Record, slug
record = Record("mitsuba_compare.md")
compared = []  # (scene, verdict, mean z², RMSE, bright verdict, control verdict, control z², control RMSE)
cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "unknown CPU")

def channels(path):
    b = mi.Bitmap(path)
    names = [f.name for f in b.struct_()]
    a = np.array(b, dtype=np.float64)
    return np.stack([a[:, :, names.index(c)] for c in "RGB"], axis=-1)

def summary(path):
    """verdict, mean z^2, RMSE, the whole image's z (positive: the candidate is brighter) of a report."""
    report = open(path).read()
    rc = open(path + ".rc").read().strip()
    m = re.search(r"RMSE ([0-9.e+-]+); mean z\^2 ([0-9.]+)", report)
    zs = re.search(r"whole image: z = (\S+) \(R\), (\S+) \(G\), (\S+) \(B\)", report).groups()
    word = {"0": "agree", "1": "**differ**"}.get(rc, f"error ({rc})")
    return word, float(m.group(2)), float(m.group(1)), [float(z) for z in zs]

rows = [l.split() for l in open(f"{work}/scenes.txt")]
print("| scene | verdict | mean z² | RMSE | whole image, Mitsuba against raylemma: R, G, B (z) "
      "| 3 % brighter copy | control, raylemma itself: verdict, mean z², RMSE | raylemma: reference "
      f"| Mitsuba 3: {spp} spp in {passes} passes | pixel samples / s, raylemma / Mitsuba |")
print("|---|---|---:|---:|---:|---|---:|---:|---:|---:|")
refused = []
for scene, name, verdict in rows:
    if verdict == "refused":
        msg = open(f"{work}/{name}.export.txt").read().strip()
        refused.append((scene, msg.removeprefix("raylemma: error: ")))
        continue
    base = name.removesuffix("-hdrfilm")
    word, z2, rmse, zs = summary(f"{work}/{name}.compare.txt")
    ref = json.load(open(f"{root}/figures/reference/{base}.json"))
    mit = json.load(open(f"{work}/{name}-mitsuba.json"))
    r = channels(f"{root}/figures/reference/{base}.exr").reshape(-1, 3).mean(axis=0)
    c = np.mean([channels(p).reshape(-1, 3).mean(axis=0)
                 for p in sorted(glob.glob(f"{work}/{name}-[0-9]*.exr"))], axis=0)
    # Relative to |raylemma|: a channel's mean is negative where the light is outside the gamut.
    rel = ", ".join(f"{100 * (c[i] - r[i]) / abs(r[i]):+.3f} % ({zs[i]:+.1f})" for i in range(3))
    if name.endswith("-hdrfilm"):
        label, bright, control = f"`{scene}`, Mitsuba's own `hdrfilm`", "", ""
    else:
        label = f"`{scene}`"
        bw, _, _, bz = summary(f"{work}/{name}.bright.txt")
        bright = f"{bw.replace('**', '')} (z {max(bz, key=abs):+.1f})"
        cw, cz2, crmse, _ = summary(f"{work}/{name}.control.txt")
        control = f"{cw}, {cz2:.3f}, {crmse:.3e}"
        compared.append((scene, word, z2, rmse, bw.replace("**", ""), cw, cz2, crmse))
        key = slug(scene)
        record.number(f"{key}.mean_z2", z2, ".3")
        record.number(f"{key}.control_mean_z2", cz2, ".3")
        record.number(f"{key}.rmse_over_control", rmse / crmse, "int")
    ratio = ref["pixel_samples_per_second"] / mit["pixel_samples_per_second"]
    if name.endswith("-hdrfilm"):
        record.claim("hdrfilm_differs", word == "**differ**", f"furnace-grey with Mitsuba's hdrfilm: {word}")
    print(f"| {label} | {word} | {z2:.3f} | {rmse:.3e} | {rel} | {bright} | {control} "
          f"| {ref['spp']} spp, {ref['seconds']:.1f} s ({ref['threads']} threads) "
          f"| {mit['seconds']:.1f} s, {mit['cpu_seconds']:.1f} s of CPU ({mit['threads']} threads) | {ratio:.2f} |")
for scene, msg in refused:
    print(f"| `{scene}` | not exported | | | | | | | | |")
print()
print(f"*`tools/mitsuba/compare_all.sh {spp} {passes} {variant}` on {cpu}, {os.cpu_count()} cores, "
      f"shared with other work: Mitsuba 3.9.1 `{variant}` renders each scene as `raylemma export` wrote it, "
      f"{passes} passes of {spp // passes} spp with independent seeds, and `raylemma compare` tests the passes "
      "against the committed reference `figures/reference/NAME.exr` at `--alpha 0.01` (the passes' spread is the "
      f"candidate's variance, {passes - 1} degrees of freedom; the reference's own, from its `spp`). The whole "
      "image's mean: the passes' minus the reference's, over the magnitude of the reference's (a channel is "
      "negative where a light lies outside the sRGB gamut, and meaningless as a ratio where it is near 0), with "
      "compare's z of that difference (positive: Mitsuba brighter). The brighter copy is the same passes times 1.03; the control is raylemma's own "
      f"{passes} renders of {spp // passes} spp with seeds 1000 to {999 + passes}, compared the same way. The "
      "`hdrfilm` row renders the same file with Mitsuba's own film in place of the exported `specfilm`. "
      "raylemma's time is its reference's render, from its JSON sidecar; the throughputs were measured at "
      "different times under different loads, so their ratio is indicative only.*")
def listed(f):
    return "; ".join(f"{c[0]}: {f(c)}" for c in compared)
record.claim(
    "every_expressible_scene_agrees_brighter_differs_control_close",
    all(c[1] == "agree" and c[4] == "differ" and c[5] == "agree" and abs(c[2] - c[6]) < 0.1
        for c in compared),
    "verdict, 3 % brighter, control, mean z² against the control's (within 0.1): "
    + listed(lambda c: f"{c[1]}, {c[4]}, {c[5]}, {c[2]:.3f} vs {c[6]:.3f}"))
record.number("not_exported", len(refused), "int")
record.claim("three_not_exported", len(refused) == 3,
             "not exported: " + ", ".join(s for s, _ in refused))
record.claim("cornell_mean_z2_above_one_in_both",
             any(c[0] == "cornell" for c in compared)
             and all(c[2] > 1 and c[6] > 1 for c in compared if c[0] == "cornell"),
             "cornell: " + "; ".join(f"{c[2]:.3f} and control {c[6]:.3f}" for c in compared if c[0] == "cornell"))
record.claim("others_mean_z2_below_one",
             all(c[2] < 1 for c in compared if c[0] != "cornell"),
             "mean z² of every scene but cornell below 1: " + listed(lambda c: f"{c[2]:.3f}"))
lps = [c for c in compared if c[0] == "lamps/low-pressure-sodium"]
record.claim("low_pressure_sodium_rmse_many_times_the_control",
             bool(lps) and lps[0][3] > 4 * lps[0][7],
             "low-pressure sodium: " + (f"RMSE {lps[0][3]:.3e} > 4 x control {lps[0][7]:.3e}" if lps else "not compared"))
record.write(root, "")
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
