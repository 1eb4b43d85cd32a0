#!/usr/bin/python3
"""Hand checks of the Radiance 6.1 reference outputs in this directory (see README.md).

Two kinds of check:
  independent  - from the scene's definition alone: the illuminant-A formula, exact band averages of the
                 spectra on a 0.01 nm grid, E = L * omega * cos, rho/pi * E, and the CIE 1931 observer
                 from the analytic multi-lobe fit of Wyman, Sloan & Shirley (JCGT 2(2), 2013), good to
                 about 1% of the tables;
  formula      - Radiance's own conversion (16-bit cumulative observer tables, band integration as in
                 spec_rgb.c spec_dot), re-done in numpy from the band values Radiance printed with -co.
                 Needs the tables: pass the path of Radiance's src/common/spec_rgb.c (default
                 /tmp/radiance-src/src/common/spec_rgb.c); skipped if it is absent.
  tabulated    - the 1 nm CIE 1931 2-degree, CIE 1951 scotopic and CIE S 026 melanopic tables of Radiance's
                 lib/cieresp.cal (default /tmp/radiance/lib/cieresp.cal; skipped if absent) applied to the
                 continuous spectra (no bands): what an exact spectral renderer would print.
Usage: python3 check.py [path/to/spec_rgb.c [path/to/cieresp.cal]]
"""
import math, os, re, sys
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
specrgb = sys.argv[1] if len(sys.argv) > 1 else "/tmp/radiance-src/src/common/spec_rgb.c"
cieresp = sys.argv[2] if len(sys.argv) > 2 else "/tmp/radiance/lib/cieresp.cal"

def values(name):
    rows = []
    with open(os.path.join(here, name)) as f:
        body = f.read().split("\n\n", 1)[1]
    for line in body.splitlines():
        if line.strip():
            rows.append([float(v) for v in line.split()])
    return np.array(rows)

