#!/usr/bin/env python3
"""Writes rays.txt (view rays, "label x y z dx dy dz") and sensors.txt (rtrace -I points with normals) for
scene.rad: each view ray is aimed at a point of one placed object, given in the object's own coordinates and
moved into the world by the placement's transforms (the first ones applied first, as Radiance's xf does);
the name of each ray says what it should meet. Sensors lie on the floor around and between the objects.
Points in penumbrae (where Radiance's -ds cells or single rays to the bulb's centre would show) were
moved away by hand, and so were points on the vault's edges between materials (where the two programs may
pick either side); one ray meets an edge between segments of the same material on purpose. Run: python3 make_rays.py ."""
import math
import sys


def rz(deg):
    a = math.radians(deg)
    return lambda p: (p[0] * math.cos(a) - p[1] * math.sin(a), p[0] * math.sin(a) + p[1] * math.cos(a), p[2])


def t(x, y, z):
    return lambda p: (p[0] + x, p[1] + y, p[2] + z)


def s(k):
    return lambda p: (p[0] * k, p[1] * k, p[2] * k)


def mx(p):
    return (-p[0], p[1], p[2])


def my(p):
    return (p[0], -p[1], p[2])


def place(p, *steps):
    for f in steps:
        p = f(p)
    return p


VAULT = (rz(20), t(1.5, 1.2, 0))
RED_VAULT = (s(.6), mx, rz(-15), t(-1.2, 3, 0))
TABLE1 = (rz(30), t(2.5, 3, 0))
TABLE2 = (s(1.5), my, t(-2, 1, 0))
GROUP = (rz(90), t(3, .5, 0))
GROUP_TABLE = (t(-.2, -.15, 0),) + GROUP
GROUP_VAULT = (s(.3), t(0, -.8, .002)) + GROUP


def on_vault(angle_deg, y):
    a = math.radians(angle_deg)
    return (.5 * math.cos(a), y, .5 * math.sin(a))


# label, point in the object's coordinates, its placement, direction the viewer looks from (toward the point)
VIEWS = [
    ("vault_paint_top", on_vault(79, .5), VAULT, (0, 0, -1)),
    ("vault_paint_side", on_vault(33, .3), VAULT, (-.6, .1, -.5)),
    # exactly on the edge between two paint segments: a shadow ray leaving one must not stop at the other
    ("vault_paint_edge", on_vault(30, .3), VAULT, (-.6, .1, -.5)),
    ("vault_paint_low", on_vault(11, .8), VAULT, (-1, .2, -.3)),
    ("vault_tile_top", on_vault(101, .4), VAULT, (0, 0, -1)),
    ("vault_tile_side", on_vault(147, .6), VAULT, (.7, -.2, -.4)),
    ("vault_tile_grazing", on_vault(118, .2), VAULT, (.3, .1, -.2)),
    ("vault_far_cap", (-.15, 1, .25), VAULT, (0, -1, -.3)),
    ("red_vault_top", on_vault(71, .5), RED_VAULT, (0, 0, -1)),
    ("red_vault_side", on_vault(142, .3), RED_VAULT, (.5, -.3, -.5)),
    ("red_vault_other_side", on_vault(34, .7), RED_VAULT, (-.6, .2, -.4)),
    ("table1_top", (.3, .2, .5), TABLE1, (0, 0, -1)),
    ("table1_top_oblique", (.1, .1, .5), TABLE1, (.3, -.5, -.6)),
    ("table1_knob", (.2, .15, .7), TABLE1, (0, 0, -1)),
    ("table1_knob_side", (.3, .15, .6), TABLE1, (-1, .2, -.1)),
    ("table1_edge", (.2, 0, .49), TABLE1, (0, 1, 0)),
    ("table1_leg", (.05, .02, .25), TABLE1, (-.1, 1, -.2)),
    ("table2_top", (.3, .25, .5), TABLE2, (0, 0, -1)),
    ("table2_knob", (.15, .2, .62), TABLE2, (.2, .3, -1)),
    ("table2_edge", (.1, 0, .49), TABLE2, (0, -1, .1)),
    ("table2_leg", (.35, .22, .3), TABLE2, (.1, -1, -.2)),
    ("group_plate", (.45, .2, .002), GROUP, (0, 0, -1)),
    ("group_plate_2", (-.3, .35, .002), GROUP, (.3, 0, -1)),
    ("group_table_top", (.1, .25, .5), GROUP_TABLE, (0, 0, -1)),
    ("group_table_knob", (.2, .15, .7), GROUP_TABLE, (0, 0, -1)),
    ("group_vault_top", on_vault(84, .5), GROUP_VAULT, (0, 0, -1)),
    ("group_vault_tile", on_vault(128, .5), GROUP_VAULT, (0, .5, -1)),
]

