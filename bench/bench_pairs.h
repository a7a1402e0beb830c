/* prox_bench: the cylinder-pair sets shared by the prox cases and the peers, a uniform "method"
 * wrapper (one answer per pair: distance, signed distance or verdict) and its accuracy against a
 * high-precision reference. */
#ifndef PROX_BENCH_PAIRS_H
#define PROX_BENCH_PAIRS_H

#include "bench.h"

/* A set of cylinder pairs, optionally with a reference signed distance and witness points. */
typedef struct bench_pairs {
    const char *name;
    size_t n;
    prox_rcc *a, *b;
    double *sd_ref;      /* reference signed distance (NULL: no reference) */
    bench_ref *ref;      /* reference witness points (NULL when only sd_ref is known) */
    double *scale;       /* S = max(|cA - cB|, hA, hB, rA, rB) */
    int *family;         /* generator family (stress sets), else NULL */
} bench_pairs;

/* Protocol A of Agarwal Sec. 5 / validation README, n pairs (10^6, --quick 2*10^4), seed 2016. */
const bench_pairs *bench_pairs_agarwal(const bench_opts *o);
/* A validation set read from DIR/NAME.pairs and .ref ("agarwal_public", "stress_public"); NULL if absent. */
const bench_pairs *bench_pairs_valid(const bench_opts *o, const char *name);
/* Near-degenerate pairs of bench/stress_gen.h with their exact constructed distance. */
const bench_pairs *bench_pairs_stressgen(const bench_opts *o);

/* What a method answers. */
typedef enum bench_kind { BENCH_DIST = 0, BENCH_SIGNED, BENCH_VERDICT } bench_kind;

/* One answer: distance (or signed distance) with witness points, or a verdict. */
typedef struct bench_answer {
    int ok;        /* 0: error status or failure */
    int intersect; /* verdict (BENCH_VERDICT; derived from the value for the others) */
    double value;  /* distance (>= 0) or signed distance */
    prox_vec3 p1, p2;
    int has_points;
} bench_answer;

typedef void (*bench_method_fn)(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out);

/* A method under a setting. */
typedef struct bench_method {
    const char *name; /* e.g. "prox/distance", "fcl/gjk-libccd/tol=1e-6" */
    bench_kind kind;
    bench_method_fn run;
    const void *cfg;
} bench_method;

/* Registers the case "<prefix>/<method>/<set><suffix>" timing the method on the pairs (a subset when
 * idx != NULL, copied once to a contiguous array so that scattered reads do not count) and, when the
 * set has a reference, its accuracy on those pairs. */
bench_case *bench_add_method(const char *prefix, const bench_method *m, const bench_pairs *P, const size_t *idx,
                             size_t n, const char *suffix);

/* Registers the method under `prefix` ("rcc", "peer") on every set with a reference: the validation
 * sets agarwal_public and stress_public (when present) and the stress generator. */
void bench_add_on_reference_sets(const bench_opts *o, const char *prefix, const bench_method *m);

/* Accuracy of a method on a set (every pair, or the subset idx). */
bench_accuracy bench_method_accuracy(const bench_method *m, const bench_pairs *P, const size_t *idx, size_t n);

/* The prox cylinder methods the library has, NULL-terminated, in the order distance, SAT verdict,
 * signed distance (bench_methods.c). */
extern const bench_method *const bench_prox_methods[];
#ifdef PROX_BENCH_HAVE_RCC
/* The exact distance alone (prox_rcc_distance), for the per-class cases. */
extern const bench_method bench_prox_distance_method;
#endif

/* The capsule approximation (segment-segment distance minus the radii): the cost floor
 * an exact cylinder distance is compared with. */
extern const bench_method bench_capsule_method;
/* A method without geometry: the cost of the benchmark's harness per query (bench_capsule.c). */
extern const bench_method bench_harness_method;

#endif
