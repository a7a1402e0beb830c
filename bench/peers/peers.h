/* prox_bench peers (built only with -DPROX_BENCH_PEERS=ON): FCL, Bullet and libccd behind the
 * uniform bench_method interface. Peers are used only by the benchmark, never by the library. */
#ifndef PROX_BENCH_PEERS_H
#define PROX_BENCH_PEERS_H

#ifdef __cplusplus
extern "C" {
#endif

#include "bench_pairs.h"

/* FCL 0.7 distance (GJK with nearest points; libccd and independent solvers, tolerances 1e-2..1e-12). */
int bench_fcl_methods(const bench_method **out);
/* Bullet 3 GJK pair detector with zero margins (distance; EPA penetration depth when overlapping). */
int bench_bullet_methods(const bench_method **out);
/* libccd 2.1 with prox's cylinder support function: GJK and MPR intersection verdicts. */
int bench_ccd_methods(const bench_method **out);

#ifdef __cplusplus
}
#endif

#endif
