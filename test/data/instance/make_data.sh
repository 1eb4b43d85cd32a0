#!/bin/sh
# Remakes lamp.oct and the lamp moved by xform, for test/instance_test.cpp, from an installed Radiance (oconv
# and xform on PATH). Run it in this directory. Each lamp_N.rad is `xform <transform N> lamp.rad`; the test
# places lamp.oct with the same transforms.
set -eu
cd "$(dirname "$0")"
oconv -f lamp.rad > lamp.oct
n=0
while read -r transform; do
    n=$((n + 1))
    { echo "# xform $transform lamp.rad"; xform $transform lamp.rad | grep -v '^#'; } > lamp_$n.rad
done < transforms.txt
