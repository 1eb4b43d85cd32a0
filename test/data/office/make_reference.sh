#!/bin/sh
# Regenerates the furniture, the compiled chair octree and cabinet mesh, and Radiance's converged values for
# the office comparison in test/radiance_compat_test.cpp, from an installed Radiance (obj2mesh, oconv,
# rtrace, gensky on PATH). Run it in this directory:
#     PATH=/path/to/radiance/bin:$PATH RAYPATH=.:/path/to/radiance/lib ./make_reference.sh
# It writes desk.rad, chair.rad, cabinet.obj, sensors.txt, rays.txt (make_scene.py), chair.oct, cabinet.rtm,
# reference_sensors.txt and reference_rays.txt ("label R G B sR sG sB": the mean of RUNS independent runs
# and its standard error), then prints the convergence check (a second setting against the first), the
# sensors in or near a penumbra of the sun, and the rtrace version to put in README.md.
set -eu
cd "$(dirname "$0")"
for tool in obj2mesh oconv rtrace gensky; do
    command -v $tool >/dev/null || { echo "need Radiance's $tool on PATH" >&2; exit 1; }
done

python3 make_scene.py
obj2mesh cabinet.obj cabinet.rtm
oconv -f chair.rad > chair.oct

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
oconv office.rad > "$tmp/office.oct"

# Path tracing without the irradiance cache (-aa 0), six bounces, Russian roulette below -lw, and without
# super-sampling (-as 0): Radiance adds -as samples where its first ones differ most and averages them in,
# which pulls the bright outliers (rays that find the sun patch) toward the mean and biases the value low,
# here by 2-5% on surfaces lit mostly by interreflection (README.md).
OPTS="-ab 6 -aa 0 -ad 4096 -as 0 -lw 1e-5"
RUNS=64
# The second setting: a quarter of the samples per first bounce, ten times lower roulette threshold.
CHECK_OPTS="-ab 6 -aa 0 -ad 1024 -as 0 -lw 1e-6"
CHECK_RUNS=128

# means RAYS "OPTIONS" RUNS > "label R G B sR sG sB": every ray RUNS times in one rtrace -u+ (-n 2), averaged.
means() {
    grep -v '^#' "$1" | awk '{print $1}' > "$tmp/labels"
    grep -v '^#' "$1" | awk -v n="$3" '{for (i = 0; i < n; i++) print $2, $3, $4, $5, $6, $7}' |
        rtrace -h- -n 2 -u+ $2 "$tmp/office.oct" |
        awk -v n="$3" '{for (c = 1; c <= 3; c++) {s[c] += $c; q[c] += $c * $c}}
            NR % n == 0 {for (c = 1; c <= 3; c++) {m[c] = s[c] / n; e[c] = sqrt((q[c] / n - m[c] * m[c]) / (n - 1));
                s[c] = q[c] = 0}; printf "%.6g %.6g %.6g %.3g %.3g %.3g\n", m[1], m[2], m[3], e[1], e[2], e[3]}' |
        paste -d' ' "$tmp/labels" -
}

{ echo "# label  R G B  standard errors (mean of $RUNS runs of rtrace -I $OPTS -u+)"; means sensors.txt "-I $OPTS" $RUNS; } > reference_sensors.txt
{ echo "# label  R G B  standard errors (mean of $RUNS runs of rtrace $OPTS -u+)"; means rays.txt "$OPTS" $RUNS; } > reference_rays.txt

# Convergence: the second setting's means against the first's, in luminance (.265 R + .670 G + .065 B).
means sensors.txt "-I $CHECK_OPTS" $CHECK_RUNS > "$tmp/check"
grep -v '^#' reference_sensors.txt | paste -d' ' - "$tmp/check" |
    awk '{a = .265*$2 + .67*$3 + .065*$4; b = .265*$9 + .67*$10 + .065*$11; ea = .265*$5 + .67*$6 + .065*$7;
          d = (b - a) / a; s += d * d; if (d * d > m * m) m = d; if (ea / a > w) w = ea / a; n++}
          END {printf "convergence: %s against %s: RMS %.2f%%, largest %+.2f%%; standard error up to %.2f%%\n",
               "'"$CHECK_OPTS"'", "'"$OPTS"'", 100 * sqrt(s / n), 100 * m, 100 * w}'

# Penumbrae: direct light with the sun seen as its centre (-dj 0) against the mean over its disc (-dj 1).
grep -v '^#' sensors.txt | awk '{print $2, $3, $4, $5, $6, $7}' | rtrace -h- -I -ab 0 -dj 0 "$tmp/office.oct" > "$tmp/centre"
means sensors.txt "-I -ab 0 -dj 1" 256 | paste -d' ' "$tmp/centre" - |
    awk '{a = $1 + $2 + $3; b = $5 + $6 + $7; if ((a - b) * (a - b) > 1e-6 * (a + b) * (a + b)) print "penumbra? " $4, a, b}'
rtrace -version
