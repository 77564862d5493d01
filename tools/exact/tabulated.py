"""Tabulated 1D densities: the piecewise-constant table's inverse CDF (the right end of
every plateau), its density and its CDF (the sampler's inverse), and the piecewise-linear
table's segment inverse and CDF (chapter Tabulated distributions,
src/sampling/tabulated.rs).

A table is the trailing arguments of a verb: for n bins, the n + 1 edges, then the n
values. Its CDF is a sum of products of doubles, computed here exactly (in rationals):
256 bits could not hold a sum of masses 1e300 and 1e-300 apart."""
import math
from fractions import Fraction

from mpmath import mp, mpf, sqrt

from exact import Verb, below, above, f32

TITLE = "Tabulated distributions: inverse CDF, density, CDF; the linear segment's inverse"
CHAPTER = "Tabulated distributions (chapters/sampling/tabulated.md)"


def frac(x):
    """An mpf as an exact rational (its sign, mantissa and exponent)."""
    sign, man, exp, _ = mpf(x)._mpf_
    if not man:
        return Fraction(0)
    return (-1) ** sign * Fraction(man) * Fraction(2) ** exp


def real(q):
    return mpf(q.numerator) / mpf(q.denominator)


def table(args):
    t = [frac(a) for a in args]
    n = (len(t) - 1) // 2
    edges, values = t[: n + 1], t[n + 1:]
    masses = [v * (edges[i + 1] - edges[i]) for i, v in enumerate(values)]
    total = sum(masses)
    levels = [Fraction(0)]
    for m in masses:
        levels.append(levels[-1] + m / total)
    return edges, values, levels, total


def sample(u, *args):
    """inf {x : F(x) > u}: the bin i with C_i <= u < C_(i+1), x linear within it."""
    edges, values, levels, _ = table(args)
    u = frac(u)
    for i in range(len(values)):
        if levels[i] <= u < levels[i + 1]:
            t = (u - levels[i]) / (levels[i + 1] - levels[i])
            return [real(edges[i] + t * (edges[i + 1] - edges[i]))]
    raise ValueError("u outside [0, 1)")


def pdf(x, *args):
    edges, values, _, total = table(args)
    x = frac(x)
    for i in range(len(values)):
        if edges[i] <= x < edges[i + 1]:
            return [real(values[i] / total)]
    return [mpf(0)]


def cdf(x, *args):
    edges, values, levels, _ = table(args)
    x = frac(x)
    if x < edges[0]:
        return [mpf(0)]
    for i in range(len(values)):
        if edges[i] <= x < edges[i + 1]:
            s = (x - edges[i]) / (edges[i + 1] - edges[i])
            return [real(levels[i] + s * (levels[i + 1] - levels[i]))]
    return [mpf(1)]


def linear_table(args):
    t = [frac(a) for a in args]
    n = len(t) // 2
    knots, values = t[:n], t[n:]
    masses = [(values[i] + values[i + 1]) / 2 * (knots[i + 1] - knots[i])
              for i in range(n - 1)]
    total = sum(masses)
    levels = [Fraction(0)]
    for m in masses:
        levels.append(levels[-1] + m / total)
    return knots, values, levels


def linear_sample(u, *args):
    """The piecewise-linear table's inf {x : F(x) > u}: the segment i with
    C_i <= u < C_(i+1), then the root t of the segment's quadratic CDF at the fraction
    xi = (u - C_i) / (C_(i+1) - C_i) of its mass (xi and 1 - xi exact, as rationals)."""
    knots, values, levels = linear_table(args)
    u = frac(u)
    for i in range(len(knots) - 1):
        if levels[i] <= u < levels[i + 1]:
            xi = (u - levels[i]) / (levels[i + 1] - levels[i])
            a, b = real(values[i]), real(values[i + 1])
            d = a + sqrt(real(1 - xi) * a * a + real(xi) * b * b)
            t = real(xi) * (a + b) / d if d != 0 else mpf(0)
            return [real(knots[i]) + t * real(knots[i + 1] - knots[i])]
    raise ValueError("u outside [0, 1)")


def segment_inverse(a, b, xi):
    """The t in [0, 1] with (b - a) t^2 / 2 + a t = xi (a + b) / 2: the root
    xi (a + b) / (a + sqrt((1 - xi) a^2 + xi b^2)), every term non-negative."""
    d = a + sqrt((1 - xi) * a * a + xi * b * b)
    if d == 0:
        return [mpf(0)]
    return [xi * (a + b) / d]


