#!/bin/sh
# Plots, for every pair type of the bench group "mix", the mean ns/query of each method on all pairs
# against its worst signed-distance (or distance) error relative to S:
#     bench/plot_mix.sh OUT MIX.CSV
# writes OUT-<PAIR>.png, e.g. docs/perf/mix-RCC-RCC.png. prox is drawn in one colour, the peers in
# another; verdict-only methods (no error figure) are left out. Errors below 1e-17 are drawn at 1e-17
# (log scale). prox's error is its disagreement with its own support-function method, the peers'
# error their disagreement with prox's exact answer (bench/bench_mix.c). Needs gnuplot (gnuplot-nox).
set -eu
OUT=$1
CSV=$2
for fam in $(awk -F, 'FNR > 1 { split($1, p, "/"); if (!seen[p[2]]++) print p[2] }' "$CSV"); do
    prox=$(mktemp)
    peer=$(mktemp)
    awk -F, -v f="mix/$fam/" -v prox="$prox" -v peer="$peer" '
        FNR > 1 && index($1, f) == 1 && $1 ~ /\/all$/ && $7 != "" && $7 != "nan" {
            name = $1; sub(f, "", name); sub(/\/all$/, "", name);
            out = (name ~ /^prox(-solid)?\//) ? prox : peer;
            emax = ($7 < 1e-17) ? 1e-17 : $7;
            printf "\"%s\" %s %s\n", name, $4, emax > out }' "$CSV"
    gnuplot <<GP
set terminal pngcairo size 1000,650 noenhanced font ",10"
set output "$OUT-$fam.png"
set logscale xy
set yrange [5e-18:5]
set format y "%.0e"
set xlabel "mean ns/query (all pairs)"
set ylabel "worst error / S"
set title "$fam: run time against error (bench group mix)"
set key outside right
set grid
plot "$prox" using 2:3:1 with labels left offset 0.7,0.3 font ",9" tc rgb "#1f4e9c" notitle, \
     "$prox" using 2:3 with points pt 7 ps 1.4 lc rgb "#1f4e9c" title "prox", \
     "$peer" using 2:3:1 with labels left offset 0.7,0.3 font ",9" tc rgb "#b03a2e" notitle, \
     "$peer" using 2:3 with points pt 5 ps 1.2 lc rgb "#b03a2e" title "peers"
GP
    rm -f "$prox" "$peer"
done
