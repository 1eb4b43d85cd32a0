#!/bin/sh
# Regenerates the Radiance 6.1 reference outputs of test/data/spectral (see README.md) from a Radiance
# on PATH (oconv, rtrace, rpict, getinfo; RAYPATH must let rtrace find rayinit.cal). Run it anywhere:
#     PATH=/path/to/radiance/bin:$PATH RAYPATH=.:/path/to/radiance/lib test/data/spectral/make_reference.sh
# The only lines removed from Radiance's output are the date stamps of -h+ headers (CAPDATE=, GMT=).
# illumA.dat is committed; gen_illumA.py made it (python3, not needed here).
set -eu
cd "$(dirname "$0")"
for p in oconv rtrace rpict getinfo; do
    command -v $p >/dev/null || { echo "need Radiance's $p on PATH" >&2; exit 1; }
done
# Deterministic options: no ambient (-ab 0, -av 0), every source tested (-dt 0 -dc 1), the sun seen as one
# direction (-dj 0 -ds 0), no secondary sources or pretests, and a fixed random sequence (-u-; rtrace's
# default is -u+, seeded with the time) although only the smooth specfunc of step 6 draws any number.
OPTS="-ab 0 -av 0 0 0 -dt 0 -dc 1 -dj 0 -ds 0 -dr 0 -dp 0 -lr 8 -lw 0 -u-"
PC="0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0.329"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
nodate() { sed -e '1,/^$/{/^CAPDATE=/d;/^GMT=/d;}'; }

# 1. spic.hsr: the 2x2 hyperspectral picture (6 bands, 400-700 nm) read by specpict. rtrace writes the
#    pixels (-fac -co, -x 2 -y 2 puts the resolution line); the header is written here without dates.
oconv mkspic.rad > "$tmp/mkspic.oct"
{
    printf '#?RADIANCE\n'
    printf 'rtrace -ab 0 -av 0 0 0 -cs 6 -cw 400 700 -co -fac -x 2 -y 2 mkspic.oct < mkspic_rays.txt\n'
    printf 'NCOMP=6\nWAVELENGTH_SPLITS= 700 588 480 400\nFORMAT=Radiance_spectra\n\n'
    rtrace -h- -ab 0 -av 0 0 0 -cs 6 -cw 400 700 -co -fac -x 2 -y 2 "$tmp/mkspic.oct" < mkspic_rays.txt
} > spic.hsr
rtrace -h+ -ab 0 -av 0 0 0 -cs 6 -cw 400 700 -co "$tmp/mkspic.oct" < mkspic_rays.txt | nodate > spic_values.txt

# 2. The scene and its outputs.
oconv spectral.rad > "$tmp/spectral.oct"
oct="$tmp/spectral.oct"
run() {        # run OUTPUT INPUT rtrace-options...
    out=$1 in=$2; shift 2
    rtrace -h+ "$@" "$oct" < "$in" | nodate > "$out"
    echo "$out: rtrace -h+ $* spectral.oct < $in" >> "$tmp/commands"
}
: > "$tmp/commands"
run rays_cs24_co.txt   rays.txt $OPTS -cs 24 -co
run rays_cs24_pRGB.txt rays.txt $OPTS -cs 24 -pRGB
run rays_cs24_pXYZ.txt rays.txt $OPTS -cs 24 -pXYZ
run rays_cs24_pY.txt   rays.txt $OPTS -cs 24 -pY
run rays_cs24_pS.txt   rays.txt $OPTS -cs 24 -pS
run rays_cs24_pM.txt   rays.txt $OPTS -cs 24 -pM
run rays_cs24_pA.txt   rays.txt $OPTS -cs 24 -pA
run rays_cs24_pc.txt   rays.txt $OPTS -cs 24 -pc $PC
run rays_cs3.txt       rays.txt $OPTS -cs 3
run rays_cs3_pY.txt    rays.txt $OPTS -cs 3 -pY
run rays_cs12_cw400-700_co.txt rays.txt $OPTS -cs 12 -cw 400 700 -co
run rays_cs12_cw400-700.txt    rays.txt $OPTS -cs 12 -cw 400 700
run irr_cs24_co.txt    irr.txt -I $OPTS -cs 24 -co
run irr_cs24_pY.txt    irr.txt -I $OPTS -cs 24 -pY
run irr_cs24_pXYZ.txt  irr.txt -I $OPTS -cs 24 -pXYZ
run irr_cs24_pRGB.txt  irr.txt -I $OPTS -cs 24 -pRGB
run irr_cs3.txt        irr.txt -I $OPTS -cs 3

