#!/usr/bin/env python3
"""Annual daylight (issue 40): the time to a year of sensor illuminances at 2 % RMS, Radiance's 2-phase method
(rfluxmtx daylight coefficients, gendaymtx, then the timestep) under Chicago's TMY3 year, on three cases:
bench/annual/office.rad (a 6 x 8 m side-lit office, 192 sensors) at Tregenza's 145 patches and at Reinhart's 577,
and bench/annual/deepplan.rad (20 x 12 m, two south windows and an east one, 416 sensors) at 145. Each case has
a converged reference (results/annual_reference_<case>.txt; their headers say how they were made and their own
error) and the metrics of its hourly illuminances (results/annual_reference_<case>_metrics.csv).

Each rung: rfluxmtx -I+ -y <sensors> <options> - sky.rad -i model.oct < grid.pts, timed (CPU s, one process),
then the timestep with Honeybee's conversion to lux (-c 47.4 119.9 11.6) in each program's faster form, timed once
per program and case and added to every rung: `dctimestep dc.mtx sky.smx | rmtxop -ff -c ... -` (Radiance's
faster) or `rmtxop -ff dc.mtx sky.smx -c ...` (Honeybee's form; Brume's faster). Per sensor the annual mean
illuminance; its error against the reference: RMS over sensors (%), mean (the bias) and the worst sensor. The
metrics (daymetrics, Honeybee's definitions, 8 to 18 h every day) against the reference's: sDA300/50% (points)
and the worst sensor's DA (points). Radiance's runs are kept in bench/results/annual_radiance.json, Brume's in
annual_brume.json (the table shows every case run so far); --radiance DIR runs Radiance's again with its programs
in DIR. Brume's ladders run the same command lines with Brume's programs
(build/bin) and -n 1 (one thread), each rung twice with different seeds (the RMS of the two, and their CPU
mean), at its defaults (shared bounces, rcontrib's -aS) and with -aS 0 (each first bounce its own path, as in
Radiance); with --radiance the two programs' rungs alternate, so that the machine's drift in speed falls on both.
The goal is 2 % in a tenth of Radiance's cheapest rung within 2 %.

    python3 bench/annual.py [--radiance /tmp/radiance/inst/bin] [--cases office,office_m2,deepplan]
    python3 bench/annual.py --reference CASE --radiance DIR     # a case's converged reference, one run

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
DAYMETRICS = os.path.join(bench.ROOT, "build", "bin", "daymetrics")
RUNS = os.path.join(bench.RESULTS, "annual_radiance.json")
BRUME_RUNS = os.path.join(bench.RESULTS, "annual_brume.json")
TABLE = os.path.join(bench.RESULTS, "annual.md")
PLOT = os.path.join(bench.RESULTS, "annual_time_vs_error.png")
WEATHER = os.path.join(bench.ROOT, "..", "shared", "data", "weather", "chicago.epw")
TARGET = 2.0  # % RMS
REFERENCE_OPTIONS = "-ab 10 -ad 50000 -lw 1e-7"
HONEYBEE = ["-ab", "2", "-ad", "5000", "-lw", "2e-5"]


class Case:
    def __init__(self, name, title, model, grid, sensors, patches, ladder, brume_ladder):
        self.name, self.title, self.model, self.grid, self.sensors = name, title, model, grid, sensors
        self.patches, self.ladder, self.brume_ladder = patches, ladder, brume_ladder
        self.reference = os.path.join(bench.RESULTS, "annual_reference_%s.txt" % name)
        self.metrics = os.path.join(bench.RESULTS, "annual_reference_%s_metrics.csv" % name)

    def label(self):
        return "%s, %d patches" % (self.title, 145 if self.patches == 1 else 577)


def rungs(*specs):
    """Honeybee's rung, then one per (ab, ad, lw[, more options])."""
    return [HONEYBEE] + [["-ab", ab, "-ad", ad, "-lw", lw] + list(more) for ab, ad, lw, *more in specs]


