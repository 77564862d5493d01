#!/usr/bin/env python3
"""Mitsuba 3 as a candidate of `raylemma conformance --format mitsuba`: renders one
exported scene once and writes one EXR, as a user of Mitsuba would save it.

    candidate.py SCENE.xml OUT.exr --spp N --seed S [--variant V] [--fault F]

The exported film is a specfilm whose channels are raylemma's CIE XYZ; the EXR keeps
them as channels X, Y, Z (which `raylemma compare` reads and converts itself). A fault
makes this a realistic wrong renderer, one mistake at a time, for the renderer chapter's
table of faults against verdicts:

    emitter-bright   every emitter's radiance 1 % too high
    wall-dark        the reflectance of the material "red" 2 % low (one wall of a box)
    depth-short      the maximum depth one short (Mitsuba's max_depth counts segments)
    gamma            the image converted to sRGB and saved gamma-encoded (R, G, B)
    fov              the camera's vertical field of view 0.5 degrees too wide

Run by tools/mitsuba/conformance.sh; the venv is tools/mitsuba/setup.sh's.
"""

import argparse
import re
import sys

import numpy as np
import drjit as dr
import mitsuba as mi

FAULTS = ["none", "emitter-bright", "wall-dark", "depth-short", "gamma", "fov"]


def faulty_text(text, fault):
    """The scene text with the fault written into it (faults of the scene description)."""
    if fault == "depth-short":
        def shorter(m):
            n = int(m.group(2))
            return m.group(1) + str(n - 1 if n > 0 else n) + m.group(3)
        text, n = re.subn(r'(<integer name="max_depth" value=")(-?\d+)(")', shorter, text)
        assert n == 1, "no max_depth in the exported scene"
    if fault == "fov":
        def wider(m):
            return m.group(1) + repr(float(m.group(2)) + 0.5) + m.group(3)
        text, n = re.subn(r'(<float name="fov" value=")([^"]+)(")', wider, text)
        assert n == 1, "no fov in the exported scene"
    if fault == "wall-dark":
        # The exporter writes `<!-- material "red" -->` before the material's BSDF.
        m = re.search(r'<!-- material "red" -->\s*<bsdf type="twosided" id="([^"]+)">', text)
        if m:
            block_start = m.end()
            block_end = text.index("</bsdf>\n    </bsdf>", block_start)
            block = text[block_start:block_end]

            def darker(v):
                values = [float(x) * 0.98 for x in v.group(2).split(",")]
                return v.group(1) + ", ".join(repr(x) for x in values) + v.group(3)
            block = re.sub(r'(<string name="values" value=")([^"]+)(")', darker, block)
            block = re.sub(r'(<spectrum name="reflectance" value=")([^"]+)(")', darker, block)
            text = text[:block_start] + block + text[block_end:]
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("xml")
    ap.add_argument("out")
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--seed", type=int, required=True)
    ap.add_argument("--variant", default="scalar_spectral")
    ap.add_argument("--fault", choices=FAULTS, default="none")
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args()
    if "spectral" not in args.variant:
        sys.exit(f"candidate.py: {args.variant} is not a spectral variant; the exported film needs one")

    mi.set_variant(args.variant)
    if args.threads > 0:
        dr.set_thread_count(args.threads)
    text = open(args.xml).read()
    # The header comment gives raylemma's matrix from XYZ to linear sRGB.
    rows = re.search(r"M = \[\[([^\]]+)\], \[([^\]]+)\], \[([^\]]+)\]\]", text)
    assert rows, "no XYZ-to-sRGB matrix in the exported scene's header"
    to_srgb = np.array([[float(x) for x in r.split(",")] for r in rows.groups()])
    scene = mi.load_string(faulty_text(text, args.fault), spp=args.spp)
    if args.fault == "emitter-bright":
        params = mi.traverse(scene)
        keys = [k for k in params.keys() if ".emitter.radiance." in k and k.endswith(("values", "value"))]
        assert keys, "no emitter radiance among the scene's parameters"
        for k in keys:
            params[k] = params[k] * 1.01
        params.update()
    img = mi.render(scene, spp=args.spp, seed=args.seed)
    dr.eval(img)
    xyz = np.array(img, dtype=np.float64)
    if not np.all(np.isfinite(xyz)):
        sys.exit("candidate.py: non-finite pixels")
    # Writing an EXR with no worker threads deadlocks in Mitsuba 3.9.1 (README).
    dr.set_thread_count(max(2, dr.thread_count()))
    if args.fault == "gamma":
        rgb = xyz @ to_srgb.T
        a = np.abs(rgb)
        enc = np.where(a <= 0.0031308, 12.92 * a, 1.055 * np.power(a, 1 / 2.4) - 0.055)
        out = (np.sign(rgb) * enc).astype(np.float32)
        mi.Bitmap(out, pixel_format=mi.Bitmap.PixelFormat.RGB).write(args.out)
    else:
        mi.Bitmap(xyz.astype(np.float32), pixel_format=mi.Bitmap.PixelFormat.XYZ).write(args.out)


if __name__ == "__main__":
    main()
