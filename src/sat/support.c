/* Signed distance of any two macrobodies by the support-function engine (sup_engine.c) alone: the
 * bodies are the core's (core/body.h), whose support functions are Eberly's Eq. (4) for the cylinder,
 * the sum of |d.a_k| half extents for a box and c.d + r|d| for a sphere. */
#include "prox/support.h"

#include "sup_engine.h"
#include "convex.h"

PROX_API prox_signed_result prox_shape_signed_distance_support(const prox_shape *a, const prox_shape *b)
{
    prox_signed_result r = {0};
    if (!a || !b) { r.status = PROX_EINVAL_ARG; return r; }
    r.status = prox_shape_validate(a);
    if (r.status == PROX_OK) r.status = prox_shape_validate(b);
    if (r.status != PROX_OK) return r;
    /* relative to A's centre and at unit scale (a power of two, exact): no square or product of the
     * pair's numbers can overflow or underflow */
    prox_body ba = prox_body_make(a), bb = prox_body_make(b);
    /* the ridge search of sup_engine.c assumes centrally symmetric bodies (CYL, BOX, SPH); the added
     * kinds take the general certified method (convex.c), which scales and translates on its own */
    if (!prox_body_symmetric(&ba) || !prox_body_symmetric(&bb)) {
        r = prox_convex_signed(&ba, &bb);
        prox_body_signed_bounds(&ba, &bb, &r);
        return r;
    }
    prox_body a0 = ba, b0 = bb; /* the bodies as given, for the enclosure */
    prox_vec3 o = ba.c;
    ba.c = prox_v3(0, 0, 0);
    bb.c = prox_v3_sub(bb.c, o);
    double f = prox_unit_scale(fmax(prox_v3_norm(bb.c), fmax(ba.size, bb.size)));
    ba = prox_body_scaled(&ba, f);
    bb = prox_body_scaled(&bb, f);
    r = sup_signed_distance(&ba, &bb, NULL);
    r.sd /= f;
    r.p1 = prox_v3_mad(o, 1.0 / f, r.p1);
    r.p2 = prox_v3_mad(o, 1.0 / f, r.p2);
    prox_body_signed_bounds(&a0, &b0, &r); /* the global search proves no depth: overlaps stay uncertified */
    return r;
}
