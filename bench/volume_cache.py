#!/usr/bin/env python3
"""Volume cache: run time against error of view rays through lit smoke, records in the media against path tracing.

Scenes (those of bench/smoke.py, with indirect light):
  corridor  the corridor of make demo in the FDS soot at t = 60 s and t = 120 s, its soot's albedo .2 and (a copy
            of examples/corridor/smoke.rad) .8; 48 view rays from its near end, -ms .05.
  plume     OpenVDB's smoke1 plume in a hall (albedo .9, g .3) lit by a ceiling panel, -ms 1.
  halo      a small lamp in a room of fog (-me .3, albedo .9, g .6), -ms .5.
  picture   the corridor at t = 120 s as a picture of 40 x 30 view rays over the same view (albedo .2 and .8,
            -ab 1 only): records shared by 1200 rays, as a picture's pixels share them; and as one of 160 x 120
            rays (the cache only), whose error is that of its 40 x 30 rays through the smaller picture's pixel
            centres, against the same reference, and whose path tracing costs 16 times the smaller one's (the
            same paths per pixel, 16 times the pixels), at -aa .1 only: a picture of a useful size shares its
            records among more pixels.
  sensors   a grid of 50 x 10 sensors at 0.8 m over the corridor's floor (10 cm along it, 20 cm across), facing up,
            t = 120 s, albedo .2 and .8, rtrace -I -ab 3: illuminance for a building code, through the smoke; 32
            reference repeats, path tracing x1 and x4, the cache at -aa .1 and .05 once (as the pictures).
At -ab 1 and -ab 3, with -al+ (nothing past -ab bounces, so that path tracing and the cache estimate the same
light). Path tracing (-aa 0) repeats each ray r = 1, 4, 16, 64 times; the cache (-aa .1, and .05 at the last
rung) traces the 48 rays r = 1, 4, 16 times in one run, its records shared by all of them (as a picture's are by
its pixels). Each ray's mean against a reference of REFERENCE_REPEATS path-traced repeats (two threads); error:
the RMS over the rays over the mean reference luminance (bench/smoke.py's); also the 99.9th percentile of the
rays' errors over that RMS (splotches: a tail far beyond normal errors' 3.3; of 48 rays, the largest) and the size
of the cache's -af file (its records). One thread, CPU seconds. The time
to an error is interpolated along each ladder in log-log (bench.time_to); "sooner" is path tracing's time over
the cache's at the smallest error both reach.
The pictures' references, STORED_REPEATS path-traced repeats each (own error ~1 %, about an hour of CPU each),
are kept in results/volume_cache_references.json and used when there (--remake-reference makes them anew).
Writes results/NAME.md and results/NAME_time_vs_error.png (NAME volume_cache unless --name says otherwise).
Skipped without ../shared/data.
"""
import argparse
import json
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
FINER = 4  # the larger picture's pixels across one of PICTURE's
STORED = os.path.join(RESULTS, "volume_cache_references.json")
STORED_REPEATS = 128
SENSORS = [(10.05 + 0.1 * i, 2.1 + 0.2 * j, 0.8, 0, 0, 1) for i in range(50) for j in range(10)]


