#!/usr/bin/python3
"""Generate Model A (side-lit office) and Model B (deep plan, several windows)
Radiance geometry, sensor grids and the rfluxmtx sky files of bench/annual.py, in the current directory
(needs numpy: /usr/bin/python3 make_models.py).
All coordinates in metres; z up, y north, x east.  Window walls are 0.2 m
thick (interior face, exterior face, reveals); the glazing sits at mid-depth
of the window wall.  The other walls, floor and ceiling are single interior
faces (their outsides can never be reached by a ray: the sky/ground are
distant glow hemispheres, not geometry)."""
import numpy as np

T = 0.2  # window-wall thickness

MATS = """void plastic wall_mat 0 0 5 0.5 0.5 0.5 0 0
void plastic floor_mat 0 0 5 0.2 0.2 0.2 0 0
void plastic ceiling_mat 0 0 5 0.8 0.8 0.8 0 0
void plastic ext_mat 0 0 5 0.5 0.5 0.5 0 0
void glass glazing 0 0 3 0.654 0.654 0.654
"""

_n = [0]


def poly(mod, name, pts, normal):
    pts = [np.asarray(p, float) for p in pts]
    nrm = np.cross(pts[1] - pts[0], pts[2] - pts[1])
    if np.dot(nrm, normal) < 0:
        pts = pts[::-1]
    _n[0] += 1
    s = f"{mod} polygon {name}_{_n[0]}\n0\n0\n{3*len(pts)}\n"
    s += "".join(f"  {p[0]:.4f} {p[1]:.4f} {p[2]:.4f}\n" for p in pts)
    return s


def P(axis, c, u, z):
    """point on a vertical plane axis=c ('y' or 'x'), along-wall coord u, height z"""
    return (u, c, z) if axis == 'y' else (c, u, z)


def rect_v(mod, name, axis, c, u0, u1, z0, z1, normal):
    return poly(mod, name, [P(axis, c, u0, z0), P(axis, c, u1, z0),
                            P(axis, c, u1, z1), P(axis, c, u0, z1)], normal)


def wall_with_holes(mod, name, axis, c, U0, U1, H, holes, sill, head, normal):
    """wall rectangle [U0,U1]x[0,H] minus holes [(u0,u1)] all at the same sill/head"""
    s = rect_v(mod, name, axis, c, U0, U1, 0, sill, normal)
    s += rect_v(mod, name, axis, c, U0, U1, head, H, normal)
    edges = [U0] + [v for h in sorted(holes) for v in h] + [U1]
    for a, b in zip(edges[0::2], edges[1::2]):
        if b - a > 1e-9:
            s += rect_v(mod, name, axis, c, a, b, sill, head, normal)
    return s


def window_wall(axis, c_in, out_sign, U0, U1, H, holes, sill, head):
    """thick window wall: interior plane at c_in, exterior at c_in+out_sign*T"""
    nin = np.zeros(3); nout = np.zeros(3)
    k = 1 if axis == 'y' else 0
    nin[k] = -out_sign; nout[k] = out_sign
    c_out = c_in + out_sign * T
    c_gl = c_in + out_sign * T / 2
    s = wall_with_holes('wall_mat', f'{axis}{c_in:g}_in', axis, c_in, U0, U1, H,
                        holes, sill, head, nin)
    s += wall_with_holes('ext_mat', f'{axis}{c_in:g}_out', axis, c_out, U0, U1, H,
                         holes, sill, head, nout)
    ku = 0 if axis == 'y' else 1
    for (u0, u1) in holes:
        # reveals (normals pointing into the opening)
        def R(pa, pb, nrm, nm):
            return poly('wall_mat', nm, pa + pb, nrm)
        for (z, nz) in ((sill, 1), (head, -1)):
            nrm = np.array([0, 0, nz], float)
            s += poly('wall_mat', 'reveal', [P(axis, c_in, u0, z), P(axis, c_in, u1, z),
                                           P(axis, c_out, u1, z), P(axis, c_out, u0, z)], nrm)
        for (u, nu) in ((u0, 1), (u1, -1)):
            nrm = np.zeros(3); nrm[ku] = nu
            s += poly('wall_mat', 'reveal', [P(axis, c_in, u, sill), P(axis, c_out, u, sill),
                                           P(axis, c_out, u, head), P(axis, c_in, u, head)], nrm)
    glass = ""
    for (u0, u1) in holes:
        glass += rect_v('glazing', f'win_{axis}', axis, c_gl, u0, u1, sill, head, nout)
    return s, glass


