#!/bin/sh
# Chooses rays.txt for the text comparison (test/data/text): on a grid of points over each panel, keeps the
# points where Radiance sees the same value at the point and at four neighbours 4 mm away, so that no ray
# lands on (or within rounding of) a glyph's edge; then up to eight points per panel and value, so that
# letters and background are both tested. Needs Radiance's oconv and rtrace (as make_reference.sh).
set -eu
cd "$(dirname "$0")"
export RAYPATH=".:../../../lib/pattern/fonts:${RAYPATH:-/usr/local/lib/ray}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
oconv text.rad > "$tmp/text.oct"
# label x y: panel p's grid point (i, j); each followed by its four neighbours
awk 'BEGIN { split("bright_inline color_file color_squeezed mix_materials mix_void tiny_font", name, " ");
             for (p = 1; p <= 6; p++) for (i = 0; i < 23; i++) for (j = 0; j < 23; j++) {
                 x = p - 1 + 0.0217 + i * 0.0431; y = 0.0173 + j * 0.0427
                 print name[p], x, y; print name[p], x + .004, y; print name[p], x - .004, y
                 print name[p], x, y + .004; print name[p], x, y - .004 } }' > "$tmp/points"
awk '{ print $2, $3, 2, 0, 0, -1 }' "$tmp/points" |
    rtrace -h- -ab 0 -dj 0 -u- -ov "$tmp/text.oct" | paste -d' ' "$tmp/points" - > "$tmp/values"
awk 'function key(i) { return sprintf("%.4g %.4g %.4g", v[i, 1], v[i, 2], v[i, 3]) }
     { k = (NR - 1) % 5; label[k] = $1; x[k] = $2; y[k] = $3; v[k, 1] = $4; v[k, 2] = $5; v[k, 3] = $6 }
     k == 4 { for (i = 1; i < 5; i++) if (key(i) != key(0)) next
              if (++count[label[0] " " key(0)] > 8) next
              printf "%s_%d %.4f %.4f 2 0 0 -1\n", label[0], ++n[label[0]], x[0], y[0] }' "$tmp/values" > "$tmp/rays"
{ echo "# label x y z dx dy dz (view rays for test/data/text, chosen by make_rays.sh)"; cat "$tmp/rays"; } > rays.txt
wc -l < "$tmp/rays"
