#!/usr/bin/env python3
"""Side by side with F-Engrave 1.75: the same text, layout and cut, timed and measured the same way.

    scripts/fengrave_compare.py plain  --fengrave DIR --font normal.cxf [--rows 10,40,160]
    scripts/fengrave_compare.py vcarve --fengrave DIR --font DejaVuSans.ttf [--text TEXT] [--height 10]

DIR is a checkout of github.com/stephenhouser/f-engrave (F-Engrave 1.75 by Scorch, Python/Tk),
with TTF2CXF_STREAM/ttf2cxf_stream built (`make -C TTF2CXF_STREAM`) for TrueType fonts. F-Engrave
runs headless in its batch mode (-b) under xvfb-run, reading its settings from a file of
`(fengrave_set ...)` lines; it needs Debian's python3-tk, python3-pyclipper and xvfb. None of it is
needed by the build or the tests: this script only produces the figures of docs/cnc.md.

Both programs go through the same LinuxCNC rs274 (build/rs274/rs274, scripts/fetch_rs274.sh), and
every figure is read from its canonical calls, so both are measured by one yardstick:
  rapid_mm   XY length of the rapid moves from the first plunge on (the way to the first cut is
             where the operator left the spindle, not the program's choice);
  retracts   rapid moves that go up from below the surface;
  cpu_s      user + system CPU of the generating process (F-Engrave: the Python process, start-up
             included; ours: `marker gcode`).
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MARKER = os.path.join(REPO, "build", "marker", "marker")
RS274 = os.path.join(REPO, "build", "rs274", "rs274")
TEXT = "The quick brown fox jumps over the lazy dog. 0123456789 ABCDEF"  # 62 characters

CALL = re.compile(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED)\(([^)]*)\)")


def canonical_figures(ngc):
    """Rapid travel after the first plunge, retracts and cutting moves, from rs274's calls."""
    out = subprocess.run([RS274, ngc], capture_output=True, text=True)
    if out.returncode != 0:
        raise SystemExit(f"rs274 refused {ngc}:\n{out.stderr[-2000:]}")
    pos = None
    cut_started = False
    rapid = 0.0
    retracts = 0
    feeds = 0
    for m in CALL.finditer(out.stdout):
        kind, args = m.group(1), [float(v) for v in m.group(2).split(",")]
        if kind == "ARC_FEED":
            end = (args[0], args[1], args[5])
        else:
            end = (args[0], args[1], args[2])
        if kind == "STRAIGHT_TRAVERSE":
            if pos is not None and cut_started:
                rapid += math.hypot(end[0] - pos[0], end[1] - pos[1])
            if pos is not None and pos[2] < 0 and end[2] > pos[2]:
                retracts += 1
        else:
            feeds += 1
            if end[2] < 0:
                cut_started = True
        pos = end
    return {"rapid_mm": rapid, "retracts": retracts, "cutting_moves": feeds}


def timed(cmd, env=None):
    """Runs cmd; returns (stdout, user+system CPU seconds of the child)."""
    before = os.times()
    res = subprocess.run(cmd, capture_output=True, text=True, env=env)
    after = os.times()
    if res.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed:\n{res.stderr[-2000:]}")
    cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    return res.stdout, cpu


def fengrave(dirpath, settings, text, font):
    """F-Engrave batch mode: G-code on stdout. Its CPU time is measured inside xvfb-run by time."""
    with tempfile.TemporaryDirectory() as tmp:
        cfg = os.path.join(tmp, "settings.ngc")
        with open(cfg, "w") as f:
            for k, v in settings.items():
                f.write(f"(fengrave_set {k} {v} )\n")
        env = dict(os.environ, HOME=tmp, PATH=os.path.join(dirpath, "TTF2CXF_STREAM") + ":" + os.environ["PATH"])
        timing = os.path.join(tmp, "cpu")
        cmd = ["xvfb-run", "-a", "/usr/bin/time", "-f", "%U %S", "-o", timing, "/usr/bin/python3",
               os.path.join(dirpath, "f-engrave.py"), "-b", "-g", cfg, "-f", os.path.abspath(font), "-t", text]
        out = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=dirpath)
        if out.returncode != 0 or "G90" not in out.stdout:
            raise SystemExit("F-Engrave failed:\n" + out.stdout[-1500:] + out.stderr[-1500:])
        with open(timing) as f:
            user, system = (float(v) for v in f.read().split()[-2:])
        # Batch mode prints its messages as comments first; the program starts at G90.
        program = out.stdout[out.stdout.index("G90"):]
        return program, user + system


