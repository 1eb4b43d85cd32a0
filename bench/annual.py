#!/usr/bin/env python3
"""Annual daylight (issue 40): the time to a year of sensor illuminances at 2 % RMS, Radiance's 2-phase method
(rfluxmtx daylight coefficients, gendaymtx, dctimestep) on bench/annual/office.rad, a 6 x 8 m side-lit office
with 192 sensors, under Chicago's TMY3 year; against the converged reference
bench/results/annual_reference_office.txt (its header says how it was made and its own error).

Each rung: rfluxmtx -I+ -y 192 <options> - sky.rad -i office.oct < grid.pts, then dctimestep | rmtxop -c 47.4 119.9
11.6 (Honeybee's conversion to lux), timed together (CPU s, one process); per sensor the annual mean illuminance;
its error against the reference: RMS over sensors (%), mean (the bias) and the worst sensor. Radiance's runs are
kept in bench/results/annual_radiance.json; --radiance DIR runs them again with Radiance's programs in DIR.
Brume's ladder runs the same command lines with Brume's programs (build/bin) and -n 1 (one thread), each rung
twice with different seeds (the RMS of the two, and their CPU mean): its rungs differ by -ad at -ab 7 and -ab 10
(Brume's diffuse rays also aim at the sky through the window, so far fewer of them are needed; -ab 7 leaves out
about 0.5 %, as Radiance's does); the goal is 2 % in a tenth of Radiance's cheapest rung within 2 %.

    python3 bench/annual.py [--radiance /tmp/radiance/inst/bin]

Standard library only; the plot (results/annual_time_vs_error.png) is drawn by a Python that has matplotlib.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
import bench  # noqa: E402

MODEL = os.path.join(HERE, "annual")
REFERENCE = os.path.join(bench.RESULTS, "annual_reference_office.txt")
RUNS = os.path.join(bench.RESULTS, "annual_radiance.json")
TABLE = os.path.join(bench.RESULTS, "annual.md")
PLOT = os.path.join(bench.RESULTS, "annual_time_vs_error.png")
WEATHER = os.path.join(bench.ROOT, "..", "shared", "data", "weather", "chicago.epw")
TARGET = 2.0  # % RMS
BRUME_LADDER = [  # Honeybee's default first
    ["-ab", "2", "-ad", "5000", "-lw", "2e-5"],
    ["-ab", "7", "-ad", "512", "-lw", "1e-5"],
    ["-ab", "7", "-ad", "1024", "-lw", "1e-5"],
    ["-ab", "7", "-ad", "2048", "-lw", "1e-5"],
    ["-ab", "7", "-ad", "4096", "-lw", "1e-5"],
    ["-ab", "10", "-ad", "1024", "-lw", "1e-5"],
    ["-ab", "10", "-ad", "1536", "-lw", "1e-5"],
    ["-ab", "10", "-ad", "2048", "-lw", "1e-5"],
]
LADDER = [  # Honeybee's default first
    ["-ab", "2", "-ad", "5000", "-lw", "2e-5"],
    ["-ab", "5", "-ad", "10000", "-lw", "2e-5"],
    ["-ab", "7", "-ad", "10000", "-lw", "1e-6"],
    ["-ab", "7", "-ad", "20000", "-lw", "1e-6"],
    ["-ab", "10", "-ad", "20000", "-lw", "1e-6"],
]


def reference():
    values = []
    with open(REFERENCE) as f:
        for line in f:
            if not line.startswith("#"):
                values.append(float(line.split()[3]))
    return values


def annual_means(path):
    """Each row's mean of a Radiance float matrix with one component (sensors x hours)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"\n\n")
    head = dict(l.split("=", 1) for l in data[:end].decode().splitlines() if "=" in l and not l.startswith("#"))
    rows, cols = int(head["NROWS"]), int(head["NCOLS"])
    import array
    a = array.array("f")
    a.frombytes(data[end + 2:end + 2 + 4 * rows * cols])
    return [sum(a[r * cols:(r + 1) * cols]) / cols for r in range(rows)]


def errors(values, ref):
    rel = [v / r - 1 for v, r in zip(values, ref)]
    worst = max(rel, key=abs)
    return {"rms": 100 * math.sqrt(sum(e * e for e in rel) / len(rel)), "bias": 100 * sum(rel) / len(rel),
            "worst": 100 * worst}


def run_radiance(bindir, ref):
    env = dict(os.environ, PATH=bindir + ":" + os.environ["PATH"],
               RAYPATH=".:" + os.path.join(os.path.dirname(bindir), "lib"))
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        sh = lambda cmd, **kw: subprocess.run(cmd, shell=True, cwd=tmp, env=env, check=True, **kw)
        sh("epw2wea '%s' chicago.wea && gendaymtx -m 1 -of chicago.wea > sky.smx 2> /dev/null" % WEATHER)
        sh("oconv '%s/materials.rad' '%s/office.rad' > office.oct" % (MODEL, MODEL))
        for options in LADDER:
            script = os.path.join(tmp, "rung.sh")
            with open(script, "w") as f:
                f.write("cd '%s' && rfluxmtx -I+ -y 192 %s - '%s/sky.rad' -i office.oct < '%s/grid.pts' > dc.mtx && "
                        "dctimestep dc.mtx sky.smx | rmtxop -ff -c 47.4 119.9 11.6 - > ill.mtx\n"
                        % (tmp, " ".join(options), MODEL, MODEL))
            t = bench.Timer(["bash", script], os.devnull, env=env, capture=False)
            runs.append({"options": " ".join(options), "cpu": t.cpu, "wall": t.wall,
                         **errors(annual_means(os.path.join(tmp, "ill.mtx")), ref)})
            print("  %-28s %6.1f CPU s  RMS %.2f %%" % (runs[-1]["options"], t.cpu, runs[-1]["rms"]), file=sys.stderr)
    with open(RUNS, "w") as f:
        json.dump({"machine": bench.machine(), "runs": runs}, f, indent=1)
    return runs


