#!/usr/bin/env python3
"""Daylit rooms: illuminance on sensor grids against time, Brume against Radiance 6.1, one thread each.

Scenes (each a room lit through glazing by a gensky sky and its ground, see bench/README.md, "Daylit rooms"):
  office      examples/office/office.rad with examples/office/sky.rad (CIE overcast, its six luminaires on), 96 sensors
  deep        bench/daylight/deep.rad: a 10 m deep side-lit room, clear sky and sun making a patch on the floor, 114
  clerestory  bench/daylight/clerestory.rad: a band of glazing high in one wall, overcast sky, 48 sensors
  atrium      bench/daylight/atrium.rad: a 12 m atrium under a skylight, clear sky and sun, 49 sensors

Every rung is timed (CPU time, one thread) and compared with the scene's converged reference
(bench/results/daylight_reference_<scene>.txt: the mean of independent path-traced runs, with each sensor's
standard error). Radiance's runs are kept in bench/results/daylight_radiance.json (by command and scene), so that
a rerun times only Brume (--rerun-radiance times them again).

    python3 bench/daylight.py --bin build/bin [--scenes office,deep] [--families ...] [--remake-reference]

Standard library only; the plot (results/daylight_time_vs_error.png) is drawn by a Python that has matplotlib.
"""
import argparse
import hashlib
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
import bench  # noqa: E402  (Timer, lux, Radiance, git commit)

ROOT = bench.ROOT
RESULTS = bench.RESULTS
TABLE = os.path.join(RESULTS, "daylight.md")
PLOT = os.path.join(RESULTS, "daylight_time_vs_error.png")
RADIANCE_RUNS = os.path.join(RESULTS, "daylight_radiance.json")
TARGET_RMS = 2.0  # the goal, in %

SCENES = {
    "office": {"files": ["examples/office/office.rad", "examples/office/sky.rad"], "grid": "examples/office/grid.txt",
               "title": "office, overcast sky through a 4 m window, 96 sensors"},
    "deep": {"files": ["bench/daylight/deep.rad"], "grid": "bench/daylight/deep_grid.txt",
             "title": "deep side-lit room, clear sky and a sun patch, 114 sensors"},
    "clerestory": {"files": ["bench/daylight/clerestory.rad"], "grid": "bench/daylight/clerestory_grid.txt",
                   "title": "room lit by a clerestory, overcast sky, 48 sensors"},
    "atrium": {"files": ["bench/daylight/atrium.rad"], "grid": "bench/daylight/atrium_grid.txt",
               "title": "12 m atrium under a skylight, clear sky and sun, 49 sensors"},
}

# The reference: path tracing with every bounce (Russian roulette ends the paths; -ab 50 is never reached), the
# sky found by rays alone (-aP-), so that it does not rest on the sampling measured here.
REF_OPTIONS = ["-I", "-h", "-ab", "50", "-aa", "0", "-ad", "65536", "-as", "0", "-ds", ".05", "-lw", "1e-6", "-aP-"]
REF_RUNS = 4