def cxf_metrics(font, text):
    """What F-Engrave measures on a CXF font, in font units, the way its parse() reads the file:
    a one-character key is the character, a four-hex-digit key (five with a leading #) its code;
    lines and arcs (5° chords, counter-clockwise; it skips AR records) give each glyph's strokes.
    Returns the used glyphs' highest and lowest y and the font's widest glyph (get_xmax)."""
    glyphs, key = {}, None
    for raw in open(font, errors="ignore"):
        line = raw.rstrip("\n") + " "
        m = re.match(r"^\[(.*)\]\s", line)
        if m:
            k = m.group(1)
            if len(k) == 1:
                key = ord(k)
            else:
                k = k[1:] if len(k) == 5 else k
                try:
                    key = int(k, 16) if len(k) == 4 else None
                except ValueError:
                    key = None
            if key is not None:
                glyphs[key] = []
            continue
        if key is None:
            continue
        m = re.match(r"^L (.*)", line)
        if m:
            x1, y1, x2, y2 = (float(v) for v in m.group(1).split(","))
            glyphs[key].append((x1, y1, x2, y2))
        m = re.match(r"^A (.*)", line)
        if m:
            cx, cy, r, a1, a2 = (float(v) for v in m.group(1).split(","))
            if a2 < a1:
                a1 -= 360.0
            segs = int((a2 - a1) / 5.0) + 1
            pts = [(cx + r * math.cos(math.radians(a1 + (a2 - a1) * k / segs)),
                    cy + r * math.sin(math.radians(a1 + (a2 - a1) * k / segs))) for k in range(segs + 1)]
            glyphs[key] += [(p[0], p[1], q[0], q[1]) for p, q in zip(pts, pts[1:])]
    used = [glyphs[ord(c)] for c in set(text) if ord(c) in glyphs and glyphs[ord(c)]]
    ymax = max(max(l[1], l[3]) for g in used for l in g)
    ymin = min(min(l[1], l[3]) for g in used for l in g)
    char_width = max(max(max(l[0], l[2]) for l in g) for g in glyphs.values() if g)
    return ymax, ymin, char_width


def plain(args):
    height, letter_spacing, word_spacing, line_height, cap = 1.0, 3.0, 6.75, 9 * 1.6, 9.0  # QCAD CXF metrics
    ymax, ymin, char_width = cxf_metrics(args.font, TEXT)
    rows_out = []
    for rows in [int(r) for r in args.rows.split(",")]:
        text = "\n".join([TEXT] * rows)
        with tempfile.TemporaryDirectory() as tmp:
            ours = os.path.join(tmp, "ours.ngc")
            _, cpu_ours = timed([MARKER, "gcode", text.replace("\n", "\\n"), "--font", args.font, "--height", str(height),
                                 "--tool-diameter", "0.1", "--depth", "0.1", "--units", "mm", "-o", ours, "--quiet"])
            f_ours = canonical_figures(ours)
            f_ours["lines"] = sum(1 for _ in open(ours))
            settings = {
                "units": "mm", "cut_type": "engrave", "YSCALE": height * (ymax - ymin) / cap, "H_CALC": "max_use",
                "CSPACE": 100 * letter_spacing / char_width, "WSPACE": 100 * word_spacing / char_width,
                "LSPACE": line_height / (ymax - ymin), "ZSAFE": 5, "ZCUT": -0.1, "FEED": 300, "accuracy": 0.001,
                "no_comments": 1, "segarc": 5, "STHICK": 0,
            }
            program, cpu_fe = fengrave(args.fengrave, settings, text.replace("\n", "|"), args.font)
            theirs = os.path.join(tmp, "fengrave.ngc")
            with open(theirs, "w") as f:
                f.write(program)
            f_fe = canonical_figures(theirs)
            f_fe["lines"] = program.count("\n")
        rows_out.append({"rows": rows, "ours": dict(f_ours, cpu_s=cpu_ours), "fengrave": dict(f_fe, cpu_s=cpu_fe)})
        print(json.dumps(rows_out[-1]), flush=True)


