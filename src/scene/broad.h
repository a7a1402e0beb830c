/* Internal (scene): the broad phase of scene queries and the small thread helper the scene stages
 * share. src/scene/broad.c explains the bounding volume hierarchy; docs/PERFORMANCE.md, "Scenes"
 * measures it. */
#ifndef PROX_SCENE_BROAD_H
#define PROX_SCENE_BROAD_H

#include <stddef.h>

#include "prox/scene.h"

/* A candidate pair of body indices, a < b. */
typedef struct prox_broad_pair {
    size_t a, b;
} prox_broad_pair;

/* Every pair i < j of the n boxes (box i at byte offset i * stride from box0) whose boxes come
 * within c >= 0 on all three axes:
 *     lo_j <= hi_i + c  and  lo_i <= hi_j + c   on x, y and z,
 * the test of the sort-and-sweep it replaces, evaluated with the same rounding. The pairs come
 * sorted by (a, b), whatever the thread count. threads >= 1 (see prox_par_threads). Returns 0 with
 * *out malloc'ed (NULL when *nout = 0), or -1 when out of memory (*out NULL, *nout 0). Time
 * O(n log n + k log n) for k pairs with boxes of bounded overlap, memory O(n + k). */
int prox_broad_pairs(const prox_aabb *box0, size_t stride, size_t n, double c, int threads, prox_broad_pair **out,
                     size_t *nout);

/* The thread count a request means: requested > 0 itself (at most PROX_PAR_MAX_THREADS); <= 0 one
 * per processor (OpenMP's default when the library is built with OpenMP). */
#define PROX_PAR_MAX_THREADS 256
int prox_par_threads(int requested);

/* Runs fn(ctx, w) for every worker w < threads, each on its own POSIX thread (worker 0 on the
 * caller's). A worker whose thread cannot be started runs on the caller's thread after worker 0, so
 * the work is always done; workers are meant to take their work from a shared atomic counter. */
typedef void (*prox_par_fn)(void *ctx, int worker);
void prox_par_run(int threads, prox_par_fn fn, void *ctx);

#endif
