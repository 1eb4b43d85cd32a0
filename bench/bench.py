#!/usr/bin/env python3
"""Brume benchmark: speed and time-versus-error of rtrace on examples/office, against Radiance if present.

Called by bench/run.sh (`make bench`); see bench/README.md. Standard library only: the plot is drawn by
bench/plot.py in a Python that has matplotlib, or by gnuplot.
"""
import argparse
import hashlib
import json
import math
import os
import platform
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SCENE = os.path.join(ROOT, "examples", "office", "office.rad")
GRID = os.path.join(ROOT, "examples", "office", "grid.txt")
RESULTS = os.path.join(HERE, "results")
REFERENCE = os.path.join(RESULTS, "reference.txt")

# The converged reference: several independent Brume runs, averaged (see make_reference).
REF_OPTIONS = ["-I", "-h", "-ab", "5", "-aa", "0", "-ad", "8192", "-as", "0", "-ds", ".05", "-lw", "1e-6"]
REF_RUNS = 4
# Options shared by every rung of the time-versus-error ladders.
LADDER_COMMON = ["-I", "-h", "-ab", "5", "-lw", "1e-5"]
AD_LADDER = [64, 128, 256, 512, 1024, 2048, 4096]
RADIANCE_CACHE_LADDER = [  # (-aa, -ar, -ad, -as): Radiance's irradiance cache, coarse to fine
    (".3", "32", "128", "64"),
    (".2", "64", "256", "128"),
    (".15", "128", "512", "256"),
    (".1", "128", "1024", "512"),
]
VIEWPOINT = (4.5, 3.2, 1.2)  # a seated eye in the office's north-east quarter


def lux(rgb):
    return 179.0 * (0.265 * rgb[0] + 0.670 * rgb[1] + 0.065 * rgb[2])


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def read_rgb(text):
    rows = []
    for line in text.splitlines():
        v = line.split()
        if len(v) >= 3:
            rows.append(tuple(float(x) for x in v[:3]))
    return rows


GNU_TIME = "/usr/bin/time"
MAX_RSS = "bench max rss kB: "


class Timer:
    """One run of cmd with stdin from a file and stdout captured (out, text), discarded, or written to out_path: its
    wall and CPU time (user + system), peak memory (max_rss_mb, None if unknown), stderr (err) and exit status
    (returncode). A failed run ends the bench unless check is False. The peak memory is GNU time's: the maximum
    resident set that wait4 gives for a child of this process counts the copy of Python it was forked from."""

    def __init__(self, cmd, stdin_path, env=None, capture=True, out_path=None, check=True):
        timed = os.access(GNU_TIME, os.X_OK)
        with open(stdin_path, "rb") as fin, open(out_path or os.devnull, "wb") as fout, \
                tempfile.TemporaryFile() as ferr:
            t0 = time.perf_counter()
            p = subprocess.Popen(([GNU_TIME, "-f", MAX_RSS + "%M"] if timed else []) + list(cmd), stdin=fin,
                                 stdout=subprocess.PIPE if capture and not out_path else fout, stderr=ferr, env=env)
            out = p.stdout.read() if p.stdout else None
            _, status, usage = os.wait4(p.pid, 0)  # the child's own resource usage, not all children's
            self.wall = time.perf_counter() - t0
            p.returncode = os.waitstatus_to_exitcode(status)
            if p.stdout:
                p.stdout.close()
            ferr.seek(0)
            err = ferr.read().decode(errors="replace").splitlines(keepends=True)
        self.out = out.decode() if out is not None else None
        self.cpu = usage.ru_utime + usage.ru_stime  # GNU time's and its child's
        ours = [l for l in err if l.startswith((MAX_RSS, "Command exited with", "Command terminated by"))] if timed else []
        rss = [l for l in ours if l.startswith(MAX_RSS)]
        self.max_rss_mb = int(rss[-1][len(MAX_RSS):]) / 1024 if rss else None
        self.err = "".join(l for l in err if l not in ours)
        self.returncode = p.returncode
        if check and p.returncode != 0:
            sys.exit("bench: command failed (%d): %s\n%s" % (p.returncode, " ".join(cmd), self.err))


def best_of(n, cmd, stdin_path, env=None):
    """The fastest of n runs (least disturbed by other load): (wall, cpu)."""
    runs = [Timer(cmd, stdin_path, env, capture=False) for _ in range(n)]
    best = min(runs, key=lambda r: r.wall)
    return best.wall, best.cpu


