#!/usr/bin/env python3
"""The table of tools/mitsuba/speed.sh: reads its work folder and prints
figures/mitsuba_speed.md (medians over the rounds, the machine, the verdicts of
`raylemma compare`, and the sentences that compare the renderers, made from the medians),
and with --machines FILE puts this machine's line into the table of every machine measured
(figures/mitsuba_speed_machines.md), replacing an earlier line of the same machine.

    speed.py WORK --spp 256 --res 256 --runs 3 --passes 16 [--png MEAN.png] [--machines FILE]

Efficiency is 1 / (mean per-pixel variance of the pixel's mean x render seconds): the
variance is raylemma's own var.R, var.G, var.B channels (the variance of each pixel's
mean, from its samples), and for Mitsuba the spread of its independent passes divided by
their number; both are unbiased estimates of the same quantity, averaged over the pixels
and the three channels.
"""

import argparse
import datetime
import glob
import json
import os
import re
import statistics
import sys

import numpy as np
import mitsuba as mi

mi.set_variant("scalar_rgb")

VARIANTS = ["scalar_spectral", "llvm_ad_spectral"]


def read_exr(path):
    bmp = mi.Bitmap(path)
    names = [f.name for f in bmp.struct_()]
    return names, np.array(bmp, dtype=np.float64)


def ours_variance(path):
    names, a = read_exr(path)
    idx = [names.index(c) for c in ("var.R", "var.G", "var.B")]
    return float(a[:, :, idx].mean())


def theirs_variance_and_mean(stem):
    files = sorted(glob.glob(f"{stem}-[0-9]*.exr"))
    stack = []
    for f in files:
        names, a = read_exr(f)
        stack.append(a[:, :, [names.index(c) for c in ("R", "G", "B")]])
    stack = np.stack(stack)
    k = stack.shape[0]
    return float((stack.var(axis=0, ddof=1) / k).mean()), stack.mean(axis=0), k


def process(path):
    wall, kib = open(path).read().split()[-2:]
    return float(wall), int(kib)


def machine(work):
    """The machine as the figure job names it (`raylemma-figures machine`, written by
    speed.sh), so that the fingerprint is the one of every other timing caption."""
    return open(f"{work}/machine").read().strip()


def fmt_ratio(x):
    return f"{x:.2f}×"


GOAL = 2.0  # the efficiency raylemma should have, against Mitsuba's fastest CPU variant

MACHINES_HEAD = [
    "| machine | fingerprint | date | raylemma s | fastest Mitsuba variant, s | "
    "throughput ratio | efficiency ratio of the medians (range over rounds) | "
    f"at least {GOAL:.0f}× in efficiency |",
    "|---|---|---|---:|---:|---:|---:|---|",
]


