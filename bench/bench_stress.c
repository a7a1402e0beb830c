/* prox_bench group "stress": the numerical stress families of bench/stress_gen.h (issue 7 section 2)
 * one by one, for every prox cylinder method, with the error against the constructed exact distance
 * (distance error, witness error, verdict mismatches) and the time per query. `--long` runs 10^5
 * pairs per family (the quick CI-sized version is tests/test_stress.c). */
#include <stdlib.h>
#include <string.h>

#include "bench_pairs.h"
#include "prox/sat.h"
#include "stress_gen.h"

#ifdef PROX_BENCH_HAVE_RCC
static void run_distance(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    (void)cfg;
    prox_rcc_result r = prox_rcc_distance(a, b);
    out->ok = r.status == PROX_OK;
    out->value = r.distance;
    out->intersect = r.interfere;
    out->p1 = r.p1, out->p2 = r.p2;
    out->has_points = 1;
}
#endif
#ifdef PROX_BENCH_HAVE_SAT
static void run_sat(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    (void)cfg;
    prox_sat_result r = prox_rcc_sat(a, b);
    out->ok = r.status == PROX_OK;
    out->intersect = r.intersect;
    out->value = r.value;
    out->has_points = 0;
}
#endif
#ifdef PROX_BENCH_HAVE_SIGNED
static void run_signed(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    (void)cfg;
    prox_signed_result r = prox_rcc_signed_distance(a, b);
    out->ok = r.status == PROX_OK;
    out->value = r.sd;
    out->intersect = r.sd <= 0;
    out->p1 = r.p1, out->p2 = r.p2;
    out->has_points = 1;
}
#endif

static const bench_method k_methods[] = {
#ifdef PROX_BENCH_HAVE_RCC
    {"prox-distance", BENCH_DIST, run_distance, NULL},
#endif
#ifdef PROX_BENCH_HAVE_SAT
    {"prox-sat", BENCH_VERDICT, run_sat, NULL},
#endif
#ifdef PROX_BENCH_HAVE_SIGNED
    {"prox-signed", BENCH_SIGNED, run_signed, NULL},
#endif
    {NULL, BENCH_DIST, NULL, NULL},
};

void bench_group_stress(const bench_opts *o)
{
    if (!bench_selected(o, "stress/")) return;
    const bench_pairs *G = bench_pairs_stressgen(o);
    for (int f = 0; f < SG_NFAMILIES; ++f) {
        size_t *idx = bench_xmalloc(G->n * sizeof *idx), n = 0;
        for (size_t i = 0; i < G->n; ++i)
            if (G->family[i] == f) idx[n++] = i;
        char sfx[64];
        snprintf(sfx, sizeof sfx, "/%s", sg_family_names[f]);
        for (const bench_method *m = k_methods; m->name; ++m) {
            char name[96];
            snprintf(name, sizeof name, "stress/%s/stressgen%s", m->name, sfx);
            if (bench_selected(o, name)) bench_add_method("stress", m, G, idx, n, sfx);
        }
    }
}
