"""Fresnel reflectance and transmittance of a dielectric interface, Schlick's approximation
and the Chebyshev fit (chapter Fresnel and Schlick, src/optics/fresnel.rs)."""
import math

from mpmath import mp, mpf, sqrt, cos, pi

from exact import Verb, below, above

TITLE = "Fresnel reflectance and transmittance, Schlick, the fit"
CHAPTER = "Fresnel and Schlick (chapters/optics/fresnel.md)"


def cos_t(c, n1, n2):
    """cos theta_t, or None past the critical angle (exactly: the sign of cos^2)."""
    c2 = 1 - (n1 / n2) ** 2 * (1 - c * c)
    if c2 < 0:
        return None
    return sqrt(c2)


def amplitudes(c, n1, n2):
    c = min(abs(c), mpf(1))
    if n1 == n2:
        return [mpf(0), mpf(0), mpf(1), mpf(1)]
    t = cos_t(c, n1, n2)
    if t is None:
        return None
    a, b, d, e = n1 * c, n2 * t, n2 * c, n1 * t
    return [(a - b) / (a + b), (d - e) / (d + e), 2 * a / (a + b), 2 * a / (d + e)]


def reflectance(c, n1, n2):
    amp = amplitudes(c, n1, n2)
    if amp is None:
        return [mpf(1)]
    return [(amp[0] ** 2 + amp[1] ** 2) / 2]


def transmittance(c, n1, n2):
    if n1 == n2:
        return [mpf(1), mpf(1)]
    c = min(abs(c), mpf(1))
    t = cos_t(c, n1, n2)
    if t is None:
        return [mpf(0), mpf(0)]
    a, b, d, e = n1 * c, n2 * t, n2 * c, n1 * t
    if a + b == 0:
        return [mpf(0), mpf(0)]
    return [4 * a * b / (a + b) ** 2, 4 * a * b / (d + e) ** 2]


def less_dense_cos(c, n1, n2):
    c = min(abs(c), mpf(1))
    return c if n1 <= n2 else cos_t(c, n1, n2)


def schlick(c, n1, n2):
    x = less_dense_cos(c, n1, n2)
    if x is None:
        return [mpf(1)]
    r0 = ((n1 - n2) / (n1 + n2)) ** 2
    return [r0 + (1 - r0) * (1 - x) ** 5]


def fit(n1, n2, c):
    """The polynomial of degree 8 interpolating the exact reflectance (on the less dense
    side) at the Chebyshev points of the second kind of [0, 1], at the less dense side's
    cosine; clamped to [0, 1]."""
    lo, hi = (n1, n2) if n1 <= n2 else (n2, n1)
    x = less_dense_cos(c, n1, n2)
    if x is None:
        return [mpf(1)]
    d = 8
    nodes = [(cos(pi * j / d) + 1) / 2 for j in range(d + 1)]
    values = [reflectance(t, lo, hi)[0] for t in nodes]
    # Barycentric formula for Chebyshev points of the second kind: weights (-1)^j, halved
    # at the ends.
    num = den = mpf(0)
    for j, (t, v) in enumerate(zip(nodes, values)):
        if x == t:
            return [min(max(v, mpf(0)), mpf(1))]
        w = (-1) ** j * (mpf(1) / 2 if j in (0, d) else 1)
        num += w * v / (x - t)
        den += w / (x - t)
    return [min(max(num / den, mpf(0)), mpf(1))]


VERBS = [
    Verb("fresnel_amplitudes", ["cos_i", "n1", "n2"], ["r_s", "r_p", "t_s", "t_p"], 1,
         "amplitude coefficients (Born & Wolf's signs), none under total internal reflection",
         amplitudes),
    Verb("fresnel", ["cos_i", "n1", "n2"], ["R"], 1,
         "unpolarised reflectance (R_s + R_p) / 2, 1 under total internal reflection",
         reflectance),
    Verb("fresnel_transmittance", ["cos_i", "n1", "n2"], ["T_s", "T_p"], 1,
         "transmittances T_s, T_p, 0 under total internal reflection", transmittance),
    Verb("schlick", ["cos_i", "n1", "n2"], ["R"], 1,
         "Schlick's R0 + (1 - R0)(1 - cos)^5 with the less dense side's cosine", schlick),
    Verb("fresnel_fit", ["n1", "n2", "cos_i"], ["R"], 1,
         "the degree-8 Chebyshev interpolant of the reflectance, at the less dense side's"
         " cosine", fit),
]


def critical_cos(n1, n2):
    """The double nearest cos of the critical angle, sqrt(1 - (n2/n1)^2)."""
    return float(sqrt(1 - (mpf(n2) / mpf(n1)) ** 2))


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    pairs = [(1.0, 1.5, "air to glass"), (1.5, 1.0, "glass to air"),
             (1.0, 4.0, "index ratio 4 (air to germanium)"),
             (4.0, 1.0, "index ratio 1/4, critical angle 14.5 degrees"),
             (1.0, 1.0000001, "nearly matched indices, n2/n1 - 1 = 1e-7"),
             (1.0000001, 1.0, "nearly matched, leaving the denser side"),
             (1.333, 1.333, "matched indices: no interface")]
    for verb in ["fresnel_amplitudes", "fresnel", "fresnel_transmittance", "schlick"]:
        for n1, n2, pair in pairs:
            add(f"normal incidence, {pair}", verb, 1.0, n1, n2)
            add(f"grazing: cos_i = 0 exactly, {pair}", verb, 0.0, n1, n2)
            add(f"near-grazing, cos_i = 1e-8, {pair}", verb, 1e-8, n1, n2)
            add(f"subnormal cos_i = 5e-324, {pair}", verb, 5e-324, n1, n2)
            add(f"45 degrees, {pair}", verb, math.sqrt(0.5), n1, n2)
            add(f"cos_i = 1 - 2^-53 (the double below 1), {pair}", verb, below(1.0), n1, n2)
            if n1 > n2:
                cc = critical_cos(n1, n2)
                add(f"the double nearest the critical angle's cosine, {pair}", verb, cc, n1, n2)
                add(f"one double above the critical cosine (transmits), {pair}", verb,
                    above(cc), n1, n2)
                add(f"one double below the critical cosine (total internal reflection),"
                    f" {pair}", verb, below(cc), n1, n2)
                add(f"1e-12 above the critical cosine, {pair}", verb, cc * (1 + 1e-12),
                    n1, n2)
            if n1 < n2:
                # Brewster's angle: r_p = 0, crossing zero.
                cb = float(mpf(n1) / sqrt(mpf(n1) ** 2 + mpf(n2) ** 2))
                add(f"Brewster's angle (r_p crosses 0), {pair}", verb, cb, n1, n2)
    for n1, n2, pair in pairs[:4]:
        for c in [0.0, 1e-8, 0.1, 0.5, math.sqrt(0.5), 0.9, 1.0]:
            add(f"the fit at cos = {c:g}, {pair}", "fresnel_fit", n1, n2, c)
    return out
