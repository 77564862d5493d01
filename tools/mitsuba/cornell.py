#!/usr/bin/env python3
"""Independent validation render of raylemma's Cornell box with Mitsuba 3.

Builds the scene as a Python dict (mi.load_dict), renders it with the
`scalar_spectral` variant in K independent passes (different seeds), and
writes one float32 OpenEXR with channels

    R, G, B             per-pixel mean, linear sRGB (Rec.709, D65)
    var.R, var.G, var.B variance of that mean (squared standard error):
                        sample variance across the K passes / K

plus a JSON sidecar (same stem, .json) with the timing. Row 0 is the top
of the image. See README.md next to this file for the conventions.

Run through run.sh (which makes the venv); directly:

    python cornell.py --spp 1024 --passes 16 --out /tmp/mitsuba/cornell.exr
"""

import argparse
import csv
import json
import os
import struct
import sys
import time

import numpy as np
import drjit as dr
import mitsuba as mi

VARIANT = "scalar_spectral"
REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CHANNELS = ["R", "G", "B", "var.R", "var.G", "var.B"]
SIZE = 256


# --------------------------------------------------------------------------
# Data


def default_data_dir():
    """`data/` of the repo if it holds the Cornell tables, else ../shared/data/."""
    for d in (os.path.join(REPO, "data"), os.path.join(REPO, "..", "shared", "data")):
        if os.path.isfile(os.path.join(d, "cornell_box_reflectance.csv")) and os.path.isfile(
            os.path.join(d, "cornell_box_light.csv")
        ):
            return os.path.abspath(d)
    sys.exit("cornell.py: no cornell_box_*.csv in data/ or ../shared/data/; pass --data DIR")


def read_csv(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].lstrip().startswith("#")]
    header, body = rows[0], rows[1:]
    cols = {name.strip(): [float(r[i]) for r in body] for i, name in enumerate(header)}
    wl = cols[header[0].strip()]
    if any(b <= a for a, b in zip(wl, wl[1:])):
        sys.exit(f"cornell.py: {path}: wavelengths not strictly increasing")
    return header[0].strip(), cols


def irregular(wavelengths, values):
    """Piecewise-linear spectrum; Mitsuba's `irregular` is 0 outside its range."""
    return {
        "type": "irregular",
        "wavelengths": ", ".join(repr(float(w)) for w in wavelengths),
        "values": ", ".join(repr(float(v)) for v in values),
    }


def load_spectra(data_dir):
    key, refl = read_csv(os.path.join(data_dir, "cornell_box_reflectance.csv"))
    wl = refl[key]
    spectra = {name: irregular(wl, refl[name]) for name in ("white", "red", "green")}
    lkey, light = read_csv(os.path.join(data_dir, "cornell_box_light.csv"))
    spectra["light"] = irregular(light[lkey], light["radiance"])
    return spectra


# --------------------------------------------------------------------------
# Scene