def rel(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    m = np.abs(b) > 1e-12 * np.max(np.abs(b))
    return np.max(np.abs(a[m] - b[m]) / np.abs(b[m])) if m.any() else 0.0

# ---- scene definition -------------------------------------------------------------------------
def S_A(l):
    c2 = 1.435e7
    return 100 * (560 / l) ** 5 * (math.exp(c2 / (2848 * 560)) - 1) / (np.exp(c2 / (2848 * l)) - 1)

g = np.arange(300.0, 900.0, 0.01) + 0.005          # fine grid (bin centres)
dg = 0.01
def pwc(nmA, nmB, vals, wl):
    """Radiance's reading of a uniform spectrum: value i fills the bin of width |nmB-nmA|/(n-1)
    centred on its wavelength; zero outside."""
    vals = np.asarray(vals, float); n = len(vals)
    lo, hi = min(nmA, nmB), max(nmA, nmB)
    step = (hi - lo) / (n - 1)
    if nmA > nmB: vals = vals[::-1]
    i = np.floor((wl - (lo - step / 2)) / step).astype(int)
    ok = (i >= 0) & (i < n)
    out = np.zeros_like(wl); out[ok] = vals[i[ok]]
    return out

def bands(f, n=24, wl0=780.0, wl1=380.0):
    """Band averages of f on the grid, long wavelength first (Radiance's order)."""
    edges = wl0 + (wl1 - wl0) * np.arange(n + 1) / n
    out = []
    for k in range(n):
        a, b = sorted((edges[k], edges[k + 1]))
        w = np.clip(np.minimum(g + dg / 2, b) - np.maximum(g - dg / 2, a), 0, dg)   # cell overlap
        out.append((f * w).sum() / (b - a))
    return np.array(out)

sun_exact = 1000 * S_A(g)                                   # the formula, continuous
sun_tab = 1000 * pwc(380, 780, S_A(np.arange(380, 781, 5.0)), g)  # illumA.dat as Radiance reads it
omega = 2 * math.pi * (1 - math.cos(math.radians(0.25)))
cosz = 1.7320508 / math.sqrt(1 + 1.7320508 ** 2)
refl7 = 0.8 * pwc(400, 700, [0.2, 0.3, 0.5, 0.8, 0.9, 0.7, 0.4], g)
stair = 0.8 * np.where(g > 600, 0.3, np.where(g > 500, 0.9, 0.2)) * ((g > 400) & (g < 700))
sd_x35 = 0.8 * pwc(420, 680, [0.5] * 5, g)
sd_x31 = 0.8 * pwc(420, 680, 0.8 * np.array([0.9, 0.7, 0.5, 0.3, 0.1]) + 0.2 * 0.5, g)
glow = 10 * pwc(720, 420, [0.2, 0.6, 1.0, 0.6, 0.2], g)

# ---- CIE 1931 analytic fit (Wyman, Sloan, Shirley 2013) ------------------------------------------
def lobe(l, mu, s1, s2):
    s = np.where(l < mu, s1, s2)
    return np.exp(-0.5 * ((l - mu) / s) ** 2)
xbar = 1.056 * lobe(g, 599.8, 37.9, 31.0) + 0.362 * lobe(g, 442.0, 16.0, 26.7) - 0.065 * lobe(g, 501.1, 20.4, 26.2)
ybar = 0.821 * lobe(g, 568.8, 46.9, 40.5) + 0.286 * lobe(g, 530.9, 16.3, 31.1)
zbar = 1.217 * lobe(g, 437.0, 11.8, 36.0) + 0.681 * lobe(g, 459.0, 26.0, 13.8)
vis = (g >= 380) & (g <= 780)

def xyz_fit(f):
    """179 * integral f*cmf / integral ybar over 380-780 (Radiance's equal-energy normalisation)."""
    k = 179.0 / (ybar[vis].sum() * dg)
    return np.array([k * (f * c)[vis].sum() * dg for c in (xbar, ybar, zbar)])

print("== independent checks (scene definition, exact band averages, CIE fit) ==")
co = values("rays_cs24_co.txt")
irr = values("irr_cs24_co.txt")
print("sun radiance bands vs continuous formula x1000:  max rel diff %.2e" % rel(co[0], bands(sun_exact)))
print("sun radiance bands vs illumA.dat as 5 nm bins:    max rel diff %.2e" % rel(co[0], bands(sun_tab)))
E = bands(sun_tab) * omega
print("omega = %.6e sr, cos = %.7f" % (omega, cosz))
print("-I floor (E = L omega cos):     max rel diff %.2e" % rel(irr[0], E * cosz))
print("-I facing sun (E = L omega):    max rel diff %.2e" % rel(irr[2], E))
print("P0 grey 0.5/pi E:               max rel diff %.2e" % rel(co[2], 0.5 / math.pi * E * cosz))
rho = lambda f: bands(f)
print("P1 spectrum 0.8*refl7/pi E:     max rel diff %.2e" % rel(co[3], rho(refl7 * sun_tab) * omega * cosz / math.pi))
print("P2 specfunc 0.8*stair/pi E:     max rel diff %.2e" % rel(co[4], rho(stair * sun_tab) * omega * cosz / math.pi))
print("P3 specdata x=3.5 (flat 0.5):   max rel diff %.2e" % rel(co[6], rho(sd_x35 * sun_tab) * omega * cosz / math.pi))
print("P3 specdata x=3.1 (interp.):    max rel diff %.2e" % rel(co[5], rho(sd_x31 * sun_tab) * omega * cosz / math.pi))
print("glow 10*spectrum(720->420):     max rel diff %.2e" % rel(co[1], bands(glow)))
# NB: Radiance multiplies band averages (product of averages), the exact answer is the average of the
# product; the two differ where a band straddles a step of the reflectance spectrum.
print("  (P1-P3 above use the band average of the product; Radiance multiplies band averages:)")
for lab, f, row in (("P1", refl7, 3), ("P2", stair, 4), ("P3 x=3.5", sd_x35, 6)):
    print("  %-9s product of band averages: max rel diff %.2e" % (lab, rel(co[row], bands(f) * bands(sun_tab) * omega * cosz / math.pi)))

xyz = values("rays_cs24_pXYZ.txt")
X, Y, Z = xyz[0]
print("sun -pXYZ chromaticity x,y = %.4f %.4f (CIE illuminant A: 0.4476 0.4074)" % (X / (X + Y + Z), Y / (X + Y + Z)))
fx = xyz_fit(sun_exact)
print("   fit on the continuous spectrum:  x,y = %.4f %.4f; Y = %.6e (Radiance %.6e, rel %.2e)"
      % (fx[0] / fx.sum(), fx[1] / fx.sum(), fx[1], Y, (Y - fx[1]) / fx[1]))
ee = xyz_fit(np.ones_like(g))
print("   equal-energy white through the fit: XYZ = %.2f %.2f %.2f (Radiance: 179 179 179 by construction)" % tuple(ee))
fy = xyz_fit(refl7 * sun_tab * omega * cosz / math.pi)
print("P1 -pY: Radiance %.6e, fit %.6e (rel %.2e)" % (values("rays_cs24_pY.txt")[3][0], fy[1],
      (values("rays_cs24_pY.txt")[3][0] - fy[1]) / fy[1]))
ei = values("irr_cs24_pY.txt")[0][0]
fe = xyz_fit(sun_tab * omega * cosz)[1]
print("floor illuminance -I -pY: Radiance %.4f lx, fit %.4f lx (rel %.2e)" % (ei, fe, (ei - fe) / fe))
print("  P3 x=3.1  product of band averages: max rel diff %.2e" % rel(co[5], bands(sd_x31) * bands(sun_tab) * omega * cosz / math.pi))
if os.path.exists(cieresp):
    cal = open(cieresp).read()
    def caltab(name):
        m = re.search(r"\n%s\(x\)\s*[:=][^;]*?select\(x-(\d+),([^;]*?)\)\s*;" % name, cal, re.S)
        if m is None:
            m = re.search(r"\n%s\(x\)\s*[:=][^;]*?select\(x-(\d+),([^;]*?)\)+\s*;" % name, cal, re.S)
        first = int(m.group(1)) + 1
        vals = np.array([float(v) for v in re.sub(r"[{}()]", " ", m.group(2)).replace(",", " ").split()])
        wl = first + np.arange(len(vals))
        return np.interp(g, wl, vals, left=0, right=0)
    cx, cy, cz = caltab("trix"), caltab("triy"), caltab("triz")
    csc, cme = caltab("scotopic"), caltab("melanopic")
    def tab(f, c, k):
        return k * (f * c)[vis].sum() / c[vis].sum()
    print("-- with the 1 nm CIE tables of cieresp.cal, continuous spectra:")
    for lab, f, fname, row in (("sun", sun_exact, "rays_cs24_%s.txt", 0),
                               ("P1 spectrum", refl7 * sun_tab * omega * cosz / math.pi, "rays_cs24_%s.txt", 3),
                               ("P2 specfunc", stair * sun_tab * omega * cosz / math.pi, "rays_cs24_%s.txt", 4),
                               ("glow", glow, "rays_cs24_%s.txt", 1),
                               ("floor E", sun_tab * omega * cosz, "irr_cs24_%s.txt", 0)):
        X, Y, Z = tab(f, cx, 179), tab(f, cy, 179), tab(f, cz, 179)
        rx = values(fname % "pXYZ")[row]
        line = "%-12s x,y %.4f %.4f (Radiance %.4f %.4f)  Y %.6g (Radiance %.6g, %+.2f%%)" % (
            lab, X / (X + Y + Z), Y / (X + Y + Z), rx[0] / rx.sum(), rx[1] / rx.sum(), Y, rx[1], 100 * (rx[1] - Y) / Y)
        if fname.startswith("rays"):
            S, M = tab(f, csc, 412), tab(f, cme, 179)
            rs, rm = values(fname % "pS")[row][0], values(fname % "pM")[row][0]
            line += "  S %+.2f%%  M %+.2f%%" % (100 * (rs - S) / S, 100 * (rm - M) / M)
        print(line)
pa = values("rays_cs24_pA.txt")
print("-pA = mean of the 24 bands:     max rel diff %.2e" % rel(pa[:, 0], co.mean(axis=1)))
c12 = values("rays_cs12_cw400-700_co.txt")
print("-cs 12 -cw 400 700 sun bands:   max rel diff %.2e" % rel(c12[0], bands(sun_tab, 12, 700, 400)))
print("-cs 12 -cw 400 700 P0 grey:     max rel diff %.2e" % rel(c12[2], 0.5 / math.pi * bands(sun_tab, 12, 700, 400) * omega * cosz))

# ---- Radiance's own formulas --------------------------------------------------------------------
if not os.path.exists(specrgb):
    print("(no %s: skipping the formula checks)" % specrgb); sys.exit(0)
src = open(specrgb).read()
def table(name):
    lo = int(re.search(r"#define\s+%s_WLMIN\s+(\d+)" % name, src).group(1))
    hi = int(re.search(r"#define\s+%s_WLMAX\s+(\d+)" % name, src).group(1))
    arr = re.search(r"%s_cumul\[[^\]]*\]\s*=\s*\{([^}]*)\}" % name.lower(), src).group(1)
    vals = np.array([int(v) for v in arr.replace("\n", " ").split(",") if v.strip()])
    assert len(vals) == hi - lo + 1
    return vals, lo, hi
T = {n: table(n) for n in ("CIE_X", "CIE_Y", "CIE_Z", "SCOTOPIC", "MELANOPIC")}
def spec_dot(sc, tab, wl0=780.0, wl3=380.0):          # spec_rgb.c spec_dot(), ncs > 3
    cum, lo, hi = tab; ncs = len(sc)
    st = (wl0 - wl3) / ncs; wl1 = int(wl3); n = 0; s = 0.0
    if wl1 < lo:
        n += int((lo - wl1) / st); wl1 = lo
    elif wl1 >= hi:
        return 0.0
    while n < ncs:
        w0 = wl1; wl1 = int(wl3 + (n + 1) * st)
        if wl1 >= hi:
            s += (65535 - cum[w0 - lo]) * sc[ncs - 1 - n]; break
        s += (cum[wl1 - lo] - cum[w0 - lo]) * sc[ncs - 1 - n]; n += 1
    return s / 65535.0
def xyz_rad(sc): return np.array([spec_dot(sc, T[k]) for k in ("CIE_X", "CIE_Y", "CIE_Z")])
def prim_mat(p):                                     # compxyz2rgbmat (same algebra)
    (xr, yr), (xg, yg), (xb, yb), (xw, yw) = p
    P = np.array([[xr, xg, xb], [yr, yg, yb], [1 - xr - yr, 1 - xg - yg, 1 - xb - yb]])
    W = np.array([xw / yw, 1.0, (1 - xw - yw) / yw])
    return np.linalg.inv(P * np.linalg.solve(P, W))
def clip_lower(c, Y):                               # clipgamut(.., CGAMUT_LOWER, black, white)
    if Y < 0: return np.zeros(3)
    if (c >= 0).all(): return c
    grey = Y * np.ones(3); vv = 1.0
    for i in range(3):
        if c[i] < 0: vv = min(vv, (0 - grey[i]) / (c[i] - grey[i]))
    return vv * c + (1 - vv) * grey
std = [(0.64, 0.33), (0.29, 0.60), (0.15, 0.06), (1 / 3, 1 / 3)]
pcp = [(0.64, 0.33), (0.3, 0.6), (0.15, 0.06), (0.3127, 0.329)]
vk = np.array([[1.2694, -0.0988, -0.1706], [-0.8364, 1.8006, 0.0357], [0.0297, -0.0315, 1.0018]])
ivk = np.array([[0.8156, 0.0472, 0.1372], [0.3791, 0.5769, 0.0440], [-0.0123, 0.0167, 0.9955]])
def wb(w1, w2):
    c1 = vk @ np.array([w1[0] / w1[1], 1, (1 - w1[0] - w1[1]) / w1[1]])
    c2 = vk @ np.array([w2[0] / w2[1], 1, (1 - w2[0] - w2[1]) / w2[1]])
    return ivk @ np.diag(c2 / c1) @ vk

print("\n== Radiance's formulas on the -co band values (spec_rgb.c tables) ==")
outs = {k: values("rays_cs24_%s.txt" % k) for k in ("pXYZ", "pY", "pS", "pM", "pRGB", "pc")}
M_std, M_pc = prim_mat(std), prim_mat(pcp) @ wb((1 / 3, 1 / 3), (0.3127, 0.329))
err = {k: 0.0 for k in outs}
for i, sc in enumerate(co):
    xyz = xyz_rad(sc)
    err["pXYZ"] = max(err["pXYZ"], rel(outs["pXYZ"][i], 179 * xyz))
    err["pY"] = max(err["pY"], rel(outs["pY"][i], [179 * xyz[1]]))
    err["pS"] = max(err["pS"], rel(outs["pS"][i], [412 * spec_dot(sc, T["SCOTOPIC"])]))
    err["pM"] = max(err["pM"], rel(outs["pM"][i], [179 * spec_dot(sc, T["MELANOPIC"])]))
    err["pRGB"] = max(err["pRGB"], rel(outs["pRGB"][i], clip_lower(M_std @ xyz, xyz[1])))
    err["pc"] = max(err["pc"], rel(outs["pc"][i], clip_lower(M_pc @ xyz, xyz[1])))
for k, v in err.items():
    print("-%-5s from -co bands: max rel diff %.2e" % (k, v))
# -cs 3: a spectrum of more than MAXCSAMP samples (illumA.dat, 81) is first resampled to 24 bands over
# 380-780 nm, then taken to XYZ (spec_dot) and to RGB (cie_rgb, lower gamut clip).
xyzA = xyz_rad(bands(sun_tab))
print("-cs 3 sun RGB: Radiance %s, formula %s (rel %.2e)" % (values("rays_cs3.txt")[0],
      clip_lower(M_std @ xyzA, xyzA[1]), rel(values("rays_cs3.txt")[0], clip_lower(M_std @ xyzA, xyzA[1]))))

# -cs 3 materials (p_data.c -> convertscolorcol with NCSAMP 3): a spectrum given long-to-short with at most
# MAXCSAMP values goes straight to XYZ over its own range (the glow); one given short-to-long (refl7)
# is first resampled to int(n*400/range + .99) = 8 bands of 50 nm over 380-780 nm, then to XYZ.
def rgb_from(sc, wl0, wl3):
    xyz = np.array([spec_dot(sc, T[k], wl0, wl3) for k in ("CIE_X", "CIE_Y", "CIE_Z")])
    return clip_lower(M_std @ xyz, xyz[1])
c3 = values("rays_cs3.txt")
k3 = omega * cosz / math.pi
p1 = 0.8 * rgb_from(bands(pwc(400, 700, [0.2, 0.3, 0.5, 0.8, 0.9, 0.7, 0.4], g), 8), 780, 380) * c3[0] * k3
print("-cs 3 P1 (refl7 via 8 bands of 50 nm): rel %.2e" % rel(c3[3], p1))
print("-cs 3 glow (5 values, 757.5-382.5 nm direct): rel %.2e" % rel(c3[1], 10 * rgb_from(np.array([0.2, 0.6, 1.0, 0.6, 0.2]), 757.5, 382.5)))
print("-cs 3 P0 grey 0.5/pi E: rel %.2e" % rel(c3[2], 0.5 * c3[0] * k3))

# ---- specpict: P4 from the pixels of spic.hsr (bilinear between pixel centres at u,v = 0 and 1) ------
raw = open(os.path.join(here, "spic.hsr"), "rb").read()
hdr, rest = raw.split(b"\n\n", 1)
resl, data = rest.split(b"\n", 1)
px = np.frombuffer(data[:4 * 7], dtype=np.uint8).reshape(4, 7).astype(float)
spec6 = (px[:, :6] + 0.5) * 2.0 ** (px[:, 6:7] - 136)      # rows: TL TR BL BR; bands 700->400 nm
print("\n== specpict (spic.hsr pixels: %s) ==" % resl.decode())
for row, (u, v) in zip(range(8, 13), ((.25, .75), (.75, .75), (.25, .25), (.75, .25), (.5, .5))):
    s6 = (1 - u) * v * spec6[0] + u * v * spec6[1] + (1 - u) * (1 - v) * spec6[2] + u * (1 - v) * spec6[3]
    f = 0.8 * pwc(675, 425, s6, g)
    print("P4 u=%.2f v=%.2f: max rel diff %.2e" % (u, v, rel(co[row], bands(f) * bands(sun_tab) * omega * cosz / math.pi)))

# ---- smooth specfunc (P5): Radiance's jittered samples vs the exact answer ------------------------------
sm = np.loadtxt(os.path.join(here, "smooth_specfunc_runs.txt"), comments="#")
bumpf = 0.8 * (0.1 + 0.8 * np.exp(-((g - 550) / 40) ** 2)) * ((g > 400) & (g < 700))
yb = 179 * spec_dot(bands(bumpf) * bands(sun_tab) * omega * cosz / math.pi, T["CIE_Y"])
print("\n== smooth specfunc P5 -pY: 20 jittered rays mean %.4f, min %.4f, max %.4f; exact (band averages) %.4f"
      % (sm.mean(), sm.min(), sm.max(), yb))
