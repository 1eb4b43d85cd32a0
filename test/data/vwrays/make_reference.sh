#!/bin/sh
# Regenerates the *.ref files (and the small pictures and depth buffer they read) from Radiance 6.1's
# vwrays: sh make_reference.sh [radiance bin directory], run from anywhere.
set -e
cd "$(dirname "$0")"
[ -n "$1" ] && PATH="$1:$PATH"
command -v vwrays >/dev/null || { echo "make_reference.sh: Radiance's vwrays is not on PATH" >&2; exit 1; }
# 4x3 pictures, flat RGBE (all one grey): one in the standard order, one stored column by column from the
# bottom right ("+X -Y" is not it: "-X 4 +Y 3" makes scanlines of columns, right to left, bottom up).
pixels() { i=0; while [ $i -lt 12 ]; do printf '\200\200\200\201'; i=$((i+1)); done; }
{ printf '#?RADIANCE\nrpict -vtv -vp 0 0 1 -vd 0 1 0 -vh 50 -vv 40\nVIEW= -vu 0 .2 1 -vs .05\n';
  printf 'FORMAT=32-bit_rle_rgbe\n\n-Y 3 +X 4\n'; pixels; } > picture.hdr
{ printf '#?RADIANCE\nVIEW= -vtv -vp 0 0 1 -vd 1 0 0 -vh 50 -vv 40\n';
  printf 'FORMAT=32-bit_rle_rgbe\n\n-X 4 +Y 3\n'; pixels; } > rotated.hdr
# depths 1 to 12 in scan order, as native floats
printf '1\n2\n3\n4\n5\n6\n7\n8\n9\n10\n11\n12\n' | rcalc -of -e '$1=$1' > picture.zbf
grep -v '^#' cases.txt | while IFS= read -r line; do
    name=${line%%:*}
    args=${line#*: }
    sh -c "vwrays $args" > "$name.ref"
done
