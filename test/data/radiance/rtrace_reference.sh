#!/bin/sh
# Radiance's values for labelled rays, as the make_reference.sh scripts write them:
#     OPTS="rtrace options" rtrace_reference.sh OCTREE RAYS "EXTRA OPTIONS" OUTPUT
# reads RAYS ("label x y z dx dy dz" lines, '#' comments) and writes OUTPUT ("label R G B" lines under a
# comment naming the options).
set -eu
octree=$1 rays=$2 extra=$3 output=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -v '^#' "$rays" | awk '{print $1}' > "$tmp/labels"
grep -v '^#' "$rays" | awk '{print $2, $3, $4, $5, $6, $7}' |
    rtrace -h- $extra $OPTS "$octree" | awk '{print $1, $2, $3}' > "$tmp/values"
[ "$(wc -l < "$tmp/labels")" -eq "$(wc -l < "$tmp/values")" ] || { echo "rtrace failed on $rays" >&2; exit 1; }
{ echo "# label  R G B  (rtrace$extra $OPTS)"; paste -d' ' "$tmp/labels" "$tmp/values"; } > "$output"
