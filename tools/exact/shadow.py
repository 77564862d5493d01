"""Shadow-ray pdfs (chapter Shadow-ray pdfs, src/transport/shadow.rs): area to solid
angle, the sphere light's cone, the multiple-importance weights, the triangle's solid
angle."""
import math

from mpmath import mpf, sqrt, atan2, pi

from exact import Verb, f32, below, above

TITLE = "area to solid angle, the sphere light's cone, MIS weights, a triangle's solid angle"
CHAPTER = "Shadow-ray pdfs (chapters/transport/shadow.md)"

MAX = mpf(1.7976931348623157e308)


def area_to_solid_angle(pdf_area, dist, cos_light):
    """pdf_area dist^2 / |cos_light|; 0 where that is not a finite double (seen edge-on,
    cos_light = 0, or beyond the largest double), as the routine's contract says."""
    if cos_light == 0:
        return [mpf(0)]
    p = pdf_area * dist * dist / abs(cos_light)
    return [p if p <= MAX else mpf(0)]


def one_minus_cos_max(cx, cy, cz, r, px, py, pz):
    """1 - cos(theta_max) = 1 - sqrt(1 - (r/d)^2), d = |p - c|; none from inside (d <= r)."""
    d = sqrt((px - cx) ** 2 + (py - cy) ** 2 + (pz - cz) ** 2)
    if not d > r:
        return None
    s2 = (r / d) ** 2
    # The same number as 1 - sqrt(1 - s2), written so that 256 bits keep it when s2 is
    # below 2^-256.
    return [s2 / (1 + sqrt(1 - s2))]


def cone_solid_angle(cx, cy, cz, r, px, py, pz):
    h = one_minus_cos_max(cx, cy, cz, r, px, py, pz)
    return [2 * pi * h[0]] if h is not None else [mpf(0)]


def weight(a, b):
    return [a / (a + b)] if a + b > 0 else [mpf(0)]


def balance(pa, pb):
    """pa / (pa + pb); 0 when both are 0."""
    return weight(pa, pb)


def power(pa, pb):
    """pa^2 / (pa^2 + pb^2); 0 when both are 0."""
    return weight(pa * pa, pb * pb)


def triangle(ax, ay, az, bx, by, bz, cx, cy, cz):
    """The solid angle of the triangle a, b, c seen from the origin (Van Oosterom and
    Strackee): 2 atan2(|a . (b x c)|, |a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|)."""
    a, b, c = (ax, ay, az), (bx, by, bz), (cx, cy, cz)

    def dot(u, v):
        return sum(x * y for x, y in zip(u, v))

    bc = (b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0])
    la, lb, lc = sqrt(dot(a, a)), sqrt(dot(b, b)), sqrt(dot(c, c))
    num = abs(dot(a, bc))
    den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la
    return [2 * atan2(num, den)]


