/* Scene benchmark of prox_bench (owned by the scene module, called by bench/bench.c). */
#ifndef PROX_BENCH_SCENE_H
#define PROX_BENCH_SCENE_H

#include <stdio.h>

/* Times scenes of 10^3, 10^4, 10^5 mixed bodies (broad phase + ladder, 1 and 2 threads, against the
 * naive all-pairs count) and the query modes and batch API on one set of pairs. Prints a table to
 * stdout and, when csv is not NULL, rows in prox_bench's CSV layout (figures in the note column). */
void prox_bench_scene(FILE *csv);

#endif
