#!/usr/bin/env python3
"""Brume benchmark of rpict: time per picture against its error, Brume against Radiance's rpict, on examples/office.

bench/run.sh runs it after bench.py (--skip-rpict leaves it out); see bench/README.md. It needs numpy, and
matplotlib for the figures: when this Python lacks them it reruns itself with one that has them
(python3 on PATH or /usr/bin/python3).
"""
import argparse
import hashlib
import json
import os
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ beside the bench
sys.path.insert(0, HERE)
import bench  # noqa: E402  (shared helpers: timing, Radiance, git commit, hashes, finding a Python)


def _python_with_numpy():
    """Reruns this script with a Python that has numpy (and matplotlib if one has both), if this one lacks it."""
    try:
        import numpy  # noqa: F401
        import matplotlib  # noqa: F401
        return
    except ImportError:
        pass
    here = os.path.realpath(sys.executable)
    for mods in (["numpy", "matplotlib"], ["numpy"]):
        for exe in bench.pythons_with(mods):
            if os.path.realpath(exe) != here:
                os.execv(exe, [exe] + sys.argv)
    try:
        import numpy  # noqa: F401,F811
    except ImportError:
        sys.exit("bench/rpict.py: needs numpy (Debian: apt-get install python3-numpy python3-matplotlib)")


_python_with_numpy()
import numpy as np  # noqa: E402

RESULTS = bench.RESULTS
CACHE = os.path.join(RESULTS, "rpict_reference")  # converged pictures (git-ignored)
TABLE = os.path.join(RESULTS, "rpict.md")
PLOT = os.path.join(RESULTS, "rpict_time_vs_error.png")
SHEET = os.path.join(RESULTS, "rpict_contact_sheet.png")

VIEWS = {  # name: (what it shows, view options)
    "seated": ("seated eye facing the desks and the door",
               ["-vp", "0.3", "0.3", "1.6", "-vd", "1", "0.8", "-0.3", "-vh", "75", "-vv", "55"]),
    "window": ("standing eye facing the window, luminaires in view",
               ["-vp", "5.7", "3.7", "1.2", "-vd", "-1", "-0.7", "0.05", "-vh", "75", "-vv", "58"]),
}
RESOLUTION = ["-x", "320", "-y", "240"]
# Every picture samples pixel centres (-pj 0), so that errors are the shading's, not aliasing from jitter.
COMMON = RESOLUTION + ["-pj", "0"]
LUMINANCE = np.array([0.265, 0.670, 0.065])
FLOOR = 0.01  # pixels darker than this fraction of the reference's mean luminance are left out (the night window)

# The converged references: the mean of REF_RUNS independent Brume runs (-u+: a new seed each run).
REFERENCE = {
    0: ["-ab", "0", "-ps", "1", "-ds", ".01"],
    1: ["-ab", "1", "-aa", "0", "-ad", "256", "-as", "0", "-ps", "1"],
}
# The (view, -ab) pairs benched by default: -ab 1 pictures cost a minute or more each, so only one view has them.
CASES = "seated:0,seated:1,window:0"
REF_RUNS = 4

DS = [".5", ".25", ".1", ".05"]
AD = ["16", "64", "256"]
CACHE_LADDER = [("-aa", ".3", "-ar", "32", "-ad", "256", "-as", "64"),
                ("-aa", ".2", "-ar", "64", "-ad", "512", "-as", "128"),  # Radiance's rpict defaults
                ("-aa", ".1", "-ar", "128", "-ad", "1024", "-as", "512")]


