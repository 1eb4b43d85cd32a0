#!/usr/bin/env python3
"""Writes sensors.txt, rays.txt and rays_glow.txt for the mkillum room (room.rad), and checks that every
sensor called sun_* is in the sun patch, and every other one out of it, by at least MARGIN in the window
plane. The sun's direction is read from sky.rad (gensky's output). Run in this directory;
make_reference.sh runs it."""
import math
import sys

WINDOW_X = (1.0, 3.0)   # the window opening in the south wall y = 0
WINDOW_Z = (0.9, 2.4)
MARGIN = 0.10           # metres, in the window plane, from the edges of the sun's beam


def sun_direction():
    """The direction of gensky's "solar source sun" in sky.rad."""
    words = open("sky.rad").read().split()
    i = words.index("sun")
    assert words[i - 2:i] == ["solar", "source"], "sky.rad: no solar source sun"
    # sun 0 0 4 dx dy dz angle
    return tuple(float(w) for w in words[i + 4:i + 7])


def beam_margin(p, sun):
    """Signed distance, in the window plane, from where p's ray to the sun crosses y = 0 to the nearest
    window edge: > 0 inside the window (p in the sun patch), < 0 outside; None if it never crosses."""
    if p[1] <= 0 or sun[1] >= 0:
        return None
    t = -p[1] / sun[1]
    x, z = p[0] + t * sun[0], p[2] + t * sun[2]
    return min(x - WINDOW_X[0], WINDOW_X[1] - x, z - WINDOW_Z[0], WINDOW_Z[1] - z)


# Sensors "label x y z dx dy dz": sun_* in the sun patch, the rest in the shade.
UP, DOWN = (0, 0, 1), (0, 0, -1)
SOUTH, NORTH, EAST, WEST = (0, -1, 0), (0, 1, 0), (1, 0, 0), (-1, 0, 0)
SENSORS = [
    # the floor's sun patch, facing up
    ("sun_floor_1.4_1.2", (1.4, 1.2, 0.001), UP), ("sun_floor_2.0_1.2", (2.0, 1.2, 0.001), UP),
    ("sun_floor_2.6_1.2", (2.6, 1.2, 0.001), UP), ("sun_floor_1.4_1.7", (1.4, 1.7, 0.001), UP),
    ("sun_floor_2.0_1.7", (2.0, 1.7, 0.001), UP), ("sun_floor_2.6_1.7", (2.6, 1.7, 0.001), UP),
    ("sun_floor_1.4_2.2", (1.4, 2.2, 0.001), UP), ("sun_floor_2.0_2.2", (2.0, 2.2, 0.001), UP),
    ("sun_floor_2.6_2.2", (2.6, 2.2, 0.001), UP),
    # the work plane (0.8 m) in the sun, facing up; a vertical sensor in the beam facing the window
    ("sun_wp_1.5_0.6", (1.5, 0.6, 0.8), UP), ("sun_wp_2.5_0.6", (2.5, 0.6, 0.8), UP),
    ("sun_wp_2.0_1.2", (2.0, 1.2, 0.8), UP),
    ("sun_vertical_2.0_1.5", (2.0, 1.5, 0.5), SOUTH),
    # the work plane in the shade, front to back, facing up
    ("wp_0.4_0.5", (0.4, 0.5, 0.8), UP), ("wp_3.6_1.5", (3.6, 1.5, 0.8), UP),
    ("wp_0.5_3.0", (0.5, 3.0, 0.8), UP), ("wp_2.0_3.0", (2.0, 3.0, 0.8), UP), ("wp_3.5_3.0", (3.5, 3.0, 0.8), UP),
    ("wp_0.5_4.5", (0.5, 4.5, 0.8), UP), ("wp_2.0_4.5", (2.0, 4.5, 0.8), UP), ("wp_3.5_4.5", (3.5, 4.5, 0.8), UP),
    # the floor in the shade: below the sill in front of the window, and at the back
    ("floor_2.0_0.4", (2.0, 0.4, 0.001), UP), ("floor_2.0_3.5", (2.0, 3.5, 0.001), UP),
    ("floor_3.5_4.5", (3.5, 4.5, 0.001), UP),
    # walls and ceiling, facing into the room (1 cm off the surface)
    ("north_wall_2.0_1.5", (2.0, 4.99, 1.5), SOUTH), ("east_wall_2.5_1.5", (3.99, 2.5, 1.5), WEST),
    ("west_wall_1.0_1.5", (0.01, 1.0, 1.5), EAST), ("ceiling_2.0_1.0", (2.0, 1.0, 2.99), DOWN),
    ("ceiling_2.0_3.5", (2.0, 3.5, 2.99), DOWN),
    # mid-room, facing the window at eye height, and facing sideways (grazing the window plane)
    ("eye_2.0_3.0_facing_window", (2.0, 3.0, 1.2), SOUTH), ("eye_0.5_1.0_facing_east", (0.5, 1.0, 1.6), EAST),
    # outside, half a metre in front of the window, facing it: behind the illum, which lights only its front
    ("outside_facing_window", (2.0, -0.5, 1.6), NORTH),
]

