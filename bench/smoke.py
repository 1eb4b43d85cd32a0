#!/usr/bin/env python3
"""Smoke: run time against error, with and without empty-space skipping, and what smoke far away costs.

Scenes (../shared/data):
  corridor  the corridor of make demo (examples/corridor) in the FDS soot, at t = 60 s (a layer under the
            ceiling, clear air below) and t = 120 s (the corridor filled); 48 view rays over a 70° x 50° view
            from its near end, rtrace -ab 0 -ms .05 (attenuation and single scattering of the luminaires' light).
  plume     OpenVDB's smoke1 plume (sparse: median density 0.018, peak 5.7) in a hall built around it, K .2,
            albedo .9, g .3, lit by a ceiling panel; 48 view rays from the hall's front wall, -ab 0 -ms 1.
  halo      a small sphere lamp (R 5 cm) in a room filled with fog (-me .3, albedo .9, g .6: Radiance's
            global medium), 48 view rays past it, -ab 0 -ms .5: the halo, where in-scattering samples drawn
            toward the lamp (equiangular, shaped by the phase) matter most.
  bulb      the plume's hall lit by a sphere bulb (R 0.5) inside the plume instead of the ceiling panel, a
            metre beside one of the rays (a ray meeting it would see it only through the plume's
            transmittance, whose noise would swamp the rest).
  Each ray is repeated r = 1, 4, 16, 64 times and its mean compared with a reference of 2000 repeats: the
  error is the RMS over the rays of (value − reference), over the mean reference luminance (rays meeting an
  unlit ceiling have a reference near 0, so errors relative to each ray mean nothing there). The majorant
  grid has cells of 8 voxels (-mc 8, the default) or one cell over the grid's box (-mc 0: no empty-space
  skipping), and at 64 repeats also of 1, 2, 4 and 16 voxels (corridor and plume; halo and bulb: -mc 8
  only). One thread, CPU seconds (user + system, loading included).
  far       the corridor moved 100 m away from the smoke (xform -t -100 0 0): rtrace -I -ab 2 -aa 0 -ad 2048 on
            200 sensors, with and without the smoke object in the scene, and one sensor (the cost of loading the
            grids); best of --repeat runs.
Writes results/smoke.md and results/smoke_time_vs_error.png. Skipped without ../shared/data.
"""
import argparse
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench import (RESULTS, ROOT, Timer, best_of, find_radiance, git_commit, ladders_plot, lux, read_rgb,  # noqa: E402
                   write_result)

CORRIDOR = os.path.join(ROOT, "examples", "corridor")
VDB = os.path.join(ROOT, "..", "shared", "data", "vdb")
SOOT = os.path.join(VDB, "fds_room_fire_mesh2_soot")
LADDER = [1, 4, 16, 64]
SWEEP = [1, 2, 4, 16]  # further cell sizes, at the ladder's last rung
SWEEP_COLUMNS = [1, 2, 4, 8, 16, 0]
REFERENCE_REPEATS = 2000