COMMON = ["-I", "-h"]
# (family, label, program, rungs). Brume's sensors at -aa > 0 send their own paths and share the bounces past the
# first (rtrace's -aS, the defaults); its cache serves them with -aS 0. Brume's path tracing with every bounce, as the reference, ended by roulette at
# its default -lw (each path's weight is its share of the sensor's value, as in Radiance); its cache's paths
# go on past -ab by roulette too. Radiance's -ab 7 leaves out about 0.3 % of the light in these rooms. Radiance's
# path tracing without -as: its super-samples, placed where the first samples differ most, bias it low by 5-15 %
# in side-lit rooms (its cache takes them, as users run it, and once without).
FAMILIES = [
    ("brume-default", "Brume defaults (-ab 5)", "brume", [["-ab", "5"]]),
    ("brume-shared", "Brume's sensors' own paths, shared bounces (the defaults' sampling)", "brume",
     [["-ab", "5", "-ad", str(n)] for n in (256, 512, 1024, 2048, 4096)]),
    ("brume-cache", "Brume cache (-aS 0)", "brume",
     [["-ab", "5", "-aa", aa, "-ad", ad, "-aS", "0"]
      for aa, ad in ((".3", "256"), (".2", "512"), (".1", "1024"), (".05", "2048"))]),
    ("brume-pt", "Brume path tracing", "brume",
     [["-ab", "50", "-aa", "0", "-ad", str(n)] for n in (64, 256, 1024, 4096)]),
    ("brume-pt-rays", "Brume path tracing, sky by rays only (-aP-)", "brume",
     [["-ab", "50", "-aa", "0", "-aP-", "-ad", str(n)] for n in (256, 1024, 4096)]),
    ("radiance-cache", "Radiance cache", "radiance",
     [["-ab", "5", "-aa", ".2", "-ar", "64", "-ad", "512", "-as", "128"],
      ["-ab", "5"],
      ["-ab", "5", "-aa", ".15", "-ar", "128", "-ad", "512", "-as", "256"],
      ["-ab", "6", "-aa", ".1", "-ar", "128", "-ad", "2048", "-as", "1024"],
      ["-ab", "6", "-aa", ".1", "-ar", "128", "-ad", "2048", "-as", "0"]]),
    ("radiance-pt", "Radiance path tracing (-as 0)", "radiance",
     [["-ab", "7", "-aa", "0", "-lw", "1e-5", "-ad", str(n), "-as", "0"] for n in (256, 1024, 4096, 16384)]),
]


def path(rel):
    return os.path.join(ROOT, rel)


def scene_hash(scene):
    h = "".join(bench.sha256(path(f)) for f in SCENES[scene]["files"] + [SCENES[scene]["grid"]])
    return hashlib.sha256(h.encode()).hexdigest()[:16]


def reference_path(scene):
    return os.path.join(RESULTS, "daylight_reference_%s.txt" % scene)


def load_reference(scene):
    """(lux, relative standard errors) of the scene's reference, or None if missing or made for other input."""
    p = reference_path(scene)
    if not os.path.exists(p):
        return None
    meta, lx, se = bench.read_reference(p)
    if meta.get("input sha256") != scene_hash(scene):
        print("daylight: %s was made for another scene or grid: remaking it" % os.path.relpath(p, ROOT))
        return None
    return lx, se


def write_reference(scene, runs, command, commit, seconds):
    pts = [l.split() for l in open(path(SCENES[scene]["grid"])) if l.split()]
    lx, se = [], []
    with open(reference_path(scene), "w") as f:
        f.write("# Brume daylight bench reference (bench/daylight.py): %s\n" % SCENES[scene]["title"])
        f.write("# the mean of %d independent runs of\n" % len(runs))
        f.write("# command: %s %s < %s\n" % (command, " ".join(SCENES[scene]["files"]), SCENES[scene]["grid"]))
        f.write("# cpu time: %.0f s\n" % seconds)
        f.write("# brume commit: %s\n" % commit)
        f.write("# date: %s\n" % time.strftime("%Y-%m-%d %H:%M:%S"))
        f.write("# input sha256: %s\n" % scene_hash(scene))
        f.write("# columns: x y z R G B (mean irradiance, W/m2), illuminance (lux), "
                "standard error of the mean illuminance (%)\n")
        for i in range(len(pts)):
            rgb = [statistics.fmean(r[i][c] for r in runs) for c in range(3)]
            vals = [bench.lux(r[i]) for r in runs]
            m = statistics.fmean(vals)
            s = statistics.stdev(vals) / math.sqrt(len(vals)) / m if m > 0 else 0.0
            lx.append(m)
            se.append(s)
            f.write("%s %s %s %.6e %.6e %.6e %.3f %.3f\n" % (pts[i][0], pts[i][1], pts[i][2], *rgb, m, 100 * s))
    return lx, se


