#!/bin/sh
# Regenerates expected/<name>.txt from Radiance's xform for each case of cases.txt (not run by make test).
# usage: sh regenerate.sh [radiance-prefix]   (default /tmp/radiance, whose bin/ holds xform)
set -e
radiance=${1:-/tmp/radiance}
cd "$(dirname "$0")"
mkdir -p expected
grep -v '^#' cases.txt | while IFS='	' read -r name command; do
    PATH="$radiance/bin:$PATH" RAYPATH=. sh -c "$command" > "expected/$name.txt" 2> /dev/null < /dev/null \
        || echo "$name: Radiance's xform failed" >&2
done
