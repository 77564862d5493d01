"""Reflectance and transmittance of one thin film between two half-spaces, for s and p
light (chapter Thin-film interference, src/optics/thinfilm.rs).

The mathematics: Snell's cosines (complex past a critical angle, on the branch Re >= 0,
Im >= 0), the Fresnel amplitudes of the two interfaces, and the Airy sum of the multiple
reflections, r = (r12 + r23 z) / (1 + r12 r23 z), t = t12 t23 e^(i delta) / (1 + r12 r23 z),
z = e^(2 i delta), delta = 2 pi n2 d cos theta2 / lambda; R = |r|^2,
T = Re(n3 cos theta3) / (n1 cos theta1) |t|^2."""
import math

from mpmath import mp, mpf, mpc, sqrt, exp, pi, cos, sin

from exact import Verb, below, above

TITLE = "thin-film reflectance and transmittance (the Airy sum), s and p"
CHAPTER = "Thin-film interference (chapters/optics/thinfilm.md)"

I = mpc(0, 1)


def cos_in(n1, c1, n):
    """cos theta in a medium of index n: sqrt(1 - (n1/n)^2 (1 - c1^2)), Re >= 0, Im >= 0."""
    c2 = 1 - (n1 / n) ** 2 * (1 - c1 * c1)
    return mpc(sqrt(c2), 0) if c2 >= 0 else mpc(0, sqrt(-c2))


def airy(a1, a2, a3, phase):
    """(r, t) for admittances a1, a2, a3 (t is the s-like 2 a1 / ... amplitude; for p the
    caller rescales). The plain Airy sum, or (where a2 = 0 exactly and the sum is 0/0) its
    limit: the same expression multiplied through by (a1 + a2)(a2 + a3) e^(-i delta)/(2 a2)."""
    if a2 != 0:
        r12, r23 = (a1 - a2) / (a1 + a2), (a2 - a3) / (a2 + a3)
        t12, t23 = 2 * a1 / (a1 + a2), 2 * a2 / (a2 + a3)
        z = exp(2 * I * phase)
        den = 1 + r12 * r23 * z
        return (r12 + r23 * z) / den, t12 * t23 * exp(I * phase) / den
    raise ZeroDivisionError("a2 = 0: use the limit")


def film(n1, n2, n3, d, lam, c1):
    if c1 == 0:
        # Grazing: the limit cos1 -> 0 (every wave reflected, r = -1) as long as some
        # interface is there.
        return [mpf(1), mpf(1), mpf(0), mpf(0)]
    c2, c3 = cos_in(n1, c1, n2), cos_in(n1, c1, n3)
    k = 2 * pi / lam
    phase = k * n2 * d * c2
    out_r, out_t = [], []
    for pol in "sp":
        if pol == "s":
            a = [n1 * c1, n2 * c2, n3 * c3]
            kf = k * d
        else:
            a = [c1 / n1, c2 / n2, c3 / n3]
            kf = k * n2 * n2 * d
        if a[1] != 0:
            r, t = airy(a[0], a[1], a[2], phase)
        else:
            # The limit at the film's critical angle (S = K sin(delta)/delta = K).
            a1, _, a3 = a
            r = ((a1 - a3) - I * a1 * a3 * kf) / ((a1 + a3) + I * a1 * a3 * kf)
            t = 2 * a1 / ((a1 + a3) + I * a1 * a3 * kf)
        if pol == "p":
            # 2 a_i / (a_i + a_j) with a = cos/n is n_j/n_i times Born & Wolf's t_p (a ratio
            # of electric fields): the product over both interfaces is n3/n1 times theirs.
            t = t * (n1 / n3)
        out_r.append(abs(r) ** 2)
        out_t.append(t)
    flux = (n3 * c3).real / (n1 * c1)
    ts, tp = out_t
    return [out_r[0], out_r[1], flux * abs(ts) ** 2, flux * abs(tp) ** 2]


VERBS = [
    Verb("film", ["n1", "n2", "n3", "d_nm", "lambda_nm", "cos1"], ["R_s", "R_p", "T_s", "T_p"], 1,
         "a film of index n2 and thickness d between the ambient n1 and the substrate n3, at"
         " cos theta1 from the ambient: reflectances and transmittances, s and p", film),
]


def critical_cos(n1, n):
    """The double nearest the cosine (from the ambient) of the critical angle into n < n1."""
    return float(sqrt(1 - (mpf(n) / mpf(n1)) ** 2))


