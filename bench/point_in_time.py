#!/usr/bin/env python3
"""One instant on a sensor grid (issue 40's point-in-time goal: the worst sensor within 6 % at rtrace's
defaults): bench/annual's office (192 sensors at 0.75 m) under three skies of Chicago, a clear June noon with its
sun through the window, a clear December morning with a low sun deep in the room and an overcast sky, with
`rtrace -I` at its defaults (-aa .1 -ad 1024: the sensors' own paths and shared bounces, -aS .125) and the -ab a
daylight study takes, and with -aS 0 (the sensors take the irradiance cache's records, -ar 256), against a
converged reference: the mean of four path-traced runs (-aa 0 -ab 12 -ad 16384 -lw 1e-6, independent seeds),
whose own standard error is printed. Each setting runs --runs times with independent seeds; the table gives each
run's RMS, bias and worst sensor.

    python3 bench/point_in_time.py [--runs 5] [--remake-reference]

Standard library only. About 10 minutes on two cores for the references (cached in results/, remade when the
scene, grid or skies change), 1-2 minutes for the rest.
"""
import argparse
import hashlib
import math
import os
import statistics
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
import bench  # noqa: E402

MODEL = os.path.join(HERE, "annual")
SCENE = [os.path.join(MODEL, "materials.rad"), os.path.join(MODEL, "office.rad")]
GRID = os.path.join(MODEL, "grid.pts")
RTRACE = os.path.join(bench.ROOT, "build", "bin", "rtrace")
TABLE = os.path.join(bench.RESULTS, "point_in_time.md")
GLOWS = ("skyfunc glow skyglow 0 0 4 1 1 1 0\nskyglow source skydome 0 0 4 0 0 1 180\n"
         "skyfunc glow groundglow 0 0 4 1 1 1 0\ngroundglow source ground 0 0 4 0 0 -1 180\n")
SKIES = {  # Chicago, 41.98 N 87.92 W, standard meridian 90 W
    "june": "!gendaylit 6 21 12.5 -a 41.98 -o 87.92 -m 90 -W 800 100\n" + GLOWS,
    "december": "!gendaylit 12 21 10.5 -a 41.98 -o 87.92 -m 90 -W 750 60\n" + GLOWS,
    "overcast": "!gensky 6 21 12 -c -a 41.98 -o 87.92 -m 90 -B 100\n" + GLOWS,
}
TITLES = {"june": "clear June noon (sun 70° high)", "december": "clear December morning (sun 22° high)",
          "overcast": "overcast (CIE, 100 W/m² diffuse)"}
REFERENCE_OPTIONS = ["-ab", "12", "-aa", "0", "-ad", "16384", "-lw", "1e-6"]
REFERENCE_RUNS = 4
SETTINGS = [["-ab", "5"], ["-ab", "7"], ["-ab", "5", "-aS", "0"]]


def rtrace(options, sky_path, threads, out_path=None):
    cmd = [RTRACE, "-n", str(threads), "-h", "-I", "-u+"] + options + SCENE + [sky_path]
    return bench.Timer(cmd, GRID, out_path=out_path)


def fingerprint(sky):
    h = hashlib.sha256(sky.encode())
    for path in SCENE + [GRID]:
        h.update(bench.sha256(path).encode())
    return h.hexdigest()


def reference(name, sky_path, remake):
    """Each sensor's lux (the mean of REFERENCE_RUNS runs) and its relative standard error, cached."""
    path = os.path.join(bench.RESULTS, "point_in_time_reference_%s.txt" % name)
    key = fingerprint(SKIES[name]) + " " + " ".join(REFERENCE_OPTIONS)
    if not remake and os.path.exists(path):
        with open(path) as f:
            lines = f.read().splitlines()
        if lines and lines[0] == "# " + key:
            rows = [tuple(float(x) for x in l.split()) for l in lines if not l.startswith("#")]
            return [r[0] for r in rows], [r[1] for r in rows]
    print("bench: making the %s reference (%d runs of rtrace %s)" % (name, REFERENCE_RUNS, " ".join(REFERENCE_OPTIONS)),
          flush=True)
    runs = [[bench.lux(v) for v in bench.read_rgb(rtrace(REFERENCE_OPTIONS, sky_path, 2).out)] for _ in range(REFERENCE_RUNS)]
    mean = [statistics.fmean(s) for s in zip(*runs)]
    se = [statistics.stdev(s) / math.sqrt(len(s)) / m for s, m in zip(zip(*runs), mean)]
    with open(path, "w") as f:
        f.write("# %s\n# lux, relative standard error: the mean of %d runs of rtrace -I -u+ %s on %s under %s\n"
                % (key, REFERENCE_RUNS, " ".join(REFERENCE_OPTIONS), ", ".join(os.path.relpath(p, bench.ROOT) for p in SCENE),
                   SKIES[name].splitlines()[0]))
        for m, s in zip(mean, se):
            f.write("%.6g %.6g\n" % (m, s))
    return mean, se


def judged(values, ref):
    rel = [bench.lux(v) / r - 1 for v, r in zip(values, ref)]
    worst = max(range(len(rel)), key=lambda i: abs(rel[i]))
    return (100 * math.sqrt(statistics.fmean(e * e for e in rel)), 100 * statistics.fmean(rel), 100 * rel[worst],
            worst)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=5, help="runs of each setting (independent seeds)")
    ap.add_argument("--remake-reference", action="store_true")
    args = ap.parse_args()
    lines = ["# One instant on a sensor grid (bench/point_in_time.py)", "",
             "bench/annual's office, 192 sensors; `rtrace -I -n 1` at its defaults but -ab, %d runs each with its own seed; "
             "errors of each sensor's illuminance against the reference (the mean of %d runs of `rtrace -I %s`)." %
             (args.runs, REFERENCE_RUNS, " ".join(REFERENCE_OPTIONS)), ""]
    with tempfile.TemporaryDirectory() as tmp:
        for name, sky in SKIES.items():
            sky_path = os.path.join(tmp, name + ".rad")
            with open(sky_path, "w") as f:
                f.write(sky)
            ref, se = reference(name, sky_path, args.remake_reference)
            own = 100 * math.sqrt(statistics.fmean(s * s for s in se))
            lines += ["## %s" % TITLES[name], "",
                      "Reference: mean %.0f lx (%.0f to %.0f), its own error %.2f %% RMS (worst sensor %.2f %%)." %
                      (statistics.fmean(ref), min(ref), max(ref), own, 100 * max(se)), "",
                      "| options | CPU s | RMS % | bias % | worst sensor % (sensor, lx) |", "|---|---|---|---|---|"]
            for options in SETTINGS:
                for _ in range(args.runs):
                    t = rtrace(options, sky_path, 1)
                    rms, bias, worst, at = judged(bench.read_rgb(t.out), ref)
                    lines.append("| %s | %.2f | %.2f | %+.2f | %+.1f (%d, %.0f) |" % (" ".join(options), t.cpu, rms, bias, worst,
                                                                                   at, ref[at]))
                    print(lines[-1], flush=True)
            lines.append("")
    with open(TABLE, "w") as f:
        f.write("\n".join(lines))
    print("bench: wrote %s" % os.path.relpath(TABLE, bench.ROOT))


if __name__ == "__main__":
    main()