def make_reference(scene, rtrace):
    cmd = [rtrace] + REF_OPTIONS + ["-n", str(os.cpu_count() or 1)] + [path(f) for f in SCENES[scene]["files"]]
    print("daylight: making the %s reference (%d runs of rtrace %s); cached in %s" % (
        scene, REF_RUNS, " ".join(REF_OPTIONS), os.path.relpath(reference_path(scene), ROOT)), flush=True)
    runs, cpu = [], 0.0
    for k in range(REF_RUNS):
        t = bench.Timer(cmd, path(SCENES[scene]["grid"]))
        cpu += t.cpu
        runs.append(bench.read_rgb(t.out))
        print("  run %d/%d: %.0f s" % (k + 1, REF_RUNS, t.wall), flush=True)
    return write_reference(scene, runs, "rtrace " + " ".join(REF_OPTIONS), bench.git_commit(), cpu)


def errors(rows, ref):
    rel = [(bench.lux(v) - r) / r for v, r in zip(rows, ref)]
    if len(rel) != len(ref):
        sys.exit("daylight: expected %d values, got %d" % (len(ref), len(rel)))
    return 100 * math.sqrt(sum(e * e for e in rel) / len(rel)), 100 * max(abs(e) for e in rel)


class Programs:
    def __init__(self, brume_bin, tmp):
        self.brume = os.path.join(brume_bin, "rtrace")
        self.rad = bench.find_radiance()
        self.tmp = tmp
        self.octrees = {}

    def octree(self, scene):
        """Radiance's frozen octree of the scene (the sky's .cal file is read at run time, along RAYPATH)."""
        if scene not in self.octrees:
            p = os.path.join(self.tmp, scene + ".oct")
            with open(p, "wb") as f:
                subprocess.run([self.rad["oconv"], "-f"] + [path(x) for x in SCENES[scene]["files"]], stdout=f,
                               env=self.rad["env"], check=True, cwd=ROOT)
            self.octrees[scene] = p
        return self.octrees[scene]

    def command(self, prog, scene, opts):
        if prog == "brume":
            return [self.brume] + COMMON + opts + ["-n", "1"] + [path(f) for f in SCENES[scene]["files"]]
        return [self.rad["rtrace"]] + COMMON + opts + [self.octree(scene)]


def measure(scene, progs, ref, chosen, radiance_runs, rerun_radiance):
    rows = []
    grid = path(SCENES[scene]["grid"])
    for fam, label, prog, rungs in FAMILIES:
        if fam not in chosen:
            continue
        if prog == "radiance" and not progs.rad:
            print("  %s: Radiance not found, skipped" % label)
            continue
        for opts in rungs:
            key = "%s %s %s" % (scene, scene_hash(scene), " ".join(opts))
            if prog == "radiance" and key in radiance_runs and not rerun_radiance:
                cpu, values = radiance_runs[key]["cpu"], radiance_runs[key]["values"]
            else:
                t = bench.Timer(progs.command(prog, scene, opts), grid, progs.rad["env"] if prog == "radiance" else None)
                cpu, values = t.cpu, bench.read_rgb(t.out)
                if prog == "radiance":
                    radiance_runs[key] = {"cpu": cpu, "values": values, "machine": bench.machine()}
            rms, mx = errors(values, ref)
            rows.append((fam, label, " ".join(opts), cpu, rms, mx))
            print("  %-16s %-48s %7.2f s  RMS %6.2f %%  max %6.2f %%" % (fam, " ".join(opts), cpu, rms, mx), flush=True)
    return rows


def time_to(rows, target):
    return bench.time_to([(r[3], r[4]) for r in rows], target)


def summary(scene, rows):
    fam = {}
    for r in rows:
        fam.setdefault(r[0], []).append(r)
    lines = ["%s: time to %.0f %% RMS (CPU s, interpolated log-log between rungs):" % (scene, TARGET_RMS)]
    reach = {}
    for name, rs in fam.items():
        reach[name] = time_to(rs, TARGET_RMS)
        lines.append("    %-16s %s" % (name, "%.2f s" % reach[name] if reach[name] else "not reached"))
    rad = [reach[f] for f in ("radiance-cache", "radiance-pt") if reach.get(f)]
    brume = [reach[f] for f in ("brume-default", "brume-shared", "brume-cache", "brume-pt") if reach.get(f)]
    if rad and brume:
        lines.append("    Radiance's cheapest / Brume's cheapest: %.1fx (goal: 10x)" % (min(rad) / min(brume)))
    return "\n".join(lines)


