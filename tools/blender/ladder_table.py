#!/usr/bin/env python3
"""The book's table of an RGB renderer on the conformance ladder, from a card that
`raylemma conformance --format json --json CARD.json --work WORK` wrote: each rung and depth,
its verdict against the spectral reference, and for each that differs raylemma's prediction
of the RGB image (predict_rgb.py) with the two comparisons that explain the difference:

    the cost of RGB     the reference against the prediction: the block (16 x 16 pixels) and
                        channel where RGB moves furthest from the spectral answer, predicted
                        (on a grey rung, where the renderer moves furthest: RGB costs nothing)
    the residual        `raylemma compare PREDICTION.exr RUN-*.exr`: whether the renderer's
                        images are that RGB image within noise

    ladder_table.py --name NAME --label LABEL --card CARD.json --work WORK --figure FILE.md
                    --caption TEXT [--prediction-spp N]

Writes figures/FILE.md and its named values (tools/values/values.py's Record). Run by
conformance.sh, with raylemma on the PATH or in $RAYLEMMA.
"""

import argparse
import json
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tools", "values"))
from predict_rgb import read_channels  # noqa: E402
from values import Record  # noqa: E402

BLOCK = 16


def rgb(path):
    channels, _ = read_channels(path)
    return np.stack([channels[c] for c in "RGB"], axis=-1)


def blocks(image):
    """Means of 16 x 16 blocks: (h / 16, w / 16, 3)."""
    h, w, _ = image.shape
    return image.reshape(h // BLOCK, BLOCK, w // BLOCK, BLOCK, 3).mean(axis=(1, 3))


def stem(comparison):
    name = os.path.splitext(os.path.basename(comparison["scene"]))[0]
    return name if comparison["depth"] is None else f"{name}-depth{comparison['depth']}"


def depth(comparison):
    return "own" if comparison["depth"] is None else str(comparison["depth"])


def explain(comparison, work, spp, raylemma, clamp_negative):
    """Predict the RGB image of a differing comparison and measure the two comparisons."""
    name = stem(comparison)
    here = os.path.join(work, name)
    reference = os.path.join(ROOT, "figures", "reference", "conformance", name + ".exr")
    prediction = os.path.join(work, "prediction", name + ".exr")
    os.makedirs(os.path.dirname(prediction), exist_ok=True)
    if not os.path.exists(prediction):  # kept from an earlier run of this card
        subprocess.run([sys.executable, os.path.join(HERE, "predict_rgb.py"), os.path.join(here, "scene.json"),
                        prediction, "--spp", str(spp), "--work", os.path.join(work, "prediction", name)]
                       + (["--clamp-negative"] if clamp_negative else []),
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    runs = sorted(os.path.join(here, d, "scene.exr") for d in os.listdir(here) if d.startswith("run-"))
    residual = subprocess.run([raylemma, "compare", prediction, *runs], capture_output=True, text=True)
    ref, pred = blocks(rgb(reference)), blocks(rgb(prediction))
    measured = blocks(np.mean([rgb(r) for r in runs], axis=0))
    # Blocks the reference has black (the sky, a light's back) have no relative difference.
    lit = np.abs(ref) > 1e-6
    cost = np.where(lit, pred / np.where(lit, ref, 1) - 1, 0)
    off = np.where(lit, measured / np.where(lit, ref, 1) - 1, 0)
    # Where the prediction moves furthest; for grey scenes (the prediction is the reference
    # itself: the same scene, seed and spp) where the renderer does.
    worst = cost if np.any(cost) else off
    y, x, c = np.unravel_index(np.argmax(np.abs(worst)), worst.shape)
    return {
        "block": (int(x) * BLOCK, int(y) * BLOCK),
        "channel": "RGB"[c],
        "predicted": float(cost[y, x, c]),
        "measured": float(off[y, x, c]),
        "residual_agrees": residual.returncode == 0,
        "residual_line": next((l for l in residual.stdout.splitlines() if l.startswith("whole image, candidate")), ""),
    }


def reason(comparison, work):
    """What the adapter said when it refused a rung."""
    log = os.path.join(work, stem(comparison), "run-1", "log.txt")
    try:
        lines = [l for l in open(log).read().splitlines() if "cannot express" in l]
    except FileNotFoundError:
        lines = []
    if lines:
        return lines[-1].split("cannot express this scene: ", 1)[-1]
    return comparison.get("detail", "")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    for a in ("--name", "--label", "--card", "--work", "--figure", "--caption"):
        ap.add_argument(a, required=True)
    ap.add_argument("--prediction-spp", type=int, default=4096)
    ap.add_argument("--clamp-negative", action="store_true", help="the renderer clamps negative colours (predict_rgb.py)")
    args = ap.parse_args()
    raylemma = os.environ.get("RAYLEMMA", "raylemma")
    card = json.load(open(args.card))
    record = Record(args.figure)
    lines = [f"| rung | depth | {args.label} against the spectral reference | whole image (R, G, B) | "
             "where RGB moves furthest: block, channel | RGB − spectral there: predicted by raylemma | measured | "
             f"{args.label} against raylemma's RGB prediction |",
             "|---|---|---|---|---|---|---|---|"]
    counts = {"agree": 0, "differ": 0, "error": 0, "explained": 0}
    for comparison in card["rungs"]:
        verdict = comparison["verdict"]
        counts[verdict] = counts.get(verdict, 0) + 1
        rung, d = comparison["rung"], depth(comparison)
        if verdict == "error":
            lines.append(f"| {rung} | {d} | not expressed: {reason(comparison, args.work)} | | | | | |")
            continue
        rel = comparison.get("relative_difference") or []
        whole = ", ".join(f"{100 * r['value']:+.2f} %" for r in rel)
        if verdict == "agree":
            lines.append(f"| {rung} | {d} | agrees | {whole} | | | | |")
            continue
        try:
            e = explain(comparison, args.work, args.prediction_spp, raylemma, args.clamp_negative)
        except subprocess.CalledProcessError as failed:
            lines.append(f"| {rung} | {d} | differs | {whole} | no prediction: {' '.join(failed.cmd[:2])} failed | | | |")
            continue
        counts["explained"] += e["residual_agrees"]
        x, y = e["block"]
        lines.append(f"| {rung} | {d} | differs | {whole} | ({x}, {y}), {e['channel']} | "
                     f"{100 * e['predicted']:+.2f} % | {100 * e['measured']:+.2f} % | "
                     f"{'agrees' if e['residual_agrees'] else '**differs**'} |")
        key = f"rung{rung}_depth{d}"
        record.number(f"{key}.predicted", 100 * e["predicted"], ".2")
        record.number(f"{key}.measured", 100 * e["measured"], ".2")
    for k in ("agree", "differ", "error", "explained"):
        record.number(k, counts[k], "int")
    record.claim("every_difference_is_the_rgb_product", counts["differ"] == counts["explained"],
                 f"{counts['explained']} of {counts['differ']} differing comparisons agree with raylemma's RGB prediction")
    record.claim("every_expressed_rung_agrees_or_is_explained", counts["differ"] == counts["explained"] and counts["agree"] > 0,
                 f"{counts['agree']} agree, {counts['differ']} differ, {counts['explained']} of them explained")
    table = "\n".join(lines) + "\n\n" + args.caption + "\n"
    open(os.path.join(ROOT, "figures", args.figure), "w").write(table)
    record.write(ROOT, table)
    print(table)


if __name__ == "__main__":
    main()
