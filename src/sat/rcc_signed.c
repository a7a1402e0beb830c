/* Signed distance of two solid cylinders (issue 4, Sec. 2).
 *
 * Disjoint pairs: the closed-form distance of Agarwal et al. (prox_rcc_distance, certified by
 * duality) is the exact answer: sd = distance, p1, p2 its proximal points, normal (p2 - p1) / sd.
 * Overlapping pairs: penetration depth = min over unit D of h_A(D) + h_B(-D) (h from Eberly's
 * Eq. (4)), minimised by enumerating the stationary directions of each stratum (rcc_depth.c), or
 * by the global search of the support-function engine (sup_engine.c) when a stratum cannot be
 * settled; sd = -depth.
 * sup_rcc_signed_support is the support-function method alone for both signs (SAT direction as a
 * start): the independent second method of the cross-check. */
#include "prox/sat.h"

#include "prox/distance.h"
#include "sup_engine.h"

prox_signed_result sup_rcc_signed_support(const prox_rcc *a, const prox_rcc *b)
{
    prox_signed_result r = {0};
    /* the SAT validates both and gives a separating direction: the start of the local search */
    prox_test_result s = prox_rcc_sat(a, b);
    if (s.status != PROX_OK) { r.status = s.status; return r; }
    prox_shape sa = prox_shape_from_rcc(*a), sb = prox_shape_from_rcc(*b);
    sup_body ba = sup_body_make(&sa), bb = sup_body_make(&sb);
    return sup_signed_distance(&ba, &bb, s.intersect ? NULL : &s.direction);
}

PROX_API prox_signed_result prox_rcc_signed_distance(const prox_rcc *a, const prox_rcc *b)
{
    prox_signed_result r = {0};
    prox_distance_result d = prox_rcc_distance(a, b); /* validates both */
    if (d.status != PROX_OK) { r.status = d.status; return r; }
    if (!d.intersect && d.distance > 0.0) {
        r.status = PROX_OK;
        r.sd = d.distance;
        r.p1 = d.p1;
        r.p2 = d.p2;
        /* (p2 - p1) / |p2 - p1| is the normal: it makes p2 - p1 = sd n hold to the points' rounding.
         * Its direction carries that rounding, eps |p| / distance, so very near touching it is only a
         * valid supporting direction to that accuracy. When the points coincide (a distance below
         * their resolution) the SAT's separating direction is used. */
        prox_vec3 e = prox_v3_sub(d.p2, d.p1);
        double en = prox_v3_norm(e);
        if (en > 0.0) {
            r.normal = prox_v3_scale(e, 1.0 / en);
            return r;
        }
        prox_test_result s = prox_rcc_sat(a, b);
        r.normal = s.intersect ? prox_v3(0, 0, 1) : s.direction;
        return r;
    }
    prox_shape sa = prox_shape_from_rcc(*a), sb = prox_shape_from_rcc(*b);
    sup_body ba = sup_body_make(&sa), bb = sup_body_make(&sb);
    /* overlapping: enumeration of the strata (rcc_depth.c); the global search when it cannot settle */
    if (sup_rcc_depth_enum(&ba, &bb, &r)) return r;
    return sup_signed_distance(&ba, &bb, NULL);
}
