#!/bin/sh
# Builds the fuzz harnesses with clang and ASan + UBSan, two drivers each, and runs them.
#
# `fuzz/run.sh [SECONDS]`: libFuzzer (-fsanitize=fuzzer), coverage-guided, for a bounded time per
# harness (default 30 s) on its seed corpus (fuzz/corpus/<name>). Its input sequence depends on the
# machine even at a fixed -seed (coverage differs where floating-point results do), so it explores;
# it does not reproduce. A fault writes the input to $BUILD/crashes/<name>/, prints the broken contract
# (the input replayed with the harness's output) and the input in base64, and makes the script exit 1.
#
# `fuzz/run.sh --stress`: the reproducible driver (fuzz/stress.c): PROX_FUZZ_RUNS inputs per harness
# (defaults below), mutated from the seed corpus by a fixed generator from PROX_FUZZ_SEED (default 1),
# the same inputs on every machine; first it replays every crash file kept in fuzz/crashes/. CI gates
# on this mode.
#
# Each fault must become a regression test in tests/test_fuzz_regress.c, its crash file kept in
# fuzz/crashes/ with a row in fuzz/crashes/README.md. Debian packages: clang (clang-14),
# libclang-rt-14-dev (the fuzzer and sanitizer runtimes), libgsl-dev. The library sources are compiled
# once (JOBS in parallel, default 2). PROX_FUZZ_ONLY="queries pairs" runs only the named harnesses.
set -eu
MODE=fuzz
[ "${1:-}" = --stress ] && MODE=stress && shift
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
# PROX_FUZZ_REUSE=1 keeps binaries already built in $BUILD (the same sources, built by an earlier run).
if [ "${PROX_FUZZ_REUSE:-}" != 1 ] || [ ! -x "$BUILD/stress_pairs" ] || [ ! -x "$BUILD/fuzz_pairs" ]; then
    # One object per source (-fsanitize=fuzzer on a non-main object only instruments it), in parallel.
    rm -f "$BUILD"/obj/*.o
    # shellcheck disable=SC2086
    printf '%s\n' $LIBSRC $CLISRC | xargs -P "$JOBS" -I{} sh -c \
        'f={}; d=$(basename "$(dirname "$f")"); exec '"$CC $FLAGS"' -c "$f" -o "'"$BUILD"'/obj/${d}_$(basename "$f" .c).o"'
    LIBOBJ=$(ls "$BUILD"/obj/*.o | grep -v '/obj/cli_')
    CLIOBJ=$(ls "$BUILD"/obj/cli_*.o)
    # The stress driver has its own main: the same objects, without libFuzzer's runtime.
    SFLAGS=$(echo "$FLAGS" | sed 's/-fsanitize=fuzzer,/-fsanitize=fuzzer-no-link,/')
    for name in queries deck pairs; do
        extra=""
        [ "$name" = pairs ] && extra="$CLIOBJ"
        # shellcheck disable=SC2086
        $CC $FLAGS -o "$BUILD/fuzz_$name" "$ROOT/fuzz/fuzz_$name.c" $extra $LIBOBJ $LIBS
        # shellcheck disable=SC2086
        $CC $SFLAGS -o "$BUILD/stress_$name" "$ROOT/fuzz/stress.c" "$ROOT/fuzz/fuzz_$name.c" $extra $LIBOBJ $LIBS
    done
fi
t1=$(date +%s)
echo "build: $((t1 - t0)) s"
status=0
if [ "$MODE" = stress ]; then
    for name in ${PROX_FUZZ_ONLY:-queries deck pairs}; do
        crashes="$BUILD/crashes/$name"
        mkdir -p "$crashes"
        kept=$(ls "$ROOT"/fuzz/crashes/"$name"-* 2>/dev/null || true)
        if [ -n "$kept" ]; then
            # shellcheck disable=SC2086
            if "$BUILD/stress_$name" $kept > "$BUILD/replay_$name.log" 2>&1; then
                echo "stress_$name: $(echo "$kept" | wc -l) kept crash files replayed, no fault"
            else
                echo "stress_$name: a kept crash file faults:"; tail -5 "$BUILD/replay_$name.log"; status=1
            fi
        fi
        case $name in pairs) runs=150000 ;; *) runs=200000 ;; esac
        runs=${PROX_FUZZ_RUNS:-$runs}
        echo "== stress_$name: $runs inputs from seed ${PROX_FUZZ_SEED:-1}"
        if ! "$BUILD/stress_$name" "$ROOT/fuzz/corpus/$name" "$runs" "${PROX_FUZZ_SEED:-1}" "$crashes" \
            > "$BUILD/stress_$name.log" 2>&1; then
            cat "$BUILD/stress_$name.log"
            for f in "$crashes"/stress-*; do
                [ -f "$f" ] || continue
                echo "-- $f replayed:"; "$BUILD/stress_$name" "$f" 2>&1 | grep -v '^stress: replaying' | tail -8
                echo "-- base64:"; base64 -w 0 "$f"; echo
            done
            status=1
        else
            cat "$BUILD/stress_$name.log"
        fi
    done
    echo "run: $(($(date +%s) - t1)) s"
    exit $status
fi
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
        for f in "$crashes"/crash-* "$crashes"/timeout-* "$crashes"/leak-* "$crashes"/oom-*; do
            [ -f "$f" ] || continue
            echo "-- $f replayed:"; "$BUILD/stress_$name" "$f" 2>&1 | grep -E "contract broken|ERROR|SUMMARY|runtime error" | head -4
            echo "-- base64:"; base64 -w 0 "$f"; echo
        done
        status=1
    fi
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$BUILD/fuzz_$name.log" || true
done
echo "run: $(($(date +%s) - t1)) s"
exit $status