UNSHARED = "-aS", "0"  # Brume with each first bounce's own path, Radiance's estimator


CASES = [
    Case("office", "office (192 sensors)", "office.rad", "grid.pts", 192, 1,
         rungs(("5", "10000", "2e-5"), ("7", "10000", "1e-6"), ("7", "20000", "1e-6"), ("10", "20000", "1e-6")),
         rungs(("10", "256", "1e-5"), ("10", "512", "1e-5"), ("10", "1024", "1e-5"), ("10", "2048", "1e-5"),
               ("10", "1024", "1e-5", *UNSHARED), ("10", "1536", "1e-5", *UNSHARED), ("10", "2048", "1e-5", *UNSHARED))),
    Case("office_m2", "office (192 sensors)", "office.rad", "grid.pts", 192, 2,
         rungs(("7", "10000", "1e-6"), ("7", "20000", "1e-6")),
         rungs(("10", "256", "1e-5"), ("10", "512", "1e-5"), ("10", "1024", "1e-5"),
               ("10", "1536", "1e-5", *UNSHARED), ("10", "2048", "1e-5", *UNSHARED))),
    Case("deepplan", "deep plan (416 sensors)", "deepplan.rad", "grid_B.pts", 416, 1,
         rungs(("7", "10000", "1e-6"), ("7", "20000", "1e-6")),
         rungs(("10", "256", "1e-5"), ("10", "512", "1e-5"), ("10", "1024", "1e-5"), ("10", "2048", "1e-5"),
               ("10", "2048", "1e-5", *UNSHARED), ("10", "3072", "1e-5", *UNSHARED))),
]


def reference(case):
    values = []
    with open(case.reference) as f:
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
    """Brume's daymetrics of an hourly matrix: its per-sensor CSV text, each sensor's DA (%), the grid's sDA (%)."""
    cmd = [DAYMETRICS] + (["-g", grid] if grid else []) + [path]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    da = [float(l.split(",")[1]) for l in out.splitlines() if l[:1].isdigit()]
    return out, da, 100 * sum(d >= 50 for d in da) / len(da)


def reference_metrics(case):
    with open(case.metrics) as f:
        da = [float(l.split(",")[1]) for l in f if l[:1].isdigit()]
    return da, 100 * sum(d >= 50 for d in da) / len(da)


def judged(ill, ref, metrics):
    """The errors of one year of illuminances: annual means against the reference, metrics against its metrics."""
    _, da, sda = daymetrics(ill)
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


def coefficients(case, threads):
    return "rfluxmtx %s -I+ -y %d %%s - sky.rad -i model.oct < '%s/%s' > dc.mtx" % (threads, case.sensors, MODEL, case.grid)


def ladder(case, rungs, line, env, tries):
    """A program's ladder on a case, a rung at a time (a generator, so that two programs' rungs can alternate): each
    rung's coefficients `tries` times (the RMS of their errors, their mean CPU), plus the faster timestep."""
    ref, metrics = reference(case), reference_metrics(case)
    steps = None
    with tempfile.TemporaryDirectory() as tmp:
        prepare(case, tmp, env)
        for options in rungs:
            results = []
            for _ in range(tries):
                t = timed(tmp, env, line % " ".join(options))
                if steps is None:
                    steps = timestep(tmp, env)
                else:
                    timed(tmp, env, TIMESTEPS[steps[0]])
                results.append((t.cpu, judged(os.path.join(tmp, "ill.mtx"), ref, metrics)))
            n = len(results)
            mean = lambda key: sum(e[key] for _, e in results) / n
            run = {"options": " ".join(options), "coefficients_cpu": sum(c for c, _ in results) / n,
                   "timestep": steps[0], "timestep_cpu": steps[1][steps[0]], "timesteps": steps[1],
                   "rms": math.sqrt(sum(e["rms"] ** 2 for _, e in results) / n), "bias": mean("bias"),
                   "worst": max((e["worst"] for _, e in results), key=abs), "sda": mean("sda"),
                   "da_worst": max((e["da_worst"] for _, e in results), key=abs)}
            run["cpu"] = run["coefficients_cpu"] + run["timestep_cpu"]
            print("  %-10s %-28s %6.1f CPU s  RMS %.2f %%  sDA %+.2f" % (case.name, run["options"], run["cpu"],
                                                                        run["rms"], run["sda"]), file=sys.stderr)
            yield run