# View rays "label x y z dx dy dz" from eyes in the room (and one outside), each aimed at a point.
EYE = (2.0, 4.2, 1.6)
LOW_EYE = (2.0, 1.0, 0.8)
SIDE_EYE = (0.5, 3.0, 1.6)
OUTSIDE_EYE = (2.0, -3.0, 1.6)
RAYS = [
    # through the window: the sky just above the horizon, the sunlit ground, the sky high up
    ("window_centre", EYE, (2.0, 0, 1.65)), ("window_sky_low", EYE, (2.0, 0, 2.3)),
    ("window_ground", EYE, (2.2, 0, 1.0)), ("window_oblique", SIDE_EYE, (2.8, 0, 1.5)),
    ("window_sky_high", LOW_EYE, (1.8, 0, 2.2)), ("window_sky_high_west", LOW_EYE, (1.2, 0, 1.9)),
    # room surfaces
    ("floor_sun_patch", EYE, (2.0, 1.7, 0)), ("floor_shade", EYE, (3.5, 3.5, 0)),
    ("floor_below_window", EYE, (2.0, 0.4, 0)), ("ceiling", EYE, (2.0, 1.5, 3)),
    ("east_wall", EYE, (4, 2.0, 1.5)), ("west_wall", EYE, (0, 1.0, 1.5)),
    ("south_wall_beside_window", EYE, (0.5, 0, 1.5)), ("north_wall", LOW_EYE, (2.0, 5, 1.2)),
    # from outside into the room through the window (its back side)
    ("outside_in", OUTSIDE_EYE, (2.0, 0, 1.65)),
]
# View rays through the window toward the glow of glow.rad
GLOW_RAYS = [
    ("glow_centre", EYE, (2.0, 0, 1.65)), ("glow_upper_west", EYE, (1.2, 0, 2.2)),
    ("glow_lower_east", EYE, (2.8, 0, 1.1)), ("glow_oblique", SIDE_EYE, (2.8, 0, 1.5)),
    ("glow_steep", LOW_EYE, (1.8, 0, 2.2)),
]


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def main():
    sun = sun_direction()
    bad = 0
    lines = ["# label x y z dx dy dz: sensors for rtrace -I (make_scene.py); sun_* in the sun patch, at least"
             " %g m in the window plane from its edges, the rest at least as far out of it" % MARGIN]
    for label, p, n in SENSORS:
        m = beam_margin(p, sun)
        lit = m is not None and m > 0 and p[2] < 3 and 0 < p[0] < 4
        if label.startswith("sun_") != lit or (m is not None and abs(m) < MARGIN and lit):
            print("make_scene.py: %s: margin %s" % (label, m), file=sys.stderr)
            bad += 1
        elif not lit and m is not None and -MARGIN < m:
            print("make_scene.py: %s: %g m from the sun's beam" % (label, -m), file=sys.stderr)
            bad += 1
        lines.append("%s %g %g %g %g %g %g" % ((label,) + p + n))
    open("sensors.txt", "w").write("\n".join(lines) + "\n")

    for name, rays, what in [("rays.txt", RAYS, "view rays"),
                             ("rays_glow.txt", GLOW_RAYS, "view rays through the window to glow.rad's glow")]:
        lines = ["# label x y z dx dy dz: %s (make_scene.py)" % what]
        for label, org, target in rays:
            d = unit(tuple(target[i] - org[i] for i in range(3)))
            cos_sun = sum(d[i] * sun[i] for i in range(3))
            if cos_sun > math.cos(math.radians(5)):
                print("make_scene.py: %s: within 5 degrees of the sun" % label, file=sys.stderr)
                bad += 1
            lines.append("%s %g %g %g %.6f %.6f %.6f" % ((label,) + org + d))
        open(name, "w").write("\n".join(lines) + "\n")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
