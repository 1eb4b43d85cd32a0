#!/bin/sh
# Regenerates the mkillum room's inputs and Radiance's reference values for it (README.md) from an
# installed Radiance (gensky, oconv, mkillum, rtrace on PATH; RAYPATH with rayinit.cal, skybright.cal
# and illum.cal). Run it in this directory:
#     PATH=/path/to/radiance/bin:$PATH RAYPATH=.:/path/to/radiance/lib ./make_reference.sh
# It writes sky.rad (gensky's sky and sun, and the glows that show them), sensors.txt, rays.txt and
# rays_glow.txt (make_scene.py), window_mkillum.rad and illum.dat (mkillum's output for window_glass.rad),
# then, for each of the three windows (mkillum, twice, glass):
#     reference_sensors_W.txt        rtrace -I, -ab 0, deterministic            "label R G B"
#     reference_rays_W.txt           rtrace, -ab 0, deterministic               "label R G B"
#     reference_rays_glow_W.txt      rtrace, -ab 0, the glow.rad variant        "label R G B"
#     reference_irradiance_at_hit_W.txt  rtrace -i, -ab 0                       "label R G B"
#     reference_sensors_ab1_W.txt, reference_sensors_ab2_W.txt  rtrace -I, -ab 1 and 2, path traced:
#                                    the mean of RUNS runs and its standard error  "label R G B sR sG sB"
# and prints the sensors near a penumbra of the sun and the rtrace version to put in README.md.
set -eu
cd "$(dirname "$0")"
for tool in gensky oconv mkillum rtrace; do
    command -v $tool >/dev/null || { echo "need Radiance's $tool on PATH" >&2; exit 1; }
done

# ---- the sky: gensky's output, committed so that no gensky is needed to read the scene ----
{
    gensky 3 21 12 -a 45.5 -o 0.5 -m 0 +s
    cat <<'SKY'

# The glows that show gensky's skyfunc (make_reference.sh): radius 0, so not light sources; rtrace sees
# them through view and ambient rays, mkillum through its sample rays.
skyfunc glow sky_glow
0
0
4 .9 .9 1.15 0

sky_glow source sky
0
0
4 0 0 1 180

skyfunc glow ground_glow
0
0
4 1.4 .9 .6 0

ground_glow source ground
0
0
4 0 0 -1 180
SKY
} > sky.rad

python3 make_scene.py

tmp=$(mktemp -d)
trap 'rm -rf "$tmp" mkillum_input.oct' EXIT

# ---- mkillum: the glass window of the room, sampled through the glass into the sky and the ground ----
# Its defaults (c=n d=48 s=32 l-, -dj .5 -dr 3; -ab 2 replaced by -ab 1) with -ad 1024; -u- makes the
# run repeatable. The octree is named relatively so that mkillum's header line does not name $tmp.
# mkillum numbers its data file illum.dat, illum1.dat, ... after the ones that exist, so they go first.
rm -f illum*.dat
oconv sky.rad room.rad window_glass.rad > mkillum_input.oct
mkillum -ab 1 -ad 1024 -u- mkillum_input.oct < window_glass.rad > window_mkillum.rad
[ -f illum.dat ] || { echo "mkillum wrote no illum.dat" >&2; exit 1; }

for w in mkillum twice glass; do
    oconv sky.rad room.rad window_$w.rad > "$tmp/$w.oct"
    oconv sky.rad room.rad window_$w.rad glow.rad > "$tmp/${w}_glow.oct"
done

# Deterministic settings (as ../radiance/make_reference.sh, README.md): every source sample tested
# (-dt 0 -dc 1), no jitter (-dj 0), flat sources in 64 cells (-ds 0.02), no virtual sources (-dr 0),
# no sampled specular rays (-st 1), no ambient value (-av 0 0 0), a hard reflection limit (-lr 12).
OPTS="-ab 0 -av 0 0 0 -aw 0 -dt 0 -dc 1 -dj 0 -ds 0.02 -dr 0 -dv+ -bv+ -st 1 -lr 12 -lw 1e-5 -u-"
run() { OPTS="$OPTS" ../radiance/rtrace_reference.sh "$@"; }
for w in mkillum twice glass; do
    run "$tmp/$w.oct" sensors.txt " -I" reference_sensors_$w.txt
    run "$tmp/$w.oct" rays.txt "" reference_rays_$w.txt
    run "$tmp/${w}_glow.oct" rays_glow.txt "" reference_rays_glow_$w.txt
    run "$tmp/$w.oct" rays.txt " -i" reference_irradiance_at_hit_$w.txt
done

# Interreflection: path tracing without the irradiance cache (-aa 0) or super-sampling (-as 0, which
# biases, ../office/README.md), Russian roulette below -lw (the default -lr -10). The direct part as
# above except -dj 1: rays of low weight (past the first bounce) see the window as one cell of
# Radiance's source subdivision, which -dj 0 would sample only at its centre; jittered over the cell
# the estimate is unbiased.
AB_OPTS="-aa 0 -ad 4096 -as 0 -lw 1e-5 -av 0 0 0 -aw 0 -dt 0 -dc 1 -dj 1 -ds 0.02 -dr 0 -dv+ -bv+ -st 1"
RUNS=64

# means OCTREE RAYS "OPTIONS" RUNS > "label R G B sR sG sB": every ray RUNS times in one rtrace -u+ (-n 2).
means() {
    grep -v '^#' "$2" | awk '{print $1}' > "$tmp/labels"
    grep -v '^#' "$2" | awk -v n="$4" '{for (i = 0; i < n; i++) print $2, $3, $4, $5, $6, $7}' |
        rtrace -h- -n 2 -u+ $3 "$1" |
        awk -v n="$4" '{for (c = 1; c <= 3; c++) {s[c] += $c; q[c] += $c * $c}}
            NR % n == 0 {for (c = 1; c <= 3; c++) {m[c] = s[c] / n; v = (q[c] / n - m[c] * m[c]) / (n - 1);
                e[c] = sqrt(v > 0 ? v : 0); s[c] = q[c] = 0}
                printf "%.6g %.6g %.6g %.3g %.3g %.3g\n", m[1], m[2], m[3], e[1], e[2], e[3]}' |
        paste -d' ' "$tmp/labels" -
}
for w in mkillum twice glass; do
    for ab in 1 2; do
        { echo "# label  R G B  standard errors (mean of $RUNS runs of rtrace -I -ab $ab $AB_OPTS -u+)"
          means "$tmp/$w.oct" sensors.txt "-I -ab $ab $AB_OPTS" $RUNS; } > reference_sensors_ab${ab}_$w.txt
    done
done

# Penumbrae: direct light with the sun seen as its centre (-dj 0) against the mean over its disc (-dj 1),
# in the plain glass room (where the sun is the only source at -ab 0).
grep -v '^#' sensors.txt | awk '{print $2, $3, $4, $5, $6, $7}' |
    rtrace -h- -I $OPTS "$tmp/glass.oct" > "$tmp/centre"
means "$tmp/glass.oct" sensors.txt "-I $(echo "$OPTS" | sed 's/-dj 0/-dj 1/; s/ -u-//')" 64 |
    paste -d' ' "$tmp/centre" - |
    awk '{a = $1 + $2 + $3; b = $5 + $6 + $7; if ((a - b) * (a - b) > 1e-6 * (a + b) * (a + b)) print "penumbra? " $4, a, b}'
rtrace -version
