#!/usr/bin/env bash
# Brume demo (make demo): illuminance on the work plane of the example office, computed by rtrace, and a
# picture of the office rendered by rpict; an exit sign seen through a fire's soot; a room lit by a fire;
# visibility maps of two signs in the fire hall of the shared FDS case (fds2vdb, vismap).
# Usage: bash examples/demo.sh BIN_DIR   (BIN_DIR holds Brume's programs; make demo passes build/bin)
# The pictures (office.hdr, corridor.hdr, corridor_ab2.hdr, flame.hdr), the flame's grids, vismap's CSVs, maps
# (hall_*.hdr) and plots (with matplotlib) go to BIN_DIR/../demo/.
set -euo pipefail
bin=${1:-build/bin}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rtrace=$bin/rtrace
[ -x "$rtrace" ] || { echo "demo: no rtrace in '$bin' (run make first)" >&2; exit 1; }
scene=$here/office/office.rad   # absolute paths: taken as given, whatever RAYPATH says
grid=$here/office/grid.txt
threads=$(nproc 2> /dev/null || echo 2)
# -I: irradiance at each sensor (x y z dx dy dz, facing up); -ab 5 diffuse bounces, -aa 0 path tracing
# with -ad 1024 paths per sensor; -ds .1 samples the luminaires more finely than the default (.2), for
# less noise in the monitors' shadows; -lw 1e-5 Russian roulette. About 1 % RMS noise (bench/README.md).
opts=(-h -I -ab 5 -aa 0 -ad 1024 -ds .1 -lw 1e-5 -n "$threads")

echo "Brume demo: the office of examples/office (6 m x 4 m x 3 m, six 0.6 m ceiling panels, night)"
echo "  rtrace ${opts[*]} office.rad < grid.txt    ($(grep -c . "$grid") sensors at 0.8 m)"
start=$(date +%s%N)
values=$("$rtrace" "${opts[@]}" "$scene" < "$grid")
end=$(date +%s%N)

# Illuminance (lux) = 179 * (.265 R + .670 G + .065 B) of the irradiance; a plan of the room, north up.
paste "$grid" <(printf '%s\n' "$values") | awk '
  NF >= 9 {
    x = $1 + 0; y = $2 + 0; lx = 179 * (.265 * $7 + .670 * $8 + .065 * $9)
    if (!(x in seenx)) { seenx[x] = 1; xs[++nx] = x }
    if (!(y in seeny)) { seeny[y] = 1; ys[++ny] = y }
    E[x, y] = lx; n++; sum += lx
    if (n == 1 || lx < mn) mn = lx
    if (n == 1 || lx > mx) mx = lx
    # the task area: sensors at least 0.5 m from the walls
    if (x >= 0.5 && x <= 5.5 && y >= 0.5 && y <= 3.5) {
      tn++; tsum += lx
      if (tn == 1 || lx < tmn) tmn = lx
      if (tn == 1 || lx > tmx) tmx = lx
    }
    if (lx != lx) nan++
  }
  END {
    if (n == 0) { print "demo: rtrace gave no values" > "/dev/stderr"; exit 1 }
    # sort the coordinates (few: insertion sort)
    for (i = 2; i <= nx; i++) for (j = i; j > 1 && xs[j] < xs[j-1]; j--) { t = xs[j]; xs[j] = xs[j-1]; xs[j-1] = t }
    for (i = 2; i <= ny; i++) for (j = i; j > 1 && ys[j] < ys[j-1]; j--) { t = ys[j]; ys[j] = ys[j-1]; ys[j-1] = t }
    printf "\nIlluminance (lux) on the work plane, z = 0.8 m; north wall at the top, window (south) at the bottom\n"
    printf "%7s |", "y \\ x"
    for (i = 1; i <= nx; i++) printf "%6.2f", xs[i]
    printf "\n--------+"
    for (i = 1; i <= nx; i++) printf "------"
    printf "\n"
    for (j = ny; j >= 1; j--) {
      printf "%7.2f |", ys[j]
      for (i = 1; i <= nx; i++) printf ((xs[i], ys[j]) in E ? "%6.0f" : "%6s", (xs[i], ys[j]) in E ? E[xs[i], ys[j]] : "-")
      printf "\n"
    }
    printf "%7s  %s\n", "", "(window: x 1 to 5 m in the south wall)"
    printf "\n%-30s %6s %6s %6s %12s\n", "", "min", "mean", "max", "U0=min/mean"
    printf "%-30s %6.0f %6.0f %6.0f %12.2f\n", "all " n " sensors", mn, sum / n, mx, mn / (sum / n)
    if (tn) printf "%-30s %6.0f %6.0f %6.0f %12.2f\n", "task area (0.5 m from walls)", tmn, tsum / tn, tmx, tmn / (tsum / tn)
    printf "(EN 12464-1 asks 500 lx and U0 >= 0.60 for writing, typing and reading in offices)\n"
    if (nan) printf "WARNING: %d sensors gave NaN\n", nan
  }'
