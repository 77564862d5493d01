"""Ray-sphere intersection and the parallelogram hit (chapter Ray-sphere intersection,
src/geometry/sphere.rs; the parallelogram of chapter Shadow-ray pdfs,
src/geometry/parallelogram.rs)."""
import math

from mpmath import mpf, sqrt

from exact import Verb, f32, below, above

TITLE = "ray-sphere intersection (both roots, the first beyond t_min), the parallelogram hit"
CHAPTER = "Ray-sphere intersection (chapters/geometry/sphere.md)"


def roots(ox, oy, oz, dx, dy, dz, cx, cy, cz, r):
    """The line O + tD meets |P - C| = r at t = (-b -+ sqrt(b^2 - a c)) / a, with f = O - C,
    a = D.D, b = D.f, c = f.f - r^2; none where b^2 - a c < 0 (exactly)."""
    f = (ox - cx, oy - cy, oz - cz)
    d = (dx, dy, dz)
    a = sum(x * x for x in d)
    b = sum(x * y for x, y in zip(d, f))
    c = sum(x * x for x in f) - r * r
    disc = b * b - a * c
    if disc < 0:
        return None
    root = sqrt(disc)
    return [(-b - root) / a, (-b + root) / a]


def first(ox, oy, oz, dx, dy, dz, cx, cy, cz, r, t_min):
    """The smallest root strictly greater than t_min, or none."""
    t = roots(ox, oy, oz, dx, dy, dz, cx, cy, cz, r)
    if t is None:
        return None
    for x in t:
        if x > t_min:
            return [x]
    return None


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v):
    return sum(x * y for x, y in zip(u, v))


def quad(ox, oy, oz, dx, dy, dz, cx, cy, cz, ax, ay, az, bx, by, bz):
    """Where the ray O + tD meets the parallelogram C + a E1 + b E2 (a, b in [0, 1]): the
    plane n.(P - C) = 0, n = E1 x E2, at t = n.(C - O) / n.D (a hit needs t > 0); the edge
    coordinates of Q = O + tD - C from the dual basis, a = Q.(E2 x n) / n.n,
    b = Q.(n x E1) / n.n. Returns (t, a, b) or None."""
    o, d, c = (ox, oy, oz), (dx, dy, dz), (cx, cy, cz)
    e1, e2 = (ax, ay, az), (bx, by, bz)
    n = cross(e1, e2)
    nd = dot(n, d)
    if nd == 0:
        return None
    t = dot(n, tuple(p - q for p, q in zip(c, o))) / nd
    if not t > 0:
        return None
    q = tuple(oo + t * dd - cc for oo, dd, cc in zip(o, d, c))
    nn = dot(n, n)
    a = dot(q, cross(e2, n)) / nn
    b = dot(q, cross(n, e1)) / nn
    if not (0 <= a <= 1 and 0 <= b <= 1):
        return None
    return [t, a, b]


def quad_t(*args):
    h = quad(*args)
    return None if h is None else [h[0]]


def quad_ab(*args):
    h = quad(*args)
    return None if h is None else [h[1], h[2]]


RAY = ["ox", "oy", "oz", "dx", "dy", "dz", "cx", "cy", "cz"]
QUAD = RAY + ["e1x", "e1y", "e1z", "e2x", "e2y", "e2z"]

VERBS = [
    Verb("sphere_roots", RAY + ["r"], ["t_near", "t_far"], 0,
         "both roots of the ray-sphere quadratic (the line's two meetings), none for a miss",
         roots),
    Verb("sphere_first", RAY + ["r", "t_min"], ["t"], 0,
         "the first root beyond t_min (what the routine returns), none for a miss or when"
         " both roots are at most t_min", first),
    Verb("quad_hit", QUAD, ["t"], 0,
         "the ray's hit of the parallelogram corner + a e1 + b e2 (a, b in [0, 1]), t > 0,"
         " none for a miss", quad_t),
    Verb("quad_coords", QUAD, ["a", "b"], 1,
         "the edge coordinates (a, b) of that hit, none for a miss", quad_ab),
]

