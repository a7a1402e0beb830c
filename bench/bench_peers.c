/* prox_bench group "peer": run time against error of the peer libraries on the same pairs as prox:
 * the capsule approximation (always built) and, with -DPROX_BENCH_PEERS=ON,
 * FCL 0.7 (GJK, libccd and independent solvers, distance tolerances 1e-2..1e-12), Bullet 3 (GJK
 * with zero margin, EPA when overlapping) and libccd 2.1 (GJK / MPR verdicts with prox's cylinder
 * support function). Sets with a quad-precision or constructed reference: agarwal_public,
 * stress_public (tests/data) and the bench stress generator; FCL's default setting also
 * on the 10^6 pairs of Agarwal's protocol, the mean-time comparison of docs/PERFORMANCE.md. */
#include "bench_pairs.h"
#ifdef PROX_BENCH_PEERS
#include "peers/peers.h"
#endif

void bench_group_peers(const bench_opts *o)
{
    if (!bench_selected(o, "peer/")) return;
    bench_add_on_reference_sets(o, "peer", &bench_capsule_method);
#ifdef PROX_BENCH_PEERS
    const bench_method *list;
    int n = bench_fcl_methods(&list);
    for (int k = 0; k < n; ++k) bench_add_on_reference_sets(o, "peer", &list[k]);
    if (bench_selected(o, "peer/fcl-gjk-libccd/tol=1e-6/agarwal")) {
        const bench_pairs *P = bench_pairs_agarwal(o);
        bench_add_method("peer", &list[2], P, NULL, P->n, "/all");
    }
    n = bench_bullet_methods(&list);
    for (int k = 0; k < n; ++k) bench_add_on_reference_sets(o, "peer", &list[k]);
    n = bench_ccd_methods(&list);
    for (int k = 0; k < n; ++k) bench_add_on_reference_sets(o, "peer", &list[k]);
#endif
}