# The hall around smoke1 (y up; the plume's voxels span x −33.6 … 18.8, y −12.1 … 93.1, z −26 … 26.9).
PANEL = """void light panel 0 0 3 50 50 50
panel polygon lamp 0 0 12  -20 99.9 -15  0 99.9 -15  0 99.9 15  -20 99.9 15
"""
BULB = """void light bulb 0 0 3 20000 20000 20000
bulb sphere lamp 0 0 4  -3 51.5 5  0.5
"""
def box(modifier, name, lo, hi):
    """Six polygons facing out of the box lo–hi (Radiance's genbox, without its options)."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    faces = [[(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)], [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
             [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)], [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
             [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)], [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)]]
    return "".join(f"{modifier} polygon {name}.{i} 0 0 12 " + "  ".join("%g %g %g" % v for v in f) + "\n"
                   for i, f in enumerate(faces))


# The fog is Radiance's global medium (-me -ma -mg); a mist box listing the lamp, a millimetre inside the walls,
# makes Radiance scatter the lamp's light in it too (it scatters only the sources a mist lists) and changes
# nothing in Brume (which scatters every source's light).
FOG_ROOM = """void light bulb 0 0 3 2000 2000 2000
bulb sphere b 0 0 4  0 0 2.5  0.05
void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon floor 0 0 12  -5 -5 0  5 -5 0  5 5 0  -5 5 0
grey polygon ceiling 0 0 12  -5 -5 4  -5 5 4  5 5 4  5 -5 4
grey polygon west 0 0 12  -5 -5 0  -5 5 0  -5 5 4  -5 -5 4
grey polygon east 0 0 12  5 -5 0  5 -5 4  5 5 4  5 5 0
grey polygon north 0 0 12  -5 5 0  -5 5 4  5 5 4  5 5 0
grey polygon south 0 0 12  -5 -5 0  5 -5 0  5 -5 4  -5 -5 4
void mist fog 1 b 0 0
""" + box("fog", "fogbox", (-4.999, -4.999, 0.001), (4.999, 4.999, 3.999))
HALL = """void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon floor 0 0 12  -40 -15 -35  25 -15 -35  25 -15 35  -40 -15 35
grey polygon ceiling 0 0 12  -40 100 -35  -40 100 35  25 100 35  25 100 -35
grey polygon west 0 0 12  -40 -15 -35  -40 -15 35  -40 100 35  -40 100 -35
grey polygon east 0 0 12  25 -15 -35  25 100 -35  25 100 35  25 -15 35
grey polygon back 0 0 12  -40 -15 35  25 -15 35  25 100 35  -40 100 35
grey polygon front 0 0 12  -40 -15 -35  -40 100 -35  25 100 -35  25 -15 -35
void smoke plume 1 openvdb_smoke1.vdb 0 7 .2 .2 .2 .9 .9 .9 .3
"""


def view_rays(eye, forward, right, up):
    """48 directions over a 70° x 50° view."""
    rays = []
    for i in range(8):
        for j in range(6):
            a, b = (i - 3.5) / 3.5 * 0.7, (j - 2.5) / 2.5 * 0.45
            rays.append(eye + tuple(f + a * r + b * u for f, r, u in zip(forward, right, up)))
    return rays


def scenes(tmp):
    """(name, scene files, options, rays, RAYPATH, whether to compare cell sizes) of each measured case."""
    def scene(name, text):
        path = os.path.join(tmp, name)
        with open(path, "w") as f:
            f.write(text)
        return path
    corridor_rays = view_rays((10.3, 3, 1.6), (1, 0, 0), (0, 1, 0), (0, 0, 1))
    corridor = [os.path.join(CORRIDOR, f) for f in ("corridor.rad", "smoke.rad")]
    hall_rays = view_rays((-7, 40, -34), (0, 0, 1), (1, 0, 0), (0, 1, 0))
    return [(f"corridor, t = {t} s", corridor, ["-ab", "0", "-ms", ".05", "-T", str(t)], corridor_rays,
             f"{SOOT}:{CORRIDOR}", True) for t in (60, 120)] + [
        ("plume", [scene("hall.rad", PANEL + HALL)], ["-ab", "0", "-ms", "1"], hall_rays, VDB, True),
        ("halo", [scene("fog.rad", FOG_ROOM)], ["-ab", "0", "-ms", ".5", "-me", ".3", ".3", ".3", "-ma", ".9", ".9",
                                                ".9", "-mg", ".6"],
         view_rays((-4, -4, 1.5), (0.707, 0.707, 0), (0.707, -0.707, 0), (0, 0, 1)), VDB, False),
        ("bulb in the plume", [scene("bulb.rad", BULB + HALL)], ["-ab", "0", "-ms", "1"], hall_rays, VDB, False)]


def luminances(text, repeats, spread=False):
    """Mean photopic luminance (cd/m²) of each ray's repeats; with spread, instead the sum over the rays of the
    variance of one trace, over the squared mean luminance (time × that compares estimators at equal error)."""
    values = [lux(rgb) for rgb in read_rgb(text)]  # lux's factors are luminance's too
    groups = [values[k:k + repeats] for k in range(0, len(values), repeats)]
    if not spread:
        return [sum(g) / repeats for g in groups]
    mean = sum(values) / len(values)
    return sum(sum((v - sum(g) / repeats) ** 2 for v in g) / repeats for g in groups) / mean ** 2


def write_rays(tmp, rays, repeats):
    """The rays, each repeated, as rtrace's input file in tmp."""
    path = os.path.join(tmp, "rays.txt")
    with open(path, "w") as f:
        for r in rays:
            f.write(("%g %g %g %g %g %g\n" % r) * repeats)
    return path


def trace(bin_dir, tmp, case, repeats, cells):
    """Brume's rtrace on the case's rays, each repeated: the run (Timer)."""
    _, files, options, rays, raypath, _ = case
    cmd = [os.path.join(bin_dir, "rtrace"), "-h", "-n", "1", "-mc", str(cells)] + options + files
    return Timer(cmd, write_rays(tmp, rays, repeats), env=dict(os.environ, RAYPATH=raypath))


def run(bin_dir, tmp, case, repeats, cells):
    t = trace(bin_dir, tmp, case, repeats, cells)
    return luminances(t.out, repeats), t.cpu


