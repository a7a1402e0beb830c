/* Scene benchmark (docs/scene.md): wall time of scene queries on 10^3, 10^4, 10^5 mixed bodies at a
 * fixed density (mean spacing 4 x the typical body size), candidate pairs from the broad phase
 * (src/scene/broad.c) and exact queries run against the naive all-pairs count, on 1 and 2 threads;
 * then the cost of each query mode and of the batch API on one seeded set of pairs. Inputs are built
 * before timing; each figure is the median of 3 runs.
 *
 * Scaling mode (docs/PERFORMANCE.md, "Scenes"): with PROX_BENCH_SCENE_N=n in the environment the group
 * runs only the question of `prox check` (RELATION at clearance 0) on n RCC/RPP/SPH bodies at the
 * same density, once on 1 and once on 2 threads, so that /usr/bin/time -v of the process gives the
 * peak memory of one size: PROX_BENCH_SCENE_N=1000000 /usr/bin/time -v prox_bench --filter scene */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_scene.h"
#include "prox/scene.h"

/* Seeded generator (splitmix64): the scene bench needs no more. */
static double bs_uniform(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}
static double bs_range(uint64_t *s, double lo, double hi) { return lo + (hi - lo) * bs_uniform(s); }
static prox_vec3 bs_unit(uint64_t *s)
{
    for (;;) {
        prox_vec3 v = prox_v3(bs_range(s, -1, 1), bs_range(s, -1, 1), bs_range(s, -1, 1));
        double n = prox_v3_norm(v);
        if (n > 1e-3 && n <= 1) return prox_v3_scale(v, 1 / n);
    }
}

