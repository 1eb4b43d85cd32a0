#!/usr/bin/env python3
"""A daylit picture: rpict at -ab 5 against time, Brume against Radiance 6.1's irradiance cache, one thread each.

The deep side-lit room of bench/daylight.py (bench/daylight/deep.rad: clear sky and a sun patch through one
window), seen from its back wall toward the window at 64 × 44 pixels, every pixel sampled at its centre
(-pj 0), so that errors are the shading's. Each picture is compared with a converged reference (the mean of
REF_RUNS runs of Brume's path tracing with every bounce, see REF_OPTIONS), cached in
results/daylight_picture_reference.npz with its own error: RMS, 99th percentile and the bias of the mean of the
relative error of pixel luminance. Radiance's runs are kept in results/daylight_picture_radiance.json (by command),
so that a rerun times only Brume (--rerun-radiance times them again).

    python3 bench/daylight_picture.py --bin build/bin [--remake-reference] [--rerun-radiance]
"""
import argparse
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
import rpict  # noqa: E402  (reads pictures with numpy, and their errors)

np = rpict.np
SCENE = os.path.join(bench.ROOT, "bench", "daylight", "deep.rad")
VIEW = ["-vp", "3", "9.5", "1.5", "-vd", "0", "-1", "-0.15", "-vh", "70", "-vv", "50", "-x", "64", "-y", "48",
        "-pj", "0"]
# The reference aims at the window and the sun patch (-aP): by rays alone (-aP-) its own error would be about five
# times larger at the same cost. -aP is checked independently by bench/daylight.py, whose sensor references find the
# sky by rays alone.
REF_OPTIONS = ["-ab", "50", "-aa", "0", "-ad", "4096", "-ps", "1", "-ds", ".05"]
REF_RUNS = 2
REFERENCE = os.path.join(bench.RESULTS, "daylight_picture_reference")
RADIANCE_RUNS = os.path.join(bench.RESULTS, "daylight_picture_radiance.json")
TABLE = os.path.join(bench.RESULTS, "daylight_picture.md")
TARGETS = (3.5, 3.0, 2.5)  # % RMS at which times are compared

RUNGS = [  # (family, program, options)
    ("Brume defaults", "brume", ["-ab", "5"]),
    ("Brume cache -ps 4", "brume", ["-ab", "5", "-aa", ".1"]),
    ("Brume cache -ps 4", "brume", ["-ab", "5", "-aa", ".07"]),
    ("Brume cache -ps 4", "brume", ["-ab", "5", "-aa", ".05", "-ad", "2048"]),
    ("Brume cache", "brume", ["-ab", "5", "-ps", "1", "-aa", ".1", "-ad", "1024"]),
    ("Brume cache", "brume", ["-ab", "5", "-ps", "1", "-aa", ".05", "-ad", "2048"]),
    ("Brume path tracing", "brume", ["-ab", "50", "-aa", "0", "-ps", "1", "-ad", "64"]),
    ("Brume path tracing", "brume", ["-ab", "50", "-aa", "0", "-ps", "1", "-ad", "256"]),
    ("Radiance defaults", "radiance", ["-ab", "5"]),
    ("Radiance cache", "radiance", ["-ab", "5", "-ps", "1"]),
    ("Radiance cache", "radiance", ["-ab", "5", "-ps", "1", "-aa", ".1", "-ar", "128", "-ad", "1024", "-as", "512"]),
    ("Radiance cache", "radiance", ["-ab", "6", "-ps", "1", "-aa", ".05", "-ar", "256", "-ad", "2048", "-as", "1024",
                                    "-ds", ".05", "-dj", ".7"]),
]


