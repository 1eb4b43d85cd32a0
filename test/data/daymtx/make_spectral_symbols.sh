#!/bin/bash
# Writes spectral9.mtx and spectral6.mtx (each band's unit colour, one a row: 9 bands over 780-380 nm and 6 over
# 720-400 nm) and spectral_symbols.txt: what Radiance's rmtxop -c makes of them for each symbolic component,
# "bands symbol weight..." a line, the band of 780 nm (or 720) first. test/daymtx_cli_test.cpp compares Brume's
# rmtxop with them. Needs Radiance's programs on PATH (6.1a, commit bcffc2b52d of LBNL-ETA/Radiance):
#   PATH=/tmp/radiance/inst/bin:$PATH test/data/daymtx/make_spectral_symbols.sh
set -euo pipefail
cd "$(dirname "$0")"
for spec in "9 780 588 480 380" "6 720 588 480 400"; do
    set -- $spec
    n=$1
    {
        printf '#?RADIANCE\nNROWS=%d\nNCOLS=1\nNCOMP=%d\nWAVELENGTH_SPLITS= %s %s %s %s\nFORMAT=ascii\n\n' $n $n $2 $3 $4 $5
        for i in $(seq 0 $((n - 1))); do
            row=()
            for j in $(seq 0 $((n - 1))); do row+=($([ $i = $j ] && echo 1 || echo 0)); done
            echo "${row[*]}"
        done
    } > spectral$n.mtx
done
{
    echo "# bands symbol weights (Radiance 6.1's rmtxop -fa -c SYMBOL spectralN.mtx, a row each band's unit colour)"
    for n in 9 6; do
        for c in R G B X Y Z S M A y m; do
            echo "$n $c $(rmtxop -fa -c $c spectral$n.mtx | sed '1,/^$/d' | tr -s ' \t\n' ' ')"
        done
    done
} > spectral_symbols.txt