# Exactness: the same numbers with a time-seeded random sequence (-u+ after OPTS) and with the rays in
# reverse order.
for cs in "-cs 24 -co" "-cs 3" "-cs 12 -cw 400 700 -co"; do
    rtrace -h- $OPTS $cs "$oct" < rays.txt > "$tmp/a"
    sed -n '1!G;h;$p' rays.txt | rtrace -h- $OPTS -u+ $cs "$oct" | sed -n '1!G;h;$p' > "$tmp/b"
    cmp -s "$tmp/a" "$tmp/b" || { echo "rtrace $cs outputs are not deterministic" >&2; exit 1; }
done

# 3. headers.txt: every -h+ header verbatim (dates removed).
: > headers.txt
for f in rays_*.txt irr_*.txt; do
    { echo "==> $f <=="; sed -n '1,/^$/p' "$f"; } >> headers.txt
done

# 4. options.txt: what rtrace and rpict say to sampling options at and past the limits.
: > options.txt
probe() {      # probe PROGRAM options... (rtrace: first 3 rays; rpict: header only)
    prog=$1; shift
    {
        echo "==> $prog $* <=="
        if [ "$prog" = rtrace ]; then
            sed -n 1,3p rays.txt | rtrace -h+ $OPTS "$@" "$oct" > "$tmp/o" 2> "$tmp/e" && rc=0 || rc=$?
            nodate < "$tmp/o"
        else
            rpict -vf view.vf -x 32 -y 24 -ps 1 $OPTS "$@" "$oct" > "$tmp/o" 2> "$tmp/e" && rc=0 || rc=$?
            [ -s "$tmp/o" ] && sed -n '1,/^$/p' "$tmp/o" | nodate
        fi
        sed 's/(PID [0-9]*)/(PID ...)/; s/after [0-9.]*u [0-9.]*s [0-9.]*r/after ...u ...s ...r/; s/ on [^ ]* (PID/ on ... (PID/' "$tmp/e" | sed 's/^/stderr: /'
        echo "exit status: $rc"
        echo
    } >> options.txt
}
probe rtrace -cs 30 -co
probe rtrace -cs 30
probe rtrace -cs 2
probe rtrace -cs 3 -co
probe rtrace -cw 500 520
probe rtrace -cs 24 -cw 500 520 -co
probe rtrace -cw 400 500
probe rtrace -cs 24 -cw 400 500
probe rtrace -cs 24 -cw 400 500 -co
probe rtrace -cs 24 -cw 500 780
probe rtrace -cs 24 -cw 500 780 -co
probe rtrace -cs 24 -cw 700 400 -co
probe rtrace -cs 24 -pY -co
probe rtrace -cs 24 -pXYZ -co
probe rtrace -cs 24 -co -pY
probe rtrace -cs 24 -co-
probe rpict -cs 24
probe rpict -cs 24 -co
probe rpict -cs 24 -pY
probe rpict -cs 24 -pXYZ
probe rpict -cs 24 -pc $PC
probe rpict -cs 30
probe rpict -cs 2
probe rpict -cs 24 -cw 400 500
probe rpict -cs 24 -cw 500 780
probe rpict -cs 12 -cw 400 700

# 5. Tiny pictures (32x24) of the scene with rpict; view.vf looks at the panels and the glow.
for o in "cs24:-cs 24" "cs3:-cs 3" "cs24_pXYZ:-cs 24 -pXYZ"; do
    name=${o%%:*} args=${o#*:}
    rpict -vf view.vf -x 32 -y 24 -ps 1 $OPTS $args "$oct" | nodate > "rpict_$name.hdr"
    echo "rpict_$name.hdr: rpict -vf view.vf -x 32 -y 24 -ps 1 $OPTS $args spectral.oct" >> "$tmp/commands"
done

# 6. The smooth specfunc (not exact): the same ray 20 times in one run; each draws its own jittered
#    wavelengths (-u-: the sequence, and so this file, is the same every time).
oconv spectral.rad smooth.rad > "$tmp/smooth.oct"
{
    echo "# 20 x ray 5.5 0.5 1 0 0 -1 (P5, smooth specfunc bump()) through one"
    echo "# rtrace -h- $OPTS -cs 24 -pY"
    for i in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20; do echo "5.5 0.5 1 0 0 -1"; done |
        rtrace -h- $OPTS -cs 24 -pY "$tmp/smooth.oct"
} > smooth_specfunc_runs.txt

cp "$tmp/commands" commands.txt
rtrace -version
