#!/usr/bin/env python3
"""Blender's Cycles as a candidate of `raylemma conformance --format json`: builds a Cycles
scene from raylemma's JSON export, renders it once on the CPU and writes one EXR of linear
sRGB (channels R, G, B, float32), as a user of Blender would save it.

    candidate.py SCENE.json OUT.exr --spp N --seed S [--threads T] [--blend FILE]

Cycles renders in RGB (its working space, Linear Rec.709, is linear sRGB), so every spectrum
becomes three numbers here:

    an emitted radiance L(nm)      its linear sRGB, M XYZ(L), XYZ as raylemma integrates it
                                   (the 1 nm CIE 1931 table, both linear between knots,
                                   divided by the table's integral of y-bar)
    a reflectance R(nm)            the linear sRGB of R under the equal-energy light, divided
                                   channel by channel by that of the light itself, so that
                                   a grey R = c is (c, c, c) and one bounce of a flat light
                                   off R gives exactly the spectral answer

What Cycles is told, and why (README.md has the longer account):

    pixel filter           a box one pixel wide (raylemma: each sample uniform in its pixel)
    clamping               direct and indirect off (Cycles clamps indirect at 10 by default)
    light threshold        0 (Cycles ignores lights below 0.01 by default)
    light tree             off (either is unbiased; off is the plainer estimator)
    adaptive sampling,     off: every pixel gets exactly N samples, nothing is filtered
    denoising, guiding
    filter glossy          0 (Cycles blurs sharp reflections after a diffuse bounce by default)
    bounces                max_depth - 1 in every kind: Cycles counts scattering events after
                           the camera hit, raylemma every bounce including it (the JSON's
                           render.max_depth_counts: 1 is direct light only, Cycles' 0)
    quad light             an emissive mesh, black on its back face (a Mix shader driven by
                           Backfacing), emission sampling "front": radiance = Emission
                           strength, no unit conversion (Emission strength 1 is radiance 1)
    sphere                 an icosphere (6 subdivisions, smooth shading) whose radius is grown
                           so that its area is the sphere's, 4 pi r^2

Features Cycles cannot express (Sellmeier dispersion, a thin film with raylemma's varying
thickness, a gradient sky) stop the script with a message naming the feature, which the card
then reports for that rung.
"""

import argparse
import json
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_CMF = os.path.join(HERE, "..", "..", "data", "cie1931_2deg_cmf_1nm.csv")


class Unsupported(Exception):
    """A scene feature that Cycles cannot express."""


# ---------------------------------------------------------------------------------------
# Colour: spectra to linear sRGB, integrated as raylemma does.

def load_cmf(path):
    """The CIE 1931 table: wavelengths (nm) and an (n, 3) array of x-bar, y-bar, z-bar."""
    table = np.loadtxt(path, delimiter=",", skiprows=1)
    return table[:, 0], table[:, 1:4]


def spectrum_xyz(spec, cmf, y_integral):
    """The XYZ of a spectrum given on whole nanometres (linear between, zero outside), the
    integral of two piecewise-linear functions done exactly, divided by y_integral."""
    cmf_nm, cmf_values = cmf
    nm = np.asarray(spec["nm"], dtype=float)
    values = np.asarray(spec["values"], dtype=float)
    if len(nm) == 0:
        return np.zeros(3)
    if np.any(np.abs(nm - np.round(nm)) > 1e-9) or np.any(np.diff(nm) != 1):
        raise Unsupported("a spectrum not on the 1 nm grid")
    # The spectrum on the table's grid, zero where it is not given.
    s = np.zeros(len(cmf_nm))
    index = (nm - cmf_nm[0]).astype(int)
    keep = (index >= 0) & (index < len(cmf_nm))
    s[index[keep]] = values[keep]
    s0, s1 = s[:-1, None], s[1:, None]
    c0, c1 = cmf_values[:-1], cmf_values[1:]
    # The integral over [0, 1] of (s0 + t ds)(c0 + t dc).
    ds, dc = s1 - s0, c1 - c0
    per_nm = s0 * c0 + (s0 * dc + ds * c0) / 2 + ds * dc / 3
    return per_nm.sum(axis=0) / y_integral


class Colour:
    """raylemma's conversions, from the JSON export's conventions and the CIE table."""

    def __init__(self, conventions, cmf_path):
        self.cmf = load_cmf(cmf_path)
        self.y_integral = conventions["y_integral"]
        self.to_srgb = np.array(conventions["xyz_to_linear_srgb"])
        flat = {"nm": list(range(360, 831)), "values": [1.0] * 471}
        self.flat_rgb = self.radiance(flat)

    def radiance(self, spec):
        """The linear sRGB of an emitted radiance."""
        return self.to_srgb @ spectrum_xyz(spec, self.cmf, self.y_integral)

    def reflectance(self, spec):
        """The linear sRGB of a reflectance: under the equal-energy light, relative to it."""
        if spec.get("kind") == "constant":
            return np.full(3, spec["value"])
        return self.radiance(spec) / self.flat_rgb