def ladders(threads):
    """(ab, program, series label, [options of each rung], threads); rpict's defaults otherwise (-ps 4 -pt .05)."""
    s = []
    for ps in ("4", "1"):
        s.append((0, "brume", "Brume -ps %s" % ps, [["-ps", ps, "-ds", d] for d in DS], 1))
    for ps, dj in (("4", "0"), ("1", "0"), ("1", ".7")):
        s.append((0, "radiance", "Radiance -ps %s -dj %s" % (ps, dj), [["-ps", ps, "-dj", dj, "-ds", d] for d in DS], 1))
    s.append((0, "brume", "Brume -n %d" % threads, [["-ps", "4", "-ds", ".25"]], threads))
    pt = ["-ab", "1", "-aa", "0", "-as", "0", "-ps", "1"]
    s.append((1, "brume", "Brume path tracing -ps 1", [pt + ["-ad", a] for a in AD], 1))
    s.append((1, "radiance", "Radiance path tracing -ps 1", [pt + ["-ad", a] for a in AD[:2]], 1))
    s.append((1, "radiance", "Radiance irradiance cache", [["-ab", "1"] + list(c) for c in CACHE_LADDER], 1))
    # The same with fine, jittered direct light: at -ab 1 Radiance's default -ds .25 -dj 0 dominates its error.
    s.append((1, "radiance", "Radiance cache -ds .05 -dj .7",
              [["-ab", "1"] + list(c) + ["-ds", ".05", "-dj", ".7"] for c in CACHE_LADDER[1:]], 1))
    s.append((1, "brume", "Brume -n %d" % threads, [pt + ["-ad", "64"]], threads))
    return s


# The pictures of the contact sheet: (ab, program, options); Radiance's and Brume's defaults at -ab 0, and at -ab 1
# Brume's path tracing against Radiance's cache at its defaults.
SHEET_RUNS = [(0, "brume", ["-ps", "4", "-ds", ".25"]), (0, "radiance", ["-ps", "4", "-dj", "0", "-ds", ".25"]),
              (1, "brume", ["-ab", "1", "-aa", "0", "-as", "0", "-ps", "1", "-ad", "64"]),
              (1, "radiance", ["-ab", "1"] + list(CACHE_LADDER[1]))]


# ---------------------------------------------------------------- Radiance pictures

def read_picture(path):
    """A Radiance picture (RGBE, flat or run-length encoded scanlines) as float32 [rows, columns, 3], top row first."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"\n\n")
    if not data.startswith(b"#?") or end < 0:
        sys.exit("bench/rpict.py: %s is not a Radiance picture" % path)
    exposure = 1.0
    for line in data[:end].split(b"\n"):
        if line.startswith(b"EXPOSURE="):
            exposure *= float(line[9:])
        if line.startswith(b"FORMAT=") and b"32-bit_rle_rgbe" not in line:
            sys.exit("bench/rpict.py: %s: only RGBE pictures are read" % path)
    eol = data.index(b"\n", end + 2)
    res = data[end + 2:eol].split()
    if res[0] != b"-Y" or res[2] != b"+X":
        sys.exit("bench/rpict.py: %s: unusual orientation %s" % (path, b" ".join(res).decode()))
    h, w = int(res[1]), int(res[3])
    buf = np.frombuffer(data, np.uint8)
    pos = eol + 1
    rgbe = np.empty((h, w, 4), np.uint8)
    for y in range(h):
        if 8 <= w < 32768 and buf[pos] == 2 and buf[pos + 1] == 2 and (buf[pos + 2] << 8 | buf[pos + 3]) == w:
            pos += 4
            for c in range(4):
                x = 0
                row = rgbe[y, :, c]
                while x < w:
                    n = int(buf[pos])
                    if n > 128:
                        row[x:x + n - 128] = buf[pos + 1]
                        x += n - 128
                        pos += 2
                    else:
                        row[x:x + n] = buf[pos + 1:pos + 1 + n]
                        x += n
                        pos += 1 + n
        else:  # flat pixels (Radiance's old run-length marks are not written by either program)
            rgbe[y] = buf[pos:pos + 4 * w].reshape(w, 4)
            pos += 4 * w
    e = rgbe[..., 3].astype(np.int32)
    scale = np.where(e > 0, np.ldexp(1.0, e - 136), 0.0)
    return ((rgbe[..., :3] + 0.5) * scale[..., None] / exposure).astype(np.float32)


def luminance(rgb):
    return rgb @ LUMINANCE


# ---------------------------------------------------------------- the reference

def scene_key(view, common, options):
    """What a reference depends on, hashed: the scene, the view, the resolution and the reference's options."""
    text = json.dumps([bench.sha256(bench.SCENE), VIEWS[view][1], common, options, REF_RUNS])
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def load_cached(path, key, remake):
    """The arrays and metadata saved as path.npz and path.json (see save_cached) if their key is `key` and remake is
    false; else None, saying so if they are out of date."""
    if remake or not (os.path.exists(path + ".npz") and os.path.exists(path + ".json")):
        return None
    meta = json.load(open(path + ".json"))
    if meta.get("key") != key:
        print("  %s is out of date (scene, view or options changed): remaking it" % os.path.relpath(path, bench.ROOT))
        return None
    return dict(np.load(path + ".npz")), meta