def quad(centre, u, v):
    """Mitsuba `rectangle` ([-1,1]^2 in local xy, normal +z) mapped to
    centre + s*u + t*v, s,t in [-1,1]; the normal is along u x v."""
    u, v, c = np.asarray(u, float), np.asarray(v, float), np.asarray(centre, float)
    n = np.cross(u, v)
    n /= np.linalg.norm(n)
    m = np.identity(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = u, v, n, c
    return mi.ScalarTransform4f(m.tolist())


def twosided_diffuse(spectrum):
    return {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": spectrum}}


def scene_dict(spectra, spp):
    L, h = 555.0, 277.5  # box side, half side
    white = twosided_diffuse(spectra["white"])
    return {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": -1},  # rr_depth: default (5)
        "sensor": {
            "type": "perspective",
            "fov": 39.3077,
            "fov_axis": "y",
            # Mitsuba's look_at puts camera +x = up x dir = world +x (for
            # dir +z, up +y) on the LEFT of the image: red wall (x = 555)
            # on the left, as wanted. Verified on the rendered image.
            "to_world": mi.ScalarTransform4f().look_at(
                origin=[278.0, 273.0, -800.0], target=[278.0, 273.0, 0.0], up=[0.0, 1.0, 0.0]
            ),
            "sampler": {"type": "independent", "sample_count": spp},
            "film": {
                "type": "hdrfilm",
                "width": SIZE,
                "height": SIZE,
                "pixel_format": "rgb",
                "component_format": "float32",
                "rfilter": {"type": "box"},
            },
        },
        # Walls: full 555 x 555 faces, normals pointing into the box
        # (irrelevant for shading since they are two-sided).
        "floor": {"type": "rectangle", "to_world": quad([h, 0, h], [0, 0, h], [h, 0, 0]), "bsdf": white},
        "ceiling": {"type": "rectangle", "to_world": quad([h, L, h], [h, 0, 0], [0, 0, h]), "bsdf": white},
        "back": {"type": "rectangle", "to_world": quad([h, h, L], [0, h, 0], [h, 0, 0]), "bsdf": white},
        "red": {
            "type": "rectangle",
            "to_world": quad([L, h, h], [0, 0, h], [0, h, 0]),
            "bsdf": twosided_diffuse(spectra["red"]),
        },
        "green": {
            "type": "rectangle",
            "to_world": quad([0, h, h], [0, h, 0], [0, 0, h]),
            "bsdf": twosided_diffuse(spectra["green"]),
        },
        # Light: one-sided (Mitsuba's area emitter emits on the normal side
        # only), normal -y, x 213..343, z 227..332 at y = 554; black BSDF.
        "light": {
            "type": "rectangle",
            "to_world": quad([278.0, 554.0, 279.5], [65.0, 0, 0], [0, 0, 52.5]),
            "bsdf": {"type": "diffuse", "reflectance": {"type": "uniform", "value": 0.0}},
            "emitter": {"type": "area", "radiance": spectra["light"]},
        },
        "mirror": {
            "type": "sphere",
            "center": [390.0, 100.0, 370.0],
            "radius": 100.0,
            "bsdf": {"type": "conductor", "material": "none"},  # reflectance exactly 1
        },
        "glass": {
            "type": "sphere",
            "center": [170.0, 100.0, 190.0],
            "radius": 100.0,
            # ext_ior must be given: Mitsuba's default is air, 1.000277.
            "bsdf": {"type": "dielectric", "int_ior": 1.5, "ext_ior": 1.0},
        },
    }


def check_scene(scene):
    """Cheap self-checks: the light faces down, emits on that side only, and
    its spectrum reaches Mitsuba unscaled (8 at 500 nm, 15.6 at 600 nm)."""
    wl = mi.Spectrum([450.0, 500.0, 600.0, 650.0])
    up, down = mi.Vector3f(0, 1, 0), mi.Vector3f(0, -1, 0)
    si = scene.ray_intersect(mi.Ray3f(mi.Point3f(278.0, 300.0, 280.0), up, 0.0, wl))
    assert si.is_valid() and abs(si.t - 254.0) < 1e-3, si.t
    assert si.emitter(scene) is not None
    assert abs(si.n[1] + 1.0) < 1e-6, f"light normal {si.n}, want -y"
    below = si.emitter(scene).eval(si)
    want = [4.0, 8.0, 15.6, 17.0]
    assert all(abs(float(below[i]) - want[i]) < 1e-4 for i in range(4)), below
    # Between light and ceiling, looking down at the light's back: no emission.
    si_up = scene.ray_intersect(mi.Ray3f(mi.Point3f(278.0, 554.5, 280.0), down, 0.0, wl))
    assert abs(si_up.t - 0.5) < 1e-3 and si_up.emitter(scene) is not None
    above = si_up.emitter(scene).eval(si_up)
    assert all(float(above[i]) == 0.0 for i in range(4)), above
    # Glass: relative IOR exactly 1.5 (so ext_ior = 1, not air's 1.000277).
    params = mi.traverse(scene)
    assert float(params["glass.bsdf.eta"]) == 1.5, params["glass.bsdf.eta"]
    # Mirror: reflectance exactly 1, at normal and at oblique incidence.
    ctx = mi.BSDFContext()
    for dy in (0.0, 60.0, 95.0):  # incidence 0, 37 and 72 degrees
        o = mi.Point3f(390.0, 100.0 + dy, 100.0)
        si = scene.ray_intersect(mi.Ray3f(o, mi.Vector3f(0, 0, 1), 0.0, wl))
        assert si.is_valid() and si.shape.id() == "mirror", si
        _, w = si.bsdf().sample(ctx, si, 0.5, mi.Point2f(0.5, 0.5))
        assert all(float(w[i]) == 1.0 for i in range(4)), w


def check_spectra(spectra):
    """Every table is zero outside 400-700 nm and exact at its knots."""
    outside = mi.Spectrum([360.0, 399.9, 700.1, 830.0])
    si = dr.zeros(mi.SurfaceInteraction3f)
    for name, d in spectra.items():
        tex = mi.load_dict(d)
        si.wavelengths = outside
        v = tex.eval(si)
        assert all(float(v[i]) == 0.0 for i in range(4)), (name, v)
        knots = [float(w) for w in d["wavelengths"].split(",")]
        vals = [float(x) for x in d["values"].split(",")]
        si.wavelengths = mi.Spectrum([knots[0], knots[1], knots[-2], knots[-1]])
        v = tex.eval(si)
        want = [vals[0], vals[1], vals[-2], vals[-1]]
        assert all(abs(float(v[i]) - want[i]) < 1e-5 for i in range(4)), (name, v, want)


def y_scale():
    """Factor that makes a constant spectrum 1 come out with luminance Y = 1.

    Mitsuba divides by MI_CIE_Y_NORMALIZATION = 1/106.7502594, but its own
    CIE 1931 y-bar table (linear between knots, 360-830 nm) integrates to
    106.857, so unscaled it gives Y = 1.000999 for a constant 1. Linear in
    the image, so mean and variance (times its square) are scaled after the
    render.
    """
    wl = np.arange(mi.MI_CIE_MIN, mi.MI_CIE_MAX + 1e-9, 0.125)
    ybar = np.array([float(mi.cie1931_y(float(w))) for w in wl])
    return 1.0 / (np.trapezoid(ybar, wl) * mi.MI_CIE_Y_NORMALIZATION)


# --------------------------------------------------------------------------
# EXR header check (no OpenEXR module needed)


def exr_channels(path):
    """(name, pixel_type) of each channel in an EXR header; type 2 = float32."""
    with open(path, "rb") as f:
        data = f.read(1 << 16)
    assert struct.unpack("<I", data[:4])[0] == 20000630, "not an OpenEXR file"
    pos = 8
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        end2 = data.index(b"\0", end + 1)
        typ = data[end + 1 : end2].decode()
        (size,) = struct.unpack("<i", data[end2 + 1 : end2 + 5])
        value = data[end2 + 5 : end2 + 5 + size]
        pos = end2 + 5 + size
        if name == "channels" and typ == "chlist":
            out, p = [], 0
            while value[p] != 0:
                e = value.index(b"\0", p)
                (ptype,) = struct.unpack("<i", value[e + 1 : e + 5])
                out.append((value[p:e].decode(), ptype))
                p = e + 1 + 16
            return out
    raise ValueError("no channels attribute")


# --------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--spp", type=int, default=1024, help="total samples per pixel (default 1024)")
    ap.add_argument("--passes", type=int, default=16, help="independent passes K (default 16)")
    ap.add_argument("--out", required=True, help="output .exr (a .json sidecar is written next to it)")
    ap.add_argument("--data", default=None, help="directory with cornell_box_{reflectance,light}.csv")
    ap.add_argument("--threads", type=int, default=0, help="render threads (default: all cores)")
    ap.add_argument("--seed", type=int, default=0, help="seed of pass 0; pass k uses seed+k")
    ap.add_argument("--png", default=None, help="also write an sRGB-encoded, clipped 8-bit PNG preview")
    ap.add_argument(
        "--mitsuba-y",
        action="store_true",
        help="keep Mitsuba's own luminance scale (constant 1 -> Y = 1.000999) instead of Y = 1",
    )
    args = ap.parse_args()

    K, spp = args.passes, args.spp
    if K < 2 or spp % K != 0:
        sys.exit(f"cornell.py: need passes >= 2 dividing spp (spp={spp}, passes={K})")
    per_pass = spp // K

    mi.set_variant(VARIANT)
    threads = args.threads if args.threads > 0 else os.cpu_count()
    dr.set_thread_count(threads)
    threads = dr.thread_count()

    data_dir = os.path.abspath(args.data) if args.data else default_data_dir()
    print(f"mitsuba {mi.__version__} {VARIANT}; data from {data_dir}; {threads} thread(s)", flush=True)
    spectra = load_spectra(data_dir)
    check_spectra(spectra)
    scene = mi.load_dict(scene_dict(spectra, per_pass))
    check_scene(scene)

    passes = np.zeros((K, SIZE, SIZE, 3))
    seconds = cpu_seconds = 0.0
    for k in range(K):
        t0, c0 = time.perf_counter(), time.process_time()
        img = mi.render(scene, spp=per_pass, seed=args.seed + k)
        seconds += time.perf_counter() - t0
        cpu_seconds += time.process_time() - c0
        a = np.array(img, dtype=np.float64)
        assert a.shape == (SIZE, SIZE, 3), a.shape
        if not np.all(np.isfinite(a)):
            sys.exit(f"cornell.py: non-finite pixels in pass {k}")
        passes[k] = a
        print(f"pass {k + 1}/{K}: {per_pass} spp, {seconds:.1f} s so far", flush=True)

    # Writing an EXR with no worker threads (--threads 1) deadlocks in Mitsuba
    # 3.9.1: give the pool a worker back now that the timed part is over.
    dr.set_thread_count(max(2, threads))

    scale = 1.0 if args.mitsuba_y else y_scale()
    mean = passes.mean(axis=0) * scale
    # Unbiased sample variance of the K pass means, / K: variance of the mean.
    var = passes.var(axis=0, ddof=1) / K * scale**2
    out = np.concatenate([mean, var], axis=2).astype(np.float32)

    os.makedirs(os.path.dirname(os.path.abspath(args.out)) or ".", exist_ok=True)
    bmp = mi.Bitmap(out, pixel_format=mi.Bitmap.PixelFormat.MultiChannel, channel_names=CHANNELS)
    bmp.write(args.out)

    # Read it back: channel names and float32 from the header, values through Mitsuba.
    chans = exr_channels(args.out)
    names = sorted(c for c, _ in chans)
    assert names == sorted(CHANNELS), chans
    assert all(t == 2 for _, t in chans), f"not all float32: {chans}"
    back = mi.Bitmap(args.out)
    arr = np.array(back)
    order = [f.name for f in back.struct_()]
    for i, c in enumerate(CHANNELS):
        assert np.array_equal(arr[:, :, order.index(c)], out[:, :, i]), f"channel {c} differs on read-back"

    pss = SIZE * SIZE * spp / seconds
    sidecar = {
        "renderer": f"mitsuba {mi.__version__} {VARIANT}",
        "spp": spp,
        "passes": K,
        "seconds": round(seconds, 3),
        "pixel_samples_per_second": round(pss, 1),
        "threads": threads,
        # CPU time of all threads while rendering: with the machine to itself,
        # about seconds * threads; much less when other work shares the cores.
        "cpu_seconds": round(cpu_seconds, 3),
        "scene": "cornell",
        # Applied to Mitsuba's output so that a constant spectrum 1 has Y = 1.
        "y_scale": float(scale),
    }
    stem = os.path.splitext(args.out)[0]
    with open(stem + ".json", "w") as f:
        json.dump(sidecar, f, indent=2)
        f.write("\n")

    if args.png:
        c = np.clip(mean, 0.0, 1.0)
        srgb = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
        png = mi.Bitmap((np.round(srgb * 255)).astype(np.uint8), pixel_format=mi.Bitmap.PixelFormat.RGB)
        png.write(args.png)

    print(f"wrote {args.out} ({', '.join(c for c, _ in chans)}; float32) and {stem}.json")
    m = mean.reshape(-1, 3).mean(axis=0)
    print(f"mean R G B = {m[0]:.6f} {m[1]:.6f} {m[2]:.6f}")
    print(
        f"{spp} spp in {seconds:.2f} s ({cpu_seconds:.2f} s CPU): "
        f"{pss:.4g} pixel samples/s on {threads} thread(s)"
    )


if __name__ == "__main__":
    main()
