#!/usr/bin/python3
"""Writes the small TrueType / CFF fonts the outline-font tests and the fuzz_outline_font seeds use.

The fonts are committed next to this script; run it again (Debian python3-fonttools) only to change
them. Output is deterministic (fixed timestamps), so a rerun without changes leaves git clean.

  tests/fonts/data/outline/make_fixtures.py [OUT_DIR]      (default: this script's directory)

blob_N.ttf            one 2000-point glyph ("blob", 6.5 KB) and a character map (format 13) that points N
                      code points at it: N = 1 ('A'), 256 (U+0021..U+0120), 65502 (U+0021..U+FFFE).
                      The loader must fit the glyph once, however many code points share it.
cmap13.ttf            a small glyph (an 'H' of three bars) with a format-13 character map pointing
                      U+0021..U+00FF at it: the fuzz seed for that map (the blob fonts cost too
                      much a run to be seeds).
one_point_contours.ttf  'A' a square then a one-point contour, 'B' two one-point contours then a
                      square, 'C' square / one-point contour / square, 'D' only a one-point contour,
                      'H' a plain bar: one-point contours draw nothing and leave no laser-off move.
no_glyphs.ttf         a valid font whose character map maps nothing.
zero_height.ttf       no 'H', OS/2 cap height 0 and ascender 0: no usable standard height.
negative_height.ttf   'H' lies wholly below the baseline: a negative cap height.
absurd_height.ttf     16 units per em and an 'H' 16000 units high (1000 em).
sample.ttf            'H', 'O' (quadratic), 'x', space: a plain TrueType seed.
sample_cff.otf        the same letters as CFF (cubic) outlines: a plain OpenType/CFF seed.
"""
import math
import os
import sys
from array import array

from fontTools.fontBuilder import FontBuilder
from fontTools.pens.cu2quPen import Cu2QuPen
from fontTools.pens.t2CharStringPen import T2CharStringPen
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib.tables import ttProgram
from fontTools.ttLib.tables._c_m_a_p import CmapSubtable
from fontTools.ttLib.tables._g_l_y_f import Glyph, GlyphCoordinates

# 2020-01-01 in the font's epoch (seconds since 1904-01-01): fixed, so the bytes never change.
FIXED_TIME = 3660681600


def raw_glyph(contours):
    """A glyf entry from contours of (x, y, on_curve) points, one-point contours included (the
    pens drop those)."""
    g = Glyph()
    coords, flags, ends = [], [], []
    for contour in contours:
        for x, y, on in contour:
            coords.append((x, y))
            flags.append(1 if on else 0)
        ends.append(len(coords) - 1)
    g.numberOfContours = len(contours)
    g.coordinates = GlyphCoordinates(coords)
    g.flags = array("B", flags)
    g.endPtsOfContours = ends
    g.program = ttProgram.Program()
    g.program.fromBytecode(b"")
    return g


def square(x0, y0, x1, y1):
    return [(x0, y0, True), (x0, y1, True), (x1, y1, True), (x1, y0, True)]


def empty_glyph():
    return TTGlyphPen(None).glyph()


