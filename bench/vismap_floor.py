#!/usr/bin/env python3
"""vismap over a whole floor, as FDSVisMap studies it: where the time goes, and how long against FDSVisMap.

Case (../shared/data): the shared FDS case (FDSVisMap's room fire, 20 m x 10 m, eight meshes, only mesh 2 with 3D
smoke), its building from its own input (fds2rad: walls less doors), its soot at ten instants (0 to 180 s every
20 s) from fds2vdb with the 2.05 m slice filled over 1.5-2.5 m in the meshes without 3D smoke (-l), three signs
placed by position (an exit sign over the hall's north door, one over the door between the rooms and the hall,
both emitting, and a reflecting plan on the hall's south wall), eyes at 1.7 m:
  import        fds2vdb: the ten instants' grids (reading the .smv, the .s3d and the slices, writing OpenVDB)
  jin 0.1 m     vismap -vj (Jin's law alone, FDSVisMap's question): 20,000 cells of 0.1 m, 600,000 sight lines
  jin 0.1 m -vf the same with FDSVisMap's view-angle factor and 30 m cap (-vf -vx 30)
  light 0.5 m   vismap by the light (Adrian's visibility level, -ab 0: the luminaires' light through the smoke, its
                veil): 800 cells of 0.5 m, ten instants, -vr 32
  light -ab 1   the same at -ab 1 with the caches (-aa .1 -ad 256), three instants (60, 120, 180 s)
On two threads (-n 2), wall and CPU seconds; each vismap run once, its grids read included. FDSVisMap's own
figure for its full run on the same case (reading included, two cores) is about 40 s (issue 39; FDSVisMap is on
PyPI, which this machine cannot reach). Writes results/vismap_floor.md and results/vismap_floor.png.
"""
import argparse
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench import ROOT, Timer, git_commit, matplotlib_plot, write_result  # noqa: E402

FDS = os.path.join(ROOT, "..", "shared", "data", "fds", "fdsvismap_room_fire")
LIGHTS = os.path.join(ROOT, "examples", "hall", "lights.rad")
INSTANTS = ",".join(str(t) for t in range(0, 181, 20))
SIGNS = """# name      centre           front    width height kind       L|rho
north_exit  17.47 10 2.35     0 -1 0   0.4   0.2    emitting   150
door_exit   10 3.87 2.35      1 0 0    0.4   0.2    emitting   150
plan        12.5 0 1.5        0 1 0    0.4   0.3    reflecting 0.8
"""
FLOOR = ["-g", "0", "0", "20", "10", "0.1", "1.7"]
COARSE = ["-g", "0", "0", "20", "10", "0.5", "1.7"]
RUNS = [
    ("jin 0.1 m", FLOOR + ["-vj", "-T", INSTANTS]),
    ("jin 0.1 m -vf -vx 30", FLOOR + ["-vj", "-vf", "-vx", "30", "-T", INSTANTS]),
    ("light 0.5 m, -ab 0", COARSE + ["-ab", "0", "-vr", "32", "-T", INSTANTS]),
    ("light 0.5 m, -ab 1, caches", COARSE + ["-ab", "1", "-aa", ".1", "-ad", "256", "-vr", "32", "-T", "60,120,180"]),
]
PLOT = """fig, ax = plt.subplots(figsize=(7, 3.5))
names = [r[0] for r in d['rows']]
ax.barh(names, [r[1] for r in d['rows']], color='C0', label='wall s, two threads')
ax.axvline(40, color='C3', ls='--', label="FDSVisMap's full run (about 40 s)")
ax.set_xscale('log'); ax.set_xlabel('seconds'); ax.invert_yaxis()
ax.set_title('vismap on the shared FDS case, whole floor'); ax.legend(fontsize=8)
fig.tight_layout(); fig.savefig(sys.argv[2], dpi=110)
"""


def lines_of(path):
    with open(path) as f:
        return sum(1 for _ in f) - 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    args = ap.parse_args()
    if not os.path.exists(os.path.join(FDS, "model.smv")):
        print("vismap floor bench: no ../shared/data/fds: skipped")
        return
    commit = git_commit()
    rows, table = [], []
    with tempfile.TemporaryDirectory() as tmp:
        placed, signs, building = (os.path.join(tmp, n) for n in ("placed.txt", "signs.txt", "building.rad"))
        with open(placed, "w") as f:
            f.write(SIGNS)
        Timer([os.path.join(args.bin, "fds2rad"), "-s", placed, "-S", signs, os.path.join(FDS, "model.fds")],
              os.devnull, out_path=building)
        smoke = os.path.join(tmp, "smoke.rad")
        t = Timer([os.path.join(args.bin, "fds2vdb"), "-t", INSTANTS, "-l", "1.5,2.5", "-o", os.path.join(tmp, "soot"),
                   os.path.join(FDS, "model.smv")], os.devnull, out_path=smoke)
        rows.append(("import (fds2vdb, ten instants)", t.wall))
        table.append(f"| import (fds2vdb, ten instants) | | {t.wall:.1f} | {t.cpu:.1f} | |")
        print(f"  import: {t.wall:.1f} s", file=sys.stderr)
        for name, options in RUNS:
            out = os.path.join(tmp, "sight.csv")
            t = Timer([os.path.join(args.bin, "vismap"), "-S", signs, "-n", "2", *options, building, LIGHTS, smoke],
                      os.devnull, out_path=out)
            n = lines_of(out)
            rows.append((name, t.wall))
            table.append(f"| {name} | {n:,} | {t.wall:.1f} | {t.cpu:.1f} | {n / t.wall:,.0f} |")
            print(f"  {name}: {n} sight lines, {t.wall:.1f} s", file=sys.stderr)
    text = (f"# vismap over a whole floor\n\nBrume {commit}, two threads (bench/vismap_floor.py; its docstring says "
            "what runs). FDSVisMap's full run on this case: about 40 s on two cores.\n\n"
            "| run | sight lines | wall s | CPU s | lines per wall s |\n|---|---|---|---|---|\n" + "\n".join(table) + "\n")
    write_result(text, "vismap_floor.md",
                 matplotlib_plot(PLOT, {"rows": rows}, os.path.join(HERE, "results", "vismap_floor.png")),
                 "vismap_floor.png")


if __name__ == "__main__":
    main()
