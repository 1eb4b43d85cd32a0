#!/usr/bin/env python3
"""Cost of spectral rendering: the example office at -cs 3 (RGB), 12, 24, 41 and 81 bands, as time against RGB's.

Workloads, one thread each (CPU seconds; the fastest of --repeat runs):
  grid     rtrace -I -ab 3 -aa 0 -ad 4096 on the 96 sensors (path tracing)
  cache    rtrace -I -ab 5 on the 96 sensors (Brume's defaults: the irradiance cache)
  picture  rpict -ab 1 -x 240 -y 180, the seated view (the cache, rpict's defaults)
  start    rtrace on one ray: loading the scene and, with bands, fitting the RGB-to-spectrum table
With Radiance found (bench.py's rules), its rtrace on the grid workload at -cs 3 and -cs 24 for comparison.
Writes results/spectral.md and results/spectral_cost.png. Goal (issue 7): 41 bands within 2x RGB's time.
"""
import argparse
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench import GRID, ROOT, SCENE, Timer, best_of, find_radiance, frozen_octree, git_commit, matplotlib_plot, write_result  # noqa: E402

BANDS = [3, 12, 24, 41, 81]
SEATED = ["-vp", "0.3", "0.3", "1.6", "-vd", "1", "0.8", "-0.3", "-vh", "75", "-vv", "55"]
WORKLOADS = {  # name: (program, options, standard input)
    "grid": ("rtrace", ["-h", "-I", "-ab", "3", "-aa", "0", "-ad", "4096", "-u-"], GRID),
    "cache": ("rtrace", ["-h", "-I", "-ab", "5", "-aS", "0", "-u-"], GRID),  # -aS 0: the sensors take records
    "picture": ("rpict", ["-ab", "1", "-x", "240", "-y", "180"] + SEATED, os.devnull),
    "start": ("rtrace", ["-h", "-ab", "0"], None),
}
RESULTS = os.path.join(HERE, "results")


def one_ray(tmp):
    path = os.path.join(tmp, "ray.txt")
    with open(path, "w") as f:
        f.write("4.5 3.2 1.2 0 1 0\n")
    return path


def measure(bin_dir, repeat, tmp):
    times = {}
    for name, (prog, opts, stdin) in WORKLOADS.items():
        for n in BANDS:
            cmd = [os.path.join(bin_dir, prog), "-n", "1", "-cs", str(n)] + opts + [SCENE]
            _, cpu = best_of(repeat, cmd, stdin or one_ray(tmp))
            times[name, n] = cpu
            print(f"  {name:8s} -cs {n:2d}: {cpu:7.2f} s", file=sys.stderr)
    return times


def radiance_times(rad, repeat, tmp):
    if not rad:
        return None
    octree = frozen_octree(rad, tmp)
    prog, opts, stdin = WORKLOADS["grid"]
    out = {}
    for n in (3, 24):
        cmd = [rad["rtrace"], "-n", "1", "-cs", str(n)] + opts + ["-as", "0", octree]
        _, out[n] = best_of(repeat, cmd, stdin, rad["env"])
    return out


def table(times, rad):
    lines = ["| workload | " + " | ".join(f"-cs {n}" for n in BANDS) + " |",
             "|---|" + "---|" * len(BANDS)]
    for name in WORKLOADS:
        base = times[name, 3]
        cells = [f"{times[name, n]:.2f} s" + ("" if n == 3 else f" ({times[name, n] / base:.2f}x)") for n in BANDS]
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    if rad:
        lines.append(f"| Radiance grid (-as 0) | {rad[3]:.2f} s | | {rad[24]:.2f} s ({rad[24] / rad[3]:.2f}x) | | |")
    return "\n".join(lines)


def plot(times, png):
    script = (
        "bands = d['bands']\n"
        "fig, ax = plt.subplots(figsize=(6, 4))\n"
        "for name, ratios in d['ratios'].items(): ax.plot(bands, ratios, 'o-', label=name)\n"
        "ax.axhline(2, color='grey', ls='--', lw=1, label='goal at 41 bands: 2x')\n"
        "ax.set_xlabel('bands (-cs)'); ax.set_ylabel('CPU time / RGB time'); ax.set_xticks(bands)\n"
        "ax.set_title('Brume, example office: cost of spectral bands'); ax.legend(); ax.grid(alpha=.3)\n"
        "fig.tight_layout(); fig.savefig(sys.argv[2], dpi=110)\n")
    data = {"bands": BANDS, "ratios": {name: [times[name, n] / times[name, 3] for n in BANDS]
                                       for name in WORKLOADS if name != "start"}}
    return matplotlib_plot(script, data, png)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        times = measure(args.bin, args.repeat, tmp)
        rad = radiance_times(find_radiance(), args.repeat, tmp)
    text = (f"# Spectral rendering: CPU time against bands\n\nBrume {git_commit()}, one thread, fastest of "
            f"{args.repeat} runs (bench/spectral.py; times are CPU seconds, ratios against -cs 3).\n\n"
            + table(times, rad) + "\n")
    write_result(text, "spectral.md", plot(times, os.path.join(RESULTS, "spectral_cost.png")), "spectral_cost.png")


if __name__ == "__main__":
    main()
