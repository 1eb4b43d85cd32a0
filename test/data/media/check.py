#!/usr/bin/python3
"""Hand/numerical checks for the Radiance media reference outputs (reads out/*.txt)."""
import numpy as np, sys, os
os.chdir(os.path.dirname(os.path.abspath(__file__)))
def trapz(y, x): return float(np.sum((y[1:]+y[:-1])*np.diff(x))/2)
def load(f):
    p = os.path.join('out', f)
    return np.loadtxt(p if os.path.exists(p) else p + '.gz', ndmin=2)
def rays(f): return np.loadtxt(f, ndmin=2)
def hg(g, c):
    if g <= 1e-6: return np.ones_like(c)          # Radiance: g<=FTINY (incl. negative g) -> isotropic
    return (1-g*g)/(1+g*g-2*g*c)**1.5
def line(o, d, t1, f, n=2000001):
    d = d/np.linalg.norm(d); t = np.linspace(0, t1, n)
    x = o[None,:] + t[:,None]*d[None,:]
    y = f(x, t, d); return trapz(y, t)
def stats(a, nrep):
    a = a[:,0].reshape(-1, nrep); return a.mean(1), a.std(1, ddof=1)/np.sqrt(nrep)
def report(name, ref, mean, se):
    for i,(r,m,s) in enumerate(zip(ref, mean, se)):
        print(f"{name} ray{i}: radiance mean {m:.6e} +- {s:.1e} (SE)  reference {r:.6e}  ratio {m/r:.5f}  ({(m-r)/s:+.1f} SE)")
NREP = int(sys.argv[1]) if len(sys.argv) > 1 else 4000
# ---- a: Beer-Lambert
L = np.array([100, 50, 20.])
for tag, ext, alb, av in (('a1', [.1,.1,.1], 0, 0), ('a2', [.1,.2,.3], .5, .2)):
    out = load(f'{tag}.txt'); ext = np.array(ext)
    for i, dist in enumerate([0.1, 10, 50]):
        ref = L*np.exp(-ext*dist) + alb*av*(1-np.exp(-ext*dist))
        print(f"{tag} dist {dist}: radiance {out[i]}  hand {ref}  max rel err {np.max(np.abs(out[i]/ref-1)):.1e}")
    print(f"{tag} ray away from panel (to infinity): radiance {out[3]}  hand {alb*av*np.ones(3)}")
# ---- b: sphere lamp in mist-enabled global medium
R, Ls, se_, S = .05, 1000., .01, np.zeros(3)
def sphere_f(g, sig_e, alb, flen=0., aim=None, cone=None):
    def f(x, t, d):
        v = S[None,:]-x; dist = np.linalg.norm(v, axis=1); c = (v@d)/dist
        dom = np.pi*R*R/(dist+flen)**2
        val = sig_e*alb*hg(g, c)/(4*np.pi)*Ls*dom*np.exp(-sig_e*(1-alb)*dist)*np.exp(-sig_e*t)
        if cone is not None:
            val = val*(((-v/dist[:,None])@aim) >= np.cos(np.radians(cone/2)))
        return val
    return f
for tag, g in (('b_iso', 0.), ('b_g06', .6), ('b_gm06', 0.)):
    rr = rays('b_rays.txt'); ref = []
    for o in rr:
        o_, d = o[:3], o[3:]/np.linalg.norm(o[3:]); t1 = (4.999-o_[1])/d[1]
        ref.append(line(o_, d, t1, sphere_f(g, se_, 1.)))
    m, s = stats(load(f'{tag}.txt'), NREP); report(tag, ref, m, s)
rr = rays('b_spot_rays.txt'); ref = []
for o in rr:
    o_, d = o[:3], o[3:]/np.linalg.norm(o[3:]); t1 = (4.999-o_[1])/d[1]
    ref.append(line(o_, d, t1, sphere_f(0., se_, 1., flen=1., aim=np.array([0,0,-1.]), cone=60)))
