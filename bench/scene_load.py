#!/usr/bin/env python3
"""Scene loading: time and peak memory of Brume's and Radiance's rtrace for a 1M-triangle mesh and for 1000
instances of an octree (see README.md). Usage: python3 bench/scene_load.py --bin BIN_DIR [--triangles N]
[--instances N] [--keep DIR]. Radiance's columns need $RADIANCE_BIN (or /tmp/radiance/bin) with obj2mesh,
oconv and rtrace. Each rtrace traces one ray that meets the geometry, so Radiance loads it too (it reads
meshes and instanced octrees when a ray first needs them)."""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile


def write_terrain(path, triangles):
    """A height field of about `triangles` triangles over 100 x 100, with vertex normals and (u, v)."""
    n = max(2, int(math.sqrt(triangles / 2)))
    with open(path, "w") as f:
        f.write("# terrain for bench/scene_load.py\nusemtl ground\n")
        for j in range(n + 1):
            for i in range(n + 1):
                x, y = 100.0 * i / n, 100.0 * j / n
                f.write(f"v {x:.6f} {y:.6f} {math.sin(x / 7) * math.cos(y / 5):.6f}\n")
        for j in range(n + 1):
            for i in range(n + 1):
                x, y = 100.0 * i / n, 100.0 * j / n
                gx, gy = math.cos(x / 7) * math.cos(y / 5) / 7, -math.sin(x / 7) * math.sin(y / 5) / 5
                f.write(f"vn {-gx:.6f} {-gy:.6f} 1\nvt {i / n:.6f} {j / n:.6f}\n")
        for j in range(n):
            for i in range(n):
                a = j * (n + 1) + i + 1
                b, c, d = a + 1, a + n + 2, a + n + 1
                f.write(f"f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}\nf {a}/{a}/{a} {c}/{c}/{c} {d}/{d}/{d}\n")
    return 2 * n * n


def write_piece(path):
    """An object to instance: a faceted ball of 120 x 60 quads on a box, 7206 polygons; returns the count."""
    with open(path, "w") as f:
        f.write("void plastic paint 0 0 5 .6 .5 .4 0 0\n")
        rows, cols = 60, 120
        for r in range(rows):
            for c in range(cols):
                def p(rr, cc):
                    t, a = math.pi * rr / rows, 2 * math.pi * cc / cols
                    return (.4 * math.sin(t) * math.cos(a), .4 * math.sin(t) * math.sin(a), .9 + .4 * math.cos(t))
                q = [p(r, c), p(r + 1, c), p(r + 1, c + 1), p(r, c + 1)]
                f.write(f"paint polygon f{r}_{c} 0 0 12 " + " ".join(f"{v:.12f}" for pt in q for v in pt) + "\n")
        box = [((-.5, -.5, 0), (.5, -.5, 0), (.5, .5, 0), (-.5, .5, 0)), ((-.5, -.5, .5), (-.5, .5, .5), (.5, .5, .5), (.5, -.5, .5))]
        for k, q in enumerate(box):
            f.write(f"paint polygon box{k} 0 0 12 " + " ".join(f"{v}" for pt in q for v in pt) + "\n")
        for k in range(4):
            a0, a1 = math.pi / 2 * k, math.pi / 2 * (k + 1)
            c0 = (math.sqrt(.5) * math.cos(a0 + math.pi / 4), math.sqrt(.5) * math.sin(a0 + math.pi / 4))
            c1 = (math.sqrt(.5) * math.cos(a1 + math.pi / 4), math.sqrt(.5) * math.sin(a1 + math.pi / 4))
            q = [(c0[0], c0[1], 0), (c1[0], c1[1], 0), (c1[0], c1[1], .5), (c0[0], c0[1], .5)]
            f.write(f"paint polygon side{k} 0 0 12 " + " ".join(f"{v:.6f}" for pt in q for v in pt) + "\n")
    return rows * cols + 6


LIGHT = "void light sky 0 0 3 1 1 1\nsky source sun 0 0 4 .3 .2 1 10\n"


