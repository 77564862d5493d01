"""Uniform points of the unit disc: the polar and the concentric map, their inverses and
the density (chapter The unit disc, src/sampling/disc.rs)."""
import math

from mpmath import mp, mpf, sqrt, cos, sin, atan, atan2, pi

from exact import Verb, below, above, f32

TITLE = "The unit disc: the polar and concentric maps, their inverses, the density"
CHAPTER = "The unit disc (chapters/sampling/disc.md)"


def concentric(u1, u2):
    """Shirley and Chiu's map with a = 2u - 1: r = a_x, phi = (pi/4) a_y / a_x where
    |a_x| > |a_y|, else r = a_y, phi = pi/2 - (pi/4) a_x / a_y; the centre at a = 0."""
    ax, ay = 2 * u1 - 1, 2 * u2 - 1
    if ax == 0 and ay == 0:
        return [mpf(0), mpf(0)]
    if abs(ay) < abs(ax):
        r, phi = ax, pi / 4 * (ay / ax)
    else:
        r, phi = ay, pi / 2 - pi / 4 * (ax / ay)
    return [r * cos(phi), r * sin(phi)]


def polar(u1, u2):
    r, phi = sqrt(u1), 2 * pi * u2
    return [r * cos(phi), r * sin(phi)]


def concentric_invert(x, y):
    r = sqrt(x * x + y * y)
    if r == 0:
        return [mpf(1) / 2, mpf(1) / 2]
    if abs(x) >= abs(y):
        ax = r if x > 0 else -r
        ay = ax * atan(y / x) / (pi / 4)
    else:
        ay = r if y > 0 else -r
        ax = ay * atan(x / y) / (pi / 4)
    return [(ax + 1) / 2, (ay + 1) / 2]


def polar_invert(x, y):
    phi = atan2(y, x) if (x, y) != (0, 0) else mpf(0)
    if phi < 0:
        phi += 2 * pi
    return [x * x + y * y, phi / (2 * pi)]


def pdf(x, y):
    return [1 / pi if x * x + y * y <= 1 else mpf(0)]


