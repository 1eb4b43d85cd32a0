#!/usr/bin/env python3
"""Writes rays.txt for test/data/material_functions: label x y z dx dy dz.

For each floor panel, at three points: a ray along the mirror direction of the nearest lamp (the peak of the
highlight), two rays with the view turned off that direction by 0.25 rad across x and across y (the
anisotropy shows as their difference), and a steep view. For the trans2 panels (z = 1), rays from below
straight toward the lamp above (the peak of the transmitted lobe), turned off it, and a ray from above.
Usage: python3 make_rays.py > rays.txt
"""
import math

lamps = [(1.5, 0.5, 2), (4.5, 0.5, 2), (1.5, 2.5, 4), (7.5, 0.5, 2), (3.5, 2.5, 4)]
floor = ["plastic2", "metal2", "parallel", "textured", "spiral", "plasfunc", "metfunc", "plasdata", "metdata"]
trans = ["trans2", "trans2_circles", "transfunc", "transdata"]


def norm(v):
    length = math.sqrt(sum(c * c for c in v))
    return tuple(c / length for c in v)


def turn(d, axis, angle):
    """d rotated by angle about the x (axis 0) or y (axis 1) axis."""
    c, s = math.cos(angle), math.sin(angle)
    x, y, z = d
    if axis == 0:
        return (x, c * y - s * z, s * y + c * z)
    return (c * x + s * z, y, -s * x + c * z)


def nearest(p):
    return min((l for l in lamps if abs(l[1] - p[1]) < 1.5 and l[2] > p[2]), key=lambda l: (l[0] - p[0]) ** 2 + (l[1] - p[1]) ** 2)


def ray(label, p, d, back=1.5):
    o = tuple(p[i] - back * d[i] for i in range(3))
    print(label, " ".join("%.6f" % c for c in o), " ".join("%.6f" % c for c in d))


print("# label x y z dx dy dz (view rays for test/data/material_functions, made by make_rays.py)")
for k, name in enumerate(floor):
    for j, (px, py) in enumerate([(0.3, 0.35), (0.55, 0.7), (0.8, 0.45)]):
        p = (k + px, py, 0)
        lamp = nearest(p)
        peak = norm((lamp[0] - p[0], lamp[1] - p[1], -lamp[2]))
        ray("%s_peak_%d" % (name, j), p, peak)
        ray("%s_offx_%d" % (name, j), p, norm(turn(peak, 1, 0.25)))
        ray("%s_offy_%d" % (name, j), p, norm(turn(peak, 0, 0.25)))
        ray("%s_steep_%d" % (name, j), p, norm((0.1, 0.2, -1)))
for k, name in enumerate(trans):
    for j, (px, py) in enumerate([(0.35, 0.4), (0.7, 0.6)]):
        p = (k + px, 2 + py, 1)
        lamp = nearest(p)
        up = norm((lamp[0] - p[0], lamp[1] - p[1], lamp[2] - p[2]))
        ray("%s_through_%d" % (name, j), p, up, 0.6)
        ray("%s_offx_%d" % (name, j), p, norm(turn(up, 1, 0.2)), 0.6)
        ray("%s_offy_%d" % (name, j), p, norm(turn(up, 0, 0.2)), 0.6)
        ray("%s_above_%d" % (name, j), p, norm((0.3, -0.2, -1)), 0.6)
