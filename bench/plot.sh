#!/bin/sh
# Plots median ns/query against the worst (and p99) distance error relative to S, per method and
# setting, from a prox_bench CSV: bench/plot.sh docs/perf/bench.csv runtime-vs-error
# (writes <out>-<set>.png for the sets agarwal_public and stress_public). Needs gnuplot (gnuplot-nox).
set -eu
CSV=$1
OUT=$2
for set in agarwal_public stress_public; do
    dat=$(mktemp)
    # case,n,repeats,mean,median,p99,err_max,err_p99,... ; keep rows of this set with an error figure
    awk -F, -v s="/$set" 'NR > 1 && index($1, s) && $7 != "" {
        name = $1; sub(s, "", name); sub(/^(rcc|peer)\//, "", name);
        emax = ($7 < 1e-17) ? 1e-17 : $7; ep99 = ($8 < 1e-17) ? 1e-17 : $8;
        printf "\"%s\" %s %s %s\n", name, $5, emax, ep99 }' "$CSV" > "$dat"
    gnuplot <<GP
set terminal pngcairo size 1400,900 noenhanced font ",10"
set output "$OUT-$set.png"
set logscale xy
set format y "%.0e"
set xlabel "median ns/query"
set ylabel "distance error / S (max: filled, p99: open)"
set title "run time against error, $set (tests/data quad-precision references)"
set key outside right
set grid
plot "$dat" using 2:3:1 with labels left offset 0.5,0 font ",7" notitle, \
     "$dat" using 2:3 with points pt 7 ps 1.2 title "max error", \
     "$dat" using 2:4 with points pt 6 ps 1.2 title "p99 error"
GP
    rm -f "$dat"
done
