"""The Sellmeier index n(lambda) of the three fits of data/sellmeier.csv, and the Abbe
number (chapter Dispersion, src/optics/dispersion.rs).

The coefficients are fixed per glass (one verb per material): they are read from the same
CSV the crate embeds, as the doubles the crate parses, so the only input a case rounds is
the wavelength (nm)."""
import csv
import math
import os

from mpmath import mp, mpf, sqrt, findroot

from exact import Verb, below, above, f32

TITLE = "the Sellmeier index of N-BK7, fused silica and water, the Abbe number"
CHAPTER = "Dispersion (chapters/optics/dispersion.md)"

HERE = os.path.dirname(os.path.abspath(__file__))
CSV = os.path.join(HERE, "..", "..", "data", "sellmeier.csv")


def table():
    """name -> list of (B, C) as mpf of the doubles the crate parses."""
    rows = [line for line in open(CSV) if line.strip() and not line.startswith("#")]
    out = {}
    for row in list(csv.reader(rows))[1:]:
        terms = []
        for i in range(4):
            b, c = row[3 + 2 * i].strip(), row[4 + 2 * i].strip()
            if b:
                terms.append((mpf(float(b)), mpf(float(c))))
        out[row[0].strip()] = terms
    return out


TERMS = table()
GLASSES = [("bk7", "N-BK7"), ("silica", "fused silica"), ("water", "water")]

# The crate's Fraunhofer/helium lines (nm), as the doubles it holds.
LINE_D, LINE_F, LINE_C = 587.5618, 486.1327, 656.2725


def n_squared(terms, nm):
    l2 = (mpf(nm) / 1000) ** 2
    return 1 + sum(b * l2 / (l2 - c) for b, c in terms)


def index_of(terms):
    def f(nm):
        n2 = n_squared(terms, nm)
        if n2 < 0:
            return None
        return [sqrt(n2)]

    return f


def abbe_of(terms):
    def f(d, fl, cl):
        n = [n_squared(terms, x) for x in (d, fl, cl)]
        if min(n) < 0 or n[1] == n[2]:
            return None
        nd, nf, nc = (sqrt(v) for v in n)
        return [(nd - 1) / (nf - nc)]

    return f


VERBS = []
for short, name in GLASSES:
    VERBS.append(Verb(f"n_{short}", ["lambda_nm"], ["n"], 0,
                      f"Sellmeier index of {name}, sqrt(1 + sum B_i l^2 / (l^2 - C_i)),"
                      " l = lambda_nm / 1000; none where n^2 < 0", index_of(TERMS[name])))
for short, name in GLASSES:
    VERBS.append(Verb(f"abbe_{short}", ["lambda_d", "lambda_F", "lambda_C"], ["V"], 0,
                      f"Abbe number (n(d) - 1) / (n(F) - n(C)) of {name}, wavelengths in nm",
                      abbe_of(TERMS[name])))


