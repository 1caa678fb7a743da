#!/usr/bin/python3
"""Writes a "PNG bomb": a small, valid PNG that declares a huge grey image (every pixel black),
for measuring what the image readers spend on it (docs/gravure.md, "Hostile images").

  scripts/make_png_bomb.py OUT.png [WIDTH [HEIGHT]]      (default 20000 x 20000, 8-bit grey)

20000 x 20000 compresses to about 0.4 MB; decoded it is 400 MB of 8-bit samples (1.6 GB as
floats). Python's standard library only (zlib), no third-party package.
"""
import struct
import sys
import zlib


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    width = int(sys.argv[2]) if len(sys.argv) > 2 else 20000
    height = int(sys.argv[3]) if len(sys.argv) > 3 else width
    # IHDR: width, height, bit depth 8, colour type 0 (grey), deflate, adaptive filter, no interlace.
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    z = zlib.compressobj(9)
    row = bytes(1 + width)  # filter byte 0 (none) + black samples
    idat = bytearray()
    for _ in range(height):
        idat += z.compress(row)
    idat += z.flush()
    with open(out, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", bytes(idat)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    main()
