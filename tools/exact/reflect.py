"""Mirror reflection and Snell refraction in vector form (chapter Reflection and
refraction, src/optics/reflect.rs)."""
import math

from mpmath import mpf, sqrt

from exact import Verb, below, above

TITLE = "mirror reflection and Snell refraction of a direction"
CHAPTER = "Reflection and refraction (chapters/optics/reflect.md)"


def dot(u, v):
    return sum(a * b for a, b in zip(u, v))


def reflect(wx, wy, wz, nx, ny, nz):
    """w_o = w_i - 2 (w_i . n) n."""
    w, n = (wx, wy, wz), (nx, ny, nz)
    k = 2 * dot(w, n)
    return [a - k * b for a, b in zip(w, n)]


def refract(wx, wy, wz, nx, ny, nz, n1, n2):
    """With m the normal facing the light (w_i . m <= 0), cos_i = -w_i . m, eta = n1/n2:
    cos_t^2 = 1 - eta^2 (1 - cos_i^2); none (total internal reflection) if negative;
    w_t = eta w_i + (eta cos_i - cos_t) m."""
    w, m = (wx, wy, wz), (nx, ny, nz)
    cos_i = -dot(w, m)
    if cos_i < 0:
        m = tuple(-c for c in m)
        cos_i = -cos_i
    eta = n1 / n2
    c2 = 1 - eta * eta * (1 - cos_i * cos_i)
    if c2 < 0:
        return None
    k = eta * cos_i - sqrt(c2)
    return [eta * a + k * b for a, b in zip(w, m)]


VERBS = [
    Verb("reflect", ["wix", "wiy", "wiz", "nx", "ny", "nz"], ["wox", "woy", "woz"], 1,
         "the mirror direction w_i - 2 (w_i . n) n", reflect),
    Verb("refract", ["wix", "wiy", "wiz", "nx", "ny", "nz", "n1", "n2"],
         ["wtx", "wty", "wtz"], 1,
         "Snell's transmitted direction from index n1 into n2, none under total internal"
         " reflection", refract),
]


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def incident(cos_i, normal=(0.0, 0.0, 1.0), phi=0.0):
    """A direction travelling towards the surface of unit normal `normal` at the cosine
    cos_i (its sine from sqrt((1 - c)(1 + c))), in doubles."""
    s = math.sqrt((1 - cos_i) * (1 + cos_i))
    n = normal
    # A tangent orthogonal to n, then rotated by phi about n.
    helper = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
    t = unit([helper[1] * n[2] - helper[2] * n[1], helper[2] * n[0] - helper[0] * n[2],
              helper[0] * n[1] - helper[1] * n[0]])
    b = [n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]]
    c, d = math.cos(phi), math.sin(phi)
    return [s * (c * t[i] + d * b[i]) - cos_i * n[i] for i in range(3)]


def critical_cos(n1, n2):
    return float(sqrt(1 - (mpf(n2) / mpf(n1)) ** 2))


def cases():
    out = []

    def add(why, verb, *args):
        out.append((why, verb, list(args)))

    z = (0.0, 0.0, 1.0)
    tilted = tuple(unit([1.0, 2.0, 2.0]))

    # Reflection.
    for n, where in [(z, "n = +z"), (tilted, "n = (1, 2, 2)/3")]:
        add(f"normal incidence, {where}", "reflect", *[-c for c in n], *n)
        add(f"45 degrees, {where}", "reflect", *incident(math.sqrt(0.5), n), *n)
        add(f"near-grazing, cos_i = 1e-8, {where}", "reflect", *incident(1e-8, n), *n)
        add(f"near-normal, cos_i = 1 - 2^-53, {where}", "reflect",
            *incident(below(1.0), n, 0.3), *n)
        add(f"the normal on the far side, 45 degrees, {where}", "reflect",
            *incident(math.sqrt(0.5), n, 1.1), *[-c for c in n])
    add("grazing: w_i . n = 0 exactly", "reflect", 1.0, 0.0, 0.0, *z)
    add("grazing: w_i . n = 0 exactly, oblique", "reflect", 0.6, -0.8, 0.0, *z)
    add("cos_i = 1e-300", "reflect", 1.0, 0.0, -1e-300, *z)
    add("a subnormal normal component", "reflect", 0.6, 0.0, -0.8, 5e-324, 0.0, 1.0)
    add("a subnormal incident component", "reflect", 5e-324, 0.6, -0.8, *z)
    add("w_i nearly along n: an output component crossing 0", "reflect",
        *unit([1e-9, -2e-9, -1.0]), *tilted)

    # Refraction.
    pairs = [(1.0, 1.5, "air to glass"), (1.5, 1.0, "glass to air"),
             (1.0, 4.0, "index ratio 4"), (4.0, 1.0, "index ratio 1/4"),
             (1.0, 1.0000001, "nearly matched indices, n2/n1 - 1 = 1e-7"),
             (1.0000001, 1.0, "nearly matched, leaving the denser side"),
             (1.333, 1.333, "matched indices")]
    for n1, n2, pair in pairs:
        for n, where in [(z, ""), (tilted, ", tilted normal")]:
            w = f"{pair}{where}"
            add(f"normal incidence, {w}", "refract", *[-c for c in n], *n, n1, n2)
            add(f"45 degrees, {w}", "refract", *incident(math.sqrt(0.5), n), *n, n1, n2)
            add(f"near-grazing, cos_i = 1e-8, {w}", "refract", *incident(1e-8, n), *n,
                n1, n2)
            add(f"cos_i = 1 - 2^-53, {w}", "refract", *incident(below(1.0), n, 0.3), *n,
                n1, n2)
        add(f"grazing, cos_i = 0 exactly, {pair}", "refract", 0.6, 0.8, 0.0, *z, n1, n2)
        add(f"the normal on the far side, 45 degrees, {pair}", "refract",
            *incident(math.sqrt(0.5), z, 0.4), 0.0, 0.0, -1.0, n1, n2)
        if n1 > n2:
            cc = critical_cos(n1, n2)
            for c, what in [(cc, "the double nearest the critical cosine"),
                            (above(cc), "one double above the critical cosine"),
                            (below(cc), "one double below the critical cosine"),
                            (cc * (1 + 1e-12), "1e-12 above the critical cosine (transmits)"),
                            (cc * (1 - 1e-12), "1e-12 below the critical cosine (total"
                             " internal reflection)"),
                            (cc * (1 + 1e-6), "1e-6 above the critical cosine")]:
                add(f"{what}, {pair}", "refract", *incident(c), *z, n1, n2)
    return out
