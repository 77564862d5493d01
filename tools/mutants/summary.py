"""Summarises cargo-mutants outcomes per group of modules (figures/mutants.md).

    summary.py OUT N

`outcomes` and `wilson` are shared with tools/mutants/render.sh's table. The numbers the book
quotes are recorded in figures/values.json (tools/values/values.py) as `mutants.*`.
"""
import json, math, os, sys
from collections import defaultdict

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools", "values"))
from values import Record  # noqa: E402

# The derivation modules, whose sample the chapter *Tests of the tests* scales up.
DERIVATIONS = ["src/sampling", "src/optics", "src/spectral", "src/transport"]


def outcomes(out):
    """Every mutant's outcome under OUT: (folder, file, summary, its name), in folder order."""
    for d in sorted(os.listdir(out)):
        path = os.path.join(out, d, "mutants.out", "outcomes.json")
        if not os.path.exists(path):
            continue
        for o in json.load(open(path))["outcomes"]:
            scenario = o.get("scenario")
            if not isinstance(scenario, dict) or "Mutant" not in scenario:
                continue  # the baseline
            m = scenario["Mutant"]
            line = m.get("span", {}).get("start", {}).get("line", "?")
            name = m.get("name") or f"{m['file']}:{line}: {m.get('replacement', '')}"
            yield d, m["file"], o["summary"], name


def wilson(k, t, z=1.96):
    if t == 0:
        return (float("nan"), float("nan"))
    p = k / t
    c = (p + z * z / (2 * t)) / (1 + z * z / t)
    h = z * math.sqrt(p * (1 - p) / t + z * z / (4 * t * t)) / (1 + z * z / t)
    return (c - h, c + h)

def row(name, s, which):
    caught, miss, to = s["CaughtMutant"], s["MissedMutant"], s["Timeout"]
    viable = caught + miss + to
    lo, hi = wilson(caught + to, viable)
    share = 100 * (caught + to) / max(viable, 1)
    return f"| {name} | {which} | {viable} | {caught} | {miss} | {to} | {s['Unviable']} | {share:.0f} % | {100*lo:.0f}–{100*hi:.0f} % |"

def main():
    out, n = sys.argv[1], int(sys.argv[2])
    groups = defaultdict(lambda: defaultdict(int))
    complete = set()
    missed = defaultdict(list)
    for d, file, summary, name in outcomes(out):
        group = "/".join(file.split("/")[:2])
        if d.endswith(".all"):
            complete.add(group)
        groups[group][summary] += 1
        if summary == "MissedMutant":
            missed[group].append(name)
    print("| modules | mutants | tested | caught | missed | timeouts | unviable | caught share | 95 % interval |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    order = ["src/sampling", "src/optics", "src/spectral", "src/transport", "src/check", "src/render"]
    for g in sorted(groups, key=lambda g: order.index(g) if g in order else len(order)):
        which = "every one" if g in complete else f"a sample, 1 in {n}" if n > 1 else "every one"
        print(row(f"`{g}/`", groups[g], which))
    print()
    shards = sorted({d.rsplit(".s", 1)[1] for d in os.listdir(out) if ".s" in d and not d.endswith(".all")}, key=int) or ["0"]
    print(f"*cargo-mutants. The derivations and checkers: {len(shards)} of every {n} mutants of each file "
          f"(`--shard K/{n}` for K in {', '.join(shards)}), each tested with its chapter's tests (the "
          "renderer's sample is tools/mutants/render.sh's own table). A timeout counts as caught (the "
          f"mutant made a test loop). Regenerate with `tools/mutants/run.sh {n} {' '.join(shards)}` "
          "in a clean checkout.*")
    for g in sorted(missed, key=lambda g: order.index(g) if g in order else len(order)):
        print()
        print(f"Surviving mutants of `{g}/`:")
        print()
        for m in missed[g]:
            print(f"- `{m}`")
    record = Record("mutants.md")
    sample = sum(sum(groups[g].values()) for g in DERIVATIONS)
    factor = n / len(shards)
    record.number("derivations.sample", sample, "int")
    record.number("derivations.sample_factor", factor, "int")
    record.number("derivations.estimated_total", sample * factor, "s2")
    record.write(ROOT, "")


if __name__ == "__main__":
    main()
