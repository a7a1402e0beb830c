/* Cross-check of the two cylinder methods (issue 4, Sec. 3): the closed-form distance of Agarwal
 * et al. (prox_rcc_distance, rcc_rcc.c) against Eberly's separating axes (prox_rcc_sat) and the
 * support-function signed distance (sup_rcc_signed_support). By duality the distance of a
 * disjoint pair equals max over unit D of the projection gap, so both must give the same number;
 * verdicts may differ only within the tolerance band around touching. */
#include "prox/sat.h"

#include <float.h>

#include "prox/distance.h"
#include "sup_engine.h"

PROX_API prox_crosscheck_result prox_rcc_crosscheck(const prox_rcc *a, const prox_rcc *b)
{
    prox_crosscheck_result r = {0};
    r.status = prox_rcc_validate(a);
    if (r.status == PROX_OK) r.status = prox_rcc_validate(b);
    if (r.status != PROX_OK) return r;
    prox_distance_result d = prox_rcc_distance(a, b);
    prox_test_result s = prox_rcc_sat(a, b);
    prox_signed_result g = sup_rcc_signed_support(a, b); /* not prox_rcc_signed_distance: it uses the distance */
    if (d.status != PROX_OK) { r.status = d.status; return r; }
    if (s.status != PROX_OK) { r.status = s.status; return r; }
    if (g.status != PROX_OK) { r.status = g.status; return r; }
    r.scale = prox_rcc_pair_scale(a, b);
    double M = fmax(prox_v3_maxabs(a->base), prox_v3_maxabs(b->base));
    r.tol = 1e-12 * r.scale + 8.0 * DBL_EPSILON * M;
    r.intersect_distance = d.intersect;
    r.intersect_sat = s.intersect;
    r.distance = d.distance;
    r.sd = g.sd;
    r.sat_value = s.value;
    r.distance_diff = fabs(d.distance - fmax(g.sd, 0.0));
    r.margin = fabs(g.sd) / r.scale;
    r.verdict_agree = r.intersect_distance == r.intersect_sat;
    int touching = fabs(g.sd) <= r.tol;
    /* a separating gap is a lower bound of the distance */
    int gap_ok = s.intersect || s.value <= d.distance + r.tol;
    r.agree = (r.verdict_agree || touching) && r.distance_diff <= r.tol && gap_ok;
    return r;
}