def save_cached(path, arrays, meta):
    """Saves arrays (as float32) in path.npz and meta, which holds the key load_cached checks, in path.json."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    np.savez_compressed(path + ".npz", **{k: v.astype(np.float32) for k, v in arrays.items()})
    with open(path + ".json", "w") as f:
        json.dump(meta, f, indent=1)


def own_error(ref, se):
    """A reference's own RMS error in %: its per-pixel standard error of luminance over the pixels above FLOOR."""
    lr = luminance(ref)
    mask = lr > FLOOR * lr.mean()
    return 100 * float(np.sqrt(np.mean((se[mask] / lr[mask]) ** 2)))


def reference(brume_rpict, ab, view, tmp, remake):
    """The converged picture of a case of this bench: see converged."""
    return converged(brume_rpict, "%s_ab%d" % (view, ab), view, COMMON, REFERENCE[ab], tmp, remake)


def converged(brume_rpict, name, view, common, options, tmp, remake, prefix=()):
    """The converged picture, the mean of REF_RUNS runs of Brume's rpict (command prefix, e.g. nice, then the view,
    common and options), cached as CACHE/name: (mean RGB, per-pixel standard error of the mean luminance, metadata)."""
    name = os.path.join(CACHE, name)
    key = scene_key(view, common, options)
    cached = load_cached(name, key, remake)
    if cached:
        return cached[0]["rgb"], cached[0]["se"], cached[1]
    threads = os.cpu_count() or 1
    cmd = [brume_rpict] + VIEWS[view][1] + common + options + ["-u+", "-n", str(threads), bench.SCENE]
    print("  making the reference %s: the mean of %d runs of rpict %s (cached in %s)" % (
        os.path.basename(name), REF_RUNS, " ".join(cmd[1:-1]), os.path.relpath(CACHE, bench.ROOT)), flush=True)
    runs, wall = [], 0.0
    out = os.path.join(tmp, "reference.hdr")
    for k in range(REF_RUNS):
        t = bench.Timer(list(prefix) + cmd, os.devnull, out_path=out)
        wall += t.wall
        runs.append(read_picture(out))
        print("    run %d/%d: %.0f s" % (k + 1, REF_RUNS, t.wall), flush=True)
    runs = np.stack(runs)
    rgb = runs.mean(axis=0)
    lum = luminance(runs)
    se = lum.std(axis=0, ddof=1) / np.sqrt(REF_RUNS)
    # Check of the estimate: two independent half-references differ by sqrt(2) times a half's error, that is by
    # twice the error of the whole mean.
    half = REF_RUNS // 2
    a, b = lum[:half].mean(axis=0), lum[half:2 * half].mean(axis=0)
    mask = luminance(rgb) > FLOOR * luminance(rgb).mean()
    split = float(np.sqrt(np.mean(((a - b)[mask] / luminance(rgb)[mask]) ** 2)) / 2)
    meta = {"key": key, "command": "rpict " + " ".join(cmd[1:-1]) + " examples/office/office.rad", "runs": REF_RUNS,
            "wall_s": round(wall, 1), "brume_commit": bench.git_commit(), "date": time.strftime("%Y-%m-%d %H:%M:%S"),
            "split_half_rms_pct": 100 * split}
    save_cached(name, {"rgb": rgb, "se": se}, meta)
    return rgb, se, meta


# ---------------------------------------------------------------- measurements