MAX = 1.7976931348623157e308  # t_min = -MAX: every root counts (the line)


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    def both(why, o, d, c, r):
        add(why, "sphere_roots", *o, *d, *c, r)

    def single(why, o, d, c, r):
        """Every input a single, so that the f32 twins answer the same question."""
        o, d, c = [f32(x) for x in o], [f32(x) for x in d], [f32(x) for x in c]
        both(why + " (inputs singles)", o, d, c, f32(r))

    zero = [0.0, 0.0, 0.0]
    z = [0.0, 0.0, 1.0]

    # Ordinary rays, as the checker's: the baseline.
    single("a unit sphere 5 away, on the axis", [0.0, 0.0, -5.0], z, zero, 1.0)
    single("a non-unit direction (|D| = 3)", [0.0, 0.0, -5.0], [0.0, 0.0, 3.0], zero, 1.0)
    single("an oblique ray, off-centre sphere", [0.3, -0.2, -4.0], [0.1, 0.05, 1.0],
           [0.5, 0.25, 3.0], 1.5)
    single("an oblique ray, half a radius off the centre", [0.5, 0.0, -5.0],
           unit([0.1, 0.7, 1.0]), [0.25, 1.0, -1.0], 2.0)
    single("origin inside the sphere (near root negative)", [0.1, 0.2, 0.3],
           [0.6, -0.8, 0.0], zero, 1.0)
    single("origin at the centre", [1.0, 2.0, 3.0], [0.0, 0.6, 0.8], [1.0, 2.0, 3.0], 0.5)
    single("the sphere behind the origin (both roots negative)", [0.0, 0.0, 5.0], z,
           zero, 1.0)
    both("a tiny direction (|D| = 1e-150: a = 1e-300)", [0.0, 0.0, -5.0],
         [0.0, 0.0, 1e-150], zero, 1.0)
    both("a subnormal direction component", [0.0, 0.0, -5.0], [5e-324, 0.0, 1.0], zero, 1.0)
    both("a radius of 1e-150 (r^2 = 1e-300)", [0.0, 0.0, -5e-150], z, zero, 1e-150)
    both("a radius of 1e150 seen from 5e150", [0.0, 0.0, -5e150], z, zero, 1e150)

    # Far rays: the discriminant b^2 - ac cancels by d^2 / r^2.
    for d in [1e6, 1e9, 1e12]:
        both(f"a unit sphere {d:g} away, on the axis", [0.0, 0.0, -d], z, zero, 1.0)
        for h in [0.5, 0.999]:
            both(f"{d:g} away, passing {h:g} radii from the centre", [h, 0.0, -d], z, zero,
                 1.0)
    o = [1e12, 3e11, -7e11]
    c = [0.5, -0.25, 0.125]
    both("1e12 away, an oblique unit direction aimed at the centre", o,
         unit([c[i] - o[i] for i in range(3)]), c, 1.0)
    both("1e12 away, D = C - O unnormalised (|D| = 1.26e12, t near 1)", o,
         [c[i] - o[i] for i in range(3)], c, 1.0)
    for h in [0.5, 0.9]:
        aim = [c[0], c[1] + h, c[2]]
        both(f"1e12 away, oblique, aimed {h:g} radii off the centre", o,
             unit([aim[i] - o[i] for i in range(3)]), c, 1.0)
    both("1e12 away, passing 1.001 radii from the centre: a decided miss",
         [1.001, 0.0, -1e12], z, zero, 1.0)
    both("1e12 away, oblique, from 1.01 radii off to 1.11 radii from the centre: a decided miss",
         [1.01, 0.0, -1e12], unit([1e-13, 0.0, 1.0]), zero, 1.0)
    both("1e12 away, exactly tangent (b^2 - ac = 0 exactly)", [1.0, 0.0, -1e12], z, zero,
         1.0)

    # Far-away small spheres in single precision (the chapter's far bundle).
    for d in [1e2, 1e3, 3e3, 1e4, 1e5]:
        for h in [0.0, 0.5, 0.9, 0.99]:
            single(f"a unit sphere {d:g} away, passing {h:g} radii off", [h, 0.0, -d], z,
                   zero, 1.0)
        single(f"a unit sphere {d:g} away, oblique ray", [0.25, -0.5, -d],
               unit([-0.25 / d, 0.75 / d, 1.0]), zero, 1.0)
        single(f"a unit sphere {d:g} away, passing 1.01 radii off: a decided miss",
               [1.01, 0.0, -d], z, zero, 1.0)
        single(f"a sphere of radius 0.01 at {d:g} from the origin, seen from the origin",
               zero, unit([1.0, 2.0, 2.0]), [d / 3, 2 * d / 3, 2 * d / 3], 0.01)

    for d, r in [(1e12, 1e-2), (1e12, 1e-3), (1e12, 4e-4)]:
        both(f"a sphere of radius {r:g} at {d:g} from the origin ({d / r:.0e} radii),"
             " seen from the origin", [0.0, 0.0, 0.0], unit([1.0, 2.0, 2.0]),
             [d / 3, 2 * d / 3, 2 * d / 3], r)
    for d, r in [(1e5, 0.1), (3e5, 0.1), (1e5, 0.03)]:
        single(f"a sphere of radius {r:g} at {d:g} from the origin ({d / r:.0e} radii),"
               " seen from the origin", [0.0, 0.0, 0.0], unit([1.0, 2.0, 2.0]),
               [d / 3, 2 * d / 3, 2 * d / 3], r)

    # Tangent and grazing rays: the discriminant is near 0.
    single("exactly tangent, 5 away (b^2 - ac = 0 exactly)", [1.0, 0.0, -5.0], z, zero, 1.0)
    single("exactly tangent, |D| = 2", [0.0, 1.0, -3.0], [0.0, 0.0, 2.0], zero, 1.0)
    for k in [20, 30, 40]:
        h = 1.0 - 2.0 ** -k
        both(f"grazing: passing 1 - 2^-{k} radii off, 5 away", [h, 0.0, -5.0], z, zero, 1.0)
        both(f"just missing: passing 1 + 2^-{k} radii off, 5 away", [1.0 + 2.0 ** -k, 0.0,
             -5.0], z, zero, 1.0)
    for k in [8, 12, 20]:
        single(f"grazing: passing 1 - 2^-{k} radii off, 5 away", [1.0 - 2.0 ** -k, 0.0,
               -5.0], z, zero, 1.0)
    both("grazing, oblique: tangent point missed by 1e-9 inward", [0.0, 0.0, -5.0],
         unit([1.0 - 1e-9, 0.0, math.sqrt(24.0)]), zero, 1.0)
    both("grazing 1e3 away (f64): passing 1 - 1e-6 radii off", [1.0 - 1e-6, 0.0, -1e3], z,
         zero, 1.0)

    # Origins on the surface: a root at (or within a rounding of) 0.
    single("origin on the sphere, entering along the diameter (roots 0 and 2)",
           [1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], zero, 1.0)
    single("origin on the sphere, leaving (roots -2 and 0)", [0.0, 0.0, 1.0], z, zero, 1.0)
    single("origin on the sphere, tangent there (double root 0)", [1.0, 0.0, 0.0],
           [0.0, 1.0, 0.0], zero, 1.0)
    both("origin on the sphere, nearly tangent (far root 2e-8)", [1.0, 0.0, 0.0],
         [-1e-8, 1.0, 0.0], zero, 1.0)
    single("origin within a rounding of the sphere (0.6, 0.8), entering", [0.6, 0.8, 0.0],
           [-0.6, -0.8, 0.0], zero, 1.0)
    both("origin within a rounding of the sphere, oblique", [0.6, 0.8, 0.0],
         unit([-1.0, 0.1, 0.3]), zero, 1.0)
    both("origin 1 unit outside a sphere of radius 2048, c a small exact integer",
         [2048.0, 1.0, 0.0], [-1.0, 0.0, 0.0], zero, 2048.0)
    both("integer origin just outside radius 2048, oblique", [2047.0, 64.0, 3.0],
         unit([-1.0, -0.03, 0.0]), zero, 2048.0)
    both("origin on a sphere far from the coordinates' origin (C = 1e6 (1, 1, 1))",
         [1e6 + 1e-3, 1e6, 1e6], [-1.0, 0.0, 0.0], [1e6, 1e6, 1e6], 1e-3)
    single("origin on a sphere far from the coordinates' origin (f32, C = 1024 (1, 1, 1))",
           [1024.0 + 0.25, 1024.0, 1024.0], unit([-1.0, 0.5, 0.0]), [1024.0] * 3, 0.25)

    # The routine itself: the first root beyond t_min.
    def firsts(why, o, d, c, r, t_min, as_single=False):
        args = o + d + c + [r, t_min]
        if as_single:
            args = [f32(x) for x in args]
            why += " (inputs singles)"
        add(why, "sphere_first", *args)

    for s in [False, True]:
        firsts("from outside, t_min = 0: the near root", [0.0, 0.0, -5.0], z, zero, 1.0, 0.0,
               s)
        firsts("from inside, t_min = 0: the far root", [0.1, 0.2, 0.3], [0.6, -0.8, 0.0],
               zero, 1.0, 0.0, s)
        firsts("t_min between the roots", [0.0, 0.0, -5.0], z, zero, 1.0, 5.0, s)
        firsts("t_min exactly at the near root (4): the far one", [0.0, 0.0, -5.0], z, zero,
               1.0, 4.0, s)
        firsts("t_min beyond both roots: none", [0.0, 0.0, -5.0], z, zero, 1.0, 7.0, s)
        firsts("the sphere behind the origin, t_min = 0: none", [0.0, 0.0, 5.0], z, zero,
               1.0, 0.0, s)
        firsts("origin on the sphere, entering, t_min = 1e-4: the far root",
               [1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], zero, 1.0, 1e-4, s)
        firsts("origin within a rounding of the sphere, leaving, t_min = 1e-4: none",
               [0.6, 0.8, 0.0], [0.6, 0.8, 0.0], zero, 1.0, 1e-4, s)
        firsts("a unit sphere 1e4 away, 0.9 radii off, t_min = 0", [0.9, 0.0, -1e4], z, zero,
               1.0, 0.0, s)
        firsts("grazing, 5 away, 1 - 2^-12 radii off, t_min = 0", [1.0 - 2.0 ** -12, 0.0,
               -5.0], z, zero, 1.0, 0.0, s)
    firsts("1e12 away, 0.5 radii off, t_min = 0", [0.5, 0.0, -1e12], z, zero, 1.0, 0.0)
    firsts("1e12 away, oblique, D = C - O, t_min = 0", o, [c[i] - o[i] for i in range(3)],
           c, 1.0, 0.0)
    firsts("origin within a rounding of the sphere, entering, t_min = 1e-9",
           [0.6, 0.8, 0.0], [-0.6, -0.8, 0.0], zero, 1.0, 1e-9)
    firsts("the line only (t_min = -MAX), from inside", [0.1, 0.2, 0.3], [0.6, -0.8, 0.0],
           zero, 1.0, -MAX)

    # The parallelogram.
    def quads(why, o, d, c, e1, e2, as_single=False):
        args = o + d + c + e1 + e2
        if as_single:
            args = [f32(x) for x in args]
        for verb in ["quad_hit", "quad_coords"]:
            add(why, verb, *args)

    ex, ey = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]
    quads("a unit square 5 away, hit at its centre", [0.5, 0.5, 5.0], [0.0, 0.0, -1.0], zero,
          ex, ey)
    def aim(o, c, e1, e2, a, b):
        return unit([c[i] + a * e1[i] + b * e2[i] - o[i] for i in range(3)])

    c, e1, e2 = [-0.5, 0.0, 0.5], [1.5, 0.2, -0.3], [0.4, 1.2, 0.6]
    quads("an oblique ray, an oblique parallelogram", [0.3, -1.0, 4.0],
          aim([0.3, -1.0, 4.0], c, e1, e2, 0.3, 0.6), c, e1, e2)
    quads("hit from behind (the normal points away)", [0.25, 0.75, -5.0], [0.0, 0.0, 1.0],
          zero, ex, ey)
    quads("the Cornell box light, from the floor below it",
          [278.0, 0.0, 279.5], unit([0.01, 1.0, -0.02]), [343.0, 548.8, 227.0],
          [-130.0, 0.0, 0.0], [0.0, 0.0, 105.0])
    quads("a hit exactly on an edge (a = 0 exactly)", [0.0, 0.5, 5.0], [0.0, 0.0, -1.0],
          zero, ex, ey)
    quads("a hit exactly at a corner (a = b = 1)", [1.0, 1.0, 5.0], [0.0, 0.0, -1.0], zero,
          ex, ey)
    quads("just inside an edge, by 1e-12", [1e-12, 0.5, 5.0], [0.0, 0.0, -1.0], zero,
          ex, ey)
    quads("just outside an edge, by 1e-12", [-1e-12, 0.5, 5.0], [0.0, 0.0, -1.0], zero,
          ex, ey)
    quads("just inside the far edge, a = 1 - 2^-52", [below(1.0, 2), 0.5, 5.0],
          [0.0, 0.0, -1.0], zero, ex, ey)
    quads("a nearly parallel ray, n.D = -1e-10, meeting the plane 1e3 along",
          [0.5, -0.5, 1e-7], unit([0.0, 1.0, -1e-10]), zero, [1.0, 0.0, 0.0],
          [0.0, 1e4, 0.0])
    quads("a grazing ray, n.D = 1e-8, on a long strip", [0.5, 0.0, 1e-8 * 0.5],
          unit([0.0, 1.0, -1e-8]), zero, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    quads("1e12 away, hitting the centre of a unit square", [0.5, 0.5, 1e12],
          [0.0, 0.0, -1.0], zero, ex, ey)
    quads("1e12 away, oblique, aimed at (0.3, 0.6)", [1e12, -4e11, 5e11],
          unit([0.3 - 1e12, 0.6 + 4e11, -5e11]), zero, ex, ey)
    quads("a tiny parallelogram (1e-6) 1e3 away", [0.0, 0.0, 1e3],
          [5e-7 / 1e3, 5e-7 / 1e3, -1.0], zero, [1e-6, 0.0, 0.0], [0.0, 1e-6, 0.0])
    quads("a thin parallelogram: edges at an angle of 1e-9", [0.5, 0.5e-9 * 0.5, 1.0],
          [0.0, 0.0, -1.0], zero, [1.0, 0.0, 0.0], [1.0, 1e-9, 0.0])
    quads("a parallelogram far from the coordinates' origin, ray from near it",
          [1e6 + 0.5, 1e6 + 0.5, 1e6 + 1e-3], [0.0, 0.0, -1.0], [1e6, 1e6, 1e6], ex, ey)
    quads("far from the coordinates' origin, tilted, ray from near it",
          [1e6 + 0.5, 1e6 + 0.25, 1e6 + 0.75], unit([-0.1, 0.2, -1.0]), [1e6, 1e6, 1e6],
          [1.0, 0.0, 0.5], [0.0, 1.0, 0.25])
    quads("origin on the plane (t = 0): none", [0.5, 0.5, 0.0], [0.0, 0.0, -1.0], zero,
          ex, ey)
    quads("origin 1e-300 above the plane", [0.5, 0.5, 1e-300], [0.0, 0.0, -1.0], zero,
          ex, ey)
    quads("a subnormal direction component", [0.5, 0.5, 5.0], [5e-324, 0.0, -1.0], zero,
          ex, ey)
    quads("the plane behind the origin: none", [0.5, 0.5, 5.0], [0.0, 0.0, 1.0], zero, ex, ey)
    quads("a huge parallelogram (1e6), oblique", [1.0, 2.0, 3.0], unit([0.3, -0.4, -1.0]),
          [-5e5, -5e5, -1.0], [1e6, 0.0, 1e3], [0.0, 1e6, -2e3])
    for s in [True]:
        quads("a unit square 5 away (inputs singles)", [0.25, 0.75, 5.0], [0.0, 0.0, -1.0],
              zero, ex, ey, s)
        quads("an oblique parallelogram, 1e3 away (inputs singles)", [0.3, -1.0, 1e3],
              aim([0.3, -1.0, 1e3], c, e1, e2, 0.7, 0.2), c, e1, e2, s)
    return out
