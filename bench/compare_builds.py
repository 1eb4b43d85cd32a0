#!/usr/bin/env python3
"""Two builds of Brume on the same work: is one slower than the other?

    python3 bench/compare_builds.py BIN_A BIN_B [--repeat 5] [--skip-callgrind] [--skip-wall]

For a refactor that must not slow anything down (its outputs are checked by test/same_outputs.sh). Each
workload runs the programs of BIN_A and BIN_B on the same input, one thread:
  - instructions: callgrind's count (valgrind), on a small version of the workload: the same count for the
    same binary and input whatever else the machine does, so a difference of 0.1% is real;
  - wall time: the bench-sized workload, A and B alternated `--repeat` times, the median of each (the machine
    is shared and noisy: only the ratio in one run means anything).
Workloads: the office's view rays (-ab 0; -ab 1 -aa 0), its sensor grid (path tracing, and the irradiance
cache's defaults), an rpict picture with the cache, 41 bands, the corridor's FDS soot (-ab 0 and -ab 1 at
t = 120 s; needs ../shared/data), and a mist (test/data/media). Prints a table, writes
results/compare_builds.md and results/compare_builds.png (B against A in %).
"""
import argparse
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench import RESULTS, ROOT, matplotlib_plot, view_rays, write_result  # noqa: E402

OFFICE = os.path.join(ROOT, "examples", "office")
CORRIDOR = os.path.join(ROOT, "examples", "corridor")
SOOT = os.path.join(ROOT, "..", "shared", "data", "vdb", "fds_room_fire_mesh2_soot")
MEDIA = os.path.join(ROOT, "test", "data", "media")
VIEW = "-vp 0.3 0.3 1.6 -vd 1 0.8 -0.3 -vh 75 -vv 55".split()


def corridor_rays(path, n):
    """n rays from the corridor's near end toward the exit sign, fanned over 70° × 50°."""
    with open(path, "w") as f:
        for i in range(n):
            a, b = (i % 8) / 7 - 0.5, (i // 8 % 6) / 5 - 0.5
            f.write("10.3 3 1.6 1 %.4f %.4f\n" % (0.7 * a, 0.5 * b))


def workloads(tmp):
    """(name, program, arguments, stdin, working folder, env, the small version's stdin and arguments)."""
    office = os.path.join(OFFICE, "office.rad")
    grid = os.path.join(OFFICE, "grid.txt")
    v100k, v2k, v10k, v500 = (os.path.join(tmp, n) for n in ("v100k", "v2k", "v10k", "v500"))
    view_rays(v100k, 100000)
    view_rays(v2k, 2000)
    view_rays(v10k, 10000, seed=2)
    view_rays(v500, 500, seed=2)
    grid12 = os.path.join(tmp, "grid12")
    with open(grid) as f, open(grid12, "w") as g:
        g.writelines([line for line in f if line.split()][:12])
    rpict = ["-ab", "1"] + VIEW + [office]
    c = os.path.join(MEDIA, "c_rays.txt")
    mist = ["-h", "-ab", "1", "-ad", "64", "-ms", ".01", "expanded/c_list.rad"]
    out = [
        ("office view rays -ab 0", "rtrace", ["-h", "-ab", "0", office], v100k, OFFICE, None, v2k, None),
        ("office view rays -ab 1 -aa 0 -ad 64", "rtrace", ["-h", "-ab", "1", "-aa", "0", "-ad", "64", office],
         v10k, OFFICE, None, v500, None),
        ("office grid -I -ab 5 -aa 0 -ad 512", "rtrace",
         ["-h", "-I", "-ab", "5", "-aa", "0", "-ad", "512", "-lw", "1e-5", office], grid, OFFICE, None, grid12, None),
        ("office grid -I -ab 5 (defaults)", "rtrace", ["-h", "-I", "-ab", "5", office], grid, OFFICE, None,
         grid12, None),
        ("office grid -I -ab 2 -cs 41", "rtrace", ["-h", "-I", "-ab", "2", "-cs", "41", office], grid, OFFICE,
         None, grid12, None),
        ("office rpict 160x120 -ab 1 (cache)", "rpict", ["-x", "160", "-y", "120"] + rpict, None, OFFICE, None,
         None, ["-x", "40", "-y", "30"] + rpict),
        ("mist (test/data/media c_list) -ab 1", "rtrace", mist, c, MEDIA, None, c, None),
    ]
    if os.path.isdir(SOOT):
        c480, c48 = os.path.join(tmp, "c480"), os.path.join(tmp, "c48")
        corridor_rays(c480, 480)
        corridor_rays(c48, 48)
        env = dict(os.environ, RAYPATH=SOOT + ":.")
        for ab in ("0", "1"):
            out.append(("corridor soot t=120 -ab %s" % ab, "rtrace",
                        ["-h", "-ab", ab, "-ad", "64", "-ms", ".05", "-T", "120", "corridor.rad", "smoke.rad"],
                        c480, CORRIDOR, env, c48, None))
    return out


def run(binary, args, stdin, cwd, env):
    with open(stdin) if stdin else open(os.devnull) as f:
        subprocess.run([binary] + args, stdin=f, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=cwd,
                       env=env, check=True)


def instructions(binary, args, stdin, cwd, env, tmp):
    """callgrind's total instruction count of one run (-u-: the same samples every time)."""
    log = os.path.join(tmp, "callgrind.out")
    with open(stdin) if stdin else open(os.devnull) as f:
        subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + log, binary, "-u-", "-n", "1"] + args,
                       stdin=f, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=cwd, env=env, check=True)
    with open(log) as f:
        for line in f:
            if line.startswith("summary:") or line.startswith("totals:"):
                return int(line.split()[1])
    raise RuntimeError("no instruction count in " + log)


