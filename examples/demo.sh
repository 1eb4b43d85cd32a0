#!/usr/bin/env bash
# Brume demo (make demo): illuminance on the work plane of the example office, computed by rtrace, and a
# picture of the office rendered by rpict; an exit sign seen through a fire's soot; a room lit by a fire.
# Usage: bash examples/demo.sh BIN_DIR   (BIN_DIR holds Brume's programs; make demo passes build/bin)
# The pictures (office.hdr, corridor.hdr, corridor_ab2.hdr, flame.hdr) and the flame's grids go to BIN_DIR/../demo/.
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
# ../shared/data) at three instants of the fire, and without smoke. Luminance (cd/m²) of the sign and of
# the wall beside it from three places along the corridor, each the mean of 200 rays (the smoke's light is
# sampled); the contrast C = (L_sign − L_wall)/L_wall. Without the shared data, a homogeneous medium of
# soot's extinction stands in for the smoke.
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
    instants=(none 60 120 180); medium=()
    echo; echo "Smoke: exit sign (150 cd/m²) through FDS soot (K_m 8700 m²/kg, albedo .2), corridor 5 m x 2 m x 2.6 m"
else
    smoke=(); instants=(none mist); medium=(-me .4 .4 .4 -ma .2 .2 .2 -mg .6)
    echo; echo "Smoke: ../shared/data is absent; a homogeneous medium (σ = 0.4/m, albedo .2) stands in for the soot"
fi
sopts=(-h -ab 1 -ms .05 -n "$threads")
echo "  rtrace ${sopts[*]} -T t corridor.rad smoke.rad    (luminance = 179 x photopic radiance)"
rays() {  # 200 rays from each eye (1.7 m high) to the sign's centre, then to the wall beside it
    for x in 10.3 12 13.5; do for y in 3 3.45; do
        for i in $(seq 200); do echo "$x 3 1.7 $(awk -v x="$x" -v y="$y" 'BEGIN { print 15 - x, y - 3, .5 }')"; done
    done; done
}
printf "\n%-14s %-22s %-22s %-22s\n" "" "4.7 m from the sign" "3.0 m" "1.5 m"
printf "%-14s %-22s %-22s %-22s\n" "instant" "sign  wall  C" "sign  wall  C" "sign  wall  C"
for t in "${instants[@]}"; do
    case $t in none) scene_files=("$corridor/corridor.rad"); extra=(); label="no smoke" ;;
               mist) scene_files=("$corridor/corridor.rad"); extra=("${medium[@]}"); label="medium" ;;
               *) scene_files=("$corridor/corridor.rad" "${smoke[@]}"); extra=(-T "$t"); label="t = $t s" ;; esac
    rays | "$rtrace" "${sopts[@]}" "${extra[@]}" "${scene_files[@]}" | awk -v label="$label" '
        { k = int((NR - 1) / 200); L[k] += 179 * (.265 * $1 + .670 * $2 + .065 * $3) / 200 }
        END { printf "%-14s", label
              for (p = 0; p < 3; p++) printf " %6.1f %5.1f %5.1f    ", L[2 * p], L[2 * p + 1], (L[2 * p] - L[2 * p + 1]) / L[2 * p + 1]
              printf "\n" }'
done
echo "(a light-emitting sign stays legible while C is well above the eye's threshold; Jin's law S = 8/K"
echo " estimates the visibility distance from the extinction K alone, ignoring the lighting)"

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