def table(results, noise):
    out = ["| scene | family | options | CPU s | RMS % | max % |", "|---|---|---|---|---|---|"]
    for scene, rows in results.items():
        for r in rows:
            out.append("| %s | %s | `%s` | %.2f | %.2f | %.2f |" % (scene, r[1], r[2], r[3], r[4], r[5]))
    out.append("")
    out.append("References' own RMS standard error: " +
               ", ".join("%s %.2f %%" % (s, n) for s, n in noise.items()))
    return "\n".join(out)


PLOT_SCRIPT = """
names, titles, target = d["names"], d["titles"], d["target"]
scenes = list(d["results"])
columns = min(2, len(scenes))
rows = (len(scenes) + columns - 1) // columns
fig, axes = plt.subplots(rows, columns, figsize=(6.5 * columns, 5 * rows), squeeze=False)
for ax, scene in zip(axes.flat, scenes):
    fam = {}
    for r in d["results"][scene]:
        fam.setdefault(r[0], []).append(r)
    for name, rs in fam.items():
        rs = sorted(rs, key=lambda r: r[3])
        k = names.index(name)
        ax.loglog([r[3] for r in rs], [r[4] for r in rs], "-" if name.startswith("brume") else "--",
                  marker="*osDv^p"[k], color="C%d" % k, label=rs[0][1])
    ax.axhline(d["noise"][scene], color="grey", lw=0.8, ls=":", label="reference's own error")
    ax.axhline(target, color="red", lw=0.6, ls="-.", label="goal: %.0f %%" % target)
    ax.set_title(titles[scene], fontsize=9)
    ax.set_xlabel("CPU time, one thread (s)")
    ax.set_ylabel("RMS relative error of illuminance (%)")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7)
fig.suptitle("Daylit rooms: time against error (Brume solid, Radiance 6.1 dashed)")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
"""


def plot(results, noise, png):
    data = {"results": results, "noise": noise, "names": [f[0] for f in FAMILIES], "target": TARGET_RMS,
            "titles": {s: SCENES[s]["title"] for s in results}}
    if bench.matplotlib_plot(PLOT_SCRIPT, data, png):
        print("daylight: plot in %s" % os.path.relpath(png, ROOT))
    else:
        print("daylight: no matplotlib: no plot (Debian's python3-matplotlib draws it)", file=sys.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--families", default=",".join(f[0] for f in FAMILIES))
    ap.add_argument("--remake-reference", action="store_true")
    ap.add_argument("--rerun-radiance", action="store_true")
    a = ap.parse_args()
    chosen = set(a.families.split(","))
    radiance_runs = json.load(open(RADIANCE_RUNS)) if os.path.exists(RADIANCE_RUNS) else {}
    print("daylight: load average %.2f %.2f %.2f" % os.getloadavg())
    results, noise = {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        progs = Programs(os.path.abspath(a.bin), tmp)
        for scene in a.scenes.split(","):
            ref = None if a.remake_reference else load_reference(scene)
            ref = ref or make_reference(scene, progs.brume)
            lx, se = ref
            noise[scene] = 100 * math.sqrt(sum(s * s for s in se) / len(se))
            print("%s (reference's own RMS error %.2f %%):" % (scene, noise[scene]))
            results[scene] = measure(scene, progs, lx, chosen, radiance_runs, a.rerun_radiance)
    with open(RADIANCE_RUNS, "w") as f:
        json.dump(radiance_runs, f, indent=0)
    text = table(results, noise) + "\n\n" + "\n\n".join(summary(s, r) for s, r in results.items())
    print(text)
    with open(TABLE, "w") as f:
        f.write("Made by `python3 bench/daylight.py` (commit %s, %s, %s).\n\n" % (
            bench.git_commit(), time.strftime("%Y-%m-%d"), bench.machine()))
        f.write(text.replace("\n    ", "\n- ") + "\n")
    plot(results, noise, PLOT)


if __name__ == "__main__":
    main()
