#!/bin/bash
# Writes bins.txt: for 400 directions spread over the sphere (a Fibonacci lattice, jittered), the bins
# Radiance 6.1's tregenza.cal, reinhart.cal (MF 1, 2, 4) and reinhartb.cal (a window facing south with up
# along z, MF 2, left-handed; and with JTR 1) give them, by Radiance's own rcalc; test/cal_bins_test.cpp
# compares Brume's files with them. Needs Radiance's rcalc and .cal files:
#   PATH=/tmp/radiance/inst/bin:$PATH RAYPATH=.:/tmp/radiance/inst/lib test/data/daymtx/make_bins.sh
set -euo pipefail
cd "$(dirname "$0")"
python3 -c '
import math
n = 400
for i in range(n):
    z = 1 - (2 * i + 1) / n + 0.37 / n * math.sin(7.3 * i)
    r = math.sqrt(max(0, 1 - z * z))
    a = i * math.pi * (3 - math.sqrt(5)) + 0.011 * math.cos(3.1 * i)
    print("%.9f %.9f %.9f" % (r * math.cos(a), r * math.sin(a), z))
' > /tmp/bins_dirs.txt
paste -d' ' /tmp/bins_dirs.txt \
    <(rcalc -e 'Dx=$1;Dy=$2;Dz=$3' -f tregenza.cal -e '$1=tbin' < /tmp/bins_dirs.txt) \
    <(rcalc -e 'Dx=$1;Dy=$2;Dz=$3' -e 'MF:1' -f reinhart.cal -e '$1=rbin' < /tmp/bins_dirs.txt) \
    <(rcalc -e 'Dx=$1;Dy=$2;Dz=$3' -e 'MF:2' -f reinhart.cal -e '$1=rbin' < /tmp/bins_dirs.txt) \
    <(rcalc -e 'Dx=$1;Dy=$2;Dz=$3' -e 'MF:4' -f reinhart.cal -e '$1=rbin' < /tmp/bins_dirs.txt) \
    <(rcalc -e 'Dx=$1;Dy=$2;Dz=$3' -f reinhartb.cal -e 'MF=2;RHS=-1;rNx=0;rNy=1;rNz=0;Ux=0;Uy=0;Uz=1' -e '$1=rbin' < /tmp/bins_dirs.txt) \
    <(rcalc -e 'Dx=$1;Dy=$2;Dz=$3' -f reinhartb.cal -e 'MF=1;JTR=1' -e '$1=rbin' < /tmp/bins_dirs.txt) \
    > bins.txt