def find_radiance():
    cand = os.environ.get("RADIANCE_BIN") or "/tmp/radiance/bin"
    rt, oc = os.path.join(cand, "rtrace"), os.path.join(cand, "oconv")
    if not (os.access(rt, os.X_OK) and os.access(oc, os.X_OK)):
        return None
    env = dict(os.environ)
    lib = os.environ.get("RADIANCE_LIB") or os.path.join(os.path.dirname(cand), "lib")
    if os.path.isdir(lib):
        env["RAYPATH"] = ".:" + lib
    return {"rtrace": rt, "oconv": oc, "env": env, "dir": cand}


def frozen_octree(rad, tmp):
    """Radiance's octree of the office in tmp, frozen (oconv -f) so that it does not depend on the working directory."""
    path = os.path.join(tmp, "office.oct")
    with open(path, "wb") as f:
        subprocess.run([rad["oconv"], "-f", SCENE], stdout=f, env=rad["env"], check=True)
    return path


def machine():
    """The machine's name, and its processor, which cached timings hold for."""
    model = "unknown processor"
    try:
        with open("/proc/cpuinfo") as f:
            model = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), model)
    except OSError:
        pass
    return "%s (%s x%d)" % (platform.node(), model, os.cpu_count() or 1)


def git_commit():
    """HEAD's short hash, with -dirty if the sources have uncommitted changes (a guess at what was built)."""
    try:
        head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "-uno", "--", "lib", "rtrace"],
                               capture_output=True, text=True).stdout.strip()
        return (head + ("-dirty" if dirty else "")) or "unknown"
    except OSError:
        return "unknown"


# ---------------------------------------------------------------- reference

def read_reference(path):
    """A reference file's header fields, lux and relative standard errors (the columns make_reference writes)."""
    meta, lx, se = {}, [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if ":" in line:
                    k, v = line[1:].split(":", 1)
                    meta[k.strip()] = v.strip()
                continue
            v = line.split()
            if len(v) >= 8:
                lx.append(float(v[6]))
                se.append(float(v[7]) / 100)
    return meta, lx, se


def load_reference(path=REFERENCE, options=REF_OPTIONS):
    """The cached reference, if it was made from the current scene and grid with these options: list of lux,
    list of rel. SE, metadata."""
    if not os.path.exists(path):
        return None
    meta, lx, se = read_reference(path)
    if meta.get("scene sha256") != sha256(SCENE) or meta.get("grid sha256") != sha256(GRID):
        print("bench: %s was made for another scene or grid: remaking it" % os.path.relpath(path, ROOT))
        return None
    if not meta.get("command", "").startswith("rtrace " + " ".join(options) + " "):
        print("bench: %s was made with other options: remaking it" % os.path.relpath(path, ROOT))
        return None
    return lx, se, meta


def time_to(points, target):
    """The time at which a ladder of (time, RMS error) points first reaches an RMS error of target, interpolated
    log-log between rungs (a rung's own time if the first one is there already); None if it never does."""
    pts = sorted(points)
    if not pts:
        return None
    if pts[0][1] <= target:
        return pts[0][0]
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e1 <= target < e0:
            f = math.log(target / e0) / math.log(e1 / e0)
            return math.exp(math.log(t0) + f * math.log(t1 / t0))
        if e1 <= target:
            return t1
    return None


def soonest(rungs, target):
    """(time, name) of the ladder that first reaches an RMS error of target (see time_to), of rungs given as
    (ladder name, time, RMS error); None if none does."""
    ladders = {}
    for name, t, e in rungs:
        ladders.setdefault(name, []).append((t, e))
    times = [(t, name) for name, pts in ladders.items() for t in [time_to(pts, target)] if t]
    return min(times) if times else None


def make_reference(rtrace, threads, path=REFERENCE, options=REF_OPTIONS):
    cmd = [rtrace] + options + ["-n", str(threads), SCENE]
    print("bench: making the reference (%d runs of: %s < grid.txt); this is done once and cached in %s"
          % (REF_RUNS, " ".join(["rtrace"] + cmd[1:-1] + ["office.rad"]), os.path.relpath(path, ROOT)))
    runs, total, commit = [], 0.0, git_commit()
    for k in range(REF_RUNS):
        t = Timer(cmd, GRID)
        total += t.wall
        runs.append(read_rgb(t.out))
        print("  run %d/%d: %.0f s" % (k + 1, REF_RUNS, t.wall), flush=True)
    pts = [l.split() for l in open(GRID) if l.split()]
    n = len(pts)
    os.makedirs(RESULTS, exist_ok=True)
    lx, se = [], []
    with open(path, "w") as f:
        f.write("# Brume bench reference: converged irradiance at the sensors of examples/office/grid.txt\n")
        f.write("# made by bench/bench.py (make bench, or --remake-reference): the mean of independent runs of\n")
        f.write("# command: rtrace %s -n %d examples/office/office.rad < examples/office/grid.txt\n"
                % (" ".join(options), threads))
        f.write("# runs: %d\n" % REF_RUNS)
        f.write("# wall time: %.0f s\n" % total)
        f.write("# brume commit: %s (the source tree's HEAD when the reference was made)\n" % commit)
        f.write("# rtrace binary: %s, built %s\n"
                % (rtrace, time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(os.path.getmtime(rtrace)))))
        f.write("# date: %s\n" % time.strftime("%Y-%m-%d %H:%M:%S"))
        f.write("# scene sha256: %s\n" % sha256(SCENE))
        f.write("# grid sha256: %s\n" % sha256(GRID))
        f.write("# columns: x y z R G B (mean irradiance, W/m2), illuminance (lux), "
                "standard error of the mean illuminance (%)\n")
        for i in range(n):
            rgb = [statistics.fmean(r[i][c] for r in runs) for c in range(3)]
            vals = [lux(r[i]) for r in runs]
            m = statistics.fmean(vals)
            s = statistics.stdev(vals) / math.sqrt(len(vals)) / m if m > 0 else 0.0
            lx.append(m)
            se.append(s)
            f.write("%s %s %s %.6e %.6e %.6e %.3f %.3f\n" % (pts[i][0], pts[i][1], pts[i][2], *rgb, m, 100 * s))
    return lx, se, {"runs": str(REF_RUNS), "command": "rtrace " + " ".join(options)}


