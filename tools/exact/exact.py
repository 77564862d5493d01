"""The exact answers of the corpora of hard inputs (`data/corpus/*.txt`).

Each corpus is made from one module of this folder (`sphere.py`, `fresnel.py`, ...), which
declares its verbs (the routine's mathematics written in mpmath) and its cases (the hard
inputs, each with a line saying why it is hard). For every case this script evaluates the
mathematics at 256 bits (77 digits) from the *same double inputs*, so that its answer is
the exact value for those inputs, and the problem's condition number there:

    cond_k = sum_i |x_i * d y_k / d x_i| / max(|y_k|, scale)   (for a smooth routine)

measured as how far the answer moves when each input moves by one rounding (`condition`
below; `scale` is the verb's output scale, 0 for a relative measure, 1 for a direction or a
reflectance, so that an answer crossing 0 is measured against its scale).

    tools/exact/run                 # rewrite every corpus
    tools/exact/run --check         # fail (status 1) if a corpus is not what its module makes
    tools/exact/run fresnel disc    # only these

The file format is described in `data/corpus/README.md`; the checker that reads it is
`raylemma::check::accuracy` (chapter *Accuracy against exact arithmetic*).
"""
import importlib
import math
import os
import struct
import sys

from mpmath import mp, mpf, nstr

mp.prec = 256

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
CORPUS = os.path.join(ROOT, "data", "corpus")

# The corpora, one per chapter, in book order.
GROUPS = [
    "sphere",
    "uniform",
    "disc",
    "cosine",
    "tabulated",
    "frame",
    "reflect",
    "fresnel",
    "dispersion",
    "thinfilm",
    "shadow",
    "colour",
    "wavelength",
    "display",
]



class Verb:
    """A routine's mathematics: `f(*args)` of mpf arguments returns a list of mpf (one per
    output) or None (no answer: a miss, total internal reflection)."""

    def __init__(self, name, args, outs, scale, doc, f):
        self.name, self.args, self.outs = name, args, outs
        self.scale, self.doc, self.f = scale, doc, f

    def declaration(self):
        return (
            f"verb {self.name} {' '.join(self.args)} -> {' '.join(self.outs)}"
            f" ; scale {self.scale:g} ; {self.doc}"
        )


def f32(x):
    """x rounded to the nearest single-precision float (as a Python float)."""
    return struct.unpack("f", struct.pack("f", x))[0]


def below(x, k=1):
    """The k-th double below x."""
    for _ in range(k):
        x = math.nextafter(x, -math.inf)
    return x


def above(x, k=1):
    """The k-th double above x."""
    for _ in range(k):
        x = math.nextafter(x, math.inf)
    return x


def number(x):
    """A double as text that reads back exactly (shortest round trip)."""
    if x == 0:
        return "-0.0" if math.copysign(1, x) < 0 else "0.0"
    return repr(float(x))


def exact_text(y):
    """An exact answer with 25 significant digits: more than a double's 17, so that it
    rounds correctly to a double and to a single."""
    if y == 0:
        return "0.0"
    return nstr(y, 25, min_fixed=-4, max_fixed=8)


def cond_text(c):
    # Beyond the largest double (an answer of 1e-600 that one rounding of an input moves
    # to another bin's density) it is as undetermined as a change of kind: `inf`.
    if c is None or not mp.isfinite(c) or c > sys.float_info.max:
        return "inf"
    return nstr(c, 3, min_fixed=-4, max_fixed=8) if c != 0 else "0"


def condition(verb, args, y, u):
    """Per output, how far the answer moves when every input moves by one rounding:
    sum_i max_(+-) |y(.., x_i (1 +- u), ..) - y| / (u max(|y|, scale)), u the unit
    roundoff (2^-53, or 2^-24 for singles). For a smooth function this is the condition
    number sum_i |x_i dy/dx_i| / max(|y|, scale); near a square root's branch point (a
    tangent ray, the critical angle) it is the larger, true, sensitivity that the
    derivative misses. None if a perturbation changes the kind of answer (a hit becomes a
    miss): the decision itself is not determined by the inputs."""
    moved = [mpf(0)] * len(y)
    for i, x in enumerate(args):
        if x == 0:
            continue
        worst = [mpf(0)] * len(y)
        for sign in (1, -1):
            p = list(args)
            p[i] = x * (1 + sign * u)
            yp = verb.f(*p)
            if yp is None:
                return None
            worst = [max(w, abs(a - b)) for w, a, b in zip(worst, yp, y)]
        moved = [m + w for m, w in zip(moved, worst)]
    out = []
    for m, yk in zip(moved, y):
        s = max(abs(yk), mpf(verb.scale))
        out.append(m / (u * s) if s > 0 else (mpf(0) if m == 0 else mp.inf))
    return out