def zeros_nm(terms):
    """The wavelengths (nm) where n^2 crosses 0: one between each pair of adjacent
    poles where n^2 changes sign away from the poles (found on a fine grid, then refined)."""
    poles = sorted(1000 * sqrt(c) for _, c in terms)
    out = []
    edges = [mpf(1e-3)] + poles + [poles[-1] * 10]
    for lo, hi in zip(edges, edges[1:]):
        k = 4000
        xs = [lo + (hi - lo) * (j + mpf(1) / 2) / k for j in range(k)]
        vs = [n_squared(terms, x) for x in xs]
        for x0, x1, v0, v1 in zip(xs, xs[1:], vs, vs[1:]):
            # A sign change between two grid points with no pole between them.
            if (v0 < 0) != (v1 < 0) and abs(v0) < 50 and abs(v1) < 50:
                out.append(findroot(lambda x: n_squared(terms, x), (x0, x1),
                                    solver="anderson"))
    return out


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    ranges = {"N-BK7": (300.0, 2500.0), "fused silica": (210.0, 3710.0),
              "water": (182.0, 1129.0)}
    for short, name in GLASSES:
        verb = f"n_{short}"
        terms = TERMS[name]
        lo, hi = ranges[name]
        for x, why in [
            (360.0, "the render range's short end, 360 nm"),
            (below(360.0), "one double below 360 nm"),
            (830.0, "the render range's long end, 830 nm"),
            (above(830.0), "one double above 830 nm"),
            (550.0, "mid-visible, 550 nm"),
            (f32(550.3), "a single-precision wavelength, 550.3 nm as an f32"),
            (LINE_D, "the helium d line, 587.5618 nm"),
            (LINE_F, "the hydrogen F line"),
            (LINE_C, "the hydrogen C line"),
            (lo, "the fitted range's short end"),
            (hi, "the fitted range's long end"),
            (1.0, "far outside: 1 nm, below every pole (n^2 - 1 small and negative)"),
            (1e-3, "far outside: 1e-3 nm, n - 1 ~ -1e-10"),
            (1e-150, "far outside: 1e-150 nm, where n rounds to 1"),
            (5e-324, "the subnormal wavelength 5e-324 nm"),
            (0.0, "wavelength 0 exactly"),
            (-550.0, "a negative wavelength (the formula is even in lambda)"),
            (1e5, "far outside: 0.1 mm, beyond the infrared pole"),
            (1e9, "far outside: 1 m, n^2 -> 1 + sum B_i"),
            (1e150, "far outside: 1e150 nm, lambda^2 near 1e294"),
            (1e160, "far outside: 1e160 nm, lambda^2 overflows a double"),
            (1.7e308, "the largest wavelengths: 1.7e308 nm"),
        ]:
            add(f"{why}, {name}", verb, x)
        for c_pole in sorted(c for _, c in terms):
            p = float(1000 * sqrt(c_pole))
            for x, why in [
                (p, "the double nearest a pole sqrt(C_i)"),
                (below(p), "one double below a pole"),
                (above(p), "one double above a pole"),
                (p * (1 - 1e-9), "1e-9 below a pole (relatively)"),
                (p * (1 + 1e-9), "1e-9 above a pole"),
                (p * (1 - 1e-4), "1e-4 below a pole"),
                (p * (1 + 1e-4), "1e-4 above a pole"),
            ]:
                add(f"{why} ({p:.6g} nm), {name}", verb, x)
        for z in zeros_nm(terms):
            zd = float(z)
            for x, why in [
                (zd, "the double nearest a zero of n^2 (n -> 0)"),
                (below(zd), "one double below a zero of n^2"),
                (above(zd), "one double above a zero of n^2"),
                (zd * (1 - 1e-8), "1e-8 below a zero of n^2"),
                (zd * (1 + 1e-8), "1e-8 above a zero of n^2"),
            ]:
                add(f"{why} ({zd:.6g} nm), {name}", verb, x)
    for short, name in GLASSES:
        verb = f"abbe_{short}"
        add(f"the catalogue's lines d, F, C, {name}", verb, LINE_D, LINE_F, LINE_C)
        add(f"F and C 1 nm apart around d: n_F - n_C cancels, {name}", verb,
            LINE_D, LINE_D - 0.5, LINE_D + 0.5)
        add(f"F and C 1e-6 nm apart: n_F - n_C keeps 6 digits fewer, {name}", verb,
            LINE_D, LINE_D - 5e-7, LINE_D + 5e-7)
        add(f"F and C swapped (negative V), {name}", verb, LINE_D, LINE_C, LINE_F)
        add(f"the render range's ends as F and C, {name}", verb, 550.0, 360.0, 830.0)
        add(f"single-precision lines, {name}", verb, f32(LINE_D), f32(LINE_F), f32(LINE_C))
        add(f"far infrared lines (beyond the infrared pole), {name}", verb, 2e5, 1e5, 4e5)
    return out
