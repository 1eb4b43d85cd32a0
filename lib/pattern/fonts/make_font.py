#!/usr/bin/python3
"""Writes a Radiance font file (.fnt) from a Hershey font in James Hurt's .jhf format.

    lib/pattern/fonts/make_font.py /usr/share/hershey-fonts/futural.jhf > lib/pattern/fonts/helvet.fnt

Needs Debian's hershey-fonts-data (the .jhf files) and python3-shapely (polygon union).

A Hershey glyph is pen strokes; a Radiance glyph is one filled polygon on a 0-255 grid, tested by the
even-odd rule. Each stroke is thickened into a band of constant width with round ends and joints, the
bands of a glyph are merged into their union (so that overlaps at joints do not cancel out under the
even-odd rule), and the union's rings (outlines and holes, several for glyphs such as "i" or "%") are
chained into one vertex list by seams, zero-width bridges walked once out and once back, which leave
the even-odd coverage unchanged.
"""
import sys

from shapely.geometry import LineString, Point, Polygon
from shapely.ops import unary_union

HALF_WIDTH = 1.2      # half the stroke width, in Hershey units (cap height 21): a regular weight
ROUND_SEGMENTS = 3    # segments per quarter circle at stroke ends and joints
SIMPLIFY = 0.04       # outline tolerance in Hershey units, well under one grid step
FIRST, LAST = 32, 126  # the .jhf file lists the printable ASCII characters in order


def read_jhf(path):
    """Each glyph as (left margin, right margin, strokes), a stroke being a list of (x, y), y down."""
    glyphs = []
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if not line.strip():
                continue
            count = int(line[5:8])
            pairs = [line[8 + 2 * i:10 + 2 * i] for i in range(count)]
            left, right = (ord(c) - ord("R") for c in pairs[0])
            strokes, stroke = [], []
            for p in pairs[1:]:
                if p == " R":  # pen up
                    strokes.append(stroke)
                    stroke = []
                else:
                    stroke.append((ord(p[0]) - ord("R"), ord(p[1]) - ord("R")))
            strokes.append(stroke)
            glyphs.append((left, right, [s for s in strokes if s]))
    return glyphs


def outline(strokes):
    """The union of the thickened strokes."""
    bands = []
    for s in strokes:
        shape = Point(s[0]) if len(s) == 1 else LineString(s)
        bands.append(shape.buffer(HALF_WIDTH, ROUND_SEGMENTS))
    return unary_union(bands).simplify(SIMPLIFY)


def rings(shape):
    polygons = [shape] if isinstance(shape, Polygon) else list(shape.geoms)
    for p in polygons:
        yield list(p.exterior.coords)[:-1]
        for hole in p.interiors:
            yield list(hole.coords)[:-1]


def to_grid(ring, scale, x_center, y_middle):
    """Grid coordinates (x right, y up, 0-255), consecutive repeats dropped."""
    out = []
    for x, y in ring:
        v = (round(127.5 + (x - x_center) * scale), round(127.5 - (y - y_middle) * scale))
        if not out or out[-1] != v:
            out.append(v)
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
    return out if len(out) >= 3 else []


def chained(grid_rings):
    """One vertex list: each ring closed on its first vertex, then the seams walked back to the first."""
    vertices = []
    for r in grid_rings:
        vertices += r + [r[0]]
    for r in reversed(grid_rings[1:-1]):
        vertices.append(r[0])
    return vertices


def main(path):
    glyphs = read_jhf(path)[:LAST - FIRST + 1]
    ys = [y for _, _, strokes in glyphs for s in strokes for _, y in s]
    y_middle = (min(ys) + max(ys)) / 2
    scale = 127 / ((max(ys) - min(ys)) / 2 + HALF_WIDTH + 0.5)
    print("# Radiance font file made by Brume's lib/pattern/fonts/make_font.py from %s" % path.split("/")[-1])
    print("# (strokes thickened to %.1f of 21 cap-height units, merged, on the 0-255 grid)." % (2 * HALF_WIDTH))
    print("# The Hershey Fonts were originally created by Dr. A. V. Hershey while working at the")
    print("# U. S. National Bureau of Standards.")
    print("# The format of the Font data in this distribution was originally created by James Hurt,")
    print("# Cognition, Inc., 900 Technology Park Drive, Billerica, MA 01821 (mit-eddie!ci-dandelion!hurt)")
    for code, (left, right, strokes) in enumerate(glyphs, FIRST):
        grid = [] if not strokes else [g for r in rings(outline(strokes)) if (g := to_grid(r, scale, (left + right) / 2, y_middle))]
        vertices = chained(grid)
        print("%d %d  # %r" % (code, len(vertices), chr(code)))
        for i in range(0, len(vertices), 8):
            print("  " + " ".join("%d %d" % v for v in vertices[i:i + 8]))


if __name__ == "__main__":
    main(sys.argv[1])
