#!/usr/bin/env bash
# Scaling of scene checks with the number of bodies (docs/PERFORMANCE.md, "Scenes"): for each n, the
# library alone (prox_bench's scene scaling mode: n RCC/RPP/SPH bodies at constant density, the
# RELATION question of `prox check` at clearance 0 on 1 and 2 threads) and the whole command
# (`prox check DECK --bodies` on a deck from bench/gen_scene.py), each process under /usr/bin/time -v
# for its wall time, CPU time and peak memory. Prints one markdown table row per n.
#
#   bench/scene_scaling.sh BUILD_DIR [N ...]      (default N: 1000 10000 100000 1000000)
#
# BUILD_DIR holds bench/prox_bench and prox (a Release build with PROX_BUILD_BENCH=ON). Decks are
# written to a temporary directory and removed at the end. Nothing here is a test: run it by hand.
set -euo pipefail
build=${1:?usage: scene_scaling.sh BUILD_DIR [N ...]}
shift
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1000 10000 100000 1000000)
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# field NAME FILE: a value of /usr/bin/time -v's report.
field() { grep -F "$1" "$2" | sed 's/.*: //'; }
# note KEY LINE: a key=value of a prox_bench note.
note() { echo "$2" | awk '{print $NF}' | tr ';' '\n' | sed -n "s/^$1=//p" | head -1; }

echo "| bodies | candidates | exact | reported | query t=1 wall / CPU (s) | query t=2 wall (s) | bench peak RSS (MB) | prox check --bodies wall / user+sys (s) | prox check peak RSS (MB) |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for n in "${sizes[@]}"; do
    # (a bench built with the peers may abort at exit, after its table: FCL and Coal each bring Octomap)
    PROX_BENCH_SCENE_N=$n /usr/bin/time -v "$build/bench/prox_bench" --filter scene >"$tmp/bench.txt" 2>"$tmp/bench.time" || true
    r1=$(grep "scene/scale/relation/n=$n/t=1" "$tmp/bench.txt")
    r2=$(grep "scene/scale/relation/n=$n/t=2" "$tmp/bench.txt")
    python3 "$here/gen_scene.py" "$n" >"$tmp/deck.i"
    status=0
    /usr/bin/time -v "$build/prox" check "$tmp/deck.i" --bodies >"$tmp/check.txt" 2>"$tmp/check.time" || status=$?
    [ "$status" -le 1 ] || { echo "prox check failed ($status) at n=$n" >&2; exit 1; }
    wall=$(field "Elapsed (wall clock)" "$tmp/check.time")
    cpu=$(echo "$(field "User time" "$tmp/check.time") + $(field "System time" "$tmp/check.time")" | bc)
    printf "| %s | %s | %s | %s | %.3f / %.3f | %.3f | %.0f | %s / %.2f | %.0f |\n" "$n" \
        "$(note candidates "$r1")" "$(note exact "$r1")" "$(note reported "$r1")" \
        "$(echo "$(note wall_ms "$r1") / 1000" | bc -l)" "$(echo "$(note cpu_ms "$r1") / 1000" | bc -l)" \
        "$(echo "$(note wall_ms "$r2") / 1000" | bc -l)" \
        "$(echo "$(field "Maximum resident" "$tmp/bench.time") / 1024" | bc -l)" \
        "$wall" "$cpu" "$(echo "$(field "Maximum resident" "$tmp/check.time") / 1024" | bc -l)"
done
