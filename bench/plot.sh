#!/bin/sh
# Plots median ns/query against the worst (and p99) distance error relative to S, per method and
# setting, from one or more prox_bench CSVs:
#     bench/plot.sh OUT CSV [CSV ...]
# e.g. bench/plot.sh docs/perf/runtime-vs-error docs/perf/bench.csv docs/perf/bench-stress.csv
# writes OUT-agarwal_public.png and OUT-stress_public.png. prox's methods (rcc/...) are drawn in
# one colour, the peers (peer/...) in another; a row that appears in several CSVs is plotted from
# the first. Errors below 1e-17 are drawn at 1e-17 (log scale). Needs gnuplot (gnuplot-nox).
set -eu
OUT=$1
shift
for set in agarwal_public stress_public; do
    prox=$(mktemp)
    peer=$(mktemp)
    # case,n,repeats,mean,median,p99,err_max,err_p99,... ; keep rows of this set with an error
    # figure (verdict-only methods have none)
    awk -F, -v s="/$set" -v prox="$prox" -v peer="$peer" '
        FNR > 1 && index($1, s) && $7 != "" && $7 != "nan" && !seen[$1]++ {
            name = $1; sub(s, "", name);
            out = (name ~ /^rcc\//) ? prox : peer;
            sub(/^(rcc|peer)\//, "", name);
            emax = ($7 < 1e-17) ? 1e-17 : $7; ep99 = ($8 < 1e-17) ? 1e-17 : $8;
            printf "\"%s\" %s %s %s\n", name, $5, emax, ep99 > out }' "$@"
    if [ ! -s "$prox" ] && [ ! -s "$peer" ]; then
        echo "plot.sh: no rows of $set with an error figure" >&2
        rm -f "$prox" "$peer"
        continue
    fi
    gnuplot <<GP
set terminal pngcairo size 1400,900 noenhanced font ",10"
set output "$OUT-$set.png"
set logscale xy
set yrange [5e-18:5]
set format y "%.0e"
set xlabel "median ns/query"
set ylabel "distance error / S (max: filled, p99: open)"
set title "run time against error, $set (tests/data quad-precision references)"
set key outside right
set grid
plot "$prox" using 2:3:1 with labels left offset 0.7,0.3 font ",8" tc rgb "#1f4e9c" notitle, \
     "$prox" using 2:3 with points pt 7 ps 1.4 lc rgb "#1f4e9c" title "prox, max error", \
     "$prox" using 2:4 with points pt 6 ps 1.4 lc rgb "#1f4e9c" title "prox, p99 error", \
     "$peer" using 2:3:1 with labels left offset 0.7,0.3 font ",7" tc rgb "#b03a2e" notitle, \
     "$peer" using 2:3 with points pt 5 ps 1.1 lc rgb "#b03a2e" title "peers, max error", \
     "$peer" using 2:4 with points pt 4 ps 1.1 lc rgb "#b03a2e" title "peers, p99 error"
GP
    rm -f "$prox" "$peer"
done
