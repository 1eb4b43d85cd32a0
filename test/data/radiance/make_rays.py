#!/usr/bin/env python3
"""Writes rays.txt and sensors.txt for materials.rad (run: python3 make_rays.py [outdir]).

Each line is "label x y z dx dy dz": a view ray aimed at a surface of one material (rays.txt), or a
sensor point and its normal for rtrace -I (sensors.txt). Points are kept off penumbrae of sphere sources
and the sun, off the spotlight's cone edge and off the glow's 2 m radius, where Radiance's one shadow ray
per sphere (or sun) gives a step the exact answer does not have.
"""
import math
def norm(v):
    l=math.sqrt(sum(c*c for c in v)); return [c/l for c in v]
def sub(a,b): return [a[i]-b[i] for i in range(3)]
rays=[]
def look(label, cam, target):
    rays.append((label, cam, norm(sub(target,cam))))
def ray(label, cam, d):
    rays.append((label, cam, norm(d)))
C1=[3.0,2.5,1.6]; C2=[0.5,0.5,1.6]; C3=[5.5,4.5,1.6]; C4=[1.0,4.5,1.2]; C5=[5.0,1.0,1.0]
sun=norm([0.5,0.1,0.85])
# floor (diffuse plastic)
for i,(t,c) in enumerate([([2.6,2.6,0],C1),([2.0,3.8,0],C4),([3.5,1.6,0],C1),([5.5,1.6,0],C5),([1.5,1.5,0],C2),([3.0,3.5,0],C3),([0.3,3.0,0],C4),([5.2,2.4,0],C1),([4.6,4.6,0],C3)]):
    look("floor_%d"%i, c, t)
look("floor_skylight_sun", C1, [2.13,3.55,0])
for i,(t,c) in enumerate([([3.0,1.0,3],C1),([2.0,4.5,3],C1),([5.0,4.0,3],C5),([0.5,0.5,3],C1),([5.5,2.0,3],C2)]):
    look("ceiling_%d"%i, c, t)
for i,(t,c) in enumerate([([0,1.0,1.5],C1),([0,4.8,0.7],C1),([0,4.0,0.5],[1.5,3.0,1.5]),([0,0.7,2.5],[2.0,2.0,0.8]),([0,1.5,0.3],C5)]):
    look("rough_wall_%d"%i, c, t)
for i,(t,c) in enumerate([([3.0,0,1.5],C1),([4.5,0,1.2],C1),([2.5,0,2.8],C1),([5.5,0,2.0],C4)]):
    look("wall_south_%d"%i, c, t)
for i,(t,c) in enumerate([([1.5,5,1.5],C1),([5.8,5,2.5],C1),([0.5,5,0.5],C5),([2.0,5,2.8],C5)]):
    look("wall_north_%d"%i, c, t)
for i,(t,c) in enumerate([([6,1.0,1.5],C1),([6,4.5,0.5],C1),([6,2.7,2.6],C2),([6,2.7,0.5],C2),([6,4.2,1.6],C4)]):
    look("wall_east_%d"%i, c, t)