# patterned.rad: patterns in placed tiles and meshes (the tiles at z = .01, colour tile x 0…1, texture tile x 1.1…2.1)
TILES_A = (rz(30), t(-2, -1.5, 0))
TILES_B = (s(1.2), mx, t(3, -1.8, 0))
UV_VAULT = (rz(20), t(-1.5, 2, 0))
P_VAULT = (s(1.3), rz(-10), t(1.8, 1.5, 0))
PATTERNED_VIEWS = [
    ("tilesA_colour_1", (.2, .3, .01), TILES_A, (0, 0, -1)),
    ("tilesA_colour_2", (.7, .6, .01), TILES_A, (.3, .2, -1)),
    ("tilesA_colour_3", (.45, .85, .01), TILES_A, (-.2, .4, -1)),
    ("tilesA_texture_1", (1.3, .2, .01), TILES_A, (0, 0, -1)),
    ("tilesA_texture_2", (1.75, .55, .01), TILES_A, (.2, -.3, -1)),
    ("tilesA_texture_3", (1.9, .9, .01), TILES_A, (0, 0, -1)),
    ("tilesB_colour_1", (.25, .35, .01), TILES_B, (0, 0, -1)),
    ("tilesB_colour_2", (.8, .75, .01), TILES_B, (.1, .3, -1)),
    ("tilesB_texture_1", (1.4, .3, .01), TILES_B, (0, 0, -1)),
    ("tilesB_texture_2", (1.85, .7, .01), TILES_B, (-.3, .1, -1)),
    ("uv_vault_1", on_vault(40, .2), UV_VAULT, (0, 0, -1)),
    ("uv_vault_2", on_vault(95, .7), UV_VAULT, (0, 0, -1)),
    ("uv_vault_3", on_vault(140, .45), UV_VAULT, (.5, -.2, -.6)),
    ("uv_vault_4", on_vault(62, .9), UV_VAULT, (-.4, .1, -.7)),
    ("pvault_paint_1", on_vault(50, .25), P_VAULT, (0, 0, -1)),
    ("pvault_paint_2", on_vault(20, .6), P_VAULT, (-.7, .1, -.4)),
    ("pvault_paint_3", on_vault(75, .85), P_VAULT, (0, 0, -1)),
    ("pvault_tile_1", on_vault(105, .3), P_VAULT, (0, 0, -1)),
    ("pvault_tile_2", on_vault(135, .65), P_VAULT, (.6, -.1, -.5)),
    ("pvault_tile_3", on_vault(160, .5), P_VAULT, (.8, .2, -.3)),
]

SENSORS = [
    ("floor_open", (0, 0, 0)),
    ("floor_by_vault", (.6, .8, 0)),
    ("floor_behind_vault", (2.4, 1.6, 0)),
    ("floor_under_panel", (1.4, 1.5, 0)),
    ("floor_by_red_vault", (-1.6, 2.3, 0)),
    ("floor_under_table2", (-1.6, .8, 0)),
    ("floor_by_table2", (-2.8, 1.8, 0)),
    ("floor_by_table1", (2.2, 2.5, 0)),
    ("floor_by_group", (3.6, 1.4, 0)),
    ("floor_between", (.5, 3.5, 0)),
    ("floor_far", (3.5, 4.5, 0)),
    ("floor_west", (-2.5, 4, 0)),
]


def write_views(path, views):
    with open(path, "w") as f:
        f.write("# label  x y z  dx dy dz  (make_rays.py)\n")
        for label, p, steps, d in views:
            q = place(p, *steps)
            n = math.sqrt(sum(c * c for c in d))
            d = tuple(c / n for c in d)
            o = tuple(q[i] - 1.5 * d[i] for i in range(3))
            f.write(f"{label} {o[0]:.9f} {o[1]:.9f} {o[2]:.9f} {d[0]:.9f} {d[1]:.9f} {d[2]:.9f}\n")


def main(out):
    write_views(f"{out}/rays.txt", VIEWS)
    write_views(f"{out}/patterned_rays.txt", PATTERNED_VIEWS)
    with open(f"{out}/sensors.txt", "w") as f:
        f.write("# label  x y z  nx ny nz  (make_rays.py)\n")
        for label, p in SENSORS:
            f.write(f"{label} {p[0]} {p[1]} {p[2]} 0 0 1\n")


main(sys.argv[1] if len(sys.argv) > 1 else ".")