CONE = ["cx", "cy", "cz", "r", "px", "py", "pz"]
VERBS = [
    Verb("area_to_solid_angle", ["pdf_area", "dist", "cos_light"], ["pdf"], 0,
         "pdf_area dist^2 / |cos_light|, 0 where that is not a finite double (edge-on)",
         area_to_solid_angle),
    Verb("one_minus_cos_max", CONE, ["h"], 0,
         "1 - cos(theta_max) of the cone a sphere (centre c, radius r) subtends from p,"
         " none from inside", one_minus_cos_max),
    Verb("cone_solid_angle", CONE, ["omega"], 0,
         "that cone's solid angle 2 pi (1 - cos theta_max), 0 from inside",
         cone_solid_angle),
    Verb("mis_balance", ["pa", "pb"], ["w"], 1,
         "the balance heuristic pa / (pa + pb), 0 when both are 0", balance),
    Verb("mis_power", ["pa", "pb"], ["w"], 1,
         "the power heuristic pa^2 / (pa^2 + pb^2), 0 when both are 0", power),
    Verb("triangle_solid_angle", ["ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz"],
         ["omega"], 0, "the solid angle of the triangle a, b, c seen from the origin",
         triangle),
]


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    # Area to solid angle.
    for pa, dist, cos, why in [
            (1.0, 1.0, 1.0, "a unit patch at unit distance, facing"),
            (0.25, 3.0, -0.5, "a light facing the point (cos < 0)"),
            (1.0 / 0.0182, 2.5, -0.8, "the Cornell light's 1/A"),
            (1e12, 1e-6, 1.0, "a tiny light (1e-12 area) a micron away"),
            (1e-12, 1e6, 0.5, "a huge light (1e12 area) a million away"),
            (1.0, 1.0, 1e-12, "nearly edge-on, cos = 1e-12"),
            (1.0, 1.0, 5e-324, "edge-on to a subnormal: beyond the largest double, 0"),
            (1.0, 1.0, 0.0, "exactly edge-on, cos = 0: 0"),
            (1.0, 1.0, -0.0, "exactly edge-on, cos = -0: 0"),
            (1e300, 1e10, 1.0, "pdf_area dist^2 overflows, the exact density too: 0"),
            (1.0, 1e154, 1e-10, "beyond the largest double after the division: 0"),
            (1e-100, 1e-50, 1e-200, "a tiny density, distance and cosine (products stay"
             " normal)"),
            (1e100, 1e100, 1e-8, "a density of 1e308, near the largest double"),
            (3.0, 0.1, 0.7071067811865476, "45 degrees"),
            (0.1, 1e-150, 1e-150, "dist^2 = 1e-300, cos = 1e-150"),
    ]:
        add(why, "area_to_solid_angle", pa, dist, cos)
        if all(f32(x) == x for x in (pa, dist, cos)):
            pass
    # The sphere light's cone.
    for d, r, why in [(2.0, 1.0, "d = 2 R"), (10.0, 1.0, "d = 10 R"),
                      (1e3, 1.0, "1e3 radii away"), (1e6, 1.0, "1e6 radii away"),
                      (1e8, 1.0, "1e8 radii away (1 - cos = 5e-17 below the double's"
                       " spacing at 1)"),
                      (1e12, 1.0, "1e12 radii away"), (1.0, 1e-150, "1e150 radii away"),
                      (1.0, 1e-155, "1e155 radii away: (R/d)^2 subnormal"),
                      (1.0, 1e-170, "(R/d)^2 underflows to 0"),
                      (above(1.0), 1.0, "one double outside the sphere"),
                      (1.0 + 1e-12, 1.0, "1e-12 outside the sphere"),
                      (1.0 + 1e-6, 1.0, "1e-6 outside the sphere"),
                      (0.5, 1.0, "inside the sphere: none")]:
        for verb in ["one_minus_cos_max", "cone_solid_angle"]:
            add(f"{why}, on an axis", verb, 0.0, 0.0, 0.0, r, d, 0.0, 0.0)
    for k in [3, 6, 8, 12]:
        p = [10.0 ** k * x for x in (0.36, -0.48, 0.8)]
        for verb in ["one_minus_cos_max", "cone_solid_angle"]:
            add(f"an oblique point 1e{k} from a unit sphere off the origin", verb,
                1.5, -2.0, 0.25, 1.0, *p)
    # MIS weights.
    for pa, pb, why in [
            (1.0, 1.0, "equal pdfs"), (0.3, 0.7, "ordinary pdfs"),
            (1.0, 0.0, "the other strategy cannot draw it"), (0.0, 1.0, "this one cannot"),
            (0.0, 0.0, "neither: 0"), (1.0, 1e-8, "a ratio of 1e8"),
            (1e-8, 1.0, "a ratio of 1e-8"),
            (1.0, 1e-160, "the other's square underflows"),
            (1e154, 1e154, "equal pdfs whose squares overflow (1e154)"),
            (2e154, 1e154, "squares overflow, ratio 2"),
            (1e200, 3e200, "huge pdfs (1e200)"), (1e300, 1e300, "pdfs of 1e300"),
            (1.7976931348623157e308, 1.7976931348623157e308,
             "both the largest double: the sum overflows"),
            (1e308, 5e307, "the sum overflows"),
            (1e-160, 1e-160, "equal pdfs whose squares underflow"),
            (1e-200, 3e-200, "tiny pdfs (1e-200)"), (5e-324, 5e-324, "equal subnormal pdfs"),
            (5e-324, 1e-323, "subnormal pdfs, ratio 1/2"), (1e-300, 1e300, "1e-300 against 1e300"),
            (1e300, 1e-300, "1e300 against 1e-300"), (123.25, 0.001953125, "a delta-like light"
             " pdf against a wide lobe")]:
        add(why, "mis_balance", pa, pb)
        add(why, "mis_power", pa, pb)
    # Triangles.
    tri = [
        ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), "an octant: pi/2"),
        ((1.0, -1.0, 2.0), (1.0, 1.0, 2.0), (-1.0, 0.0, 2.0), "a triangle 2 away"),
        ((1.0, 0.0, 1e-6), (0.0, 1.0, 1e-6), (-1.0, -1.0, 1e-6),
         "seen nearly edge-on, 1e-6 out of its plane, around the viewpoint (above pi)"),
        ((1e-6, 0.0, 1.0), (0.0, 1e-6, 1.0), (0.0, 0.0, 1.0),
         "a 1e-6 triangle at unit distance (omega 5e-13)"),
        ((1e-3, 0.0, 1e3), (0.0, 1e-3, 1e3), (0.0, 0.0, 1e3),
         "a 1e-3 triangle 1e3 away (omega 5e-13)"),
        ((1.0, 0.0, 1e6), (0.0, 1.0, 1e6), (0.0, 0.0, 1e6), "a unit triangle 1e6 away"),
        ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (1.0, 1.0, 1e-12),
         "nearly through the viewpoint: a degenerate sliver"),
        ((0.3, 0.1, -1.0), (-0.2, 0.4, -1.0), (0.1, -0.5, -1.0), "below the viewpoint"),
        ((1e-100, 0.0, 1e-100), (0.0, 1e-100, 1e-100), (0.0, 0.0, 1e-100),
         "a triangle at 1e-100 (the product of three lengths, 1e-300, still normal)"),
        ((1e100, 0.0, 1e100), (0.0, 2e100, 1e100), (0.0, 0.0, 1e100),
         "a triangle at 1e100 (the product of three lengths, 1e300, still finite)"),
    ]
    for a, b, c, why in tri:
        add(why, "triangle_solid_angle", *a, *b, *c)
    return out
