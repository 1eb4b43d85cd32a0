#!/usr/bin/env python3
"""Brume benchmark of -ab 0 pictures from 100 to 2000 pixels wide: wall time against error, Brume's rpict against
Radiance's, one thread each, start-up included (Brume reads the scene and builds its structures each run; Radiance
reads an octree made beforehand, whose making is not counted).

The reference at each width is a fixed random choice of the picture's own pixel centres (all of them up to 20,000),
each traced by Brume's rtrace at -ds .01 (the mean of REF_RUNS runs; its own error is stated),
so that a 2000-pixel picture is judged pixel for pixel without a converged 2000-pixel picture. Pictures are made
at -pj 0 (pixel centres), so the error is the shading's and the adaptive sampling's (-ps), not aliasing.

bench/run.sh runs it after rpict.py (--skip-rpict leaves both out). Needs numpy, and matplotlib for the plot.
"""
import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
import bench  # noqa: E402
import rpict  # noqa: E402  (reruns this script with a Python that has numpy; pictures, errors, timing, figures)
import numpy as np  # noqa: E402

RESULTS = bench.RESULTS
CACHE = os.path.join(RESULTS, "rpict_reference")  # git-ignored, as rpict.py's references
TABLE = os.path.join(RESULTS, "picture_widths.md")
PLOT = os.path.join(RESULTS, "picture_widths.png")

VIEW = "seated"
WIDTHS = [100, 320, 1000, 2000]
REF_OPTIONS = ["-ab", "0", "-ds", ".01"]
REF_RUNS = 4
REF_PIXELS = 20000  # pixels in each width's reference
TARGETS = (16, 12, 8, 5)  # % RMS at which times are compared
# (program, series, [options of each rung]); -pj 0 is added to all. -ps 4 is both programs' default; Radiance's
# -dj .7 at -ps 1 is its smoothest (least biased) direct light.
LADDERS = [("brume", "Brume -ps 4", [["-ps", "4", "-ds", d] for d in ("1", ".5", ".25", ".1")]),
           ("radiance", "Radiance -ps 4 -dj 0", [["-ps", "4", "-dj", "0", "-ds", d] for d in (".5", ".25", ".1", ".05")]),
           ("radiance", "Radiance -ps 1 -dj .7", [["-ps", "1", "-dj", ".7", "-ds", d] for d in (".25", ".1")])]


def size(width):
    """The options of a picture `width` pixels wide, its height fitted to the view."""
    return ["-x", str(width), "-y", str(width)]


def resolution(vwrays, width):
    """The picture's width and height, fitted to the view as rpict fits them (vwrays -d)."""
    out = subprocess.run([vwrays, "-d"] + rpict.VIEWS[VIEW][1] + size(width),
                         capture_output=True, text=True, check=True).stdout.split()
    return int(out[out.index("-x") + 1]), int(out[out.index("-y") + 1])


def pixels(w, h):
    """The reference's pixels: all, or a fixed random choice of REF_PIXELS (every residue of a first pass's grid is
    as likely as any other), as indices in scanline order, top row first."""
    if w * h <= REF_PIXELS:
        return np.arange(w * h)
    return np.sort(np.random.default_rng(w * 100003 + h).choice(w * h, REF_PIXELS, replace=False))


