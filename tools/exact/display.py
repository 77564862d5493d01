"""The display transforms: the sRGB transfer function and its inverse (IEC 61966-2-1, with
the standard's decimals), the power-law encoding, and the move toward the grey of equal
luminance that brings a colour into [0, 1]^3 (chapter From spectrum to display,
src/spectral/display.rs)."""
from mpmath import mp, mpf

from exact import Verb, below, above, f32

TITLE = "the sRGB transfer function and its inverse, gamma encoding, the gamut fit"
CHAPTER = "From spectrum to display (chapters/spectral/display.md)"

BREAK_LIN, BREAK_ENC = mpf("0.0031308"), mpf("0.04045")
A, OFF, SLOPE, EXP = mpf("1.055"), mpf("0.055"), mpf("12.92"), mpf("2.4")
LUMA = [mpf("0.2126"), mpf("0.7152"), mpf("0.0722")]


def srgb_encode(x):
    if x > BREAK_LIN:
        return [A * x ** (1 / EXP) - OFF]
    return [SLOPE * x if x > 0 else mpf(0)]


def srgb_decode(v):
    if v > BREAK_ENC:
        return [((v + OFF) / A) ** EXP]
    return [v / SLOPE if v > 0 else mpf(0)]


def gamma_encode(x, g):
    return [x ** (1 / g) if x > 0 else mpf(0)]


def fit(r, g, b):
    """c' = Y + s (c - Y) with the largest s <= 1 that brings every component into [0, 1];
    white for Y >= 1, black for Y <= 0; clipped to [0, 1]."""
    c = [r, g, b]
    y = sum(w * v for w, v in zip(LUMA, c))
    if y >= 1:
        return [mpf(1)] * 3
    if y <= 0:
        return [mpf(0)] * 3
    hi, lo = max(c), min(c)
    s = mpf(1)
    if hi > 1:
        s = min(s, (1 - y) / (hi - y))
    if lo < 0:
        s = min(s, y / (y - lo))
    return [min(max(y + s * (v - y), mpf(0)), mpf(1)) for v in c]


VERBS = [
    Verb("srgb_encode", ["x"], ["V"], 0,
         "the sRGB curve: 12.92 x up to 0.0031308, 1.055 x^(1/2.4) - 0.055 above, 0 for x <= 0",
         srgb_encode),
    Verb("srgb_decode", ["V"], ["x"], 0,
         "its inverse: V / 12.92 up to 0.04045, ((V + 0.055)/1.055)^2.4 above, 0 for V <= 0",
         srgb_decode),
    Verb("gamma_encode", ["x", "gamma"], ["V"], 0, "x^(1/gamma), 0 for x <= 0", gamma_encode),
    Verb("fit_to_gamut", ["r", "g", "b"], ["r", "g", "b"], 1,
         "toward the grey of equal luminance until every component is in [0, 1]", fit),
]


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    knee = 0.0031308
    for x, why in [(0.0, "0"), (1.0, "1"), (knee, "the knee 0.0031308 (as a double)"),
                   (below(knee), "one double below the knee"), (above(knee), "one double above"),
                   (knee * (1 + 1e-9), "1e-9 above the knee"), (0.5, "1/2"), (0.18, "18 % grey"),
                   (below(1.0), "1 - 2^-53"), (1e-3, "1e-3"), (0.01, "0.01"),
                   (5e-324, "the smallest subnormal"), (1e-310, "a subnormal"),
                   (2.2250738585072014e-308, "the smallest normal"),
                   (-1e-300, "slightly negative"), (-5e-324, "the negative subnormal"),
                   (-0.0, "-0"), (2.0, "2, over-bright"), (1e3, "1e3, over-bright"), (1e6, "1e6"),
                   (f32(0.2140), "a single, 0.214"), (f32(0.0031308), "the knee as a single")]:
        add(f"sRGB encode at {why}", "srgb_encode", x)
    kv = 0.04045
    for v, why in [(0.0, "0"), (1.0, "1"), (kv, "the knee 0.04045"), (below(kv), "below the knee"),
                   (above(kv), "above the knee"), (0.5, "1/2"), (below(1.0), "1 - 2^-53"),
                   (5e-324, "the smallest subnormal"), (1e-310, "a subnormal"),
                   (-1e-300, "slightly negative"), (2.0, "2"), (1e3, "1e3"), (1e6, "1e6"),
                   (f32(0.7353), "a single")]:
        add(f"sRGB decode at {why}", "srgb_decode", v)
    for x, g, why in [(0.5, 2.2, "1/2, gamma 2.2"), (1e-300, 2.2, "1e-300"),
                      (5e-324, 2.2, "the smallest subnormal"), (below(1.0), 2.2, "1 - 2^-53"),
                      (0.0, 2.2, "0"), (-0.1, 2.2, "negative"), (0.18, 1.0, "gamma 1"),
                      (1e300, 2.2, "huge"), (0.5, 1e-3, "gamma 1e-3 (x^1000)")]:
        add(f"gamma encode at {why}", "gamma_encode", x, g)
    for c, why in [((0.5, 0.5, 0.5), "a grey (unchanged)"), ((1.0, 1.0, 1.0), "white"),
                   ((2.0, 0.5, 0.1), "over-bright red"), ((-0.2, 0.8, 0.3), "a negative red"),
                   ((1.5, -0.1, 0.2), "over-bright and negative"),
                   ((0.0, 0.0, 0.0), "black"), ((above(1.0), 0.9, 0.9), "one double over 1"),
                   ((-5e-324, 0.5, 0.5), "a negative subnormal component"),
                   ((1e300, 0.0, 0.0), "a huge red (Y >= 1: white)"),
                   ((4.0, 0.0, 0.0), "red 4, Y = 0.85 (s = (1 - Y)/(4 - Y))"),
                   ((4.7, 0.0, 0.0), "Y just below 1"),
                   ((-1e-17, 1e-17, 1e-17), "tiny, Y ~ 1e-17"),
                   ((f32(1.2), f32(0.3), f32(-0.05)), "single inputs")]:
        add(f"gamut fit: {why}", "fit_to_gamut", *c)
    return out