m, s = stats(load('b_spot.txt'), NREP); report('b_spot', ref, m, s)
# sun overhead, 0.5 deg, L=1e6; mist box |x|,|y|<=2, |z|<=1, ext .05
Esun = 1e6*2*np.pi*(1-np.cos(np.radians(.25)))
for tag, alb, g in (('b_sun_a1', 1., 0.), ('b_sun_a05_g06', .5, .6)):
    rr = rays('b_sun_rays.txt'); ref = []
    for o in rr:
        o_, d = o[:3], o[3:]/np.linalg.norm(o[3:])
        # entry at y=-2, exit at y=2 or z=1
        t0 = (-2-o_[1])/d[1]; t1 = (2-o_[1])/d[1]
        if d[2] > 0: t1 = min(t1, (1-o_[2])/d[2])
        def f(x, t, d, alb=alb, g=g, t0=t0):
            ell = 1 - x[:,2]
            return .05*alb*hg(g, d[2]*np.ones_like(t))/(4*np.pi)*Esun*np.exp(-.05*(1-alb)*ell)*np.exp(-.05*(t-t0))
        tt = np.linspace(t0, t1, 200001); x = o_[None,:]+tt[:,None]*d[None,:]
        ref.append(trapz(f(x, tt, d), tt))
    m, s = stats(load(f'{tag}.txt'), NREP); report(tag, ref, m, s)
print(f"b_nomist (no mist box, same -me/-ma): {load('b_nomist.txt')[:,0]}  (Radiance: no source in-scattering without a mist naming the source)")
m1, s1 = stats(load('b_iso.txt'), NREP); m2, s2 = stats(load('b_iso_reversed.txt'), NREP)
print(f"b_iso vs reversed order (-u+): {(m1-m2)/np.hypot(s1,s2)} SE differences")
# ---- c: mist box in room
lo, hi = np.array([-1,-1,.5]), np.array([1,1,2.5]); lamp = np.array([0,0,3.5])
def exitdist(x, u):
    with np.errstate(divide='ignore', invalid='ignore'):
        t = np.where(u > 0, (hi-x)/u, np.where(u < 0, (lo-x)/u, np.inf))
    return t.min(axis=1)
def c_ref(o, t0, t1, glow_t):
    d = np.array([0,1.,0]); se, a, g = .1, .8, .3
    tt = np.linspace(t0, t1, 400001); x = o[None,:]+tt[:,None]*d[None,:]
    v = lamp[None,:]-x; dist = np.linalg.norm(v, axis=1); u = v/dist[:,None]
    ell = exitdist(x, u)
    f = se*a*hg(g, u@d)/(4*np.pi)*1000*np.pi*.05**2/dist**2*np.exp(-se*(1-a)*ell)*np.exp(-se*(tt-t0))
    return np.exp(-se*glow_t) + trapz(f, tt)
cref = [c_ref(np.array([0,-4.5,1.5]), 3.5, 5.5, 2), 1.0, c_ref(np.array([0,0,1.5]), 0, 1, 1),
        1.0, c_ref(np.array([.6,-4.5,1.5]), 3.5, 5.0, 1.5)]
m, s = stats(load('c_list_rays.txt'), NREP); report('c_list', cref, m, s)
print("   (c_list ray3 hits a glow inside the mist from an eye inside the mist: physically", np.exp(-.1)+0, "+ in-scatter)")
m, s = stats(load('c_nolist_rays.txt'), NREP)
print("c_nolist rays:", m, " hand (extinction only, for rays entering from outside):", [np.exp(-.2), 1, np.exp(-.1), np.exp(-.1), np.exp(-.15)])
E0 = 1000*np.pi*.05**2
sref = [E0/2.5**2*np.exp(-.02*1.5), E0/3.3**2*np.exp(-.02*2), E0*2.5/(9+2.5**2)**1.5]
print("c_list sensors:", load('c_list_sensors.txt')[:,0], " hand:", sref)
print("c_nolist sensors:", load('c_nolist_sensors.txt')[:,0], " hand (physical):", sref, "unattenuated:", E0/2.5**2)
# ---- d: -ab 1 sensor irradiance = single-scattered light from the medium (lamp behind the sensor)
n = 300; u1, u2 = np.meshgrid((np.arange(n)+.5)/n, (np.arange(n)+.5)/n); u1 = u1.ravel(); u2 = u2.ravel()
r = np.sqrt(u1); ph = 2*np.pi*u2
dirs = np.stack([r*np.cos(ph), r*np.sin(ph), -np.sqrt(1-u1)], 1)      # cosine-weighted about -z
o = np.array([0,0,-1.]); blo, bhi = np.array([-20,-10,-20.]), np.array([20,4.999,20.])
Lsum = []
for k in range(0, len(dirs), 2000):
    D = dirs[k:k+2000]
    with np.errstate(divide='ignore'):
        tb = np.where(D > 0, (bhi-o)/D, np.where(D < 0, (blo-o)/D, np.inf)).min(1)
    s_ = (np.arange(4000)+.5)/4000
    t = tb[:,None]*s_[None,:]
    x = o[None,None,:] + t[:,:,None]*D[:,None,:]
    dist2 = (x**2).sum(2)
    f = .01/(4*np.pi)*E0/dist2*np.exp(-.01*t)
    Lsum.append(f.mean(1)*tb)
