#!/usr/bin/env bash
# same_outputs.sh: checks that a behaviour-preserving refactor changes no output.
#
#     bash test/same_outputs.sh BIN_A BIN_B [OUTDIR]
#
# Runs one fixed list of commands (rtrace, rpict, mkcache, vwrays, xform, gensky, gendaylit on the example
# office, the smoke corridor and the scenes of test/data) once with the programs of BIN_A and once with
# those of BIN_B, always with -u- (a fixed seed: Brume's outputs are then the same bit for bit on every run
# and for any -n), and reports per command whether the outputs are byte-identical: the standard output,
# every file the command wrote (pictures, depth buffers, binary ray values) and the exit status.
# Exit status 0 only if every command gives identical outputs.
#
# - Dates differ legitimately: header lines CAPDATE=, GMT= and SOFTWARE= (and OpenEXR's capDate,
#   utcOffset and Software attributes) are left out of the comparison. Everything else in a header must
#   match: the programs are run by name from PATH (so the header's command line is the same for both
#   bins), and every command runs in the same working folder, OUTDIR/work, whichever bin (so paths of
#   files written, which headers name, are the same too).
# - Irradiance cache files (-af, named *.cache here) are NOT compared: their format may change. Their
#   values are: each cache case runs a second program on the file (mkcache then rtrace -af, rtrace -af
#   twice, mkcache or rpict then rpict -af), and the values that second run computes are compared.
# - Where outputs differ, the table gives the largest relative difference |a-b|/max(|a|,|b|) over the
#   numbers of text outputs, binary float outputs (*.f32, *.f64, *.zbf) and the pixels of Radiance
#   (RGBE/XYZE) and OpenEXR (ZIP, half or float) pictures, when the two have the same shape.
# - Commands named NAME@n1 and NAME@n2 are the same command with -n 1 and -n 2: besides the A/B comparison,
#   the two are compared with each other within each bin (the -n in header command lines aside), since
#   results must not depend on threads. Those findings are reported but do not change the exit status.
#
# Outputs go to OUTDIR (default /tmp/same_outputs): OUTDIR/A/NAME.out (standard output), NAME.err, NAME.files/
# (files written), and the same under OUTDIR/B; OUTDIR/inputs holds the ray lists, views, camera paths and
# small scenes the commands read (written by this script, the same for both bins). COMPARE_ONLY=1 compares
# the outputs already in OUTDIR again without running anything (after looking into, or editing, them).
# The scenes of examples/corridor need the smoke of the shared data: SHARED (default REPO/../shared/data).
set -uo pipefail

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
    echo "usage: bash test/same_outputs.sh BIN_A BIN_B [OUTDIR]" >&2
    exit 2
fi
abs() { (cd "$1" 2>/dev/null && pwd) || { echo "same_outputs: no folder $1" >&2; exit 2; }; }
BIN_A=$(abs "$1") || exit 2
BIN_B=$(abs "$2") || exit 2
OUT=${3:-/tmp/same_outputs}
mkdir -p "$OUT" && OUT=$(abs "$OUT") || exit 2
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SHARED=${SHARED:-$REPO/../shared/data}
[ -d "$SHARED/vdb/fds_room_fire_mesh2_soot" ] && SHARED=$(abs "$SHARED") ||
    { echo "same_outputs: no smoke data in $SHARED (set SHARED)" >&2; exit 2; }
for bin in "$BIN_A" "$BIN_B"; do
    for p in rtrace rpict mkcache vwrays xform gensky gendaylit; do
        [ -x "$bin/$p" ] || { echo "same_outputs: no $p in $bin" >&2; exit 2; }
    done
done
PY=/usr/bin/python3
[ -x $PY ] || PY=python3

TD=$REPO/test/data            # test scenes
EX=$REPO/examples             # example office and corridor
SOOT=$SHARED/vdb/fds_room_fire_mesh2_soot
INP=$OUT/inputs               # generated inputs, read by both bins
WORK=$OUT/work                # every command's files go here ($W), the same path for both bins

# ------------------------------------------------------------------------------------------------------
# Inputs (plain text made with awk, the same for both bins)
# ------------------------------------------------------------------------------------------------------
# The office's standing eye by the west wall (examples/demo.sh).
OFFICE_VIEW="-vp 0.3 0.3 1.6 -vd 1 0.8 -0.3 -vh 75 -vv 55"
make_inputs() {
    # 1000 view rays fanned from the office's standing eye.
    awk 'BEGIN { pi = atan2(0, -1)
        for (j = 0; j < 25; j++) for (i = 0; i < 40; i++) {
            az = (5 + 80 * i / 39) * pi / 180; el = (-45 + 65 * j / 24) * pi / 180
            printf "0.3 0.3 1.6 %.6f %.6f %.6f\n", cos(az) * cos(el), sin(az) * cos(el), sin(el) } }' > "$INP/office_view_rays.txt"
    # The same with a zero-direction ray (rtrace flushes its output there) after every 250.
    awk '{ print } NR % 250 == 0 { print "0 0 0 0 0 0" }' "$INP/office_view_rays.txt" > "$INP/office_flush_rays.txt"
    # Three rays for trace output: a desk, the floor between desks, the window.
    printf '0.3 0.3 1.6 1 0.8 -0.3\n3 2 1.5 0 0 -1\n3 2 1.5 0 -1 -0.2\n' > "$INP/office_three_rays.txt"
    # Rays with direction lengths for -ld: the same directions, some shorter than the distance to the walls.
    awk '{ s = 1 + (NR % 7); print $1, $2, $3, $4 * s, $5 * s, $6 * s }' "$INP/office_view_rays.txt" |
        sed -n '1~5p' > "$INP/office_ld_rays.txt"
    # A -S sequence: each line changes the view cumulatively.
    cat > "$INP/office_views.txt" <<'EOF'
VIEW= -vp 0.3 0.3 1.6 -vd 1 0.8 -0.3
rpict -vp 3 0.5 1.5 -vd 0 1 -0.2
VIEW= -vth -vh 180 -vv 180 -vp 3 2 2.9 -vd 0 0 -1 -vu 0 1 0
EOF
    # A camera path (rpict -path): time px py pz dx dy dz [ux uy uz].
    cat > "$INP/office_path.txt" <<'EOF'
# walk along the room, turning toward the window
0    0.5 2 1.6   1 0 -0.1
1    3 2 1.6     1 -0.5 -0.1
2.5  5 1.5 1.5   0 -1 -0.2    0 0 1
EOF
    # The corridor (examples/demo.sh): rays from three eyes to the exit sign and to the wall beside it, 30 each,
    # and a fan of view rays along the corridor.
    for x in 10.3 12 13.5; do for y in 3 3.45; do
        awk -v x="$x" -v y="$y" 'BEGIN { for (i = 0; i < 30; i++) print x, 3, 1.7, 15 - x, y - 3, .5 }'
    done; done > "$INP/corridor_rays.txt"
    awk 'BEGIN { for (j = 0; j < 6; j++) for (i = 0; i < 10; i++)
        printf "10.3 3 1.6 1 %.4f %.4f\n", -0.5 + i / 9, -0.3 + 0.6 * j / 5 }' > "$INP/corridor_fan.txt"
    # rpict -S views of the corridor carrying their instants: two at t = 60 (the second reuses the first's
    # records), one at t = 120 (records of its own instant).
    cat > "$INP/corridor_views.txt" <<'EOF'
VIEW= -vp 10.3 3 1.6 -vd 1 0 0.05 -T 60
VIEW= -vp 12 3 1.6 -T 60
VIEW= -vp 12 3 1.6 -T 120
EOF
    # A camera path through the corridor, one frame per key: its times are the scene's instants.
    cat > "$INP/corridor_path.txt" <<'EOF'