def room(W, D, H, south_holes, east_holes, sill, head):
    s = "# --- interior surfaces (normals into the room) ---\n"
    s += poly('floor_mat', 'floor', [(0, 0, 0), (W, 0, 0), (W, D, 0), (0, D, 0)], (0, 0, 1))
    s += poly('ceiling_mat', 'ceiling', [(0, 0, H), (W, 0, H), (W, D, H), (0, D, H)], (0, 0, -1))
    s += rect_v('wall_mat', 'west', 'x', 0, 0, D, 0, H, (1, 0, 0))
    s += rect_v('wall_mat', 'north', 'y', D, 0, W, 0, H, (0, -1, 0))
    glass = ""
    if south_holes:
        a, g = window_wall('y', 0.0, -1, 0, W, H, south_holes, sill, head)
        s += "# --- south window wall (0.2 m thick) ---\n" + a; glass += g
    else:
        s += rect_v('wall_mat', 'south', 'y', 0, 0, W, 0, H, (0, 1, 0))
    if east_holes:
        a, g = window_wall('x', W, +1, 0, D, H, east_holes, sill, head)
        s += "# --- east window wall (0.2 m thick) ---\n" + a; glass += g
    else:
        s += rect_v('wall_mat', 'east', 'x', W, 0, D, 0, H, (-1, 0, 0))
    return s + "# --- glazing (tn = 0.6) ---\n" + glass


def grid(W, D, sp, z):
    nx, ny = int(np.floor(W / sp + 1e-9)), int(np.floor(D / sp + 1e-9))
    xs = (W - (nx - 1) * sp) / 2 + sp * np.arange(nx)
    ys = (D - (ny - 1) * sp) / 2 + sp * np.arange(ny)
    lines = [f"{x:.3f} {y:.3f} {z:.3f} 0 0 1" for y in ys for x in xs]
    return "\n".join(lines) + "\n", nx, ny


def sky(n):
    return f"""#@rfluxmtx h=u u=Y
void glow ground_glow
0
0
4 1 1 1 0

ground_glow source ground
0
0
4 0 0 -1 180

#@rfluxmtx h=r{n} u=Y
void glow sky_glow
0
0
4 1 1 1 0

sky_glow source sky
0
0
4 0 0 1 180
"""


if __name__ == "__main__":
    hdr = "# generated by gen_models.py\n"
    # Model A: 6 x 8 x 3, window 5.6 x 1.5, sill 0.9
    with open("materials.rad", "w") as f:
        f.write(MATS)
    with open("office.rad", "w") as f:
        f.write(hdr + "# Model A: side-lit office 6 (x) x 8 (y) x 3 m, south window 5.6 x 1.5 m, sill 0.9 m\n")
        f.write(room(6, 8, 3, [(0.2, 5.8)], [], 0.9, 2.4))
    g, nx, ny = grid(6, 8, 0.5, 0.75)
    open("grid.pts", "w").write(g)
    print("model A grid", nx, ny, nx * ny)
    # Model B: 20 x 12 x 3, south windows 2 x (4 x 1.5), east window 3 x 1.5
    with open("deepplan.rad", "w") as f:
        f.write(hdr + "# Model B: deep plan 20 (x) x 12 (y) x 3 m; south windows x=3-7 and 13-17;"
                " east window y=4.5-7.5; all 1.5 m high, sill 0.9 m\n")
        f.write(room(20, 12, 3, [(3, 7), (13, 17)], [(4.5, 7.5)], 0.9, 2.4))
    g, nx, ny = grid(20, 12, 0.75, 0.75)
    open("grid_B.pts", "w").write(g)
    print("model B grid", nx, ny, nx * ny)
    open("sky.rad", "w").write(sky(1))
    open("sky_r2.rad", "w").write(sky(2))
