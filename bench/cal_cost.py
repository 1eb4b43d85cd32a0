#!/usr/bin/env python3
"""The cost of .cal evaluation per ray: rtrace on two patterned scenes against the same scenes with the patterns
taken out, Brume against Radiance, one thread each (see README.md). Usage: python3 bench/cal_cost.py --bin BIN_DIR
[--repeat N]. Radiance's columns need $RADIANCE_BIN (or /tmp/radiance/bin) with oconv and rtrace, and its
library ($RADIANCE_LIB or <bin>/../lib) for skybright.cal."""
import argparse
import os
import random
import resource
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PATTERNS = os.path.join(ROOT, "test", "data", "patterns")
PATTERN_TYPES = {"brightfunc", "colorfunc", "texfunc", "brightdata", "colordata", "texdata", "colorpict"}
MIXTURE_TYPES = {"mixfunc", "mixdata", "mixpict"}

# Outdoors under gensky's clear sky: a ground plane; each sensor's -ab 1 rays meet the sky, whose brightness
# skybright.cal gives (in the plain scene the sky is one colour).
SKY = """!gensky 3 21 12 -a 45.5 -o 0.5 -m 0 +s
skyfunc glow sky_glow 0 0 4 .9 .9 1.15 0
sky_glow source sky 0 0 4 0 0 1 180
void plastic grass 0 0 5 .2 .3 .1 0 0
grass polygon ground 0 0 12  -50 -50 0  50 -50 0  50 50 0  -50 50 0
"""


def without_patterns(text):
    """The scene with its patterns, textures and mixtures taken out: a surface or material modified by a pattern
    takes the pattern's own modifier, one modified by a mixture the mixture's foreground (its background if the
    foreground is void). The
    scene must hold one primitive per line, as test/data/patterns/patterns.rad does."""
    replaced, lines = {}, []
    resolve = lambda name: resolve(replaced[name]) if name in replaced else name
    for line in text.splitlines():
        words = line.split()
        if len(words) > 3 and words[1] in PATTERN_TYPES:
            replaced[words[2]] = words[0]
        elif len(words) > 4 and words[1] in MIXTURE_TYPES:
            replaced[words[2]] = words[4] if words[4] != "void" else words[5]
        else:
            if words and not line.startswith(("#", "!")):
                words[0] = resolve(words[0])
                line = " ".join(words)
            lines.append(line)
    return "\n".join(lines) + "\n"


def patterns_rays(count):
    """`count` view rays: test/data/patterns/rays.txt (one per panel, light and sky) over and over."""
    with open(os.path.join(PATTERNS, "rays.txt")) as f:
        rays = [" ".join(l.split()[1:7]) for l in f if l.strip() and not l.startswith("#")]
    return "".join(rays[i % len(rays)] + "\n" for i in range(count))


def sky_sensors(count):
    """`count` upward sensors scattered on the ground (a fixed seed)."""
    rng = random.Random(7)
    return "".join(f"{rng.uniform(-20, 20):.3f} {rng.uniform(-20, 20):.3f} 0.01 0 0 1\n" for _ in range(count))


def cpu_seconds(commands, cwd, rays, env, repeat):
    """CPU time (user + system) of the fastest of `repeat` runs of each command, the commands run in turn so
    that changes in the machine's load reach them alike."""
    best = [float("inf")] * len(commands)
    for _ in range(repeat):
        for i, cmd in enumerate(commands):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            p = subprocess.run(cmd, cwd=cwd, input=rays.encode(), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               env=env)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            if p.returncode != 0:
                raise RuntimeError(f"{' '.join(cmd)} failed:\n{p.stderr.decode(errors='replace')[-2000:]}")
            best[i] = min(best[i], after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return best


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    ap.add_argument("--repeat", type=int, default=5, help="runs per measurement (the fastest is kept)")
    args = ap.parse_args()
    brume = os.path.abspath(os.path.join(args.bin, "rtrace"))
    rad_bin = os.environ.get("RADIANCE_BIN", "/tmp/radiance/bin")
    have_radiance = all(os.access(os.path.join(rad_bin, t), os.X_OK) for t in ("oconv", "rtrace"))
    rad_lib = os.environ.get("RADIANCE_LIB", os.path.join(rad_bin, "..", "lib"))
    # Radiance's own gensky must answer its !gensky lines; Brume runs its own whatever PATH says.
    rad_env = dict(os.environ, RAYPATH=".:" + rad_lib, PATH=rad_bin + ":" + os.environ["PATH"])
    brume_env = dict(os.environ, RAYPATH=".")
    work = tempfile.mkdtemp(prefix="brume_cal_")
    for name in os.listdir(PATTERNS):  # the function files, data files and picture
        shutil.copy(os.path.join(PATTERNS, name), work)
    with open(os.path.join(PATTERNS, "patterns.rad")) as f:
        panels = f.read()
    # The panels' patterns alone: the luminaire's light distribution (a brightdata that every shadow ray toward
    # the luminaire evaluates, and Brume takes more of those than Radiance) taken out too.
    surfaces = panels.replace("ldist light lamp", "void light lamp")
    scenes = {"panels": panels, "panels_plain": without_patterns(panels),
              "surfaces": surfaces, "surfaces_plain": without_patterns(surfaces),
              "sky": SKY, "sky_plain": SKY.replace("skyfunc glow", "void glow")}
    for name, text in scenes.items():
        with open(os.path.join(work, name + ".rad"), "w") as f:
            f.write(text)
        if have_radiance:
            with open(os.path.join(work, name + ".oct"), "wb") as out:
                subprocess.run([os.path.join(rad_bin, "oconv"), name + ".rad"], cwd=work, env=rad_env, check=True,
                               stdout=out)

    cases = [  # (scene, options, rays, count, what a ray meets)
        ("panels", ["-ab", "0"], patterns_rays(500_000), 500_000, "view rays -ab 0: patterned panels, luminaire, sky"),
        ("surfaces", ["-ab", "0"], patterns_rays(500_000), 500_000, "the same without the luminaire's brightdata"),
        ("sky", ["-I", "-ab", "1", "-aa", "0", "-ad", "256", "-as", "0"], sky_sensors(5000), 5000 * 256,
         "sensors -I -ab 1 -ad 256: gensky sky (skybright.cal)"),
    ]
    print(f"# .cal evaluation cost, one thread, fastest of {args.repeat}, load average {os.getloadavg()[0]:.2f}")
    print(f"{'scene':<8} {'program':<9} {'patterned s':>11} {'plain s':>8} {'ratio':>6} {'extra µs/ray':>12}")
    programs = [("Brume", [brume, "-h", "-n", "1"], ".rad", brume_env)]
    if have_radiance:
        programs.append(("Radiance", [os.path.join(rad_bin, "rtrace"), "-h"], ".oct", rad_env))
    for scene, opts, rays, count, what in cases:
        print(f"# {scene}: {what}; {count} rays")
        for program, rtrace, ext, env in programs:
            patterned, plain = cpu_seconds([rtrace + opts + [scene + ext], rtrace + opts + [scene + "_plain" + ext]],
                                           work, rays, env, args.repeat)
            extra = 1e6 * (patterned - plain) / count
            print(f"{scene:<8} {program:<9} {patterned:>11.2f} {plain:>8.2f} {patterned / plain:>6.2f} {extra:>12.3f}")
    if not have_radiance:
        print("# Radiance not found, skipped")
    shutil.rmtree(work)


if __name__ == "__main__":
    sys.exit(main())
