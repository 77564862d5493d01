"""Cosine-weighted directions: Malley's method (the concentric disc lifted onto the
hemisphere), its inverse and density, and the source's seed in Cartesian form (chapter
Cosine-weighted hemisphere, src/sampling/cosine.rs)."""
from mpmath import mp, mpf, sqrt, cos, sin, pi

from exact import Verb, below, above, f32
from disc import concentric, concentric_invert

TITLE = "Cosine-weighted hemisphere: Malley's method, its inverse, the density, the seed"
CHAPTER = "Cosine-weighted hemisphere (chapters/sampling/cosine.md)"


def malley(u1, u2):
    """The concentric map's (x, y) lifted to z = sqrt(1 - x^2 - y^2).

    x^2 + y^2 = r^2 with r = max(|2 u1 - 1|, |2 u2 - 1|), and 1 - r is the distance
    d = 2 min(u1, 1 - u1, u2, 1 - u2) of u to the square's edge, exactly; so
    1 - x^2 - y^2 = d (2 - d). Written so because 256 bits cannot hold 1 - x^2 - y^2 for
    u1 = 1e-300 (it would round to 0): every input here is a double, and so is each term
    of d."""
    x, y = concentric(u1, u2)
    d = 2 * min(u1, 1 - u1, u2, 1 - u2)
    return [x, y, sqrt(d * (2 - d))]


def malley_pdf(u1, u2):
    return [malley(u1, u2)[2] / pi]


def malley_invert(x, y, z):
    return concentric_invert(x, y)


def seed(u1, u2):
    """sin theta = sqrt(u1), cos theta = sqrt(1 - u1), phi = 2 pi u2."""
    s, phi = sqrt(u1), 2 * pi * u2
    return [s * cos(phi), s * sin(phi), sqrt(1 - u1)]


def seed_pdf(u1, u2):
    return [sqrt(1 - u1) / pi]


def pdf(x, y, z):
    return [max(z, mpf(0)) / pi]