def alternating(ladders):
    """Every ladder's rungs, one of each in turn, so that the machine's drift in speed falls on all of them."""
    runs = [[] for _ in ladders]
    pending = list(enumerate(ladders))
    while pending:
        for entry in list(pending):
            try:
                runs[entry[0]].append(next(entry[1]))
            except StopIteration:
                pending.remove(entry)
    return runs


def prepare(case, tmp, env):
    """The year's sky matrix, the receivers at the case's patches, the model's octree."""
    with open(os.path.join(MODEL, "sky.rad")) as f:
        sky = f.read().replace("h=r1", "h=r%d" % case.patches)
    with open(os.path.join(tmp, "sky.rad"), "w") as f:
        f.write(sky)
    subprocess.run("epw2wea '%s' chicago.wea && gendaymtx -m %d -of chicago.wea > sky.smx 2> /dev/null && "
                   "oconv -f '%s/materials.rad' '%s/%s' > model.oct" % (WEATHER, case.patches, MODEL, MODEL, case.model),
                   shell=True, cwd=tmp, env=env, check=True)


def radiance_env(bindir):
    return dict(os.environ, PATH=bindir + ":" + os.environ["PATH"],
                RAYPATH=".:" + os.path.join(os.path.dirname(bindir), "lib"))


def kept(path, runs):
    """The ladders kept in `path`, those of `runs` replacing theirs; written back."""
    cases = {}
    if os.path.exists(path):
        with open(path) as f:
            cases = json.load(f).get("cases", {})
    cases.update(runs)
    with open(path, "w") as f:
        json.dump({"machine": bench.machine(), "cases": cases}, f, indent=1)
    return cases


def brume_env():
    bindir = os.path.join(bench.ROOT, "build", "bin")
    env = dict(os.environ, PATH=bindir + ":" + os.environ["PATH"])
    env.pop("RAYPATH", None)
    return env


def run_case(case, radiance_bin):
    """Brume's ladder on a case (rfluxmtx and rmtxop from build/bin, one thread, two seeds a rung) and, given its
    programs, Radiance's (one run a rung), their rungs alternating."""
    ladders = [ladder(case, case.brume_ladder, coefficients(case, "-n 1"), brume_env(), 2)]
    if radiance_bin:
        ladders.append(ladder(case, case.ladder, coefficients(case, ""), radiance_env(radiance_bin), 1))
    return alternating(ladders)


def make_reference(case, bindir):
    """One run of Radiance's rfluxmtx at REFERENCE_OPTIONS: each sensor's annual mean, and the metrics."""
    env = radiance_env(bindir)
    with tempfile.TemporaryDirectory() as tmp:
        prepare(case, tmp, env)
        t = timed(tmp, env, coefficients(case, "") % REFERENCE_OPTIONS)
        timed(tmp, env, TIMESTEPS["dctimestep"])
        ill = os.path.join(tmp, "ill.mtx")
        means = annual_means(ill)
        text, _, sda = daymetrics(ill)
    how = ("# Radiance's converged 2-phase result on bench/annual/%s (%s), %d patches, Chicago's TMY3 year:\n"
           "# rfluxmtx -I+ -y %d %s - sky.rad -i model.oct < %s (sky.rad with h=r%d), gendaymtx -m %d -of,\n"
           "# dctimestep | rmtxop -ff -c 47.4 119.9 11.6; one run, %.0f CPU s (bench/annual.py --reference %s).\n"
           "# Its own error: the same run on the office at 145 patches is 0.58 %% RMS (worst sensor 2.1 %%) from\n"
           "# annual_reference_office.txt, the mean of ten such runs.\n") % (
        case.model, case.grid, 145 if case.patches == 1 else 577, case.sensors, REFERENCE_OPTIONS, case.grid,
        case.patches, case.patches, t.cpu, case.name)
    with open(os.path.join(MODEL, case.grid)) as f:
        points = [l.split()[:3] for l in f if l.strip()]
    with open(case.reference, "w") as f:
        f.write(how + "# x y z annual-mean-lux\n")
        for p, m in zip(points, means):
            f.write("%s %s %s %.4f\n" % (p[0], p[1], p[2], m))
    with open(case.metrics, "w") as f:
        f.write(how + "# Its metrics by Brume's daymetrics (sDA300/50%% %.2f %%):\n" % sda + text)


