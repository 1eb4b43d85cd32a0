#!/usr/bin/env python3
"""Brume's headline benchmark: run time against error at -ab 5, irradiance caches against path tracing.

Two parts on examples/office, each a set of ladders (families of settings, coarse to fine) timed on one thread and
compared with a converged Brume reference with every bounce: the 96-sensor grid with rtrace -I (reference
bench/results/reference_all_bounces.txt, made by bench.py's make_reference) and a picture of the seated view with rpict (reference made once and cached, see rpict.py). Families:
Brume's defaults, Brume path tracing (-aa 0), Brume's adaptive cache (-aa > 0), Brume's classic cache
(-acache classic), Radiance's cache and Radiance's path tracing. Radiance's runs are cached in
bench/results/cache_radiance.json (by command, scene and machine), so that a rerun times only Brume.

    python3 bench/cache.py --bin build/bin [--quick] [--parts grid,image] [--families ...] [--rerun-radiance]

See bench/README.md, "Irradiance cache: time against error". Needs numpy and matplotlib: like rpict.py, it reruns
itself with a Python that has them.
"""
import argparse
import hashlib
import json
import math
import os
import re
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ beside the bench
sys.path.insert(0, HERE)
import bench  # noqa: E402  (timing, Radiance, the grid and its reference)
import rpict  # noqa: E402  (pictures, their reference and errors; reruns this script in a Python with numpy)
import numpy as np  # noqa: E402

TABLE = os.path.join(bench.RESULTS, "cache.md")
PLOT = os.path.join(bench.RESULTS, "cache_time_vs_error.png")
RADIANCE_RUNS = os.path.join(bench.RESULTS, "cache_radiance.json")  # Radiance's timings and grid values (committed)
RADIANCE_PICTURES = os.path.join(bench.RESULTS, "cache_radiance")  # their pictures' luminance (git-ignored)

GRID_COMMON = ["-I", "-h"]
VIEW = "seated"
IMAGE_COMMON = ["-x", "240", "-y", "240", "-pj", "0"]  # 240 x 163 pixels; pixel centres, as in rpict.py
# References: the true answer, every bounce (path tracing ended by Russian roulette; -ab 50 is never reached).
# Brume's cache lands there too (past -ab its paths go on by roulette); Radiance's -ab 5 stops near five bounces,
# which counts as its error (about 0.8 % of the grid's light).
GRID_REFERENCE = os.path.join(bench.RESULTS, "reference_all_bounces.txt")
GRID_REFERENCE_OPTIONS = ["-I", "-h", "-ab", "50", "-aa", "0", "-ad", "8192", "-as", "0", "-ds", ".05", "-lw", "1e-6"]
IMAGE_REFERENCE = ["-ab", "50", "-aa", "0", "-ad", "200", "-as", "0", "-ps", "1", "-ds", ".05", "-lw", "1e-5"]
TARGET_RMS = 2.0  # the goal on the grid, in %

# Path tracing: -ad paths at the first bounce, one path after; Brume's with every bounce (unbiased), Radiance's
# with five (its -lr -10 would cap more anyway).
PT = ["-ab", "50", "-aa", "0", "-lw", "1e-5"]
RADIANCE_PT = ["-ab", "5", "-aa", "0", "-lw", "1e-5"]
AA_LADDER = [(".3", "256"), (".2", "512"), (".15", "512"), (".1", "1024"), (".07", "1024"), (".05", "2048")]
# Radiance's cache, coarse to fine, from the values (-ab 2/3/6, -ad 512/2048/4096, -as 128/2048/4096,
# -ar 16/64/128, -aa .25/.2/.1); "-ab 5" alone is the program's defaults (rtrace: -aa .1 -ar 256 -ad 1024 -as 512,
# rpict: -aa .2 -ar 64 -ad 512 -as 128). No -af: every run starts without an ambient file.
RADIANCE_CACHE = [
    ["-ab", "2", "-aa", ".25", "-ar", "16", "-ad", "512", "-as", "128"],
    ["-ab", "3", "-aa", ".2", "-ar", "64", "-ad", "512", "-as", "128"],
    ["-ab", "5"],
    ["-ab", "5", "-aa", ".2", "-ar", "64", "-ad", "2048", "-as", "2048"],
    ["-ab", "6", "-aa", ".1", "-ar", "128", "-ad", "2048", "-as", "2048"],
    ["-ab", "6", "-aa", ".1", "-ar", "128", "-ad", "4096", "-as", "4096"],
]
PT_AD = {"grid": {"brume": [64, 256, 1024, 4096], "radiance": [64, 256, 1024, 4096]},
         "image": {"brume": [4, 16, 64, 256], "radiance": [4, 16, 64]}}
