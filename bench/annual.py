#!/usr/bin/env python3
"""Annual daylight (issue 40): the time to a year of sensor illuminances at 2 % RMS, Radiance's 2-phase method
(rfluxmtx daylight coefficients, gendaymtx, then the timestep) on bench/annual/office.rad, a 6 x 8 m side-lit
office with 192 sensors, under Chicago's TMY3 year; against the converged reference
bench/results/annual_reference_office.txt (its header says how it was made and its own error).

Each rung: rfluxmtx -I+ -y 192 <options> - sky.rad -i office.oct < grid.pts, timed (CPU s, one process), then
the timestep with Honeybee's conversion to lux (-c 47.4 119.9 11.6) in each program's faster form, timed once
per program and added to every rung: `dctimestep dc.mtx sky.smx | rmtxop -ff -c ... -` (Radiance's faster) or
`rmtxop -ff dc.mtx sky.smx -c ...` (Honeybee's form; Brume's faster). Per sensor the annual mean illuminance; its
error against the reference: RMS over sensors (%), mean (the bias) and the worst sensor. The metrics (daymetrics,
Honeybee's definitions, 8 to 18 h every day) against those of Radiance's converged hourly illuminances
(results/annual_reference_office_metrics.csv, how it was made in its header): sDA300/50% (points) and the worst
sensor's DA (points). Radiance's runs are kept in bench/results/annual_radiance.json; --radiance DIR runs them
again with Radiance's programs in DIR. Brume's ladder runs the same command lines with Brume's programs
(build/bin) and -n 1 (one thread), each rung twice with different seeds (the RMS of the two, and their CPU
mean): its rungs differ by -ad at -ab 7 and -ab 10 (Brume's diffuse rays also aim at the sky through the window,
so far fewer of them are needed; -ab 7 leaves out about 0.5 %, as Radiance's does); the goal is 2 % in a tenth
of Radiance's cheapest rung within 2 %.

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
REFERENCE_METRICS = os.path.join(bench.RESULTS, "annual_reference_office_metrics.csv")
DAYMETRICS = os.path.join(bench.ROOT, "build", "bin", "daymetrics")
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


def daymetrics(path, grid=None):
    """Each sensor's DA (%) by Brume's daymetrics, and the grid's sDA (%) when asked."""
    cmd = [DAYMETRICS] + (["-g", grid] if grid else []) + [path]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    da = [float(l.split(",")[1]) for l in out.splitlines() if l[:1].isdigit()]
    sda = None
    if grid:
        with open(grid) as f:
            sda = next(float(l.split(",")[1]) for l in f if l.startswith("sda,"))
    return da, sda


def reference_metrics():
    with open(REFERENCE_METRICS) as f:
        rows = [l.strip().split(",") for l in f if l[:1].isdigit()]
    da = [float(r[1]) for r in rows]
    return da, 100 * sum(d >= 50 for d in da) / len(da)


def judged(ill, ref, metrics, tmp):
    """The errors of one year of illuminances: annual means against the reference, metrics against its metrics."""
    da, sda = daymetrics(ill, os.path.join(tmp, "grid.csv"))
    ref_da, ref_sda = metrics
    return {**errors(annual_means(ill), ref), "sda": sda - ref_sda,
            "da_worst": max((d - r for d, r in zip(da, ref_da)), key=abs)}


TIMESTEPS = {"dctimestep": "dctimestep dc.mtx sky.smx | rmtxop -ff -c 47.4 119.9 11.6 - > ill.mtx",
             "rmtxop": "rmtxop -ff dc.mtx sky.smx -c 47.4 119.9 11.6 > ill.mtx"}


def timed(tmp, env, line):
    script = os.path.join(tmp, "step.sh")
    with open(script, "w") as f:
        f.write("cd '%s' && %s\n" % (tmp, line))
    return bench.Timer(["bash", script], os.devnull, env=env, capture=False)


def timestep(tmp, env):
    """Each form of the timestep on this dc.mtx, timed; the faster one's name, and all their CPU s. The faster
    one runs last, its ill.mtx left behind."""
    cpu = {name: timed(tmp, env, line).cpu for name, line in TIMESTEPS.items()}
    best = min(cpu, key=cpu.get)
    timed(tmp, env, TIMESTEPS[best])
    return best, cpu