# ---------------------------------------------------------------- measurements

def errors(values, ref):
    rel = [(lux(v) - r) / r for v, r in zip(values, ref)]
    if len(rel) != len(ref):
        sys.exit("bench: expected %d values, got %d" % (len(ref), len(rel)))
    rms = math.sqrt(sum(e * e for e in rel) / len(rel))
    return 100 * rms, 100 * max(abs(e) for e in rel), statistics.fmean(lux(v) for v in values)


def view_rays(path, n, seed=1):
    """n rays from VIEWPOINT, directions uniform over the sphere (fixed seed: the same rays every run)."""
    rng = random.Random(seed)
    with open(path, "w") as f:
        for _ in range(n):
            z = 2 * rng.random() - 1
            phi = 2 * math.pi * rng.random()
            s = math.sqrt(max(0.0, 1 - z * z))
            f.write("%g %g %g %.7f %.7f %.7f\n" % (*VIEWPOINT, s * math.cos(phi), s * math.sin(phi), z))


def fmt_rate(n, t):
    r = n / t
    return "%.0fk/s" % (r / 1e3) if r >= 1e4 else "%.0f/s" % r


def throughput(brume, rad, tmp, repeat, threads):
    views = os.path.join(tmp, "view100k.txt")
    view_rays(views, 100000)
    views10 = os.path.join(tmp, "view10k.txt")
    view_rays(views10, 10000, seed=2)
    ngrid = sum(1 for l in open(GRID) if l.split())
    tests = [
        ("view rays, -ab 0", views, 100000, ["-h", "-ab", "0"]),
        ("view rays, -ab 1 -aa 0 -ad 64 -as 32", views10, 10000, ["-h", "-ab", "1", "-aa", "0", "-ad", "64", "-as", "32"]),
        ("sensor grid -I -ab 5 -aa 0 -ad 512 -as 256", GRID, ngrid,
         ["-h", "-I", "-ab", "5", "-aa", "0", "-ad", "512", "-as", "256", "-lw", "1e-5"]),
    ]
    print("\n== Rays per second: the same rays, the same options (best of %d runs; wall time, CPU time in "
          "brackets) ==" % repeat)
    hdr = "%-44s %7s  %-22s %-22s %-22s %9s %8s" % ("test", "rays", "Brume -n 1", "Radiance -n 1",
                                                     "Brume -n %d" % threads, "Brume/Rad", "-n %d/-n 1" % threads)
    print(hdr)
    print("-" * len(hdr))
    rows = []
    for name, inp, n, opts in tests:
        b1 = best_of(repeat, [brume] + opts + ["-n", "1", SCENE], inp)
        bn = best_of(repeat, [brume] + opts + ["-n", str(threads), SCENE], inp)
        r1 = best_of(repeat, [rad["rtrace"]] + opts + ["-n", "1", rad["oct"]], inp, rad["env"]) if rad else None
        cell = lambda t: "%6.2f s (%5.2f) %7s" % (t[0], t[1], fmt_rate(n, t[0]))
        ratio = "%8.2fx" % (r1[0] / b1[0]) if r1 else "%9s" % "-"
        print("%-44s %7d  %-22s %-22s %-22s %s %7.2fx" % (name, n, cell(b1), cell(r1) if r1 else "skipped",
                                                           cell(bn), ratio, b1[0] / bn[0]))
        rows.append((name, n, b1, r1, bn))
    print("Brume/Rad: how many times faster Brume -n 1 is than Radiance -n 1 (wall time) on the same rays.")
    print("-n %d/-n 1: Brume's speed-up; if its CPU time is not about %d times its wall time, other processes "
          "held the other cores." % (threads, threads))
    if not rad:
        print("Radiance not found, skipped (set RADIANCE_BIN to the directory holding its rtrace and oconv).")
    return rows