VERBS = [
    Verb("cosine_malley", ["u1", "u2"], ["x", "y", "z"], 1,
         "Malley's method: the concentric disc point lifted to z = sqrt(1 - x^2 - y^2)",
         malley),
    Verb("cosine_malley_pdf", ["u1", "u2"], ["p"], 0,
         "the density cos theta / pi of Malley's direction at u (relative: the rim's z)",
         malley_pdf),
    Verb("cosine_malley_invert", ["x", "y", "z"], ["u1", "u2"], 1,
         "Malley's inverse: the concentric map's inverse of (x, y)", malley_invert),
    Verb("cosine_seed", ["u1", "u2"], ["x", "y", "z"], 1,
         "the source's inverse CDF: sin theta = sqrt(u1), cos theta = sqrt(1 - u1),"
         " phi = 2 pi u2", seed),
    Verb("cosine_seed_pdf", ["u1", "u2"], ["p"], 0,
         "the density cos theta / pi = sqrt(1 - u1) / pi of the seed's direction at u",
         seed_pdf),
    Verb("cosine_pdf", ["x", "y", "z"], ["p"], 0,
         "the cosine-weighted density max(z, 0) / pi", pdf),
]


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    tiny = 5e-324
    one = below(1.0)
    rim = [
        (0.0, "u1 = 0: a_x = -1, on the rim, z = 0"),
        (tiny, "subnormal u1: 1 - r = 1e-323, z = 4.4e-162"),
        (1e-300, "u1 = 1e-300: z = 2e-150"),
        (1e-17, "u1 = 1e-17: 2 u1 - 1 rounds to -1, the naive lift gives z = 0"),
        (2.0 ** -53, "u1 = 2^-53, the generator's smallest step"),
        (1e-10, "u1 = 1e-10: 1 - x^2 - y^2 cancels, keeping 6 digits"),
        (2.0 ** -24, "u1 = 2^-24 (a single)"),
        (f32(1e-4), "u1 = 1e-4 as a single: near the rim in f32"),
        (f32(0.3), "u1 = 0.3 as a single"),
        (0.5, "u1 = 1/2: a_x = 0"),
        (above(0.5), "one double above 1/2: next to the centre"),
        (1 - 2.0 ** -24, "u1 = 1 - 2^-24, the largest single below 1"),
        (one, "u1 = 1 - 2^-53: a_x = 1 - 2^-52, the rim"),
    ]
    u2s = [
        (0.5, "u2 = 1/2: a_y = 0"),
        (f32(0.7), "u2 = 0.7 as a single"),
        (0.0, "u2 = 0: a_y = -1, on the rim too"),
        (one, "u2 = 1 - 2^-53"),
    ]
    for u1, w1 in rim:
        for u2, w2 in u2s:
            add(f"{w1}; {w2}", "cosine_malley", u1, u2)
            add(f"{w1}; {w2}", "cosine_malley_pdf", u1, u2)
    for u2, w2 in rim[1:6]:
        add(f"the rim in u2: {w2.replace('u1', 'u2').replace('a_x', 'a_y')}; u1 = 0.4",
            "cosine_malley", 0.4, u2)
        add(f"the rim in u2: {w2.replace('u1', 'u2').replace('a_x', 'a_y')}; u1 = 0.4",
            "cosine_malley_pdf", 0.4, u2)
    add("the centre: u = (1/2, 1/2), z = 1", "cosine_malley", 0.5, 0.5)
    add("the centre: u = (1/2, 1/2), z = 1", "cosine_malley_pdf", 0.5, 0.5)
    add("the diagonal at the rim: u1 = u2 = 1e-17", "cosine_malley", 1e-17, 1e-17)
    add("the diagonal at the rim: u1 = u2 = 1e-17", "cosine_malley_pdf", 1e-17, 1e-17)

    for u1, w1 in rim:
        for u2, w2 in u2s[:2]:
            x, y, z = (float(c) for c in malley(mpf(u1), mpf(u2)))
            add(f"the inverse at Malley's direction for ({w1}; {w2})",
                "cosine_malley_invert", x, y, z)
    add("the inverse at the zenith", "cosine_malley_invert", 0.0, 0.0, 1.0)
    add("the inverse on the horizon, on the diagonal", "cosine_malley_invert",
        0.7071067811865476, -0.7071067811865476, 0.0)
    add("the inverse at singles near the horizon", "cosine_malley_invert",
        f32(0.6), f32(-0.8), f32(1e-4))

    seeds = [
        (0.0, "u1 = 0: the zenith"),
        (tiny, "subnormal u1: sin theta = 2.2e-162"),
        (1e-300, "u1 = 1e-300"),
        (2.0 ** -24, "u1 = 2^-24 (a single)"),
        (f32(0.3), "u1 = 0.3 as a single"),
        (0.5, "u1 = 1/2: theta = pi/4"),
        (f32(0.99), "u1 = 0.99 as a single: near the horizon"),
        (f32(0.9999), "u1 = 0.9999 as a single: cos theta = 0.01"),
        (1 - 2.0 ** -24, "u1 = 1 - 2^-24: the horizon in f32, cos theta = 2^-12"),
        (below(1.0, 2), "u1 = 1 - 2^-52"),
        (one, "u1 = 1 - 2^-53: the horizon, cos theta = 2^-26.5"),
    ]
    for u1, w1 in seeds:
        for u2, w2 in [(0.0, "u2 = 0"), (0.25, "u2 = 1/4: x crosses 0"),
                       (f32(0.7), "u2 = 0.7 as a single")]:
            add(f"{w1}; {w2}", "cosine_seed", u1, u2)
        add(f"{w1}", "cosine_seed_pdf", u1, f32(0.7))

    dirs = [
        ((0.0, 0.0, 1.0), "the zenith"),
        ((1.0, 0.0, 0.0), "the horizon: z = 0"),
        ((0.0, 1.0, -0.5), "below the horizon: density 0"),
        ((1.0, 0.0, tiny), "subnormal z: the density rounds into the subnormals"),
        ((1.0, 0.0, 1e-300), "z = 1e-300"),
        ((0.6, 0.8, 1e-8), "z = 1e-8, a grazing direction"),
        ((f32(0.6), f32(0.8), f32(1e-4)), "singles, near the horizon"),
        ((f32(0.36), f32(0.48), f32(0.8)), "singles"),
    ]
    for d, why in dirs:
        add(f"the density at {why}", "cosine_pdf", *d)
    return out
