#!/bin/bash
# Writes Radiance's output for each line of commands.txt into radiance/NN.txt (NN: the line number), and
# fingerprints.txt: for whole years of the shared weather files, the CRC-32 and length of the data (after the
# header) that Radiance's gendaymtx writes with -of. (Not -i there: Radiance is built with -mfma, and where
# -i moves a record's time to the middle of its daylit part, 22 of 8760 columns of the PVGIS year differ from
# Brume's in the last bit of a float; commands.txt has -i at the printed precision.) test/daymtx_cli_test.cpp compares Brume's programs with
# both. Needs Radiance's programs on PATH (6.1a, commit bcffc2b52d of LBNL-ETA/Radiance, built with CMake,
# -DBUILD_HEADLESS=ON); chicago48.wea is Radiance's epw2wea of ../shared/data/weather/chicago.epw, its
# header and the records of June 21st and December 21st. a.mtx, b.mtx, dc.mtx, v41.mtx and d41.mtx were written by hand.
#   PATH=/tmp/radiance/inst/bin:$PATH test/data/daymtx/make_radiance_outputs.sh
set -euo pipefail
cd "$(dirname "$0")"
weather=../../../../shared/data/weather
n=0
while read -r line; do
    n=$((n + 1))
    set -f
    $line > "radiance/$(printf %02d $n).txt" 2> /dev/null
    set +f
done < commands.txt
epw2wea $weather/chicago.epw /tmp/chicago.wea
epw2wea $weather/tmy_45.000_8.000_2005_2023.epw /tmp/tmy45.wea
{
    echo "# crc32 bytes command (the data after the header of gendaymtx -of; the .wea files are epw2wea's)"
    while read -r input options; do
        gendaymtx $options -of "$input" 2> /dev/null | python3 -c '
import sys, zlib
b = sys.stdin.buffer.read(); d = b[b.index(b"\n\n") + 2:]
print("%08x %d" % (zlib.crc32(d), len(d)), end=" ")'
        echo "gendaymtx $options $(basename "$input")"
    done <<'LIST'
/tmp/chicago.wea -m 1
/tmp/chicago.wea -m 2
/tmp/chicago.wea -m 4 -d
/tmp/chicago.wea -m 1 -s
/tmp/chicago.wea -m 1 -O1
/tmp/chicago.wea -m 1 -r 30
/tmp/chicago.wea -m 1 -5 .533
/tmp/chicago.wea -m 1 -A
/tmp/chicago.wea -m 1 -u
/tmp/tmy45.wea -m 1
../../../../shared/data/weather/chicago.epw -m 1
/tmp/tmy45.wea -m 1 -r 90 -g .3 .2 .1 -c .9 .9 1.2
LIST
} > fingerprints.txt
