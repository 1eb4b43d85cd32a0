#!/usr/bin/env python3
"""A walk through evolving smoke: per-frame error and flicker of three ways of rendering it, against time.

Case (../shared/data): the fire hall of examples/hall under its normal lighting, its soot from the shared FDS case
imported by fds2vdb every 10 s from 0 to 180 s (-l 1.5,2.5: the meshes without 3-D smoke filled from the 2.05 m
slice); a camera path from the hall's door toward its north-east corner over 60-180 s of the fire (the smoke
thickens while one walks), frames at even instants (rpict -path -fps), -ab 1.
  paths       path tracing, each frame on its own (-aa 0), at -ad 4, 16
  frame cache the irradiance caches made afresh at each frame's instant (-at 0), at -ad 64, 256
  time cache  records that serve windows of time (-at 32), at -ad 64, 256
The reference: path tracing at -ad 1024 of REF_PAIRS pairs of consecutive frames spread over the walk, their
views read from the frames' headers (kept in results/walk_reference_*.npz, keyed by the case; --remake-reference
makes them again). Its own error is stated beside the results: the paths' error at -ad 16 scaled by sqrt(16/1024)
(the -ad part only: at -ms 0 the in-scattering along each view ray is one sample in it too; see bench/README).
Metrics, on the luminance, over the reference frames (bench/README.md, "A measure of flicker"):
  error    the RMS over pixels and frames of (frame - ref), over the mean luminance of the references;
  flicker  the RMS over pixels and pairs of (frame_t - frame_t-1) - (ref_t - ref_t-1), over the same mean.
One thread each (-n 1; two runs at a time on a machine of two cores), CPU seconds (user + system) of the whole
walk. Writes results/walk.md, results/walk_time_vs_error.png and results/walk_in_time.png. The issue's case is
100 frames of 320 x 240 over 60-180 s (--frames 100 --size 320 240 --span 60 180); smaller ones run sooner.
"""
import argparse
import concurrent.futures
import hashlib
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench import ROOT, RESULTS, Timer, git_commit, matplotlib_plot, write_result  # noqa: E402
from rpict import luminance, read_picture  # noqa: E402

HALL = os.path.join(ROOT, "examples", "hall")
FDS = os.path.join(ROOT, "..", "shared", "data", "fds", "fdsvismap_room_fire", "model.smv")
SOOT_TIMES = ",".join(str(t) for t in range(0, 181, 10))
# The walk over the whole fire: (time, position, direction) at its two ends.
WALK = [(60.0, (10.6, 3.9, 1.7), (0.8, 0.6, -0.05)), (180.0, (14.0, 8.6, 1.7), (0.5, 0.85, -0.05))]
# Every pixel traced at its centre (-ps 1 -pj 0), in the reference too: frames and references see the same
# points, and no pixel is interpolated between samples.
VIEW = ["-vh", "70", "-vv", "55", "-ps", "1", "-pj", "0"]
WAYS = {
    "paths": [["-aa", "0", "-ad", ad] for ad in ("4", "16")],
    "frame cache": [["-at", "0", "-ad", ad] for ad in ("64", "256")],
    "time cache": [["-at", "32", "-ad", ad] for ad in ("64", "256")],
}
REF_OPTIONS = ["-aa", "0", "-ad", "1024"]
REF_PAIRS = 5


def walk_between(t0, t1):
    """The walk's camera path cut to [t0, t1] (positions and directions linear in time between its ends)."""
    (a, pa, da), (b, pb, db) = WALK

    def at(t):
        w = (t - a) / (b - a)
        return [p + w * (q - p) for p, q in zip(pa, pb)], [p + w * (q - p) for p, q in zip(da, db)]

    lines = []
    for t in (t0, t1):
        p, d = at(t)
        lines.append("%g  %s  %s" % (t, " ".join("%.6f" % x for x in p), " ".join("%.6f" % x for x in d)))
    return "\n".join(lines) + "\n"


def rpict_walk(bindir, options, scene, path, fps, size, out_dir, ab):
    os.makedirs(out_dir, exist_ok=True)
    cmd = [os.path.join(bindir, "rpict"), "-u-", "-n", "1", "-path", path, "-fps", repr(fps), *VIEW,
           "-x", str(size[0]), "-y", str(size[1]), "-ab", str(ab), *options, "-o", os.path.join(out_dir, "f%03d.hdr"),
           *scene]
    t = Timer(cmd, os.devnull)
    return t.cpu