def errors(rgb, ref, percentile=99):
    """RMS and a percentile (99th) of the relative error of pixel luminance, and the bias of the mean, in %; rgb is a
    picture or its luminance."""
    lr = luminance(ref)
    mask = lr > FLOOR * lr.mean()
    lum = luminance(rgb) if rgb.ndim == 3 else rgb
    if lum.shape != lr.shape:
        sys.exit("bench/rpict.py: picture of %s pixels, the reference has %s" % (lum.shape, lr.shape))
    rel = (lum[mask] - lr[mask]) / lr[mask]
    return (100 * float(np.sqrt(np.mean(rel ** 2))), 100 * float(np.percentile(np.abs(rel), percentile)),
            100 * float(lum[mask].sum() / lr[mask].sum() - 1))


def timed_picture(cmd, env, out, repeat):
    """Renders once (repeating short runs, keeping the fastest): (picture, wall s, cpu s)."""
    t = bench.Timer(cmd, os.devnull, env, out_path=out)
    best = (t.wall, t.cpu)
    picture = read_picture(out)
    for _ in range(repeat - 1 if t.wall < 2 else 0):
        t = bench.Timer(cmd, os.devnull, env, out_path=out)
        best = min(best, (t.wall, t.cpu))
    return picture, best[0], best[1]


def measure(progs, view, ab, ref, tmp, threads, repeat, keep):
    """Runs the ladders of one view and bounce count: rows (series, settings, wall, cpu, rms, p99, bias)."""
    rows = []
    out = os.path.join(tmp, "picture.hdr")
    for lab, prog, label, rungs, n in ladders(threads):
        if lab != ab or prog not in progs:
            continue
        exe, scene, env = progs[prog]
        for opts in rungs:
            # Radiance's rpict has one thread and no -n
            cmd = [exe] + VIEWS[view][1] + COMMON + opts + (["-n", str(n)] if prog == "brume" else []) + [scene]
            picture, wall, cpu = timed_picture(cmd, env, out, repeat)
            rms, p99, bias = errors(picture, ref)
            settings = " ".join(opts)
            rows.append((label, settings, wall, cpu, rms, p99, bias))
            print("  %-30s %-52s %7.2f %7.2f %7.2f %7.1f %+7.2f" % (label, settings, wall, cpu, rms, p99, bias),
                  flush=True)
            if (ab, prog, opts) in SHEET_RUNS:
                keep[(view, ab, prog)] = (picture, settings, rms)
    return rows


# ---------------------------------------------------------------- output

def write_table(results, refs, header_lines, path):
    lines = header_lines + [""]
    for (view, ab), rows in results.items():
        meta, ref_se = refs[(view, ab)]
        lines.append("**%s view (%s), -ab %d**; reference: %s, the mean of %d runs (its own error: RMS %.2f %% "
                     "from the spread of the runs, %.2f %% from its two halves)" % (
                         view, VIEWS[view][0], ab, meta["command"].replace(" examples/office/office.rad", ""),
                         meta["runs"], ref_se, meta["split_half_rms_pct"]))
        lines.append("")
        lines.append("| series | settings | wall s | CPU s | RMS % | p99 % | bias % |")
        lines.append("|---|---|---:|---:|---:|---:|---:|")
        for label, settings, wall, cpu, rms, p99, bias in rows:
            lines.append("| %s | `%s` | %.2f | %.2f | %.2f | %.1f | %+.2f |" % (label, settings, wall, cpu, rms, p99, bias))
        lines.append("")
    with open(path, "w") as f:
        f.write("\n".join(lines))


def plot(results, refs, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    keys = list(results)
    fig, axes = plt.subplots(1, len(keys), figsize=(4.2 * len(keys), 4.4), squeeze=False)
    for ax, key in zip(axes[0], keys):
        series = {}
        for label, settings, wall, cpu, rms, p99, bias in results[key]:
            series.setdefault(label, []).append((cpu, rms, settings))
        for label, pts in series.items():
            style = "-" if label.startswith("Brume") else "--"
            marker = "o" if label.startswith("Brume") else "s"
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, marker=marker, ms=4, label=label)
            for t, e, s in (pts[0], pts[-1]) if len(pts) > 1 else pts[:1]:
                s = " ".join(w for w in s.split() if w not in ("-ab", "1", "-aa", "0", "-as", "-ps")) if len(s) > 20 else s
                ax.annotate(s, (t, e), fontsize=5, xytext=(2, 2), textcoords="offset points")
        ax.axhline(refs[key][1], color="grey", lw=0.8, ls=":", label="reference's own error")
        label_axes(ax, "%s view, -ab %d" % key, "CPU time per 320-wide picture (s)",
                   "RMS relative error of pixel luminance (%)", 5.5)
    save_figure(fig, "rpict on examples/office: CPU time against error versus a converged Brume picture "
                "(Brume solid, Radiance 6.1 dashed)", path, 110)