60   10.3 3 1.6   1 0 0.05
90   11 3 1.6     1 0.05 0.05
120  12 3 1.6     1 0.1 0.1
150  13 2.8 1.6   1 0.15 0.1
EOF
    # Labelled ray files ("label x y z dx dy dz", # comments) without their labels.
    for f in bsdf/rays bsdf/sensors material_functions/rays mkillum/rays mkillum/rays_glow mkillum/sensors \
             office/rays office/sensors patterns/rays radiance/rays radiance/sensors radiance_instances/rays \
             radiance_instances/sensors radiance_instances/patterned_rays text/rays; do
        grep -v '^#' "$TD/$f.txt" | awk 'NF >= 7 { print $2, $3, $4, $5, $6, $7 }' > "$INP/${f/\//_}.txt"
    done
    # test/data/media: the jittered rays repeated (10 consecutive copies each), a sensor facing away from the lamp.
    awk '{ for (i = 0; i < 10; i++) print }' "$TD/media/b_rays.txt" > "$INP/media_b_rays10.txt"
    awk '{ for (i = 0; i < 10; i++) print }' "$TD/media/b_spot_rays.txt" > "$INP/media_b_spot_rays10.txt"
    awk '{ for (i = 0; i < 10; i++) print }' "$TD/media/b_sun_rays.txt" > "$INP/media_b_sun_rays10.txt"
    awk '{ for (i = 0; i < 10; i++) print }' "$TD/media/c_rays.txt" > "$INP/media_c_rays10.txt"
    awk 'BEGIN { for (i = 0; i < 20; i++) print "0 0 -1 0 0 -1" }' > "$INP/media_d_sensor.txt"
    # test/data/instance: lamp.oct placed by instances with the transforms of transforms.txt, over a floor.
    {
        echo 'void plastic floor_grey 0 0 5 .5 .5 .5 0 0'
        echo 'floor_grey polygon floor 0 0 12  -6 -6 0  6 -6 0  6 6 0  -6 6 0'
        echo 'void instance lamp_here 1 lamp.oct 0 0'
        awk '{ printf "void instance lamp_%d %d lamp.oct %s 0 0\n", NR, NF + 1, $0 }' "$TD/instance/transforms.txt"
        echo '!xform -t 0 3 0 lamp.rad'
    } > "$INP/instance.rad"
    awk 'BEGIN { for (j = 0; j < 12; j++) for (i = 0; i < 12; i++) printf "%g %g 0 0 0 1\n", -5.5 + i, -5.5 + j }' > "$INP/floor_grid.txt"
    awk 'BEGIN { for (j = 0; j < 12; j++) for (i = 0; i < 12; i++) printf "%g %g 5 0 0 -1\n", -5.3 + 0.9 * i, -5.3 + 0.9 * j }' > "$INP/down_grid.txt"
    awk 'BEGIN { for (j = 0; j < 21; j++) for (i = 0; i < 21; i++) printf "%g %g 3 0.1 0.05 -1\n", -1 + 0.1 * i, -1 + 0.1 * j }' > "$INP/small_down_grid.txt"
    # test/data/mesh: the compiled mesh and its .obj (Brume's extension) under the sun and a sky.
    cat > "$INP/mesh.rad" <<'EOF'
void light sun_light 0 0 3 6e6 6e6 6e6
sun_light source sun 0 0 4 0.3 -0.4 0.866 0.53
void glow sky_glow 0 0 4 .8 .9 1.2 0
sky_glow source sky 0 0 4 0 0 1 180
void plastic ground 0 0 5 .4 .5 .3 0 0
ground mesh terrain 7 grid.rtm -s 5 -t -5 -5 1 0 0
ground mesh terrain_obj 9 grid.obj -s 5 -rz 90 -t 5 0 1 0 0
EOF
    # Skies: gensky's and gendaylit's sky (run by the scene's ! lines), a ground and a box on it.
    printf 'concrete polygon box_top 0 0 12  0 0 2  2 0 2  2 2 2  0 2 2\nconcrete polygon box_south 0 0 12  0 0 0  2 0 0  2 0 2  0 0 2\nconcrete polygon box_east 0 0 12  2 0 0  2 2 0  2 2 2  2 0 2\n' > "$INP/box.rad"
    sky_scene() {
        cat <<EOF
!$1
skyfunc glow sky_glow 0 0 4 .9 .9 1.15 0
sky_glow source sky 0 0 4 0 0 1 180
skyfunc glow ground_glow 0 0 4 1.4 .9 .6 0
ground_glow source ground 0 0 4 0 0 -1 180
void plastic grass 0 0 5 .2 .3 .1 0 0
grass polygon ground_plane 0 0 12  -20 -20 0  20 -20 0  20 20 0  -20 20 0
void plastic concrete 0 0 5 .5 .5 .5 0 0
!xform -t -1 -1 0 $INP/box.rad
EOF
    }
    sky_scene "gensky 3 21 12 -a 45.5 -o 0.5 -m 0 +s" > "$INP/sky_gensky.rad"
    sky_scene "gendaylit 6 21 10 -W 600 100 -a 45.5 -o 0.5 -m 0" > "$INP/sky_gendaylit.rad"
    awk 'BEGIN { for (j = -3; j <= 3; j++) for (i = -3; i <= 3; i++) printf "%g %g 0.001 0 0 1\n", 1.5 * i, 1.5 * j
                 print "1.001 0 1 1 0 0"; print "0 -1.001 1 0 -1 0" }' > "$INP/sky_sensors.txt"
}

# ------------------------------------------------------------------------------------------------------
# The commands
# ------------------------------------------------------------------------------------------------------
# add NAME FOLDER 'COMMAND': COMMAND runs by bash in FOLDER with PATH=BIN:/usr/bin:/bin, RAYPATH=. and
# $W (the folder for files it writes), $I (generated inputs), $TD (test/data), $EX (examples), $SOOT (the
# corridor's smoke frames). Its standard output is compared, and the files it writes into $W.
# both NAME FOLDER 'COMMAND': the command twice, with $N = 1 and 2 (use -n $N): NAME@n1 and NAME@n2.
NAMES=() DIRS=() CMDS=()
add() { NAMES+=("$1"); DIRS+=("$2"); CMDS+=("$3"); }
both() { add "$1@n1" "$2" "N=1; $3"; add "$1@n2" "$2" "N=2; $3"; }

