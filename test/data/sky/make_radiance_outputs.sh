#!/bin/bash
# Writes Radiance's output for each line of commands.txt into radiance/NN.txt (NN: the line number),
# the references test/sky_cli_test.cpp compares Brume's gensky and gendaylit with. Needs Radiance's
# gensky and gendaylit on PATH (they were 6.1a, commit bcffc2b52d of LBNL-ETA/Radiance):
#   PATH=/tmp/radiance/bin:$PATH test/data/sky/make_radiance_outputs.sh
set -euo pipefail
cd "$(dirname "$0")"
n=0
while read -r line; do
    n=$((n + 1))
    $line > "radiance/$(printf %02d $n).txt" 2> /dev/null
done < commands.txt
