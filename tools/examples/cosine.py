"""A cosine-weighted hemisphere sampler, checked from outside Rust (chapter *Checks from
any language*). The inverse CDF: x = sqrt(u1) cos(2 pi u2), y = sqrt(u1) sin(2 pi u2),
z = sqrt(1 - u1); its density z / pi; its inverse.

It reads questions on standard input, one a line, and writes one answer a line:

    warp u1 u2     ->  x y z
    pdf x y z      ->  p
    invert x y z   ->  u1 u2

    raylemma check sampler --target cosine-hemisphere --inverse --program "python3 cosine.py"
"""

import math
import sys


def warp(u1, u2):
    r, phi = math.sqrt(u1), 2.0 * math.pi * u2
    return r * math.cos(phi), r * math.sin(phi), math.sqrt(1.0 - u1)


def pdf(x, y, z):
    return (max(z, 0.0) / math.pi,)


def invert(x, y, z):
    return x * x + y * y, (math.atan2(y, x) / (2.0 * math.pi)) % 1.0


ANSWERS = {"warp": warp, "pdf": pdf, "invert": invert}

for line in sys.stdin:
    verb, *numbers = line.split()
    print(*ANSWERS[verb](*map(float, numbers)))  # print writes every digit