def table(case, radiance, brume):
    within = [r for r in radiance if r["rms"] <= TARGET]
    cheapest = min(within, key=lambda r: r["cpu"]) if within else None
    lines = ["## %s" % case.label(), "",
             "bench/annual/%s, %s; reference %s (sDA300/50%% %.2f %%). Timestep: Radiance %s %.2f s, Brume %s %.2f s." % (
                 case.model, case.grid, os.path.basename(case.reference), reference_metrics(case)[1],
                 radiance[0]["timestep"], radiance[0]["timestep_cpu"], brume[0]["timestep"], brume[0]["timestep_cpu"]), "",
             "| program | options | CPU s | RMS % | bias % | worst sensor % | sDA points | worst DA points |",
             "|---|---|---|---|---|---|---|---|"]
    row = "| %s | %s | %.1f | %.2f | %+.2f | %+.1f | %+.2f | %+.2f |"
    for who, rows in (("Radiance rfluxmtx", radiance), ("Brume rfluxmtx -n 1", brume)):
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
    return lines + [""]


def frontier(rows):
    """The rungs no cheaper rung beats, (CPU s, RMS error) in order of time: a program's time against its error."""
    points, best = [], float("inf")
    for r in sorted(rows, key=lambda r: r["cpu"]):
        if r["rms"] < best:
            points.append((r["cpu"], r["rms"] / 100))
            best = r["rms"]
    return points


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--radiance", help="run Radiance's ladders again with its programs in this directory")
    ap.add_argument("--cases", default=",".join(c.name for c in CASES), help="the cases to run, comma-separated")
    ap.add_argument("--reference", help="make this case's converged reference with Radiance (needs --radiance)")
    args = ap.parse_args()
    by_name = {c.name: c for c in CASES}
    if args.reference:
        if not args.radiance:
            sys.exit("bench: --reference needs --radiance DIR")
        return make_reference(by_name[args.reference], args.radiance)
    cases = [by_name[n] for n in args.cases.split(",")]
    runs = {c.name: run_case(c, args.radiance) for c in cases}
    brume = kept(BRUME_RUNS, {name: r[0] for name, r in runs.items()})
    radiance = kept(RUNS, {name: r[1] for name, r in runs.items() if len(r) > 1})
    cases = [c for c in CASES if c.name in brume and c.name in radiance]  # the table: every case run so far
    lines = ["# Annual daylight: time to a year of illuminances (bench/annual.py)", "",
             "Chicago TMY3, one process; errors of each sensor's annual mean illuminance against the case's reference,",
             "and of the metrics against the reference's (sDA and the worst sensor's DA, in points). CPU s: the",
             "coefficients plus each program's faster form of the timestep.", ""]
    series = {}
    for case in cases:
        lines += table(case, radiance[case.name], brume[case.name])
        for who, rows in (("Radiance", radiance[case.name]), ("Brume", brume[case.name])):
            series["%s, %s" % (case.label(), who)] = frontier(rows)
    plotted = bench.ladders_plot(series, PLOT, "Annual illuminance: CPU time against RMS error", ", ", "Brume")
    bench.write_result("\n".join(lines), os.path.basename(TABLE), plotted, os.path.basename(PLOT))


if __name__ == "__main__":
    main()
