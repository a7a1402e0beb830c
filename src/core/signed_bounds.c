/* The proved enclosure of a signed distance (prox_signed_result.sd_lower, sd_upper, certified).
 *
 * Lower bound, every pair: for any unit n the projections of A and B on n are [a-, h_A(n)] and
 * [-h_B(-n), b+], and the signed distance is at least their gap g(n) = -h_B(-n) - h_A(n): when
 * disjoint, a separating plane's gap never exceeds the distance (weak duality); when overlapping, the
 * depth is the least overlap h_A(n) + h_B(-n) over all n, so -depth >= g(n). Evaluated at the
 * answer's normal, with the support functions taken relative to A's centre.
 *
 * Upper bound: disjoint, |p2 - p1| for the witnesses once each is checked in its solid (a pair of
 * points of A and B is never closer than the distance). Overlapping, the depth's own proof: the
 * method enumerated every deciding feature pair in closed form or covered the sphere of directions
 * (r->certified on entry), else only the overlap verdict, sd <= 0. */
#include <math.h>

#include "core/body.h"
#include "core/tol.h"

/* Distance of x from the body: 0 when it lies within tol of it, else the exact distance. */
static double off_body(const prox_body *b, prox_vec3 x, double tol)
{
    if (prox_body_contains(b, x, tol)) return tol;
    return prox_v3_dist(x, prox_body_closest(b, x)) + tol;
}

void prox_body_signed_bounds(const prox_body *a, const prox_body *b, prox_signed_result *r)
{
    int proved = r->certified;
    double method_lower = r->sd_lower, method_upper = r->sd_upper;
    r->certified = 0;
    r->sd_lower = r->sd_upper = 0.0;
    if (r->status != PROX_OK) return;
    /* The bar's scale, taken no larger than any pair scale in use (the validation sets' max of the
     * centre distance, heights and radii; prox_shape_pair_scale): half the largest dimension. */
    double S = fmax(prox_v3_dist(a->c, b->c), 0.5 * fmax(a->size, b->size)), err = PROX_TOL_BOUND * 2.0 * S;
    prox_vec3 n = r->normal;
    double g = prox_v3_dot(n, prox_v3_sub(b->c, a->c)) - prox_body_hc(a, n) - prox_body_hc(b, prox_v3_neg(n));
    r->sd_lower = fmin(g - err, r->sd);
    if (!(g == g) || !(fabs(prox_v3_norm(n) - 1.0) <= PROX_TOL_BOUND)) r->sd_lower = -INFINITY;
    if (r->sd > 0.0) {
        /* the method's own duality certificate, at its separating direction (sharper than the
         * witnesses' direction when they are ulps apart) */
        if (method_lower > 0.0 && method_lower <= r->sd + err) r->sd_lower = fmax(r->sd_lower, fmin(method_lower - err, r->sd));
        double t1 = PROX_TOL_BOUND * (S + prox_v3_norm(r->p1)), t2 = PROX_TOL_BOUND * (S + prox_v3_norm(r->p2));
        r->sd_upper = fmax(prox_v3_dist(r->p1, r->p2) + off_body(a, r->p1, t1) + off_body(b, r->p2, t2), r->sd);
        r->certified = r->sd_upper - r->sd_lower <= PROX_TOL_TOUCH * S;
        return;
    }
    /* a method's -phi at its own best direction (the normal reported may be a witness-consistent
     * neighbour whose overlap is larger) */
    if (method_lower < 0.0 && method_lower <= r->sd + err) r->sd_lower = fmax(r->sd_lower, fmin(method_lower - err, r->sd));
    r->sd_upper = 0.0;
    if (proved) r->sd_upper = fmax(r->sd + err, method_upper < 0.0 ? method_upper : r->sd + err);
    r->sd_upper = fmin(r->sd_upper, 0.0);
    r->certified = proved && r->sd_upper - r->sd_lower <= PROX_TOL_DEPTH_BAR * S;
}

/* Centre and size of the four original kinds without preparing a body (the disjoint answers of their
 * certified distance methods need nothing more); 0 for the added kinds. */
static int quick_centre(const prox_shape *s, prox_vec3 *c, double *size)
{
    switch (s->kind) {
    case PROX_SHAPE_RCC:
        *c = prox_rcc_center(&s->u.rcc);
        *size = fmax(prox_v3_norm(s->u.rcc.axis), 2.0 * s->u.rcc.radius);
        return 1;
    case PROX_SHAPE_BOX: {
        const prox_box *b = &s->u.box;
        *c = prox_v3_mad(b->corner, 0.5, prox_v3_add(b->edge[0], prox_v3_add(b->edge[1], b->edge[2])));
        *size = fmax(prox_v3_norm(b->edge[0]), fmax(prox_v3_norm(b->edge[1]), prox_v3_norm(b->edge[2])));
        return 1;
    }
    case PROX_SHAPE_SPH:
        *c = s->u.sph.center;
        *size = 2.0 * s->u.sph.radius;
        return 1;
    default: return 0;
    }
}

/* A disjoint answer whose method certified its distance by duality (r->certified on entry, its
 * certificate_gap in r->sd_lower): the enclosure is that gap and |p2 - p1| (the method's witnesses on
 * the solids), each with its rounding. 0 when the shapes are not of the original kinds. */
static int certified_disjoint(const prox_shape *a, const prox_shape *b, prox_signed_result *r)
{
    prox_vec3 ca, cb;
    double sa, sb;
    if (!(r->sd > 0.0 && r->certified && r->sd_lower > 0.0) || !quick_centre(a, &ca, &sa) || !quick_centre(b, &cb, &sb))
        return 0;
    double S = fmax(prox_v3_dist(ca, cb), 0.5 * fmax(sa, sb)), err = PROX_TOL_BOUND * 2.0 * S;
    r->sd_lower = fmin(r->sd_lower - err, r->sd);
    r->sd_upper = fmax(prox_v3_dist(r->p1, r->p2) + err, r->sd);
    r->certified = r->sd_upper - r->sd_lower <= PROX_TOL_TOUCH * S;
    return 1;
}

void prox_shape_signed_bounds(const prox_shape *a, const prox_shape *b, prox_signed_result *r)
{
    if (r->status != PROX_OK || certified_disjoint(a, b, r)) return;
    prox_body ba = prox_body_make(a), bb = prox_body_make(b);
    prox_body_signed_bounds(&ba, &bb, r);
}
