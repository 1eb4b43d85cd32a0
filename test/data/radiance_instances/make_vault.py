#!/usr/bin/env python3
"""Writes vault.obj: a half cylinder (a barrel vault) of radius 0.5 and length 1 along y, its axis on the x
axis's line z = 0, made of 12 segments, each a quad with smooth (radial) vertex normals and (u, v) texture
coordinates (u: angle / pi, v: y). The first half of the segments uses material "paint", the second "tile";
the end caps are 12-sided polygons with no normals ("paint"), which obj2mesh triangulates.
Run: python3 make_vault.py > vault.obj"""
import math

N = 12
print("# barrel vault, written by make_vault.py")
for y in (0.0, 1.0):
    for i in range(N + 1):
        a = math.pi * i / N
        print(f"v {0.5 * math.cos(a):.9f} {y:.9f} {0.5 * math.sin(a):.9f}")
for i in range(N + 1):
    a = math.pi * i / N
    print(f"vn {math.cos(a):.9f} 0 {math.sin(a):.9f}")
for y in (0.0, 1.0):
    for i in range(N + 1):
        print(f"vt {i / N:.9f} {y:.9f}")
# vertex k at y0 is k+1, at y1 is N+2+k; normal k+1; texture as vertex
for i in range(N):
    if i == 0:
        print("usemtl paint")
    if i == N // 2:
        print("usemtl tile")
    a, b = i + 1, i + 2  # at y = 0, angles i and i + 1
    d, c = N + 2 + i, N + 3 + i  # at y = 1
    # counter-clockwise seen from outside, where the normals point
    print(f"f {a}/{a}/{i + 1} {d}/{d}/{i + 1} {c}/{c}/{i + 2} {b}/{b}/{i + 2}")
print("usemtl paint")
print("f " + " ".join(str(k + 1) for k in range(N + 1)))  # the end at y = 0, facing -y
print("f " + " ".join(str(-(k + 1)) for k in range(N + 1)))  # the end at y = 1 by negative indices: faces +y