def put_machine_line(path, fingerprint, line):
    """Rewrites the table of every machine measured at `path` with `line` in place of the
    line of the machine `fingerprint` (or added), keeping the other machines' lines and the
    text under the table."""
    rows, tail = [], []
    if os.path.exists(path):
        lines = open(path).read().splitlines()
        body = [l for l in lines[len(MACHINES_HEAD):] if l.startswith("| ")]
        tail = [l for l in lines[len(MACHINES_HEAD):] if not l.startswith("| ")]
        rows = [l for l in body if f"| `{fingerprint}` |" not in l]
    rows.append(line)
    text = "\n".join(MACHINES_HEAD + rows + tail).rstrip("\n") + "\n"
    tmp = path + ".tmp"
    open(tmp, "w").write(text)
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("work")
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--res", type=int, required=True)
    ap.add_argument("--runs", type=int, required=True)
    ap.add_argument("--passes", type=int, required=True)
    ap.add_argument("--png", default=None)
    ap.add_argument("--machines", default=None)
    a = ap.parse_args()
    w = a.work
    pixels = a.res * a.res

    rows = {}
    mean_images = {}
    name = {}
    for who in ["raylemma"] + VARIANTS:
        secs, var, walls, rss, threads = [], [], [], [], set()
        for r in range(1, a.runs + 1):
            d = f"{w}/r{r}/{who}"
            if who == "raylemma":
                side = json.load(open(f"{d}/cornell.json"))
                assert side["spp"] == a.spp, side
                var.append(ours_variance(f"{d}/cornell.exr"))
            else:
                side = json.load(open(f"{d}/cornell-mitsuba.json"))
                assert side["spp"] == a.spp, side
                v, m, k = theirs_variance_and_mean(f"{d}/cornell")
                assert k == a.passes, (k, a.passes)
                var.append(v)
                if r == 1:
                    mean_images[who] = m
            name[who] = side["renderer"]
            threads.add(side["threads"])
            secs.append(side["seconds"])
            wall, kib = process(f"{d}/process")
            walls.append(wall)
            rss.append(kib)
        med = statistics.median(secs)
        mvar = statistics.median(var)
        effs = [1.0 / (v * s) for v, s in zip(var, secs)]
        rows[who] = dict(
            seconds=med, lo=min(secs), hi=max(secs), throughput=pixels * a.spp / med,
            variance=mvar, efficiency=statistics.median(effs), wall=statistics.median(walls),
            rss=max(rss) / 1024, threads=",".join(str(t) for t in sorted(threads)),
            effs=effs)

    verdict = {}
    for v in VARIANTS:
        status = int(open(f"{w}/compare-{v}.status").read())
        text = open(f"{w}/compare-{v}.txt").read()
        line = next((l for l in text.splitlines() if l.startswith("RMSE")), "")
        m = re.match(r"RMSE (\S+); mean z\^2 (\S+)", line)
        verdict[v] = (status, f"RMSE {m.group(1)}, mean z² {m.group(2)}" if m else line)

    print("| renderer | threads | render seconds, median (range) | pixel samples / s | "
          "mean variance of a pixel's mean | efficiency, 1 / (variance × s) | process wall s | "
          "peak memory (MiB) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for who in ["raylemma"] + VARIANTS:
        r = rows[who]
        print(f"| {name[who]} | {r['threads']} | {r['seconds']:.2f} ({r['lo']:.2f}–{r['hi']:.2f}) | "
              f"{r['throughput']:.3e} | {r['variance']:.3e} | {r['efficiency']:.1f} | "
              f"{r['wall']:.1f} | {r['rss']:.0f} |")
    print()
    print("| raylemma against | throughput ratio | efficiency ratio | `raylemma compare` of the images |")
    print("|---|---:|---:|---|")
    for v in VARIANTS:
        t = rows["raylemma"]["throughput"] / rows[v]["throughput"]
        e = rows["raylemma"]["efficiency"] / rows[v]["efficiency"]
        status, mz = verdict[v]
        word = {0: "agree", 1: "DIFFER"}.get(status, "error")
        print(f"| {name[v]} | {fmt_ratio(t)} | {fmt_ratio(e)} | {word} ({mz}) |")
    print()
    fast = max(VARIANTS, key=lambda v: rows[v]["throughput"])
    t_fast = rows["raylemma"]["throughput"] / rows[fast]["throughput"]
    e_fast = rows["raylemma"]["efficiency"] / rows[fast]["efficiency"]
    # Round by round (the renderers ran one after the other in each round), so that a
    # drift of the machine's speed between rounds does not widen the range.
    by_round = [o / t for o, t in zip(rows["raylemma"]["effs"], rows[fast]["effs"])]
    print(f"On this machine raylemma renders `cornell` {fmt_ratio(t_fast)} as many pixel samples "
          f"per second as Mitsuba's fastest CPU variant here, `{fast.split()[-1]}`, "
          f"and its efficiency, which also counts the noise each sample leaves, is "
          f"{fmt_ratio(e_fast)} Mitsuba's (round by round from {fmt_ratio(min(by_round))} to "
          f"{fmt_ratio(max(by_round))}).")
    print()
    print(f"*`tools/mitsuba/speed.sh {a.spp} {a.res} {a.runs} {a.passes}`: `cornell` at "
          f"{a.res}×{a.res}, {a.spp} samples per pixel, Russian roulette from depth 5 in both "
          f"(`roulette_depth = 5`, exported as `rr_depth` 5), the same maximum depth; each "
          f"renderer on all cores, one after the other, {a.runs} rounds after an untimed warm-up "
          f"(in which Dr.Jit compiles and caches its kernels); the medians of the rounds. "
          f"Mitsuba renders {a.passes} independent passes of {a.spp // a.passes} samples, whose "
          f"spread is its variance; its render seconds are those of `mi.render` with the "
          f"result evaluated, raylemma's those of its render, the scene's loading left out for "
          f"both (the process column has everything, Python's start-up included). Peak memory "
          f"is the process's maximum resident set. Machine: {machine(w)}.*")

    if a.machines:
        mach = machine(w)
        fp = re.search(r"fingerprint (\w+)", mach)
        assert fp, mach
        status, _ = verdict[fast]
        met = ("yes" if min(by_round) >= GOAL else
               "no" if max(by_round) < GOAL else "not in every round")
        if status == 1:
            met = "no verdict: the images differ"
        elif status != 0:
            met = "no verdict: compare failed"
        # The processor as the figure job names it: up to its "(family ...)" where it has
        # one (x86), else up to the first comma (other architectures).
        named = re.match(r"^(.*?\(family [^)]*\))", mach)
        cpu = named.group(1) if named else mach.split(",")[0]
        day = datetime.datetime.now(datetime.timezone.utc).date().isoformat()
        put_machine_line(a.machines, fp.group(1), (
            f"| {cpu} | `{fp.group(1)}` | {day} | {rows['raylemma']['seconds']:.2f} | "
            f"{rows[fast]['seconds']:.2f} (`{fast}`) | {fmt_ratio(t_fast)} | "
            f"{fmt_ratio(e_fast)} ({fmt_ratio(min(by_round))}–{fmt_ratio(max(by_round))}) | "
            f"{met} |"))

    if a.png:
        m = mean_images[fast]
        c = np.clip(m, 0.0, 1.0)
        srgb = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
        mi.Bitmap(np.round(srgb * 255).astype(np.uint8),
                  pixel_format=mi.Bitmap.PixelFormat.RGB).write(a.png)


if __name__ == "__main__":
    sys.exit(main())
