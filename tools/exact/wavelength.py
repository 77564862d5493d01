"""Hero wavelengths and the visible-range importance density (chapter Wavelength sampling
and hero wavelengths, src/spectral/wavelength.rs).

The range is 360..830 nm; the visible density is p(l) = a / (t1 - t0) / cosh^2(a (l - c)),
a = 0.0072 per nm, c = 538 nm, t_i = tanh(a (l_i - c)) at the range's ends."""
from mpmath import mp, mpf, tanh, atanh, cosh, floor

from exact import Verb, below, above

TITLE = "hero wavelengths, the visible importance density, its CDF and inverse"
CHAPTER = "Wavelength sampling and hero wavelengths (chapters/spectral/wavelength.md)"

LO, HI = mpf(360), mpf(830)
A, C = mpf(0.0072), mpf(538)  # the crate's doubles (a is not a decimal in binary)
T0, T1 = tanh(A * (LO - C)), tanh(A * (HI - C))
N = 4


def frac(x):
    return x - floor(x)


def hero_uniform(u):
    """l_j = 360 + ((u + j/4) mod 1) 470."""
    return [LO + frac(u + mpf(j) / N) * (HI - LO) for j in range(N)]


def sample_visible(u):
    """The inverse CDF and the density there: t = t0 + u (t1 - t0), l = c + atanh(t)/a,
    p = a (1 - t^2) / (t1 - t0); l clamped to the range."""
    t = T0 + u * (T1 - T0)
    if not (-1 < t < 1):
        return None
    lam = C + atanh(t) / A
    return [min(max(lam, LO), HI), A * (1 - t * t) / (T1 - T0)]


def visible_pdf(nm):
    if not (LO <= nm <= HI):
        return [mpf(0)]
    return [A / (T1 - T0) / cosh(A * (nm - C)) ** 2]


def visible_cdf(nm):
    nm = min(max(nm, LO), HI)
    return [min(max((tanh(A * (nm - C)) - T0) / (T1 - T0), mpf(0)), mpf(1))]


VERBS = [
    Verb("hero_uniform", ["u"], ["l0", "l1", "l2", "l3"], 0,
         "the four hero wavelengths 360 + ((u + j/4) mod 1) 470 nm", hero_uniform),
    Verb("visible_sample", ["u"], ["lambda", "pdf"], 0,
         "the visible density's inverse CDF at u and the density there", sample_visible),
    Verb("visible_pdf", ["lambda_nm"], ["pdf"], 0,
         "the visible density a / (t1 - t0) / cosh^2(a (l - c)), 0 outside 360..830", visible_pdf),
    Verb("visible_cdf", ["lambda_nm"], ["P"], 1,
         "its CDF (tanh(a (l - c)) - t0) / (t1 - t0), clamped", visible_cdf),
]


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    us = [(0.0, "u = 0"), (below(1.0), "u = 1 - 2^-53, the last double below 1"),
          (0.5, "u = 1/2"), (0.25, "u = 1/4: lane 3 lands exactly on the wrap (1.0 mod 1 = 0)"),
          (below(0.25), "one double below 1/4: lane 3 just below the wrap"),
          (above(0.25), "one double above 1/4: lane 3 just past the wrap"),
          (below(0.75), "one double below 3/4: lane 1 at 1 - 2^-53"),
          (0.75, "u = 3/4: lane 1 exactly on the wrap"),
          (below(0.5), "one double below 1/2"), (5e-324, "the subnormal u = 5e-324"),
          (1e-300, "u = 1e-300"), (1e-17, "u = 1e-17: lanes j/4 + tiny"),
          (0.1, "u = 0.1"), (0.9, "u = 0.9"), (1 / 3, "u = 1/3"), (0.123456789, "u = 0.123456789"),
          (below(1.0, 2), "the second double below 1"),
          (0.999999, "u = 0.999999")]
    for u, why in us:
        add(why, "hero_uniform", u)
    # The inverse CDF: its ends, t = 0 (l = c, where ln((1 + t)/(1 - t)) loses relative
    # accuracy), and the clamp.
    t_zero = float(-T0 / (T1 - T0))
    for u, why in us + [(t_zero, "u where t = 0 (lambda = c = 538 nm)"),
                        (t_zero * (1 + 1e-10), "u where t = 1e-10 (lambda near c)"),
                        (above(t_zero), "one double above t = 0"),
                        (below(t_zero), "one double below t = 0")]:
        add(f"visible inverse CDF: {why}", "visible_sample", u)
    for nm, why in [(360.0, "the range's short end"), (830.0, "the range's long end"),
                    (below(360.0), "one double below 360 nm (outside: 0)"),
                    (above(830.0), "one double above 830 nm (outside: 0)"),
                    (538.0, "the centre c"), (550.0, "550 nm"), (400.0, "400 nm"),
                    (700.0, "700 nm"), (above(360.0), "one double above 360 nm"),
                    (below(830.0), "one double below 830 nm"), (1e6, "far outside: 1 mm"),
                    (0.0, "0 nm"), (-538.0, "a negative wavelength")]:
        add(f"visible density at {why}", "visible_pdf", nm)
        add(f"visible CDF at {why}", "visible_cdf", nm)
    return out