UTM = (512345.6, 5412345.7, 120.0)  # a site's UTM coordinates (m), where BIM and GIS tools put models


def moved_rays(src, dst, offset):
    """The rays of src with their origins moved by offset, every digit kept."""
    with open(src) as fin, open(dst, "w") as fout:
        for line in fin:
            w = line.split()
            if len(w) == 6:
                fout.write("%.10f %.10f %.10f %s %s %s\n" % (float(w[0]) + offset[0], float(w[1]) + offset[1],
                                                           float(w[2]) + offset[2], w[3], w[4], w[5]))


def site_coordinates(brume, tmp, repeat, ref):
    """The office at a site's UTM coordinates against itself at the origin: the same rays moved, one thread,
    in one run; and the sensors' error against the reference there."""
    scene = os.path.join(tmp, "office_utm.rad")
    with open(scene, "w") as f:
        f.write("!xform -t %.17g %.17g %.17g %s\n" % (*UTM, SCENE))
    env = dict(os.environ, PATH=os.path.dirname(brume) + os.pathsep + os.environ.get("PATH", ""))
    views = os.path.join(tmp, "view100k.txt")
    if not os.path.exists(views):
        view_rays(views, 100000)
    cases = [("view rays, -ab 0", views, ["-h", "-ab", "0"]),
             ("sensor grid -I -ab 5 -aa 0 -ad 512", GRID, ["-h", "-I", "-ab", "5", "-aa", "0", "-ad", "512", "-lw", "1e-5"]),
             ("sensor grid -I -ab 5 (defaults)", GRID, ["-h", "-I", "-ab", "5"])]
    print("\n== Site coordinates: the office moved to UTM (%.1f, %.1f, %.1f) against itself at the origin, "
          "-n 1 (best of %d) ==" % (*UTM, repeat))
    hdr = "%-40s %10s %10s %8s %13s %13s" % ("test", "origin s", "UTM s", "UTM/orig", "RMS % origin", "RMS % UTM")
    print(hdr)
    print("-" * len(hdr))
    for name, inp, opts in cases:
        moved = os.path.join(tmp, "utm_" + os.path.basename(inp))
        moved_rays(inp, moved, UTM)
        t0 = best_of(repeat, [brume] + opts + ["-n", "1", SCENE], inp, env)
        t1 = best_of(repeat, [brume] + opts + ["-n", "1", scene], moved, env)
        errs = ["%13s" % "-", "%13s" % "-"]
        if inp == GRID and ref:
            errs = ["%13.2f" % errors(read_rgb(Timer([brume] + opts + ["-n", "1", s], i, env).out), ref)[0]
                    for s, i in ((SCENE, GRID), (scene, moved))]
        print("%-40s %10.2f %10.2f %7.3fx %s %s" % (name, t0[0], t1[0], t1[0] / t0[0], errs[0], errs[1]), flush=True)
    print("UTM/orig: wall time at the site over the time at the origin; RMS: the sensors' illuminance against the "
          "reference (at the site, the same sensors moved).")


