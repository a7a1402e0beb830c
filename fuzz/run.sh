#!/bin/sh
# Builds the libFuzzer harnesses with clang (-fsanitize=fuzzer,address,undefined) and runs each for a
# bounded time on its seed corpus (fuzz/corpus/<name>), e.g. `fuzz/run.sh 30` (seconds per harness,
# default 30). Needs clang and libclang-rt-14-dev (Debian). Crashes are written to
# $BUILD/crashes/<name>/ and make the script exit 1; each one must become a regression test in
# tests/test_fuzz_regress.c.
set -eu
SECONDS_PER=${1:-30}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${PROX_FUZZ_BUILD:-$ROOT/build-fuzz}
CC=${CC:-clang}
mkdir -p "$BUILD"
FLAGS="-std=c17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -ffp-contract=off"
FLAGS="$FLAGS -I$ROOT/include -I$ROOT/src -DPROX_STATIC"
LIBSRC=$(ls "$ROOT"/src/core/*.c "$ROOT"/src/distance/*.c "$ROOT"/src/sat/*.c "$ROOT"/src/scene/*.c 2>/dev/null)
CLISRC=$(ls "$ROOT"/src/cli/*.c | grep -v '/main.c$')
LIBS="-lgsl -lgslcblas -lm"
# shellcheck disable=SC2086
$CC $FLAGS -o "$BUILD/fuzz_queries" "$ROOT/fuzz/fuzz_queries.c" $LIBSRC $LIBS
# shellcheck disable=SC2086
$CC $FLAGS -o "$BUILD/fuzz_deck" "$ROOT/fuzz/fuzz_deck.c" $LIBSRC $LIBS
# shellcheck disable=SC2086
$CC $FLAGS -D_POSIX_C_SOURCE=200809L -o "$BUILD/fuzz_pairs" "$ROOT/fuzz/fuzz_pairs.c" $CLISRC $LIBSRC $LIBS
status=0
for name in queries deck pairs; do
    work="$BUILD/corpus/$name"
    crashes="$BUILD/crashes/$name"
    mkdir -p "$work" "$crashes"
    extra=""
    [ "$name" = pairs ] && extra="-close_fd_mask=3"
    echo "== fuzz_$name for ${SECONDS_PER}s"
    # shellcheck disable=SC2086
    if ! "$BUILD/fuzz_$name" -max_total_time="$SECONDS_PER" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
        -artifact_prefix="$crashes/" -print_final_stats=1 $extra "$work" "$ROOT/fuzz/corpus/$name" \
        > "$BUILD/fuzz_$name.log" 2>&1; then
        echo "fuzz_$name: FAILED (see $BUILD/fuzz_$name.log and $crashes)"
        status=1
    fi
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$BUILD/fuzz_$name.log" || true
done
exit $status
