#!/usr/bin/env python3
"""The 3-phase method (issue 40): time against error, Radiance's programs and Brume's on the same command lines.
test/data/rfluxmtx/room.rad (a 4 x 5 m side-lit room, a block across the street) whose window is the prismatic
pane test/data/bsdf/prism_quarter.xml (Klems' quarter basis), 16 sensors, 48 hours of Chicago
(test/data/daymtx/chicago48.wea): each rung runs the view matrix (rfluxmtx -I - window_v.rad, the window h=kq),
the daylight matrix (rfluxmtx window_d.rad sky.rad, the window h=-kq, Tregenza's sky and the ground) and
dctimestep V T D sky with the XML BSDF, one process each at -n 1, the CPU of the two matrices added. Per sensor the
48-hour mean illuminance; its error against Radiance's converged 3-phase result
(test/data/rfluxmtx/three_phase_reference.txt, its own error 0.5 % or less): RMS over sensors (%) and the worst.
Two runs a rung with different seeds (their RMS, CPU mean). The LBNL tutorial's settings (-ab 4 -ad 5000 -lw 2e-4
for V; -ab 4 -ad 1000 -lw 1e-3 -c 1000 for D) are a rung. The view matrix's noise is most of the error here: its
sensors find a window of 41 bins, each weighed by a prismatic pane and the sky; the daylight matrix's -c rays a
bin matter less. The table ends with each program's cheapest rung within 2 % RMS.

    python3 bench/three_phase.py [--radiance /tmp/radiance/inst/bin]

Standard library only; the plot (results/three_phase_time_vs_error.png) is drawn by a Python that has matplotlib.
"""
import argparse
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
import bench  # noqa: E402

DATA = os.path.join(bench.ROOT, "test", "data")
MODEL = os.path.join(DATA, "rfluxmtx")
BSDF = os.path.join(DATA, "bsdf", "prism_quarter.xml")
WEA = os.path.join(DATA, "daymtx", "chicago48.wea")
REFERENCE = os.path.join(MODEL, "three_phase_reference.txt")
TABLE = "three_phase.md"
PLOT = "three_phase_time_vs_error.png"
# (view matrix options, daylight matrix options): the same rungs for both programs, then each one's own.
RUNGS = [
    ("-ab 4 -ad 1000 -lw 1e-3", "-ab 2 -ad 256 -lw 1e-3 -c 250"),
    ("-ab 6 -ad 8192 -lw 1e-5", "-ab 2 -ad 256 -lw 1e-4 -c 250"),
    ("-ab 4 -ad 5000 -lw 2e-4", "-ab 4 -ad 1000 -lw 1e-3 -c 1000"),
    ("-ab 6 -ad 10000 -lw 1e-5", "-ab 3 -ad 2048 -lw 1e-4 -c 2000"),
]
RADIANCE_RUNGS = RUNGS + [("-ab 7 -ad 32768 -lw 1e-6", "-ab 2 -ad 512 -lw 1e-4 -c 500")]
BRUME_RUNGS = RUNGS + [("-ab 6 -ad 2048 -lw 1e-5", "-ab 2 -ad 256 -lw 1e-4 -c 250"),
                       ("-ab 6 -ad 4096 -lw 1e-5", "-ab 2 -ad 256 -lw 1e-4 -c 250")]
TARGET = 0.02  # RMS
RUNS = 2


def reference():
    with open(REFERENCE) as f:
        return [float(l.split()[0]) for l in f if l.strip() and not l.startswith("#")]


def run(program_dir, env, cmd, stdin, out):
    """A command of `program_dir`, its output to `out`: its CPU seconds."""
    return bench.Timer([os.path.join(program_dir, cmd[0])] + cmd[1:], stdin, env=env, out_path=out).cpu


def rung(program_dir, env, vopts, dopts, seed, tmp):
    """(CPU s of the two matrices, each sensor's 48-hour mean lux)."""
    u = ["-u+"] if seed else ["-u-"]
    v, d, window_v, window_d, sky, room = (os.path.join(tmp, n) for n in ("v.mtx", "d.mtx", "window_v.rad",
                                                                          "window_d.rad", "sky.rad", "room.rad"))
    cpu = run(program_dir, env, ["rfluxmtx", "-n", "1"] + u + ["-I", "-y", "16"] + vopts.split() + ["-", window_v, room],
              os.path.join(tmp, "sensors.pts"), v)
    cpu += run(program_dir, env, ["rfluxmtx", "-n", "1"] + u + dopts.split() + [window_d, sky, room], os.devnull, d)
    product = subprocess.run([os.path.join(program_dir, "dctimestep"), v, BSDF, d, os.path.join(tmp, "sky.smx")],
                             capture_output=True, env=env, check=True, cwd=tmp).stdout
    lux = subprocess.run([os.path.join(program_dir, "rmtxop"), "-fa", "-", "-c", "47.4", "119.9", "11.6"], input=product,
                         capture_output=True, env=env, check=True, cwd=tmp).stdout.decode()
    rows = [[float(x) for x in l.split()] for l in lux.split("\n\n", 1)[1].splitlines() if l.strip()]
    return cpu, [statistics.fmean(r) for r in rows]