def truetype(path, upem, glyphs, cmap, ascent=800, descent=-200, cap=700, x_height=500,
             cmap13=None):
    """glyphs: name -> (glyf Glyph, advance). cmap: code point -> name (format 4/12), or cmap13:
    code point -> name written as one format-13 subtable (3, 10) instead."""
    order = [".notdef"] + [n for n in glyphs if n != ".notdef"]
    fb = FontBuilder(upem, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap(cmap)
    glyf = {".notdef": empty_glyph()}
    metrics = {".notdef": (upem // 2, 0)}
    for name, (g, advance) in glyphs.items():
        glyf[name] = g
        metrics[name] = (advance, 0)
    fb.setupGlyf(glyf)
    for name, g in glyf.items():
        g.recalcBounds(fb.font["glyf"])
        metrics[name] = (metrics[name][0], getattr(g, "xMin", 0))
    fb.setupHorizontalMetrics(metrics)
    fb.setupHorizontalHeader(ascent=ascent, descent=descent)
    fb.setupNameTable({"familyName": os.path.splitext(os.path.basename(path))[0], "styleName": "Regular"})
    fb.setupOS2(sTypoAscender=ascent, sTypoDescender=descent, usWinAscent=max(ascent, 0),
                usWinDescent=max(-descent, 0), sCapHeight=cap, sxHeight=x_height)
    fb.setupPost()
    if cmap13 is not None:
        sub = CmapSubtable.newSubtable(13)
        sub.platformID, sub.platEncID, sub.language = 3, 10, 0
        sub.cmap = cmap13
        fb.font["cmap"].tables = [sub]
    save(fb, path)


def save(fb, path):
    fb.font["head"].created = FIXED_TIME
    fb.font["head"].modified = FIXED_TIME
    fb.font.recalcTimestamp = False
    fb.save(path)


def blob_glyph(points=2000):
    """A closed wobbly ring of `points` TrueType points, on- and off-curve alternating: 1000
    quadratic Béziers whose control points swing 30 % in and out of the ring, so each is fitted
    with many arcs (about 15 000 elements in all, like the glyph the issue was found with)."""
    contour = []
    for i in range(points):
        a = 2 * math.pi * i / points
        r = 300 + 40 * math.sin(37 * a) + 15 * math.cos(11 * a)
        if i % 2:
            r *= 1.3 if (i // 2) % 2 else 0.7
        contour.append((round(500 + r * math.cos(a)), round(350 + r * math.sin(a)), i % 2 == 0))
    return raw_glyph([contour])


def bars_glyph():
    return raw_glyph([square(100, 0, 200, 700), square(400, 0, 500, 700), square(200, 300, 400, 400)])


def blob_fonts(out):
    for n, first in ((1, 0x41), (256, 0x21), (65502, 0x21)):
        truetype(os.path.join(out, "blob_%d.ttf" % n), 1000, {"blob": (blob_glyph(), 1000)},
                 {}, cmap13={cp: "blob" for cp in range(first, first + n)})
    truetype(os.path.join(out, "cmap13.ttf"), 1000, {"bars": (bars_glyph(), 600)}, {},
             cmap13={cp: "bars" for cp in range(0x21, 0x100)})


def contract_fonts(out):
    one = lambda x, y: [(x, y, True)]
    glyphs = {
        "A": (raw_glyph([square(100, 0, 500, 700), one(800, 300)]), 900),
        "B": (raw_glyph([one(50, 50), one(900, 900), square(100, 0, 500, 700)]), 900),
        "C": (raw_glyph([square(100, 0, 300, 700), one(400, 400), square(500, 0, 700, 700)]), 900),
        "D": (raw_glyph([one(300, 300)]), 900),
        "H": (raw_glyph([square(100, 0, 200, 700)]), 900),
    }
    truetype(os.path.join(out, "one_point_contours.ttf"), 1000, glyphs, {ord(c): c for c in "ABCDH"})

    plain_a = {"A": (raw_glyph([square(100, 0, 500, 700)]), 900)}
    truetype(os.path.join(out, "no_glyphs.ttf"), 1000, plain_a, {})
    truetype(os.path.join(out, "zero_height.ttf"), 1000, plain_a, {0x41: "A"}, ascent=0, cap=0,
             x_height=0)
    below = {"H": (raw_glyph([square(100, -600, 500, -100)]), 900)}
    truetype(os.path.join(out, "negative_height.ttf"), 1000, below, {0x48: "H"})
    tall = {"H": (raw_glyph([square(1, 0, 10, 16000)]), 12)}
    truetype(os.path.join(out, "absurd_height.ttf"), 16, tall, {0x48: "H"}, ascent=16000, descent=-4,
             cap=16000, x_height=8)


def ring(pen, cx, cy, r, k=0.5523):
    """A circle of four cubics (pen: a cubic pen) or quadratics (TTGlyphPen: qCurveTo)."""
    pen.moveTo((cx + r, cy))
    for i in range(4):
        a0, a1 = i * math.pi / 2, (i + 1) * math.pi / 2
        p0 = (cx + r * math.cos(a0), cy + r * math.sin(a0))
        p3 = (cx + r * math.cos(a1), cy + r * math.sin(a1))
        c1 = (p0[0] - k * r * math.sin(a0), p0[1] + k * r * math.cos(a0))
        c2 = (p3[0] + k * r * math.sin(a1), p3[1] - k * r * math.cos(a1))
        pen.curveTo(*[(round(x), round(y)) for x, y in (c1, c2, p3)])
    pen.closePath()


def draw_sample(pen, name):
    if name == "H":
        for x0, y0, x1, y1 in ((100, 0, 200, 700), (400, 0, 500, 700), (200, 300, 400, 400)):
            pen.moveTo((x0, y0)); pen.lineTo((x0, y1)); pen.lineTo((x1, y1)); pen.lineTo((x1, y0))
            pen.closePath()
    elif name == "O":
        ring(pen, 350, 350, 350)
        ring(pen, 350, 350, 250)
    elif name == "x":
        pen.moveTo((0, 0)); pen.lineTo((250, 500)); pen.lineTo((350, 500)); pen.lineTo((100, 0))
        pen.closePath()


def sample_fonts(out):
    names = ["H", "O", "x", "space"]
    cmap = {ord("H"): "H", ord("O"): "O", ord("x"): "x", 0x20: "space"}
    glyphs = {}
    for n in names:
        pen = TTGlyphPen(None)
        draw_sample(Cu2QuPen(pen, max_err=0.5), n)  # the cubics as TrueType quadratics
        glyphs[n] = (pen.glyph(), 300 if n == "space" else 800)
    truetype(os.path.join(out, "sample.ttf"), 1000, glyphs, cmap)

    fb = FontBuilder(1000, isTTF=False)
    fb.setupGlyphOrder([".notdef"] + names)
    fb.setupCharacterMap(cmap)
    charstrings = {}
    for n in [".notdef"] + names:
        pen = T2CharStringPen(300 if n == "space" else 800, None)
        draw_sample(pen, n)
        charstrings[n] = pen.getCharString()
    fb.setupCFF("SampleCFF", {"FullName": "SampleCFF"}, charstrings, {})
    fb.setupHorizontalMetrics({n: (300 if n == "space" else 800, 0) for n in [".notdef"] + names})
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": "SampleCFF", "styleName": "Regular"})
    fb.setupOS2(sTypoAscender=800, sTypoDescender=-200, usWinAscent=800, usWinDescent=200,
                sCapHeight=700, sxHeight=500)
    fb.setupPost()
    save(fb, os.path.join(out, "sample_cff.otf"))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(out, exist_ok=True)
    blob_fonts(out)
    contract_fonts(out)
    sample_fonts(out)


if __name__ == "__main__":
    main()
