#!/bin/bash
# Brume's sky .cal files (lib/cal/library) against Radiance's, evaluated by Radiance's own rcalc.
#
# For each sky below, Radiance's gensky or gendaylit writes the sky; its skyfunc arguments are handed to
# Brume's .cal file and to Radiance's, both are evaluated at the same directions (a 5° grid over the whole
# sphere, directions around the horizon where the models switch, and directions at and around the sun),
# and the values must agree to a relative 1e-6 of the larger. rcalc prints 9 significant digits; so far
# every value has come out the same to all 9. Brume's gensky and
# gendaylit write the same text (test/sky_cli_test.cpp), so this also covers Brume's skies with
# Radiance's files and the reverse.
#
# Needs Radiance: gensky, gendaylit, rcalc, cnt on PATH, rayinit.cal and Radiance's sky .cal files in
# RADIANCE_LIB. Not part of `make test`. Its output is committed as check_cal.out beside it:
#   RADIANCE_LIB=/tmp/radiance/lib PATH=/tmp/radiance/bin:$PATH test/data/sky/check_cal.sh > test/data/sky/check_cal.out
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
brume_lib=$here/../../../lib/cal/library
radiance_lib=${RADIANCE_LIB:?set RADIANCE_LIB to the folder with Radiance\'s rayinit.cal and skybright.cal}
tolerance=1e-6
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

skies=(
    "gensky 3 21 12 -a 45.5 -o 0.5 -m 0"
    "gensky 3 21 12 -a 45.5 -o 0.5 -m 0 -s -t 5"
    "gensky 6 21 12 -c"
    "gensky 6 21 12 -u -g 0.4"
    "gensky 12 21 9 -a 51.5 -o 0 -m 0 +i"
    "gensky -ang 10 -60 -i"
    "gensky -ang 86 30 +s"
    "gensky -ang 2 100 +s"
    "gendaylit -ang 60 0 -P 6.3 0.12"
    "gendaylit -ang 60 0 -P 1 0.08"
    "gendaylit -ang 20 90 -W 300 200"
    "gendaylit 3 21 12 -a 45.5 -o 0.5 -m 0 -W 600 150"
    "gendaylit -ang 5 -100 -W 100 50"
    "gendaylit -ang 45 0 -P 2 0.2 -O 1"
    "gendaylit -ang 60 0 -W 840 135 -C"
    "gendaylit -ang 40 0 -P 1 0.2 -C -CIE"
)

# Unit directions: the grid, the horizon band, then directions at and within 1° of the sun (sx sy sz).
directions() {
    cnt 73 37 | rcalc -e 'az=$1*5*PI/180;alt=($2*5-90)*PI/180' \
        -e '$1=cos(alt)*sin(az);$2=cos(alt)*cos(az);$3=sin(alt)'
    cnt 12 11 | rcalc -e 'az=$1*30*PI/180;alt=select($2+1,-1,-.6,-.58,-.57,-.2,0,.2,.57,.58,.6,1)*PI/180' \
        -e '$1=cos(alt)*sin(az);$2=cos(alt)*cos(az);$3=sin(alt)'
    cnt 9 4 | rcalc -e "sx=$1;sy=$2;sz=$3" -e 'off=select($2+1,0,1e-4,1e-2,1)*PI/180;az=$1*45*PI/180' \
        -e 'ex=-sy;ey=sx;n=sqrt(ex*ex+ey*ey)+1e-20;ux=ex/n;uy=ey/n' \
        -e 'vx=-sz*uy;vy=sz*ux;vz=sx*uy-sy*ux' \
        -e 'wx=cos(az)*ux+sin(az)*vx;wy=cos(az)*uy+sin(az)*vy;wz=sin(az)*vz' \
        -e 'dx=cos(off)*sx+sin(off)*wx;dy=cos(off)*sy+sin(off)*wy;dz=cos(off)*sz+sin(off)*wz' \
        -e 'l=sqrt(dx*dx+dy*dy+dz*dz);$1=dx/l;$2=dy/l;$3=dz/l'
}

# Values of the sky functions of one .cal file at the directions on stdin.
evaluate() {  # cal-file arg-definition function...
    local cal=$1 args=$2
    shift 2
    local i=1 outputs=""
    for f in "$@"; do outputs="$outputs\$$i=$f;" i=$((i + 1)); done
    rcalc -f "$radiance_lib/rayinit.cal" -f "$cal" -e "$args" -e 'Dx=$1;Dy=$2;Dz=$3' -e "$outputs"
}

status=0
echo "# Brume's sky .cal files against Radiance's, by Radiance's rcalc; tolerance: relative $tolerance"
echo "# sky | .cal | values compared (their range) | largest relative difference | result"
for sky in "${skies[@]}"; do
    $sky > "$work/sky.rad" 2> /dev/null
    header=$(grep -A1 'skyfunc$' "$work/sky.rad" | tail -1)  # "2 skybr skybright.cal" or colorfunc's 4
    read -r -a words <<< "$header"
    cal=${words[${#words[@]} - 1]}
    functions=("${words[@]:1:${#words[@]}-2}")
    read -r -a values <<< "$(tail -1 "$work/sky.rad")"
    argdef="arg(n)=select(n$(printf ',%s' "${values[@]:1}"))"
    if [ "$cal" = skybright.cal ] && [ "${values[0]}" = 3 ]; then
        sun="0 0 1"  # overcast and uniform skies have no sun
    else
        n=${#values[@]}
        [ "$cal" = perezlum_c.cal ] && n=11
        sun="${values[n - 3]} ${values[n - 2]} ${values[n - 1]}"
    fi
    set -- $sun
    directions "$1" "$2" "$3" > "$work/dirs"
    evaluate "$brume_lib/$cal" "$argdef" "${functions[@]}" < "$work/dirs" > "$work/brume"
    evaluate "$radiance_lib/$cal" "$argdef" "${functions[@]}" < "$work/dirs" > "$work/radiance"
    result=$(paste "$work/brume" "$work/radiance" | awk -v tol="$tolerance" -v k="${#functions[@]}" '
        NR == 1 { low = high = $(1 + k) }
        { for (i = 1; i <= k; ++i) {
              a = $i; b = $(i + k); m = (a < 0 ? -a : a); mb = (b < 0 ? -b : b); if (mb > m) m = mb
              d = a - b; if (d < 0) d = -d
              r = m > 0 ? d / m : 0; if (r > worst) worst = r; ++count
              if (b < low) low = b; if (b > high) high = b
          } }
        END { printf "%d (%.4g to %.4g) | %.2e | %s", count, low, high, worst, (worst <= tol && count > 0 ? "ok" : "FAIL") }')
    echo "$sky | $cal | $result"
    case $result in *FAIL) status=1 ;; esac
done
exit $status