# ---- examples/office: rtrace ----
O=$EX/office
both office/I_ab5_cache   "$O" 'rtrace -u- -n $N -I -ab 5 office.rad < grid.txt'
add  office/I_ab5_aa0_ad256 "$O" 'rtrace -h -u- -n 2 -I -ab 5 -aa 0 -ad 256 office.rad < grid.txt'
add  office/I_ab2_al      "$O" 'rtrace -h -u- -n 2 -I -ab 2 -al+ office.rad < grid.txt'
add  office/I_ab2_al_aa0  "$O" 'rtrace -h -u- -n 1 -I -ab 2 -al+ -aa 0 -ad 128 office.rad < grid.txt'
add  office/I_ab3_classic "$O" 'rtrace -h -u- -n 2 -I -ab 3 -acache classic office.rad < grid.txt'
add  office/I_ab2_options "$O" 'rtrace -h -u- -n 2 -I -ab 2 -aa .2 -ar 64 -ad 256 -ds .05 -dt 0 -lr 0 -lw 1e-3 -st .05 office.rad < grid.txt'
add  office/I_ab1_av      "$O" 'rtrace -h -u- -n 2 -I -ab 1 -av .1 .1 .1 -dr 0 -bv- office.rad < grid.txt'
add  office/I_ab0_ds0     "$O" 'rtrace -h -u- -n 1 -I -ab 0 -ds 0 -dv- office.rad < grid.txt'
add  office/view_ab0      "$O" 'rtrace -u- -n 2 -ab 0 office.rad < $I/office_view_rays.txt'
both office/view_ab1      "$O" 'rtrace -h -u- -n $N -ab 1 office.rad < $I/office_view_rays.txt'
add  office/view_ab1_aa0  "$O" 'rtrace -h -u- -n 2 -ab 1 -aa 0 -ad 64 office.rad < $I/office_view_rays.txt'
both office/view_ab2_flush "$O" 'rtrace -h -u- -n $N -ab 2 -ad 256 office.rad < $I/office_flush_rays.txt'
add  office/view_ab2_x10  "$O" 'rtrace -h -u- -n 2 -ab 2 -ad 256 -x 10 office.rad < $I/office_view_rays.txt'
add  office/view_ab2_ld   "$O" 'rtrace -h -u- -n 2 -ab 2 -ld+ -ad 256 office.rad < $I/office_ld_rays.txt'
add  office/trace_ot_ab0  "$O" 'rtrace -u- -n 1 -ab 0 -ovtodvLs office.rad < $I/office_three_rays.txt'
add  office/trace_ot_ab1  "$O" 'rtrace -h -u- -n 2 -ab 1 -ad 32 -ovtodvw office.rad < $I/office_three_rays.txt'
add  office/trace_oT_ab1  "$O" 'rtrace -h -u- -n 2 -ab 1 -ad 16 -aa 0 -oTodvWLm office.rad < $I/office_three_rays.txt'
add  office/o_letters     "$O" 'rtrace -u- -n 2 -ab 1 -ad 128 -ovLlpnNsmrxRX office.rad < $I/office_view_rays.txt'
add  office/o_all_letters "$O" 'rtrace -h -u- -n 2 -ab 0 -ovVwWlLcpnNsmMrxRXd~o office.rad < $I/office_view_rays.txt'
add  office/i_ab1         "$O" 'rtrace -h -u- -n 2 -i -ab 1 office.rad < $I/office_view_rays.txt'
add  office/i_ab0         "$O" 'rtrace -h -u- -n 1 -i -ab 0 office.rad < $I/office_view_rays.txt'
add  office/cs41_pY       "$O" 'rtrace -u- -n 2 -I -ab 5 -cs 41 -pY office.rad < grid.txt'
add  office/cs41_pMD65    "$O" 'rtrace -h -u- -n 2 -I -ab 2 -cs 41 -pMD65 office.rad < grid.txt'
both office/cs41_co       "$O" 'rtrace -u- -n $N -I -ab 1 -cs 41 -co office.rad < grid.txt'
add  office/cs12_cw_pXYZ  "$O" 'rtrace -h -u- -n 2 -ab 1 -cs 12 -cw 400 700 -pXYZ office.rad < $I/office_view_rays.txt'
add  office/fdd           "$O" 'awk "NR % 4 == 1" grid.txt | rtrace -fad -h -u- -n 2 -I -ab 2 office.rad > $W/values.f64'
add  office/vwrays_fff    "$O" 'vwrays -ff -x 40 -y 30 '"$OFFICE_VIEW"' | rtrace -fff -h -u- -n 2 -ab 1 -ad 256 office.rad > $W/values.f32'
add  office/vwrays_fdc    "$O" 'vwrays -fd -x 48 -y 36 '"$OFFICE_VIEW"' | rtrace -fdc -u- -n 2 -ab 0 $(vwrays -d -x 48 -y 36 '"$OFFICE_VIEW"') office.rad > $W/picture.hdr'
add  office/ffa_header    "$O" 'vwrays -ff -x 20 -y 15 '"$OFFICE_VIEW"' | rtrace -ffa -u- -n 2 $(vwrays -d -x 20 -y 15 '"$OFFICE_VIEW"') -ab 1 -ad 128 -aa 0 office.rad'
add  office/defaults      "$O" 'rtrace -defaults; rpict -defaults; mkcache -defaults; mkcache -defaults -vtv; rtrace -help; rpict -version'
# rtrace -af twice: the second run reuses the first one's records (their values are compared, not the file)
add  office/af_twice      "$O" 'rtrace -h -u- -n 2 -I -ab 3 -af $W/a.cache office.rad < grid.txt; echo second run; rtrace -h -u- -n 2 -I -ab 3 -af $W/a.cache office.rad < grid.txt; echo other points; rtrace -h -u- -n 2 -I -ab 3 -af $W/a.cache office.rad < $TD/cache/office_sensors.txt'
# (other points than mkcache's first: rtrace alone would make other records for them, so the values show
# that the file's records were read back as they were made)
both office/mkcache_rtrace "$O" 'mkcache -u- -n $N -I -ab 4 -ad 512 -af $W/m.cache office.rad < grid.txt; rtrace -h -u- -n 2 -I -ab 4 -ad 512 -af $W/m.cache office.rad < $TD/cache/office_sensors.txt; echo mkcache points; rtrace -h -u- -n 2 -I -ab 4 -ad 512 -af $W/m.cache office.rad < grid.txt'
add  office/mkcache_rtrace_other "$O" 'mkcache -u- -n 2 -I -ab 3 -ad 256 -af $W/o.cache office.rad < grid.txt; rtrace -h -u- -n 2 -I -ab 3 -ad 256 -af $W/o.cache office.rad < $TD/cache/office_sensors.txt'
add  office/mkcache_view_rays "$O" 'mkcache -u- -n 2 -ab 2 -af $W/v.cache office.rad < $I/office_view_rays.txt; rtrace -h -u- -n 2 -ab 2 -af $W/v.cache office.rad < $I/office_view_rays.txt'
add  office/mkcache_cs41  "$O" 'mkcache -u- -n 2 -I -ab 2 -cs 41 -af $W/s.cache office.rad < grid.txt; rtrace -h -u- -n 2 -I -ab 2 -cs 41 -pY -af $W/s.cache office.rad < grid.txt'

# ---- examples/office: rpict ----
V=$OFFICE_VIEW
add  office/rpict_ab0     "$O" "rpict -u- -n 2 -x 64 -y 48 $V -ab 0 office.rad"
both office/rpict_ab1     "$O" "rpict -u- -n \$N -x 64 -y 48 $V -ab 1 office.rad"
add  office/rpict_ab1_ps1 "$O" "rpict -u- -n 2 -x 64 -y 48 $V -ab 1 -ps 1 office.rad"
add  office/rpict_ab1_pj0 "$O" "rpict -u- -n 2 -x 64 -y 48 $V -ab 1 -ps 1 -pj 0 -pt .1 office.rad"
add  office/rpict_ab2_aa0 "$O" "rpict -u- -n 2 -x 48 -y 36 $V -ab 2 -aa 0 -ad 16 -ps 2 office.rad"
add  office/rpict_ab2_classic "$O" "rpict -u- -n 2 -x 48 -y 36 $V -ab 2 -acache classic -ad 256 office.rad"
add  office/rpict_i       "$O" "rpict -u- -n 2 -x 64 -y 48 $V -i -ab 1 -ps 1 office.rad"
add  office/rpict_i_ab0   "$O" "rpict -u- -n 1 -x 64 -y 48 $V -i -ab 0 office.rad"
add  office/rpict_z_exr   "$O" "rpict -u- -n 2 -x 64 -y 48 $V -ab 1 -z \$W/depth.zbf -o \$W/picture.exr office.rad"
add  office/rpict_exr_f   "$O" "rpict -u- -n 2 -x 48 -y 36 $V -ab 0 -ef f -o \$W/picture.exr office.rad"
add  office/rpict_pd      "$O" "rpict -u- -n 2 -x 48 -y 36 $V -vd 2 1.6 -0.6 -pd .05 -ab 0 office.rad"
add  office/rpict_pa0     "$O" "rpict -u- -n 2 -x 40 -y 40 $V -pa 0 -ab 0 -dv- office.rad"
add  office/rpict_cs24_pXYZ "$O" "rpict -u- -n 2 -x 48 -y 36 $V -ab 1 -cs 24 -pXYZ office.rad"
add  office/rpict_cs24_exr "$O" "rpict -u- -n 2 -x 32 -y 24 $V -ab 0 -cs 24 -o \$W/spectra.exr office.rad"
both office/rpict_S       "$O" "rpict -u- -n \$N -S 1 -x 48 -y 36 $V -ab 1 -ad 256 -o \$W/frame%02d.hdr office.rad < \$I/office_views.txt"
add  office/rpict_S_stdout "$O" "rpict -u- -n 2 -S 3 -x 32 -y 24 $V -ab 0 -z \$W/depth%d.zbf office.rad < \$I/office_views.txt"
both office/rpict_path    "$O" "rpict -u- -n \$N -path \$I/office_path.txt -fps 2 -vh 70 -vv 50 -x 32 -y 24 -ab 1 -ad 256 -o \$W/walk%03d.hdr office.rad"
add  office/rpict_path_keys "$O" "rpict -u- -n 2 -path \$I/office_path.txt -vth -vh 180 -vv 180 -x 24 -y 24 -ab 0 -o \$W/key%d.exr office.rad"
# -af reuse by rpict: mkcache for the view then rpict, and rpict twice on one file
add  office/mkcache_rpict "$O" "mkcache -u- -n 2 $V -x 32 -y 24 -ab 1 -af \$W/c.cache office.rad; rpict -u- -n 2 -x 64 -y 48 $V -ab 1 -af \$W/c.cache -o \$W/picture.hdr office.rad"
add  office/rpict_af_twice "$O" "rpict -u- -n 2 -x 48 -y 36 $V -ab 2 -ad 256 -af \$W/r.cache -o \$W/first.hdr office.rad; rpict -u- -n 2 -x 48 -y 36 $V -ab 2 -ad 256 -af \$W/r.cache -o \$W/second.hdr office.rad; rpict -u- -n 2 -x 48 -y 36 -vp 5.5 3.5 1.6 -vd -1 -0.8 -0.3 -vh 75 -vv 55 -ab 2 -ad 256 -af \$W/r.cache -o \$W/other_view.hdr office.rad"
add  office/mkcache_rpict_S "$O" "mkcache -u- -n 2 $V -x 24 -y 18 -ab 1 -ad 256 -af \$W/s.cache office.rad; rpict -u- -n 2 -S 1 -x 48 -y 36 $V -ab 1 -ad 256 -af \$W/s.cache -o \$W/frame%d.hdr office.rad < \$I/office_views.txt"