awk -v t="$(( (end - start) / 1000000 ))" -v n="$threads" 'BEGIN { printf "\nrtrace run time: %.2f s on %d threads\n", t / 1000, n }'

# The same sensors in 41 wavelength bands (RGB colours become smooth spectra): photopic illuminance and
# CIE S 026 melanopic equivalent daylight illuminance (EDI), with Brume's irradiance cache (its defaults).
sopts=(-h -I -ab 5 -cs 41 -n "$threads")
echo
echo "  rtrace ${sopts[*]} -pY | -pMD65 office.rad < grid.txt    (41 bands, 380-780 nm)"
mean() { awk '{ s += $1; n++ } END { printf "%.0f", s / n }'; }
lux=$("$rtrace" "${sopts[@]}" -pY "$scene" < "$grid" | mean)
edi=$("$rtrace" "${sopts[@]}" -pMD65 "$scene" < "$grid" | mean)
echo "Mean illuminance $lux lx, mean melanopic EDI $edi lx (the panels' white is equal-energy light)"

# A picture from a standing eye by the west wall, looking at the desks: diffuse interreflection from the
# irradiance cache (-ab 1 with rpict's -aa .2 -ad 512; bounces past the first by Russian roulette), every
# other pixel traced first and the rest traced or interpolated (-ps 2 -pt .1). -t 5 reports progress every
# 5 seconds, and the cache's records at the end.
out=$(cd "$bin/.." && pwd)/demo
mkdir -p "$out"
picture=$out/office.hdr
rm -f "$picture"   # rpict never overwrites a picture
view=(-vp 0.3 0.3 1.6 -vd 1 0.8 -0.3 -vh 75 -vv 55)
popts=(-x 480 -y 360 -ab 1 -ps 2 -pt .1 -n "$threads")
echo
echo "  rpict ${popts[*]} ${view[*]} -o office.hdr office.rad"
start=$(date +%s%N)
"$bin/rpict" "${popts[@]}" "${view[@]}" -t 5 -o "$picture" "$scene"
end=$(date +%s%N)
awk -v t="$(( (end - start) / 1000000 ))" -v n="$threads" -v p="$picture" \
  'BEGIN { printf "rpict run time: %.2f s on %d threads\nPicture: %s (Radiance RGBE; view it with ximage, or oiiotool/OpenImageIO; -o name.exr writes OpenEXR)\n", t / 1000, n, p }'

# Smoke: an exit sign at the end of a corridor, seen through the soot of a fire simulation (NIST FDS,
# ../shared/data) at the six instants of its grids, from three places along the corridor (vismap: 64 rays to
# the sign and to the wall around it per place and instant, the smoke's light sampled). Without the shared
# data, a homogeneous medium of soot's extinction stands in for the smoke.
corridor=$here/corridor
timed() {  # timed PICTURE COMMAND...: runs the command, then says how long it took and where the picture is
    local picture=$1 start end
    shift
    start=$(date +%s%N)
    "$@"
    end=$(date +%s%N)
    awk -v t="$(( (end - start) / 1000000 ))" -v n="$threads" -v p="$picture" \
      'BEGIN { printf "rpict run time: %.2f s on %d threads\nPicture: %s\n", t / 1000, n, p }'
}
soot=$here/../../shared/data/vdb/fds_room_fire_mesh2_soot
if [ -d "$soot" ]; then
    smoke=("$corridor/smoke.rad"); export RAYPATH="$soot:${RAYPATH:-.:/usr/local/lib/ray}"
    when=(-T 30,60,90,120,150,180); medium=()
    echo; echo "Smoke: exit sign (150 cd/m²) through FDS soot (K_m 8700 m²/kg, albedo .2), corridor 5 m x 2 m x 2.6 m"
