#!/usr/bin/env python3
"""Fire pictures: run time against error of pictures lit by a flame, against path-traced references.

Scenes (examples/flame: make_flame's plume, 1500 K at its core, soot K_m 8700 m²/kg, albedo .2, g .6, in a dark
5 m x 4 m x 2.7 m room):
  room      the demo's view of the room (rpict -vp -2.3 -1.8 1.5 -vd 1 .85 -.35 -vh 80 -vv 62): the plume seen
            through the room, the walls and floor lit by it (next-event estimation of the flame), the smoke lit by
            its own flame; at -ab 0 (76 x 60 rays) and at -ab 1 (one diffuse bounce, -al+ for the cache; 40 x 30).
  thick     the same plume with five times the soot (K_m 43,500: its core about 8.5 /m, a flame one cannot see
            into) seen from 1.2 m over 50°, -ab 1 (32 x 32 rays): the flame's light comes from its near side,
            through its own cooler soot, and its smoke scatters it.
Path tracing (-aa 0, -ad 128 at -ab 1) repeats each ray r = 1, 4, 16 times; the caches (-aa .1 and .05, -ad
1024; records shared by all the picture's rays and repeats) r = 1 and 4 times, at -ab 1: the error of these
pictures is mostly the view rays' own (the flame's light along them, and the light their smoke scatters, with a
phase function's ray from each of its points at -ab 1), which -ad does not lower. With --before BIN, path
tracing by another build too (the session's start), on the same rays. Error: the RMS over the pixels of (value −
reference) over the mean reference luminance, with the reference's own error (from its repeats' spread) taken
out; "p99.9/RMS": the 99.9th percentile of the pixels' absolute errors over their RMS (3.3 for errors of a normal
law); beside them the same two for the pixels' relative errors (those above a hundredth of the mean luminance):
a flame's core is a thousand times the mean luminance, and two or three of its pixels make most of the first
RMS, and of its tail. One thread, CPU seconds; the time to 2 % interpolated along each ladder (bench.time_to), on
the relative RMS. The references (path tracing, REFERENCE_REPEATS repeats at -ab 0; -ad 512 and
REFERENCE_AD_REPEATS repeats at -ab 1; on two threads) are kept in results/fire_references.json, made anew when
the scene, the options or the rays change or with --remake-reference.
Before them, flames seen along one ray (the table "Planck"): a cube of smoke 2 m across at 1500 K and 2000 K (its
temperature grid wider than its density's), albedo 0, K 0.5 to 500 /m, 16 rays face-on through its middle at
rtrace -ab 0 -u+, in RGB and with -cs 41 -pY: their mean luminance against Planck's B (1 − e^{−2K}) (683 lm/W
∫ B ȳ, the CIE's 1 nm table) and the spread of one ray (needs /usr/bin/python3 with pyopenvdb to write the grids).
Writes results/fire.md and results/fire_time_vs_error.png.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench import RESULTS, ROOT, Timer, git_commit, ladders_plot, lux, read_rgb, sha256, time_to, write_result  # noqa: E402

ROOM = os.path.join(ROOT, "examples", "flame", "room.rad")
STORED = os.path.join(RESULTS, "fire_references.json")
REFERENCE_REPEATS, REFERENCE_AD, REFERENCE_AD_REPEATS = 256, "512", 64
PATHS = [1, 4, 16]
CACHED = [(".1", 1), (".1", 4), (".05", 4)]
TARGET = 0.02
ROOM_VIEW = ["-vp", "-2.3", "-1.8", "1.5", "-vd", "1", "0.85", "-0.35", "-vh", "80", "-vv", "62"]
THICK_VIEW = ["-vp", "-1.2", "0", "0.5", "-vd", "1", "0", "0", "-vh", "50", "-vv", "50", "-x", "32", "-y", "32"]
THICK_SMOKE = "void smoke fire 2 temperature=temperature flame.vdb 0 7 43500 43500 43500 .2 .2 .2 .6\n"


def thick_room(tmp):
    """The room with the plume's soot five times as dense."""
    with open(ROOM) as f:
        text = "".join(l for l in f if not l.startswith("void smoke fire"))
    path = os.path.join(tmp, "thick.rad")
    with open(path, "w") as f:
        f.write(text + THICK_SMOKE)
    return path


def cases(tmp):
    """(name, scene, view, options) of each picture."""
    thick = thick_room(tmp)
    return [("room, -ab 0", ROOM, ROOM_VIEW + ["-x", "80", "-y", "60"], ["-ab", "0"]),
            ("room, -ab 1", ROOM, ROOM_VIEW + ["-x", "40", "-y", "30"], ["-ab", "1"]),
            ("thick flame, -ab 1", thick, THICK_VIEW, ["-ab", "1"])]


def rays(bin_dir, tmp, view):
    """The view's rays (vwrays), as rtrace's input lines."""
    out = subprocess.run([os.path.join(bin_dir, "vwrays"), "-fa"] + view, capture_output=True, text=True, check=True)
    return [l for l in out.stdout.splitlines() if l.strip()]


