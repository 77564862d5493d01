"""Summarises cargo-mutants outcomes per module group (figures/mutants.md)."""
import json, math, os, sys
from collections import defaultdict

out, n = sys.argv[1], int(sys.argv[2])
groups = defaultdict(lambda: defaultdict(int))
missed = []
for d in sorted(os.listdir(out)):
    path = os.path.join(out, d, "mutants.out", "outcomes.json")
    if not os.path.exists(path):
        continue
    for o in json.load(open(path))["outcomes"]:
        scenario = o.get("scenario")
        if not isinstance(scenario, dict) or "Mutant" not in scenario:
            continue  # the baseline
        m = scenario["Mutant"]
        file = m["file"]
        group = file.split("/")[1]
        summary = o["summary"]
        groups[group][summary] += 1
        if summary == "MissedMutant":
            line = m.get("span", {}).get("start", {}).get("line", "?")
            missed.append(m.get("name") or f"{file}:{line}: {m.get('replacement', '')}")

def wilson(k, t, z=1.96):
    if t == 0:
        return (float("nan"), float("nan"))
    p = k / t
    c = (p + z * z / (2 * t)) / (1 + z * z / t)
    h = z * math.sqrt(p * (1 - p) / t + z * z / (4 * t * t)) / (1 + z * z / t)
    return (c - h, c + h)

print("| modules | mutants tested | caught | missed | timeouts | unviable | caught share | 95 % interval |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
tot = defaultdict(int)
for g in sorted(groups):
    s = groups[g]
    for k, v in s.items():
        tot[k] += v
    caught, miss, to = s["CaughtMutant"], s["MissedMutant"], s["Timeout"]
    viable = caught + miss + to
    lo, hi = wilson(caught + to, viable)
    print(f"| `src/{g}/` | {viable} | {caught} | {miss} | {to} | {s['Unviable']} | {100*(caught+to)/max(viable,1):.0f} % | {100*lo:.0f}–{100*hi:.0f} % |")
caught, miss, to = tot["CaughtMutant"], tot["MissedMutant"], tot["Timeout"]
viable = caught + miss + to
lo, hi = wilson(caught + to, viable)
print(f"| **all four** | {viable} | {caught} | {miss} | {to} | {tot['Unviable']} | {100*(caught+to)/max(viable,1):.0f} % | {100*lo:.0f}–{100*hi:.0f} % |")
print()
shards = sorted({d.rsplit(".s", 1)[1] for d in os.listdir(out) if ".s" in d}, key=int) or ["0"]
print(f"*cargo-mutants, {len(shards)} of every {n} mutants of each file (`--shard K/{n}` for K in {', '.join(shards)}), each tested with its chapter's test file and the unit tests; a timeout counts as caught (the mutant made a test loop). Regenerate with `tools/mutants/run.sh {n} {' '.join(shards)}`.*")
print()
if missed:
    print("Surviving mutants:")
    print()
    for m in missed:
        print(f"- `{m}`")
