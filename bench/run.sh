#!/usr/bin/env bash
# Brume benchmark (make bench): bash bench/run.sh BIN_DIR [options]; see bench/README.md.
# bench.py (rtrace) takes every option but --skip-rpict, --skip-cache and --rerun-radiance; rpict.py (pictures)
# takes --repeat, --threads and --remake-reference, picture_widths.py (-ab 0 pictures 100 to 2000 pixels wide)
# --repeat and --remake-reference, and both are left out with --skip-rpict; cache.py (time against
# error of the irradiance caches) takes --remake-reference and --rerun-radiance, and is left out with --skip-cache;
# spectral.py (cost of -cs 12 … 81 against RGB) takes --repeat and is left out with --skip-spectral; smoke.py
# (time against error through FDS soot, with and without empty-space skipping) takes --repeat and is left out
# with --skip-smoke; volume_cache.py (time against error of view rays through lit smoke, volume cache against path
# tracing, 48 rays and 40 x 30 pictures; about 80 minutes) and vismap.py (a floor's visibility study, path tracing
# against the caches; about 15 minutes) are left out with --skip-smoke too; daylight.py (daylit rooms' sensor grids against Radiance) and daylight_picture.py (a daylit
# picture at -ab 5 against Radiance's cache) take --remake-reference and --rerun-radiance, and are left out with
# --skip-daylight.
set -euo pipefail
bin=${1:-build/bin}
shift || true
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
command -v python3 > /dev/null || { echo "bench: python3 is needed" >&2; exit 1; }
skip_rpict=0
skip_cache=0
skip_spectral=0
skip_smoke=0
skip_daylight=0
bench_args=()
rpict_args=()
widths_args=()
cache_args=()
spectral_args=()
smoke_args=()
daylight_args=()
while (($#)); do
    case $1 in
        --skip-rpict) skip_rpict=1 ;;
        --skip-cache) skip_cache=1 ;;
        --skip-spectral) skip_spectral=1 ;;
        --skip-smoke) skip_smoke=1 ;;
        --skip-daylight) skip_daylight=1 ;;
        --rerun-radiance) cache_args+=("$1"); daylight_args+=("$1") ;;
        --remake-reference) bench_args+=("$1"); rpict_args+=("$1"); widths_args+=("$1"); cache_args+=("$1"); daylight_args+=("$1") ;;
        --repeat) bench_args+=("$1" "${2:?$1 needs a value}"); rpict_args+=("$1" "$2"); widths_args+=("$1" "$2"); spectral_args+=("$1" "$2"); smoke_args+=("$1" "$2"); shift ;;
        --threads) bench_args+=("$1" "${2:?$1 needs a value}"); rpict_args+=("$1" "$2"); shift ;;
        *) bench_args+=("$1") ;;
    esac
    shift
done
python3 "$here/bench.py" --bin "$bin" "${bench_args[@]}"
if ((!skip_rpict)); then
    echo
    python3 "$here/rpict.py" --bin "$bin" "${rpict_args[@]}"  # reruns itself in a Python with numpy
    echo
    python3 "$here/picture_widths.py" --bin "$bin" "${widths_args[@]}"
fi
if ((!skip_cache)); then
    echo
    python3 "$here/cache.py" --bin "$bin" "${cache_args[@]}"  # likewise
fi
if ((!skip_spectral)); then
    echo
    python3 "$here/spectral.py" --bin "$bin" "${spectral_args[@]}"
fi
if ((!skip_smoke)); then
    echo
    python3 "$here/smoke.py" --bin "$bin" "${smoke_args[@]}"
    echo
    python3 "$here/volume_cache.py" --bin "$bin"
    echo
    python3 "$here/vismap.py" --bin "$bin"
    echo
    python3 "$here/fire.py" --bin "$bin"
fi
if ((!skip_daylight)); then
    echo
    python3 "$here/daylight.py" --bin "$bin" "${daylight_args[@]}"
    echo
    python3 "$here/daylight_picture.py" --bin "$bin" "${daylight_args[@]}"  # needs numpy, as rpict.py
fi
