/* prox_bench: shared declarations of the benchmark program (bench/bench.c runs the table).
 * A case is a named batch of n prepared queries: `one(data, i)` answers query i and returns a
 * double that is folded into a sink so the compiler cannot drop the work. Inputs are seeded and
 * built by the group's setup before any timing. */
#ifndef PROX_BENCH_H
#define PROX_BENCH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "prox/prox.h"

/* One query of a case; returns something derived from the answer. */
typedef double (*bench_query_fn)(const void *data, size_t i);

/* Accuracy figures of a case against a high-precision reference (NaN when not measured). */
typedef struct bench_accuracy {
    double err_max, err_p99, err_median; /* |d - d_ref| / S */
    double wit_max;                      /* worst witness error / S (points off their solid, |p1-p2| != d) */
    long mismatches;                     /* verdict (overlap / apart) disagreements with the reference */
    long failures;                       /* queries that returned an error status or a non-finite value */
} bench_accuracy;

/* A named case of the table. */
typedef struct bench_case {
    char name[96];
    bench_query_fn one;
    const void *data;
    const size_t *idx; /* the subset of query indices to run (NULL: 0..n-1) */
    size_t n;
    char note[160];    /* extra key=value;... written to the CSV (distribution, settings) */
    bench_accuracy acc;
    int has_acc;
} bench_case;

/* Options shared by the setups. */
typedef struct bench_opts {
    int quick;        /* short run */
    int long_stress;  /* the long numerical stress run */
    int repeats;      /* >= 5 */
    const char *filter;
    const char *validation_dir;
    long pairs;       /* Agarwal-protocol pairs (0: 10^6, --quick 2*10^4) */
} bench_opts;

/* Registers a case (copied); returns it so the caller can add a note or accuracy. */
bench_case *bench_add(const char *name, bench_query_fn one, const void *data, const size_t *idx, size_t n);
/* Appends printf-style text to a case's note. */
void bench_note(bench_case *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Setup-time selection: 1 when the group (name ending in '/') or sub-group `name` may hold a case
 * selected by --filter (cases themselves are selected by substring). */
int bench_selected(const bench_opts *o, const char *name);
/* Allocates or exits with a message (bench only: setup code, never timed). */
void *bench_xmalloc(size_t bytes);

/* Seeded RNG (xoshiro256** seeded by splitmix64), the same generator as the validation sets. */
typedef struct bench_rng {
    uint64_t s[4];
} bench_rng;
bench_rng bench_rng_seed(uint64_t seed);
uint64_t bench_rng_next(bench_rng *r);
/* Uniform in [0, 1). */
double bench_uniform(bench_rng *r);
/* Uniform in [lo, hi). */
double bench_range(bench_rng *r, double lo, double hi);
/* Log-uniform in [lo, hi] (lo > 0). */
double bench_logrange(bench_rng *r, double lo, double hi);
/* Uniform unit vector. */
prox_vec3 bench_unit(bench_rng *r);
/* Uniformly random rotation applied to v (Shoemake's quaternion). */
typedef struct bench_rot {
    double m[3][3];
} bench_rot;
bench_rot bench_random_rot(bench_rng *r);
prox_vec3 bench_rot_apply(const bench_rot *R, prox_vec3 v);

/* Reads a 14-number pair file (validation format); returns the count, arrays allocated. */
size_t bench_read_pairs(const char *path, prox_rcc **a, prox_rcc **b);
/* Reads the matching .ref file: sd p1 p2 per line. */
typedef struct bench_ref {
    double sd;
    prox_vec3 p1, p2;
} bench_ref;
size_t bench_read_refs(const char *path, bench_ref **out);

/* Order statistics of an array (sorted in place): q in [0,1]. */
double bench_quantile(double *v, size_t n, double q);

/* Case groups (each file registers its cases when selected). */
void bench_group_poly(const bench_opts *o);
void bench_group_prim(const bench_opts *o);
void bench_group_rcc(const bench_opts *o);
void bench_group_peers(const bench_opts *o);
void bench_group_stress(const bench_opts *o);
void bench_group_query(const bench_opts *o);
/* --agarwal-cases: shares of Agarwal's cases under several definitions (bench_agarwal_cases.c). */
void bench_agarwal_case_study(const bench_opts *o);

#endif