# ---- examples/corridor: smoke that evolves in time (FDS soot frames at 30 ... 180 s) ----
C=$EX/corridor
SMOKE="RAYPATH=$SOOT:.;"
add  corridor/rays_ab0_T60   "$C" "$SMOKE rtrace -h -u- -n 2 -ab 0 -ms .05 -T 60 corridor.rad smoke.rad < \$I/corridor_rays.txt"
add  corridor/rays_ab0_T125  "$C" "$SMOKE rtrace -h -u- -n 2 -ab 0 -ms .05 -T 125 corridor.rad smoke.rad < \$I/corridor_rays.txt"
both corridor/rays_ab1_T60   "$C" "$SMOKE rtrace -h -u- -n \$N -ab 1 -ad 128 -ms .05 -T 60 corridor.rad smoke.rad < \$I/corridor_rays.txt"
add  corridor/rays_ab1_T120  "$C" "$SMOKE rtrace -h -u- -n 2 -ab 1 -ad 128 -ms .05 -T 120 corridor.rad smoke.rad < \$I/corridor_rays.txt"
add  corridor/rays_ab1_aa0   "$C" "$SMOKE rtrace -h -u- -n 2 -ab 1 -aa 0 -ad 32 -ms .05 -T 90 corridor.rad smoke.rad < \$I/corridor_rays.txt"
add  corridor/fan_ab2_T180   "$C" "$SMOKE rtrace -u- -n 2 -ab 2 -ad 64 -ms .1 -T 180 -mc 4 corridor.rad smoke.rad < \$I/corridor_fan.txt"
add  corridor/fan_ab0_mc0    "$C" "$SMOKE rtrace -h -u- -n 1 -ab 0 -ms .1 -T 150 -mc 0 -ovLd corridor.rad smoke.rad < \$I/corridor_fan.txt"
add  corridor/I_ab1_T120     "$C" "$SMOKE rtrace -h -u- -n 2 -I -ab 1 -ad 128 -T 120 corridor.rad smoke.rad < \$I/corridor_fan.txt"
add  corridor/mist_ab1       "$C" "rtrace -h -u- -n 2 -ab 1 -ad 64 -ms .05 -me .4 .4 .4 -ma .2 .2 .2 -mg .6 corridor.rad < \$I/corridor_rays.txt"
add  corridor/mkcache_T120   "$C" "$SMOKE mkcache -u- -n 2 -ab 1 -ad 64 -ms .05 -T 120 -af \$W/t.cache corridor.rad smoke.rad < \$I/corridor_fan.txt; awk 'NR % 2 == 0' \$I/corridor_fan.txt | rtrace -h -u- -n 2 -ab 1 -ad 64 -ms .05 -T 120 -af \$W/t.cache corridor.rad smoke.rad"
add  corridor/rpict_T120_ab0 "$C" "$SMOKE rpict -u- -n 2 -x 40 -y 30 -vp 10.3 3 1.6 -vd 1 0 0.05 -vh 70 -vv 55 -ab 0 -ms .05 -T 120 corridor.rad smoke.rad"
both corridor/rpict_S_T      "$C" "$SMOKE rpict -u- -n \$N -S 1 -x 32 -y 24 -vh 70 -vv 55 -ab 1 -ad 32 -aa .2 -ms .05 -o \$W/frame%d.hdr corridor.rad smoke.rad < \$I/corridor_views.txt"
add  corridor/rpict_path_T   "$C" "$SMOKE rpict -u- -n 2 -path \$I/corridor_path.txt -x 32 -y 24 -vh 70 -vv 55 -ab 1 -ad 32 -aa .25 -ms .05 -o \$W/walk%d.hdr corridor.rad smoke.rad"
add  corridor/rpict_S_af_instants "$C" "$SMOKE rpict -u- -n 2 -S 1 -x 16 -y 12 -ab 1 -ad 16 -af \$W/x.cache -o \$W/frame%d.hdr corridor.rad smoke.rad < \$I/corridor_views.txt"

# ---- test/data scenes with rays or sensors: -ab 0, -ab 1 and -ab 2, with and without the cache ----
# Radiance's deterministic reference options (test/data/radiance/README.md)
REF="-av 0.1 0.1 0.1 -aw 0 -dt 0 -dc 1 -dj 0 -ds 0.02 -dr 0 -dv+ -bv+ -st 1 -lr 12 -lw 1e-5"
# rays: name folder scene-files ray-file [extra options]: -ab 0 (reference options), -ab 1 (cache), -ab 2
# (cache, both thread counts), -ab 1 and 2 by path tracing
rays_set() {
    local name=$1 dir=$2 scene=$3 rays=$4 extra=${5:-}
    add  "$name/ab0_ref"  "$dir" "rtrace -u- -n 2 -ab 0 $REF $extra $scene < $rays"
    add  "$name/ab0"      "$dir" "rtrace -h -u- -n 1 -ab 0 $extra $scene < $rays"
    add  "$name/ab1"      "$dir" "rtrace -h -u- -n 2 -ab 1 -ad 256 $extra $scene < $rays"
    both "$name/ab2"      "$dir" "rtrace -h -u- -n \$N -ab 2 -ad 256 $extra $scene < $rays"
    add  "$name/ab1_aa0"  "$dir" "rtrace -h -u- -n 2 -ab 1 -aa 0 -ad 64 $extra $scene < $rays"
    add  "$name/ab2_aa0"  "$dir" "rtrace -h -u- -n 2 -ab 2 -aa 0 -ad 32 $extra $scene < $rays"
}
rays_set bsdf/rays     "$TD/bsdf" scene.rad '$I/bsdf_rays.txt'
rays_set bsdf/sensors  "$TD/bsdf" scene.rad '$I/bsdf_sensors.txt' -I
rays_set material_functions "$TD/material_functions" scene.rad '$I/material_functions_rays.txt'
add  material_functions/glossy "$TD/material_functions" 'rtrace -h -u- -n 2 -ab 1 -ad 128 -st .15 scene.rad < $I/material_functions_rays.txt'
for w in mkillum twice glass; do
    rays_set "mkillum/$w/sensors" "$TD/mkillum" "sky.rad room.rad window_$w.rad" '$I/mkillum_sensors.txt' -I
    add "mkillum/$w/rays_ab0"  "$TD/mkillum" "rtrace -h -u- -n 2 -ab 0 $REF sky.rad room.rad window_$w.rad < \$I/mkillum_rays.txt"
    add "mkillum/$w/rays_ab1"  "$TD/mkillum" "rtrace -h -u- -n 2 -ab 1 -ad 128 sky.rad room.rad window_$w.rad < \$I/mkillum_rays.txt"
    add "mkillum/$w/rays_i"    "$TD/mkillum" "rtrace -h -u- -n 2 -i -ab 0 $REF sky.rad room.rad window_$w.rad < \$I/mkillum_rays.txt"
    add "mkillum/$w/rays_glow" "$TD/mkillum" "rtrace -h -u- -n 2 -ab 1 -ad 64 sky.rad room.rad window_$w.rad glow.rad < \$I/mkillum_rays_glow.txt"