def reference(bindir, w, h, chosen, tmp, remake):
    """(mean RGB at the chosen pixels [n, 1, 3], its per-pixel standard error of luminance, metadata), cached."""
    name = os.path.join(CACHE, "widths_%s_%d" % (VIEW, w))
    key = hashlib.sha256(json.dumps([bench.sha256(bench.SCENE), rpict.VIEWS[VIEW][1], w, h, len(chosen), REF_OPTIONS,
                                     REF_RUNS]).encode()).hexdigest()[:16]
    cached = rpict.load_cached(name, key, remake)
    if cached:
        return cached[0]["rgb"], cached[0]["se"], cached[1]
    rays = subprocess.run([os.path.join(bindir, "vwrays"), "-ff", "-pj", "0"] + rpict.VIEWS[VIEW][1] + size(w),
                          capture_output=True, check=True).stdout
    rays = np.frombuffer(rays, np.float32).reshape(h * w, 6)[chosen]
    path = os.path.join(tmp, "rays.f")
    rays.tofile(path)
    cmd = [os.path.join(bindir, "rtrace"), "-ff", "-h"] + REF_OPTIONS + ["-u+", "-n", str(os.cpu_count() or 1),
                                                                          bench.SCENE]
    print("  making the reference at %d x %d: %d pixels, the mean of %d runs of rtrace %s" % (
        w, h, len(chosen), REF_RUNS, " ".join(cmd[1:-1])), flush=True)
    runs, wall = [], time.perf_counter()
    for _ in range(REF_RUNS):
        with open(path, "rb") as f:
            out = subprocess.run(cmd, stdin=f, capture_output=True, check=True).stdout
        runs.append(np.frombuffer(out, np.float32).reshape(len(chosen), 1, 3))
    runs = np.stack(runs)
    rgb = runs.mean(axis=0)
    se = rpict.luminance(runs).std(axis=0, ddof=1) / np.sqrt(REF_RUNS)
    meta = {"key": key, "command": "vwrays -ff -pj 0 | rtrace " + " ".join(cmd[1:-1]), "pixels": len(chosen),
            "runs": REF_RUNS, "wall_s": round(time.perf_counter() - wall, 1), "brume_commit": bench.git_commit()}
    rpict.save_cached(name, {"rgb": rgb, "se": se}, meta)
    return rgb, se, meta


def measure(progs, w, h, chosen, ref, tmp, repeat):
    rows = []
    out = os.path.join(tmp, "picture.hdr")
    for prog, label, rungs in LADDERS:
        if prog not in progs:
            continue
        exe, scene, env = progs[prog]
        for opts in rungs:
            cmd = [exe] + rpict.VIEWS[VIEW][1] + size(w) + ["-pj", "0"] + opts + (
                ["-n", "1"] if prog == "brume" else []) + [scene]
            picture, wall, cpu = rpict.timed_picture(cmd, env, out, repeat)
            if picture.shape[:2] != (h, w):
                sys.exit("bench/picture_widths.py: %s made %s pixels, not %d x %d" % (prog, picture.shape[:2], w, h))
            rms, p99, bias = rpict.errors(picture.reshape(h * w, 1, 3)[chosen], ref)
            rows.append((label, " ".join(opts), wall, cpu, rms, p99, bias))
            print("  %-24s %-28s %8.2f %8.2f %7.2f %7.1f %+7.2f" % (label, " ".join(opts), wall, cpu, rms, p99, bias),
                  flush=True)
    return rows


def soonest(rows, program, target):
    """The wall time to an RMS error of target along the soonest of a program's series, or None."""
    found = bench.soonest([(r[0], r[2], r[4]) for r in rows if r[0].startswith(program)], target)
    return found[0] if found else None


def write_table(results, header):
    lines = header + [""]
    for (w, h), (rows, meta, own) in results.items():
        lines += ["**%d x %d**; reference: %s at %d pixels, the mean of %d runs (its own error: RMS %.2f %%)" % (
                      w, h, meta["command"], meta["pixels"], meta["runs"], own), "",
                  "| series | settings | wall s | CPU s | RMS % | p99 % | bias % |", "|---|---|---:|---:|---:|---:|---:|"]
        lines += ["| %s | `%s` | %.2f | %.2f | %.2f | %.1f | %+.2f |" % r for r in rows]
        lines.append("")
    lines += ["Wall time to a given RMS error (s, interpolated log-log between the rungs of a series; the soonest "
              "series): Brume / Radiance, and in brackets Radiance's time over Brume's (above 1: Brume is sooner):", "", "| picture | " + " | ".join("%g %%" % t for t in TARGETS) + " |",
              "|---|" + "---:|" * len(TARGETS)]
    for (w, h), (rows, meta, own) in results.items():
        cells = []
        for target in TARGETS:
            b, r = (soonest(rows, who, target) for who in ("Brume", "Radiance"))
            cells.append("%s / %s%s" % ("%.2f" % b if b else "–", "%.2f" % r if r else "–",
                                        " (%.1f×)" % (r / b) if b and r else ""))
        lines.append("| %d × %d | %s |" % (w, h, " | ".join(cells)))
    with open(TABLE, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines[-len(results) - 4:]))