def ladders(brume, rad, ref):
    series = []  # (label, [(settings, wall, cpu, rms, max, mean)])

    def rung(cmd, env=None):
        t = Timer(cmd, GRID, env)
        rms, mx, mean = errors(read_rgb(t.out), ref)
        return t.wall, t.cpu, rms, mx, mean

    print("\n== Time against error: -ab 5 on the office grid (%d sensors) versus the reference, one thread ==" %
          len(ref))
    hdr = "%-12s %-40s %8s %8s %7s %7s %7s" % ("program", "settings", "wall s", "cpu s", "RMS %", "max %", "mean lx")
    print(hdr)
    print("-" * len(hdr))

    def report(prog, label, rows):
        series.append((label, rows))
        for s, w, c, rms, mx, mean in rows:
            print("%-12s %-40s %8.2f %8.2f %7.2f %7.2f %7.1f" % (prog, s, w, c, rms, mx, mean), flush=True)

    # -ds .05 costs about six times -ds .2 per path: its ladder stops at -ad 1024.
    for label, extra, ads in (("Brume path tracing (-ds .2)", [], AD_LADDER),
                              ("Brume path tracing -ds .05", ["-ds", ".05"], AD_LADDER[:5])):
        rows = []
        for ad in ads:
            o = ["-aa", "0", "-ad", str(ad)] + extra
            rows.append((" ".join(o),) + rung([brume] + LADDER_COMMON + o + ["-n", "1", SCENE]))
        report("Brume", label, rows)
    if rad:
        rows = []
        for ad in AD_LADDER:
            o = ["-aa", "0", "-ad", str(ad), "-as", str(ad // 2)]
            rows.append((" ".join(o),) + rung([rad["rtrace"]] + LADDER_COMMON + o + ["-n", "1", rad["oct"]], rad["env"]))
        report("Radiance", "Radiance path tracing (-aa 0)", rows)
        rows = []
        for aa, ar, ad, as_ in RADIANCE_CACHE_LADDER:
            o = ["-aa", aa, "-ar", ar, "-ad", ad, "-as", as_]
            rows.append((" ".join(o),) + rung([rad["rtrace"]] + LADDER_COMMON + o + ["-n", "1", rad["oct"]], rad["env"]))
        report("Radiance", "Radiance irradiance cache", rows)
    else:
        print("Radiance not found, skipped")
    print("common options: %s; RMS and max: relative error of each sensor's illuminance." % " ".join(LADDER_COMMON))
    return series


def write_series(series, path):
    with open(path, "w") as f:
        f.write("# series\tsettings\twall_s\tcpu_s\trms_pct\tmax_pct\tmean_lux\n")
        for label, rows in series:
            for s, w, c, rms, mx, mean in rows:
                f.write("%s\t%s\t%.4f\t%.4f\t%.4f\t%.4f\t%.2f\n" % (label, s, w, c, rms, mx, mean))


def pythons_with(modules):
    """The Pythons (this one, python3 on PATH, /usr/bin/python3) that can import all of modules."""
    found = []
    for py in [sys.executable, "python3", "/usr/bin/python3"]:
        exe = shutil.which(py) if not os.path.isabs(py) else py
        if not exe or os.path.realpath(exe) in [os.path.realpath(f) for f in found]:
            continue
        if subprocess.run([exe, "-c", "import " + ", ".join(modules)], capture_output=True).returncode == 0:
            found.append(exe)
    return found


def matplotlib_plot(script, data, png):
    """Runs `script` in a Python that has matplotlib, with pyplot as plt, the JSON-able `data` as d and the PNG's
    path as sys.argv[2]; False if no Python has matplotlib."""
    for exe in pythons_with(["matplotlib"]):
        preamble = ("import sys, json\nimport matplotlib\nmatplotlib.use('Agg')\nimport matplotlib.pyplot as plt\n"
                    "d = json.loads(sys.argv[1])\n")
        subprocess.run([exe, "-c", preamble + script, json.dumps(data), png], check=True)
        return True
    return False


def ladders_plot(series, png, title, case_separator, solid):
    """Time against error on log-log axes of ladders {name: [(CPU s, RMS error)]}: one colour per case (the name
    before its last case_separator), solid lines with circles for ladders whose name holds `solid`, dashed with
    squares for the others. False if no Python has matplotlib."""
    script = (
        "sep, solid, title = d['sep'], d['solid'], d['title']\n"
        "fig, ax = plt.subplots(figsize=(7, 4.5))\n"
        "cases = list(dict.fromkeys(n.rsplit(sep, 1)[0] for n in d['series']))\n"
        "for name, pts in d['series'].items():\n"
        "    colour = 'C%d' % (cases.index(name.rsplit(sep, 1)[0]) % 10)\n"
        "    ax.loglog([p[0] for p in pts], [100 * p[1] for p in pts], 'o-' if solid in name else 's--',\n"
        "              color=colour, label=name)\n"
        "ax.set_xlabel('CPU time (s)'); ax.set_ylabel('normalised RMS error (%)')\n"
        "ax.set_title(title)\n"
        "ax.legend(fontsize=7); ax.grid(alpha=.3, which='both')\n"
        "fig.tight_layout(); fig.savefig(sys.argv[2], dpi=110)\n")
    return matplotlib_plot(script, {"series": series, "sep": case_separator, "solid": solid, "title": title}, png)


def write_result(text, name, plotted, png_name):
    """Prints `text`, writes it to results/<name>, and says on stderr when the plot could not be drawn."""
    print(text)
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, name), "w") as f:
        f.write(text)
    if not plotted:
        print(f"no matplotlib: no {png_name}", file=sys.stderr)