def run_brume(ref):
    """Brume's ladder: rfluxmtx, dctimestep and rmtxop from build/bin, one thread, two seeds a rung."""
    bindir = os.path.join(bench.ROOT, "build", "bin")
    env = dict(os.environ, PATH=bindir + ":" + os.environ["PATH"])
    env.pop("RAYPATH", None)
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        sh = lambda cmd: subprocess.run(cmd, shell=True, cwd=tmp, env=env, check=True)
        sh("epw2wea '%s' chicago.wea && gendaymtx -m 1 -of chicago.wea > sky.smx 2> /dev/null" % WEATHER)
        for options in BRUME_LADDER:
            script = os.path.join(tmp, "rung.sh")
            with open(script, "w") as f:
                f.write("cd '%s' && rfluxmtx -n 1 -I+ -y 192 %s - '%s/sky.rad' '%s/materials.rad' '%s/office.rad' "
                        "< '%s/grid.pts' > dc.mtx && dctimestep dc.mtx sky.smx | rmtxop -ff -c 47.4 119.9 11.6 - > ill.mtx\n"
                        % (tmp, " ".join(options), MODEL, MODEL, MODEL, MODEL))
            tries = []
            for _ in range(2):
                t = bench.Timer(["bash", script], os.devnull, env=env, capture=False)
                tries.append((t.cpu, t.wall, errors(annual_means(os.path.join(tmp, "ill.mtx")), ref)))
            rms = math.sqrt(sum(e["rms"] ** 2 for _, _, e in tries) / 2)
            worst = max((e["worst"] for _, _, e in tries), key=abs)
            runs.append({"options": " ".join(options), "cpu": sum(c for c, _, _ in tries) / 2,
                         "wall": sum(w for _, w, _ in tries) / 2, "rms": rms,
                         "bias": sum(e["bias"] for _, _, e in tries) / 2, "worst": worst})
            print("  Brume %-22s %6.1f CPU s  RMS %.2f %%" % (runs[-1]["options"], runs[-1]["cpu"], rms), file=sys.stderr)
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--radiance", help="run Radiance's ladder again with its programs in this directory")
    args = ap.parse_args()
    ref = reference()
    brume = run_brume(ref)
    if args.radiance:
        runs = run_radiance(args.radiance, ref)
    else:
        with open(RUNS) as f:
            runs = json.load(f)["runs"]
    within = [r for r in runs if r["rms"] <= TARGET]
    cheapest = min(within, key=lambda r: r["cpu"]) if within else None
    lines = ["# Annual daylight: time to a year of illuminances (bench/annual.py)", "",
             "bench/annual/office.rad (6 x 8 m, south window, 192 sensors), Chicago TMY3, one process; errors of each",
             "sensor's annual mean illuminance against the reference (its own error 0.18 % RMS).", "",
             "| program | options | CPU s | RMS % | bias % | worst sensor % |", "|---|---|---|---|---|---|"]
    for r in runs:
        lines.append("| Radiance rfluxmtx | %s | %.1f | %.2f | %+.2f | %+.1f |" % (r["options"], r["cpu"], r["rms"], r["bias"], r["worst"]))
    for r in brume:
        lines.append("| Brume rfluxmtx -n 1 | %s | %.1f | %.2f | %+.2f | %+.1f |" % (r["options"], r["cpu"], r["rms"], r["bias"], r["worst"]))
    if cheapest:
        lines += ["", "Radiance's cheapest within %g %%: %s, %.1f CPU s; Brume's goal: %g %% in %.1f CPU s or less." %
                  (TARGET, cheapest["options"], cheapest["cpu"], TARGET, cheapest["cpu"] / 10)]
        ours = [r for r in brume if r["rms"] <= TARGET]
        if ours:
            best = min(ours, key=lambda r: r["cpu"])
            lines.append("Brume's cheapest within %g %%: %s, %.1f CPU s: %.1f x sooner than Radiance's." %
                         (TARGET, best["options"], best["cpu"], cheapest["cpu"] / best["cpu"]))
    series = {"Radiance rfluxmtx, office": [(r["cpu"], r["rms"] / 100) for r in sorted(runs, key=lambda r: r["cpu"])],
              "Brume rfluxmtx, office": [(r["cpu"], r["rms"] / 100) for r in sorted(brume, key=lambda r: r["cpu"])]}
    plotted = bench.ladders_plot(series, PLOT, "Annual illuminance: CPU time against RMS error", ", ", "Brume")
    bench.write_result("\n".join(lines) + "\n", os.path.basename(TABLE), plotted, os.path.basename(PLOT))


if __name__ == "__main__":
    main()