def trace(bin_dir, tmp, scene, lines, options, repeats, threads=1):
    """Each ray traced `repeats` times: (per-pixel mean luminance, per-pixel standard error, CPU s)."""
    path = os.path.join(tmp, "rays.txt")
    with open(path, "w") as f:
        for l in lines:
            f.write((l + "\n") * repeats)
    cmd = [os.path.join(bin_dir, "rtrace"), "-h", "-ov", "-n", str(threads)] + options + [scene]
    t = Timer(cmd, path, env=dict(os.environ, RAYPATH=tmp + ":" + os.environ.get("RAYPATH", ".")))
    values = [lux(rgb) for rgb in read_rgb(t.out)]
    means, errors = [], []
    for k in range(0, len(values), repeats):
        g = values[k:k + repeats]
        m = sum(g) / repeats
        means.append(m)
        errors.append((sum((v - m) ** 2 for v in g) / max(1, repeats - 1) / repeats) ** .5 if repeats > 1 else 0)
    return means, errors, t.cpu


def reference(bin_dir, tmp, case, lines, stored, remake, commit):
    """The case's path-traced reference (kept in `stored`): per-pixel means and standard errors."""
    name, scene, _, options = case
    direct = options[options.index("-ab") + 1] == "0"
    opts = ["-aa", "0"] + ([] if direct else ["-ad", REFERENCE_AD]) + options
    repeats = REFERENCE_REPEATS if direct else REFERENCE_AD_REPEATS
    key = {"scene": sha256(scene), "rays": len(lines), "first_ray": lines[0], "options": opts, "repeats": repeats}
    kept = stored.get(name)
    if kept and kept["key"] == key and not remake:
        return kept["means"], kept["errors"]
    print(f"  {name}: tracing the reference ({' '.join(opts)} x{repeats}, two threads)", file=sys.stderr)
    means, errors, cpu = trace(bin_dir, tmp, scene, lines, opts, repeats, threads=2)
    stored[name] = {"key": key, "means": means, "errors": errors, "cpu": cpu, "commit": commit}
    return means, errors


def ladders(options):
    """{method: [(repeats, options)]} of a case."""
    if options[options.index("-ab") + 1] == "0":
        return {"path tracing": [(r, ["-aa", "0"] + options) for r in PATHS]}
    return {"path tracing": [(r, ["-aa", "0", "-ad", "128"] + options) for r in PATHS],
            "cache": [(r, ["-aa", a, "-ad", "1024", "-al+"] + options) for a, r in CACHED]}


def measure(values, means, errors):
    """Over the mean luminance: the RMS error with the reference's own taken out, the p99.9 of |error| over the RMS;
    and the same two of the pixels' relative errors (those above a hundredth of the mean luminance); and the
    reference's own two RMS errors."""
    mean = sum(means) / len(means)

    def rms_and_tail(diffs, own):
        diffs = sorted(abs(d) for d in diffs)
        rms = (sum(d * d for d in diffs) / len(diffs)) ** .5
        p999 = diffs[min(len(diffs) - 1, int(math.ceil(0.999 * len(diffs))) - 1)]
        return math.sqrt(max(0.0, rms * rms - own * own)), p999 / rms if rms > 0 else 0

    lit = [(v, r, e) for v, r, e in zip(values, means, errors) if r > 0.01 * mean]
    own = (sum(e * e for e in errors) / len(errors)) ** .5
    own_relative = (sum((e / r) ** 2 for _, r, e in lit) / len(lit)) ** .5
    absolute, tail = rms_and_tail([v - r for v, r in zip(values, means)], own)
    relative, relative_tail = rms_and_tail([(v - r) / r for v, r, _ in lit], own_relative)
    return absolute / mean, tail, relative, relative_tail, own / mean, own_relative


CUBE = """import pyopenvdb as vdb, sys
def box(lo, hi, v, name):
    g = vdb.FloatGrid(0.0)
    g.transform = vdb.createLinearTransform(voxelSize=0.01)
    g.fill(lo, hi, v, True)
    g.name, g.gridClass = name, vdb.GridClass.FOG_VOLUME
    return g
vdb.write(sys.argv[1], grids=[box((0, 0, 0), (199, 199, 199), 1.0, "density"),
                              box((-2, -2, -2), (201, 201, 201), float(sys.argv[2]), "temperature")])
"""


def planck_luminance(kelvin):
    """683 lm/W ∫ B ȳ dλ over the CIE's 1 nm table (cd/m²)."""
    h, c, k = 6.62607015e-34, 299792458.0, 1.380649e-23
    total = 0
    with open(os.path.join(ROOT, "lib", "spectrum", "cie", "CIE_xyz_1931_2deg.csv")) as f:
        for line in f:
            nm, _, y, _ = (float(v) for v in line.split(","))
            lam = nm * 1e-9
            total += 683.002 * 2 * h * c * c / lam ** 5 / math.expm1(h * c / (lam * k * kelvin)) * 1e-9 * y
    return total