def ttf_used_extent(dirpath, font, text):
    """ttf2cxf_stream's units (9 = the height of 'A'): the used glyphs' highest and lowest y."""
    out = subprocess.run([os.path.join(dirpath, "TTF2CXF_STREAM", "ttf2cxf_stream"), "-s", "0.5", font, "STDOUT"],
                         capture_output=True, text=True, check=True).stdout
    glyphs, key = {}, None
    for line in out.splitlines():
        m = re.match(r"^\[#([0-9A-F]+)\]", line)
        if m:
            key = int(m.group(1), 16)
            glyphs[key] = []
        elif line.startswith("L") and key is not None:
            v = [float(x) for x in line[1:].split(",")]
            glyphs[key] += [v[1], v[3]]
    ys = [y for c in set(text) if ord(c) in glyphs for y in glyphs[ord(c)]]
    return max(ys), min(ys)


def vcarve(args):
    """The same text, font, height and 60° bit (no depth cap) v-carved by both; F-Engrave steps
    0.05 mm along the outline (its default 0.01 in is 0.254 mm). Its letter spacing is its own
    (a percentage of the widest glyph), so the layouts differ slightly: the figures are times."""
    ymax, ymin = ttf_used_extent(args.fengrave, args.font, args.text)
    with tempfile.TemporaryDirectory() as tmp:
        ours = os.path.join(tmp, "ours.ngc")
        _, cpu_ours = timed([MARKER, "gcode", args.text, "--font", args.font, "--height", str(args.height), "--mode",
                             "v-carve", "--bit-angle", "60", "--tool-diameter", "20", "-o", ours, "--quiet"])
        f_ours = canonical_figures(ours)
        settings = {"units": "mm", "cut_type": "v-carve", "bit_shape": "VBIT", "v_bit_angle": 60, "v_bit_dia": 20,
                    "v_depth_lim": 0.0, "v_step_len": 0.05, "YSCALE": args.height * (ymax - ymin) / 9,
                    "H_CALC": "max_use", "segarc": 0.5, "accuracy": 0.001, "ZSAFE": 5, "FEED": 300,
                    "no_comments": 1, "v_check_all": "all", "arc_fit": "none"}
        program, cpu_fe = fengrave(args.fengrave, settings, args.text, args.font)
        theirs = os.path.join(tmp, "fengrave.ngc")
        with open(theirs, "w") as f:
            f.write(program)
        f_fe = canonical_figures(theirs)
    print(json.dumps({"text": args.text, "ours": dict(f_ours, cpu_s=cpu_ours), "fengrave": dict(f_fe, cpu_s=cpu_fe)}))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mode", choices=["plain", "vcarve"])
    ap.add_argument("--fengrave", required=True)
    ap.add_argument("--font", required=True)
    ap.add_argument("--rows", default="10,40,160")
    ap.add_argument("--text", default="Serial No. 2026-0815")  # 20 characters
    ap.add_argument("--height", type=float, default=10)
    args = ap.parse_args()
    plain(args) if args.mode == "plain" else vcarve(args)


if __name__ == "__main__":
    sys.exit(main())
