/* prox_bench group "stress": the numerical stress families of bench/stress_gen.h
 * one by one, for every prox cylinder method, with the error against the constructed exact distance
 * (distance error, witness error, verdict mismatches) and the time per query. `--long` runs 10^5
 * pairs per family (the quick CI-sized version is tests/test_stress.c). */
#include <stdlib.h>
#include <string.h>

#include "bench_pairs.h"
#include "stress_gen.h"

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
        for (const bench_method *const *m = bench_prox_methods; *m; ++m) {
            char name[96];
            snprintf(name, sizeof name, "stress/%s/stressgen%s", (*m)->name, sfx);
            if (bench_selected(o, name)) bench_add_method("stress", *m, G, idx, n, sfx);
        }
    }
}
