/* Signed distance of two solid cylinders by support-function optimisation (issue 4, Sec. 2):
 * sd = -min over unit D of h_A(D) + h_B(-D), h from Eberly's Eq. (4). See sup_engine.c. */
#include "prox/sat.h"

#include "sup_engine.h"

PROX_API prox_signed_result prox_rcc_signed_distance(const prox_rcc *a, const prox_rcc *b)
{
    prox_signed_result r = {0};
    /* the SAT validates both and gives a separating direction: the start of the local search */
    prox_sat_result s = prox_rcc_sat(a, b);
    if (s.status != PROX_OK) { r.status = s.status; return r; }
    prox_shape sa = prox_shape_from_rcc(*a), sb = prox_shape_from_rcc(*b);
    sup_body ba = sup_body_make(&sa), bb = sup_body_make(&sb);
    return sup_signed_distance(&ba, &bb, s.intersect ? NULL : &s.direction);
}
