#!/bin/bash
# Writes hand_reference.txt: for the window of window_d.rad as a sender with h=-kq and with h=kq, each bin's share of
# rays that reach the sky or the ground past block_aside.rad (a block off to one side), by Radiance 6.1's rfluxmtx
# (-ab 0 -c 20000: each share's own standard error 0.0035 at most); test/rcontrib_cli_test.cpp compares Brume's.
#   PATH=/tmp/radiance/inst/bin:$PATH RAYPATH=.:/tmp/radiance/inst/lib test/data/rfluxmtx/make_hand_reference.sh
set -euo pipefail
cd "$(dirname "$0")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed 's/h=-kq/h=kq/' window_d.rad > "$tmp/right.rad"
shares() { rfluxmtx -h -ab 0 -c 20000 "$1" ../rcontrib/sky.rad block_aside.rad | awk '{ s = 0; for (i = 1; i <= NF; i += 3) s += $i; printf "%.5f\n", s }'; }
{
    echo "# each bin's share of rays past the block: h=-kq, h=kq (Radiance 6.1's rfluxmtx -ab 0 -c 20000; make_hand_reference.sh)"
    paste -d' ' <(shares window_d.rad) <(shares "$tmp/right.rad")
} > hand_reference.txt