def plot(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(results), figsize=(3.6 * len(results), 3.8), squeeze=False)
    for ax, ((w, h), (rows, meta, own)) in zip(axes[0], results.items()):
        series = {}
        for label, settings, wall, cpu, rms, p99, bias in rows:
            series.setdefault(label, []).append((wall, rms))
        for label, pts in series.items():
            brume = label.startswith("Brume")
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "-" if brume else "--", marker="o" if brume else "s",
                      ms=4, label=label)
        ax.axhline(own, color="grey", lw=0.8, ls=":", label="reference's own error")
        rpict.label_axes(ax, "%d x %d" % (w, h), "wall time per picture, one thread (s)",
                         "RMS relative error of pixel luminance (%)", 5.5)
    rpict.save_figure(fig, "-ab 0 pictures of examples/office (seated view): time against error, start-up included "
                      "(Brume solid, Radiance 6.1 dashed)", PLOT, 110)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--bin", default=os.path.join(bench.ROOT, "build", "bin"), help="directory holding Brume's programs")
    ap.add_argument("--repeat", type=int, default=3, help="runs of pictures under 2 s (the fastest is kept)")
    ap.add_argument("--widths", default=",".join(map(str, WIDTHS)), help="picture widths (default %(default)s)")
    ap.add_argument("--remake-reference", action="store_true", help="recompute the cached references")
    a = ap.parse_args()
    start = time.perf_counter()
    bindir = os.path.abspath(a.bin)
    for prog in ("rpict", "rtrace", "vwrays"):
        if not os.access(os.path.join(bindir, prog), os.X_OK):
            sys.exit("bench/picture_widths.py: no Brume %s in %s (run make first)" % (prog, bindir))
    header = ["# -ab 0 pictures from 100 to 2000 pixels wide (`bench/picture_widths.py --bin build/bin`)", "",
              "- Brume: %s (commit %s); one thread each (Brume -n 1); wall time of the whole run, start-up included "
              "(Radiance's octree made beforehand, not counted)" % (bindir, bench.git_commit()),
              "- machine: %s, load average %.2f at start" % (bench.machine(), os.getloadavg()[0]),
              "- view: %s (%s), `-pj 0`; RMS and p99: relative error of pixel luminance over the reference's pixels "
              "brighter than %g of its mean" % (VIEW, " ".join(rpict.VIEWS[VIEW][1]), rpict.FLOOR)]
    for line in header[2:]:
        print(line)
    rad = bench.find_radiance()
    results = {}
    with tempfile.TemporaryDirectory(prefix="brume-widths-") as tmp:
        progs = {"brume": (os.path.join(bindir, "rpict"), bench.SCENE, None)}
        if rad and os.access(os.path.join(rad["dir"], "rpict"), os.X_OK):
            progs["radiance"] = (os.path.join(rad["dir"], "rpict"), bench.frozen_octree(rad, tmp), rad["env"])
        else:
            print("Radiance not found, skipped (set RADIANCE_BIN to the directory holding its rpict and oconv)")
        for width in [int(x) for x in a.widths.split(",")]:
            w, h = resolution(os.path.join(bindir, "vwrays"), width)
            print("\n== %d x %d ==" % (w, h))
            chosen = pixels(w, h)
            ref, se, meta = reference(bindir, w, h, chosen, tmp, a.remake_reference)
            own = rpict.own_error(ref, se)
            print("  reference: %s, %d pixels, %d runs; its own error: RMS %.2f %%" % (
                meta["command"], meta["pixels"], meta["runs"], own))
            results[(w, h)] = (measure(progs, w, h, chosen, ref, tmp, a.repeat), meta, own)
    header.append("- load average at the end %.2f; bench total %.0f s" % (os.getloadavg()[0], time.perf_counter() - start))
    write_table(results, header)
    plot(results)
    print("\ntable: %s\nplot:  %s" % (os.path.relpath(TABLE, bench.ROOT), os.path.relpath(PLOT, bench.ROOT)))


if __name__ == "__main__":
    main()