def plot(tsv, png, ref_noise):
    """bench/plot.py with a Python that has matplotlib, else gnuplot, else nothing."""
    for exe in pythons_with(["matplotlib"]):
        r = subprocess.run([exe, os.path.join(HERE, "plot.py"), tsv, png, "%.4f" % ref_noise])
        if r.returncode == 0:
            return "matplotlib"
    if shutil.which("gnuplot"):
        r = subprocess.run(["bash", os.path.join(HERE, "plot.gnuplot.sh"), tsv, png])
        if r.returncode == 0:
            return "gnuplot"
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"), help="directory holding Brume's rtrace")
    ap.add_argument("--repeat", type=int, default=3, help="runs per throughput measurement (the best is kept)")
    ap.add_argument("--threads", type=int, default=2, help="the multi-threaded Brume column's -n")
    ap.add_argument("--remake-reference", action="store_true", help="recompute bench/results/reference.txt")
    ap.add_argument("--skip-throughput", action="store_true")
    ap.add_argument("--skip-ladders", action="store_true")
    ap.add_argument("--skip-site", action="store_true", help="leave out the office at UTM coordinates")
    a = ap.parse_args()

    start = time.perf_counter()
    brume = os.path.abspath(os.path.join(a.bin, "rtrace"))
    if not os.access(brume, os.X_OK):
        sys.exit("bench: no Brume rtrace at %s (run make first)" % brume)
    print("Brume:    %s (commit %s)" % (brume, git_commit()))
    print("machine:  %d CPUs, load average %.2f at start (other load disturbs the timings)"
          % (os.cpu_count(), os.getloadavg()[0]))
    rad = find_radiance()
    with tempfile.TemporaryDirectory(prefix="brume-bench-") as tmp:
        if rad:
            rad["oct"] = frozen_octree(rad, tmp)
            print("Radiance: %s (octree made with its oconv -f in %s)" % (rad["dir"], tmp))
        else:
            print("Radiance not found, skipped (looked in $RADIANCE_BIN, then /tmp/radiance/bin)")
        if not a.skip_throughput:
            throughput(brume, rad, tmp, a.repeat, a.threads)
        if not a.skip_ladders:
            refd = None if a.remake_reference else load_reference()
            if refd is None:
                refd = make_reference(brume, os.cpu_count() or 1)
            ref, se, meta = refd
            ref_noise = 100 * math.sqrt(sum(s * s for s in se) / len(se))
            print("\nreference: %s, the mean of %s runs of %s;\n           its own standard error: RMS %.2f %%, "
                  "max %.2f %%; mean illuminance %.1f lx" % (os.path.relpath(REFERENCE, ROOT), meta.get("runs", "?"),
                                                             meta.get("command", "?").split(" -n ")[0], ref_noise,
                                                             100 * max(se), statistics.fmean(ref)))
            series = ladders(brume, rad, ref)
            if not a.skip_site:
                site_coordinates(brume, tmp, a.repeat, ref)
            os.makedirs(RESULTS, exist_ok=True)
            tsv = os.path.join(RESULTS, "time_vs_error.tsv")
            png = os.path.join(RESULTS, "time_vs_error.png")
            write_series(series, tsv)
            how = plot(tsv, png, ref_noise)
            print("\ntable: %s" % os.path.relpath(tsv, ROOT))
            print("plot:  %s" % (os.path.relpath(png, ROOT) + " (" + how + ")" if how else
                                 "not drawn (neither matplotlib nor gnuplot found)"))
    print("\nbench total: %.0f s" % (time.perf_counter() - start))


if __name__ == "__main__":
    main()
