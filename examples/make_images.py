#!/usr/bin/env python3
"""Writes the README's example pictures (standard library only, so anyone can re-make them):

shadow.png  a back-lit 1 mm tool seen from its end at 5 µm a pixel (`marker tool-measure`):
            a dark disk 200 px across on a bright field, edges anti-aliased by 8×8 supersampling.
photo.png   a small grey "photo" for `marker gravure`: a smooth tone wedge with a dark ring.
type.png    its line-work mask, the same size: the letters "SN 42" in a 5×7 dot-matrix font,
            black on white (black marks line work).
"""
import math
import struct
import sys
import zlib
from pathlib import Path


def write_grey_png(path, rows):
    height, width = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(r) for r in rows)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    Path(path).write_bytes(png)


def shadow(size=300, radius=100.0, dark=26, bright=230):
    c = (size - 1) / 2
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            d = math.hypot(x - c, y - c)
            if d < radius - 1:
                cover = 1.0
            elif d > radius + 1:
                cover = 0.0
            else:  # 8×8 supersampling where the edge crosses the pixel
                cover = sum(math.hypot(x - 0.5 + (i + 0.5) / 8 - c, y - 0.5 + (j + 0.5) / 8 - c) < radius
                            for i in range(8) for j in range(8)) / 64
            row.append(round(bright - (bright - dark) * cover))
        rows.append(row)
    return rows


def photo(width=160, height=64):
    rows = []
    for y in range(height):
        row = []
        for x in range(width):
            tone = 235 - 200 * x / (width - 1)  # a wedge, light to dark
            if abs(math.hypot(x - 40, y - 32) - 20) < 3:  # a dark ring
                tone = 30
            row.append(round(tone))
        rows.append(row)
    return rows


FONT = {  # 5×7 dot matrix, rows top to bottom
    "S": ["01111", "10000", "10000", "01110", "00001", "00001", "11110"],
    "N": ["10001", "11001", "10101", "10011", "10001", "10001", "10001"],
    "4": ["00010", "00110", "01010", "10010", "11111", "00010", "00010"],
    "2": ["01110", "10001", "00001", "00010", "00100", "01000", "11111"],
    " ": ["00000"] * 7,
}


def type_mask(width=160, height=64, text="SN 42", scale=4, left=30, top=18):
    rows = [[255] * width for _ in range(height)]
    for k, ch in enumerate(text):
        for r, bits in enumerate(FONT[ch]):
            for c, bit in enumerate(bits):
                if bit == "1":
                    for dy in range(scale):
                        for dx in range(scale):
                            rows[top + r * scale + dy][left + (k * 6 + c) * scale + dx] = 0
    return rows


if __name__ == "__main__":
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent
    write_grey_png(out / "shadow.png", shadow())
    write_grey_png(out / "photo.png", photo())
    write_grey_png(out / "type.png", type_mask())