def reference(brume_rpict, tmp, remake):
    """(mean RGB, metadata): cached, or made from REF_RUNS runs on all threads."""
    key = "%s %s %d" % (bench.sha256(SCENE)[:16], " ".join(VIEW + REF_OPTIONS), REF_RUNS)
    cached = rpict.load_cached(REFERENCE, key, remake)
    if cached:
        return cached[0]["rgb"], cached[1]
    cmd = [brume_rpict] + VIEW + REF_OPTIONS + ["-u+", "-n", str(os.cpu_count() or 1), SCENE]
    print("making the reference: %d runs of rpict %s (about 10 CPU-minutes each)" % (REF_RUNS, " ".join(cmd[1:-1])),
          flush=True)
    out, runs, cpu = os.path.join(tmp, "ref.hdr"), [], 0.0
    for _ in range(REF_RUNS):
        t = bench.Timer(cmd, os.devnull, out_path=out)
        cpu += t.cpu
        runs.append(rpict.read_picture(out))
    rgb = np.mean(runs, axis=0)
    # Two runs differ by √2 times one run's error, that is by twice the error of their mean.
    own = rpict.errors(runs[0], runs[1])[0] / 2 if REF_RUNS == 2 else None
    meta = {"key": key, "command": "rpict " + " ".join(cmd[1:-1]) + " bench/daylight/deep.rad", "runs": REF_RUNS,
            "cpu_s": round(cpu), "brume_commit": bench.git_commit(), "date": time.strftime("%Y-%m-%d"),
            "own_rms_pct": own}
    rpict.save_cached(REFERENCE, {"rgb": rgb}, meta)
    return rgb, meta


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=os.path.join(bench.ROOT, "build", "bin"))
    ap.add_argument("--remake-reference", action="store_true")
    ap.add_argument("--rerun-radiance", action="store_true")
    a = ap.parse_args()
    rad = bench.find_radiance()
    brume = os.path.join(os.path.abspath(a.bin), "rpict")
    radiance_runs = json.load(open(RADIANCE_RUNS)) if os.path.exists(RADIANCE_RUNS) else {}
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        ref, meta = reference(brume, tmp, a.remake_reference)
        octree = os.path.join(tmp, "deep.oct")
        if rad:
            with open(octree, "wb") as f:
                subprocess.run([rad["oconv"], "-f", SCENE], stdout=f, env=rad["env"], check=True)
        out = os.path.join(tmp, "pic.hdr")
        for family, prog, opts in RUNGS:
            key = " ".join(VIEW + opts)
            if prog == "radiance":
                if not rad:
                    continue
                if key not in radiance_runs or a.rerun_radiance:
                    pic, _, cpu = rpict.timed_picture([os.path.join(rad["dir"], "rpict")] + VIEW + opts + [octree],
                                                      rad["env"], out, 1)
                    radiance_runs[key] = {"cpu": cpu, "errors": rpict.errors(pic, ref), "machine": bench.machine()}
                cpu, err = radiance_runs[key]["cpu"], radiance_runs[key]["errors"]
            else:
                pic, _, cpu = rpict.timed_picture([brume] + VIEW + opts + ["-n", "1", SCENE], None, out, 1)
                err = rpict.errors(pic, ref)
            rows.append((family, " ".join(opts), cpu) + tuple(err))
            print("  %-20s %-70s %7.2f s  RMS %5.2f %%  p99 %5.1f %%  bias %+.2f %%" % rows[-1], flush=True)
    with open(RADIANCE_RUNS, "w") as f:
        json.dump(radiance_runs, f, indent=0)
    lines = ["Made by `python3 bench/daylight_picture.py` (commit %s, %s, %s)." % (
        bench.git_commit(), time.strftime("%Y-%m-%d"), bench.machine()), "",
        "View `%s` of bench/daylight/deep.rad; reference: %s, the mean of %d runs (its own RMS error %.2f %%)." % (
            " ".join(VIEW), meta["command"], meta["runs"], meta["own_rms_pct"] or float("nan")), "",
        "| family | options | CPU s | RMS % | p99 % | bias % |", "|---|---|---:|---:|---:|---:|"]
    lines += ["| %s | `%s` | %.2f | %.2f | %.1f | %+.2f |" % r for r in rows]
    for target in TARGETS:
        lines.append("")
        lines.append("Time to %.1f %% RMS (CPU s, interpolated log-log between the rungs of each family; the "
                     "soonest family):" % target)
        for who in ("Brume", "Radiance"):
            found = bench.soonest([(r[0], r[2], r[3]) for r in rows if r[0].startswith(who)], target)
            lines.append("- %s: %s" % (who, "%.2f s (%s)" % found if found else "not reached"))
    text = "\n".join(lines) + "\n"
    print(text)
    with open(TABLE, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