# window: glass pane behind a void illum, sky and ground glows, the sun
look("window_level", C1, [6,2.75,1.6]); look("window_sky", [5.0,2.75,1.0], [6,2.75,2.0])
look("window_ground", [5.0,2.75,2.0], [6,2.75,1.1]); look("window_oblique", C4, [6,2.6,1.4])
ray("window_sun", [5.06,2.55,0.01], sun)
look("skylight_up", [3.9,3.9,1.0], [3.9,3.9,3]); look("skylight_oblique", C2, [4.1,3.7,3])
ray("skylight_sun", [2.13,3.55,0.01], sun)
# emitters seen directly
look("panel_below", [1.5,1.5,1.0], [1.5,1.5,2.98]); look("panel_oblique", C1, [1.45,1.55,2.98])
look("bulb_centre", C1, [4.5,1.2,2.3]); look("bulb_edge", C5, [4.52,1.21,2.3])
look("downlight_below", [1.5,4.0,1.0], [1.5,4.0,2.98]); look("downlight_oblique", C1, [1.52,3.98,2.98])
look("tube_lamp_front", [3.0,1.5,1.5], [2.2,1.5,2.5]); look("tube_lamp_oblique", C5, [2.2,3.0,2.5])
look("spot_inside_cone", [3.0,2.5,1.0], [3.0,2.5,2.98]); look("spot_outside_cone", [0.5,2.5,1.0], [3.0,2.5,2.98])
look("glow_ball", [4.0,2.5,1.5], [5.3,3.9,1.5]); look("exit_sign", C1, [2.8,4.99,2.4])
look("exit_sign_oblique", C5, [2.7,4.99,2.35])
# pure-specular plastic table, both sides
look("table_top_0", C2, [1.6,2.3,0.75]); look("table_top_1", C1, [1.4,2.8,0.75])
look("table_top_grazing", [3.5,2.5,0.9], [1.3,2.3,0.75])
# (no ray at the table's underside: it reflects the floor next to the table, where the table hides part of
# the tube lamp and Radiance's 64 cells along the tube make that edge a few percent off)
look("bowl_outside", C2, [1.6,2.5,0.85]); look("bowl_inside", [1.6,2.5,1.8], [1.7,2.5,0.85])
look("bowl_outside_1", C1, [1.65,2.5,0.9])
look("rug_0", C1, [0.75,1.5,0.002]); look("rug_1", C1, [1.8,0.6,0.002]); look("rug_2", C4, [0.75,0.75,0.002])
look("rug_notch_floor", C1, [1.8,1.6,0.0])
look("washer", C1, [4.3,4.2,0.002]); look("washer_hole_floor", [4.0,4.2,1.0], [4.02,4.2,0])
look("ball_0", [4.0,3.45,1.0], [5.2,4.2,0.43]); look("ball_1", C1, [5.2,4.2,0.4]); look("ball_2", C5, [5.2,4.0,0.5])
look("satin_0", [1.4,2.0,1.4], [1.4,0.01,1.4]); look("satin_1", [1.0,2.6,1.1], [1.25,0.01,1.3])
look("chrome_0", C1, [2.2,0.9,0.3]); look("chrome_1", [2.2,2.0,0.3], [2.2,0.9,0.3]); look("chrome_2", C5, [2.2,0.9,0.4])
look("column_0", [2.6,1.9,1.1], [4.0,3.0,1.1]); look("column_1", [3.3,4.1,0.9], [4.0,3.0,0.9])
look("column_near_glow", [5.0,2.0,1.5], [4.1194816,2.9888578,1.5])
look("metal_sheet_window", [3.0,2.75,1.6], [0.01,2.75,1.6]); look("metal_sheet_1", [2.0,3.3,1.3], [0.01,2.10,1.26])
look("plate_bulb_through_shelf", [3.45,1.2,1.0], [3.768,1.2,0.003]); look("plate_1", [4.25,2.4,1.2], [4.25,1.2,0.003])
look("bronze_0", C1, [5.0,0.8,0.4]); look("bronze_1", C2, [5.0,0.8,0.2]); look("bronze_2", [5.0,2.5,1.5], [5.0,0.8,0.6])
look("frosted_highlight", [0.2,4.0,1.4], [0.5,4.0,1.5]); look("frosted_back", [0.2,4.0,1.8], [0.5,4.0,1.8])
look("frosted_front", [2.0,4.0,2.0], [0.5,3.8,2.0]); look("frosted_back_1", [0.1,3.7,1.6], [0.5,4.2,2.0])
look("shelf_up_to_bulb", [4.5,1.2,0.5], [4.5,1.2,2.3]); look("shelf_oblique", C1, [4.5,1.2,1.8])
look("shelf_below", [3.5,1.2,0.8], [4.4,1.1,1.8])
look("mirror_0", C1, [4.7,4.99,1.4]); look("mirror_1", [4.7,3.5,1.5], [4.7,4.99,1.3]); look("mirror_2", C4, [4.5,4.99,1.8])
look("crystal_centre", [3.0,2.0,1.0], [3.0,4.3,1.0]); look("crystal_off_axis", [2.5,3.0,1.2], [3.0,4.3,1.0])
look("crystal_edge", C1, [3.1,4.25,1.1])
look("pedestal", [3.0,3.0,0.4], [3.0,4.3,0.4]); look("pedestal_1", C5, [3.0,4.3,0.5])
import sys
out=sys.argv[1] if len(sys.argv)>1 else "."
with open(out+"/rays.txt","w") as f:
    f.write("# label  origin xyz  direction xyz (rtrace input after the label)\n")
    for l,o,d in rays: f.write("%-26s %.6g %.6g %.6g  %.9f %.9f %.9f\n"%(l,*o,*d))