done
add  mkillum/rpict_ab1  "$TD/mkillum" 'rpict -u- -n 2 -x 48 -y 36 -vp 2 4.8 1.5 -vd 0 -1 -0.1 -vh 80 -vv 60 -ab 1 -ad 256 sky.rad room.rad window_mkillum.rad'
rays_set office_daylit/sensors "$TD/office" office.rad '$I/office_sensors.txt' -I
rays_set office_daylit/rays    "$TD/office" office.rad '$I/office_rays.txt'
add  office_daylit/rpict_ab1 "$TD/office" 'rpict -u- -n 2 -x 48 -y 36 -vp 3 3.7 1.6 -vd 0 -1 -0.3 -vh 80 -vv 60 -ab 1 -ad 256 office.rad'
rays_set patterns   "$TD/patterns" patterns.rad '$I/patterns_rays.txt'
add  patterns/rpict_ab0 "$TD/patterns" 'rpict -u- -n 2 -x 64 -y 48 -vp 2 -3 3 -vd 0 1 -1 -vh 70 -vv 50 -ab 0 patterns.rad'
rays_set radiance/rays    "$TD/radiance" materials.rad '$I/radiance_rays.txt'
rays_set radiance/sensors "$TD/radiance" materials.rad '$I/radiance_sensors.txt' -I
add  radiance/rays_i     "$TD/radiance" "rtrace -h -u- -n 2 -i -ab 0 $REF materials.rad < \$I/radiance_rays.txt"
add  radiance/rays_i_ab1 "$TD/radiance" "rtrace -h -u- -n 2 -i -ab 1 -ad 128 materials.rad < \$I/radiance_rays.txt"
add  radiance/glossy     "$TD/radiance" "rtrace -h -u- -n 2 -ab 0 ${REF/-st 1/-st 0.15 -ss 1} materials.rad < \$I/radiance_rays.txt"
add  radiance/o_letters  "$TD/radiance" 'rtrace -h -u- -n 2 -ab 1 -ad 64 -ovLlpnNsmMrxRXc materials.rad < $I/radiance_rays.txt'
add  radiance/rpict_ab1  "$TD/radiance" 'rpict -u- -n 2 -x 64 -y 48 -vp 0.5 0.5 2 -vd 1 0.8 -0.3 -vh 80 -vv 60 -ab 1 -ad 256 materials.rad'
rays_set radiance_instances/rays    "$TD/radiance_instances" scene.rad '$I/radiance_instances_rays.txt'
rays_set radiance_instances/sensors "$TD/radiance_instances" scene.rad '$I/radiance_instances_sensors.txt' -I
add  radiance_instances/patterned_ab0 "$TD/radiance_instances" "rtrace -h -u- -n 2 -ab 0 $REF patterned.rad < \$I/radiance_instances_patterned_rays.txt"
add  radiance_instances/patterned_ab1 "$TD/radiance_instances" 'rtrace -h -u- -n 2 -ab 1 -ad 128 -ovsmMc patterned.rad < $I/radiance_instances_patterned_rays.txt'
rays_set text "$TD/text" text.rad '$I/text_rays.txt'
add  text/rpict_ab0 "$TD/text" 'rpict -u- -n 2 -x 64 -y 64 -vtl -vp 3 0.5 5 -vd 0 0 -1 -vu 0 1 0 -vh 6.5 -vv 6.5 -ab 0 -ps 1 text.rad'
# instance: lamp.oct placed seven times, next to the same lamp moved by xform
add  instance/floor_ab0  "$TD/instance" 'rtrace -h -u- -n 2 -I -ab 0 $I/instance.rad < $I/floor_grid.txt'
add  instance/floor_ab1  "$TD/instance" 'rtrace -h -u- -n 2 -I -ab 1 -ad 256 $I/instance.rad < $I/floor_grid.txt'
both instance/floor_ab2  "$TD/instance" 'rtrace -h -u- -n $N -I -ab 2 -ad 128 $I/instance.rad < $I/floor_grid.txt'
add  instance/floor_ab1_aa0 "$TD/instance" 'rtrace -h -u- -n 2 -I -ab 1 -aa 0 -ad 64 $I/instance.rad < $I/floor_grid.txt'
add  instance/rpict_ab1  "$TD/instance" 'rpict -u- -n 2 -x 64 -y 48 -vp 0 -9 6 -vd 0 1 -0.7 -vh 70 -vv 55 -ab 1 -ad 128 $I/instance.rad'
# mesh: a compiled mesh and its .obj
add  mesh/down_ab0   "$TD/mesh" 'rtrace -h -u- -n 2 -ab 0 -ovspnc $I/mesh.rad < $I/down_grid.txt'
add  mesh/down_ab1   "$TD/mesh" 'rtrace -h -u- -n 2 -ab 1 -ad 128 $I/mesh.rad < $I/down_grid.txt'
add  mesh/down_ab2_aa0 "$TD/mesh" 'rtrace -h -u- -n 2 -ab 2 -aa 0 -ad 16 $I/mesh.rad < $I/down_grid.txt'
add  mesh/rpict_ab0  "$TD/mesh" 'rpict -u- -n 2 -x 64 -y 48 -vp 0 -12 8 -vd 0 1 -0.7 -vh 60 -vv 45 -ab 0 $I/mesh.rad'
add  mesh/rpict_ab1  "$TD/mesh" 'rpict -u- -n 2 -x 48 -y 36 -vp 0 -12 8 -vd 0 1 -0.7 -vh 60 -vv 45 -ab 1 -ad 128 $I/mesh.rad'
add  mesh/rpict_ab2_aa0 "$TD/mesh" 'rpict -u- -n 2 -x 32 -y 24 -vp 0 -12 8 -vd 0 1 -0.7 -vh 60 -vv 45 -ab 2 -aa 0 -ad 8 $I/mesh.rad'
# rpict's reference pictures: each view of views.txt with options.txt, then -ab 1 and -ab 2
while read -r name view; do
    add "rpict/$name" "$TD/rpict" "rpict -n 2 $(cat "$TD/rpict/options.txt") $view scene.rad"