def header_view(picture):
    """The VIEW= and SCENETIME= of a picture's header, as rpict options."""
    with open(picture, "rb") as f:
        head = f.read(4096).split(b"\n\n")[0].decode(errors="replace").splitlines()
    view = next(l for l in head if l.startswith("VIEW="))[5:].split()
    time = next(l for l in head if l.startswith("SCENETIME="))[10:].strip()
    return view + ["-T", time]


def reference_frames(frames):
    """REF_PAIRS pairs (t-1, t) of frame numbers (1-based) spread over the walk."""
    step = (frames - 1) / REF_PAIRS
    return sorted({n for k in range(REF_PAIRS) for n in (int(1 + step * (k + 0.5)), int(1 + step * (k + 0.5)) + 1)})


def reference(bindir, scene, frames_dir, numbers, size, ab, key, remake):
    path = os.path.join(RESULTS, "walk_reference_%s.npz" % key)
    if os.path.exists(path) and not remake:
        data = np.load(path)
        return {int(k[1:]): data[k] for k in data.files}, 0.0
    refs, cpu = {}, 0.0
    with tempfile.TemporaryDirectory() as tmp:
        def one(n):
            out = os.path.join(tmp, "r%03d.hdr" % n)
            cmd = [os.path.join(bindir, "rpict"), "-u-", "-n", "1", *header_view(os.path.join(frames_dir, "f%03d.hdr" % n)),
                   *VIEW[4:], "-x", str(size[0]), "-y", str(size[1]), "-ab", str(ab), *REF_OPTIONS, *scene]
            t = Timer(cmd, os.devnull, out_path=out, capture=False)
            return n, t.cpu, luminance(read_picture(out))
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            for n, c, lum in pool.map(one, numbers):
                refs[n] = lum
                cpu += c
    np.savez_compressed(path, **{"f%d" % n: v for n, v in refs.items()})
    return refs, cpu


def measures(frames_dir, refs, numbers):
    """Per-frame error and flicker over the reference frames, and each reference frame's own (for the plot)."""
    lum = {n: luminance(read_picture(os.path.join(frames_dir, "f%03d.hdr" % n))) for n in numbers}
    mean = float(np.mean([refs[n].mean() for n in numbers]))
    err = {n: float(np.sqrt(np.mean((lum[n] - refs[n]) ** 2))) / mean for n in numbers}
    pairs = [n for n in numbers if n - 1 in refs]
    flick = {n: float(np.sqrt(np.mean(((lum[n] - lum[n - 1]) - (refs[n] - refs[n - 1])) ** 2))) / mean for n in pairs}
    rms = lambda d: math.sqrt(sum(v * v for v in d.values()) / len(d))
    return rms(err), rms(flick), err, flick


