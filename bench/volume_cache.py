#!/usr/bin/env python3
"""Volume cache: run time against error of view rays through lit smoke, records in the media against path tracing.

Scenes (those of bench/smoke.py, with indirect light):
  corridor  the corridor of make demo in the FDS soot at t = 60 s and t = 120 s, its soot's albedo .2 and (a copy
            of examples/corridor/smoke.rad) .8; 48 view rays from its near end, -ms .05.
  plume     OpenVDB's smoke1 plume in a hall (albedo .9, g .3) lit by a ceiling panel, -ms 1.
  halo      a small lamp in a room of fog (-me .3, albedo .9, g .6), -ms .5.
  picture   the corridor at t = 120 s as a picture of 40 x 30 view rays over the same view (albedo .2 and .8,
            -ab 1 only): records shared by 1200 rays, as a picture's pixels share them.
At -ab 1 and -ab 3, with -al+ (nothing past -ab bounces, so that path tracing and the cache estimate the same
light). Path tracing (-aa 0) repeats each ray r = 1, 4, 16, 64 times; the cache (-aa .1, and .05 at the last
rung) traces the 48 rays r = 1, 4, 16 times in one run, its records shared by all of them (as a picture's are by
its pixels). Each ray's mean against a reference of REFERENCE_REPEATS path-traced repeats (two threads); error:
the RMS over the rays over the mean reference luminance (bench/smoke.py's). One thread, CPU seconds. The time
to an error is interpolated along each ladder in log-log (bench.time_to); "sooner" is path tracing's time over
the cache's at the smallest error both reach.
Writes results/NAME.md and results/NAME_time_vs_error.png (NAME volume_cache unless --name says otherwise).
Skipped without ../shared/data.
"""
import argparse
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench import RESULTS, Timer, git_commit, ladders_plot, time_to, write_result  # noqa: E402
from smoke import (CORRIDOR, SOOT, scenes, luminances, normalised_rms, write_rays)  # noqa: E402

REFERENCE_REPEATS = 400
PATHS = [1, 4, 16, 64]
CACHED = [(1, ".1"), (4, ".1"), (16, ".1"), (16, ".05")]
# Pictures: 25 times the rays, so fewer repeats (the reference's own error is in the table).
PICTURE = (40, 30)
PICTURE_REFERENCE_REPEATS = 32
PICTURE_PATHS = [1, 4]
PICTURE_CACHED = [(1, ".1"), (1, ".05")]


def picture_rays(eye, forward, right, up):
    """PICTURE's directions over bench/smoke.py's 70° x 50° view, a ray through each pixel's centre."""
    w, h = PICTURE
    rays = []
    for j in range(h):
        for i in range(w):
            a, b = ((i + 0.5) / w - 0.5) * 1.4, ((j + 0.5) / h - 0.5) * 0.9
            rays.append(eye + tuple(f + a * r + b * u for f, r, u in zip(forward, right, up)))
    return rays


def cases(tmp, chosen):
    """(name, files, options, rays, RAYPATH, ladders) per measured case and -ab; ladders: (reference repeats,
    path tracing's repeats, the cache's (repeats, -aa))."""
    base = {c[0]: c for c in scenes(tmp)}
    pale = os.path.join(tmp, "pale_smoke.rad")
    with open(os.path.join(CORRIDOR, "smoke.rad")) as f:
        text = f.read()
    with open(pale, "w") as f:
        f.write(text.replace(".2 .2 .2  .6", ".8 .8 .8  .6"))
    out = []
    for bounces in (1, 3):
        for name, albedo in (("corridor, t = 120 s", ".2"), ("corridor, t = 120 s", ".8"), ("corridor, t = 60 s", ".2"),
                             ("plume", None), ("halo", None)):
            _, files, options, rays, raypath, _ = base[name]
            if albedo == ".8":
                files = [files[0], pale]
            label = f"{name}{', albedo ' + albedo if albedo else ''}, -ab {bounces}"
            if chosen and not any(c in label for c in chosen):
                continue
            opts = [o for o in options]
            opts[opts.index("-ab") + 1] = str(bounces)
            out.append((label, files, opts + ["-al+"], rays, raypath, (REFERENCE_REPEATS, PATHS, CACHED)))
    _, files, options, _, raypath, _ = base["corridor, t = 120 s"]
    for albedo in (".2", ".8"):
        label = f"corridor picture {PICTURE[0]} x {PICTURE[1]}, t = 120 s, albedo {albedo}, -ab 1"
        if chosen and not any(c in label for c in chosen):
            continue
        opts = [o for o in options]
        opts[opts.index("-ab") + 1] = "1"
        out.append((label, [files[0], pale] if albedo == ".8" else files, opts + ["-al+"],
                    picture_rays((10.3, 3, 1.6), (1, 0, 0), (0, 1, 0), (0, 0, 1)), raypath,
                    (PICTURE_REFERENCE_REPEATS, PICTURE_PATHS, PICTURE_CACHED)))
    return out