else
    smoke=(); when=(); medium=(-me .4 .4 .4 -ma .2 .2 .2 -mg .6)
    echo; echo "Smoke: ../shared/data is absent; a homogeneous medium (σ = 0.4/m, albedo .2) stands in for the soot"
fi
printf 'far 10.3 3 1.7\nmiddle 12 3 1.7\nnear 13.5 3 1.7\n' > "$out/corridor_route.txt"
vopts=(-ab 1 -ms .05 -vr 64 -n "$threads")
echo "  vismap -S signs.txt -wp route.txt ${when[*]} ${vopts[*]} corridor.rad smoke.rad > corridor_sight.csv"
"$bin/vismap" -S "$corridor/signs.txt" -wp "$out/corridor_route.txt" "${when[@]}" "${vopts[@]}" "${medium[@]}" \
    "$corridor/corridor.rad" "${smoke[@]}" > "$out/corridor_sight.csv"
# Per instant and place: the sign's and the wall's luminance (cd/m²) and the sign's visibility level; then the
# first instant each place loses the sign, by the light (Adrian's visibility level >= 10) and by Jin's S = 8/K.
awk -F, 'NR > 1 { if (!($2 in d)) { place[++n] = $2; d[$2] = $8 }; if (!($1 in seen)) { seen[$1]; t[++m] = $1 }
                  v[$1, $2] = sprintf("%6.1f %5.1f %5.0f", $9, $10, $14)
                  if ($15 != "visible" && !($2 in lost)) lost[$2] = $1 " s"
                  if ($20 != "visible" && !($2 in jlost)) jlost[$2] = $1 " s" }
         END { printf "%-9s", "instant"; for (i = 1; i <= n; i++) printf "  %-18s", place[i] " (" sprintf("%.1f", d[place[i]]) " m)"
               printf "\n%-9s", ""; for (i = 1; i <= n; i++) printf "  %-18s", "  sign  wall    VL"; printf "\n"
               for (j = 1; j <= m; j++) { printf "%-9s", "t = " t[j]; for (i = 1; i <= n; i++) printf "  %-18s", v[t[j], place[i]]; printf "\n" }
               printf "%-9s", "lost at:"; for (i = 1; i <= n; i++) printf "  %-18s", "light " ((place[i] in lost) ? lost[place[i]] : "never"); printf "\n"
               printf "%-9s", ""; for (i = 1; i <= n; i++) printf "  %-18s", "Jin   " ((place[i] in jlost) ? jlost[place[i]] : "never"); printf "\n" }' \
    "$out/corridor_sight.csv"
echo "(visible: Adrian's visibility level >= 10 (vismap(1)); Jin's law S = 8/K looks at the extinction alone)"
if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
    /usr/bin/python3 "$here/hall/plot_sight.py" "$out/corridor_sight.csv" -o "$out/corridor_sight.png"
    echo "Plot of contrast and visibility level over time: $out/corridor_sight.png"
fi

