#!/usr/bin/env python3
"""Draws bench/results/time_vs_error.png from the table bench.py writes: plot.py table.tsv out.png [ref_noise_%]."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

tsv, png = sys.argv[1], sys.argv[2]
ref_noise = float(sys.argv[3]) if len(sys.argv) > 3 else 0.0
series = {}
for line in open(tsv):
    if line.startswith("#") or not line.strip():
        continue
    label, settings, wall, cpu, rms, mx, mean = line.rstrip("\n").split("\t")
    series.setdefault(label, []).append((float(cpu), float(rms), settings))

fig, ax = plt.subplots(figsize=(8, 5.5))
markers = "osD^v<>"
for k, (label, pts) in enumerate(series.items()):
    x = [p[0] for p in pts]
    y = [p[1] for p in pts]
    ax.loglog(x, y, marker=markers[k % len(markers)], label=label)
    for t, e, s in (pts[0], pts[-1]):
        ax.annotate(s.replace("-aa 0 ", ""), (t, e), fontsize=6, xytext=(3, 3), textcoords="offset points")
if ref_noise > 0:
    ax.axhline(ref_noise, color="grey", lw=0.8, ls=":", label="reference's own standard error")
ax.set_xlabel("CPU time for the 96 sensors, one thread (s)")
ax.set_ylabel("RMS relative error of illuminance (%)")
ax.set_title("Office sensor grid, -ab 5: time against error versus a converged Brume reference")
ax.grid(True, which="both", lw=0.3)
ax.legend(fontsize=8, loc="lower left")
fig.tight_layout()
fig.savefig(png, dpi=120)
