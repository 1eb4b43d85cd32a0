#!/bin/sh
# Regenerates the Radiance 6.1 values for the BSDF comparison (test/radiance_compat_test.cpp) from an
# installed Radiance (oconv, rtrace on PATH). Run it here:
#     PATH=/path/to/radiance/bin:$PATH RAYPATH=/path/to/radiance/lib ./make_reference.sh
# Radiance's BSDF material is noisy (it jitters view directions over a Klems patch, samples one ray per
# component, and -ab 1 here is plain Monte Carlo, -aa 0): every ray and sensor is traced REPEAT times in
# one run (each repeat draws other random numbers) and the mean and its standard error are written.
set -eu
cd "$(dirname "$0")"
command -v rtrace >/dev/null && command -v oconv >/dev/null || { echo "need Radiance's rtrace and oconv on PATH" >&2; exit 1; }
export RAYPATH=".:${RAYPATH:-/usr/local/lib/ray}"
COMMON="-av 0 0 0 -aw 0 -aa 0 -dt 0 -dc 1 -dj 0 -ds 0.02 -dr 0 -lr 8 -lw 1e-6"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
oconv scene.rad > "$tmp/scene.oct"

# mean REPEAT file options output: "label R G B sR sG sB" per line of `file`
mean() {
    repeat=$1 file=$2 out=$3
    shift 3
    grep -v '^#' "$file" | awk -v n="$repeat" '{ for (k = 0; k < n; k++) print $2, $3, $4, $5, $6, $7 }' |
        rtrace -h- "$@" "$tmp/scene.oct" > "$tmp/values"
    grep -v '^#' "$file" | awk '{ print $1 }' > "$tmp/labels"
    awk -v n="$repeat" 'NR == FNR { label[FNR] = $1; next }
        { i = int((FNR - 1) / n) + 1; for (c = 1; c <= 3; c++) { s[i, c] += $c; s2[i, c] += $c * $c } }
        END { for (i = 1; i in label; i++) {
                  printf "%s", label[i]
                  for (c = 1; c <= 3; c++) printf " %.6g", s[i, c] / n
                  for (c = 1; c <= 3; c++) { m = s[i, c] / n; v = s2[i, c] / n - m * m
                                             printf " %.3g", sqrt(v > 0 ? v / n : 0) }
                  printf "\n" } }' "$tmp/labels" "$tmp/values" > "$tmp/out"
    { echo "# label  R G B  standard errors of R G B  (mean of $repeat: rtrace $*)"; cat "$tmp/out"; } > "$out"
}

mean 64 rays.txt reference_rays.txt -ab 0 $COMMON
mean 16 sensors.txt reference_ab0.txt -I -ab 0 $COMMON
mean 16 sensors.txt reference_ab1.txt -I -ab 1 -ad 4096 -as 0 $COMMON
rtrace -version