def radiance_ladder(rad, tmp, case):
    """The case by Radiance's rtrace (the same options, -u+ so that repeats differ) against its own reference of
    REFERENCE_REPEATS repeats: Radiance dims source light by absorption only, so its answer is not Brume's.
    [(cpu, error)] over LADDER, the reference's CPU time and its spread (see luminances)."""
    name, files, options, rays, _, _ = case
    octree = os.path.join(tmp, "radiance.oct")
    with open(octree, "wb") as f:
        subprocess.run([rad["oconv"], "-f"] + files, stdout=f, env=rad["env"], check=True)

    def one(repeats):
        return Timer([rad["rtrace"], "-h", "-u+"] + options + [octree], write_rays(tmp, rays, repeats), env=rad["env"])
    t = one(REFERENCE_REPEATS)
    reference = luminances(t.out, REFERENCE_REPEATS)
    ladder = []
    for r in LADDER:
        run_r = one(r)
        ladder.append((run_r.cpu, normalised_rms(luminances(run_r.out, r), reference)))
        print(f"  {name}, Radiance x{r}: {run_r.cpu:.2f} s, {100 * ladder[-1][1]:.2f} %", file=sys.stderr)
    return ladder, t.cpu, luminances(t.out, REFERENCE_REPEATS, spread=True)


def normalised_rms(values, reference):
    mean = sum(reference) / len(reference)
    return (sum((v - r) ** 2 for v, r in zip(values, reference)) / len(values)) ** 0.5 / mean


def far_cost(bin_dir, tmp, repeat):
    moved = os.path.join(tmp, "far.rad")
    with open(moved, "w") as f:
        subprocess.run([os.path.join(bin_dir, "xform"), "-t", "-100", "0", "0", os.path.join(CORRIDOR, "corridor.rad")],
                       stdout=f, check=True)
    sensors = os.path.join(tmp, "sensors.txt")
    with open(sensors, "w") as f:
        for i in range(50):
            for y in (2.3, 2.8, 3.2, 3.7):
                f.write(f"{-89.9 + 0.1 * i} {y} 0.8 0 0 1\n")
    env = dict(os.environ, RAYPATH=f"{SOOT}:{CORRIDOR}")
    one = os.path.join(tmp, "one.txt")
    with open(one, "w") as f:
        f.write("-89.75 2.5 0.8 0 0 1\n")
    cmd = [os.path.join(bin_dir, "rtrace"), "-h", "-I", "-ab", "2", "-aa", "0", "-ad", "2048", "-u-", "-n", "1",
           "-T", "120", moved]
    smoke = [os.path.join(CORRIDOR, "smoke.rad")]
    # (work without, work with, start without, start with): start = one sensor, mostly loading the scene
    return (best_of(repeat, cmd, sensors, env)[1], best_of(repeat, cmd + smoke, sensors, env)[1],
            best_of(repeat, cmd, one, env)[1], best_of(repeat, cmd + smoke, one, env)[1])


