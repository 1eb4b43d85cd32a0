#!/bin/sh
# Regenerates the Radiance reference pictures for test/rpict_compat_test.cpp from an installed Radiance
# (oconv and rpict on PATH, RAYPATH with rayinit.cal). Run it in this directory:
#     PATH=/path/to/radiance/bin:$PATH RAYPATH=.:/path/to/radiance/lib ./make_reference.sh
# It writes one picture, NAME.hdr, per line of views.txt: rpict with the options of options.txt and that
# line's view and resolution, and prints the rpict version to put in README.md.
set -eu
cd "$(dirname "$0")"
command -v rpict >/dev/null && command -v oconv >/dev/null || { echo "need Radiance's rpict and oconv on PATH" >&2; exit 1; }

OPTS=$(cat options.txt)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
oconv scene.rad > "$tmp/scene.oct"

grep -v '^#' views.txt | while read -r name view; do
    # shellcheck disable=SC2086  # the options are words
    rpict $OPTS $view "$tmp/scene.oct" > "$name.hdr"
done
rpict -version