done < <(grep -v '^#' "$TD/rpict/views.txt")
add  rpict/perspective_ab1 "$TD/rpict" 'rpict -u- -n 2 -x 64 -y 48 -vtv -vp 0 -2.6 1.4 -vd 0 1 -0.5 -vh 55 -vv 42 -ab 1 scene.rad'
both rpict/perspective_ab2 "$TD/rpict" 'rpict -u- -n $N -x 48 -y 36 -vtv -vp 0 -2.6 1.4 -vd 0 1 -0.5 -vh 55 -vv 42 -ab 2 -ad 256 scene.rad'
add  rpict/fisheye_ab1_aa0 "$TD/rpict" 'rpict -u- -n 2 -x 32 -y 32 -vth -vp 0 -0.2 1.0 -vd 0 0 -1 -vu 0 1 0 -vh 180 -vv 180 -ab 1 -aa 0 -ad 16 scene.rad'
# media (test/data/media, make_reference.sh's commands; expanded/ holds the scenes with genbox's output)
M=$TD/media
B_OPTS="-ab 0 -dj 0 -ds 0 -ms .01 -me .01 .01 .01 -ma 1 1 1"
add  media/a1            "$M" 'rtrace -h -u- -n 2 -ab 0 -me .1 .1 .1 -ma 0 0 0 a_panel.rad < a_rays.txt'
add  media/a2            "$M" 'rtrace -h -u- -n 2 -ab 0 -me .1 .2 .3 -ma .5 .5 .5 -av .2 .2 .2 a_panel.rad < a_rays.txt'
add  media/b_iso         "$M" "rtrace -h -u- -n 2 $B_OPTS -mg 0 expanded/b_sphere.rad < \$I/media_b_rays10.txt"
both media/b_g06         "$M" "rtrace -h -u- -n \$N $B_OPTS -mg .6 expanded/b_sphere.rad < \$I/media_b_rays10.txt"
add  media/b_gm06        "$M" "rtrace -h -u- -n 2 $B_OPTS -mg -.6 expanded/b_sphere.rad < \$I/media_b_rays10.txt"
add  media/b_spot        "$M" "rtrace -h -u- -n 2 $B_OPTS -mg 0 expanded/b_spot.rad < \$I/media_b_spot_rays10.txt"
add  media/b_sun_a1      "$M" 'rtrace -h -u- -n 2 -ab 0 -dj 0 -ms .01 expanded/b_sun_a1.rad < $I/media_b_sun_rays10.txt'
add  media/b_sun_a05_g06 "$M" 'rtrace -h -u- -n 2 -ab 0 -dj 0 -ms .01 expanded/b_sun_a05_g06.rad < $I/media_b_sun_rays10.txt'
add  media/b_sun_globalabs "$M" 'rtrace -h -u- -n 2 -ab 0 -dj 0 -ms .01 -me .001 .001 .001 -ma .5 .5 .5 expanded/b_sun_a1.rad < b_sun_rays.txt'
add  media/b_sun_ab1     "$M" 'rtrace -h -u- -n 2 -ab 1 -ad 64 -ms .01 expanded/b_sun_a05_g06.rad < $I/media_b_sun_rays10.txt'
add  media/c_list_rays   "$M" 'rtrace -h -u- -n 2 -ab 0 -dj 0 -ms .01 expanded/c_list.rad < $I/media_c_rays10.txt'
add  media/c_nolist_rays "$M" 'rtrace -h -u- -n 2 -ab 0 -dj 0 -ms .01 expanded/c_nolist.rad < $I/media_c_rays10.txt'
add  media/c_list_sensors "$M" 'rtrace -h -u- -n 2 -I -ab 0 -dj 0 expanded/c_list.rad < c_sensors.txt'
add  media/c_nolist_sensors "$M" 'rtrace -h -u- -n 2 -I -ab 0 -dj 0 expanded/c_nolist.rad < c_sensors.txt'
add  media/c_ab1_cache   "$M" 'rtrace -h -u- -n 2 -ab 1 -ad 128 -ms .05 expanded/c_list.rad < $I/media_c_rays10.txt'
add  media/c_ab2_cache   "$M" 'rtrace -h -u- -n 2 -ab 2 -ad 64 -ms .05 expanded/c_list.rad < $I/media_c_rays10.txt'
add  media/d_ab1_aa0     "$M" "rtrace -h -u- -n 2 -I $B_OPTS -ab 1 -aa 0 -ad 256 -as 0 -lw 1e-9 -mg 0 expanded/b_sphere.rad < \$I/media_d_sensor.txt"
add  media/d_ab2_aa0     "$M" "rtrace -h -u- -n 2 -I $B_OPTS -ab 2 -aa 0 -ad 64 -lw 1e-9 -mg .6 expanded/b_sphere.rad < \$I/media_d_sensor.txt"
add  media/d_ab1_cache   "$M" "rtrace -h -u- -n 2 -I $B_OPTS -ab 1 -ad 256 -mg 0 expanded/b_sphere.rad < \$I/media_d_sensor.txt"
add  media/rpict_c_ab0   "$M" 'rpict -u- -n 2 -x 48 -y 36 -vp 0 -4 1.5 -vd 0 1 0 -vh 60 -vv 45 -ab 0 -ms .05 expanded/c_list.rad'
add  media/rpict_b_ab1   "$M" 'rpict -u- -n 2 -x 32 -y 24 -vp 0 -4 0 -vd 0 1 0 -vh 60 -vv 45 -ab 1 -ad 64 -ms .05 -me .01 .01 .01 -ma .9 .9 .9 -mg .3 expanded/b_sphere.rad'
# skies: gensky and gendaylit in scenes (their ! lines run the bin's own gensky, gendaylit and xform)
for s in gensky gendaylit; do
    add "sky/$s/sensors_ab0" "$INP" "rtrace -h -u- -n 2 -I -ab 0 sky_$s.rad < sky_sensors.txt"
    add "sky/$s/sensors_ab1" "$INP" "rtrace -h -u- -n 2 -I -ab 1 -ad 256 sky_$s.rad < sky_sensors.txt"
    add "sky/$s/sensors_ab2_aa0" "$INP" "rtrace -h -u- -n 2 -I -ab 2 -aa 0 -ad 64 sky_$s.rad < sky_sensors.txt"
    add "sky/$s/fisheye_ab0" "$INP" "rpict -u- -n 2 -x 48 -y 48 -vth -vp 0 0 0.5 -vd 0 0 1 -vu 0 1 0 -vh 180 -vv 180 -ab 0 sky_$s.rad"
    add "sky/$s/rpict_ab1"   "$INP" "rpict -u- -n 2 -x 48 -y 36 -vp 4 -6 2 -vd -0.5 1 -0.2 -vh 60 -vv 45 -ab 1 -ad 128 sky_$s.rad"
done
# spectral: Radiance's commands (commands.txt) on spectral.rad, then -ab 1 and pictures
SPEC="-ab 0 -av 0 0 0 -dt 0 -dc 1 -dj 0 -ds 0 -dr 0 -dp 0 -lr 8 -lw 0 -u-"
while IFS= read -r line; do
    out=${line%%:*} args=${line#*: }
    args=${args#* }; args=${args% spectral.oct*}              # the options between the program and the octree
    case $out in
        rpict*) add "spectral/${out%.hdr}" "$TD/spectral" "rpict -n 2 ${args} spectral.rad" ;;
        irr*)   add "spectral/${out%.txt}" "$TD/spectral" "rtrace -n 2 ${args} spectral.rad < irr.txt" ;;
        *)      add "spectral/${out%.txt}" "$TD/spectral" "rtrace -n 2 ${args} spectral.rad < rays.txt" ;;
    esac
done < "$TD/spectral/commands.txt"
add  spectral/smooth_cs24   "$TD/spectral" "rtrace -h -n 2 $SPEC -cs 24 -co spectral.rad smooth.rad < rays.txt"
add  spectral/ab1_cs24      "$TD/spectral" 'rtrace -h -u- -n 2 -ab 1 -ad 128 -cs 24 -co spectral.rad < rays.txt'
both spectral/ab2_cs24_pY   "$TD/spectral" 'rtrace -h -u- -n $N -I -ab 2 -ad 64 -cs 24 -pY spectral.rad < irr.txt'
add  spectral/ab1_aa0_cs12  "$TD/spectral" 'rtrace -h -u- -n 2 -ab 1 -aa 0 -ad 32 -cs 12 -cw 400 700 -co spectral.rad < rays.txt'
add  spectral/co_fc         "$TD/spectral" "rtrace -n 2 $SPEC -cs 6 -cw 400 700 -co -fac -x 2 -y 2 mkspic.rad < mkspic_rays.txt"
add  spectral/rpict_ab1_exr "$TD/spectral" 'rpict -u- -n 2 -vf view.vf -x 32 -y 24 -ab 1 -ad 64 -cs 24 -o $W/spectra.exr spectral.rad'
# octrees given in place of the scene (frozen, made by Radiance's oconv -f): the lamp alone, the table
# (no light source: -av lights it), instances within an instance
add  octree/lamp          "$TD/instance" 'rtrace -h -u- -n 2 -I -ab 1 -ad 128 lamp.oct < $I/floor_grid.txt'
add  octree/table         "$TD/radiance_instances" 'rtrace -u- -n 1 -ab 1 -ad 64 -av .2 .2 .2 -ovsm table.oct < $I/small_down_grid.txt'
add  octree/group         "$TD/radiance_instances" 'rtrace -h -u- -n 2 -ab 0 -av .2 .2 .2 -ovsmp group.oct < $I/small_down_grid.txt'

