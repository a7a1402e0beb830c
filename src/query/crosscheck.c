/* Cross-check of two independent cylinder methods on the same pair: the closed-form method (Agarwal
 * et al.'s complete primitive decomposition, src/distance/rcc_closed_form.c) against the support
 * method (certified minimisation of the support-function gap, src/sat), which share only the
 * geometric core, plus the separating-axis verdict (prox_rcc_sat). By duality the distance of a
 * disjoint pair equals the maximum over unit D of the projection gap, so both must give the same
 * number; verdicts may differ only within the tolerance band around touching. */
#include <float.h>

#include "distance/rcc_methods.h"
#include "prox/distance.h"
#include "prox/query.h"
#include "prox/sat.h"
#include "sat/sat_internal.h"

PROX_API prox_crosscheck_result prox_rcc_crosscheck(const prox_rcc *a, const prox_rcc *b)
{
    prox_crosscheck_result r = {0};
    r.status = prox_rcc_validate(a);
    if (r.status == PROX_OK) r.status = prox_rcc_validate(b);
    if (r.status != PROX_OK) return r;
    prox_distance_result d = prox_rcc_closed_form(a, b);
    prox_test_result s = prox_rcc_sat(a, b);
    prox_signed_result g = prox_sat_rcc_signed(a, b);
    if (d.status != PROX_OK) r.status = d.status;
    else if (s.status != PROX_OK) r.status = s.status;
    else if (g.status != PROX_OK) r.status = g.status;
    if (r.status != PROX_OK) return r;
    r.scale = prox_rcc_pair_scale(a, b);
    /* the accuracy promised relative to the scale, plus the rounding of coordinates of size M */
    double M = fmax(prox_v3_maxabs(a->base), prox_v3_maxabs(b->base));
    r.tol = PROX_QUERY_REL_TOL * r.scale + 8.0 * DBL_EPSILON * M;
    r.intersect_distance = d.intersect;
    r.intersect_sat = s.intersect;
    r.distance = d.distance;
    r.sd = g.sd;
    r.sat_value = s.value;
    r.distance_diff = fabs(d.distance - fmax(g.sd, 0.0));
    r.margin = fabs(g.sd) / r.scale;
    r.verdict_agree = r.intersect_distance == r.intersect_sat;
    int touching = fabs(g.sd) <= r.tol;
    int gap_ok = s.intersect || s.value <= d.distance + r.tol; /* a separating gap bounds the distance */
    r.agree = (r.verdict_agree || touching) && r.distance_diff <= r.tol && gap_ok;
    return r;
}
