"""Writes the crafted OpenEXR files of tests/book/renderer/compare.rs (chapter *Bad input*):
headers whose claimed sizes the files cannot back. Run from this folder: python3 make.py"""
import struct


def attr(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value


def header(width, height, compression=0):
    channels = b"".join(c.encode() + b"\0" + struct.pack("<i", 2) + b"\0\0\0\0" + struct.pack("<ii", 1, 1)
                        for c in "BGR") + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    return (b"\x76\x2f\x31\x01" + struct.pack("<I", 2)
            + attr("channels", "chlist", channels)
            + attr("compression", "compression", bytes([compression]))
            + attr("dataWindow", "box2i", box)
            + attr("displayWindow", "box2i", box)
            + attr("lineOrder", "lineOrder", b"\0")
            + attr("pixelAspectRatio", "float", struct.pack("<f", 1.0))
            + attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0))
            + attr("screenWindowWidth", "float", struct.pack("<f", 1.0))
            + b"\0")


def write(name, head, size):
    data = head + bytes(max(size - len(head), 0))
    open(name, "wb").write(data)
    print(name, len(data), "bytes")


# 100000 x 100000 float pixels claimed by 598 bytes (a reader that believes it allocates 120 GB).
write("huge-100000x100000.exr", header(100_000, 100_000, compression=3), 598)
# 10^9 x 1: few pixels per line, one line.
write("wide-1000000000x1.exr", header(1_000_000_000, 1, compression=3), 598)
# 1 x 10^7, uncompressed: one chunk per line, an offset table of 80 MB in a 598-byte file.
write("tall-1x10000000.exr", header(1, 10_000_000), 598)
# 60000 x 16 ZIP-compressed (one block) in 598 bytes: within the pixel limit, its offsets
# fit, but 11.5 MB of float pixels is beyond what any compression packs into the file.
write("dense-60000x16.exr", header(60_000, 16, compression=3), 598)