# A picture of the corridor at t = 120 s: single scattering of the luminaires' light (-ab 0), 240 x 180.
picture=$out/corridor.hdr
rm -f "$picture"
cview=(-vp 10.3 3 1.6 -vd 1 0 0.05 -vh 70 -vv 55)
copts=(-x 240 -y 180 -ab 0 -ms .05 -n "$threads")
ctime=(); [ ${#smoke[@]} -gt 0 ] && ctime=(-T 120)
echo
echo "  rpict ${copts[*]} ${ctime[*]} ${cview[*]} -o corridor.hdr corridor.rad smoke.rad"
timed "$picture" "$bin/rpict" "${copts[@]}" "${ctime[@]}" "${medium[@]}" "${cview[@]}" -o "$picture" \
    "$corridor/corridor.rad" "${smoke[@]}"

# The same view with two bounces of the light the walls and the smoke scatter, from the irradiance caches
# (surface and volume records: rtrace(1), "The volume cache"), 120 x 90: every bounce's light in the smoke.
picture2=$out/corridor_ab2.hdr
rm -f "$picture2"
copts2=(-x 120 -y 90 -ab 2 -ms .05 -n "$threads")
echo
echo "  rpict ${copts2[*]} ${ctime[*]} ${cview[*]} -o corridor_ab2.hdr corridor.rad smoke.rad"
timed "$picture2" "$bin/rpict" "${copts2[@]}" "${ctime[@]}" "${medium[@]}" "${cview[@]}" -o "$picture2" \
    "$corridor/corridor.rad" "${smoke[@]}"

# Flames as light sources: a dark 5 m x 4 m x 2.7 m room lit only by a small fire on its floor
# (examples/flame: make_flame writes the plume's soot and temperature grids, an analytic cone 1.2 m tall at
# up to 1500 K). Illuminance at 0.8 m around it with two diffuse bounces (the irradiance cache), and a
# picture by the flame's own light (-ab 0: next-event estimation samples it as a lamp's).
room=$here/flame/room.rad
"$bin/make_flame" "$out/flame.vdb"
fopts=(-h -I -ab 2 -n "$threads")
echo
echo "Flames: a room lit only by a fire (examples/flame, a plume 0.5 m across at up to 1500 K)"
echo "  rtrace ${fopts[*]} room.rad < sensors at 0.8 m    (RAYPATH: the flame's grids)"
fsensors() {  # every 0.5 m at 0.8 m, facing up, but in the plume
    for x in -2 -1.5 -1 -0.5 0 0.5 1 1.5 2; do for y in -1.5 -1 -0.5 0 0.5 1 1.5; do
        awk -v x="$x" -v y="$y" 'BEGIN { if (x * x + y * y >= 0.25) print x, y, 0.8, 0, 0, 1 }'
    done; done
}
start=$(date +%s%N)
fsensors | RAYPATH="$out:${RAYPATH:-.}" "$rtrace" "${fopts[@]}" "$room" | paste <(fsensors) - | awk '
    { r = sqrt($1 * $1 + $2 * $2); lx = 179 * (.265 * $7 + .670 * $8 + .065 * $9)
      k = r < 1.2 ? 0 : (r < 2 ? 1 : 2); s[k] += lx; n[k]++; if (!(lx == lx)) nan++ }
    END { printf "Mean illuminance (lux) %.2f within 1.2 m of the fire, %.2f at 1.2-2 m, %.2f further out\n",
                 s[0] / n[0], s[1] / n[1], s[2] / n[2]
          if (nan) printf "WARNING: %d sensors gave NaN\n", nan }'
end=$(date +%s%N)
awk -v t="$(( (end - start) / 1000000 ))" -v n="$threads" 'BEGIN { printf "rtrace run time: %.2f s on %d threads\n", t / 1000, n }'
picture=$out/flame.hdr
rm -f "$picture"
fview=(-vp -2.3 -1.8 1.5 -vd 1 0.85 -0.35 -vh 80 -vv 62)
popts=(-x 240 -y 180 -ab 0 -n "$threads")
echo "  rpict ${popts[*]} ${fview[*]} -o flame.hdr room.rad"
RAYPATH="$out:${RAYPATH:-.}" timed "$picture" "$bin/rpict" "${popts[@]}" "${fview[@]}" -o "$picture" "$room"

# Fire-safety visibility, from an FDS run to maps in two commands: the fire hall of the shared FDS case
# (examples/hall; FDSVisMap's room fire, FDS 6.7.9), its soot read from the FDS output by fds2vdb (mesh 2, the
# hall's 5 m x 5 m corner by the door, from its 3D smoke file, the only one the case keeps; the other meshes from
# FDS's 2.05 m extinction slice over 1.5-2.5 m, -l, which the smoke object's comment states), and vismap over a
# grid of eyes at 1.7 m, every 0.5 m, at 60, 120 and 180 s: an exit sign that emits light (over the door) and a
# sign that reflects it (a plan on the south wall), under the normal lighting and under emergency lighting (1 %).
# Maps of each go to demo/hall_*.hdr (visibility level per instant, and the instant through which each sign
# stays visible, by the light and by Jin's law).
fds=$here/../../shared/data/fds/fdsvismap_room_fire
hall=$here/hall
if [ -f "$fds/model.smv" ]; then
    echo
    echo "Visibility maps: the fire hall of the shared FDS case (examples/hall), eyes at 1.7 m every 0.5 m"
    echo "  fds2vdb -t 60,120,180 -l 1.5,2.5 -o hall_soot model.smv > hall_smoke.rad"
    bin_dir=$(cd "$bin" && pwd)
    # Its warnings stand: above and below the slice's layer the seven meshes without 3D smoke have no data
    # (rtrace and vismap warn; vismap calls "no-data" the sight lines mostly through space without data).
    (cd "$out" && "$bin_dir/fds2vdb" -t 60,120,180 -l 1.5,2.5 -o hall_soot "$fds/model.smv" > hall_smoke.rad)
    hopts=(-g 10 0 15 5 0.5 1.7 -T 60,120,180 -ab 1 -ad 256 -n "$threads")
    for lighting in lights emergency; do
        echo "  vismap -S signs.txt ${hopts[*]} -o hall_$lighting hall.rad $lighting.rad hall_smoke.rad > hall_$lighting.csv"
        start=$(date +%s%N)
        (cd "$out" && "$bin_dir/vismap" -S "$hall/signs.txt" "${hopts[@]}" -o "hall_$lighting" "$hall/hall.rad" \
            "$hall/$lighting.rad" hall_smoke.rad > "hall_$lighting.csv")
        end=$(date +%s%N)
        awk -F, -v lighting="$lighting" -v t="$(( (end - start) / 1000000 ))" '
            NR > 1 { k = $6 " " $1; if (!(k in n)) order[++m] = k; n[k]++
                     light[k] += $15 == "visible"; jin[k] += $20 == "visible"
                     if (($15 == "visible") != ($20 == "visible")) differ[k]++ }
            END { printf "  %-9s %-10s %-8s %-16s %-16s %s\n", "lighting", "sign", "instant", "visible by light",
                         "by Jin'"'"'s law", "cells where they differ"
                  for (i = 1; i <= m; i++) { k = order[i]; split(k, w, " ")
                      printf "  %-9s %-10s %-8s %-16s %-16s %d\n", lighting, w[1], w[2] " s", light[k] "/" n[k],
                             jin[k] "/" n[k], differ[k] }
                  printf "  vismap run time: %.2f s\n", t / 1000 }' "$out/hall_$lighting.csv"
    done
    echo "  The plan sign under emergency lighting, the hall's corner seen from above (x 10-15 m left to right, y 5 m"
    echo "  at the top, the sign at y = 0, x 12.3-12.7): the last instant through which each place sees it"
    echo "  (. lost by 60 s, 1: through 60 s, 2: 120 s, 3: 180 s), by the light | by Jin's law"
    awk -F, -v S=plan_sign '
        NR > 1 && $6 == S { split($2, parts, "_"); x = parts[2] + 0; y = parts[3] + 0; k = x "," y
                            i = ($1 == 60) ? 1 : ($1 == 120) ? 2 : 3
                            if (!(k in light)) { light[k] = 0; jin[k] = 0 }
                            if ($15 == "visible" && light[k] == i - 1) light[k] = i
                            if ($20 == "visible" && jin[k] == i - 1) jin[k] = i
                            if (x > mx) mx = x; if (y > my) my = y }
        END { for (y = 0; y <= my; y++) { line = "    "
                  for (x = 0; x <= mx; x++) line = line (light[x "," y] ? light[x "," y] : ".")
                  line = line "    "
                  for (x = 0; x <= mx; x++) line = line (jin[x "," y] ? jin[x "," y] : ".")
                  print line } }' "$out/hall_emergency.csv"
    echo "(a sign that reflects the light is lost in the dim emergency lighting long before Jin's law says so:"
    echo " the law sees the smoke, not the light; maps: demo/hall_*_until.hdr, demo/hall_*_jin_until.hdr)"
    if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
        /usr/bin/python3 "$hall/plot_sight.py" "$out/hall_lights.csv" "$out/hall_emergency.csv" -o "$out/hall_maps.png"
        echo "Plots: $out/hall_maps.png"
    fi
else
    echo; echo "Visibility maps: ../shared/data/fds is absent (see README: from an FDS run to visibility maps)"
fi