def ladder(name, program_dir, env, rungs, ref, tmp):
    out = []
    for vopts, dopts in rungs:
        cpus, errors = [], []
        for seed in range(RUNS):
            cpu, lux = rung(program_dir, env, vopts, dopts, seed, tmp)
            cpus.append(cpu)
            errors.append([l / r - 1 for l, r in zip(lux, ref)])
        rms = math.sqrt(statistics.fmean(e * e for run in errors for e in run))
        worst = max(abs(e) for run in errors for e in run)
        bias = statistics.fmean(e for run in errors for e in run)
        out.append((vopts, dopts, statistics.fmean(cpus), rms, worst, bias))
        print("%s | V %s | D %s | %.2f s | RMS %.2f %% | worst %.1f %%" % (name, vopts, dopts, out[-1][2], 100 * rms,
                                                                          100 * worst), flush=True)
    return out


def plot(series):
    """Each program's rungs as points, and the line of its best so far (no cheaper rung less wrong): rungs of
    different kinds make no ladder."""
    script = (
        "fig, ax = plt.subplots(figsize=(7, 4.5))\n"
        "for i, (name, pts) in enumerate(d.items()):\n"
        "    front, best = [], float('inf')\n"
        "    for t, e in pts:\n"
        "        if e < best: front.append((t, e)); best = e\n"
        "    ax.loglog([p[0] for p in pts], [100 * p[1] for p in pts], 'os'[i % 2], color='C%d' % i, label=name)\n"
        "    ax.loglog([p[0] for p in front], [100 * p[1] for p in front], '-', color='C%d' % i, alpha=.6)\n"
        "ax.axhline(2, color='grey', lw=.8, ls=':')\n"
        "ax.set_xlabel('CPU time of the two matrices (s)'); ax.set_ylabel('RMS error of the sensors (%)')\n"
        "ax.set_title('3-phase method: CPU time against error (16 sensors, 48 h)')\n"
        "ax.legend(); ax.grid(alpha=.3, which='both')\n"
        "fig.tight_layout(); fig.savefig(sys.argv[2], dpi=110)\n")
    return bench.matplotlib_plot(script, series, os.path.join(bench.RESULTS, PLOT))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--radiance", help="directory of Radiance's programs (with its lib beside it)")
    args = ap.parse_args()
    ref = reference()
    brume_bin = os.path.join(bench.ROOT, "build", "bin")
    ladders = {}
    with tempfile.TemporaryDirectory() as tmp:
        for f in ("room.rad", "window_v.rad", "window_d.rad", "sensors.pts"):
            shutil.copy(os.path.join(MODEL, f), tmp)
        shutil.copy(os.path.join(DATA, "rcontrib", "sky.rad"), tmp)
        with open(os.path.join(tmp, "sky.smx"), "wb") as f:
            subprocess.run([os.path.join(brume_bin, "gendaymtx"), "-m", "1", WEA], stdout=f, check=True)
        brume_env = dict(os.environ, PATH=brume_bin + ":" + os.environ["PATH"])
        if args.radiance:
            env = dict(os.environ, PATH=args.radiance + ":" + os.environ["PATH"],
                       RAYPATH=".:" + os.path.join(os.path.dirname(args.radiance), "lib"))
            ladders["Radiance"] = ladder("Radiance", args.radiance, env, RADIANCE_RUNGS, ref, tmp)
        ladders["Brume"] = ladder("Brume", brume_bin, brume_env, BRUME_RUNGS, ref, tmp)
    lines = ["# The 3-phase method (bench/three_phase.py)", "",
             "test/data/rfluxmtx/room.rad behind prism_quarter.xml, 16 sensors, 48 hours of Chicago; each sensor's "
             "48-hour mean against Radiance's converged 3-phase result (its own error 0.5 %% or less); %d runs a rung "
             "(RMS over both, CPU mean of the two matrices, one thread each); machine: %s, Brume at %s." %
             (RUNS, bench.machine(), bench.git_commit()), "",
             "| program | view matrix | daylight matrix | CPU s | RMS % | worst % | bias % |", "|---|---|---|---|---|---|---|"]
    for name, rows in ladders.items():
        for vopts, dopts, cpu, rms, worst, bias in rows:
            lines.append("| %s | %s | %s | %.2f | %.2f | %.1f | %+.2f |" % (name, vopts, dopts, cpu, 100 * rms, 100 * worst,
                                                                           100 * bias))
    if "Radiance" in ladders:
        same = [r[2] / b[2] for r, b in zip(ladders["Radiance"], ladders["Brume"][:len(RUNGS)])]
        lines += ["", "At the same settings (the first %d rungs) Radiance takes %s Brume's CPU time." %
                  (len(RUNGS), ", ".join("%.1f x" % x for x in same))]
    cheapest = {name: min(((r[2], r) for r in rows if r[3] <= TARGET), default=None) for name, rows in ladders.items()}
    for name, best in cheapest.items():
        lines.append("%s's cheapest rung within %.0f %% RMS: %s" % (name, 100 * TARGET, "none" if not best else
                     "V %s, D %s: %.2f s (%.2f %%)" % (best[1][0], best[1][1], best[0], 100 * best[1][3])))
    if all(cheapest.get(n) for n in ("Radiance", "Brume")):
        lines.append("Brume is there %.1f x sooner." % (cheapest["Radiance"][0] / cheapest["Brume"][0]))
    plotted = plot({name: sorted((r[2], r[3]) for r in rows) for name, rows in ladders.items()})
    bench.write_result("\n".join(lines) + "\n", TABLE, plotted, PLOT)


if __name__ == "__main__":
    main()
