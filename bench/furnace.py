#!/usr/bin/env python3
"""White furnace with smoke (issue 38): a closed grey sphere (R = 1 m, ρ = .8) with a small lamp at its centre
(r = 2 cm, flux Φ), filled with smoke that does not absorb (a Gaussian blob from an OpenVDB grid, albedo 1, HG g).
Whatever the smoke does, all the lamp's flux ends on the wall, each reflection returning ρ of it, so the mean
wall irradiance is Φ / (4πR²(1 − ρ)) = 5 (the lamp's radiance is chosen so) -- less what the lamp itself absorbs:
a `light` is black to the light that comes back to it, the wall's (r²/R² of what the wall reflects, -0.16 %) and,
with smoke, its own light scattered back by the smoke around it (0.8 % of Φ at optical depth 2 and g .6, 3.2 %
at g 0). So the exact mean is (Φ − Φ_lamp) / (4πR²(1 − ρ)), Φ_lamp found here by path tracing the irradiance
of 400 sensors just outside the lamp, facing out (-aa 0 -ab 200; the lamp absorbs their mean times its area).

400 wall sensors (a Fibonacci sphere, 0.1 mm inside, facing in: the lamp's straight light there is (1 − 10⁻⁴)⁻² of
the wall's, +0.004 % of the whole) through rtrace -h -I; per case, --runs runs of different seeds (-u+): the mean's
error against 5 and against the exact mean, each sensor's spread from run to run (by symmetry every sensor has
the same expected value: the RMS over sensors of the relative difference of two runs, over √2, for consecutive
pairs), and the wall and CPU times of a run.

    /usr/bin/python3 bench/furnace.py [--bin build/bin] [--only LABEL ...] [--runs N] [--name NAME]
    /usr/bin/python3 bench/furnace.py --options blob 2 .6 -ab 5 -aa 0     # one case: the smoke, then options

Needs pyopenvdb (Debian's python3-openvdb). Writes results/NAME.md (NAME furnace unless --name says otherwise).
"""
import argparse
import math
import os
import statistics
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench import Timer, git_commit, machine, write_result  # noqa: E402

R, RHO = 1.0, 0.8
LAMP_RADIUS = 0.02
# The lamp's radiance, chosen so that Φ / (4πR²(1 − ρ)) = 5: Φ = L·π·4πr² (a Lambertian sphere).
LAMP_RADIANCE = 5 * 4 * math.pi * R * R * (1 - RHO) / (math.pi * 4 * math.pi * LAMP_RADIUS ** 2)
FLUX = LAMP_RADIANCE * math.pi * 4 * math.pi * LAMP_RADIUS ** 2
CLOSED_FORM = FLUX / (4 * math.pi * R * R * (1 - RHO))
SENSORS = 400
INSET = 1e-4
LAMP_SENSORS_AT = LAMP_RADIUS + 1e-4
BLOB_SIGMA = 0.35  # the Gaussian's standard deviation (m)
VOXEL = 0.025


def fibonacci(i, n):
    z = 1 - (2 * i + 1) / n
    r = math.sqrt(1 - z * z)
    phi = i * math.pi * (3 - math.sqrt(5))
    return r * math.cos(phi), r * math.sin(phi), z


def blob_depth(extinction):
    """The optical depth from the centre to the wall of the blob of `extinction` at its centre:
    K ∫₀^R exp(−r²/2s²) dr = K s √(π/2) erf(R / s√2)."""
    return extinction * BLOB_SIGMA * math.sqrt(math.pi / 2) * math.erf(R / (BLOB_SIGMA * math.sqrt(2)))


def write_grid(path, kind):
    """A density grid over the sphere: `blob`, exp(−r²/2s²) (1 at the centre); `even`, 1 everywhere within R."""
    import numpy as np
    import pyopenvdb as vdb
    n = int(math.ceil(1.04 * R / VOXEL))
    ijk = np.arange(-n, n + 1) * VOXEL
    x, y, z = np.meshgrid(ijk, ijk, ijk, indexing="ij")
    r2 = x * x + y * y + z * z
    if kind == "blob":
        density = np.exp(-r2 / (2 * BLOB_SIGMA ** 2))
        density[density < 1e-4] = 0
    else:
        density = np.ones_like(r2)
        density[r2 > (1.04 * R) ** 2] = 0
    grid = vdb.FloatGrid()
    grid.copyFromArray(density.astype(np.float32), ijk=(-n, -n, -n), tolerance=0)
    grid.transform = vdb.createLinearTransform(voxelSize=VOXEL)
    grid.gridClass = vdb.GridClass.FOG_VOLUME
    grid.name = "density"
    vdb.write(path, grids=[grid])


def write_scene(tmp, smoke):
    """The sphere, its lamp and `smoke`: None, or (kind, optical depth centre to wall, g); returns the .rad path."""
    text = [f"void plastic grey 0 0 5 {RHO} {RHO} {RHO} 0 0",
            f"grey sphere wall 0 0 4 0 0 0 {R}",
            f"void light lamp 0 0 3 {LAMP_RADIANCE:.9g} {LAMP_RADIANCE:.9g} {LAMP_RADIANCE:.9g}",
            f"lamp sphere bulb 0 0 4 0 0 0 {LAMP_RADIUS}"]
    if smoke:
        kind, depth, g = smoke
        grid = os.path.join(tmp, f"{kind}.vdb")
        if not os.path.exists(grid):
            write_grid(grid, kind)
        k = depth / (blob_depth(1) if kind == "blob" else R)
        text.append(f"void smoke fog 1 {grid} 0 7 {k:.9g} {k:.9g} {k:.9g} 1 1 1 {g}")
    path = os.path.join(tmp, "furnace_%s.rad" % ("_".join(map(str, smoke)) if smoke else "empty"))
    with open(path, "w") as f:
        f.write("\n".join(text) + "\n")
    return path


