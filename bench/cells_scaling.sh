#!/usr/bin/env bash
# Time of the cell check (`prox check DECK`) against the number of cells and the resolution, on the
# pin-cell arrays of bench/gen_pins.py (2 N^2 + 1 cells): clean arrays, and arrays with one pin too
# wide (four overlapping cell pairs). Prints one markdown table row per run, with the wall time, CPU
# time and peak memory of the whole command (/usr/bin/time -v) and the check's own summary line.
#
#   bench/cells_scaling.sh BUILD_DIR [N ...]      (default N: 10 30 70 100)
#
# Nothing here is a test: run it by hand on an otherwise idle machine (docs/PERFORMANCE.md).
set -euo pipefail
build=${1:?usage: cells_scaling.sh BUILD_DIR [N ...]}
shift
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(10 30 70 100)
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
field() { grep -F "$1" "$2" | sed 's/.*: //'; }

run() { # run LABEL DECK CELLS [OPTIONS]
    local label=$1 deck=$2 cells=$3
    shift 3
    local status=0
    /usr/bin/time -v "$build/prox" check "$deck" "$@" >"$tmp/out.txt" 2>"$tmp/time.txt" || status=$?
    [ "$status" -le 1 ] || { echo "prox check failed ($status) on $label" >&2; cat "$tmp/out.txt" >&2; exit 1; }
    local cpu
    cpu=$(echo "$(field "User time" "$tmp/time.txt") + $(field "System time" "$tmp/time.txt")" | bc)
    printf "| %s | %s | %s | %s | %s / %.2f | %.0f | %s |\n" "$label" "$cells" "${*:-default}" "$status" \
        "$(field "Elapsed (wall clock)" "$tmp/time.txt")" "$cpu" \
        "$(echo "$(field "Maximum resident set size" "$tmp/time.txt") / 1024" | bc -l)" \
        "$(grep -E "overlapping cell pair|gaps" "$tmp/out.txt" | tail -1)"
}

echo "| model | cells | options | exit | wall / CPU (s) | peak RSS (MB) | summary |"
echo "|---|---:|---|---:|---:|---:|---|"
for n in "${sizes[@]}"; do
    python3 "$here/gen_pins.py" "$n" >"$tmp/clean.i"
    run "${n}x${n} pins, clean" "$tmp/clean.i" $((2 * n * n + 1))
done
n=${sizes[0]}
python3 "$here/gen_pins.py" "$n" >"$tmp/clean.i"
python3 "$here/gen_pins.py" "$n" --wide $((n / 2)) $((n / 2)) >"$tmp/wide.i"
for res in 1e-2 1e-3 1e-4; do
    run "${n}x${n} pins, clean" "$tmp/clean.i" $((2 * n * n + 1)) --resolution "$res"
    run "${n}x${n} pins, one too wide" "$tmp/wide.i" $((2 * n * n + 1)) --resolution "$res"
done
