#!/usr/bin/env python3
"""vismap: run time against error of a whole floor's visibility study, path tracing against the caches.

Case (../shared/data): the fire hall of make demo (examples/hall) under emergency lighting, its soot at t = 120 s
imported by fds2vdb from the shared FDS case (mesh 2; grey, -g), 100 eyes at 1.7 m every 0.5 m, two signs (one emitting,
one reflecting): 200 sight lines, -ab 1 (the veil and the walls lit once; the caches with -al+, stopping at -ab
as path tracing does).
  paths     -aa 0 (path tracing) at -ad 16, 64, 256, -vr 32 rays to each sign and its band
  cache     the surface and volume caches (-aa .1) at -ad 64, 256, 1024, -vr 32
  rays      the caches at -ad 256 with -vr 8, 32, 128
The reference: path tracing at -ad 1024, -vr 256, on all threads, kept in results/vismap_reference.csv
(--remake-reference makes it again, about 15 CPU minutes). The error of a run: the RMS over the sight lines of
the luminances' relative errors (the sign's and its background's, as the eye receives them; the contrast is near
0 where a sign fades and over 1000 for an emitting sign on a dark wall, so its errors compare badly), and the
share of sight lines whose verdict differs from the reference's (the reference's own noise flips some: those
within its error of the criterion). One thread, CPU seconds (user + system). Writes results/vismap.md and
results/vismap_time_vs_error.png. Skipped without ../shared/data.
"""
import argparse
import csv
import io
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench import ROOT, Timer, git_commit, matplotlib_plot, write_result  # noqa: E402

HALL = os.path.join(ROOT, "examples", "hall")
FDS = os.path.join(ROOT, "..", "shared", "data", "fds", "fdsvismap_room_fire")
STUDY = ["-S", os.path.join(HALL, "signs.txt"), "-g", "10", "0", "15", "5", "0.5", "1.7", "-T", "120", "-ab", "1"]
LADDERS = {
    "paths": [["-aa", "0", "-ad", ad, "-vr", "32"] for ad in ("16", "64", "256")],
    "cache": [["-al+", "-ad", ad, "-vr", "32"] for ad in ("64", "256", "1024")],
    "rays": [["-al+", "-ad", "256", "-vr", vr] for vr in ("8", "32", "128")],
}
REFERENCE = ["-aa", "0", "-ad", "1024", "-vr", "256"]


PLOT = """fig, ax = plt.subplots(figsize=(7, 4.5))
for name, pts in d['series'].items():
    ax.loglog([p[0] for p in pts], [100 * p[1] for p in pts], 'o-', label=name)
ax.set_xlabel('CPU time (s)'); ax.set_ylabel('RMS relative error of the luminances (%)')
ax.set_title('vismap: 200 sight lines, hall, emergency lighting, t = 120 s')
ax.legend(fontsize=8); ax.grid(alpha=.3, which='both')
fig.tight_layout(); fig.savefig(sys.argv[2], dpi=110)
"""
REFERENCE_FILE = os.path.join(HERE, "results", "vismap_reference.csv")


def by_line(text):
    return {(r["observer"], r["sign"]): r for r in csv.DictReader(io.StringIO(text))}


def study(vismap, options, scene, threads=1):
    t = Timer([vismap, *STUDY, *options, "-n", str(threads), *scene], os.devnull)
    return t.cpu, t.out


def reference_rows(vismap, scene, remake):
    """The reference's rows, made again when asked or when the kept one has other options."""
    head = "# " + " ".join(STUDY + REFERENCE) + "\n"
    if not remake and os.path.exists(REFERENCE_FILE):
        with open(REFERENCE_FILE) as f:
            text = f.read()
        if text.startswith(head):
            return None, by_line(text[len(head):])
    cpu, out = study(vismap, REFERENCE, scene, threads=os.cpu_count() or 1)
    os.makedirs(os.path.dirname(REFERENCE_FILE), exist_ok=True)
    with open(REFERENCE_FILE, "w") as f:
        f.write(head + out)
    return cpu, by_line(out)


def errors(rows, reference):
    """The RMS relative error of the two luminances (the sign's and its background's, over all sight lines), and
    the share of verdicts unlike the reference's."""
    sq = 0.0
    for key, ref in reference.items():
        for column in ("sign_cd_m2", "background_cd_m2"):
            sq += (float(rows[key][column]) / float(ref[column]) - 1) ** 2
    differ = sum(rows[key]["verdict"] != ref["verdict"] for key, ref in reference.items())
    return math.sqrt(sq / (2 * len(reference))), differ / len(reference)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    parser.add_argument("--remake-reference", action="store_true")
    args = parser.parse_args()
    if not os.path.exists(os.path.join(FDS, "model.smv")):
        print("vismap bench: no ../shared/data/fds: skipped")
        return
    vismap = os.path.join(args.bin, "vismap")
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "smoke.rad"), "w") as out:
            # Grey soot (-g), as the kept reference was traced before fds2vdb wrote soot's spectrum.
            subprocess.run([os.path.join(args.bin, "fds2vdb"), "-g", "-t", "120", "-o", os.path.join(tmp, "soot"),
                            os.path.join(FDS, "model.smv")], stdout=out, stderr=subprocess.DEVNULL, check=True)
        scene = [os.path.join(HALL, "hall.rad"), os.path.join(HALL, "emergency.rad"), os.path.join(tmp, "smoke.rad")]
        ref_cpu, reference = reference_rows(vismap, scene, args.remake_reference)
        table = ["| ladder | options | CPU s | RMS error of the luminances | verdicts unlike the reference's |",
                 "|---|---|---:|---:|---:|"]
        series = {}
        for name, rungs in LADDERS.items():
            for options in rungs:
                cpu, out = study(vismap, options, scene)
                rms, differ = errors(by_line(out), reference)
                series.setdefault(name, []).append((cpu, rms))
                table.append(f"| {name} | `{' '.join(options)}` | {cpu:.1f} | {100 * rms:.2f} % | {100 * differ:.1f} % |")
                print(table[-1], file=sys.stderr)
        visible = sum(r["verdict"] == "visible" for r in reference.values())
        text = "\n".join([
            "# vismap: a floor's visibility study, time against error (bench/vismap.py)",
            "",
            f"Brume {git_commit()}. The fire hall of examples/hall under emergency lighting at t = 120 s, 100 eyes x 2 "
            f"signs, -ab 1. Reference: `{' '.join(REFERENCE)}`"
            + (f" ({ref_cpu:.0f} CPU s on all threads)" if ref_cpu else " (kept in results/vismap_reference.csv)")
            + f"; its verdicts: {visible} of {len(reference)} sight lines visible by the light.",
            "",
            *table,
            "",
        ])
        plotted = matplotlib_plot(PLOT, {"series": series}, os.path.join(HERE, "results", "vismap_time_vs_error.png"))
        write_result(text, "vismap.md", plotted, "vismap_time_vs_error.png")


if __name__ == "__main__":
    main()