/* A random body of one of the four kinds around c (sizes 0.2 .. 3). */
static prox_shape bs_body(uint64_t *s, prox_vec3 c)
{
    int kind = (int)(bs_uniform(s) * 4);
    if (kind == 0) return prox_shape_from_sph((prox_sph){c, bs_range(s, 0.2, 1.0)});
    if (kind == 1) {
        prox_vec3 ax = prox_v3_scale(bs_unit(s), bs_range(s, 0.5, 3.0));
        return prox_shape_from_rcc((prox_rcc){prox_v3_mad(c, -0.5, ax), ax, bs_range(s, 0.2, 1.0)});
    }
    if (kind == 2) {
        prox_vec3 u = bs_unit(s), v = prox_v3_any_perp(u), w = prox_v3_cross(u, v);
        prox_box b = {c, {prox_v3_scale(u, bs_range(s, 0.5, 2)), prox_v3_scale(v, bs_range(s, 0.5, 2)),
                          prox_v3_scale(w, bs_range(s, 0.5, 2))}};
        return prox_shape_from_box(b);
    }
    double h = bs_range(s, 0.2, 1);
    return prox_shape_from_rpp((prox_rpp){c.x - h, c.x + h, c.y - h, c.y + 0.5 * h, c.z - h, c.z + 2 * h});
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One output row: table line and CSV row in prox_bench's layout. */
static void bs_row(FILE *csv, const char *name, size_t n, double ns_total, double ns_per, const char *note)
{
    printf("%-46s %9zu %10.1f %10.1f %10s %9s %9s %9s %5s  %s\n", name, n, ns_per, ns_per, "", "", "", "", "", note);
    fflush(stdout);
    if (csv) fprintf(csv, "%s,%zu,3,%.2f,%.2f,,,,,,,,\"total_ns=%.0f;%s\"\n", name, n, ns_per, ns_per, ns_total, note);
}

/* Times one scene question (median of 3) and prints its counters. */
static void bs_scene_case(FILE *csv, prox_scene *sc, size_t n, const char *what, double c, prox_query_mode mode,
                          int threads, int naive)
{
    double t[3];
    prox_scene_report rep = {0};
    prox_scene_set_threads(sc, threads);
    for (int k = 0; k < 3; ++k) {
        prox_scene_report_free(&rep);
        double t0 = now_s();
        rep = naive ? prox_scene_pairs_naive(sc, c, mode) : prox_scene_pairs(sc, c, mode);
        t[k] = now_s() - t0;
    }
    qsort(t, 3, sizeof t[0], cmp_double);
    char name[96], note[256];
    snprintf(name, sizeof name, "scene/%s/%s/n=%zu/t=%d", what, naive ? "naive" : "broad", n, threads);
    snprintf(note, sizeof note,
             "wall_ms=%.2f;naive_pairs=%zu;candidates=%zu;bound=%zu;support=%zu;tests=%zu;exact=%zu;reported=%zu;status=%d",
             1e3 * t[1], rep.stats.naive_pairs, rep.stats.candidates, rep.stats.bound_rejects, rep.stats.support_decided,
             rep.stats.tests, rep.stats.exact, rep.stats.reported, (int)rep.status);
    bs_row(csv, name, n, 1e9 * t[1], 1e9 * t[1] / (double)n, note);
    prox_scene_report_free(&rep);
}

/* Scenes of n bodies at constant density. */
static void bs_scenes(FILE *csv)
{
    const size_t sizes[3] = {1000, 10000, 100000};
    for (int k = 0; k < 3; ++k) {
        size_t n = sizes[k];
        uint64_t seed = 42 + n;
        double L = 4.0 * cbrt((double)n);
        prox_scene *sc = prox_scene_create();
        for (size_t i = 0; i < n && sc; ++i) {
            prox_shape b = bs_body(&seed, prox_v3(bs_range(&seed, 0, L), bs_range(&seed, 0, L), bs_range(&seed, 0, L)));
            prox_scene_add(sc, &b);
        }
        if (!sc) return;
        for (int threads = 1; threads <= 2; ++threads) {
            bs_scene_case(csv, sc, n, "intersecting", 0.0, PROX_MODE_VERDICT, threads, 0);
            bs_scene_case(csv, sc, n, "within1", 1.0, PROX_MODE_CLOSER, threads, 0);
            bs_scene_case(csv, sc, n, "relation", 0.0, PROX_MODE_RELATION, threads, 0);
        }
        if (n <= 1000) bs_scene_case(csv, sc, n, "intersecting", 0.0, PROX_MODE_VERDICT, 1, 1);
        double t0 = now_s();
        prox_scene_report r = prox_scene_nearest(sc);
        char note[200];
        snprintf(note, sizeof note, "wall_ms=%.2f;candidates=%zu;exact=%zu;distance=%.6g", 1e3 * (now_s() - t0),
                 r.stats.candidates, r.stats.exact, r.npairs ? r.pairs[0].r.distance : -1.0);
        char name[96];
        snprintf(name, sizeof name, "scene/nearest/broad/n=%zu/t=1", n);
        bs_row(csv, name, n, 0, 0, note);
        prox_scene_report_free(&r);
        prox_scene_destroy(sc);
    }
}

/* Every mode and the batch API on the same pairs (centres 0 .. 5 apart: about half overlap). */
static void bs_modes(FILE *csv)
{
    enum { N = 20000 };
    prox_shape *a = malloc(N * sizeof *a), *b = malloc(N * sizeof *b);
    prox_pair_result *out = malloc(N * sizeof *out);
    if (!a || !b || !out) goto done;
    uint64_t seed = 7;
    for (size_t i = 0; i < N; ++i) {
        a[i] = bs_body(&seed, prox_v3(0, 0, 0));
        b[i] = bs_body(&seed, prox_v3_scale(bs_unit(&seed), bs_range(&seed, 0, 5)));
    }
    static const char *names[] = {"verdict", "closer0.5", "distance", "points", "signed", "relation"};
    int maxt = prox_batch_has_openmp() ? 2 : 1;
    for (int mode = PROX_MODE_VERDICT; mode <= PROX_MODE_RELATION; ++mode)
        for (int threads = 1; threads <= maxt; ++threads) {
            double t[3];
            for (int k = 0; k < 3; ++k) {
                double t0 = now_s();
                prox_batch_query(a, b, N, (prox_query_mode)mode, mode == PROX_MODE_VERDICT ? 0.0 : 0.5, threads, out);
                t[k] = now_s() - t0;
            }
            qsort(t, 3, sizeof t[0], cmp_double);
            size_t rung[5] = {0};
            for (size_t i = 0; i < N; ++i) rung[out[i].decided_by]++;
            char name[96], note[200];
            snprintf(name, sizeof name, "scene/mode/%s/batch/t=%d", names[mode], threads);
            snprintf(note, sizeof note, "pairs_per_s=%.3g;bound=%zu;support=%zu;tests=%zu;exact=%zu", N / t[1], rung[1],
                     rung[2], rung[3], rung[4]);
            bs_row(csv, name, N, 1e9 * t[1], 1e9 * t[1] / N, note);
        }
done:
    free(a), free(b), free(out);
}

/* A random RCC, RPP or SPH around c, sizes as bench/gen_scene.py draws them. */
static prox_shape bs_body3(uint64_t *s, prox_vec3 c)
{
    int kind = (int)(bs_uniform(s) * 3);
    if (kind == 0) return prox_shape_from_sph((prox_sph){c, bs_range(s, 0.2, 1.0)});
    if (kind == 1) {
        prox_vec3 ax = prox_v3_scale(bs_unit(s), bs_range(s, 0.5, 3.0));
        return prox_shape_from_rcc((prox_rcc){prox_v3_mad(c, -0.5, ax), ax, bs_range(s, 0.2, 1.0)});
    }
    double h[3] = {bs_range(s, 0.2, 1), bs_range(s, 0.2, 1), bs_range(s, 0.2, 1)};
    return prox_shape_from_rpp((prox_rpp){c.x - h[0], c.x + h[0], c.y - h[1], c.y + h[1], c.z - h[2], c.z + h[2]});
}

/* Process CPU time (both threads' time adds up). */
static double cpu_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The scaling mode: one scene of n bodies, the question of `prox check`, on 1 and 2 threads. */
static void bs_scale(FILE *csv, size_t n)
{
    uint64_t seed = 1000 + n;
    double L = 4.0 * cbrt((double)n), t0 = now_s();
    prox_scene *sc = prox_scene_create();
    for (size_t i = 0; i < n && sc; ++i) {
        prox_shape b = bs_body3(&seed, prox_v3(bs_range(&seed, 0, L), bs_range(&seed, 0, L), bs_range(&seed, 0, L)));
        if (prox_scene_add(sc, &b) != PROX_OK) break;
    }
    if (!sc) return;
    double build = now_s() - t0;
    for (int threads = 1; threads <= 2; ++threads) {
        prox_scene_set_threads(sc, threads);
        double w0 = now_s(), c0 = cpu_s();
        prox_scene_report rep = prox_scene_pairs(sc, 0.0, PROX_MODE_RELATION);
        double wall = now_s() - w0, cpu = cpu_s() - c0;
        char name[96], note[320];
        snprintf(name, sizeof name, "scene/scale/relation/n=%zu/t=%d", n, threads);
        snprintf(note, sizeof note,
                 "wall_ms=%.1f;cpu_ms=%.1f;add_ms=%.1f;candidates=%zu;bound=%zu;support=%zu;exact=%zu;reported=%zu;status=%d",
                 1e3 * wall, 1e3 * cpu, 1e3 * build, rep.stats.candidates, rep.stats.bound_rejects,
                 rep.stats.support_decided, rep.stats.exact, rep.stats.reported, (int)rep.status);
        bs_row(csv, name, n, 1e9 * wall, 1e9 * wall / (double)n, note);
        prox_scene_report_free(&rep);
    }
    prox_scene_destroy(sc);
}

void prox_bench_scene(FILE *csv)
{
    const char *scale = getenv("PROX_BENCH_SCENE_N");
    if (scale && *scale) {
        long long n = atoll(scale);
        if (n > 0) bs_scale(csv, (size_t)n);
        return;
    }
    bs_modes(csv);
    bs_scenes(csv);
}
