/* Signed distance of two solid cylinders, composed from the two modules: the exact distance of the
 * fast method (prox_rcc_distance, certified by duality) when the solids are disjoint, the penetration
 * depth of the support method (min over unit D of h_A(D) + h_B(-D), Eberly's Eq. (4) support
 * functions: prox_sat_rcc_depth) when they overlap. */
#include "prox/distance.h"
#include "prox/sat.h"
#include "sat/sat_internal.h"

PROX_API prox_signed_result prox_rcc_signed_distance(const prox_rcc *a, const prox_rcc *b)
{
    prox_signed_result r = {0};
    prox_distance_result d = prox_rcc_distance(a, b); /* validates both */
    if (d.status != PROX_OK) {
        r.status = d.status;
        return r;
    }
    if (d.intersect || !(d.distance > 0.0)) return prox_sat_rcc_depth(a, b);
    r.status = PROX_OK;
    r.sd = d.distance;
    r.p1 = d.p1;
    r.p2 = d.p2;
    /* (p2 - p1) / |p2 - p1| is the normal: it makes p2 - p1 = sd n hold to the points' rounding. Its
     * direction carries that rounding, eps |p| / distance, so very near touching it is a supporting
     * direction only to that accuracy. When the points coincide (a distance below their resolution)
     * the separating direction of the SAT is used. */
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