# ---------------------------------------------------------------------------------------
# The Cycles scene.

def settings(scene, render, camera, spp, seed, threads):
    """Render settings: everything that would bias or smooth the estimate is off."""
    import bpy
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = spp
    cycles.seed = seed % (2 ** 31)
    cycles.use_animated_seed = False
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.use_guiding = False
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.light_sampling_threshold = 0.0
    cycles.use_light_tree = False
    cycles.blur_glossy = 0.0
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    if not render.get("max_depth_counts", "bounces").startswith("bounces"):
        raise Unsupported(f"max_depth counts {render['max_depth_counts']!r}, not bounces")
    bounces = render["max_depth"] - 1
    if bounces < 0:
        raise Unsupported(f"max_depth {render['max_depth']} (Cycles renders at least direct light)")
    cycles.max_bounces = bounces
    cycles.diffuse_bounces = bounces
    cycles.glossy_bounces = bounces
    cycles.transmission_bounces = bounces
    cycles.volume_bounces = 0
    cycles.transparent_max_bounces = bounces
    # Russian roulette from the first bounce on is Cycles' default (min_light_bounces 0);
    # it is unbiased, as raylemma's.
    cycles.min_light_bounces = 0
    cycles.film_exposure = 1.0
    scene.render.film_transparent = False
    scene.render.resolution_x = camera["width"]
    scene.render.resolution_y = camera["height"]
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    scene.render.use_border = False
    scene.render.use_motion_blur = False
    if threads > 0:
        scene.render.threads_mode = "FIXED"
        scene.render.threads = threads
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    out = scene.render.image_settings
    out.file_format = "OPEN_EXR"
    out.color_mode = "RGB"
    out.color_depth = "32"
    out.exr_codec = "ZIP"
    bpy.context.view_layer.use_pass_combined = True


def add_camera(scene, camera):
    """A perspective camera whose vertical field of view and frame are raylemma's: image
    right = forward x up, as Blender's camera (its local -z forward, +y up, +x right)."""
    import bpy
    from mathutils import Matrix
    data = bpy.data.cameras.new("camera")
    data.type = "PERSP"
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(camera["fov_y_deg"])
    data.shift_x = data.shift_y = 0.0
    data.clip_start = 1e-4
    data.clip_end = 1e6
    obj = bpy.data.objects.new("camera", data)
    right, up, forward = camera["right"], camera["image_up"], camera["forward"]
    position = camera["position"]
    obj.matrix_world = Matrix([
        [right[0], up[0], -forward[0], position[0]],
        [right[1], up[1], -forward[1], position[1]],
        [right[2], up[2], -forward[2], position[2]],
        [0, 0, 0, 1],
    ])
    scene.collection.objects.link(obj)
    scene.camera = obj


def quad_mesh(name, shape):
    """One face: corner, corner + edge1, corner + edge1 + edge2, corner + edge2, so that its
    normal is edge1 x edge2, the side a quad light emits on."""
    import bpy
    c, e1, e2 = (np.array(shape[k]) for k in ("corner", "edge1", "edge2"))
    vertices = [tuple(c), tuple(c + e1), tuple(c + e1 + e2), tuple(c + e2)]
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, [], [(0, 1, 2, 3)])
    mesh.update()
    return mesh


def sphere_mesh(name, shape, subdivisions=6):
    """An icosphere, smooth shaded, scaled so that its area is the sphere's."""
    import bmesh
    import bpy
    bm = bmesh.new()
    bmesh.ops.create_icosphere(bm, subdivisions=subdivisions, radius=1.0)
    area = sum(f.calc_area() for f in bm.faces)
    grow = math.sqrt(4 * math.pi / area)
    r = shape["radius"] * grow
    centre = shape["center"]
    for v in bm.verts:
        v.co = (centre[0] + r * v.co.x, centre[1] + r * v.co.y, centre[2] + r * v.co.z)
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    for polygon in mesh.polygons:
        polygon.use_smooth = True
    mesh.update()
    return mesh


def node_material(name):
    import bpy
    material = bpy.data.materials.new(name)
    if material.node_tree is None:  # Blender 4 (in Blender 5 every material has nodes)
        material.use_nodes = True
    tree = material.node_tree
    tree.nodes.clear()
    output = tree.nodes.new("ShaderNodeOutputMaterial")
    output.target = "CYCLES"
    return material, tree, output


