"""The unpolarised Fresnel reflectance of a dielectric interface, checked from outside Rust
(chapter *Checks from any language*). It answers `fresnel cos_i n1 n2` with `R`;
`python3 fresnel.py schlick` answers with Schlick's approximation instead, which the
checker must reject.

    raylemma check fresnel --program "python3 fresnel.py"
"""

import math
import sys


def fresnel(cos_i, n1, n2):
    c = min(abs(cos_i), 1.0)
    if n1 == n2:
        return 0.0  # no interface: nothing is reflected, even at grazing incidence
    eta = n1 / n2
    cos2_t = (1.0 - eta * eta) + (eta * c) * (eta * c)
    if cos2_t < 0.0 or c == 0.0:
        return 1.0  # total internal reflection; grazing incidence
    cos_t = math.sqrt(cos2_t)
    r_s = (n1 * c - n2 * cos_t) / (n1 * c + n2 * cos_t)
    r_p = (n2 * c - n1 * cos_t) / (n2 * c + n1 * cos_t)
    return 0.5 * (r_s * r_s + r_p * r_p)


def schlick(cos_i, n1, n2):
    r0 = ((n1 - n2) / (n1 + n2)) ** 2
    return r0 + (1.0 - r0) * (1.0 - min(abs(cos_i), 1.0)) ** 5


reflectance = schlick if sys.argv[1:] == ["schlick"] else fresnel
for line in sys.stdin:
    _, cos_i, n1, n2 = line.split()
    print(reflectance(float(cos_i), float(n1), float(n2)))
