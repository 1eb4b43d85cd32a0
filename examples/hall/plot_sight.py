#!/usr/bin/python3
"""Pictures of vismap's CSVs (vismap(1)), with matplotlib.

    plot_sight.py sight.csv [more.csv ...] -o plots.png

    plot_sight.py sight.csv -o plots.png --level 4      # the criterion the study used (vismap -vl; default 10)
    plot_sight.py sight.csv -o plots.png --plan building.rad --fire 17.4,0.7   # over the floor plan

With --plan (Radiance scenes, e.g. fds2rad's), the maps are drawn over the floor plan at the eyes' height: the
walls (vertical polygons across that height) as lines, the study's signs (polygons of their names) in green with
their names, the fire (--fire x,y) as a red star.

Grid observers (cell_C_R): maps, one row per file and sign, one column per instant, each cell coloured by the
sign's visibility level (log scale; white where the sign is hidden or seen from behind, grey with "?" where the
line lacks smoke data: vismap's no-data), outlined in black where it is visible by the light (level >= the
criterion), crossed where Jin's law says otherwise. Waypoints: the contrast and the visibility level over time,
one line per waypoint and sign, the criterion drawn. Empty fields of the CSV (no level where the sign is hidden
or behind) are gaps.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.colors as colors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def scene_words(path):
    """The words of a Radiance scene file, comments and commands left out."""
    with open(path) as f:
        for line in f:
            if line.lstrip().startswith(("#", "!")):
                continue
            yield from line.split()


def polygons(paths):
    """{name: [(x, y, z), ...]} of the polygons of Radiance scene files."""
    out = {}
    for path in paths:
        words = scene_words(path)
        for modifier in words:
            kind, name = next(words), next(words)
            args = []
            for _ in range(2):  # strings and integers
                n = int(next(words))
                args.append([next(words) for _ in range(n)])
            reals = [float(next(words)) for _ in range(int(next(words)))]
            if kind == "polygon":
                out[name] = [tuple(reals[i:i + 3]) for i in range(0, len(reals) - 2, 3)]
    return out


def draw_plan(ax, plan, height, signs, fire):
    """The walls across `height` as lines, the signs in green, the fire as a star."""
    for name, vertices in plan.items():
        zs = [v[2] for v in vertices]
        if not (min(zs) <= height <= max(zs)) or max(zs) - min(zs) < 1e-6:
            continue
        xs, ys = [v[0] for v in vertices], [v[1] for v in vertices]
        # a vertical polygon seen from above: the segment between its plan's farthest points
        pts = sorted(zip(xs, ys))
        (x0, y0), (x1, y1) = pts[0], pts[-1]
        if name in signs:
            ax.plot([x0, x1], [y0, y1], color="lime", lw=3, solid_capstyle="butt")
            ax.annotate(name, ((x0 + x1) / 2, (y0 + y1) / 2), fontsize=6, color="darkgreen",
                        xytext=(2, 2), textcoords="offset points")
        else:
            ax.plot([x0, x1], [y0, y1], color="black", lw=0.8)
    if fire:
        ax.plot(*fire, marker="*", color="red", ms=10, mec="black", mew=0.5)


def value(r, key):
    """A number of the CSV, NaN where the field is empty (vismap leaves what is not there empty)."""
    return float(r[key]) if r.get(key) else math.nan


def rows_of(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def grid_panels(files):
    """(label, sign, instant) -> {(x, y): row}."""
    panels = {}
    for path, rows in files:
        label = os.path.splitext(os.path.basename(path))[0]
        for r in rows:
            key = (label, r["sign"], float(r["instant_s"]))
            panels.setdefault(key, {})[(float(r["x"]), float(r["y"]))] = r
    return panels


def plot_maps(files, out, level, plan=None, fire=None):
    panels = grid_panels(files)
    rows = sorted({(k[0], k[1]) for k in panels}, key=lambda k: (k[0], k[1]))
    instants = sorted({k[2] for k in panels})
    fig, axes = plt.subplots(len(rows), len(instants), figsize=(max(5.0, 3.2 * len(instants)), 3.0 * len(rows)),
                             squeeze=False, constrained_layout=True)
    norm = colors.LogNorm(vmin=0.1, vmax=1e4)
    image = None
    for i, (label, sign) in enumerate(rows):
        for j, t in enumerate(instants):
            ax = axes[i][j]
            cells = panels.get((label, sign, t), {})
            xs = sorted({p[0] for p in cells})
            ys = sorted({p[1] for p in cells})
            step = xs[1] - xs[0] if len(xs) > 1 else 1.0
            grid = [[math.nan] * len(xs) for _ in ys]
            for (x, y), r in cells.items():
                seen = r["verdict"] in ("visible", "below-threshold")
                grid[ys.index(y)][xs.index(x)] = max(value(r, "visibility_level"), 0.1) if seen else math.nan
            extent = (xs[0] - step / 2, xs[-1] + step / 2, ys[0] - step / 2, ys[-1] + step / 2)
            image = ax.imshow(grid, origin="lower", extent=extent, norm=norm, cmap="viridis")
            for (x, y), r in cells.items():
                light = r["verdict"] == "visible"
                if light:
                    ax.add_patch(plt.Rectangle((x - step / 2, y - step / 2), step, step, fill=False, lw=0.6))
                if r["verdict"] == "no-data":
                    ax.add_patch(plt.Rectangle((x - step / 2, y - step / 2), step, step, color="0.8", lw=0))
                    ax.text(x, y, "?", ha="center", va="center", fontsize=5)
                elif light != (r["jin_verdict"] == "visible"):
                    ax.plot(x, y, "x", color="red", ms=4, mew=1)
            if plan:
                draw_plan(ax, plan, float(next(iter(cells.values()))["z"]), {sign}, fire)
            ax.set_title(f"{label}: {sign}, t = {t:g} s", fontsize=9)
            ax.set_xlabel("x (m)", fontsize=8)
            ax.set_ylabel("y (m)", fontsize=8)
            ax.tick_params(labelsize=7)
    fig.colorbar(image, ax=axes, shrink=0.6, label=f"visibility level (Adrian); outlined: visible (>= {level:g}); "
                                                   "x: Jin's law differs; ?: no smoke data")
    fig.savefig(out, dpi=110)


def plot_waypoints(files, out, level):
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True, constrained_layout=True)
    for path, rows in files:
        series = {}
        for r in rows:
            series.setdefault((r["observer"], r["sign"]), []).append(r)
        for (observer, sign), rs in series.items():
            t = [float(r["instant_s"]) for r in rs]
            label = f"{observer} ({float(rs[0]['distance_m']):.1f} m), {sign}"
            top.plot(t, [value(r, "contrast") for r in rs], "o-", label=label)
            bottom.plot(t, [max(value(r, "visibility_level"), 0.1) for r in rs], "o-", label=label)
    bottom.axhline(level, color="black", lw=0.8, ls="--")
    bottom.text(bottom.get_xlim()[0], level, f" visible above: level {level:g}", va="bottom", fontsize=7)
    top.set_ylabel("contrast (L_sign / L_background - 1)")
    bottom.set_ylabel("visibility level (Adrian)")
    bottom.set_yscale("log")
    bottom.set_xlabel("t (s)")
    top.legend(fontsize=7)
    fig.savefig(out, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", nargs="+")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--level", type=float, default=10, help="the study's criterion (vismap -vl; default 10)")
    parser.add_argument("--plan", action="append", help="Radiance scene files whose walls and signs to draw")
    parser.add_argument("--fire", help="x,y of the fire, to mark")
    args = parser.parse_args()
    files = [(path, rows_of(path)) for path in args.csv]
    if not any(rows for _, rows in files):
        sys.exit("plot_sight.py: no rows in " + ", ".join(args.csv))
    grid = all(r["observer"].startswith("cell_") for _, rows in files for r in rows)
    if grid:
        fire = tuple(float(v) for v in args.fire.split(",")) if args.fire else None
        plot_maps(files, args.output, args.level, polygons(args.plan) if args.plan else None, fire)
    else:
        plot_waypoints(files, args.output, args.level)


if __name__ == "__main__":
    main()
