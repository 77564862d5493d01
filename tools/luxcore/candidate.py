#!/usr/bin/env python3
"""LuxCoreRender as a candidate of `raylemma conformance --format json`: builds a LuxCore
scene from raylemma's JSON export with pyluxcore, renders it once with PATHCPU and writes one
EXR of linear sRGB (R, G, B), as a user of LuxCore would save it.

    candidate.py SCENE.json OUT.exr --spp N --seed S

LuxCore renders in RGB; every spectrum becomes linear sRGB exactly as for Cycles
(tools/blender/candidate.py's Colour, imported from there: emissions their linear sRGB,
reflectances relative to the equal-energy light). What LuxCore is told:

    film.filter            BOX of width 0.5 (LuxCore's width is a radius: one pixel)
    sampler                RANDOM, adaptive strength 0 (every pixel gets N samples)
    path.clamping          off (variance clamping 0)
    path depths            total, diffuse, glossy and specular all max_depth + 1 (LuxCore
                           counts vertices, raylemma bounces; see README.md)
    lightstrategy          POWER (unbiased, as the default LOG_POWER)
    quad light             a matte of reflectance 0 with emission = the radiance, gain 1
                           (no power, no efficacy: the colour is the radiance); LuxCore's
                           triangle lights emit on the front face only; light sampling
                           ENABLED (AUTO turns it off for meshes of more than 256 triangles)
    sphere                 an icosphere, as for Cycles (--sphere-subdivisions, default 6)
    screen window          moved up one pixel row: LuxCore 2.11.2 renders one row low

Features LuxCore cannot express here (Sellmeier dispersion, raylemma's thin film, a gradient
sky) stop the script with a message naming them.
"""

import argparse
import array
import json
import math
import os
import sys
import time

# numpy and OpenEXR before pyluxcore: imported after it, either aborts the interpreter
# ("free(): invalid pointer"; the wheels bundle clashing copies of shared libraries).
import numpy as np
import OpenEXR

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "blender"))
from candidate import Colour, DEFAULT_CMF, Unsupported  # noqa: E402