PLOT_TIME_ERROR = """fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
for ax, k, label in ((axes[0], 'error', 'per-frame RMS error (%)'), (axes[1], 'flicker', 'temporal error, flicker (%)')):
    for name, pts in d['series'].items():
        ax.loglog([p['cpu'] for p in pts], [100 * p[k] for p in pts], 'o-', label=name)
    ax.axhline(100 * d['ref_' + k], color='grey', ls=':', label='reference noise')
    ax.set_xlabel('CPU time of the walk (s)'); ax.set_ylabel(label); ax.grid(alpha=.3, which='both')
axes[0].legend(fontsize=8); fig.suptitle(d['title'], fontsize=9)
fig.tight_layout(); fig.savefig(sys.argv[2], dpi=110)
"""
PLOT_IN_TIME = """fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
for ax, k, label in ((axes[0], 'errors', 'per-frame RMS error (%)'), (axes[1], 'flickers', 'flicker (%)')):
    for name, by_time in d[k].items():
        ts = sorted(by_time, key=float)
        ax.plot([float(t) for t in ts], [100 * by_time[t] for t in ts], 'o-', label=name)
    ax.set_xlabel('instant of the fire (s)'); ax.set_ylabel(label); ax.grid(alpha=.3)
axes[0].legend(fontsize=8); fig.suptitle(d['title'], fontsize=9)
fig.tight_layout(); fig.savefig(sys.argv[2], dpi=110)
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    ap.add_argument("--frames", type=int, default=100)
    ap.add_argument("--span", type=float, nargs=2, default=(60.0, 180.0), metavar=("T0", "T1"))
    ap.add_argument("--size", type=int, nargs=2, default=(320, 240), metavar=("X", "Y"))
    ap.add_argument("--ab", type=int, default=1)
    ap.add_argument("--remake-reference", action="store_true")
    args = ap.parse_args()
    if not os.path.exists(FDS):
        print("bench/walk.py: no ../shared/data: skipped", file=sys.stderr)
        return
    fps = (args.frames - 1) / (args.span[1] - args.span[0])
    instant = lambda n: args.span[0] + (n - 1) / fps
    work = tempfile.mkdtemp(prefix="brume_walk_")
    try:
        subprocess.run([os.path.join(args.bin, "fds2vdb"), "-t", SOOT_TIMES, "-l", "1.5,2.5", "-o",
                        os.path.join(work, "soot"), FDS], stdout=open(os.path.join(work, "smoke.rad"), "w"),
                       stderr=subprocess.DEVNULL, check=True, cwd=work)
        scene = [os.path.join(HALL, "hall.rad"), os.path.join(HALL, "lights.rad"), os.path.join(work, "smoke.rad")]
        path = os.path.join(work, "walk.txt")
        with open(path, "w") as f:
            f.write(walk_between(*args.span))
        runs = [(way, options) for way, ladder in WAYS.items() for options in ladder]
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            cpus = list(pool.map(lambda r: rpict_walk(args.bin, r[1], scene, path, fps, args.size,
                                                      os.path.join(work, "%s %s" % (r[0], " ".join(r[1]))), args.ab),
                                 runs))
        numbers = reference_frames(args.frames)
        key = hashlib.sha256(json.dumps([args.frames, args.span, args.size, args.ab, WALK, VIEW, REF_OPTIONS, numbers,
                                         SOOT_TIMES]).encode()).hexdigest()[:12]
        first = os.path.join(work, "%s %s" % (runs[0][0], " ".join(runs[0][1])))  # its headers give the views
        refs, ref_cpu = reference(args.bin, scene, first, numbers, args.size, args.ab, key, args.remake_reference)
        series, errors, flickers, rows = {}, {}, {}, []
        for (way, options), cpu in zip(runs, cpus):
            e, fl, per_err, per_flick = measures(os.path.join(work, "%s %s" % (way, " ".join(options))), refs, numbers)
            series.setdefault(way, []).append({"cpu": cpu, "error": e, "flicker": fl})
            name = "%s %s" % (way, " ".join(options))
            errors[name] = {str(instant(n)): v for n, v in per_err.items()}
            flickers[name] = {str(instant(n)): v for n, v in per_flick.items()}
            rows.append("| %s | %s | %.1f | %.2f | %.2f |" % (way, " ".join(options), cpu, 100 * e, 100 * fl))
        paths16 = series["paths"][-1]
        ref_error = paths16["error"] * math.sqrt(16 / 1024)
        ref_flicker = paths16["flicker"] * math.sqrt(16 / 1024)
        title = ("hall walk, %d frames %dx%d over %g-%g s, -ab %d; Brume %s"
                 % (args.frames, args.size[0], args.size[1], args.span[0], args.span[1], args.ab, git_commit()))
        plotted = matplotlib_plot(PLOT_TIME_ERROR, {"series": series, "title": title, "ref_error": ref_error,
                                                    "ref_flicker": ref_flicker},
                                  os.path.join(RESULTS, "walk_time_vs_error.png"))
        matplotlib_plot(PLOT_IN_TIME, {"errors": errors, "flickers": flickers, "title": title},
                        os.path.join(RESULTS, "walk_in_time.png"))
        text = "\n".join([
            "# A walk through evolving smoke (bench/walk.py)", "",
            title + ". Reference frames %s (path tracing %s%s); its own error about %.2f %%, flicker %.2f %% "
            "(the paths' at -ad 16 scaled to -ad 1024)." % (
                ", ".join(str(n) for n in numbers), " ".join(REF_OPTIONS),
                ", %.0f CPU s" % ref_cpu if ref_cpu else ", kept", 100 * ref_error, 100 * ref_flicker), "",
            "| way | options | CPU s | error % | flicker % |", "|---|---|---|---|---|", *rows, ""])
        write_result(text, "walk.md", plotted, "walk_time_vs_error.png")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