def run_ladder(ladder, coefficients, tmp, env, ref, metrics, tries):
    """Each rung's coefficients `tries` times (the RMS of their errors, their mean CPU), plus the faster timestep."""
    runs, steps = [], None
    for options in ladder:
        results = []
        for _ in range(tries):
            t = timed(tmp, env, coefficients % " ".join(options))
            if steps is None:
                steps = timestep(tmp, env)
            else:
                timed(tmp, env, TIMESTEPS[steps[0]])
            results.append((t.cpu, judged(os.path.join(tmp, "ill.mtx"), ref, metrics, tmp)))
        n = len(results)
        mean = lambda key: sum(e[key] for _, e in results) / n
        runs.append({"options": " ".join(options), "coefficients_cpu": sum(c for c, _ in results) / n,
                     "timestep": steps[0], "timestep_cpu": steps[1][steps[0]], "timesteps": steps[1],
                     "rms": math.sqrt(sum(e["rms"] ** 2 for _, e in results) / n), "bias": mean("bias"),
                     "worst": max((e["worst"] for _, e in results), key=abs), "sda": mean("sda"),
                     "da_worst": max((e["da_worst"] for _, e in results), key=abs)})
        runs[-1]["cpu"] = runs[-1]["coefficients_cpu"] + runs[-1]["timestep_cpu"]
        print("  %-28s %6.1f CPU s  RMS %.2f %%  sDA %+.2f" % (runs[-1]["options"], runs[-1]["cpu"], runs[-1]["rms"],
                                                             runs[-1]["sda"]), file=sys.stderr)
    return runs


def prepare(tmp, env):
    subprocess.run("epw2wea '%s' chicago.wea && gendaymtx -m 1 -of chicago.wea > sky.smx 2> /dev/null && "
                   "oconv -f '%s/materials.rad' '%s/office.rad' > office.oct" % (WEATHER, MODEL, MODEL),
                   shell=True, cwd=tmp, env=env, check=True)


COEFFICIENTS = "rfluxmtx %s -I+ -y 192 %%s - '%s/sky.rad' -i office.oct < '%s/grid.pts' > dc.mtx"


def run_radiance(bindir, ref, metrics):
    env = dict(os.environ, PATH=bindir + ":" + os.environ["PATH"],
               RAYPATH=".:" + os.path.join(os.path.dirname(bindir), "lib"))
    with tempfile.TemporaryDirectory() as tmp:
        prepare(tmp, env)
        runs = run_ladder(LADDER, COEFFICIENTS % ("", MODEL, MODEL), tmp, env, ref, metrics, 1)
    with open(RUNS, "w") as f:
        json.dump({"machine": bench.machine(), "runs": runs}, f, indent=1)
    return runs


def run_brume(ref, metrics):
    """Brume's ladder: rfluxmtx, dctimestep and rmtxop from build/bin, one thread, two seeds a rung."""
    bindir = os.path.join(bench.ROOT, "build", "bin")
    env = dict(os.environ, PATH=bindir + ":" + os.environ["PATH"])
    env.pop("RAYPATH", None)
    with tempfile.TemporaryDirectory() as tmp:
        prepare(tmp, env)
        return run_ladder(BRUME_LADDER, COEFFICIENTS % ("-n 1", MODEL, MODEL), tmp, env, ref, metrics, 2)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--radiance", help="run Radiance's ladder again with its programs in this directory")
    args = ap.parse_args()
    ref, metrics = reference(), reference_metrics()
    brume = run_brume(ref, metrics)
    if args.radiance:
        runs = run_radiance(args.radiance, ref, metrics)
    else:
        with open(RUNS) as f:
            runs = json.load(f)["runs"]
    within = [r for r in runs if r["rms"] <= TARGET]
    cheapest = min(within, key=lambda r: r["cpu"]) if within else None
    lines = ["# Annual daylight: time to a year of illuminances (bench/annual.py)", "",
             "bench/annual/office.rad (6 x 8 m, south window, 192 sensors), Chicago TMY3, one process; errors of each",
             "sensor's annual mean illuminance against the reference (its own error 0.18 % RMS); the metrics'",
             "errors against those of Radiance's converged hourly illuminances (sDA300/50%% %.2f %%). CPU s: the" %
             metrics[1],
             "coefficients plus each program's faster timestep (%s)." % ", ".join(
                 "%s %s %.2f s" % (who, r["timestep"], r["timestep_cpu"]) for who, r in (("Radiance", runs[0]), ("Brume", brume[0]))), "",
             "| program | options | CPU s | RMS % | bias % | worst sensor % | sDA points | worst DA points |",
             "|---|---|---|---|---|---|---|---|"]
    row = "| %s | %s | %.1f | %.2f | %+.2f | %+.1f | %+.2f | %+.2f |"
    for who, rows in (("Radiance rfluxmtx", runs), ("Brume rfluxmtx -n 1", brume)):
        for r in rows:
            lines.append(row % (who, r["options"], r["cpu"], r["rms"], r["bias"], r["worst"], r["sda"], r["da_worst"]))
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
