"""Where a render's instructions go, by what they do: reads a callgrind profile
(`valgrind --tool=callgrind` of `raylemma render`, built with line tables) and sums the
instructions of every source file and function into the parts of a path (chapter *The
reference renderer*, *Speed*). Writes a markdown table to stdout.

    python3 where.py PROFILE.out SAMPLES
"""
import re
import subprocess
import sys

profile, samples = sys.argv[1], int(sys.argv[2])
# `callgrind_annotate --inclusive=no` lists self costs as "N (P%)  FILE:FUNCTION [OBJECT]".
text = subprocess.run(
    ["callgrind_annotate", "--inclusive=no", "--threshold=100", profile],
    capture_output=True, text=True, check=True,
).stdout
total = 0
parts = {}
PART_ORDER = [
    "intersection (rays against the scene's surfaces)",
    "light sampling (a point on a light, its density)",
    "BSDF sampling and scattering (cosine lobe, frame, reflection, Fresnel)",
    "spectral work (wavelengths, spectra, colour matching, XYZ)",
    "random numbers",
    "path logic (weights, roulette, offsets, bookkeeping)",
    "writing the image files",
    "everything else (start-up, the scene file)",
]
def part_of(file, func):
    f = file
    if any(s in f for s in ("render/tracer.rs", "geometry/sphere.rs", "geometry/parallelogram.rs", "render/scene.rs")):
        return PART_ORDER[0]
    if "transport/shadow.rs" in f:
        return PART_ORDER[1]
    if any(s in f for s in ("sampling/cosine.rs", "sampling/disc.rs", "sampling/frame.rs", "optics/", "transport/roulette.rs")) or "sincos" in f or "s_sin.c" in f:
        return PART_ORDER[2] if "roulette" not in f else PART_ORDER[5]
    if any(s in f for s in ("spectral/", "render/pixel.rs", "log1p", "e_exp", "e_pow")):
        return PART_ORDER[3]
    if "rand_pcg" in f or "/rand-" in f:
        return PART_ORDER[4]
    if any(s in f for s in ("exr-", "miniz", "fdeflate", "png-", "image-", "image/exr.rs", "image/png.rs", "render/files.rs", "output.rs", "zune", "crc32", "adler")):
        return PART_ORDER[6]
    if "render/integrator.rs" in f:
        return PART_ORDER[5]
    # glam and core arithmetic inlined into a function: the function says whose it is.
    if "Tracer::intersect" in func or "intersect_stable" in func:
        return PART_ORDER[0]
    if "QuadLight" in func or "SphereLight" in func:
        return PART_ORDER[1]
    if "spectral::" in func or "sample_xyz" in func or "Dense" in func:
        return PART_ORDER[3]
    if "integrator::radiance" in func or "render_pixel" in func or "render_tile" in func:
        return PART_ORDER[5]
    if "exr::" in func or "miniz" in func or "png" in func:
        return PART_ORDER[6]
    return PART_ORDER[7]

# Only the function list: the annotated source that follows repeats the same costs by line.
lines = text.splitlines()
start = next(i for i, l in enumerate(lines) if l.strip().endswith("file:function")) + 2
listing = []
for line in lines[start:]:
    if not line.strip() or line.startswith("---"):
        break
    listing.append(line)
for line in listing:
    m = re.match(r"\s*([\d,]+)\s+\([\s\d.]+%\)\s+(.*?):(.*?)(\s+\[.*\])?$", line)
    if not m:
        continue
    n = int(m.group(1).replace(",", ""))
    if "PROGRAM TOTALS" in line:
        continue
    part = part_of(m.group(2), m.group(3))
    parts[part] = parts.get(part, 0) + n
    total += n

render = sum(v for k, v in parts.items() if k not in PART_ORDER[6:])
print("| part of a path | instructions per sample | share of the rendering |")
print("|---|---:|---:|")
for k in PART_ORDER[:6]:
    v = parts.get(k, 0)
    print(f"| {k} | {v / samples:.0f} | {100 * v / render:.1f} % |")
print(f"| **all of the rendering** | **{render / samples:.0f}** | 100 % |")
print()
print(f"*Instructions counted by callgrind (valgrind), which are the same on every run of the "
      f"same binary: `tools/profile/where.sh`, {samples} samples; the image files "
      f"({parts.get(PART_ORDER[6], 0) / samples:.0f} instructions per sample here) and start-up are "
      "left out. Instructions are not time (a division or a mispredicted branch costs more "
      "than an addition), but their shares say where the work is.*")