def surface_material(m, colour):
    """A material of the scene as Cycles nodes."""
    material, tree, output = node_material(m["name"])
    kind = m["type"]
    if kind == "lambert":
        node = tree.nodes.new("ShaderNodeBsdfDiffuse")
        rgb = colour.reflectance(m["reflectance"])
        node.inputs["Color"].default_value = (*rgb, 1.0)
        node.inputs["Roughness"].default_value = 0.0
    elif kind == "mirror":
        node = tree.nodes.new("ShaderNodeBsdfGlossy")
        node.distribution = "GGX"
        node.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        node.inputs["Roughness"].default_value = 0.0
    elif kind == "dielectric":
        if m.get("sellmeier"):
            raise Unsupported(f'material "{m["name"]}": Sellmeier dispersion (Cycles has one index for all wavelengths)')
        node = tree.nodes.new("ShaderNodeBsdfGlass")
        node.distribution = "GGX"
        node.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        node.inputs["Roughness"].default_value = 0.0
        node.inputs["IOR"].default_value = m["ior"]
    else:
        raise Unsupported(f'material "{m["name"]}": type {kind} (Cycles\' thin film is not raylemma\'s Airy film of varying thickness)')
    tree.links.new(node.outputs["BSDF"], output.inputs["Surface"])
    return material


def light_material(name, rgb):
    """An emitter: radiance rgb on its front faces, black behind, reflecting nothing (a
    quad's front is edge1 x edge2, an icosphere's faces wind outwards: raylemma's lights
    emit on those sides only)."""
    material, tree, output = node_material(name)
    emission = tree.nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (*rgb, 1.0)
    emission.inputs["Strength"].default_value = 1.0
    geometry = tree.nodes.new("ShaderNodeNewGeometry")
    mix = tree.nodes.new("ShaderNodeMixShader")
    tree.links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
    tree.links.new(emission.outputs["Emission"], mix.inputs[1])
    # mix.inputs[2] left empty: no closure, black, and it still blocks rays.
    tree.links.new(mix.outputs["Shader"], output.inputs["Surface"])
    material.cycles.emission_sampling = "FRONT"
    return material


def add_object(scene, name, shape, material):
    import bpy
    if shape["type"] == "quad":
        mesh = quad_mesh(name, shape)
    elif shape["type"] == "sphere":
        mesh = sphere_mesh(name, shape)
    else:
        raise Unsupported(f"shape type {shape['type']}")
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)


def add_world(scene, environment, colour):
    import bpy
    world = bpy.data.worlds.new("world")
    if world.node_tree is None:
        world.use_nodes = True
    tree = world.node_tree
    tree.nodes.clear()
    background = tree.nodes.new("ShaderNodeBackground")
    output = tree.nodes.new("ShaderNodeOutputWorld")
    tree.links.new(background.outputs["Background"], output.inputs["Surface"])
    rgb = np.zeros(3)
    if environment is not None:
        if environment["type"] != "constant":
            raise Unsupported(f"environment {environment['type']} (only a constant one is written)")
        rgb = colour.radiance(environment["radiance"])
    background.inputs["Color"].default_value = (*rgb, 1.0)
    background.inputs["Strength"].default_value = 1.0
    scene.world = world


def build(data, colour, spp, seed, threads):
    import bpy
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    settings(scene, data["render"], data["camera"], spp, seed, threads)
    add_camera(scene, data["camera"])
    add_world(scene, data.get("environment"), colour)
    materials = [surface_material(m, colour) for m in data["materials"]]
    for i, shape in enumerate(data["shapes"]):
        add_object(scene, f"shape{i}", shape, materials[shape["material"]])
    for i, light in enumerate(data["lights"]):
        rgb = colour.radiance(light["emission"])
        material = light_material(f"light{i}", rgb)
        add_object(scene, f"light{i}", light, material)
    return scene


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json")
    ap.add_argument("out")
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--seed", type=int, required=True)
    ap.add_argument("--threads", type=int, default=0, help="CPU threads (0: Blender's choice)")
    ap.add_argument("--cmf", default=DEFAULT_CMF, help="the 1 nm CIE 1931 table (raylemma's data/)")
    ap.add_argument("--blend", help="also save the Cycles scene as this .blend file")
    args = ap.parse_args()

    data = json.load(open(args.json))
    if data.get("format") != "raylemma-scene" or data.get("version") != 1:
        sys.exit(f"candidate.py: {args.json} is not a version 1 raylemma-scene JSON export")
    import bpy
    try:
        colour = Colour(data["conventions"], args.cmf)
        scene = build(data, colour, args.spp, args.seed, args.threads)
    except Unsupported as e:
        sys.exit(f"candidate.py: Cycles cannot express this scene: {e}")
    if args.blend:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(args.blend))
    scene.render.filepath = os.path.abspath(args.out)
    scene.render.use_file_extension = False
    bpy.ops.render.render(write_still=True)
    if not os.path.exists(args.out):
        sys.exit(f"candidate.py: Cycles wrote no {args.out}")


if __name__ == "__main__":
    main()
