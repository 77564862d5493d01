"""Writes the crafted spectrum images of this folder: PNGs whose header claims a size
the bytes do not hold, to check that `spectral::emission::parse_image` judges the
header before it decodes a pixel. 451 x 300000 grey is 135 MB: under the `image`
crate's default limit of 512 MB, which the reader used to decode within, and over the
fuzzer's 100 MB; 451 x 10^9 is over both.

Run: python3 tests/data/png/make.py (standard library only). The files are committed;
this script says how they were made.
"""
import pathlib
import struct
import zlib

here = pathlib.Path(__file__).resolve().parent


def chunk(kind: bytes, body: bytes) -> bytes:
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))


def png(width: int, height: int, rows: int) -> bytes:
    """8-bit grey, `width` x `height` declared, `rows` rows of dark pixels present."""
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    data = zlib.compress((b"\x00" + b"\x00" * width) * rows, 9)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", data) + chunk(b"IEND", b"")


for name, (w, h, rows) in {
    "tall-451x1000000000.png": (451, 1_000_000_000, 4),
    "tall-451x300000.png": (451, 300_000, 4),
    "tall-451x4097.png": (451, 4097, 4),
}.items():
    (here / name).write_bytes(png(w, h, rows))
    print(name, len(png(w, h, rows)), "bytes")
