#!/usr/bin/env bash
# The conformance ladder tried on real renderers (the renderer chapter's table of faults):
# raylemma itself, Mitsuba 3's scalar_spectral and llvm_ad_spectral variants through
# tools/mitsuba/candidate.py, and Mitsuba with one realistic fault at a time (candidate.py
# --fault), each through `raylemma conformance`. Writes figures/conformance_faults.md and its
# named values into figures/values.json.
#
#     tools/mitsuba/conformance.sh [SPP [RUNS]]      (default 256 spp, 4 runs a rung)
#     tools/mitsuba/conformance.sh --table [SPP [RUNS]]  (the table again from the last run's cards)
#
# The correct renderers run every rung; the faults run rungs 1-5, where each shows first.
# Work files: ${TMPDIR:-/tmp}/raylemma-conformance. The caption gives the wall time.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
source "$root/tools/adapters.sh"
ladder_options 256 "$@"
work="${TMPDIR:-/tmp}/raylemma-conformance"
venv="${RAYLEMMA_MITSUBA_VENV:-/root/.cache/raylemma-mitsuba-venv}"
bash "$root/tools/mitsuba/setup.sh" --no-test >&2
py="$venv/bin/python"
raylemma="$(raylemma_release "$root")"
if [ "$table_only" = 0 ]; then
rm -rf "$work"
mkdir -p "$work"

card() { # NAME FORMAT RUNGS RENDERER
    local name=$1 format=$2 rungs=$3 renderer=$4
    local args=(conformance --format "$format" --spp "$spp" --runs "$runs"
        --work "$work/$name" --json "$work/$name.json" --renderer "$renderer")
    [ -n "$rungs" ] && args+=(--rungs "$rungs")
    echo "== $name ($(date -u +%H:%M:%S))" >&2
    local t0
    t0=$(date +%s)
    (cd "$root" && "$raylemma" "${args[@]}" > "$work/$name.txt" 2> "$work/$name.log") || true
    echo "$name $(( $(date +%s) - t0 ))" >> "$work/seconds.txt"
    tail -n 3 "$work/$name.txt" >&2
}

candidate="$py $root/tools/mitsuba/candidate.py {scene} {out} --spp {spp} --seed {seed}"
card raylemma toml "" "$raylemma render {scene} --out {outdir} --spp {spp} --seed {seed}"
card scalar_spectral mitsuba "" "$candidate --variant scalar_spectral"
card llvm_ad_spectral mitsuba "" "$candidate --variant llvm_ad_spectral"
for fault in emitter-bright wall-dark depth-short gamma fov; do
    card "fault-$fault" mitsuba 1,2,3,4,5 "$candidate --variant scalar_spectral --fault $fault"
done
fi

"$py" - "$root" "$work" "$spp" "$runs" <<'PY'
import json, os, platform, sys
root, work, spp, runs = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
sys.path.insert(0, os.path.join(root, "tools", "values"))
from values import Record

def cpu():
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            return line.split(":", 1)[1].strip()
    return platform.processor()

record = Record("conformance_faults.md")
# What each fault must be found as: the first failing rung and depth (None: the rung's own)
# and a phrase of the card's first finding.
faults = {
    "emitter-bright": ("every emitter's radiance 1 % too high", 1, None, "a uniform factor"),
    "wall-dark": ("the red wall's reflectance 2 % low", 4, 1, 'material "red"'),
    "depth-short": ("the maximum depth one short", 1, None, "a maximum depth counted one bounce short"),
    "gamma": ("the image saved gamma-encoded", 1, None, "gamma-encoded"),
    "fov": ("the field of view 0.5° too wide", 1, None, "the camera"),
}
seconds = dict(line.split() for line in open(f"{work}/seconds.txt"))
# The rungs the Mitsuba export refuses, from the ladder: the spectral-only ones.
spectral_only = {10, 11}
rows = []

def load(name):
    return json.load(open(f"{work}/{name}.json"))

def first(card):
    for r in card["rungs"]:
        if r["verdict"] in ("differ", "error"):
            return r
    return None

