/* Support functions of the four macrobodies (Eberly, "Intersection of Cylinders", Eq. (4) for the
 * cylinder; sum of |d.e_i| half extents for a box; c.d + r|d| for a sphere) and the generic signed
 * distance built on them (sup_engine.c). The cylinder uses prox_rcc_support/_point of rcc_support.c. */
#include "prox/support.h"

#include "prox/distance.h"
#include "sup_engine.h"

PROX_API double prox_shape_support(const prox_shape *s, prox_vec3 d)
{
    if (s->kind == PROX_SHAPE_RCC) return prox_rcc_support(&s->u.rcc, d);
    sup_body b = sup_body_make(s);
    return prox_v3_dot(d, b.c) + sup_hc(&b, d);
}

PROX_API prox_vec3 prox_shape_support_point(const prox_shape *s, prox_vec3 d)
{
    if (s->kind == PROX_SHAPE_RCC) {
        if (prox_v3_norm2(d) == 0.0) return prox_v3_mad(s->u.rcc.base, 0.5, s->u.rcc.axis);
        return prox_rcc_support_point(&s->u.rcc, d);
    }
    sup_body b = sup_body_make(s);
    return prox_v3_add(b.c, sup_pc(&b, d));
}

PROX_API prox_vec3 prox_shape_center(const prox_shape *s) { return sup_body_make(s).c; }

PROX_API double prox_shape_size(const prox_shape *s) { return sup_body_make(s).size; }

PROX_API prox_signed_result prox_shape_signed_distance_support(const prox_shape *a, const prox_shape *b)
{
    prox_signed_result r = {0};
    if (!a || !b) { r.status = PROX_EINVAL_ARG; return r; }
    r.status = prox_shape_validate(a);
    if (r.status == PROX_OK) r.status = prox_shape_validate(b);
    if (r.status != PROX_OK) return r;
    sup_body ba = sup_body_make(a), bb = sup_body_make(b);
    return sup_signed_distance(&ba, &bb, NULL);
}
