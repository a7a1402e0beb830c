/* prox_bench group "peer": run time against error of the peer libraries on the same pairs as prox
 * (issue 7 section 1): the capsule approximation (always built) and, with -DPROX_BENCH_PEERS=ON,
 * FCL 0.7 (GJK, libccd and independent solvers, distance tolerances 1e-2..1e-12), Bullet 3 (GJK
 * with zero margin, EPA when overlapping) and libccd 2.1 (GJK / MPR verdicts with prox's cylinder
 * support function). Sets with a quad-precision or constructed reference: agarwal_public,
 * stress_public (../shared/validation) and the bench stress generator; FCL's default setting also
 * on the 10^6 pairs of Agarwal's protocol for the mean-time target of issue 3. */
#include "bench_pairs.h"
#ifdef PROX_BENCH_PEERS
#include "peers/peers.h"
#endif

/* Registers a method on every set with a reference. */
static void add_on_reference_sets(const bench_opts *o, const bench_method *m)
{
    char name[96];
    snprintf(name, sizeof name, "peer/%s/", m->name);
    if (!bench_selected(o, name)) return;
    const char *sets[] = {"agarwal_public", "stress_public"};
    for (int k = 0; k < 2; ++k) {
        const bench_pairs *V = bench_pairs_valid(o, sets[k]);
        if (V) bench_add_method("peer", m, V, NULL, V->n, NULL);
    }
    const bench_pairs *G = bench_pairs_stressgen(o);
    bench_add_method("peer", m, G, NULL, G->n, NULL);
}

void bench_group_peers(const bench_opts *o)
{
    if (!bench_selected(o, "peer/")) return;
    add_on_reference_sets(o, &bench_capsule_method);
#ifdef PROX_BENCH_PEERS
    const bench_method *list;
    int n = bench_fcl_methods(&list);
    for (int k = 0; k < n; ++k) add_on_reference_sets(o, &list[k]);
    if (bench_selected(o, "peer/fcl-gjk-libccd/tol=1e-6/agarwal")) {
        const bench_pairs *P = bench_pairs_agarwal(o);
        bench_add_method("peer", &list[2], P, NULL, P->n, "/all");
    }
    n = bench_bullet_methods(&list);
    for (int k = 0; k < n; ++k) add_on_reference_sets(o, &list[k]);
    n = bench_ccd_methods(&list);
    for (int k = 0; k < n; ++k) add_on_reference_sets(o, &list[k]);
#endif
}
