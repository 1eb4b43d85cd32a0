#!/bin/sh
# Regenerates the compiled mesh, the frozen octrees and the Radiance reference values for the instance and
# mesh comparison in test/radiance_compat_test.cpp, from an installed Radiance (obj2mesh, oconv, rtrace on
# PATH). Run it in this directory:
#     PATH=/path/to/radiance/bin:$PATH RAYPATH=.:/path/to/radiance/lib ./make_reference.sh
# It writes vault.rtm, vault_patterned.rtm, table.oct, group.oct, tiles.oct, reference_rays.txt,
# reference_sensors.txt and reference_patterned.txt ("label r g b"),
# prints the rays whose deterministic values are more than 0.5% off Radiance's own jittered mean (points in
# penumbrae, to move), and the rtrace version to put in README.md.
set -eu
cd "$(dirname "$0")"
for tool in obj2mesh oconv rtrace; do
    command -v $tool >/dev/null || { echo "need Radiance's $tool on PATH" >&2; exit 1; }
done

# The same deterministic settings as ../radiance/make_reference.sh (see its README.md).
OPTS="-ab 0 -av 0.1 0.1 0.1 -aw 0 -dt 0 -dc 1 -dj 0 -ds 0.02 -dr 0 -dv+ -bv+ -st 1 -lr 12 -lw 1e-5 -u-"

python3 make_vault.py > vault.obj
obj2mesh -a materials.rad vault.obj vault.rtm
obj2mesh -a patterned_materials.rad vault.obj vault_patterned.rtm
oconv -f table.rad > table.oct
oconv -f group.rad > group.oct
oconv -f tiles.rad > tiles.oct

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
oconv scene.rad > "$tmp/scene.oct"
oconv patterned.rad > "$tmp/patterned.oct"

# $1 = label/ray file, $2 = extra rtrace options, $3 = output
run() { OPTS="$OPTS" ../radiance/rtrace_reference.sh "$tmp/scene.oct" "$1" "$2" "$3"; }
run rays.txt "" reference_rays.txt
run sensors.txt " -I" reference_sensors.txt
OPTS="$OPTS" ../radiance/rtrace_reference.sh "$tmp/patterned.oct" patterned_rays.txt "" reference_patterned.txt

# Penumbra check: Radiance's deterministic value against the mean of REPEATS jittered runs (-dj 1), which
# converges to the exact value where cell centres misjudge partial shadows.
REPEATS=256
for f in rays sensors; do
    extra=""; [ $f = sensors ] && extra="-I"
    grep -v '^#' $f.txt | awk -v n=$REPEATS '{for (i = 0; i < n; i++) print $2, $3, $4, $5, $6, $7}' |
        rtrace -h- $extra $OPTS -dj 1 -u+ "$tmp/scene.oct" |
        awk -v n=$REPEATS '{s += $1} NR % n == 0 {print s / n; s = 0}' > "$tmp/jittered"
    grep -v '^#' reference_$f.txt | paste -d' ' - "$tmp/jittered" |
        awk '{d = $5 - $2; s = ($2 > $5 ? $2 : $5); if (s > 0 && (d > 0.005 * s || -d > 0.005 * s)) print "penumbra? " $1, $2, $5}'
done
rtrace -version