FAMILIES = ["brume-default", "brume-pt", "brume-adaptive", "brume-classic", "radiance-cache", "radiance-pt"]


def families(part):
    """(name, label, program, [options of each rung]) of a part. Pictures trace every pixel (-ps 1), as the
    reference: with -ps 4 a luminaire seen as a thin sliver at the picture's border is drawn by its coverage of
    each pixel (small sources), the reference samples pixel centres, and the few pixels beside it (twenty times
    the ceiling's luminance) would swamp what is measured here."""
    ps1 = ["-ps", "1"] if part == "image" else []
    ads = PT_AD[part]
    radiance_cache = RADIANCE_CACHE if part == "grid" else RADIANCE_CACHE[:4]  # the -ab 6 rungs: 40 min at -ps 1
    return [
        ("brume-default", "Brume defaults", "brume", [["-ab", "5"] + ps1]),
        ("brume-pt", "Brume path tracing", "brume", [PT + ps1 + ["-ad", str(a)] for a in ads["brume"]]),
        ("brume-adaptive", "Brume adaptive cache", "brume",
         [["-ab", "5", "-aa", aa, "-ad", ad] + ps1 for aa, ad in AA_LADDER]),
        ("brume-classic", "Brume classic cache", "brume",
         [["-ab", "5", "-acache", "classic", "-aa", aa, "-ad", ad] + ps1 for aa, ad in AA_LADDER]),
        ("radiance-cache", "Radiance cache", "radiance", [r + ps1 for r in radiance_cache]),
        ("radiance-pt", "Radiance path tracing", "radiance",
         [RADIANCE_PT + ps1 + ["-ad", str(a), "-as", str(a // 2)] for a in ads["radiance"]]),
    ]


def megabytes(mb):
    return "–" if mb is None else "%.0f" % mb


def records(err):
    """The number of cache records a run reports on stderr (a line "records: N"), else None."""
    m = re.search(r"^\s*records:\s*(\d+)", err, re.M)
    return int(m.group(1)) if m else None


# ---------------------------------------------------------------- the two parts

class Part:
    """What differs between the grid and the picture: the programs, the input, the reference and the errors."""

    def __init__(self, name, progs, tmp):
        self.name, self.progs, self.tmp = name, progs, tmp

    def command(self, prog, opts):
        exe, scene, _ = self.progs[prog]
        n = ["-n", "1"] if prog == "brume" else []  # Radiance's rpict has no -n; one thread both ways
        if self.name == "grid":
            # Brume's sensors take the cache's records only with -aS 0 (else they share bounces, rtrace(1)):
            # this bench is the cache's.
            return [exe] + GRID_COMMON + opts + n + (["-aS", "0"] if prog == "brume" else []) + [scene]
        return [exe] + rpict.VIEWS[VIEW][1] + IMAGE_COMMON + opts + n + [scene]

    def run(self, prog, opts, check=True):
        """One timed run: (Timer, output: the grid's RGB rows or the picture's luminance)."""
        env = self.progs[prog][2]
        cmd = self.command(prog, opts)
        if self.name == "grid":
            t = bench.Timer(cmd, bench.GRID, env, check=check)
            return t, (bench.read_rgb(t.out) if t.returncode == 0 else None)
        out = os.path.join(self.tmp, "picture.hdr")
        t = bench.Timer(cmd, os.devnull, env, out_path=out, check=check)
        return t, (rpict.luminance(rpict.read_picture(out)) if t.returncode == 0 else None)

    def errors(self, output, ref):
        """RMS and 99.9th percentile of the relative error, in % (with the grid's 96 sensors the latter is the max)."""
        if self.name == "grid":
            rms, mx, _ = bench.errors(output, ref)
            return rms, mx
        rms, p999, _ = rpict.errors(np.asarray(output), ref, 99.9)
        return rms, p999


def grid_reference(brume_rtrace, remake):
    refd = None if remake else bench.load_reference(GRID_REFERENCE, GRID_REFERENCE_OPTIONS)
    if refd is None:
        refd = bench.make_reference(brume_rtrace, os.cpu_count() or 1, GRID_REFERENCE, GRID_REFERENCE_OPTIONS)
    ref, se, meta = refd
    noise = 100 * math.sqrt(sum(s * s for s in se) / len(se))
    return ref, noise, "%s (%s, mean of %s runs; own error RMS %.2f %%)" % (
        os.path.relpath(GRID_REFERENCE, bench.ROOT), meta.get("command", "?").split(" -n ")[0], meta.get("runs"), noise)


def image_reference(brume_rpict, tmp, remake):
    # nice: the reference takes 10-20 minutes on two cores and should yield to anything else
    rgb, se, meta = rpict.converged(brume_rpict, "%s_all_bounces" % VIEW, VIEW, IMAGE_COMMON, IMAGE_REFERENCE, tmp,
                                    remake, prefix=("nice", "-n", "19"))
    noise = rpict.own_error(rgb, se)
    return rgb, noise, "%s, mean of %d runs, %s s, Brume %s, %s; own error RMS %.2f %% (spread), %.2f %% (halves)" % (
        meta["command"].replace(" examples/office/office.rad", ""), meta["runs"], meta["wall_s"], meta["brume_commit"],
        meta["date"], noise, meta["split_half_rms_pct"])


# ---------------------------------------------------------------- Radiance's cached runs

class RadianceRuns:
    """Radiance's runs by command, scene and machine: timings, peak memory and output (the grid's values in the
    JSON file, a picture's luminance in RADIANCE_PICTURES), so that errors follow the current reference."""

    def __init__(self, rerun):
        self.rerun = rerun
        self.runs = json.load(open(RADIANCE_RUNS)) if os.path.exists(RADIANCE_RUNS) else {}
        self.scene, self.machine = bench.sha256(bench.SCENE), bench.machine()

    def key(self, part, cmd):
        shown = [os.path.basename(c) if c.endswith((".oct", "/rtrace", "/rpict")) else c for c in cmd]
        return " | ".join([part, " ".join(shown), self.scene[:16], self.machine])

    def get(self, part, cmd):
        e = None if self.rerun else self.runs.get(self.key(part, cmd))
        if e is None:
            return None
        if part == "grid":
            return e, e["output"]
        pic = os.path.join(RADIANCE_PICTURES, e["picture"])
        return (e, np.load(pic)["lum"]) if os.path.exists(pic) else None

    def put(self, part, cmd, t, output):
        key = self.key(part, cmd)
        e = {"date": time.strftime("%Y-%m-%d %H:%M:%S"), "wall_s": round(t.wall, 3), "cpu_s": round(t.cpu, 3),
             "max_rss_mb": None if t.max_rss_mb is None else round(t.max_rss_mb, 1), "records": records(t.err),
             "load_average": round(os.getloadavg()[0], 2)}
        if part == "grid":
            e["output"] = [[float("%.5g" % v) for v in row] for row in output]
        else:
            e["picture"] = hashlib.sha256(key.encode()).hexdigest()[:16] + ".npz"
            os.makedirs(RADIANCE_PICTURES, exist_ok=True)
            np.savez_compressed(os.path.join(RADIANCE_PICTURES, e["picture"]), lum=np.asarray(output, np.float32))
        self.runs[key] = e
        os.makedirs(bench.RESULTS, exist_ok=True)
        with open(RADIANCE_RUNS + ".tmp", "w") as f:  # one run a line
            f.write("{\n%s\n}\n" % ",\n".join("%s: %s" % (json.dumps(k), json.dumps(v, sort_keys=True))
                                                 for k, v in sorted(self.runs.items())))
        os.replace(RADIANCE_RUNS + ".tmp", RADIANCE_RUNS)


# ---------------------------------------------------------------- measuring

ROW = "  %-22s %-58s %8s %8s %7s %8s %8s %8s  %s"


def measure(part, chosen, ref, radiance_runs, quick, no_new_radiance):
    """Runs the chosen families of a part: rows (family, label, settings, wall, cpu, rms, p999, records, MB, source),
    and notes on what was not run."""
    print(ROW % ("family", "settings", "wall s", "CPU s", "RMS %", "p99.9 %", "records", "peak MB", "measured"))
    rows, notes = [], []
    for name, label, prog, rungs in families(part.name):
        if name not in chosen and "%s:%s" % (part.name, name) not in chosen:
            continue
        if prog not in part.progs:
            notes.append("%s: Radiance not found, skipped" % label)
            print("  " + notes[-1])
            continue
        for opts in (rungs[:2] if quick else rungs):
            cmd = part.command(prog, opts)
            cached = radiance_runs.get(part.name, cmd) if prog == "radiance" else None
            if prog == "radiance" and not cached and no_new_radiance:
                notes.append("%s `%s`: not in %s, skipped (--no-new-radiance)" % (
                    label, " ".join(opts), os.path.basename(RADIANCE_RUNS)))
                print("  " + notes[-1])
                continue
            if cached:
                e, output = cached
                wall, cpu, rec, mb, source = e["wall_s"], e["cpu_s"], e["records"], e["max_rss_mb"], "cached " + e["date"]
            else:
                t, output = part.run(prog, opts, check=name != "brume-classic")
                if t.returncode != 0:  # only the classic cache may be refused: it does not exist yet
                    notes.append("%s: not available (%s)" % (
                        label, (t.err.strip().splitlines() or ["exit %d" % t.returncode])[-1]))
                    print("  " + notes[-1])
                    break
                wall, cpu, rec, mb, source = t.wall, t.cpu, records(t.err), t.max_rss_mb, "now"
                if prog == "radiance":
                    radiance_runs.put(part.name, cmd, t, output)
            rms, p999 = part.errors(output, ref)
            row = (name, label, " ".join(opts), wall, cpu, rms, p999, rec, mb, source)
            rows.append(row)
            print(ROW % (label, row[2], "%.2f" % wall, "%.2f" % cpu, "%.2f" % rms, "%.1f" % p999,
                         "–" if rec is None else rec, megabytes(mb), source), flush=True)
    return rows, notes


CLOCK = 3  # the time compared and plotted: the rows' wall time (3), or CPU time (4) with --clock cpu


def time_to(rows, target):
    return bench.time_to([(r[CLOCK], r[5]) for r in rows], target)


def by_family(rows):
    fam = {}
    for r in rows:
        fam.setdefault(r[0], []).append(r)
    return fam


def grid_goal(rows):
    """(a): Brume's defaults reaching TARGET_RMS on the grid against Radiance's best setting reaching it."""
    fam = by_family(rows)
    lines = ["(a) grid, time to %.0f %% RMS:" % TARGET_RMS]
    brume = None
    if "brume-default" in fam:
        r = fam["brume-default"][0]
        brume = r[CLOCK] if r[5] <= TARGET_RMS else None
        lines.append("    Brume `rtrace -I -ab 5` (defaults): %.2f s, RMS %.2f %%%s" % (
            r[CLOCK], r[5], "" if brume else ": does not reach %.0f %%" % TARGET_RMS))
    rad = [(time_to(fam[f], TARGET_RMS), f) for f in ("radiance-cache", "radiance-pt") if f in fam]
    reached = [x for x in rad if x[0] is not None]
    if reached:
        t, f = min(reached)
        lines.append("    Radiance's best (%s ladder, interpolated): %.2f s" % (f, t))
        if brume:
            lines.append("    ratio Radiance / Brume: %.2f (Brume's defaults are %.2fx faster)" % (t / brume, t / brume))
    elif rad:
        best = min((r for f in ("radiance-cache", "radiance-pt") for r in fam.get(f, [])), key=lambda r: r[5])
        lines.append("    Radiance never reaches %.0f %%: its best is %.2f %% RMS (`%s`, %.2f s)" % (
            TARGET_RMS, best[5], best[2], best[CLOCK]))
        if brume:
            lines.append("    Brume's defaults, %.2f s, against Radiance's best rung: %.2fx faster, at %.1fx less error"
                         % (brume, best[CLOCK] / brume, best[5] / fam["brume-default"][0][5]))
    for f in ("brume-pt", "brume-adaptive", "brume-classic"):
        if f in fam:
            t = time_to(fam[f], TARGET_RMS)
            lines.append("    %s ladder: %s" % (f, "%.2f s (interpolated)" % t if t else "does not reach it"))
    return lines


def image_goal(rows):
    """(b): the adaptive cache against path tracing at equal error on the picture, rung by rung."""
    fam = by_family(rows)
    lines = ["(b) image, adaptive cache against path tracing at equal RMS error:"]
    if "brume-adaptive" not in fam or "brume-pt" not in fam:
        return lines + ["    not measured (needs the brume-adaptive and brume-pt families)"]
    for r in fam["brume-adaptive"]:
        t = time_to(fam["brume-pt"], r[5])
        lines.append("    `%s`: %.2f %% RMS in %.2f s; path tracing %s" % (
            r[2], r[5], r[CLOCK], "%.2f s: adaptive %.2fx faster" % (t, t / r[CLOCK]) if t else "does not reach it"))
    return lines


# ---------------------------------------------------------------- output

def loaded(rows):
    """A warning when other load stretched wall times (of one thread) well past CPU times."""
    n = sum(1 for r in rows if r[3] > 1.2 * r[4] + 0.05)
    return ["note: %d of %d runs took over 1.2x their CPU time in wall time (other load on the machine): compare "
            "CPU times (--clock cpu)" % (n, len(rows))] if n else []


def table(rows):
    lines = ["| family | setting | wall s | CPU s | RMS % | p99.9 % | records | peak MB | measured |",
             "|---|---|---:|---:|---:|---:|---:|---:|---|"]
    for name, label, settings, wall, cpu, rms, p999, rec, mb, source in rows:
        lines.append("| %s | `%s` | %.2f | %.2f | %.2f | %.1f | %s | %s | %s |" % (
            label, settings, wall, cpu, rms, p999, "–" if rec is None else rec, megabytes(mb), source))
    return lines


def plot(results, noise, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    parts = list(results)
    fig, axes = plt.subplots(2, len(parts), figsize=(6.5 * len(parts), 9.5), squeeze=False)
    markers = dict(zip(FAMILIES, "*osDv^"))
    colours = dict(zip(FAMILIES, ["C%d" % k for k in range(len(FAMILIES))]))  # the same in every panel
    for c, part in enumerate(parts):
        for r, (col, what) in enumerate(((5, "RMS"), (6, "99.9th percentile"))):
            ax = axes[r][c]
            for name, rows in by_family(results[part]).items():
                style = "-" if name.startswith("brume") else "--"
                ax.loglog([x[CLOCK] for x in rows], [x[col] for x in rows], style, marker=markers[name], ms=5,
                          color=colours[name], label=rows[0][1])
            if r == 0:
                ax.axhline(noise[part], color="grey", lw=0.8, ls=":", label="reference's own error")
            if part == "grid" and r == 0:
                ax.axhline(TARGET_RMS, color="red", lw=0.6, ls="-.", label="goal: %.0f %%" % TARGET_RMS)
            ax.tick_params(which="minor", labelsize=6)
            rpict.label_axes(ax, "%s, -ab 5: %s relative error" % (
                "sensor grid (96 sensors, rtrace -I)" if part == "grid" else "picture (seated view, rpict 240 wide)",
                what), "%s time, one thread (s)" % ("wall" if CLOCK == 3 else "CPU"),
                "%s relative error (%%)" % what, 6.5)
    rpict.save_figure(fig, "examples/office: time against error versus a converged Brume reference\n"
                      "(Brume solid, Radiance 6.1 dashed)", path, 100)


# ---------------------------------------------------------------- main

def programs(brume_bin, rad, part, tmp):
    exe = "rtrace" if part == "grid" else "rpict"
    progs = {"brume": (os.path.join(brume_bin, exe), bench.SCENE, None)}
    if rad and os.access(os.path.join(rad["dir"], exe), os.X_OK):
        progs["radiance"] = (os.path.join(rad["dir"], exe), rad["oct"], rad["env"])
    return progs


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(bench.ROOT, "build", "bin"), help="directory holding Brume's rtrace and rpict")
    ap.add_argument("--quick", action="store_true", help="the first two rungs of each ladder only (a smoke run)")
    ap.add_argument("--parts", default="grid,image", help="grid, image or both (default)")
    ap.add_argument("--families", default=",".join(FAMILIES),
                    help="families to run, each for both parts or for one (image:brume-pt); default all: %s"
                    % ",".join(FAMILIES))
    ap.add_argument("--rerun-radiance", action="store_true", help="time Radiance again rather than use %s"
                    % os.path.relpath(RADIANCE_RUNS, bench.ROOT))
    ap.add_argument("--no-new-radiance", action="store_true",
                    help="skip the Radiance rungs that are not cached rather than measure them")
    ap.add_argument("--clock", choices=("wall", "cpu"), default="wall",
                    help="the time the plot and the ratios use (cpu on a loaded machine)")
    ap.add_argument("--remake-reference", action="store_true", help="remake the picture's cached reference")
    a = ap.parse_args()
    global CLOCK
    CLOCK = 3 if a.clock == "wall" else 4
    parts = [p for p in a.parts.split(",") if p]
    chosen = [f for f in a.families.split(",") if f]
    bad = [p for p in parts if p not in ("grid", "image")] + \
        [f for f in chosen if f.split(":")[-1] not in FAMILIES or f.count(":") > 1 or
         f.count(":") == 1 and f.split(":")[0] not in ("grid", "image")]
    if bad:
        sys.exit("bench/cache.py: unknown part or family: %s" % ", ".join(bad))

    start = time.perf_counter()
    brume_bin = os.path.abspath(a.bin)
    # Brume's rtrace for its families on the grid, its rpict for the picture's reference and families
    needed = (["rtrace"] if "grid" in parts and any(f.split(":")[-1].startswith("brume") for f in chosen) else []) + \
        (["rpict"] if "image" in parts else [])
    for exe in needed:
        if not os.access(os.path.join(brume_bin, exe), os.X_OK):
            sys.exit("bench/cache.py: no Brume %s in %s (build first)" % (exe, brume_bin))
    header = ["Brume: %s (commit %s)" % (brume_bin, bench.git_commit()),
              "machine: %s, load average %.2f at start" % (bench.machine(), os.getloadavg()[0])]
    print("\n".join(header))
    rad = bench.find_radiance()
    results, noise, goals, md = {}, {}, [], ["# Irradiance cache: time against error (`bench/cache.py %s`)" %
                                             " ".join(sys.argv[1:]), ""]
    radiance_runs = RadianceRuns(a.rerun_radiance)
    with tempfile.TemporaryDirectory(prefix="brume-cache-") as tmp:
        if rad:
            rad["oct"] = bench.frozen_octree(rad, tmp)
            print("Radiance: %s (frozen octree; cached runs in %s)" % (rad["dir"], os.path.relpath(RADIANCE_RUNS, bench.ROOT)))
        else:
            print("Radiance not found, skipped (set RADIANCE_BIN to the directory holding its rtrace, rpict and oconv)")
        for name in parts:
            t0 = time.perf_counter()
            part = Part(name, programs(brume_bin, rad, name, tmp), tmp)
            if name == "grid":
                title = "grid: rtrace %s -ab 5 ... -n 1 < examples/office/grid.txt (96 sensors)" % " ".join(GRID_COMMON)
                ref, noise[name], ref_text = grid_reference(os.path.join(brume_bin, "rtrace"), a.remake_reference)
            else:
                title = "image: rpict %s %s -ab 5 ... (one thread)" % (" ".join(rpict.VIEWS[VIEW][1]), " ".join(IMAGE_COMMON))
                ref, noise[name], ref_text = image_reference(os.path.join(brume_bin, "rpict"), tmp, a.remake_reference)
            print("\n== %s ==\nreference: %s" % (title, ref_text))
            results[name], notes = measure(part, chosen, ref, radiance_runs, a.quick, a.no_new_radiance)
            goal = (grid_goal if name == "grid" else image_goal)(results[name]) + loaded(results[name])
            goals += goal
            print("\n".join(goal))
            print("%s part: %.0f s" % (name, time.perf_counter() - t0))
            md += ["## %s" % title, "", "Reference: %s." % ref_text, ""] + table(results[name]) + [""] + \
                  ["- " + n for n in notes] + [""] * bool(notes) + ["    " + g for g in goal] + [""]
    header.append("load average %.2f at the end; total %.0f s" % (os.getloadavg()[0], time.perf_counter() - start))
    md[2:2] = ["- " + h for h in header] + [
        "- wall and CPU (user + system) time of one run, one thread (`-n 1`); peak MB: its maximum resident set; "
        "records: from a `records: N` line on stderr; RMS and p99.9: relative error of sensor illuminance / pixel "
        "luminance (pixels brighter than %g of the reference's mean); measured: now, or the date of a cached "
        "Radiance run" % rpict.FLOOR, ""]
    os.makedirs(bench.RESULTS, exist_ok=True)
    with open(TABLE, "w") as f:
        f.write("\n".join(md))
    print("\ntable: %s" % os.path.relpath(TABLE, bench.ROOT))
    if results:
        plot(results, noise, PLOT)
        print("plot:  %s" % os.path.relpath(PLOT, bench.ROOT))
    print("cache bench total: %.0f s" % (time.perf_counter() - start))


if __name__ == "__main__":
    main()