def segment_cdf(a, b, s):
    return [s * (a * (2 - s) + b * s) / (a + b)]


VERBS = [
    Verb("tabulated_sample", ["u", "edges_then_values..."], ["x"], 0,
         "the piecewise-constant table's inverse CDF inf {x : F(x) > u} (n + 1 edges,"
         " then n values)", sample),
    Verb("tabulated_pdf", ["x", "edges_then_values..."], ["p"], 0,
         "the normalised density at x: value / integral in x's bin, 0 outside", pdf),
    Verb("tabulated_cdf", ["x", "edges_then_values..."], ["u"], 1,
         "the CDF at x (the sampler's inverse), linear within each bin", cdf),
    Verb("linear_sample", ["u", "knots_then_values..."], ["x"], 0,
         "the piecewise-linear table's inverse CDF inf {x : F(x) > u} (n knots, then n"
         " values)", linear_sample),
    Verb("segment_inverse", ["a", "b", "xi"], ["t"], 0,
         "within a linear segment from density a to b, the t below which a fraction xi"
         " of its mass lies", segment_inverse),
    Verb("segment_cdf", ["a", "b", "s"], ["xi"], 1,
         "the fraction of a linear segment's mass below s: s (a (2 - s) + b s) / (a + b)",
         segment_cdf),
]


TABLES = [
    ([0.0, 1.0], [1.0], "a single bin on [0, 1]"),
    ([2.0, 5.0], [3.7], "a single bin on [2, 5]"),
    ([1e6, 1e6 + 1], [0.25], "a single bin far from 0, [1e6, 1e6 + 1]"),
    ([0.0, 1.0, 2.0], [1.0, 1.0], "two equal bins"),
    ([0.0, 1.0, 2.0, 3.0], [1.0, 0.0, 1.0], "a zero bin in the middle, plateau at 1/2"),
    ([0.0, 1.0, 2.0, 3.0], [1.0, 0.0, 2.0], "a zero bin, plateau at 1/3 (not a double)"),
    ([0.0, 1.0, 2.0, 3.0], [0.0, 1.0, 0.0], "leading and trailing zero bins"),
    ([0.0, 0.5, 1.0, 1.5, 2.0, 2.5], [0.0, 0.0, 3.0, 0.0, 0.0],
     "runs of zero bins either side of one with mass"),
    ([0.0, 1.0, 2.0], [1e300, 1e-300], "weights 1e300 and 1e-300: the second bin's"
                                        " probability 1e-600 underflows"),
    ([0.0, 1.0, 2.0], [1e-300, 1e300], "weights 1e-300 and 1e300: the first bin's"
                                        " probability underflows"),
    ([0.0, 1.0, 2.0, 3.0], [5e-324, 1.0, 5e-324], "subnormal weights either side"),
    ([0.0, 0.1, 0.35, 1.0, 4.0, 4.000001], [2.0, 0.0, 5.0, 0.25, 1e6],
     "uneven bins, a zero bin, a narrow bin of high value"),
    ([0.0, f32(0.3), 1.0], [f32(0.7), 1.0], "a table of singles"),
]


