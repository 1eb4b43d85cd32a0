#!/usr/bin/env python3
"""Writes the office's furniture and rays: desk.rad (placed by !xform), chair.rad (compiled by oconv -f into
chair.oct, placed as instances), cabinet.obj (compiled by obj2mesh into cabinet.rtm, placed as meshes),
sensors.txt and rays.txt. Run in this directory; make_reference.sh runs it."""


def box(modifier, name, lo, hi):
    """Six outward-facing polygons of an axis-aligned box from corner lo to corner hi."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    faces = {
        "bottom": [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],
        "top": [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
        "south": [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
        "north": [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],
        "west": [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],
        "east": [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
    }
    out = []
    for face, vertices in faces.items():
        out.append(f"{modifier} polygon {name}.{face}\n0\n0\n12")
        out += ["    %g %g %g" % v for v in vertices]
        out.append("")
    return "\n".join(out)


def desk():
    """A 1.4 m x 0.7 m desk centred on the origin, top 0.72-0.75 m, on four square legs."""
    parts = [box("desk_top", "top", (-0.7, -0.35, 0.72), (0.7, 0.35, 0.75))]
    for i, (x, y) in enumerate([(-0.65, -0.3), (0.6, -0.3), (-0.65, 0.25), (0.6, 0.25)]):
        parts.append(box("desk_leg", f"leg{i}", (x, y, 0), (x + 0.05, y + 0.05, 0.72)))
    return "# A desk centred on the origin (make_scene.py); its materials are the scene's.\n\n" + "\n".join(parts)


def chair():
    """A chair facing -y, centred on the origin: seat at 0.45 m, back up to 0.9 m; its own materials."""
    parts = [
        "void plastic chair_fabric\n0\n0\n5 .12 .16 .3 0 0\n",
        "void metal chair_frame\n0\n0\n5 .5 .5 .52 .8 .1\n",
        box("chair_fabric", "seat", (-0.23, -0.23, 0.42), (0.23, 0.23, 0.47)),
        box("chair_fabric", "back", (-0.23, 0.2, 0.5), (0.23, 0.24, 0.9)),
    ]
    for i, (x, y) in enumerate([(-0.22, -0.22), (0.19, -0.22), (-0.22, 0.19), (0.19, 0.19)]):
        parts.append(box("chair_frame", f"leg{i}", (x, y, 0), (x + 0.03, y + 0.03, 0.42)))
    return "# A chair centred on the origin (make_scene.py), compiled with its materials: oconv -f chair.rad\n\n" + "\n".join(parts)


def cabinet():
    """A 0.8 m x 0.45 m x 1.1 m cabinet, its back face on y = 0, as a Wavefront mesh of quads."""
    v = [(x, y, z) for z in (0, 1.1) for y in (-0.45, 0) for x in (-0.4, 0.4)]
    quads = [(1, 3, 4, 2), (5, 6, 8, 7), (1, 2, 6, 5), (3, 7, 8, 4), (1, 5, 7, 3), (2, 4, 8, 6)]
    lines = ["# A cabinet against a wall (make_scene.py); obj2mesh cabinet.obj cabinet.rtm"]
    lines += ["v %g %g %g" % p for p in v]
    lines += ["f %d %d %d %d" % q for q in quads]
    return "\n".join(lines) + "\n"


# Sensors 0.8 m above the floor, facing up: 6 columns x 5 rows, placed 13 cm or more from the edges of the
# sun patches (make_reference.sh checks) and clear of the furniture.
COLUMNS = [0.6, 1.6, 2.4, 3.6, 4.4, 5.4]
ROWS = [0.5, 1.2, 1.9, 2.6, 3.3]

# View rays from a standing eye near the north wall: "label x y z dx dy dz".
EYE = (3.0, 3.9, 1.6)
TARGETS = {
    "glass_west": (1.7, 0, 1.6), "glass_east": (4.3, 0, 1.5), "sun_patch": (1.7, 1.5, 0),
    "floor_shade": (3.0, 1.5, 0), "wall_between": (3.0, 0, 1.5), "ceiling": (3.0, 1.5, 3),
    "wall_west": (0, 2.0, 1.5), "desk_a": (1.8, 2.0, 0.75), "cabinet": (5.0, 3.5, 0.8),
}


def rays():
    lines = ["# label x y z dx dy dz: view rays from an eye near the north wall (make_scene.py)"]
    for label, t in TARGETS.items():
        d = [t[i] - EYE[i] for i in range(3)]
        n = sum(c * c for c in d) ** 0.5
        lines.append("%s %g %g %g %.6f %.6f %.6f" % ((label,) + EYE + tuple(c / n for c in d)))
    return "\n".join(lines) + "\n"


def sensors():
    lines = ["# label x y z dx dy dz: work-plane sensors facing up (make_scene.py)"]
    for y in ROWS:
        for x in COLUMNS:
            lines.append("s_%g_%g %g %g 0.8 0 0 1" % (x, y, x, y))
    return "\n".join(lines) + "\n"


for name, text in [("desk.rad", desk()), ("chair.rad", chair()), ("cabinet.obj", cabinet()),
                   ("sensors.txt", sensors()), ("rays.txt", rays())]:
    with open(name, "w") as f:
        f.write(text)
