"""Uniform directions on the sphere and the hemisphere: the inverse-CDF warp, its inverse,
the hemisphere by flipping, and their densities (chapter Uniform sphere and hemisphere,
src/sampling/sphere.rs)."""
import math

from mpmath import mp, mpf, sqrt, cos, sin, atan2, pi

from exact import Verb, below, above, f32

TITLE = "Uniform sphere and hemisphere: the inverse-CDF warp, its inverse, the densities"
CHAPTER = "Uniform sphere and hemisphere (chapters/sampling/sphere.md)"


def sphere(u1, u2):
    """z = 1 - 2 u1, radius sqrt(1 - z^2) = 2 sqrt(u1 (1 - u1)), phi = 2 pi u2."""
    z = 1 - 2 * u1
    r = 2 * sqrt(u1 * (1 - u1))
    phi = 2 * pi * u2
    return [r * cos(phi), r * sin(phi), z]


def sphere_invert(x, y, z):
    """u1 = (1 - z) / 2, u2 = phi / (2 pi) with phi = atan2(y, x) in [0, 2 pi)."""
    phi = atan2(y, x) if (x, y) != (0, 0) else mpf(0)
    if phi < 0:
        phi += 2 * pi
    return [(1 - z) / 2, phi / (2 * pi)]


def hemisphere(u1, u2, nx, ny, nz):
    """The sphere's warp flipped to n's side (kept where w . n = 0)."""
    w = sphere(u1, u2)
    if w[0] * nx + w[1] * ny + w[2] * nz < 0:
        return [-c for c in w]
    return w


def sphere_pdf(x, y, z):
    return [1 / (4 * pi)]


def hemisphere_pdf(x, y, z, nx, ny, nz):
    return [1 / (2 * pi) if x * nx + y * ny + z * nz >= 0 else mpf(0)]


VERBS = [
    Verb("sphere_inverse_cdf", ["u1", "u2"], ["x", "y", "z"], 1,
         "the uniform sphere's warp: z = 1 - 2 u1, radius 2 sqrt(u1 (1 - u1)), phi = 2 pi u2",
         sphere),
    Verb("sphere_invert", ["x", "y", "z"], ["u1", "u2"], 1,
         "its inverse: u1 = (1 - z) / 2, u2 = atan2(y, x) / (2 pi) in [0, 1)",
         sphere_invert),
    Verb("hemisphere_inverse_cdf", ["u1", "u2", "nx", "ny", "nz"], ["x", "y", "z"], 1,
         "the sphere's warp flipped to the side of n (kept where w . n = 0)", hemisphere),
    Verb("sphere_pdf", ["x", "y", "z"], ["p"], 0,
         "the uniform sphere's density 1 / (4 pi) per steradian", sphere_pdf),
    Verb("hemisphere_pdf", ["x", "y", "z", "nx", "ny", "nz"], ["p"], 0,
         "the uniform hemisphere's density 1 / (2 pi) where w . n >= 0, else 0",
         hemisphere_pdf),
]


