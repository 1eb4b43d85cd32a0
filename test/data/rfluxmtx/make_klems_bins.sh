#!/bin/bash
# Writes klems_bins.txt: for the 400 directions of ../daymtx/bins.txt (spread over the sphere), the bins
# Radiance 6.1's klems_full.cal, klems_half.cal and klems_quarter.cal give them (a south window, a tilted
# left-handed frame with an up that is not unit, jitter, a skylight), by Radiance's own rcalc;
# test/cal_bins_test.cpp compares Brume's files with them. Needs Radiance's rcalc and .cal files:
#   PATH=/tmp/radiance/inst/bin:$PATH RAYPATH=.:/tmp/radiance/inst/lib test/data/rfluxmtx/make_klems_bins.sh
set -euo pipefail
cd "$(dirname "$0")"
cut -d' ' -f1-3 ../daymtx/bins.txt > /tmp/klems_dirs.txt
bins() { rcalc -e 'Dx=$1;Dy=$2;Dz=$3' -f "$1" -e "$2" -e "\$1=$3" < /tmp/klems_dirs.txt; }
paste -d' ' /tmp/klems_dirs.txt \
    <(bins klems_full.cal 'RHS=1' 'kbinS') \
    <(bins klems_full.cal 'RHS=-1' 'kbin(0.36,-0.8,0.48,0.1,0.2,1.7)') \
    <(bins klems_full.cal 'JTR=1' 'kbin(0,0,-1,0,1,0)') \
    <(bins klems_half.cal 'RHS=1' 'khbin(-0.6,0,-0.8,0,0,2)') \
    <(bins klems_half.cal 'RHS=-1' 'khbin(0,0,-1,0,1,0)') \
    <(bins klems_quarter.cal 'RHS=1' 'kqbin(0.36,-0.8,0.48,0.1,0.2,1.7)') \
    <(bins klems_quarter.cal 'JTR=.5' 'kqbin(1,0,0,0,0,1)') \
    > klems_bins.txt