def picture_rays(eye, forward, right, up, finer=1):
    """Directions over bench/smoke.py's 70° x 50° view: PICTURE's pixel centres (finer 1), or a picture `finer`
    times as wide and high whose pixels at (finer i + finer/2, finer j + finer/2) are PICTURE's (i, j); with the
    indices of those, in PICTURE's order."""
    w, h = PICTURE
    rays, coarse = [], {}
    for n in range(h * finer):
        for m in range(w * finer):
            x, y = (m + 0.5 * (finer == 1)) / (w * finer), (n + 0.5 * (finer == 1)) / (h * finer)
            if m % finer == finer // 2 and n % finer == finer // 2:
                coarse[(n // finer, m // finer)] = len(rays)
            a, b = (x - 0.5) * 1.4, (y - 0.5) * 0.9
            rays.append(eye + tuple(f + a * r + b * u for f, r, u in zip(forward, right, up)))
    return rays, [coarse[(j, i)] for j in range(h) for i in range(w)]


def with_bounces(options, bounces):
    """The options with -ab set to `bounces`, and -al+."""
    opts = list(options)
    opts[opts.index("-ab") + 1] = str(bounces)
    return opts + ["-al+"]


def cases(tmp, chosen):
    """(name, files, options, rays, RAYPATH, ladders, finer) per measured case and -ab; ladders: (reference
    repeats, path tracing's repeats, the cache's (repeats, -aa)); finer: None, or for the larger picture (its
    rays, the indices of the case's rays among them, FINER)."""
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
            out.append((label, files, with_bounces(options, bounces), rays, raypath, (REFERENCE_REPEATS, PATHS, CACHED),
                        None))
    _, files, options, _, raypath, _ = base["corridor, t = 120 s"]
    view = ((10.3, 3, 1.6), (1, 0, 0), (0, 1, 0), (0, 0, 1))
    for albedo in (".2", ".8"):
        label = f"corridor picture {PICTURE[0]} x {PICTURE[1]}, t = 120 s, albedo {albedo}, -ab 1"
        if chosen and not any(c in label for c in chosen):
            continue
        rays, _ = picture_rays(*view)
        case = (label, [files[0], pale] if albedo == ".8" else files, with_bounces(options, 1), rays, raypath,
                (PICTURE_REFERENCE_REPEATS, PICTURE_PATHS, PICTURE_CACHED))
        out.append(case + (None,))
        big = label.replace(f"{PICTURE[0]} x {PICTURE[1]}", f"{PICTURE[0] * FINER} x {PICTURE[1] * FINER}")
        out.append((big,) + case[1:5] + ((PICTURE_REFERENCE_REPEATS, PICTURE_PATHS, PICTURE_CACHED[:1]),
                                         picture_rays(*view, finer=FINER) + (FINER,)))
    for albedo in (".2", ".8"):
        label = f"corridor sensors {len(SENSORS)} at 0.8 m, t = 120 s, albedo {albedo}, -I -ab 3"
        if chosen and not any(c in label for c in chosen):
            continue
        out.append((label, [files[0], pale] if albedo == ".8" else files, ["-I"] + with_bounces(options, 3), SENSORS,
                    raypath, (PICTURE_REFERENCE_REPEATS, PICTURE_PATHS, PICTURE_CACHED), None))
    return out


def rtrace(bin_dir, tmp, case, repeats, extra, threads=1, rays=None, cache_file=None):
    """The rays' luminances and the CPU time; with cache_file, the records are written there (anew)."""
    label, files, options, case_rays, raypath = case[:5]
    rays = rays or case_rays
    if cache_file:
        if os.path.exists(cache_file):
            os.remove(cache_file)
        extra = extra + ["-af", cache_file]
    cmd = [os.path.join(bin_dir, "rtrace"), "-h", "-n", str(threads)] + options + extra + files
    t = Timer(cmd, write_rays(tmp, rays, repeats), env=dict(os.environ, RAYPATH=f"{raypath}:{CORRIDOR}"))
    return luminances(t.out, repeats), t.cpu


def tail(values, reference):
    """The 99.9th percentile of |value - reference| over the mean reference, over their RMS (normalised_rms)."""
    mean = sum(reference) / len(reference)
    errors = sorted(abs(v - r) / mean for v, r in zip(values, reference))
    return errors[min(len(errors) - 1, int(0.999 * len(errors)))] / normalised_rms(values, reference)


def extrapolated(paths, cached, own):
    """Path tracing's time to the cache's least error, from its first rung as 1/√time (unbiased), both errors
    with the reference's own taken out (independent: e² = e_true² + own²), against the cache's time there; the
    table's rule above cannot see past the error path tracing reached."""
    tc, ec = min(cached, key=lambda c: c[1])
    (t1, e1), true_c = paths[0], (ec ** 2 - own ** 2)
    if true_c <= 0 or e1 <= ec:
        return "n/a"
    tp = t1 * (e1 ** 2 - own ** 2) / true_c
    return f"{100 * true_c ** .5:.2f} %: {tp:.0f} s / {tc:.0f} s = {tp / tc:.1f}x"


def reference_of(args, tmp, case):
    """The case's reference luminances and their repeats: a picture's as kept in STORED under the smaller
    picture's label (made and kept there with --remake-reference), else traced now."""
    label, repeats = case[0], case[5][0]

    def traced(n):
        return rtrace(args.bin, tmp, case, n, ["-aa", "0", "-u+"], threads=2)[0]

    if "picture" not in label:
        return traced(repeats), repeats
    name = label.replace(f"{PICTURE[0] * FINER} x {PICTURE[1] * FINER}", f"{PICTURE[0]} x {PICTURE[1]}")
    stored = {}
    if os.path.exists(STORED):
        with open(STORED) as f:
            stored = json.load(f)
    if args.remake_reference:
        stored[name] = {"repeats": STORED_REPEATS, "values": traced(STORED_REPEATS)}
        with open(STORED, "w") as f:
            json.dump(stored, f)
    if name in stored:
        return stored[name]["values"], stored[name]["repeats"]
    return traced(repeats), repeats


def plot(series, png):
    return ladders_plot(series, png, "Brume: view rays through lit smoke, volume cache (o) against path tracing (s)",
                        ": ", "cache")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(os.path.dirname(HERE), "build", "bin"))
    ap.add_argument("--only", nargs="*", default=[], help="cases whose label contains one of these")
    ap.add_argument("--name", default="volume_cache", help="the results' file names (results/NAME.md, ...)")
    ap.add_argument("--remake-reference", action="store_true", help="trace the pictures' references anew")
    args = ap.parse_args()
    if not os.path.isdir(SOOT):
        print(f"volume_cache: no {SOOT}: skipped", file=sys.stderr)
        return
    rows, series, summary = [], {}, []
    with tempfile.TemporaryDirectory() as tmp:
        measured = {}  # the reference and path tracing's ladder of each case's rays, for the larger picture
        for case in cases(tmp, args.only):
            label, (_, path_repeats, cached_rungs), finer = case[0], case[5], case[6]
            key = (tuple(case[1]), tuple(case[3]))
            if key not in measured:
                reference, reference_repeats = reference_of(args, tmp, case)
                paths = []
                for r in path_repeats:
                    values, cpu = rtrace(args.bin, tmp, case, r, ["-aa", "0", "-u+"])
                    paths.append((cpu, normalised_rms(values, reference), tail(values, reference)))
                measured[key] = reference, reference_repeats, paths
            reference, reference_repeats, paths = measured[key]
            scale = finer[2] ** 2 if finer else 1
            tails = [t for _, _, t in paths]
            paths = [(cpu * scale, e) for cpu, e, _ in paths]
            for r, (cpu, e), t in zip(path_repeats, paths, tails):
                extra = f", 99.9th percentile {t:.1f}x"
                rows.append(f"| {label} | paths{' (x %d pixels)' % scale if finer else ''} | {r} | {cpu:.2f} s | "
                            f"{100 * e:.2f} %{extra} |")
                print(f"  {label}, paths x{r}: {cpu:.2f} s, {100 * e:.2f} %", file=sys.stderr)
            cached = []
            for r, aa in cached_rungs:
                af = os.path.join(tmp, "records.af")
                if finer:
                    values, cpu = rtrace(args.bin, tmp, case, r, ["-aa", aa, "-u+"], rays=finer[0], cache_file=af)
                    values = [values[k] for k in finer[1]]
                else:
                    values, cpu = rtrace(args.bin, tmp, case, r, ["-aa", aa, "-u+"], cache_file=af)
                cached.append((cpu, normalised_rms(values, reference)))
                extra = (f", 99.9th percentile {tail(values, reference):.1f}x, "
                         f"records {os.path.getsize(af) / 1e6:.1f} MB")
                rows.append(f"| {label} | cache -aa {aa} | {r} | {cpu:.2f} s | {100 * cached[-1][1]:.2f} %{extra} |")
                print(f"  {label}, cache -aa {aa} x{r}: {cpu:.2f} s, {100 * cached[-1][1]:.2f} %{extra}",
                      file=sys.stderr)
            series[f"{label}: paths"], series[f"{label}: cache"] = paths, cached
            # The reference's own error: path tracing's at its last rung scaled by √(repeats there / reference's).
            own = paths[-1][1] * (path_repeats[-1] / reference_repeats) ** .5
            target = max(min(e for _, e in paths), min(e for _, e in cached))
            tp, tc = time_to(paths, target), time_to(cached, target)
            ratio = f"{tp / tc:.1f}x" if tp and tc else "n/a"
            summary.append(f"| {label} | {100 * own:.2f} % | {100 * target:.2f} % | "
                           f"{tp or float('nan'):.2f} s | {tc or float('nan'):.2f} s | {ratio} | "
                           f"{extrapolated(paths, cached, own)} |")
    text = (f"# Volume cache: time against error\n\nBrume {git_commit()}, one thread (bench/volume_cache.py; its "
            "docstring says what is measured).\n\n| case | reference's own error | at error | paths | cache | "
            "cache sooner | at the cache's least error, paths extrapolated |\n|---|---|---|---|---|---|---|\n" +
            "\n".join(summary) +
            "\n\n| case | method | repeats | CPU | error |\n|---|---|---|---|---|\n" + "\n".join(rows) + "\n")
    png = f"{args.name}_time_vs_error.png"
    write_result(text, f"{args.name}.md", plot(series, os.path.join(RESULTS, png)), png)


if __name__ == "__main__":
    main()
