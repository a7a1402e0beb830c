/* BOX-RCC signed distance: the exact distance of src/distance when the solids are disjoint, the
 * penetration depth of src/sat (closed-form enumeration of the strata) when they overlap. It composes the two
 * modules, hence lives here and not in either of them. */
#include "core/body.h"
#include "core/box.h"
#include "core/cyl.h"
#include "prox/pairs.h"
#include "prox/support.h"
#include "query/query_internal.h"
#include "sat/convex.h"
#include "sat/sat_internal.h"

static prox_signed_result box_rcc_signed(const prox_box *a, const prox_rcc *b, int *bounded);

/* The answer with its proved enclosure (core/signed_bounds.c; an overlapping answer's comes with its
 * depth, computed on the bodies the depth already built). */
PROX_API prox_signed_result prox_box_rcc_signed_distance(const prox_box *a, const prox_rcc *b)
{
    int bounded = 0;
    prox_signed_result r = box_rcc_signed(a, b, &bounded);
    if (r.status != PROX_OK || bounded) return r;
    prox_shape sa = prox_shape_from_box(*a), sb = prox_shape_from_rcc(*b);
    prox_shape_signed_bounds(&sa, &sb, &r);
    return r;
}

prox_distance_result prox_query_box_rcc_distance(const prox_box *a, const prox_rcc *b)
{
    prox_distance_result d = prox_box_rcc_distance(a, b);
    if (d.status != PROX_OK || d.intersect || d.certified) return d;
    prox_shape sa = prox_shape_from_box(*a), sb = prox_shape_from_rcc(*b);
    prox_body ba = prox_body_make(&sa), bb = prox_body_make(&sb);
    prox_distance_result e = prox_convex_distance(&ba, &bb);
    return e.certified && !e.intersect ? e : d;
}

/* 1 when x lies in the closed box a (squared-free: the corner's edge coordinates in [0, |e|^2]). */
static int box_holds(const prox_box *a, prox_vec3 x)
{
    prox_vec3 d = prox_v3_sub(x, a->corner);
    for (int i = 0; i < 3; ++i) {
        double t = prox_v3_dot(d, a->edge[i]);
        if (!(t >= 0.0 && t <= prox_v3_norm2(a->edge[i]))) return 0;
    }
    return 1;
}

/* 1 when the pair shares an evident point: a centre of one in the other, or the midpoint of the
 * centres in both. Such a pair overlaps (or touches) and goes straight to the depth, which validates
 * it (so does the distance otherwise: bad input gets its status either way). */
static int evident_common(const prox_box *a, const prox_rcc *b)
{
    if (!a || !b) return 0; /* the solvers report it */
    prox_vec3 ca = prox_v3_mad(a->corner, 0.5, prox_v3_add(a->edge[0], prox_v3_add(a->edge[1], a->edge[2])));
    prox_vec3 cb = prox_v3_mad(b->base, 0.5, b->axis), mid = prox_v3_scale(prox_v3_add(ca, cb), 0.5);
    return prox_rcc_holds(b, ca) || box_holds(a, cb) || (box_holds(a, mid) && prox_rcc_holds(b, mid));
}

static prox_signed_result box_rcc_signed(const prox_box *a, const prox_rcc *b, int *bounded)
{
    prox_signed_result r = {0};
    if (evident_common(a, b)) return prox_sat_box_rcc_depth_bounded(a, b, bounded);
    prox_distance_result d = prox_query_box_rcc_distance(a, b);
    r.status = d.status;
    if (r.status != PROX_OK) return r;
    if (!d.intersect && d.distance > 0.0) { /* disjoint: sd = distance, unit normal from p1 to p2 */
        r.sd = d.distance;
        /* normalised by |p2 - p1| itself: the distance differs from it by rounding of S, which at a
         * gap of 1e-11 S turned the normal 3 % off unit length */
        r.normal = prox_v3_normalize(prox_v3_sub(d.p2, d.p1));
        r.p1 = d.p1;
        r.p2 = d.p2;
        r.sd_lower = d.certified ? d.certificate_gap : 0.0; /* the duality certificate */
        r.certified = d.certified;
        return r;
    }
    /* overlapping: minimum of h_A(D) + h_B(-D) over unit D, every stratum enumerated in closed
     * form (src/sat/box_rcc_depth.c) */
    return prox_sat_box_rcc_depth_bounded(a, b, bounded);
}