def depth(r):
    return "own depth" if r["depth"] is None else f"depth {r['depth']}"

def counts(card):
    v = [r["verdict"] for r in card["rungs"]]
    return {k: v.count(k) for k in ("agree", "differ", "error", "skipped")}

lines = ["| candidate | fault | comparisons: agree / differ / error / skipped | first failing rung | its relative difference (R, G, B) | the card's first finding | points at the fault |",
         "|---|---|---|---|---|---|---|"]
passes = {}
for name, label in [("raylemma", "raylemma"), ("scalar_spectral", "Mitsuba `scalar_spectral`"),
                    ("llvm_ad_spectral", "Mitsuba `llvm_ad_spectral`")]:
    card = load(name)
    c = counts(card)
    f = first(card)
    passes[name] = f is None and c["agree"] > 0
    skipped = {r["rung"] for r in card["rungs"] if r["verdict"] == "skipped"}
    if name != "raylemma":
        record.claim(f"{name}_skips_exactly_the_spectral_rungs", skipped == spectral_only,
                     f"{name} skipped rungs {sorted(skipped)}")
    where = "none" if f is None else f"rung {f['rung']}, {depth(f)}"
    lines.append(f"| {label} | none | {c['agree']} / {c['differ']} / {c['error']} / {c['skipped']} | {where} | | | |")
    record.number(f"{name}.agree", c["agree"], "int")
    record.number(f"{name}.skipped", c["skipped"], "int")
pointed = {}
for fault, (what, rung, at, phrase) in faults.items():
    card = load(f"fault-{fault}")
    c = counts(card)
    f = first(card)
    if f is None:
        lines.append(f"| Mitsuba `scalar_spectral` | {what} | {c['agree']} / {c['differ']} / {c['error']} / {c['skipped']} | none | | | **no** |")
        pointed[fault] = False
        continue
    rel = f.get("relative_difference")
    rel = ", ".join(f"{100 * x['value']:+.2f} %" for x in rel) if rel else ""
    finding = (f.get("diagnosis") or [""])[0]
    ok = f["rung"] == rung and f["depth"] == at and phrase in finding
    pointed[fault] = ok
    # The finding without what undoing it left and without its list of usual causes.
    short = finding
    if ": undoing" in finding:
        short = finding.split(": undoing")[0]
        if short.endswith(")") and " (" in short:
            short = short[: short.rindex(" (")]
    lines.append(f"| Mitsuba `scalar_spectral` | {what} | {c['agree']} / {c['differ']} / {c['error']} / {c['skipped']} | rung {f['rung']}, {depth(f)} | {rel} | {short} | {'yes' if ok else '**no**'} |")
record.claim("raylemma_and_both_variants_pass", all(passes.values()),
             "; ".join(f"{k}: {'passes' if v else 'fails'}" for k, v in passes.items()))
record.claim("every_fault_found_where_expected", all(pointed.values()),
             "; ".join(f"{k}: {'yes' if v else 'no'}" for k, v in pointed.items()))
record.number("faults", len(faults), "int")
record.number("spp", spp, "int")
record.number("runs", runs, "int")
total = sum(int(v) for v in seconds.values())
record.number("minutes", total / 60, "int")
caption = (f"*`tools/mitsuba/conformance.sh {spp} {runs}` on {cpu()}, {os.cpu_count()} cores, "
           f"{total / 60:.0f} minutes of wall time in all: each candidate "
           f"through `raylemma conformance` with {runs} runs of {spp} spp per rung and depth, at `--alpha 0.01` "
           "for the whole card. raylemma reads the TOML, Mitsuba 3.9.1 the exported XML through "
           "`tools/mitsuba/candidate.py`, which writes the film's X, Y, Z as an EXR. The faults are "
           "`candidate.py --fault NAME` on rungs 1-5. A fault *points at itself* when the card's first failing "
           "rung and depth are the first that contain it and the card's first finding names it.*")
table = "\n".join(lines) + "\n\n" + caption + "\n"
open(os.path.join(root, "figures", "conformance_faults.md"), "w").write(table)
record.write(root, table)
print(table)
PY