def direction(u1, u2):
    """The double nearest the exact sphere warp of (u1, u2)."""
    return [float(c) for c in sphere(mpf(u1), mpf(u2))]


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    tiny = 5e-324
    u1s = [
        (0.0, "u1 = 0: the north pole, radius 0"),
        (tiny, "subnormal u1 = 5e-324: radius 2 sqrt(u1) = 1.4e-161"),
        (1e-300, "u1 = 1e-300: 1 - 2 u1 rounds to 1, the radius is 2e-150"),
        (1e-20, "u1 = 1e-20: sqrt(1 - z^2) is exactly 0, the radius 2e-10"),
        (2.0 ** -53, "u1 = 2^-53, the generator's smallest step"),
        (1e-10, "u1 = 1e-10: sqrt(1 - z^2) cancels, keeping 5 digits"),
        (f32(1e-4), "u1 = 1e-4 (a single): near the pole in f32"),
        (2.0 ** -24, "u1 = 2^-24, a single's smallest step below 1 / 2"),
        (0.25, "u1 = 1/4: z = 1/2 exactly"),
        (0.5, "u1 = 1/2 exactly: the equator, z = 0"),
        (below(0.5), "one double below 1/2: z = 2^-53, just north of the equator"),
        (above(0.5), "one double above 1/2: z = -2^-52, just south of the equator"),
        (f32(0.3), "u1 = 0.3 as a single"),
        (0.75, "u1 = 3/4"),
        (below(1.0, 2), "u1 = 1 - 2^-52: near the south pole"),
        (below(1.0), "u1 = 1 - 2^-53, the largest double below 1: the south pole's "
                     "neighbourhood, 1 - u1 exact"),
        (1 - 2.0 ** -24, "u1 = 1 - 2^-24, the largest single below 1"),
    ]
    u2s = [
        (0.0, "u2 = 0"),
        (0.125, "u2 = 1/8: phi = pi/4"),
        (0.25, "u2 = 1/4: phi = pi/2, x crosses 0"),
        (0.5, "u2 = 1/2: phi = pi, y crosses 0"),
        (f32(0.7), "u2 = 0.7 as a single"),
        (below(1.0), "u2 = 1 - 2^-53: phi just below 2 pi, y crosses 0"),
    ]
    for u1, w1 in u1s:
        for u2, w2 in u2s:
            add(f"{w1}; {w2}", "sphere_inverse_cdf", u1, u2)

    # The inverse, at exact directions' doubles and at the poles and the equator.
    for u1, w1 in u1s:
        for u2, w2 in [(0.0, "u2 = 0"), (0.25, "u2 = 1/4"), (f32(0.7), "u2 = 0.7"),
                       (below(1.0), "u2 = 1 - 2^-53")]:
            x, y, z = direction(u1, u2)
            add(f"the inverse at the warp of ({w1}; {w2})", "sphere_invert", x, y, z)
    poles = [
        ((0.0, 0.0, 1.0), "the north pole: x = y = 0, atan2(0, 0) taken as 0"),
        ((0.0, 0.0, -1.0), "the south pole"),
        ((1.0, 0.0, 0.0), "the equator at phi = 0"),
        ((-1.0, 0.0, 0.0), "the equator at phi = pi"),
        ((0.0, -1.0, 0.0), "the equator at phi = 3 pi / 2"),
        ((1.0, -1e-300, 0.0), "the equator just below phi = 2 pi: u2 rounds to 1"),
        ((1.0, -1e-16, 0.0), "phi = 2 pi - 1e-16: u2 one step below 1"),
        ((tiny, tiny, below(1.0)), "subnormal x = y at the north pole"),
        ((-tiny, tiny, -1.0), "subnormal x, y at the south pole"),
        ((1e-10, -2e-10, below(1.0)), "near the north pole, phi in the fourth quadrant"),
        ((f32(0.6), f32(0.8), 0.0), "a single direction on the equator"),
        ((f32(-0.36), f32(0.48), f32(-0.8)), "a single direction in the southern hemisphere"),
    ]
    for (x, y, z), why in poles:
        add(why, "sphere_invert", x, y, z)

    normals = [
        ((0.0, 0.0, 1.0), "around +z"),
        ((0.0, 0.0, -1.0), "around -z: every sample flips"),
        ((1.0, 0.0, 0.0), "around +x"),
        ((0.0, -1.0, 0.0), "around -y"),
    ]
    for n, wn in normals:
        for u1, w1 in u1s[::2]:
            for u2, w2 in [(0.0, "u2 = 0"), (f32(0.7), "u2 = 0.7"),
                           (below(1.0), "u2 = 1 - 2^-53")]:
                add(f"hemisphere {wn}: {w1}; {w2}", "hemisphere_inverse_cdf", u1, u2, *n)

    dirs = [
        ((0.0, 0.0, 1.0), "the north pole"),
        ((1.0, 0.0, 0.0), "the equator"),
        ((tiny, 0.0, -1.0), "a subnormal component"),
        ((f32(0.6), f32(0.8), 0.0), "a single direction"),
    ]
    for d, why in dirs:
        add(f"the sphere's density at {why} (a constant)", "sphere_pdf", *d)
    pdf_cases = [
        ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0), "w . n = 0 exactly (the boundary is inside)"),
        ((0.0, 0.0, 1.0), (0.0, 0.0, 1.0), "w = n"),
        ((0.0, 0.0, -1.0), (0.0, 0.0, 1.0), "w = -n: density 0"),
        ((1.0, 0.0, tiny), (0.0, 0.0, 1.0), "w . n = 5e-324 (subnormal), inside"),
        ((1.0, 0.0, -tiny), (0.0, 0.0, 1.0), "w . n = -5e-324 (subnormal), outside"),
        ((1.0, 0.0, -1e-300), (0.0, 0.0, 1.0), "w . n = -1e-300, outside"),
        ((f32(0.6), f32(-0.8), 0.0), (f32(0.8), f32(0.6), 0.0),
         "w . n cancels to 0 exactly in singles' products"),
        ((f32(0.6), f32(0.8), 0.0), (0.0, 0.0, 1.0), "a single direction on the boundary"),
        ((f32(0.36), f32(0.48), f32(-0.8)), (0.0, 0.0, -1.0), "single w, n = -z"),
        ((0.5, 0.5, math.sqrt(0.5)), (0.0, 1.0, 0.0), "a tilted normal"),
    ]
    for w, n, why in pdf_cases:
        add(why, "hemisphere_pdf", *w, *n)
    return out
