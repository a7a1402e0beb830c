/* Signed distance of two solid cylinders, composed from the two modules: the exact distance of the
 * fast method (prox_rcc_distance, certified by duality) when the solids are disjoint, the penetration
 * depth of the support method (min over unit D of h_A(D) + h_B(-D), Eberly's Eq. (4) support
 * functions: prox_sat_rcc_depth_bounded) when they overlap, which an evident common point settles
 * before the distance runs. */
#include "prox/distance.h"
#include "prox/sat.h"
#include "core/body.h"
#include "core/cyl.h"
#include "sat/sat_internal.h"

/* Polishes a disjoint pair's witnesses p1 in A, p2 in B whose separation differs from the certified
 * distance d (the fast method's points may sit 1e-11 S off the boundaries of a near-touching contact
 * while its distance is certified): alternating exact projections onto the solids, in coordinates
 * relative to A's base, accepted while |p2 - p1| decreases (each projection keeps its point on a
 * solid and never increases the separation; for a unique closest pair they converge to it). */
static void polish_disjoint(const prox_rcc *a, const prox_rcc *b, double d, prox_vec3 *p1, prox_vec3 *p2)
{
    prox_vec3 o = a->base;
    prox_rcc ra = *a, rb = *b;
    ra.base = prox_v3(0, 0, 0);
    rb.base = prox_v3_sub(b->base, o);
    prox_body ba, bb;
    prox_body_make_cyl(&ra, &ba);
    prox_body_make_cyl(&rb, &bb);
    prox_vec3 x = prox_v3_sub(*p1, o), y = prox_v3_sub(*p2, o);
    double e = fabs(prox_v3_dist(x, y) - d);
    for (int it = 0; it < 8; ++it) {
        prox_vec3 yn = prox_body_closest(&bb, x), xn = prox_body_closest(&ba, yn);
        double en = fabs(prox_v3_dist(xn, yn) - d);
        if (!(en < e)) break;
        x = xn, y = yn, e = en;
    }
    *p1 = prox_v3_add(x, o);
    *p2 = prox_v3_add(y, o);
}

static prox_signed_result rcc_signed(const prox_rcc *a, const prox_rcc *b, int *bounded);

/* The answer with its proved enclosure (core/signed_bounds.c; an overlapping answer's comes with its
 * depth, computed on the bodies the depth already built). */
PROX_API prox_signed_result prox_rcc_signed_distance(const prox_rcc *a, const prox_rcc *b)
{
    int bounded = 0;
    prox_signed_result r = rcc_signed(a, b, &bounded);
    if (r.status != PROX_OK || bounded) return r;
    prox_shape sa = prox_shape_from_rcc(*a), sb = prox_shape_from_rcc(*b);
    prox_shape_signed_bounds(&sa, &sb, &r);
    return r;
}

/* 1 when the pair shares an evident point: a centre of one cylinder in the other, or the midpoint of
 * the centres in both (relative to A's base, as the solvers take the pair). Two thirds of the
 * overlapping pairs of the bench's mix are found so and go straight to the depth, which validates
 * the pair (so does the distance otherwise: bad input gets its status either way). */
static int evident_common(const prox_rcc *a, const prox_rcc *b)
{
    if (!a || !b) return 0; /* the solvers report it */
    prox_rcc ra = *a, rb = *b;
    ra.base = prox_v3(0, 0, 0);
    rb.base = prox_v3_sub(b->base, a->base);
    prox_vec3 ca = prox_v3_scale(ra.axis, 0.5), cb = prox_v3_mad(rb.base, 0.5, rb.axis);
    prox_vec3 mid = prox_v3_scale(prox_v3_add(ca, cb), 0.5);
    return prox_rcc_holds(&rb, ca) || prox_rcc_holds(&ra, cb) || (prox_rcc_holds(&ra, mid) && prox_rcc_holds(&rb, mid));
}

static prox_signed_result rcc_signed(const prox_rcc *a, const prox_rcc *b, int *bounded)
{
    prox_signed_result r = {0};
    if (evident_common(a, b)) return prox_sat_rcc_depth_bounded(a, b, bounded);
    prox_distance_result d = prox_rcc_distance(a, b); /* validates both */
    if (d.status != PROX_OK) {
        r.status = d.status;
        return r;
    }
    if (d.intersect || !(d.distance > 0.0)) return prox_sat_rcc_depth_bounded(a, b, bounded);
    r.status = PROX_OK;
    r.sd = d.distance;
    r.p1 = d.p1;
    r.p2 = d.p2;
    r.sd_lower = d.certified ? d.certificate_gap : 0.0; /* the duality certificate */
    r.certified = d.certified;
    if (fabs(prox_v3_dist(d.p1, d.p2) - d.distance) > 0.0) polish_disjoint(a, b, d.distance, &r.p1, &r.p2);
    /* (p2 - p1) / |p2 - p1| is the normal: it makes p2 - p1 = sd n hold to the points' rounding. Its
     * direction carries that rounding, eps |p| / distance, so very near touching it is a supporting
     * direction only to that accuracy. When the points coincide (a distance below their resolution)
     * the separating direction of the SAT is used. */
    prox_vec3 e = prox_v3_sub(r.p2, r.p1);
    double en = prox_v3_norm(e);
    if (en > 0.0) {
        r.normal = prox_v3_scale(e, 1.0 / en);
        return r;
    }
    prox_test_result s = prox_rcc_sat(a, b);
    r.normal = s.intersect ? prox_v3(0, 0, 1) : s.direction;
    return r;
}
