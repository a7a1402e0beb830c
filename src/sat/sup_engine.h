/* Internal: the support-function engine shared by the signed distance of any two macrobodies, the
 * support method's cylinder distance and the penetration depth. A shape is a core prox_body
 * (core/body.h): its centre c plus a centred support function hc(d) = h(d) - d.c with
 * hc(-d) = hc(d). For a pair, phi(D) = h_A(D) + h_B(-D) = hcA(D) + hcB(D) - D.Delta, Delta = cB - cA,
 * and sd = -min_{|D|=1} phi. */
#ifndef PROX_SAT_SUP_ENGINE_H
#define PROX_SAT_SUP_ENGINE_H

#include "core/body.h"
#include "prox/result.h"

#include <stddef.h>

/* Witness points for the minimising unit direction n and signed distance sd: p1 in the support set
 * of a in n, p2 in that of b in -n. Disjoint pairs (sd > 0): the closest pair of the two support sets
 * (points, segments, disks, rectangles), solved exactly in the plane perpendicular to n, then
 * polished by exact projections onto the bodies; p1 in A, p2 in B always. Overlapping pairs: p2 - p1
 * as close to sd n as the sets allow. */
void sup_witnesses(const prox_body *a, const prox_body *b, prox_vec3 n, double sd, prox_vec3 *p1, prox_vec3 *p2);

/* Penetration depth of two overlapping cylinders (both PROX_BODY_CYL) by enumerating the stationary
 * directions of each stratum (docs/algorithms/sat.md, "fast depth"); 1 and *res filled when every
 * stratum was either solved exactly or excluded by a lower bound, 0 when the caller must fall back
 * to the global search; a negative prox_status when a circle solver failed. *res always holds the
 * best direction found (a valid upper bound). */
int sup_rcc_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res);

/* Signed distance of two bodies (see the file comment); status is always PROX_OK. hint (may be
 * NULL): a direction to try first, e.g. a separating direction from the SAT. */
prox_signed_result sup_signed_distance(const prox_body *a, const prox_body *b, const prox_vec3 *hint);

#endif
