#!/usr/bin/env python3
"""raylemma's prediction of what an RGB renderer makes of a scene, and how far that is from
the spectral reference: the number that explains a Cycles (or LuxCore) disagreement on a rung
with coloured spectra.

    predict_rgb.py SCENE.json PREDICTION.exr [--spp N] [--seed S] [--work DIR]

An RGB renderer whose materials are diagonal (each channel scattered on its own, as Lambert,
mirror and glass are) is three independent grey renderers, one a channel. So channel c of
its image is what raylemma renders when every reflectance is the constant rgb_c that
candidate.py gives Cycles and every emitter the constant L_c / E_c (L_c the light's linear
sRGB, E_c that of the equal-energy light, so that raylemma's flat light comes out as L_c in
channel c). This writes those three grey scenes as raylemma TOML, renders each once, and
writes channel c of the c-th render, with its variance channel, into PREDICTION.exr. Then

    raylemma compare REFERENCE.exr PREDICTION.exr     what the RGB product costs
    raylemma compare PREDICTION.exr CANDIDATE-*.exr   whether the candidate is that RGB image

A renderer that clamps negative colours to 0 (Cycles: the linear sRGB of a sodium lamp has a
negative blue) is predicted with --clamp-negative.

Needs numpy and OpenEXR (setup.sh installs both), and raylemma on the PATH or in $RAYLEMMA.
"""

import argparse
import json
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from candidate import Colour, DEFAULT_CMF  # noqa: E402


def vec(v):
    return "[" + ", ".join(repr(float(x)) for x in v) + "]"


def grey_toml(data, reflectances, emissions, environment):
    """The scene as raylemma TOML with every spectrum replaced by a constant."""
    r, c = data["render"], data["camera"]
    lines = ["[render]", f"spp = {r['spp']}", f"seed = {r['seed']}",
             f'wavelengths = "{r["wavelengths"]}"', f"roulette_depth = {r['roulette_depth']}",
             f"max_depth = {r['max_depth']}", "",
             "[camera]", f"position = {vec(c['position'])}", f"look_at = {vec(c['look_at'])}",
             f"up = {vec(c['up'])}", f"fov_y = {c['fov_y_deg']!r}",
             f"resolution = [{c['width']}, {c['height']}]", "", "[materials]"]
    for m, value in zip(data["materials"], reflectances):
        name = f'm{data["materials"].index(m)}'
        if m["type"] == "lambert":
            lines.append(f'{name} = {{ type = "lambert", reflectance = {value!r} }}')
        elif m["type"] == "mirror":
            lines.append(f'{name} = {{ type = "mirror" }}')
        elif m["type"] == "dielectric" and m.get("ior") is not None:
            lines.append(f'{name} = {{ type = "dielectric", ior = {m["ior"]!r} }}')
        else:
            sys.exit(f'predict_rgb.py: material "{m["name"]}" has no RGB counterpart')
    if environment is not None:
        lines += ["", "[environment]", f"emission = {environment!r}"]
    for s in data["shapes"]:
        lines += ["", "[[shape]]", f'type = "{s["type"]}"']
        lines += geometry(s)
        lines.append(f'material = "m{s["material"]}"')
    for light, value in zip(data["lights"], emissions):
        lines += ["", "[[light]]", f'type = "{light["type"]}"']
        lines += geometry(light)
        lines.append(f"emission = {value!r}")
    return "\n".join(lines) + "\n"


def geometry(s):
    if s["type"] == "quad":
        return [f"corner = {vec(s['corner'])}", f"edge1 = {vec(s['edge1'])}", f"edge2 = {vec(s['edge2'])}"]
    return [f"center = {vec(s['center'])}", f"radius = {s['radius']!r}"]


def read_channels(path):
    """An EXR's channels by name, each an (h, w) float64 array, and its header."""
    import OpenEXR
    with OpenEXR.File(path, separate_channels=True) as f:
        channels = {k: np.array(v.pixels, dtype=np.float64) for k, v in f.channels().items()}
        return channels, dict(f.header())


def write_prediction(path, rgb, var, header):
    """The prediction as raylemma writes a render: R, G, B and var.R, var.G, var.B, with the
    header (its spp) of one channel's render, so that `raylemma compare` takes it as a
    reference."""
    import OpenEXR
    channels = {}
    for c, name in enumerate("RGB"):
        channels[name] = rgb[:, :, c].astype(np.float32)
        channels["var." + name] = var[:, :, c].astype(np.float32)
    keep = {k: header[k] for k in ("compression", "spp") if k in header}
    with OpenEXR.File(keep, channels) as f:
        f.write(path)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json")
    ap.add_argument("out", help="the prediction: an EXR with variance channels")
    ap.add_argument("--spp", type=int, default=4096)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--work", default=os.path.join(os.environ.get("TMPDIR", "/tmp"), "raylemma-rgb-prediction"))
    ap.add_argument("--cmf", default=DEFAULT_CMF)
    ap.add_argument("--clamp-negative", action="store_true",
                    help="predict a renderer that clamps negative colours to 0 (Cycles does, in an Emission shader)")
    args = ap.parse_args()
    raylemma = os.environ.get("RAYLEMMA", "raylemma")

    data = json.load(open(args.json))
    colour = Colour(data["conventions"], args.cmf)
    reflectance = [colour.reflectance(m["reflectance"]) if m["type"] == "lambert" else np.ones(3)
                   for m in data["materials"]]
    emission = [colour.radiance(light["emission"]) / colour.flat_rgb for light in data["lights"]]
    env = data.get("environment")
    env_rgb = None if env is None else colour.radiance(env["radiance"]) / colour.flat_rgb
    if args.clamp_negative:
        reflectance = [np.maximum(r, 0) for r in reflectance]
        emission = [np.maximum(e, 0) for e in emission]
        env_rgb = None if env_rgb is None else np.maximum(env_rgb, 0)

    os.makedirs(args.work, exist_ok=True)
    rgb, var, header = [], [], None
    for c, name in enumerate("RGB"):
        # A saturated light (a sodium lamp) has a negative channel in linear sRGB; raylemma's
        # emission is not negative, but the image is linear in the emission: render its
        # magnitude and give the channel the sign back, when every emitter has the same one.
        lights = [float(e[c]) for e in emission] + ([] if env_rgb is None else [float(env_rgb[c])])
        sign = -1.0 if any(v < 0 for v in lights) else 1.0
        if any(v * sign < 0 for v in lights):
            sys.exit(f"predict_rgb.py: the emitters' channel {name} has both signs")
        toml = os.path.join(args.work, f"channel-{name}.toml")
        open(toml, "w").write(grey_toml(
            data, [float(r[c]) for r in reflectance], [sign * float(e[c]) for e in emission],
            None if env_rgb is None else sign * float(env_rgb[c])))
        subprocess.run([raylemma, "render", toml, "--out", args.work, "--spp", str(args.spp),
                        "--seed", str(args.seed)], check=True, stdout=subprocess.DEVNULL)
        channels, header = read_channels(os.path.join(args.work, f"channel-{name}.exr"))
        rgb.append(sign * channels[name])
        var.append(channels["var." + name])
    write_prediction(args.out, np.stack(rgb, axis=-1), np.stack(var, axis=-1), header)


if __name__ == "__main__":
    main()
