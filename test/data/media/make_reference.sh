#!/bin/sh
# Regenerate Radiance 6.1 reference outputs for participating media into out/.
# Needs rtrace/oconv/genbox/xform on PATH and RAYPATH; python3+numpy for check.py.
# Usage: sh make_reference.sh [NREP]   (NREP repeats of each jittered ray; default 4000)
set -e
cd "$(dirname "$0")"
N=${1:-4000}
mkdir -p out oct
rep() { awk -v n="$N" '{for(i=0;i<n;i++) print}' "$1"; }    # repeat each ray N times (consecutive)
rt() { rtrace -h "$@" 2>/dev/null; }                             # -h: no header (no CAPDATE/GMT)
oconv a_panel.rad > oct/a.oct
oconv b_sphere.rad > oct/b_sphere.oct
oconv b_spot.rad > oct/b_spot.oct
sed 's/ALB/1/g; s/ G$/ 0/' b_sun.rad | oconv - > oct/b_sun_a1.oct
sed 's/ALB/.5/g; s/ G$/ .6/' b_sun.rad | oconv - > oct/b_sun_a05_g06.oct
sed 's/LIST/1 lamp/' c_room.rad | oconv - > oct/c_list.oct
sed 's/LIST/0/' c_room.rad | oconv - > oct/c_nolist.oct
# a: pure attenuation / ambient in-scatter (deterministic)
rt -ab 0 -me .1 .1 .1 -ma 0 0 0 oct/a.oct < a_rays.txt > out/a1.txt
rt -ab 0 -me .1 .2 .3 -ma .5 .5 .5 -av .2 .2 .2 oct/a.oct < a_rays.txt > out/a2.txt
# b: single scattering of a sphere lamp (global medium, mist box only names the lamp)
B="-ab 0 -dj 0 -ds 0 -ms .01 -me .01 .01 .01 -ma 1 1 1"
rep b_rays.txt | rt $B -mg 0 oct/b_sphere.oct > out/b_iso.txt
rep b_rays.txt | rt $B -mg .6 oct/b_sphere.oct > out/b_g06.txt
rep b_rays.txt | rt $B -mg -.6 oct/b_sphere.oct > out/b_gm06.txt
rep b_spot_rays.txt | rt $B -mg 0 oct/b_spot.oct > out/b_spot.txt
# same medium without the mist box: no source in-scattering at all
grep -v fog b_sphere.rad | oconv - > oct/b_nomist.oct
rt $B oct/b_nomist.oct < b_rays.txt > out/b_nomist.txt
# b-sun: mist with own extinction (global medium 0)
rep b_sun_rays.txt | rt -ab 0 -dj 0 -ms .01 oct/b_sun_a1.oct > out/b_sun_a1.txt
rep b_sun_rays.txt | rt -ab 0 -dj 0 -ms .01 oct/b_sun_a05_g06.oct > out/b_sun_a05_g06.txt
# b-sun with an absorbing global medium: the sun's shadow rays go to infinity -> sun extinguished
rt -ab 0 -dj 0 -ms .01 -me .001 .001 .001 -ma .5 .5 .5 oct/b_sun_a1.oct < b_sun_rays.txt > out/b_sun_globalabs.txt
rt -ab 0 -dj 0 -ms .01 -me .001 .001 .001 -ma 1 1 1 oct/b_sun_a1.oct < b_sun_rays.txt > out/b_sun_globalscat.txt
# c: mist box in a room, with / without source list; view rays and -I sensors
for v in list nolist; do
  rep c_rays.txt | rt -ab 0 -dj 0 -ms .01 oct/c_$v.oct > out/c_${v}_rays.txt
  rt -I -ab 0 -dj 0 oct/c_$v.oct < c_sensors.txt > out/c_${v}_sensors.txt
done
# determinism: -u- twice (identical), -u+ and reversed order (same means within SE)
rt $B -u- oct/b_sphere.oct < b_rays.txt > out/det_u-_1.txt
rt $B -u- oct/b_sphere.oct < b_rays.txt > out/det_u-_2.txt
rep b_rays.txt | tac | rt $B -u+ oct/b_sphere.oct | tac > out/b_iso_reversed.txt
# d: -ab 1 in the b medium: -I sensor at (0,0,-1) facing down (lamp behind it: direct = 0)
D=$(awk -v n=$((N/4)) 'BEGIN{for(i=0;i<n;i++) print "0 0 -1 0 0 -1"}')
echo "$D" | rt -I $B -ab 1 -aa 0 -ad 2048 -as 0 -lw 1e-9 -mg 0 oct/b_sphere.oct > out/d_ab1_sensor.txt
echo "$D" | rt -I $B -ab 0 -mg 0 oct/b_sphere.oct > out/d_ab0_sensor.txt
# the repeated-ray outputs are large: keep them gzipped (-n: no timestamp)
for f in b_iso b_g06 b_gm06 b_spot b_sun_a1 b_sun_a05_g06 c_list_rays c_nolist_rays b_iso_reversed; do
  gzip -n -f out/$f.txt
done
echo "done; now: /usr/bin/python3 check.py $N"
