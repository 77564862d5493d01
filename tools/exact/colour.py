"""Planck's law, the Wyman-Sloan-Shirley fit of the CIE 1931 colour-matching functions, and
XYZ to linear sRGB (chapter Spectra and CIE colour, src/spectral/spectrum.rs and
src/spectral/cie.rs)."""
from mpmath import mp, mpf, exp, matrix, lu_solve

from exact import Verb, below, above, f32

TITLE = "Planck's law, the analytic CIE fit, XYZ to linear sRGB"
CHAPTER = "Spectra and CIE colour (chapters/spectral/colour.md)"

# The SI's exact constants (2019).
H = mpf("6.62607015e-34")
C = mpf(299792458)
K = mpf("1.380649e-23")


def planck(nm, kelvin):
    """B(lambda, T) = 2 h c^2 / lambda^5 / (e^(hc/(lambda k T)) - 1), per nm; 0 for a
    wavelength or temperature <= 0."""
    if not (nm > 0 and kelvin > 0):
        return [mpf(0)]
    lam = nm / mpf(10) ** 9
    x = H * C / (lam * K * kelvin)
    # 1/(e^x - 1) = e^-x / (1 - e^-x): the same number, evaluated without a huge e^x.
    q = exp(-x)
    return [2 * H * C * C / lam ** 5 * q / (1 - q) / mpf(10) ** 9]


# The fit's lobes (weight, mu, 1/sigma below, 1/sigma above), as the crate's doubles.
FIT = [
    [(1.056, 599.8, 0.0264, 0.0323), (0.362, 442.0, 0.0624, 0.0374),
     (-0.065, 501.1, 0.0490, 0.0382)],
    [(0.821, 568.8, 0.0213, 0.0247), (0.286, 530.9, 0.0613, 0.0322)],
    [(1.217, 437.0, 0.0845, 0.0278), (0.681, 459.0, 0.0385, 0.0725)],
]


def cmf_fit(nm):
    """sum of w exp(-((lambda - mu) s)^2 / 2), s the width on lambda's side; 0 outside
    360..830 nm."""
    if not (360 <= nm <= 830):
        return [mpf(0)] * 3
    out = []
    for lobes in FIT:
        total = mpf(0)
        for w, mu, below_, above_ in lobes:
            d = nm - mpf(mu)
            s = mpf(below_) if d < 0 else mpf(above_)
            total += mpf(w) * exp(-(d * s) ** 2 / 2)
        out.append(total)
    return out


def srgb_matrix():
    """XYZ -> linear sRGB: the inverse of the matrix whose columns are the primaries' XYZ
    (x/y, 1, (1-x-y)/y), each scaled so that the columns sum to D65 (x 0.3127, y 0.3290),
    with IEC 61966-2-1's decimals."""
    prim = [(mpf("0.64"), mpf("0.33")), (mpf("0.30"), mpf("0.60")), (mpf("0.15"), mpf("0.06"))]
    white = (mpf("0.3127"), mpf("0.3290"))

    def xyz(c):
        return [c[0] / c[1], mpf(1), (1 - c[0] - c[1]) / c[1]]

    m = matrix(3, 3)
    for j, p in enumerate(prim):
        for i, v in enumerate(xyz(p)):
            m[i, j] = v
    s = lu_solve(m, matrix(xyz(white)))
    for j in range(3):
        for i in range(3):
            m[i, j] *= s[j]
    return m ** -1


M = srgb_matrix()


def to_srgb(x, y, z):
    v = M * matrix([x, y, z])
    return [v[0], v[1], v[2]]


VERBS = [
    Verb("planck", ["lambda_nm", "kelvin"], ["B"], 0,
         "Planck's spectral radiance (W sr^-1 m^-2 nm^-1), 0 where lambda or T <= 0", planck),
    Verb("cmf_fit", ["lambda_nm"], ["x", "y", "z"], 1,
         "the Wyman-Sloan-Shirley multi-lobe fit of x-bar, y-bar, z-bar, 0 outside 360..830 nm",
         cmf_fit),
    Verb("xyz_to_srgb", ["X", "Y", "Z"], ["R", "G", "B"], 0,
         "CIE XYZ to linear sRGB (the inverse of the primaries' matrix, white D65 at Y = 1)",
         to_srgb),
]

