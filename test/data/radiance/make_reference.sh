#!/bin/sh
# Regenerates the Radiance reference values for test/radiance_compat_test.cpp from an installed Radiance
# (oconv and rtrace on PATH, RAYPATH with rayinit.cal). Run it in this directory:
#     PATH=/path/to/radiance/bin:$PATH RAYPATH=.:/path/to/radiance/lib ./make_reference.sh
# It writes reference_rays.txt, reference_sensors.txt, reference_irradiance_at_hit.txt (-i) and
# reference_glossy.txt ("label r g b", the
# glossy file adding the standard errors of the means) and prints the rtrace version to put in README.md.
set -eu
cd "$(dirname "$0")"
command -v rtrace >/dev/null && command -v oconv >/dev/null || { echo "need Radiance's rtrace and oconv on PATH" >&2; exit 1; }

# Deterministic settings, chosen so that Radiance's answer is close to the exact one (see README.md):
# every source sample tested (-dt 0), no jitter (-dj 0), fine source subdivision (-ds 0.02), no virtual
# sources through mirrors (-dr 0, Brume has none yet), no sampled specular rays (-st 1: every rough
# specular lobe is its direct part plus -av), a fixed reflection limit, reproducible random numbers.
OPTS="-ab 0 -av 0.1 0.1 0.1 -aw 0 -dt 0 -dc 1 -dj 0 -ds 0.02 -dr 0 -dv+ -bv+ -st 1 -lr 12 -lw 1e-5 -u-"
# Sampled specular reflection of the rough specular surfaces above -st 0.15: a Monte Carlo mean of
# REPEATS rays each (reproducible with -u- and the same build), for rays whose labels are listed here.
GLOSSY_OPTS="-ab 0 -av 0.1 0.1 0.1 -aw 0 -dt 0 -dc 1 -dj 0 -ds 0.02 -dr 0 -dv+ -bv+ -st 0.15 -ss 1 -lr 12 -lw 1e-5 -u-"
GLOSSY="column_0 column_1 column_near_glow metal_sheet_1 metal_sheet_window satin_0 satin_1 plate_1 plate_bulb_through_shelf"
REPEATS=4000
# the ray that shows a Brume bug (README.md) gets more, for a sharper reference
BUG_REPEATS=40000

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
oconv materials.rad > "$tmp/materials.oct"

# $1 = label/ray file, $2 = extra rtrace options, $3 = output
run() { OPTS="$OPTS" ./rtrace_reference.sh "$tmp/materials.oct" "$1" "$2" "$3"; }
run rays.txt "" reference_rays.txt
run sensors.txt " -I" reference_sensors.txt
run rays.txt " -i" reference_irradiance_at_hit.txt

echo "# label  mean R G B  standard error R G B  (rtrace $GLOSSY_OPTS, $REPEATS rays each, $BUG_REPEATS for metal_sheet_window)" > reference_glossy.txt
for label in $GLOSSY; do
    ray=$(awk -v l="$label" '$1 == l {print $2, $3, $4, $5, $6, $7}' rays.txt)
    [ -n "$ray" ] || { echo "no ray $label" >&2; exit 1; }
    n=$REPEATS
    [ "$label" = metal_sheet_window ] && n=$BUG_REPEATS
    awk -v r="$ray" -v n=$n 'BEGIN {for (i = 0; i < n; i++) print r}' |
        rtrace -h- $GLOSSY_OPTS "$tmp/materials.oct" |
        awk -v l="$label" '{for (c = 1; c <= 3; c++) {s[c] += $c; q[c] += $c * $c}}
            END {printf "%s", l; for (c = 1; c <= 3; c++) printf " %.7g", s[c] / NR;
                 for (c = 1; c <= 3; c++) {m = s[c] / NR; v = q[c] / NR - m * m; printf " %.3g", sqrt((v > 0 ? v : 0) / NR)}
                 print ""}' >> reference_glossy.txt
done
rtrace -version