def icosphere(centre, radius, subdivisions):
    """Vertices and triangles of an icosphere whose area is 4 pi r^2, outward winding."""
    t = (1 + math.sqrt(5)) / 2
    vertices = [np.array(v, dtype=float) for v in [
        (-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
        (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    vertices = [v / np.linalg.norm(v) for v in vertices]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                v = vertices[a] + vertices[b]
                vertices.append(v / np.linalg.norm(v))
                middle[key] = len(vertices) - 1
            return middle[key]
        faces = [f for a, b, c in faces
                 for f in ((a, mid(a, b), mid(c, a)), (b, mid(b, c), mid(a, b)),
                           (c, mid(c, a), mid(b, c)), (mid(a, b), mid(b, c), mid(c, a)))]
    v = np.array(vertices)
    f = np.array(faces)
    area = 0.5 * np.linalg.norm(np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]), axis=1).sum()
    v = np.asarray(centre) + v * radius * math.sqrt(4 * math.pi / area)
    normals = (v - np.asarray(centre)) / np.linalg.norm(v - np.asarray(centre), axis=1)[:, None]
    return v, f, normals


# Subdivisions of a sphere's icosphere; candidate.py --sphere-subdivisions sets it.
SPHERE_SUBDIVISIONS = 6


def mesh(shape):
    """Vertices, triangles and (for spheres) vertex normals of a shape."""
    if shape["type"] == "quad":
        c, e1, e2 = (np.array(shape[k]) for k in ("corner", "edge1", "edge2"))
        return np.array([c, c + e1, c + e1 + e2, c + e2]), np.array([(0, 1, 2), (0, 2, 3)]), None
    if shape["type"] == "sphere":
        return icosphere(shape["center"], shape["radius"], SPHERE_SUBDIVISIONS)
    raise Unsupported(f"shape type {shape['type']}")


def rgb_text(v):
    return " ".join(repr(float(x)) for x in v)


def material_props(m, colour):
    p = f"scene.materials.{m['name']}"
    if m["type"] == "lambert":
        return [f"{p}.type = matte", f"{p}.kd = {rgb_text(colour.reflectance(m['reflectance']))}"]
    if m["type"] == "mirror":
        return [f"{p}.type = mirror", f"{p}.kr = 1 1 1"]
    if m["type"] == "dielectric":
        if m.get("sellmeier"):
            raise Unsupported(f'material "{m["name"]}": Sellmeier dispersion (one index for all wavelengths in RGB)')
        return [f"{p}.type = glass", f"{p}.kr = 1 1 1", f"{p}.kt = 1 1 1",
                f"{p}.interiorior = {m['ior']!r}", f"{p}.exteriorior = 1"]
    raise Unsupported(f'material "{m["name"]}": type {m["type"]}')


def build(data, colour, spp, seed):
    import pyluxcore
    camera = data["camera"]
    r = data["render"]
    if data.get("environment") is not None:
        raise Unsupported("an environment (not written for LuxCore yet)")
    # LuxCore's path.pathdepth.* count path vertices (surface hits), raylemma's max_depth
    # counts bounces (the JSON's render.max_depth_counts): LuxCore adds emission found at
    # vertices 0..D-1 and samples lights at vertices 0..D-2 (at vertex 0 also when D = 1, but
    # then it samples no direction), so raylemma's max_depth d is LuxCore's D = d + 1
    # (pathtracer.cpp, PathDepthInfo). README.md.
    if not r.get("max_depth_counts", "bounces").startswith("bounces"):
        raise Unsupported(f"max_depth counts {r['max_depth_counts']!r}, not bounces")
    depth = r["max_depth"] + 1
    config = [
        "renderengine.type = PATHCPU", f"renderengine.seed = {seed % (2 ** 31 - 1) + 1}",
        "sampler.type = RANDOM", "sampler.random.adaptive.strength = 0",
        f"batch.haltspp = {spp}", "batch.halttime = 0", "batch.haltthreshold = -1",
        f"film.width = {camera['width']}", f"film.height = {camera['height']}",
        "film.filter.type = BOX", "film.filter.width = 0.5",
        f"path.pathdepth.total = {depth}", f"path.pathdepth.diffuse = {depth}",
        f"path.pathdepth.glossy = {depth}", f"path.pathdepth.specular = {depth}",
        "path.clamping.variance.maxvalue = 0", "path.forceblackbackground.enable = 0",
        "path.hybridbackforward.enable = 0", "lightstrategy.type = POWER",
        "film.outputs.0.type = RGB", "film.outputs.0.filename = unused.exr",
    ]
    s = [
        "scene.camera.type = perspective",
        f"scene.camera.lookat.orig = {rgb_text(camera['position'])}",
        f"scene.camera.lookat.target = {rgb_text(camera['look_at'])}",
        f"scene.camera.up = {rgb_text(camera['up'])}",
        f"scene.camera.fieldofview = {camera['fov_y_deg']!r}",
    ]
    # LuxCore 2.11.2 renders the image one pixel row low against the pinhole model (rung 1:
    # its rows r + 1 are the reference's rows r to 0.01 %): the screen window is moved up by
    # one pixel (2 / height in screen units) to undo it. README.md, "Surprises".
    aspect = camera["width"] / camera["height"]
    dy = 2 / camera["height"]
    s.append(f"scene.camera.screenwindow = {-aspect!r} {aspect!r} {-1 - dy!r} {1 - dy!r}")
    for m in data["materials"]:
        s += material_props(m, colour)
    scene = pyluxcore.Scene()
    objects = []
    for i, shape in enumerate(data["shapes"]):
        objects.append((f"shape{i}", shape, data["materials"][shape["material"]]["name"]))
    for i, light in enumerate(data["lights"]):
        name = f"light{i}"
        s += [f"scene.materials.{name}.type = matte", f"scene.materials.{name}.kd = 0 0 0",
              f"scene.materials.{name}.emission = {rgb_text(colour.radiance(light['emission']))}",
              f"scene.materials.{name}.emission.gain = 1 1 1",
              # AUTO (the default) turns light sampling off for a mesh of more than 256
              # triangles (TriangleLight::IsDirectLightSamplingEnabled): the icosphere.
              f"scene.materials.{name}.emission.directlightsampling.type = ENABLED"]
        objects.append((name, light, name))
    for name, shape, material in objects:
        v, f, n = mesh(shape)
        scene.DefineMesh(name + "_mesh", [tuple(x) for x in v], [tuple(int(i) for i in t) for t in f],
                         None if n is None else [tuple(x) for x in n], None, None, None)
        s += [f"scene.objects.{name}.shape = {name}_mesh", f"scene.objects.{name}.material = {material}"]
    scene.Parse(pyluxcore.Properties().SetFromString("\n".join(s) + "\n"))
    return pyluxcore.RenderConfig(pyluxcore.Properties().SetFromString("\n".join(config) + "\n"), scene)


def write_exr(path, image):
    channels = {c: image[:, :, i].astype(np.float32) for i, c in enumerate("RGB")}
    with OpenEXR.File({"compression": OpenEXR.ZIP_COMPRESSION}, channels) as f:
        f.write(path)


def main():
    global SPHERE_SUBDIVISIONS
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json")
    ap.add_argument("out")
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--seed", type=int, required=True)
    ap.add_argument("--cmf", default=DEFAULT_CMF)
    ap.add_argument("--sphere-subdivisions", type=int, default=SPHERE_SUBDIVISIONS)
    args = ap.parse_args()
    SPHERE_SUBDIVISIONS = args.sphere_subdivisions
    data = json.load(open(args.json))
    if data.get("format") != "raylemma-scene" or data.get("version") != 1:
        sys.exit(f"candidate.py: {args.json} is not a version 1 raylemma-scene JSON export")
    import pyluxcore
    pyluxcore.Init()
    try:
        config = build(data, Colour(data["conventions"], args.cmf), args.spp, args.seed)
    except Unsupported as e:
        sys.exit(f"candidate.py: LuxCore cannot express this scene: {e}")
    session = pyluxcore.RenderSession(config)
    session.Start()
    # The halt condition (batch.haltspp) is checked when the statistics are updated: a
    # session nobody asks for statistics renders for ever (WaitForDone alone never returns).
    while not session.HasDone():
        time.sleep(0.05)
        session.UpdateStats()
    session.Stop()
    film = session.GetFilm()
    w, h = data["camera"]["width"], data["camera"]["height"]
    buffer = array.array("f", [0.0]) * (w * h * 3)
    film.GetOutputFloat(pyluxcore.FilmOutputType.RGB, buffer)
    # LuxCore's film rows run from the bottom up.
    image = np.frombuffer(buffer, dtype=np.float32).reshape(h, w, 3)[::-1]
    if not np.all(np.isfinite(image)):
        sys.exit("candidate.py: non-finite pixels")
    write_exr(args.out, image)


if __name__ == "__main__":
    main()