def label_axes(ax, title, xlabel, ylabel, legend_size):
    """The title, labels, grid and legend of a panel of time against error."""
    ax.set_title(title, fontsize=9)
    ax.set_xlabel(xlabel, fontsize=8)
    ax.set_ylabel(ylabel, fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    ax.tick_params(labelsize=7)
    ax.legend(fontsize=legend_size, loc="best")


def save_figure(fig, title, path, dpi):
    import matplotlib.pyplot as plt
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def tone_map(rgb, exposure):
    """A simple global tone map: exposure, x / (1 + x) on each channel, sRGB-like gamma 1/2.2."""
    x = rgb * exposure
    return np.clip((x / (1 + x)) ** (1 / 2.2), 0, 1)


def contact_sheet(keep, refs_rgb, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from PIL import Image
    rows = sorted({(v, ab) for v, ab, _ in keep}, key=lambda k: (list(VIEWS).index(k[0]), k[1]))
    cols = ["reference", "brume", "radiance", "brume error", "radiance error"]
    h, w = refs_rgb[rows[0]].shape[:2]
    fig, axes = plt.subplots(len(rows), len(cols), figsize=(len(cols) * 2.3, len(rows) * 2.3 * h / w + 0.7),
                             squeeze=False)
    cmap = plt.get_cmap("RdBu_r").copy()
    cmap.set_bad("0.75")
    for r, key in enumerate(rows):
        ref = refs_rgb[key]
        lr = luminance(ref)
        exposure = 1.0 / np.percentile(lr, 75)
        mask = lr > FLOOR * lr.mean()
        for c, col in enumerate(cols):
            ax = axes[r][c]
            ax.set_xticks([]), ax.set_yticks([])
            prog = col.split()[0]
            if col == "reference":
                ax.imshow(tone_map(ref, exposure))
                title = "%s, -ab %d: reference" % key
            elif (key[0], key[1], prog) not in keep:
                ax.set_visible(False)
                continue
            else:
                picture, settings, rms = keep[(key[0], key[1], prog)]
                name = "Brume" if prog == "brume" else "Radiance"
                if col == prog:
                    ax.imshow(tone_map(picture, exposure))
                    title = "%s %s" % (name, settings.replace("-ab 1 ", "").replace("-aa 0 -as 0 ", ""))
                else:
                    rel = np.ma.masked_array((luminance(picture) - lr) / np.where(mask, lr, 1), ~mask)
                    im = ax.imshow(rel * 100, cmap=cmap, vmin=-20, vmax=20)
                    title = "%s error: RMS %.1f %%" % (name, rms)
            ax.set_title(title, fontsize=5.5)
    fig.colorbar(im, ax=axes[:, 3:].ravel().tolist(), orientation="horizontal", fraction=0.04, pad=0.02,
                 label="relative error of luminance (%), grey: left out").ax.tick_params(labelsize=6)
    fig.savefig(path + ".tmp.png", dpi=150)
    plt.close(fig)
    # A palette of 256 colours keeps the sheet small (well under 400 KB).
    Image.open(path + ".tmp.png").convert("RGB").quantize(256, method=Image.Quantize.MEDIANCUT).save(path,
                                                                                                     optimize=True)
    os.remove(path + ".tmp.png")


# ---------------------------------------------------------------- main

def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--bin", default=os.path.join(bench.ROOT, "build", "bin"), help="directory holding Brume's rpict")
    ap.add_argument("--repeat", type=int, default=3, help="runs of pictures under 2 s (the fastest is kept)")
    ap.add_argument("--threads", type=int, default=2, help="the multi-threaded Brume series' -n")
    ap.add_argument("--cases", default=CASES, help="view:ab pairs to bench (views: %s; ab: 0 or 1; default %s)"
                    % (", ".join(VIEWS), CASES))
    ap.add_argument("--remake-reference", action="store_true", help="recompute the cached converged pictures")
    a = ap.parse_args()

    start = time.perf_counter()
    brume = os.path.abspath(os.path.join(a.bin, "rpict"))
    if not os.access(brume, os.X_OK):
        sys.exit("bench/rpict.py: no Brume rpict at %s (run make first)" % brume)
    header = ["Brume rpict: %s (commit %s); Python %s" % (brume, bench.git_commit(), sys.executable),
              "machine: %d CPUs, load average %.2f at start (other load disturbs the timings)"
              % (os.cpu_count(), os.getloadavg()[0])]
    for line in header:
        print(line)
    cases = [(c.split(":")[0], int(c.split(":")[1])) for c in a.cases.split(",") if ":" in c]
    for v, ab in cases:
        if v not in VIEWS or ab not in REFERENCE:
            sys.exit("bench/rpict.py: unknown case %s:%d (views: %s; ab: 0 or 1)" % (v, ab, ", ".join(VIEWS)))
    rad = bench.find_radiance()
    results, refs, refs_rgb, keep = {}, {}, {}, {}
    with tempfile.TemporaryDirectory(prefix="brume-rpict-") as tmp:
        progs = {"brume": (brume, bench.SCENE, None)}
        if rad and os.access(os.path.join(rad["dir"], "rpict"), os.X_OK):
            progs["radiance"] = (os.path.join(rad["dir"], "rpict"), bench.frozen_octree(rad, tmp), rad["env"])
            print("Radiance: %s (octree made with its oconv -f; its time is not counted)" % rad["dir"])
        else:
            print("Radiance not found, skipped (set RADIANCE_BIN to the directory holding its rpict and oconv)")
        for view, ab in cases:
            print("\n== %s view (%s), -ab %d: %s %s -pj 0 ==" % (view, VIEWS[view][0], ab, " ".join(VIEWS[view][1]),
                                                               " ".join(RESOLUTION)))
            ref, se, meta = reference(brume, ab, view, tmp, a.remake_reference)
            lr = luminance(ref)
            mask = lr > FLOOR * lr.mean()
            ref_se = own_error(ref, se)
            print("  reference: the mean of %d runs (Brume %s, %s); its own error: RMS %.2f %% (spread of the "
                  "runs), %.2f %% (two halves); %d of %d pixels above the floor" % (
                      meta["runs"], meta["brume_commit"], meta["date"], ref_se, meta["split_half_rms_pct"],
                      mask.sum(), mask.size))
            refs[(view, ab)], refs_rgb[(view, ab)] = (meta, ref_se), ref
            print("  %-30s %-52s %7s %7s %7s %7s %7s" % ("series", "settings", "wall s", "CPU s", "RMS %", "p99 %",
                                                        "bias %"))
            results[(view, ab)] = measure(progs, view, ab, ref, tmp, a.threads, a.repeat, keep)
    load = os.getloadavg()[0]
    header[1] += ", %.2f at the end" % load
    print("\nload average at the end %.2f" % load)
    os.makedirs(RESULTS, exist_ok=True)
    cmdline = "bench/rpict.py " + " ".join(sys.argv[1:])
    write_table(results, refs, ["# rpict: time against error (`%s`)" % cmdline.strip(), ""] +
                ["- " + line for line in header] +
                ["- common options: `%s`; RMS and p99: relative error of pixel luminance (.265 R + .670 G + .065 B) "
                 "against the reference, over pixels brighter than %g of its mean; bias: of the mean luminance"
                 % (" ".join(COMMON), FLOOR)], TABLE)
    print("table: %s" % os.path.relpath(TABLE, bench.ROOT))
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("figures not drawn: no matplotlib")
    else:
        plot(results, refs, PLOT)
        print("plot:  %s" % os.path.relpath(PLOT, bench.ROOT))
        if keep:
            contact_sheet(keep, refs_rgb, SHEET)
            print("contact sheet: %s (%d KB)" % (os.path.relpath(SHEET, bench.ROOT), os.path.getsize(SHEET) // 1024))
    print("rpict bench total: %.0f s" % (time.perf_counter() - start))


if __name__ == "__main__":
    main()
