#!/usr/bin/env python3
"""Writes grid.obj: a 20 x 20 height field of 800 triangles with smooth vertex normals and (u, v), whose
441 vertices fill two patches of a compiled mesh (256 vertices each), so that grid.rtm has triangles joining
patches. Run: python3 make_grid.py > grid.obj"""
import math

N = 20
print("# height field, written by make_grid.py\nusemtl ground")
for j in range(N + 1):
    for i in range(N + 1):
        x, y = i / N, j / N
        print(f"v {x:.6f} {y:.6f} {0.1 * math.sin(6 * x) * math.cos(4 * y):.6f}")
for j in range(N + 1):
    for i in range(N + 1):
        x, y = i / N, j / N
        gx, gy = 0.6 * math.cos(6 * x) * math.cos(4 * y), -0.4 * math.sin(6 * x) * math.sin(4 * y)
        print(f"vn {-gx:.6f} {-gy:.6f} 1\nvt {x:.6f} {y:.6f}")
for j in range(N):
    for i in range(N):
        a = j * (N + 1) + i + 1
        b, c, d = a + 1, a + N + 2, a + N + 1
        print(f"f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c} {d}/{d}/{d}")