# sensors for -I
sens=[]
def inside(p):
    x,y,z=p
    if (x-5.0)**2+(y-0.8)**2<0.4**2: return True
    if (x-4.0)**2+(y-3.0)**2<0.2**2: return True
    if (x-3.0)**2+(y-4.3)**2<0.1**2: return True
    if (x-5.2)**2+(y-4.2)**2<0.4**2: return True
    return False
import random
random.seed(7)
# jittered points that fell on a penumbra (sphere sources and the sun are one shadow ray in Radiance), a
# spotlight cone edge or the glow's radius, moved off it
moved={(0.804,2.546):(0.6,2.6),(3.056,0.749):(3.2,0.95),(3.075,1.525):(3.3,1.6),(3.797,2.63):(3.5,3.2),
       (4.336,3.567):(4.1,3.4),(5.56,2.582):(5.6,2.3),(3.043,2.482):(3.3,2.5)}
for x in [0.8,1.5,2.2,3.0,3.8,4.5,5.3]:
    for y in [0.8,1.7,2.6,3.5,4.4]:
        x=round(x+random.uniform(-0.2,0.2),3); y=round(y+random.uniform(-0.2,0.2),3)
        x,y=moved.get((x,y),(x,y))
        p=[x,y,0.01]
        if not inside(p): sens.append(("floor_%g_%g"%(x,y), p, [0,0,1]))
for x in [0.9,1.8,2.7,3.6,4.5,5.4]:
    for y in [1.0,2.5,4.0]:
        x=round(x+random.uniform(-0.2,0.2),3); y=round(y+random.uniform(-0.2,0.2),3)
        p=[x,y,0.8]; sens.append(("work_%g_%g"%(x,y), p, [0,0,1]))
for i,(p,n) in enumerate([([0.01,1.0,1.2],[1,0,0]),([0.01,1.5,1.2],[1,0,0]),([3.0,0.01,1.2],[0,1,0]),([5.5,0.01,2.0],[0,1,0]),
                          ([2.0,4.99,1.2],[0,-1,0]),([5.8,4.99,2.6],[0,-1,0]),([5.99,1.0,1.2],[-1,0,0]),([5.99,4.5,2.5],[-1,0,0])]):
    sens.append(("wall_%d"%i, p, n))
for i,(p,n) in enumerate([([3.0,2.5,1.5],[1,0,0]),([3.0,2.5,1.5],[-1,0,0]),([3.0,2.5,1.5],[0,1,0]),([3.0,2.5,1.5],[0,-1,0]),
                          ([3.0,2.5,1.5],[0,0,-1]),([2.0,2.0,1.2],[0.3,-0.4,0.8]),([4.5,3.5,1.0],[0.6,0.2,0.5]),([1.5,3.5,1.5],[-0.2,0.3,1])]):
    sens.append(("mid_%d"%i, p, n))
sens.append(("sun_window_patch", [5.2,2.4,0.01],[0,0,1]))
sens.append(("sun_skylight_patch", [2.13,3.55,0.01],[0,0,1]))
with open(out+"/sensors.txt","w") as f:
    f.write("# label  point xyz  normal xyz (rtrace -I input after the label)\n")
    for l,o,d in sens: f.write("%-26s %.6g %.6g %.6g  %.9g %.9g %.9g\n"%(l,*o,*norm(d)))
print(len(rays), "rays,", len(sens), "sensors")
