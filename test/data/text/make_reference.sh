#!/bin/sh
# Regenerates reference.txt for the text comparison (test/radiance_compat_test.cpp) from an installed
# Radiance (oconv and rtrace on PATH, RAYPATH with rayinit.cal). Run it in this directory:
#     PATH=/path/to/radiance/bin:$PATH RAYPATH=.:/path/to/radiance/lib ./make_reference.sh
# The options are those of test/data/radiance/make_reference.sh (deterministic, see its README.md).
set -eu
cd "$(dirname "$0")"
# helvet.fnt is Brume's own (lib/pattern/fonts), not Radiance's of the same name: its folder goes first.
export RAYPATH=".:../../../lib/pattern/fonts:${RAYPATH:-/usr/local/lib/ray}"
command -v rtrace >/dev/null && command -v oconv >/dev/null || { echo "need Radiance's rtrace and oconv on PATH" >&2; exit 1; }
OPTS="-ab 0 -av 0.1 0.1 0.1 -aw 0 -dt 0 -dc 1 -dj 0 -ds 0.02 -dr 0 -dv+ -bv+ -st 1 -lr 12 -lw 1e-5 -u-"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
oconv text.rad > "$tmp/text.oct"
OPTS="$OPTS" ../radiance/rtrace_reference.sh "$tmp/text.oct" rays.txt "" reference.txt
rtrace -version