VERBS = [
    Verb("disc_concentric", ["u1", "u2"], ["x", "y"], 1,
         "Shirley and Chiu's concentric map of a = 2u - 1 (two wedges, negative radii)",
         concentric),
    Verb("disc_polar", ["u1", "u2"], ["x", "y"], 1,
         "the polar map: r = sqrt(u1), phi = 2 pi u2", polar),
    Verb("disc_concentric_invert", ["x", "y"], ["u1", "u2"], 1,
         "the concentric map's inverse, wedge by wedge; (1/2, 1/2) at the centre",
         concentric_invert),
    Verb("disc_polar_invert", ["x", "y"], ["u1", "u2"], 1,
         "the polar map's inverse: u1 = x^2 + y^2, u2 = atan2(y, x) / (2 pi) in [0, 1)",
         polar_invert),
    Verb("disc_pdf", ["x", "y"], ["p"], 0,
         "the uniform disc density: 1 / pi where x^2 + y^2 <= 1, else 0", pdf),
]


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    tiny = 5e-324
    one = below(1.0)
    # Points of the square around the concentric map's wedge boundaries, after a = 2u - 1:
    # |a_x| = |a_y| (the diagonals), a_x = 0 or a_y = 0 (u = 1/2), and one double either
    # side; the corners u = 0 and u = 1 - 2^-53; the centre.
    grid = [
        ((0.5, 0.5), "the centre: a = (0, 0)"),
        ((above(0.5), 0.5), "one double right of the centre: a = (2^-52, 0)"),
        ((0.5, below(0.5)), "one double below the centre: a = (0, -2^-53)"),
        ((above(0.5), above(0.5)), "a = (2^-52, 2^-52): the diagonal next to the centre"),
        ((above(0.5), below(0.5)), "a = (2^-52, -2^-53): beside the centre, first wedge"),
        ((0.0, 0.0), "u = 0: the corner a = (-1, -1), on the diagonal"),
        ((one, one), "u = 1 - 2^-53 twice: the corner a = (1 - 2^-52, 1 - 2^-52)"),
        ((0.0, one), "the corner a = (-1, 1 - 2^-52): just off the anti-diagonal"),
        ((one, 0.0), "the corner a = (1 - 2^-52, -1): just off the anti-diagonal"),
        ((0.0, 0.5), "a = (-1, 0): the rim on the first wedge's centre line"),
        ((0.5, 0.0), "a = (0, -1): the rim on the second wedge's centre line"),
        ((0.5, one), "a = (0, 1 - 2^-52): a_x = 0 exactly"),
        ((above(0.5), one), "a = (2^-52, 1 - 2^-52): a_x one double from 0"),
        ((below(0.5), one), "a = (-2^-53, 1 - 2^-52): a_x one double from 0"),
        ((one, 0.5), "a = (1 - 2^-52, 0): a_y = 0 exactly"),
        ((one, above(0.5)), "a = (1 - 2^-52, 2^-52): a_y one double from 0"),
        ((0.3, 0.3), "u1 = u2 = 0.3: |a_x| = |a_y| exactly, the diagonal"),
        ((0.3, above(0.3)), "one double off the diagonal (second wedge)"),
        ((0.3, below(0.3)), "one double off the diagonal (first wedge)"),
        ((0.8, 0.2), "a = (0.6, -0.6) as computed: the anti-diagonal"),
        ((0.75, 0.25), "a = (1/2, -1/2) exactly: the anti-diagonal"),
        ((0.75, above(0.25)), "one double off the anti-diagonal"),
        ((0.75, below(0.25)), "one double off the anti-diagonal, the other side"),
        ((f32(0.9), f32(0.9)), "u1 = u2 = 0.9 as singles: the diagonal"),
        ((f32(0.9), f32(0.1)), "singles near the anti-diagonal"),
        ((f32(0.5), f32(0.7)), "singles: a_x = 0"),
        ((f32(0.6), f32(0.5)), "singles: a_y = 0"),
        ((f32(0.5) + 2.0 ** -24, 0.5), "the single right of 1/2: a = (2^-23, 0)"),
        ((f32(0.5) + 2.0 ** -24, 0.5 - 2.0 ** -25),
         "singles one step either side of the centre"),
        ((1 - 2.0 ** -24, 1 - 2.0 ** -24), "u = 1 - 2^-24 twice, the largest single below 1"),
        ((1 - 2.0 ** -24, 0.0), "singles: a corner"),
        ((tiny, 0.5), "subnormal u1: a_x = -1 after rounding"),
        ((0.5, tiny), "subnormal u2"),
        ((1e-17, 0.4), "u1 = 1e-17: 2 u1 - 1 rounds to -1"),
        ((f32(1e-4), f32(0.3)), "u1 = 1e-4 as a single: near the rim"),
        ((0.1, 0.6), "an ordinary point in the first wedge"),
        ((0.35, 0.95), "an ordinary point in the second wedge"),
        ((0.25, 0.75), "u = (1/4, 3/4): the diagonal, a = (-1/2, 1/2) exactly"),
    ]
    for (u1, u2), why in grid:
        add(why, "disc_concentric", u1, u2)
    polar_u = [
        ((0.0, 0.0), "u = 0: the centre"),
        ((tiny, 0.3), "subnormal u1: r = 2.2e-162"),
        ((1e-300, 0.25), "u1 = 1e-300, phi = pi/2: x crosses 0"),
        ((2.0 ** -53, 0.5), "u1 = 2^-53, phi = pi"),
        ((0.5, 0.125), "u1 = 1/2, phi = pi/4"),
        ((one, one), "u = 1 - 2^-53 twice: the rim, phi just below 2 pi"),
        ((one, 0.0), "the rim at phi = 0"),
        ((one, 0.75), "the rim at phi = 3 pi / 2"),
        ((f32(0.3), f32(0.7)), "singles"),
        ((1 - 2.0 ** -24, 1 - 2.0 ** -24), "u = 1 - 2^-24 twice (singles)"),
        ((2.0 ** -24, f32(0.1)), "u1 = 2^-24 (a single): near the centre"),
        ((0.25, 0.5), "u = (1/4, 1/2): the point (-1/2, 0)"),
    ]
    for (u1, u2), why in polar_u:
        add(why, "disc_polar", u1, u2)

    points = [
        ((0.0, 0.0), "the centre"),
        ((tiny, 0.0), "a subnormal point: x^2 underflows to 0"),
        ((tiny, -tiny), "subnormal, on the anti-diagonal"),
        ((1e-200, 3e-200), "x^2 + y^2 underflows: the radius is computed as 0"),
        ((1e-150, -1e-150), "x^2 just above the underflow: the anti-diagonal"),
        ((1.0, 0.0), "the rim on the x axis"),
        ((0.0, -1.0), "the rim on the -y axis"),
        ((-1.0, 0.0), "the rim on the -x axis, phi = pi"),
        ((math.sqrt(0.5), math.sqrt(0.5)), "the rim on the diagonal, |x| = |y|"),
        ((math.sqrt(0.5), -math.sqrt(0.5)), "the rim on the anti-diagonal"),
        ((0.3, 0.3), "|x| = |y| exactly, inside"),
        ((0.3, above(0.3)), "one double off the diagonal"),
        ((0.3, below(0.3)), "one double off the diagonal, the other side"),
        ((0.6, 0.8), "x^2 + y^2 is 1 + 4.4e-17 for these doubles: just outside"),
        ((one, 0.0), "just inside the rim"),
        ((1.0, -1e-300), "the rim, phi just below 2 pi"),
        ((1.0, -1e-16), "the rim, phi = 2 pi - 1e-16"),
        ((-0.5, 1e-300), "phi just below pi"),
        ((-0.5, -1e-300), "phi just above pi"),
        ((f32(0.6), f32(0.8)), "singles near the rim"),
        ((f32(-0.3), f32(0.4)), "singles, second quadrant"),
        ((f32(0.1), f32(-0.1)), "singles on the anti-diagonal"),
        ((f32(1e-4), f32(2e-4)), "singles near the centre"),
    ]
    # And the doubles nearest the exact images of the square's hard points.
    for (u1, u2), why in grid:
        x, y = (float(c) for c in concentric(mpf(u1), mpf(u2)))
        points.append(((x, y), f"the concentric image of ({why})"))
    for (x, y), why in points:
        add(why, "disc_concentric_invert", x, y)
    for (x, y), why in points[:23]:
        add(why, "disc_polar_invert", x, y)
    for (u1, u2), why in polar_u:
        x, y = (float(c) for c in polar(mpf(u1), mpf(u2)))
        add(f"the polar image of ({why})", "disc_polar_invert", x, y)
    for (x, y), why in points[:23]:
        add(f"the density at {why}", "disc_pdf", x, y)
    add("the density just outside the rim on the x axis", "disc_pdf", above(1.0), 0.0)
    add("the density far outside", "disc_pdf", 3.0, -4.0)
    return out