def plot(series, png):
    return ladders_plot(series, png, "Brume: view rays through smoke, with and without empty-space skipping",
                        ", -mc", "-mc 8")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    if not os.path.isdir(SOOT):
        print(f"smoke: no {SOOT}: skipped", file=sys.stderr)
        return
    rows, series, notes, sweep = [], {}, [], []
    with tempfile.TemporaryDirectory() as tmp:
        for case in scenes(tmp):
            ref = trace(args.bin, tmp, case, REFERENCE_REPEATS, 8)
            reference, ref_cpu = luminances(ref.out, REFERENCE_REPEATS), ref.cpu
            if case[0] == "halo":  # the one compared with Radiance, by its spread too
                halo, halo_reference = case, ref
            curves = {}
            compared = (8, 0) if case[5] else (8,)
            for cells in compared:
                name = f"{case[0]}, -mc {cells}"
                curves[cells] = series[name] = []
                for r in LADDER:
                    values, cpu = run(args.bin, tmp, case, r, cells)
                    err = normalised_rms(values, reference)
                    curves[cells].append((cpu, err))
                    rows.append(f"| {case[0]} | -mc {cells} | {r} | {cpu:.2f} s | {100 * err:.2f} % |")
                    print(f"  {name} x{r}: {cpu:.2f} s, {100 * err:.2f} %", file=sys.stderr)
            skip = curves[8][-1]
            own = skip[1] * (LADDER[-1] / REFERENCE_REPEATS) ** .5
            note = f"- {case[0]} (rtrace {' '.join(case[2])}): reference {ref_cpu:.0f} CPU s, its own error about {100 * own:.2f} %"
            if not case[5]:
                notes.append(note + ".")
                continue
            # Cell size at the last rung: time × error² (∝ the time to a given error, variance ∝ 1/time).
            efficiency = {cells: curves[cells][-1] for cells in compared}
            for cells in SWEEP:
                values, cpu = run(args.bin, tmp, case, LADDER[-1], cells)
                efficiency[cells] = (cpu, normalised_rms(values, reference))
            base = efficiency[8][0] * efficiency[8][1] ** 2
            sweep.append(f"| {case[0]} | " + " | ".join(
                f"{efficiency[c][0]:.2f} s, {100 * efficiency[c][1]:.1f} %: {efficiency[c][0] * efficiency[c][1] ** 2 / base:.2f}"
                for c in SWEEP_COLUMNS) + " |")
            full = curves[0][-1]
            # Time at equal error: variance ∝ 1/time, so time × error² compares the two at any error.
            notes.append(note + f"; at {LADDER[-1]} repeats -mc 0 takes {full[0] / skip[0]:.2f}x the time of -mc 8, and "
                         f"{full[0] * full[1] ** 2 / (skip[0] * skip[1] ** 2):.2f}x its time at equal error (time × error²).")
        rad, versus = find_radiance(), "Radiance not found (RADIANCE_BIN or /tmp/radiance/bin): no comparison."
        if rad:
            ladder, r_cpu2, r_spread = radiance_ladder(rad, tmp, halo)
            b_cpu2, b_spread = halo_reference.cpu, luminances(halo_reference.out, REFERENCE_REPEATS, spread=True)
            series["halo, Radiance"] = ladder
            rows += [f"| halo | Radiance | {r} | {cpu:.2f} s | {100 * err:.2f} % |" for r, (cpu, err) in zip(LADDER, ladder)]
            (b_cpu, b_err), (r_cpu, r_err) = series["halo, -mc 8"][-1], ladder[-1]
            versus = (f"Radiance's rtrace on the halo (the same options, against its own reference of {r_cpu2:.1f} CPU s: "
                      f"it dims the lamp's light by absorption only): at {LADDER[-1]} repeats {r_cpu:.2f} s, "
                      f"{100 * r_err:.2f} %; Brume {b_cpu:.2f} s, {100 * b_err:.2f} % (the times mostly start-up: Brume "
                      f"builds its scene from the .rad file, Radiance reads an octree made beforehand). Over "
                      f"{REFERENCE_REPEATS} repeats: Brume {b_cpu2:.2f} s, Radiance {r_cpu2:.2f} s; the variance of one "
                      f"trace summed over the rays, over the squared mean: Brume {b_spread:.4f}, Radiance {r_spread:.4f}; "
                      f"Radiance reaches an equal error {b_cpu2 * b_spread / (r_cpu2 * r_spread):.1f}x sooner "
                      "(time × variance).")
        without, with_smoke, start, start_smoke = far_cost(args.bin, tmp, args.repeat)
    text = (f"# Smoke: time against error\n\nBrume {git_commit()}, one thread (bench/smoke.py; its docstring says what "
            f"is measured). Each ray's mean of r repeats against a reference of {REFERENCE_REPEATS} repeats; error: "
            "RMS over the 48 rays over the mean reference luminance.\n\n"
            "| scene | majorant cells | repeats | CPU | error |\n|---|---|---|---|---|\n" + "\n".join(rows) +
            "\n\n" + "\n".join(notes) + "\n\n" + versus +
            f"\n\nCell size (-mc, voxels) at {LADDER[-1]} repeats: CPU, error, and time × error² relative to -mc 8 (below "
            "1: a given error sooner):\n\n| scene | " + " | ".join(f"-mc {c}" for c in SWEEP_COLUMNS) + " |\n|---" +
            "|---" * len(SWEEP_COLUMNS) + "|\n" + "\n".join(sweep) +
            "\n\nSmoke far from every ray (the corridor 100 m away; rtrace -I -ab 2 -aa 0 -ad 2048, "
            f"200 sensors, best of {args.repeat}): {without:.2f} s without the smoke object, {with_smoke:.2f} s with it "
            f"({with_smoke / without:.2f}x); of which loading (one sensor): {start:.2f} s and {start_smoke:.2f} s; "
            f"the rays alone: {(with_smoke - start_smoke) / max(without - start, 1e-9):.2f}x.\n")
    write_result(text, "smoke.md", plot(series, os.path.join(RESULTS, "smoke_time_vs_error.png")),
                 "smoke_time_vs_error.png")


if __name__ == "__main__":
    main()