def wall_times(bins, prog, args, stdin, cwd, env, repeat):
    times = {b: [] for b in bins}
    for _ in range(repeat):
        for b in bins:
            t = time.perf_counter()
            run(os.path.join(b, prog), ["-u-", "-n", "1"] + args, stdin, cwd, env)
            times[b].append(time.perf_counter() - t)
    return [statistics.median(times[b]) for b in bins]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--skip-callgrind", action="store_true")
    ap.add_argument("--skip-wall", action="store_true")
    o = ap.parse_args()
    bins = [os.path.abspath(o.a), os.path.abspath(o.b)]
    callgrind = not o.skip_callgrind and shutil.which("valgrind")
    if not o.skip_callgrind and not callgrind:
        print("valgrind not found: instruction counts skipped")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, prog, args, stdin, cwd, env, small, small_args in workloads(tmp):
            ia = ib = None
            if callgrind:
                ia, ib = (instructions(os.path.join(b, prog), small_args or args, small, cwd, env, tmp) for b in bins)
            ta = tb = None
            if not o.skip_wall:
                ta, tb = wall_times(bins, prog, args, stdin, cwd, env, o.repeat)
            rows.append((name, ia, ib, ta, tb))
            print(row_text(rows[-1]), flush=True)
    text = table(rows, bins, o.repeat)
    plotted = plot(rows)
    write_result(text, "compare_builds.md", plotted, "compare_builds.png")


def row_text(r):
    name, ia, ib, ta, tb = r
    ins = "%14d %14d %8.4f" % (ia, ib, ib / ia) if ia else "%14s %14s %8s" % ("-", "-", "-")
    wall = "%8.2f %8.2f %7.3f" % (ta, tb, tb / ta) if ta else "%8s %8s %7s" % ("-", "-", "-")
    return "| %-40s | %s | %s |" % (name, ins.replace(" ", " ", 1), wall)


def table(rows, bins, repeat):
    head = ("A = %s, B = %s; one thread; instructions: callgrind on a small version of each workload; wall: "
            "median of %d alternated runs, seconds\n\n" % (bins[0], bins[1], repeat))
    head += "| %-40s | %14s %14s %8s | %8s %8s %7s |\n" % ("workload", "instr. A", "instr. B", "B/A", "wall A",
                                                          "wall B", "B/A")
    head += "|" + "-" * 42 + "|" + "-" * 40 + "|" + "-" * 27 + "|\n"
    return head + "\n".join(row_text(r) for r in rows) + "\n"


def plot(rows):
    names = [r[0] for r in rows]
    ins = [r[2] / r[1] if r[1] else math.nan for r in rows]
    wall = [r[4] / r[3] if r[3] else math.nan for r in rows]
    script = """
names, ins, wall, png = d["names"], d["ins"], d["wall"], sys.argv[2]
fig, ax = plt.subplots(figsize=(8, 0.45 * len(names) + 1.2))
y = range(len(names))
ax.barh([i - 0.2 for i in y], [100 * (r - 1) for r in ins], height=0.4, label="instructions (callgrind)")
ax.barh([i + 0.2 for i in y], [100 * (r - 1) for r in wall], height=0.4, label="wall time (median)")
ax.axvline(0, color="k", lw=0.8)
ax.set_yticks(list(y))
ax.set_yticklabels(names, fontsize=8)
ax.invert_yaxis()
ax.set_xlabel("build B against build A, % (0: no change; > 0: B slower)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(png, dpi=110)
"""
    return matplotlib_plot(script, {"names": names, "ins": ins, "wall": wall},
                           os.path.join(RESULTS, "compare_builds.png"))


if __name__ == "__main__":
    main()
