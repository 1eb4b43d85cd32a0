#!/usr/bin/env bash
# Fallback for bench/plot.py when no Python has matplotlib: plot.gnuplot.sh table.tsv out.png
set -euo pipefail
tsv=$1 png=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# One data block per series (gnuplot's "index"), titles in a separate list.
awk -F'\t' '!/^#/ && NF { if ($1 != last) { if (n++) printf "\n\n" > "'"$tmp"'/data"; print $1 > "'"$tmp"'/titles"; last = $1 }
                          print $4, $5 > "'"$tmp"'/data" }' "$tsv"
n=$(wc -l < "$tmp/titles")
plots=""
for ((i = 0; i < n; i++)); do
  title=$(sed -n "$((i + 1))p" "$tmp/titles")
  plots+="${plots:+, }'$tmp/data' index $i using 1:2 with linespoints title '$title'"
done
gnuplot <<GP
set terminal pngcairo size 960,660 noenhanced
set output '$png'
set logscale xy
set grid
set xlabel 'CPU time for the 96 sensors, one thread (s)'
set ylabel 'RMS relative error of illuminance (%)'
set title 'Office sensor grid, -ab 5: time against error versus a converged Brume reference'
plot $plots
GP