def levels_of(edges, values):
    _, _, levels, _ = table([mpf(e) for e in edges] + [mpf(v) for v in values])
    return levels


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    tiny = 5e-324
    for edges, values, what in TABLES:
        t = edges + values
        us = [
            (0.0, "u = 0"),
            (tiny, "subnormal u"),
            (2.0 ** -53, "u = 2^-53"),
            (f32(0.3), "u = 0.3 as a single"),
            (0.5, "u = 1/2 exactly"),
            (1 - 2.0 ** -24, "u = 1 - 2^-24, the largest single below 1"),
            (below(1.0), "u = 1 - 2^-53, the largest double below 1"),
        ]
        for k, c in enumerate(levels_of(edges, values)[1:-1], 1):
            c = float(c)
            us.append((c, f"u at the CDF's level {k} (the double nearest it)"))
            us.append((below(c), f"one double below the CDF's level {k}"))
            us.append((above(c), f"one double above the CDF's level {k}"))
        seen = set()
        if values[0] > 0 and levels_of(edges, values)[1] < Fraction(2) ** -1075:
            # Not u = 0 where the first bin's probability (1e-600) underflows: the exact
            # answer x_0 lies where the density the sampler stores (and returns) is 0, so
            # the sampler, which never returns a point of zero pdf, answers the next edge.
            # The chapter says so; it is a choice, not a loss of digits.
            seen.add(0.0)
        for u, why in us:
            if u in seen or not (0 <= u < 1):
                continue
            seen.add(u)
            add(f"{what}: {why}", "tabulated_sample", u, *t)
        xs = [(e, f"edge {i}") for i, e in enumerate(edges)]
        xs += [(below(e), f"one double below edge {i}") for i, e in enumerate(edges)]
        xs += [(0.5 * (edges[i] + edges[i + 1]), f"the middle of bin {i}")
               for i in range(len(values))]
        for x, why in xs:
            add(f"{what}: the density at {why}", "tabulated_pdf", x, *t)
            add(f"{what}: the CDF at {why}", "tabulated_cdf", x, *t)
    linear = [
        ([0.0, 1.0], [0.0, 1.0], "a ramp from 0: the density is 0 at the first knot"),
        ([0.0, 1.0], [1.0, 0.0], "a ramp down to 0 at the last knot"),
        ([2.0, 3.0], [1.0, 1.0 + 1e-12], "a nearly constant segment"),
        ([0.0, 1.0, 2.0], [0.0, 1.0, 0.0], "a triangle: zero at both ends"),
        ([0.0, 1.0, 2.0, 3.0], [1.0, 0.0, 0.0, 1.0], "a segment of zero mass in the middle"),
        ([0.0, 1.0, 2.0], [1e-300, 1e300, 1e-300], "values 1e-300 and 1e300"),
        ([0.0, f32(0.3), 1.0], [f32(0.7), 0.0, 1.0], "a table of singles"),
    ]
    for knots, values, what in linear:
        t = knots + values
        _, _, levels = linear_table([mpf(x) for x in t])
        us = [(0.0, "u = 0"), (tiny, "subnormal u"), (2.0 ** -53, "u = 2^-53"),
              (f32(0.3), "u = 0.3 as a single"), (0.5, "u = 1/2 exactly"),
              (below(1.0), "u = 1 - 2^-53")]
        for k, c in enumerate(levels[1:-1], 1):
            c = float(real(c))
            us += [(c, f"u at the CDF's level {k}"), (below(c), f"below level {k}"),
                   (above(c), f"above level {k}")]
        seen = set()
        for u, why in us:
            if u in seen or not (0 <= u < 1):
                continue
            seen.add(u)
            add(f"{what}: {why}", "linear_sample", u, *t)
    segs = [
        (1.0, 1.0, "a constant segment: t = xi"),
        (0.0, 1.0, "a = 0: t = sqrt(xi)"),
        (1.0, 0.0, "b = 0: the density falls to 0"),
        (1.0, 1.0 + 1e-12, "b = a (1 + 1e-12): the quadratic formula cancels"),
        (1.0, above(1.0), "b one double above a"),
        (1e-300, 1e300, "a = 1e-300, b = 1e300"),
        (1e300, 1e-300, "a = 1e300, b = 1e-300"),
        (tiny, 1.0, "a subnormal"),
        (3.0, 7.0, "an ordinary segment"),
        (f32(0.2), f32(0.9), "singles"),
    ]
    for a, b, what in segs:
        for xi, why in [(0.0, "xi = 0"), (tiny, "subnormal xi"), (1e-300, "xi = 1e-300"),
                        (2.0 ** -53, "xi = 2^-53"), (0.5, "xi = 1/2"),
                        (f32(0.3), "xi = 0.3 as a single"),
                        (1 - 2.0 ** -24, "xi = 1 - 2^-24"),
                        (below(1.0), "xi = 1 - 2^-53"), (1.0, "xi = 1")]:
            add(f"{what}; {why}", "segment_inverse", a, b, xi)
        for s, why in [(0.0, "s = 0"), (tiny, "subnormal s"), (0.5, "s = 1/2"),
                       (below(1.0), "s = 1 - 2^-53"), (1.0, "s = 1")]:
            add(f"{what}; {why}", "segment_cdf", a, b, s)
    return out