# hc/k in nm K: x = C2 / (lambda T).
C2_NM_K = float(H * C / K * 10 ** 9)


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    temps = [(1.0, "1 K"), (10.0, "10 K"), (300.0, "room temperature"), (1000.0, "1000 K"),
             (2856.0, "illuminant A's 2856 K"), (5778.0, "the sun's 5778 K"),
             (1e4, "10 000 K"), (1e6, "1e6 K"), (1e9, "1e9 K")]
    waves = [(360.0, "the render range's short end"), (830.0, "the render range's long end"),
             (below(360.0), "one double below 360 nm"), (above(830.0), "one double above 830 nm"),
             (550.0, "550 nm"), (1.0, "far outside: 1 nm"), (1e6, "far outside: 1 mm"),
             (1e12, "far outside: 1 km"), (1e30, "far outside: 1e30 nm")]
    for t, tw in temps:
        for nm, w in waves:
            add(f"{w}, {tw}", "planck", nm, t)
    for nm, t, why in [
        (1e-3, 1e9, "1e-3 nm at 1e9 K (x = 14)"),
        (0.0, 5778.0, "wavelength 0 (nothing emitted)"),
        (-550.0, 5778.0, "a negative wavelength"),
        (550.0, 0.0, "0 K"),
        (f32(550.3), f32(5778.3), "single-precision inputs"),
        (f32(360.7), f32(1.3), "single-precision inputs, 1.3 K"),
    ]:
        add(why, "planck", nm, t)
    # Around the exponential's overflow (e^x overflows a double past x = 709.78).
    for x in [700.0, 709.0, 709.78, 709.79, 710.0, 720.0, 740.0, 745.0, 800.0, 1400.0,
              1500.0]:
        for nm in [10.0, 360.0]:
            add(f"x = hc/(lambda k T) = {x:g} at {nm:g} nm (e^x near or past overflow)",
                "planck", nm, C2_NM_K / (nm * x))
    # expm1's regime: x small (Rayleigh-Jeans), where e^x - 1 cancels.
    for x in [1e-3, 1e-8, 1e-12, 1e-16, 1e-20]:
        add(f"x = {x:g} (Rayleigh-Jeans: e^x - 1 cancels)", "planck", 830.0, C2_NM_K / (830 * x))
    for nm, why in [(360.0, "the range's short end"), (830.0, "the range's long end"),
                    (below(360.0), "one double below 360 nm (outside: 0)"),
                    (above(830.0), "one double above 830 nm (outside: 0)"),
                    (599.8, "x-bar's main peak"), (501.1, "the negative lobe's centre"),
                    (437.0, "z-bar's peak"), (568.8, "y-bar's peak"),
                    (f32(555.5), "a single-precision wavelength"), (1e6, "far outside"),
                    (0.0, "0 nm"), (5e-324, "a subnormal wavelength")]:
        add(f"the fit at {why}", "cmf_fit", nm)
    for nm in range(380, 781, 20):
        add(f"the fit at {nm} nm", "cmf_fit", float(nm))
    # Where x-bar's fit crosses zero (the negative lobe against the blue one).
    add("the fit near x-bar's minimum (about 505 nm)", "cmf_fit", 504.0)
    for xyz, why in [
        ((0.95047, 1.0, 1.08883), "D65 white (R = G = B = 1)"),
        ((1.0, 1.0, 1.0), "equal-energy white"),
        ((0.0, 0.0, 0.0), "black"),
        ((0.64 / 0.33, 1.0, 0.03 / 0.33), "the red primary's chromaticity (G, B near 0)"),
        ((0.3, 0.6, 0.1), "a green (R, B cancel)"),
        ((0.1, 0.5, 0.05), "a spectral green outside the gamut (R < 0)"),
        ((0.17, 0.005, 0.8), "a violet outside the gamut"),
        ((1e-300, 1e-300, 1e-300), "tiny values"),
        ((5e-324, 5e-324, 5e-324), "subnormal values"),
        ((1e300, 1e300, 1e300), "huge values"),
        ((f32(0.31), f32(0.42), f32(0.53)), "single-precision inputs"),
        ((1.0, 0.0, 0.0), "X alone"),
        ((0.0, 1.0, 0.0), "Y alone"),
        ((0.0, 0.0, 1.0), "Z alone"),
    ]:
        add(f"XYZ to sRGB: {why}", "xyz_to_srgb", *xyz)
    return out