# ---- gensky, gendaylit (test/data/sky/commands.txt), xform and vwrays (their test cases) ----
n=0
while IFS= read -r line; do
    n=$((n + 1))
    add "sky/$(printf %02d $n)_${line%% *}" "$TD/sky" "$line"
done < "$TD/sky/commands.txt"
while IFS=$'\t' read -r name cmd; do
    add "xform/$name" "$TD/xform" "$cmd"
done < <(grep -v '^#' "$TD/xform/cases.txt")
while IFS= read -r line; do
    add "vwrays/${line%%:*}" "$TD/vwrays" "vwrays ${line#*: }"
done < <(grep -v '^#' "$TD/vwrays/cases.txt")
add  vwrays/office_view_fd "$O" "vwrays -fd -x 40 -y 30 $OFFICE_VIEW > \$W/rays.f64; vwrays -d -x 40 -y 30 $OFFICE_VIEW"
add  vwrays/office_rpict_picture "$O" "rpict -u- -n 2 -x 24 -y 18 $OFFICE_VIEW -ab 0 -o \$W/p.hdr office.rad; vwrays -ff \$W/p.hdr > \$W/rays.f32; vwrays -d \$W/p.hdr"

# ------------------------------------------------------------------------------------------------------
# Running
# ------------------------------------------------------------------------------------------------------
printf '%s\n' "${NAMES[@]}" > "$OUT/cases.txt"
# file name of a case: slashes become "__"
fname() { local f=${1//\//__}; echo "$f"; }

run_side() {  # run_side A|B BIN
    local side=$1 bin=$2 k name f start end rc total0 total1
    total0=$(date +%s%N)
    : > "$OUT/$side/times.txt"
    for k in "${!NAMES[@]}"; do
        name=${NAMES[k]} f=$(fname "${NAMES[k]}")
        rm -rf "$WORK"; mkdir -p "$WORK"
        start=$(date +%s%N)
        (cd "${DIRS[k]}" && exec env -i HOME="${HOME:-/tmp}" PATH="$bin:/usr/bin:/bin" LC_ALL=C RAYPATH=. \
            W="$WORK" I="$INP" TD="$TD" EX="$EX" SOOT="$SOOT" timeout 120 bash -c "${CMDS[k]}") \
            > "$OUT/$side/$f.out" 2> "$OUT/$side/$f.err" < /dev/null
        rc=$?
        end=$(date +%s%N)
        mv "$WORK" "$OUT/$side/$f.files"
        printf '%s\t%d\t%.2f\n' "$name" "$rc" "$(awk -v t=$((end - start)) 'BEGIN { print t / 1e9 }')" >> "$OUT/$side/times.txt"
    done
    total1=$(date +%s%N)
    awk -v t=$((total1 - total0)) 'BEGIN { printf "%.1f\n", t / 1e9 }' > "$OUT/$side/total_time.txt"
}

if [ -n "${COMPARE_ONLY:-}" ]; then   # compare the outputs of an earlier run again (OUTDIR/A, OUTDIR/B)
    [ -f "$OUT/A/times.txt" ] && [ -f "$OUT/B/times.txt" ] || { echo "same_outputs: no earlier run in $OUT" >&2; exit 2; }
    echo "same_outputs: comparing the outputs in $OUT again (COMPARE_ONLY)"
else
    rm -rf "$OUT/A" "$OUT/B" "$INP" "$WORK"
    mkdir -p "$OUT/A" "$OUT/B" "$INP"
    make_inputs
    echo "same_outputs: ${#NAMES[@]} commands; A = $BIN_A, B = $BIN_B; outputs in $OUT"
    run_side A "$BIN_A"
    echo "  A: $(cat "$OUT/A/total_time.txt") s"
    run_side B "$BIN_B"
    echo "  B: $(cat "$OUT/B/total_time.txt") s"
fi

# ------------------------------------------------------------------------------------------------------
# Comparing (python3: header normalisation, numeric differences, picture decoding)
# ------------------------------------------------------------------------------------------------------
"$PY" - "$OUT" <<'PYTHON'
import os, re, struct, sys, zlib

out = sys.argv[1]
names = open(os.path.join(out, "cases.txt")).read().split("\n")[:-1]
fname = lambda n: n.replace("/", "__")

def read_times(side):
    t = {}
    for line in open(os.path.join(out, side, "times.txt")):
        n, rc, s = line.rstrip("\n").split("\t")
        t[n] = (int(rc), float(s))
    return t
times = {s: read_times(s) for s in "AB"}

DATED = (b"CAPDATE=", b"GMT=", b"SOFTWARE=")
PROGRAM = re.compile(rb"^(rtrace|rpict|mkcache|vwrays|xform|gensky|gendaylit)\b")
THREADS = re.compile(rb"(^|\s)-n\s+\d+")

def norm_lines(data, threads):
    """Drops the dated header lines; with threads, writes -n N in command lines."""
    out = []
    for line in data.split(b"\n"):
        if line.startswith(DATED):
            continue
        if threads and PROGRAM.match(line):
            line = THREADS.sub(rb"\1-n N", line)
        out.append(line)
    return b"\n".join(out)

EXR_LINES = {0: 1, 1: 1, 2: 1, 3: 16, 4: 32, 5: 16, 6: 32, 7: 32, 8: 256, 9: 256}

def exr_parse(data):
    """(attributes, chunks): attributes by name (raw bytes), chunks [(y, payload)] of a scanline file."""
    pos = 8
    attrs = {}
    while data[pos] != 0:
        e = data.index(b"\0", pos); name = data[pos:e]; pos = e + 1
        e = data.index(b"\0", pos); typ = data[pos:e]; pos = e + 1
        size, = struct.unpack_from("<i", data, pos); pos += 4
        attrs[name] = (typ, data[pos:pos + size]); pos += size
    pos += 1
    x0, y0, x1, y1 = struct.unpack("<4i", attrs[b"dataWindow"][1])
    comp = attrs[b"compression"][1][0]
    n = (y1 - y0 + EXR_LINES[comp]) // EXR_LINES[comp]
    offsets = struct.unpack_from("<%dQ" % n, data, pos)
    chunks = []
    for o in offsets:
        y, size = struct.unpack_from("<ii", data, o)
        chunks.append((y, data[o + 8:o + 8 + size]))
    return attrs, chunks

def norm_exr(data, threads):
    attrs, chunks = exr_parse(data)
    keep = []
    for name in sorted(attrs):
        if name in (b"capDate", b"utcOffset", b"Software"):
            continue
        typ, value = attrs[name]
        if typ == b"string":
            value = norm_lines(value, threads)
        keep.append(name + b"\0" + typ + b"\0" + value)
    return b"\1".join(keep) + b"\2" + b"".join(struct.pack("<i", y) + c for y, c in chunks)

def normalize(data, threads=False):
    if data[:4] == b"\x76\x2f\x31\x01":
        try:
            return norm_exr(data, threads)
        except Exception:
            return data
    return norm_lines(data, threads)

# ---- numbers of an output, for the size of a difference ----
def half(h):
    s, e, m = h >> 15, (h >> 10) & 31, h & 1023
    v = (m / 1024.0) * 2.0 ** -14 if e == 0 else float("inf") if e == 31 else (1 + m / 1024.0) * 2.0 ** (e - 15)
    return -v if s else v

def exr_values(data):
    attrs, chunks = exr_parse(data)
    comp = attrs[b"compression"][1][0]
    if comp not in (0, 2, 3):
        return None
    x0, y0, x1, y1 = struct.unpack("<4i", attrs[b"dataWindow"][1])
    width = x1 - x0 + 1
    cl = attrs[b"channels"][1]
    types, pos = [], 0
    while cl[pos] != 0:
        e = cl.index(b"\0", pos); pos = e + 1
        types.append(struct.unpack_from("<i", cl, pos)[0]); pos += 16
    per_line = sum(width * (2 if t == 1 else 4) for t in types)
    values = []
    for y, c in sorted(chunks):
        lines = min(EXR_LINES[comp], y1 + 1 - y)
        if comp != 0 and len(c) < lines * per_line:   # else stored uncompressed
            raw = zlib.decompress(c)
            t = bytearray(raw)
            for i in range(1, len(t)):
                t[i] = (t[i - 1] + t[i] - 128) & 255
            h = (len(t) + 1) // 2
            raw = bytearray(len(t)); raw[0::2] = t[:h]; raw[1::2] = t[h:]
            c = bytes(raw)
        pos = 0
        while pos < len(c):
            for typ in types:
                if typ == 1:
                    values += [half(v) for v in struct.unpack_from("<%dH" % width, c, pos)]; pos += 2 * width
                else:
                    values += struct.unpack_from("<%d%s" % (width, "f" if typ == 2 else "I"), c, pos); pos += 4 * width
    return values

def rgbe_values(data):
    """Every pixel channel of the Radiance pictures (RGBE or XYZE) one after another in data, and their
    header lines (the dated ones left out)."""
    values, headers, pos = [], [], 0
    while pos < len(data):
        end = data.find(b"\n\n", pos)
        if end < 0:
            break
        header = data[pos:end]
        if b"FORMAT=" in header and b"32-bit_rle_" not in header:
            return None, None
        headers += norm_lines(header, False).split(b"\n")
        e = data.index(b"\n", end + 2)
        res = data[end + 2:e].split()
        height, width = int(res[1]), int(res[3])
        pos = e + 1
        for _ in range(height):
            scan = [bytearray(width) for _ in range(4)]
            if 8 <= width < 32768 and data[pos] == 2 and data[pos + 1] == 2 and not data[pos + 2] & 128:
                pos += 4
                for comp in range(4):
                    i = 0
                    while i < width:
                        n = data[pos]; pos += 1
                        if n > 128:
                            n -= 128; scan[comp][i:i + n] = bytes([data[pos]]) * n; pos += 1
                        else:
                            scan[comp][i:i + n] = data[pos:pos + n]; pos += n
                        i += n
            else:
                for i in range(width):
                    for comp in range(4):
                        scan[comp][i] = data[pos + comp]
                    pos += 4
            for i in range(width):
                ex = scan[3][i]
                f = 0.0 if ex == 0 else 2.0 ** (ex - 136)
                values += [(scan[c][i] + 0.5) * f if ex else 0.0 for c in range(3)]
    return values, headers

NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")

def numbers(path, data):
    """The numbers of an output (None when they cannot be read), with the words that are not numbers."""
    try:
        if path.endswith((".f32", ".zbf")):
            return list(struct.unpack("<%df" % (len(data) // 4), data[:len(data) // 4 * 4])), []
        if path.endswith(".f64"):
            return list(struct.unpack("<%dd" % (len(data) // 8), data[:len(data) // 8 * 8])), []
        if data[:4] == b"\x76\x2f\x31\x01":   # the pixels; the attributes as words
            return exr_values(data), norm_exr(data, False).split(b"\2")[0].split(b"\1")
        if data.startswith(b"#?RADIANCE") and b"FORMAT=32-bit_rle_" in data[:4096]:
            return rgbe_values(data)
        text = data.decode("utf-8")
    except Exception:
        return None, None
    nums, words = [], []
    for w in text.split():
        (nums if NUMBER.match(w) else words).append(float(w) if NUMBER.match(w) else w)
    return nums, words

def max_rel_diff(path, a, b):
    """Largest |x-y|/max(|x|,|y|) over the numbers of a and b, or why there is none. The denominator is at
    least 1e-9 of the output's largest value, so that rounding noise about 0 does not count as 100%."""
    na, wa = numbers(path, a)
    nb, wb = numbers(path, b)
    if na is None or nb is None:
        return "binary"
    if len(na) != len(nb):
        return "shape (%d vs %d numbers)" % (len(na), len(nb))
    finite = [abs(x) for x in na + nb if abs(x) != float("inf") and x == x]
    tiny = 1e-9 * max(finite, default=0.0) or 1e-300
    m = 0.0
    for x, y in zip(na, nb):
        if x != y and not (x != x and y != y):   # NaN against NaN: the same
            s = max(abs(x), abs(y), tiny)
            m = max(m, abs(x - y) / s if s != float("inf") and x == x and y == y else float("inf"))
    note = "%.3g" % m
    if wa != wb:
        note += " (and text/header)"
    return note

def outputs(side, name):
    """{output name: bytes}: the standard output, and the files written (not the *.cache files)."""
    f = fname(name)
    res = {"stdout": open(os.path.join(out, side, f + ".out"), "rb").read()}
    root = os.path.join(out, side, f + ".files")
    for d, _, files in os.walk(root):
        for x in files:
            if not x.endswith(".cache"):
                p = os.path.join(d, x)
                res[os.path.relpath(p, root)] = open(p, "rb").read()
    return res

def compare(oa, ob, threads=False):
    """[(output, description)] of the outputs that differ."""
    diffs = []
    for k in sorted(set(oa) | set(ob)):
        if k not in oa or k not in ob:
            diffs.append((k, "only in " + ("A" if k in oa else "B")))
            continue
        a, b = normalize(oa[k], threads), normalize(ob[k], threads)
        if a != b:
            diffs.append((k, max_rel_diff(k, oa[k], ob[k])))
    return diffs

w = max(len(n) for n in names) + 2
print()
print("%-*s %-9s %-24s %7s %7s  %s" % (w, "case", "identical", "max rel diff", "A (s)", "B (s)", "notes"))
print("-" * (w + 70))
bad = 0
for n in names:
    (rca, ta), (rcb, tb) = times["A"][n], times["B"][n]
    oa, ob = outputs("A", n), outputs("B", n)
    diffs = compare(oa, ob)
    notes = []
    if rca != rcb:
        notes.append("exit %d vs %d" % (rca, rcb))
    elif rca != 0:
        notes.append("exit %d" % rca)
    same = not diffs and rca == rcb
    if not same:
        bad += 1
    rel = "; ".join(("%s: %s" % (k, d)) if k != "stdout" or len(diffs) > 1 else d for k, d in diffs)
    ea = open(os.path.join(out, "A", fname(n) + ".err"), "rb").read()
    eb = open(os.path.join(out, "B", fname(n) + ".err"), "rb").read()
    if ea != eb:
        notes.append("stderr differs")
    if len(oa) > 1:
        notes.append("%d file%s" % (len(oa) - 1, "s" if len(oa) > 2 else ""))
    print("%-*s %-9s %-24s %7.2f %7.2f  %s" % (w, n, "yes" if same else "NO", rel, ta, tb, ", ".join(notes)))

# -n 1 against -n 2 within each bin
print()
print("Thread independence within each bin (NAME@n1 against NAME@n2, -n in header command lines aside):")
pairs = sorted({n[:-3] for n in names if n.endswith("@n1") and n[:-3] + "@n2" in names})
thread_bad = 0
for side in "AB":
    for p in pairs:
        d = compare(outputs(side, p + "@n1"), outputs(side, p + "@n2"), threads=True)
        if d:
            thread_bad += 1
            print("  %s: %s: -n 1 and -n 2 differ: %s" % (side, p, "; ".join("%s: %s" % x for x in d)))
if not thread_bad:
    print("  all %d pairs agree in A and in B" % len(pairs))

ta, tb = (open(os.path.join(out, s, "total_time.txt")).read().strip() for s in "AB")
print()
print("%d cases, %d differ between A and B; %d thread pairs differ; run time A %s s, B %s s"
      % (len(names), bad, thread_bad, ta, tb))
sys.exit(1 if bad else 0)
PYTHON
