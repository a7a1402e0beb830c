/* Internal (core): the minimum over the disk |x| <= r of a convex piecewise-linear function of two
 * variables, M(x) = max_j a_j + b_j . x (nj <= 8 planes, inputs not NaN). The support-function depth
 * (src/sat/convex.c) bounds phi over a cap of directions by it: phi(D) >= max_j g_j . D for support
 * points g_j, written in the cap's tangent plane. */
#ifndef PROX_CORE_PL_DISK_H
#define PROX_CORE_PL_DISK_H

#include "core/plane2.h"

/* Exact minimum of M over the disk (to rounding). */
double prox_pl_disk_min(const double *a, const prox_v2 *b, int nj, double r);

/* 1 when M >= t at every point of the disk (to rounding); the same answer as
 * prox_pl_disk_min(...) >= t, cheaper. */
int prox_pl_disk_above(const double *a, const prox_v2 *b, int nj, double r, double t);

#endif
