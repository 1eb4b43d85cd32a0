#!/bin/bash
# Writes three_phase_reference.txt: the 3-phase method on room.rad (a side-lit room whose window is
# ../bsdf/prism_quarter.xml, on Klems' quarter basis) for sensors.pts under 48 hours of Chicago
# (../daymtx/chicago48.wea), by Radiance 6.1's own rfluxmtx, gendaymtx, dctimestep and rmtxop: each sensor's
# mean illuminance over the 48 hours (lux) and its relative standard error, from four independent view
# matrices (-ab 7 -ad 16384 -lw 1e-6) and two daylight matrices (-ab 3 -ad 2048 -lw 1e-5 -c 8000), every
# pair multiplied. Needs Radiance's programs and .cal files:
#   PATH=/tmp/radiance/inst/bin:$PATH RAYPATH=.:/tmp/radiance/inst/lib test/data/rfluxmtx/make_three_phase_reference.sh
set -euo pipefail
cd "$(dirname "$0")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp ../rcontrib/sky.rad "$tmp/sky.rad"
gendaymtx -m 1 -of ../daymtx/chicago48.wea > "$tmp/sky.smx"
for v in 1 2 3 4; do
    rfluxmtx -u+ -I -ab 7 -ad 16384 -lw 1e-6 -c 1 -y 16 - window_v.rad room.rad < sensors.pts > "$tmp/v$v.mtx"
done
for d in 1 2; do
    rfluxmtx -u+ -ab 3 -ad 2048 -lw 1e-5 -c 8000 window_d.rad "$tmp/sky.rad" room.rad > "$tmp/d$d.mtx"
done
for v in 1 2 3 4; do
    for d in 1 2; do
        dctimestep "$tmp/v$v.mtx" ../bsdf/prism_quarter.xml "$tmp/d$d.mtx" "$tmp/sky.smx" |
            rmtxop -fa -c 47.4 119.9 11.6 - | sed '1,/^$/d' |
            awk '{ s = 0; for (i = 1; i <= NF; i++) s += $i; print s / NF }' > "$tmp/mean_$v$d.txt"
    done
done
{
    echo "# lux (the mean over chicago48.wea's 48 hours), relative standard error over 4 view x 2 daylight matrices:"
    echo "# Radiance 6.1's 3-phase method, made by make_three_phase_reference.sh"
    paste "$tmp"/mean_*.txt | awk '{ n = NF; s = 0; for (i = 1; i <= n; i++) s += $i; m = s / n
        v = 0; for (i = 1; i <= n; i++) v += ($i - m) ^ 2; printf "%.6g %.3g\n", m, sqrt(v / (n - 1) / n) / m }'
} > three_phase_reference.txt
