"""Snell refraction, checked from outside Rust (chapter *Checks from any language*). It
answers `refract wi_x wi_y wi_z n_x n_y n_z n1 n2` with the transmitted direction
`t_x t_y t_z`, or `tir` under total internal reflection. The normal may be on either side.

    raylemma check refraction --program "python3 refract.py"
"""

import math
import sys


def refract(w, m, n1, n2):
    cos_i = -(w[0] * m[0] + w[1] * m[1] + w[2] * m[2])
    if cos_i < 0.0:  # the normal on the far side: use the one facing the light
        m, cos_i = [-c for c in m], -cos_i
    eta = n1 / n2
    cos2_t = (1.0 - eta * eta) + (eta * cos_i) * (eta * cos_i)
    if cos2_t < 0.0:
        return ["tir"]
    k = eta * cos_i - math.sqrt(cos2_t)
    return [eta * w[i] + k * m[i] for i in range(3)]


for line in sys.stdin:
    x = [float(v) for v in line.split()[1:]]
    print(*refract(x[0:3], x[3:6], x[6], x[7]))