def rtrace(bin_dir, tmp, case, repeats, extra, threads=1):
    label, files, options, rays, raypath, _ = case
    cmd = [os.path.join(bin_dir, "rtrace"), "-h", "-n", str(threads)] + options + extra + files
    t = Timer(cmd, write_rays(tmp, rays, repeats), env=dict(os.environ, RAYPATH=f"{raypath}:{CORRIDOR}"))
    return luminances(t.out, repeats), t.cpu


def plot(series, png):
    return ladders_plot(series, png, "Brume: view rays through lit smoke, volume cache (o) against path tracing (s)",
                        ": ", "cache")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(os.path.dirname(HERE), "build", "bin"))
    ap.add_argument("--only", nargs="*", default=[], help="cases whose label contains one of these")
    ap.add_argument("--name", default="volume_cache", help="the results' file names (results/NAME.md, ...)")
    args = ap.parse_args()
    if not os.path.isdir(SOOT):
        print(f"volume_cache: no {SOOT}: skipped", file=sys.stderr)
        return
    rows, series, summary = [], {}, []
    with tempfile.TemporaryDirectory() as tmp:
        for case in cases(tmp, args.only):
            label, (reference_repeats, path_repeats, cached_rungs) = case[0], case[5]
            reference, ref_cpu = rtrace(args.bin, tmp, case, reference_repeats, ["-aa", "0", "-u+"], threads=2)
            paths, cached = [], []
            for r in path_repeats:
                values, cpu = rtrace(args.bin, tmp, case, r, ["-aa", "0", "-u+"])
                paths.append((cpu, normalised_rms(values, reference)))
                rows.append(f"| {label} | paths | {r} | {cpu:.2f} s | {100 * paths[-1][1]:.2f} % |")
                print(f"  {label}, paths x{r}: {cpu:.2f} s, {100 * paths[-1][1]:.2f} %", file=sys.stderr)
            for r, aa in cached_rungs:
                values, cpu = rtrace(args.bin, tmp, case, r, ["-aa", aa, "-u+"])
                cached.append((cpu, normalised_rms(values, reference)))
                rows.append(f"| {label} | cache -aa {aa} | {r} | {cpu:.2f} s | {100 * cached[-1][1]:.2f} % |")
                print(f"  {label}, cache -aa {aa} x{r}: {cpu:.2f} s, {100 * cached[-1][1]:.2f} %", file=sys.stderr)
            series[f"{label}: paths"], series[f"{label}: cache"] = paths, cached
            # The reference's own error: path tracing's at its last rung scaled by √(repeats there / reference's).
            own = paths[-1][1] * (path_repeats[-1] / reference_repeats) ** .5
            target = max(min(e for _, e in paths), min(e for _, e in cached))
            tp, tc = time_to(paths, target), time_to(cached, target)
            ratio = f"{tp / tc:.1f}x" if tp and tc else "n/a"
            summary.append(f"| {label} | {100 * own:.2f} % | {100 * target:.2f} % | "
                           f"{tp or float('nan'):.2f} s | {tc or float('nan'):.2f} s | {ratio} |")
    text = (f"# Volume cache: time against error\n\nBrume {git_commit()}, one thread (bench/volume_cache.py; its "
            "docstring says what is measured).\n\n| case | reference's own error | at error | paths | cache | "
            "cache sooner |\n|---|---|---|---|---|---|\n" + "\n".join(summary) +
            "\n\n| case | method | repeats | CPU | error |\n|---|---|---|---|---|\n" + "\n".join(rows) + "\n")
    png = f"{args.name}_time_vs_error.png"
    write_result(text, f"{args.name}.md", plot(series, os.path.join(RESULTS, png)), png)


if __name__ == "__main__":
    main()