def cases():
    out = []

    def add(why, *args):
        out.append((why, "film", list(args)))

    stacks = [
        (1.0, 1.33, 1.0, 300.0, "a soap film in air"),
        (1.0, 1.38, 1.52, 100.0, "a quarter-wave coating of MgF2 on glass"),
        (2.4, 1.2, 2.0, 200.0, "the chapter's 2.4 / 1.2 / 2.0 (a less dense film)"),
        (1.5, 1.0, 1.5, 100.0, "an air gap between glass (frustrated total reflection)"),
        (1.0, 4.0, 1.0, 50.0, "index ratio 4, a germanium film in air"),
        (4.0, 1.0, 4.0, 50.0, "index ratio 1/4, an air gap in germanium"),
        (1.5, 1.4, 1.0, 150.0,
         "glass / 1.4 / air (totally reflecting at the substrate beyond 41.8°)"),
        (1.0, 1.0000001, 1.0, 300.0, "a film matched to its surroundings to 1e-7"),
        (1.5, 1.5, 1.0, 300.0, "a film of the ambient's index (no first interface)"),
        (1.0, 1.5, 1.5, 300.0, "a film of the substrate's index (no second interface)"),
        (1.0, 1.5, 1.0000001, 300.0, "a substrate matched to the ambient to 1e-7"),
    ]
    for n1, n2, n3, d, name in stacks:
        for c, why in [(1.0, "normal incidence"), (math.sqrt(0.5), "45 degrees"),
                       (below(1.0), "cos = 1 - 2^-53"), (1e-8, "near-grazing, cos = 1e-8"),
                       (5e-324, "subnormal cos = 5e-324"), (0.0, "grazing, cos = 0 exactly")]:
            add(f"{why}, {name}", n1, n2, n3, d, 550.0, c)
        for lam, why in [(360.0, "the render range's short end"),
                         (830.0, "the render range's long end"),
                         (1e6, "far outside: 1 mm"), (1.0, "far outside: 1 nm")]:
            add(f"{why}, {name}", n1, n2, n3, d, lam, 0.8)
        for dd, why in [(0.0, "zero thickness (a bare interface)"),
                        (1e-3, "a 1 pm film"), (5e-324, "a subnormal thickness"),
                        (1e9, "a 1 m film (phase ~1e7)"), (1e15, "a 1e15 nm film (phase ~1e13)")]:
            add(f"{why}, {name}", n1, n2, n3, dd, 550.0, 0.8)
        for m in sorted({n2, n3}):
            if m < n1:
                cc = critical_cos(n1, m)
                where = "the film's" if m == n2 else "the substrate's"
                for c, why in [(cc, f"the double nearest {where} critical cosine"),
                               (above(cc), f"one double above {where} critical cosine"),
                               (below(cc), f"one double below {where} critical cosine"),
                               (cc * (1 + 1e-12), f"1e-12 above {where} critical cosine"),
                               (cc * (1 - 1e-12), f"1e-12 below {where} critical cosine"),
                               (cc * (1 + 1e-6), f"1e-6 above {where} critical cosine"),
                               (cc * (1 - 1e-6), f"1e-6 below {where} critical cosine")]:
                    add(f"{why}, {name}", n1, n2, n3, d, 550.0, c)
                if m == n2:
                    add(f"a thick evanescent film (1e5 nm) past the critical angle, {name}",
                        n1, n2, n3, 1e5, 550.0, 0.5 * cc)
                    add(f"a thick evanescent film (1e5 nm) 1e-6 past the critical angle,"
                        f" {name}", n1, n2, n3, 1e5, 550.0, cc * (1 - 1e-6))
    # The chapter's second corner: near grazing over a sub-picometre film, substrate =
    # ambient (r12 -> -1, r23 -> 1).
    for c in [1e-12, 1e-9]:
        add(f"near grazing (cos = {c:g}) over a 1e-4 nm film, substrate = ambient", 1.0, 1.5,
            1.0, 1e-4, 550.0, c)
    # Exactly 0 in floating point, not exactly: cos1 = 0.6 under 1.25 | 1.0.
    add("cos1 = 0.6 under 1.25 / 1.0 (cos^2 theta2 rounds to 0 in floating point)", 1.25, 1.0,
        1.5, 100.0, 550.0, 0.6)
    return out