def measure(cmd, cwd, stdin_text="", env=None, output=None):
    """Wall seconds and peak resident MB of a command (GNU time -v); its output goes to file `output`."""
    full = ["/usr/bin/time", "-v"] + cmd
    with open(os.path.join(cwd, output) if output else os.devnull, "wb") as out:
        p = subprocess.run(full, cwd=cwd, input=stdin_text.encode(), stdout=out, stderr=subprocess.PIPE, env=env)
    p.stderr = p.stderr.decode(errors="replace")
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed:\n{p.stderr[-2000:]}")
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", p.stderr)
    h, m, s = wall.groups()
    seconds = 3600 * int(h or 0) + 60 * int(m) + float(s)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr).group(1)) / 1024
    return seconds, rss


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--bin", default="build/bin")
    ap.add_argument("--triangles", type=int, default=1_000_000)
    ap.add_argument("--instances", type=int, default=1000)
    ap.add_argument("--keep", help="work in this directory and keep it")
    args = ap.parse_args()
    brume = os.path.abspath(os.path.join(args.bin, "rtrace"))
    rad_bin = os.environ.get("RADIANCE_BIN", "/tmp/radiance/bin")
    have_radiance = all(os.access(os.path.join(rad_bin, t), os.X_OK) for t in ("obj2mesh", "oconv", "rtrace"))
    rad_env = dict(os.environ, RAYPATH=".:" + os.environ.get("RADIANCE_LIB", os.path.join(rad_bin, "..", "lib")))
    work = args.keep or tempfile.mkdtemp(prefix="brume_load_")
    os.makedirs(work, exist_ok=True)
    rad = lambda tool: os.path.join(rad_bin, tool)
    print(f"# scene loading, load average {os.getloadavg()[0]:.2f}, in {work}")

    triangles = write_terrain(os.path.join(work, "terrain.obj"), args.triangles)
    with open(os.path.join(work, "terrain_obj.rad"), "w") as f:
        f.write(LIGHT + "void plastic ground 0 0 5 .3 .3 .3 0 0\nvoid mesh terrain 1 terrain.obj\n0\n0\n")
    polygons = write_piece(os.path.join(work, "piece.rad"))
    side = math.ceil(math.sqrt(args.instances))
    with open(os.path.join(work, "crowd.rad"), "w") as f:
        f.write(LIGHT + "void plastic floor 0 0 5 .3 .3 .3 0 0\n")
        f.write(f"floor polygon ground 0 0 12 -1 -1 0 {2 * side} -1 0 {2 * side} {2 * side} 0 -1 {2 * side} 0\n")
        for k in range(args.instances):
            f.write(f"void instance p{k} 7 piece.oct -rz {k % 360} -t {2 * (k % side)} {2 * (k // side)} 0\n0\n0\n")
    terrain_ray = "50.3 50.2 10 0 0 -1\n"
    crowd_ray = "0.05 0.02 5 0 0 -1\n"  # onto the first ball

    rows = []  # (what, program, step, seconds, MB)
    with open(os.path.join(work, "ground.rad"), "w") as f:
        f.write("void plastic ground 0 0 5 .3 .3 .3 0 0\n")
    if have_radiance:
        rows.append(("mesh", "Radiance", "obj2mesh", *measure([rad("obj2mesh"), "-a", "ground.rad", "terrain.obj", "terrain.rtm"], work, env=rad_env)))
        with open(os.path.join(work, "terrain_rtm.rad"), "w") as f:
            f.write(LIGHT + "void mesh terrain 1 terrain.rtm\n0\n0\n")
        rows.append(("mesh", "Radiance", "oconv", *measure([rad("oconv"), "terrain_rtm.rad"], work, env=rad_env, output="terrain.oct")))
        rows.append(("mesh", "Radiance", "rtrace .oct", *measure([rad("rtrace"), "-h", "-ab", "0", "terrain.oct"], work, terrain_ray, rad_env)))
        rows.append(("mesh", "Brume", "rtrace .rtm", *measure([brume, "-h", "-ab", "0", "terrain_rtm.rad"], work, terrain_ray)))
    rows.append(("mesh", "Brume", "rtrace .obj", *measure([brume, "-h", "-ab", "0", "terrain_obj.rad"], work, terrain_ray)))

    if have_radiance:
        subprocess.run([rad("oconv"), "-f", "piece.rad"], cwd=work, env=rad_env, check=True,
                       stdout=open(os.path.join(work, "piece.oct"), "wb"))
        rows.append(("instances", "Radiance", "oconv", *measure([rad("oconv"), "crowd.rad"], work, env=rad_env, output="crowd.oct")))
        rows.append(("instances", "Radiance", "rtrace .oct", *measure([rad("rtrace"), "-h", "-ab", "0", "crowd.oct"], work, crowd_ray, rad_env)))
        rows.append(("instances", "Brume", "rtrace .rad", *measure([brume, "-h", "-ab", "0", "crowd.rad"], work, crowd_ray)))
        rows.append(("instances", "Brume", "rtrace .oct", *measure([brume, "-h", "-ab", "0", "crowd.oct"], work, crowd_ray)))
        with open(os.path.join(work, "one.rad"), "w") as f:
            f.write(LIGHT + "void instance p 1 piece.oct\n0\n0\n")
        rows.append(("1 instance", "Brume", "rtrace .rad", *measure([brume, "-h", "-ab", "0", "one.rad"], work, crowd_ray)))
    else:
        print("# Radiance not found: its columns and the instance scenes (which need its oconv) are skipped")

    print(f"# mesh: {triangles} triangles with normals and uv; instances: {args.instances} of an octree of {polygons} polygons")
    print(f"{'scene':<11} {'program':<9} {'step':<12} {'wall s':>8} {'peak MB':>8}")
    for what, prog, step, s, mb in rows:
        print(f"{what:<11} {prog:<9} {step:<12} {s:>8.2f} {mb:>8.1f}")
    peak = {(w, p, st): mb for w, p, st, _, mb in rows}
    if ("instances", "Brume", "rtrace .rad") in peak:
        extra = peak[("instances", "Brume", "rtrace .rad")] - peak[("1 instance", "Brume", "rtrace .rad")]
        print(f"# Brume: {1024 * extra / (args.instances - 1):.1f} KB of peak memory per instance beyond the first")
    if not args.keep:
        shutil.rmtree(work)


if __name__ == "__main__":
    sys.exit(main())
