#!/usr/bin/env python3
"""Render a scene exported by `raylemma export --to mitsuba` with Mitsuba 3, in K
independent passes, as K plain linear-sRGB EXRs: what `raylemma compare REF.exr
PASS-*.exr` takes as its candidate (their spread is the candidate's variance).

    render.py SCENE.xml --json SCENE.json --spp 1024 --passes 16 --out DIR/NAME

writes DIR/NAME-00.exr ... DIR/NAME-15.exr (channels R, G, B, float32, row 0 at the
top) and DIR/NAME-mitsuba.json (timing). The XML's film is a specfilm whose channels
X, Y, Z are raylemma's CIE XYZ; the XYZ -> linear sRGB matrix is read from the scene's
JSON export (conventions.xyz_to_linear_srgb), so the colour conversion is raylemma's
own, bit for bit the same matrix. Nothing in the scene is rebuilt here: the XML is
loaded as exported.

--film hdrfilm swaps the exported specfilm for Mitsuba's own hdrfilm (its 5 nm CIE
table, its Y normalisation, its rounded matrix; linear sRGB straight from Mitsuba): the
renderer chapter's demonstration of what that colour conversion does to a comparison.
"""

import argparse
import json
import math
import os
import re
import sys
import time

import numpy as np
import drjit as dr
import mitsuba as mi


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("xml", help="the scene, from `raylemma export SCENE --to mitsuba`")
    ap.add_argument("--json", required=True, help="the same scene from `raylemma export SCENE --to json`")
    ap.add_argument("--spp", type=int, default=1024, help="total samples per pixel (default 1024)")
    ap.add_argument("--passes", type=int, default=16, help="independent passes K (default 16)")
    ap.add_argument("--out", required=True, help="output stem: STEM-00.exr ... and STEM-mitsuba.json")
    ap.add_argument("--seed", type=int, default=0, help="seed of the first pass (default 0)")
    ap.add_argument("--threads", type=int, default=0, help="render threads (default: all cores)")
    ap.add_argument("--variant", default="scalar_spectral", help="a spectral variant (default scalar_spectral)")
    ap.add_argument("--png", default=None, help="also write the mean as a clipped sRGB 8-bit PNG preview")
    ap.add_argument("--film", choices=["specfilm", "hdrfilm"], default="specfilm",
                    help="specfilm: as exported (raylemma's colour); hdrfilm: Mitsuba's own colour conversion")
    args = ap.parse_args()

    K, spp = args.passes, args.spp
    if K < 2 or spp % K != 0:
        sys.exit(f"render.py: need passes >= 2 dividing spp (spp={spp}, passes={K})")
    per_pass = spp // K
    if "spectral" not in args.variant:
        sys.exit(f"render.py: {args.variant} is not a spectral variant; the exported film needs one")

    mi.set_variant(args.variant)
    threads = args.threads if args.threads > 0 else os.cpu_count()
    dr.set_thread_count(threads)
    threads = dr.thread_count()

    with open(args.json) as f:
        resolved = json.load(f)
    assert resolved["format"] == "raylemma-scene", resolved.get("format")
    to_srgb = np.array(resolved["conventions"]["xyz_to_linear_srgb"], dtype=np.float64)
    width, height = resolved["camera"]["width"], resolved["camera"]["height"]

    if args.film == "specfilm":
        scene = mi.load_file(args.xml, spp=per_pass)
    else:
        text = open(args.xml).read()
        hdr = (f'<film type="hdrfilm"><integer name="width" value="{width}"/>'
               f'<integer name="height" value="{height}"/><string name="pixel_format" value="rgb"/>'
               '<string name="component_format" value="float32"/><rfilter type="box"/></film>')
        text, n = re.subn(r'<film type="specfilm">.*?</film>', hdr, text, flags=re.S)
        assert n == 1, "no specfilm in the exported scene"
        scene = mi.load_string(text, spp=per_pass)
    # Mitsuba's scalar renderer seeds the samplers of pass s from s and the pixel index
    # (s * 65536 + i, tools/mitsuba/README.md): space the passes' seeds so that no two
    # passes share a pixel seed, whatever the image size.
    stride = max(1, math.ceil(width * height / 65536))

    print(f"mitsuba {mi.__version__} {args.variant}; {args.xml}; {K} x {per_pass} spp; {threads} thread(s)", flush=True)
    seconds = cpu_seconds = 0.0
    mean = np.zeros((height, width, 3))
    paths = []
    for k in range(K):
        t0, c0 = time.perf_counter(), time.process_time()
        img = mi.render(scene, spp=per_pass, seed=args.seed + stride * k)
        # The llvm_* variants evaluate lazily: the render is done only once evaluated.
        dr.eval(img)
        dr.sync_thread()
        seconds += time.perf_counter() - t0
        cpu_seconds += time.process_time() - c0
        out = np.array(img, dtype=np.float64)
        assert out.shape == (height, width, 3), out.shape
        if not np.all(np.isfinite(out)):
            sys.exit(f"render.py: non-finite pixels in pass {k}")
        if k == 0:
            names = [f.name for f in scene.sensors()[0].film().bitmap().struct_()]
            want = ["X", "Y", "Z"] if args.film == "specfilm" else ["R", "G", "B"]
            assert names[:3] == want, f"the film's channels are {names}, not {want}"
        # specfilm: raylemma's XYZ, converted with raylemma's matrix; hdrfilm: Mitsuba's sRGB.
        rgb = out @ to_srgb.T if args.film == "specfilm" else out
        mean += rgb / K
        # Writing an EXR with no worker threads deadlocks in Mitsuba 3.9.1 (README).
        dr.set_thread_count(max(2, threads))
        path = f"{args.out}-{k:02d}.exr"
        mi.Bitmap(rgb.astype(np.float32), pixel_format=mi.Bitmap.PixelFormat.RGB).write(path)
        dr.set_thread_count(threads)
        paths.append(path)
        print(f"pass {k + 1}/{K}: {seconds:.1f} s so far", flush=True)

    sidecar = {
        "renderer": f"mitsuba {mi.__version__} {args.variant}",
        "film": args.film,
        "scene": args.xml,
        "spp": spp,
        "passes": K,
        "seconds": round(seconds, 3),
        "cpu_seconds": round(cpu_seconds, 3),
        "threads": threads,
        "pixel_samples_per_second": round(width * height * spp / seconds, 1),
        "passes_files": [os.path.basename(p) for p in paths],
    }
    with open(f"{args.out}-mitsuba.json", "w") as f:
        json.dump(sidecar, f, indent=2)
        f.write("\n")
    if args.png:
        c = np.clip(mean, 0.0, 1.0)
        srgb = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
        dr.set_thread_count(max(2, threads))
        mi.Bitmap(np.round(srgb * 255).astype(np.uint8), pixel_format=mi.Bitmap.PixelFormat.RGB).write(args.png)
    print(f"{spp} spp in {seconds:.2f} s ({cpu_seconds:.2f} s CPU) on {threads} thread(s); wrote {K} EXRs {args.out}-NN.exr")


if __name__ == "__main__":
    main()