Ess = np.pi*np.concatenate(Lsum).mean()
dm = load('d_ab1_sensor.txt')[:,0]
print(f"d -ab1 sensor: radiance {dm.mean():.5e} +- {dm.std(ddof=1)/np.sqrt(len(dm)):.1e}  single-scatter irradiance (python) {Ess:.5e}  ratio {dm.mean()/Ess:.4f}; -ab 0: {load('d_ab0_sensor.txt')[:,0].mean()}")
# ---- physical single scattering (source path attenuated by full extinction e^{-σe d}), for Brume
def sphere_phys(g, flen=0., aim=None, cone=None):
    f0 = sphere_f(g, se_, 1., flen, aim, cone)
    def f(x, t, d):
        dist = np.linalg.norm(S[None,:]-x, axis=1)
        return f0(x, t, d)*np.exp(-se_*dist)
    return f
for tag, fn, rf in (('b_iso', lambda: sphere_phys(0.), 'b_rays.txt'), ('b_g06', lambda: sphere_phys(.6), 'b_rays.txt'),
                    ('b_spot', lambda: sphere_phys(0., 1., np.array([0,0,-1.]), 60), 'b_spot_rays.txt')):
    vals = []
    for o in rays(rf):
        o_, d = o[:3], o[3:]/np.linalg.norm(o[3:]); t1 = (4.999-o_[1])/d[1]
        vals.append(line(o_, d, t1, fn()))
    print(f"{tag} physical single scatter (full extinction on source path): {np.array(vals)}")
for alb, g, tag in ((1., 0., 'b_sun_a1'), (.5, .6, 'b_sun_a05_g06')):
    vals = []
    for o in rays('b_sun_rays.txt'):
        o_, d = o[:3], o[3:]/np.linalg.norm(o[3:]); t0 = (-2-o_[1])/d[1]; t1 = (2-o_[1])/d[1]
        if d[2] > 0: t1 = min(t1, (1-o_[2])/d[2])
        tt = np.linspace(t0, t1, 200001); x = o_[None,:]+tt[:,None]*d[None,:]
        f = .05*alb*hg(g, d[2]*np.ones_like(tt))/(4*np.pi)*Esun*np.exp(-.05*(1-x[:,2]))*np.exp(-.05*(tt-t0))
        vals.append(trapz(f, tt))
    print(f"{tag} physical single scatter (full extinction on sun path): {np.array(vals)}")
# ---- c, physical single scattering (full extinction σe on the lamp path inside the mist), for Brume
def c_phys(o, t0, t1, glow_t):
    d = np.array([0,1.,0]); se, a, g = .1, .8, .3
    tt = np.linspace(t0, t1, 400001); x = o[None,:]+tt[:,None]*d[None,:]
    v = lamp[None,:]-x; dist = np.linalg.norm(v, axis=1); u = v/dist[:,None]
    f = se*a*hg(g, u@d)/(4*np.pi)*1000*np.pi*.05**2/dist**2*np.exp(-se*exitdist(x, u))*np.exp(-se*(tt-t0))
    return np.exp(-se*glow_t) + trapz(f, tt)
print("c physical single scatter (rays 0, 2, 3, 4; ray 3's eye is inside the mist):", [c_phys(np.array([0,-4.5,1.5]), 3.5, 5.5, 2),
      c_phys(np.array([0,0,1.5]), 0, 1, 1), c_phys(np.array([.6,-.5,1.5]), 0, 1, 1), c_phys(np.array([.6,-4.5,1.5]), 3.5, 5.0, 1.5)])