def flips(verb, args, u):
    """True if moving one input by one rounding gives an answer where there is none."""
    for i, x in enumerate(args):
        for sign in (1, -1):
            p = list(args)
            p[i] = x * (1 + sign * u)
            if verb.f(*p) is not None:
                return True
    return False


U64 = mpf(2) ** -53
U32 = mpf(2) ** -24


def case_line(verb, args):
    """`verb x1 ... = y1 ... @ c1 ...`, with a second `@ c1 ...` for singles' roundings
    when every input is a single; `verb x1 ... = none`, or `= none @ inf` when one rounding
    of an input would give an answer. A condition is `inf` when one rounding of an input
    changes the kind of answer."""
    question = " ".join([verb.name] + [number(x) for x in args])
    margs = [mpf(x) for x in args]
    single = all(f32(x) == x for x in args)
    y = verb.f(*margs)
    if y is None:
        flip = flips(verb, margs, U64) or (single and flips(verb, margs, U32))
        return f"{question} = none" + (" @ inf" if flip else "")
    if len(y) != len(verb.outs):
        raise ValueError(f"{verb.name}: {len(y)} outputs, declared {len(verb.outs)}")

    def conds(u):
        c = condition(verb, margs, y, u)
        return " ".join(cond_text(v) for v in (c if c is not None else [None] * len(y)))

    line = f"{question} = {' '.join(exact_text(v) for v in y)} @ {conds(U64)}"
    if single:
        line += f" @ {conds(U32)}"
    return line


def make(group):
    """The text of the corpus of the module `group`."""
    module = importlib.import_module(group)
    verbs = {v.name: v for v in module.VERBS}
    lines = [
        f"# raylemma corpus: {module.TITLE}",
        f"# Chapter: {module.CHAPTER}. Made by tools/exact/{group}.py with tools/exact/exact.py",
        "# (mpmath, 256 bits): edit the module, not this file. Format: data/corpus/README.md.",
        "",
    ]
    lines += [v.declaration() for v in module.VERBS]
    for why, name, args in module.cases():
        if name not in verbs:
            raise ValueError(f"{group}: a case of the undeclared verb {name}")
        if len(args) < len(verbs[name].args) and not verbs[name].args[-1].endswith("..."):
            raise ValueError(f"{group}: {name} takes {len(verbs[name].args)} arguments")
        if any(not math.isfinite(x) for x in args):
            raise ValueError(f"{group}: {name} {args}: inputs must be finite")
        lines.append("")
        lines.append(f"# {why}")
        lines.append(case_line(verbs[name], [float(x) for x in args]))
    return "\n".join(lines) + "\n"


def main(argv):
    sys.path.insert(0, HERE)
    check = "--check" in argv
    names = [a for a in argv if not a.startswith("--")] or GROUPS
    stale = []
    for group in names:
        if group not in GROUPS:
            print(f"tools/exact: no corpus named {group} (one of {', '.join(GROUPS)})")
            return 2
        if not os.path.exists(os.path.join(HERE, group + ".py")):
            continue
        text = make(group)
        path = os.path.join(CORPUS, group + ".txt")
        old = open(path).read() if os.path.exists(path) else None
        if check:
            if old != text:
                stale.append(path)
            continue
        if old != text:
            tmp = path + ".tmp"
            with open(tmp, "w") as out:
                out.write(text)
            os.replace(tmp, path)
            cases = sum(1 for line in text.splitlines() if line and line[0] not in "#v")
            print(f"tools/exact: wrote {os.path.relpath(path, ROOT)} ({cases} cases)")
    if stale:
        for p in stale:
            print(f"tools/exact: {os.path.relpath(p, ROOT)} is not what its module makes;"
                  " run tools/exact/run")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
