"""Tangent frames from a normal (chapter Tangent frames, src/sampling/frame.rs): Duff et
al.'s branchless construction (the renderer's), Frisvad's rotation, and the cross-product
frame."""
import math

from mpmath import mpf, sqrt

from exact import Verb, f32, below, above

TITLE = "tangent frames from a normal: Duff et al., Frisvad, the cross-product frame"
CHAPTER = "Tangent frames (chapters/sampling/frame.md)"


def duff(x, y, z):
    """s = sign(z) (+1 at z = 0), a = -1 / (s + z): t = (1 + s x^2 a, s x y a, -s x),
    b = (x y a, s + y^2 a, -y)."""
    s = mpf(1) if z >= 0 else mpf(-1)
    a = -1 / (s + z)
    return [1 + s * x * x * a, s * x * y * a, -s * x, x * y * a, s + y * y * a, -y]


def frisvad(x, y, z):
    """The rotation about z x n taking z to n: t = (1 - x^2/(1+z), -xy/(1+z), -x),
    b = (-xy/(1+z), 1 - y^2/(1+z), -y), and Frisvad's fixed frame t = (0, -1, 0),
    b = (-1, 0, 0) for z < -0.9999999 (the double; every single input compares the same
    with its single), where the rotation is too ill-conditioned to compute."""
    if z < mpf(-0.9999999):
        return [mpf(0), mpf(-1), mpf(0), mpf(-1), mpf(0), mpf(0)]
    a = 1 / (1 + z)
    return [1 - x * x * a, -x * y * a, -x, -x * y * a, 1 - y * y * a, -y]


def cross_frame(x, y, z):
    """The helper (-y, x, 0) if |x| > |z|, else (0, -z, y), normalised: t; b = n x t."""
    h = (-y, x, mpf(0)) if abs(x) > abs(z) else (mpf(0), -z, y)
    length = sqrt(sum(c * c for c in h))
    t = [c / length for c in h]
    b = [y * t[2] - z * t[1], z * t[0] - x * t[2], x * t[1] - y * t[0]]
    return t + b


OUTS = ["tx", "ty", "tz", "bx", "by", "bz"]
VERBS = [
    Verb("frame_duff", ["nx", "ny", "nz"], OUTS, 1,
         "Duff et al.'s tangent t and bitangent b of the normal n (the renderer's frame)",
         duff),
    Verb("frame_frisvad", ["nx", "ny", "nz"], OUTS, 1,
         "Frisvad's rotation taking z to n, its t and b, with his fixed frame below"
         " n_z = -0.9999999", frisvad),
    Verb("frame_cross", ["nx", "ny", "nz"], OUTS, 1,
         "the cross-product frame: a helper orthogonal to n normalised, and n x t",
         cross_frame),
]


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def ring(z, phi=0.7):
    """The double unit vector at height z and azimuth phi (x, y from sqrt(1 - z^2))."""
    r = math.sqrt((1 - z) * (1 + z))
    return [r * math.cos(phi), r * math.sin(phi), z]


def cases():
    out = []

    def normals():
        yield "the north pole, n = +z", [0.0, 0.0, 1.0]
        yield "the south pole, n = -z exactly", [0.0, 0.0, -1.0]
        yield "n = +x (on the equator, z = 0)", [1.0, 0.0, 0.0]
        yield "n = -y", [0.0, -1.0, 0.0]
        yield "a diagonal, (1, 1, 1)/sqrt(3)", unit([1.0, 1.0, 1.0])
        yield "a diagonal below, -(1, 1, 1)/sqrt(3)", unit([-1.0, -1.0, -1.0])
        yield "(1, 2, 2)/3", unit([1.0, 2.0, 2.0])
        yield "(2, -1, -2)/3", unit([2.0, -1.0, -2.0])
        yield "z = 1e-300 above the equator", [0.6, 0.8, 1e-300]
        yield "z = -1e-300 below the equator (s = -1)", [0.6, 0.8, -1e-300]
        yield "nearly +x: (1, 1e-9, 1e-9) normalised", unit([1.0, 1e-9, 1e-9])
        yield "nearly -x, tilted 1e-9 below", unit([-1.0, 1e-9, -1e-9])
        yield "subnormal x at the north pole", [5e-324, 0.0, 1.0]
        yield "subnormal x and y at the south pole", [5e-324, 5e-324, -1.0]
        yield "subnormal x, y = 1e-310 at the south pole", [1e-310, -1e-310, -1.0]
        yield "subnormal y at the south pole", [0.0, 5e-324, -1.0]
        yield "x = 1e-160 at the south pole (x^2 underflows)", [1e-160, 1e-160, -1.0]
        for k in [2, 4, 6, 8, 10, 12, 14, 15, 16]:
            z = -(1.0 - 10.0 ** -k)
            yield f"near the south pole, 1 + z = 1e-{k}", ring(z)
            yield f"near the north pole, 1 - z = 1e-{k}", ring(-z, 2.1)
        for z, what in [(-0.9999999, "at Frisvad's threshold z = -0.9999999"),
                        (below(-0.9999999), "one double below Frisvad's threshold"),
                        (above(-0.9999999), "one double above Frisvad's threshold"),
                        (above(-1.0), "the double above -1 (1 + z = 2^-53)"),
                        (-1.0 + 2.0 ** -24, "the single above -1 (1 + z = 2^-24), past"
                         " Frisvad's threshold"),
                        (-1.0 + 2.0 ** -22, "1 + z = 2^-22, short of Frisvad's threshold"),
                        (-0.5, "z = -0.5"), (0.5, "z = 0.5")]:
            yield what, ring(z)

    for why, n in normals():
        for verb in ["frame_duff", "frame_frisvad", "frame_cross"]:
            out.append((why, verb, n))
    # The same normals rounded to singles (each component), for the f32 twins.
    for why, n in normals():
        s = [f32(c) for c in n]
        if any(f32(c) == 0 and c != 0 for c in n):
            continue  # a component rounded to a zero whose sign the reference cannot see
        for verb in ["frame_duff", "frame_frisvad", "frame_cross"]:
            out.append((why + " (components singles)", verb, s))
    return out