def irradiances(out):
    return [sum(map(float, line.split()[:3])) / 3 for line in out.splitlines() if line.strip()]


def write_sensors(path, radius, inward):
    """SENSORS sensors over a sphere of `radius` about the centre, facing in (the wall's) or out (the lamp's)."""
    with open(path, "w") as f:
        for i in range(SENSORS):
            d = fibonacci(i, SENSORS)
            p = [c * radius for c in d]
            f.write("%.9f %.9f %.9f %.9f %.9f %.9f\n" % (*p, *((-c if inward else c) for c in d)))


def exact_mean(rtrace, scene, tmp):
    """(Φ − Φ_lamp) / (4πR²(1 − ρ)) with Φ_lamp path traced (see the docstring), and its standard error."""
    sensors = os.path.join(tmp, "lamp_sensors.txt")
    if not os.path.exists(sensors):
        write_sensors(sensors, LAMP_SENSORS_AT, inward=False)
    v = irradiances(Timer([rtrace, "-h", "-I", "-u+", "-ab", "200", "-aa", "0", scene], sensors).out)
    scale = 4 * math.pi * LAMP_SENSORS_AT ** 2 / (4 * math.pi * R * R * (1 - RHO))
    return CLOSED_FORM - statistics.fmean(v) * scale, statistics.stdev(v) / math.sqrt(len(v)) * scale


def measure(rtrace, scene, sensors, options, runs):
    """`runs` runs of different seeds: each run's mean, the sensors' spread between consecutive runs (RMS over
    sensors of their relative difference, over √2), and the wall and CPU times."""
    values, walls, cpus = [], [], []
    for _ in range(runs):
        t = Timer([rtrace, "-h", "-I", "-u+"] + options + [scene], sensors)
        values.append(irradiances(t.out))
        walls.append(t.wall)
        cpus.append(t.cpu)
    spreads = []
    for a, b in zip(values, values[1:]):
        d = [2 * (x - y) / (x + y) for x, y in zip(a, b)]
        spreads.append(math.sqrt(statistics.fmean(x * x for x in d) / 2))
    return [statistics.fmean(v) for v in values], spreads, walls, cpus


CASES = [  # (label, smoke, options)
    ("empty, -ab 5 -n 2", None, ["-ab", "5", "-n", "2"]),
    ("blob τ 2 g .6, -ab 5 -n 2", ("blob", 2, 0.6), ["-ab", "5", "-n", "2"]),
    ("blob τ 2 g .6, -ab 5 -n 1", ("blob", 2, 0.6), ["-ab", "5", "-n", "1"]),
    ("blob τ 2 g .6, path tracing -aa 0 -ab 200 -n 2", ("blob", 2, 0.6), ["-aa", "0", "-ab", "200", "-n", "2"]),
    ("blob τ 2 g 0, -ab 5 -n 2", ("blob", 2, 0.0), ["-ab", "5", "-n", "2"]),
    ("even τ 2 g .6, -ab 5 -n 2", ("even", 2, 0.6), ["-ab", "5", "-n", "2"]),
]


def row(label, means, exact, exact_error, spreads, walls, cpus):
    def pct(x):
        return "%+.2f" % (100 * x)
    return (f"| {label} | {exact:.4f} ± {exact_error:.1g} | " + " ".join(pct(m / CLOSED_FORM - 1) for m in means) +
            " | " + " ".join(pct(m / exact - 1) for m in means) + " | " + pct(statistics.fmean(means) / exact - 1) +
            " | " + (" ".join("%.2f" % (100 * s) for s in spreads) or "-") +
            " | %.1f | %.1f |" % (statistics.fmean(walls), statistics.fmean(cpus)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(os.path.dirname(HERE), "build", "bin"))
    ap.add_argument("--only", nargs="*", default=[], help="cases whose label contains one of these")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--name", default="furnace", help="the results' file name (results/NAME.md)")
    ap.add_argument("--options", nargs=argparse.REMAINDER, default=[],
                    help="one case: the smoke (empty, or kind depth g), then rtrace's options")
    args = ap.parse_args()
    rtrace = os.path.join(args.bin, "rtrace")
    cases = CASES
    if args.options:
        o = args.options
        smoke = None if o[0] == "empty" else (o[0], float(o[1]), float(o[2]))
        cases = [(" ".join(o), smoke, o[1:] if smoke is None else o[3:])]
    rows, exacts = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        sensors = os.path.join(tmp, "sensors.txt")
        write_sensors(sensors, R * (1 - INSET), inward=True)
        for label, smoke, options in cases:
            if args.only and not any(c in label for c in args.only):
                continue
            scene = write_scene(tmp, smoke)
            if scene not in exacts:
                exacts[scene] = exact_mean(rtrace, scene, tmp)
            means, spreads, walls, cpus = measure(rtrace, scene, sensors, options, args.runs)
            rows.append(row(label, means, *exacts[scene], spreads, walls, cpus))
            print(rows[-1], flush=True)
    text = (f"# White furnace with smoke (bench/furnace.py)\n\nBrume {git_commit()}, {machine()}, load average "
            f"{os.getloadavg()[0]:.1f} at the end, {args.runs} runs a case.\n\n| case | exact mean (Φ less the lamp's "
            "share) | error % against 5, per run | error % against the exact mean, per run | mean | per-sensor spread "
            "% RMS | wall s | CPU s |\n|---|---|---|---|---|---|---|---|\n" + "\n".join(rows) + "\n")
    write_result(text, args.name + ".md", True, "")


if __name__ == "__main__":
    main()
