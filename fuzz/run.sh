#!/bin/sh
# Builds the libFuzzer harnesses with clang (-fsanitize=fuzzer,address,undefined) and runs each for a
# bounded time on its seed corpus (fuzz/corpus/<name>), e.g. `fuzz/run.sh 30` (seconds per harness,
# default 30). Debian packages: clang (clang-14), libclang-rt-14-dev (the fuzzer and sanitizer
# runtimes), libgsl-dev. The library sources are compiled once (JOBS in parallel, default 2) and
# linked into the three harnesses. Crashes are written to $BUILD/crashes/<name>/ and make the script
# exit 1; each one must become a regression test in tests/test_fuzz_regress.c (crash files kept for
# the record are in fuzz/crashes/). Prints the build and run times.
# Reproducible runs (CI): PROX_FUZZ_SEED=S fixes libFuzzer's seed and PROX_FUZZ_RUNS=N stops each
# harness after N inputs (the seconds then only cap the time), so the same inputs are tried every run.
# PROX_FUZZ_ONLY="queries pairs" runs only the named harnesses (all three are still built).
set -eu
SECONDS_PER=${1:-30}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${PROX_FUZZ_BUILD:-$ROOT/build-fuzz}
CC=${CC:-clang}
JOBS=${JOBS:-2}
command -v "$CC" > /dev/null || { echo "fuzz/run.sh: $CC not found (apt-get install clang libclang-rt-14-dev)"; exit 2; }
mkdir -p "$BUILD/obj"
FLAGS="-std=c17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -ffp-contract=off"
FLAGS="$FLAGS -I$ROOT/include -I$ROOT/src -DPROX_STATIC -D_POSIX_C_SOURCE=200809L"
LIBSRC=$(ls "$ROOT"/src/*/*.c | grep -v '/src/cli/')
CLISRC=$(ls "$ROOT"/src/cli/*.c | grep -v '/main.c$')
LIBS="-lgsl -lgslcblas -lm"
t0=$(date +%s)
# One object per source (-fsanitize=fuzzer on a non-main object only instruments it), in parallel.
rm -f "$BUILD"/obj/*.o
# shellcheck disable=SC2086
printf '%s\n' $LIBSRC $CLISRC | xargs -P "$JOBS" -I{} sh -c \
    'f={}; d=$(basename "$(dirname "$f")"); exec '"$CC $FLAGS"' -c "$f" -o "'"$BUILD"'/obj/${d}_$(basename "$f" .c).o"'
LIBOBJ=$(ls "$BUILD"/obj/*.o | grep -v '/obj/cli_')
CLIOBJ=$(ls "$BUILD"/obj/cli_*.o)
# shellcheck disable=SC2086
$CC $FLAGS -o "$BUILD/fuzz_queries" "$ROOT/fuzz/fuzz_queries.c" $LIBOBJ $LIBS
# shellcheck disable=SC2086
$CC $FLAGS -o "$BUILD/fuzz_deck" "$ROOT/fuzz/fuzz_deck.c" $LIBOBJ $LIBS
# shellcheck disable=SC2086
$CC $FLAGS -o "$BUILD/fuzz_pairs" "$ROOT/fuzz/fuzz_pairs.c" $CLIOBJ $LIBOBJ $LIBS
t1=$(date +%s)
echo "build: $((t1 - t0)) s"
status=0
for name in ${PROX_FUZZ_ONLY:-queries deck pairs}; do
    work="$BUILD/corpus/$name"
    crashes="$BUILD/crashes/$name"
    mkdir -p "$work" "$crashes"
    extra=""
    [ "$name" = pairs ] && extra="-close_fd_mask=3"
    [ -n "${PROX_FUZZ_SEED:-}" ] && extra="$extra -seed=$PROX_FUZZ_SEED"
    [ -n "${PROX_FUZZ_RUNS:-}" ] && extra="$extra -runs=$PROX_FUZZ_RUNS"
    echo "== fuzz_$name for ${SECONDS_PER}s"
    # shellcheck disable=SC2086
    if ! "$BUILD/fuzz_$name" -max_total_time="$SECONDS_PER" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
        -artifact_prefix="$crashes/" -print_final_stats=1 $extra "$work" "$ROOT/fuzz/corpus/$name" \
        > "$BUILD/fuzz_$name.log" 2>&1; then
        echo "fuzz_$name: FAILED (see $BUILD/fuzz_$name.log and $crashes)"
        grep -E "contract broken|ERROR:|SUMMARY:" "$BUILD/fuzz_$name.log" | head -3 || true
        status=1
    fi
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$BUILD/fuzz_$name.log" || true
done
echo "run: $(($(date +%s) - t1)) s"
exit $status
