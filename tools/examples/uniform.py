"""A deliberately wrong cosine sampler (chapter *Checks from any language*): uniform on the
hemisphere, z = 1 - u1, which `raylemma check sampler --target cosine-hemisphere` must
reject. It answers only `warp u1 u2` questions, with `x y z`.
"""

import math
import sys

for line in sys.stdin:
    _, u1, u2 = line.split()
    z, phi = 1.0 - float(u1), 2.0 * math.pi * float(u2)
    r = math.sqrt(max(0.0, 1.0 - z * z))
    print(r * math.cos(phi), r * math.sin(phi), z)