def planck_table(bin_dir, tmp):
    """Rows of the table "Planck", or a note why there are none."""
    rows = []
    for kelvin in (1500, 2000):
        grid = os.path.join(tmp, f"cube{kelvin}.vdb")
        if subprocess.run(["/usr/bin/python3", "-c", CUBE, grid, str(kelvin)], capture_output=True).returncode:
            return ["(no pyopenvdb in /usr/bin/python3: no table)"]
        expected = planck_luminance(kelvin)
        for k in (0.5, 5, 50, 500):
            scene = os.path.join(tmp, "cube.rad")
            with open(scene, "w") as f:
                f.write(f"void smoke f 2 temperature=temperature {grid} 0 3 {k} {k} {k}\n")
            cells = [f"{kelvin} K", f"{k:g}"]
            for bands in ([], ["-cs", "41", "-pY"]):
                ray = os.path.join(tmp, "ray.txt")
                with open(ray, "w") as f:
                    f.write("0.995 -1 0.995 0 1 0\n" * 16)
                t = Timer([os.path.join(bin_dir, "rtrace"), "-h", "-ov", "-ab", "0", "-u+"] + bands + [scene], ray)
                if bands:  # -pY: the photopic value (cd/m²) in each channel
                    values = [float(l.split()[0]) for l in t.out.splitlines() if l.strip()]
                else:
                    values = [lux(rgb) for rgb in read_rgb(t.out)]
                mean = sum(values) / len(values)
                spread = (sum((v - mean) ** 2 for v in values) / (len(values) - 1)) ** .5 / mean
                cells.append(f"{100 * (mean / (expected * -math.expm1(-2 * k)) - 1):+.2f} %, {100 * spread:.2f} %")
            rows.append("| " + " | ".join(cells) + " |")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    ap.add_argument("--before", help="another build's bin directory, whose path tracing runs the same ladders")
    ap.add_argument("--remake-reference", action="store_true")
    args = ap.parse_args()
    commit = git_commit()  # what was built, as the run starts
    stored = json.load(open(STORED)) if os.path.exists(STORED) else {}
    rows, series, notes = [], {}, []
    with tempfile.TemporaryDirectory() as tmp:
        planck = planck_table(args.bin, tmp)
        subprocess.run([os.path.join(args.bin, "make_flame"), os.path.join(tmp, "flame.vdb")], check=True)
        for case in cases(tmp):
            name, scene, view, options = case
            lines = rays(args.bin, tmp, view)
            means, errors = reference(args.bin, tmp, case, lines, stored, args.remake_reference, commit)
            runs = [(method, args.bin, rungs) for method, rungs in ladders(options).items()]
            if args.before:
                runs.append(("path tracing, before", args.before, ladders(options)["path tracing"]))
            for method, bin_dir, rungs in runs:
                points = series[f"{name}: {method}"] = []
                for repeats, opts in rungs:
                    values, _, cpu = trace(bin_dir, tmp, scene, lines, opts, repeats)
                    rms, tail, relative, relative_tail, own, own_relative = measure(values, means, errors)
                    points.append((cpu, relative))
                    shown = " ".join(opts[:opts.index("-ab")]) + (f" x{repeats}" if repeats > 1 else "")
                    rows.append(f"| {name} | {method} | {shown} | {cpu:.1f} | {100 * rms:.2f} % | {tail:.1f} "
                                f"| {100 * relative:.2f} % | {relative_tail:.1f} |")
                    print(f"  {name}, {method} {' '.join(opts)} x{repeats}: {cpu:.1f} s, {100 * rms:.2f} % "
                          f"(p99.9 {tail:.1f}x), relative {100 * relative:.2f} % (p99.9 {relative_tail:.1f}x)",
                          file=sys.stderr)
                t = time_to(points, TARGET)
                notes.append(f"- {name}, {method}: " + (f"2 % (relative) at about {t:.1f} CPU s" if t
                                                        else "not at 2 % (relative) on its ladder"))
            notes.append(f"- {name}: the reference's own error {100 * own:.2f} % over the mean luminance, "
                         f"{100 * own_relative:.2f} % relative ({len(lines)} rays, {stored[name]['cpu']:.0f} CPU s on "
                         f"two threads, {stored[name]['commit']}).")
    with open(STORED, "w") as f:
        json.dump(stored, f)
    text = (f"# Fire pictures: time against error\n\nBrume {commit}, one thread (bench/fire.py; its docstring "
            "says what is measured).\n\nPlanck: a flame along one ray (mean of 16 rays against Planck, spread of one "
            "ray)\n\n| T | K (1/m) | RGB | 41 bands, -pY |\n|---|---|---|---|\n" + "\n".join(planck) +
            "\n\nPictures (errors with the reference's own taken out):\n\n| picture | method | options | CPU s | "
            "RMS over the mean | p99.9/RMS | pixels' relative RMS | p99.9/RMS |\n|---|---|---|---|---|---|---|---|\n" +
            "\n".join(rows) + "\n\n" + "\n".join(notes) + "\n")
    write_result(text, "fire.md", ladders_plot(series, os.path.join(RESULTS, "fire_time_vs_error.png"),
                                               "Fire pictures: time against relative error", ": ", "path"),
                 "fire_time_vs_error.png")


if __name__ == "__main__":
    main()
