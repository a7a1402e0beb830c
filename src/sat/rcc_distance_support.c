/* Distance of two solid cylinders by the support method alone (PROX_METHOD_SUPPORT), from the
 * geometric core only:
 *   verdict     prox_sat_cyl (Eberly's axis tests, then Minkowski portal refinement with a certified
 *               bound; rcc_sat.c);
 *   disjoint    the certified minimisation of phi(D) = h_A(D) + h_B(-D) over unit D (sup_engine.c),
 *               started from the separating direction; witnesses from the two support sets along the
 *               optimal normal, their closest pair solved exactly (sup_witnesses); the bound
 *               gap(n) = -phi(n) <= distance <= |p2 - p1| (weak duality) is the certificate;
 *   overlapping a common point from the final portal (the A-part of Delta, prox_sat_common_point),
 *               checked in both solids; containment by rims: A lies in B iff both rims of A do (B is
 *               convex and A the hull of its rims), a rim lying in B iff its axial range is within B's
 *               height and its farthest point from B's axis within B's radius. */
#include "prox/sat.h"

#include "core/circle.h"
#include "core/tol.h"
#include "sat_internal.h"
#include "sup_engine.h"

/* Alternating projections between the two solids (prox_cyl_closest) from *x, a fallback for a common
 * point when the portal gave none or one outside a solid by its rounding: for two overlapping convex
 * sets they converge to a point of the intersection. 1 and *x when a point within tol of both was
 * reached. */
static int project_common(const prox_cyl *a, const prox_cyl *b, double tol, prox_vec3 *x)
{
    prox_vec3 p = *x;
    if (prox_cyl_contains(a, p, tol) && prox_cyl_contains(b, p, tol)) return 1;
    for (int it = 0; it < 200; ++it) {
        p = prox_cyl_closest(b, prox_cyl_closest(a, p));
        if (prox_cyl_contains(a, p, tol) && prox_cyl_contains(b, p, tol)) {
            *x = p;
            return 1;
        }
    }
    return 0;
}

/* The overlapping answer: containment and a checked common point (start: where the projections
 * begin when the portal gives none). */
static void overlap_answer(const prox_cyl *c0, const prox_cyl *c1, double S, prox_vec3 start, prox_distance_result *r)
{
    double tol = PROX_TOL_CERT * S;
    r->intersect = 1;
    r->distance = 0.0;
    r->a_in_b = prox_cyl_in_cyl(c0, c1, tol);
    r->b_in_a = prox_cyl_in_cyl(c1, c0, tol);
    prox_vec3 x = start;
    int ok = 0;
    if (r->a_in_b) x = c0->c, ok = 1; /* nested: the inner centre */
    else if (r->b_in_a) x = c1->c, ok = 1;
    if (!ok) {
        prox_sat_common_point(c0, c1, &x); /* else x stays the midpoint of the centres */
        ok = project_common(c0, c1, tol, &x);
        /* the touching band: the solids may share no point in floating point */
        if (!ok) ok = prox_cyl_contains(c0, x, PROX_TOL_TOUCH * S) && prox_cyl_contains(c1, x, PROX_TOL_TOUCH * S);
    }
    r->p1 = r->p2 = x;
    r->certified = ok;
}

PROX_API prox_distance_result prox_rcc_distance_support(const prox_rcc *a, const prox_rcc *b)
{
    prox_distance_result r = {0};
    if (!a || !b) { r.status = PROX_EINVAL_ARG; return r; }
    r.status = prox_rcc_validate(a);
    if (r.status == PROX_OK) r.status = prox_rcc_validate(b);
    if (r.status != PROX_OK) return r;
    r.method = PROX_METHOD_SUPPORT;
    /* everything relative to A's base: a pair far from the origin keeps its relative precision */
    prox_vec3 o = a->base;
    prox_rcc ra = *a, rb = *b;
    ra.base = prox_v3(0, 0, 0);
    rb.base = prox_v3_sub(b->base, o);
    prox_shape sa = prox_shape_from_rcc(ra), sb = prox_shape_from_rcc(rb);
    prox_body ba = prox_body_make(&sa), bb = prox_body_make(&sb);
    /* the scale of tests/data/README.md, max(|cA - cB|, hA, hB, rA, rB), brought into [1, 2) by a
     * power of two (exact): no square or product of the pair's numbers can overflow or underflow */
    double f = prox_unit_scale(fmax(prox_v3_dist(ba.c, bb.c), fmax(fmax(ba.cyl.h, bb.cyl.h), fmax(ba.cyl.r, bb.cyl.r))));
    ba = prox_body_scaled(&ba, f);
    bb = prox_body_scaled(&bb, f);
    prox_cyl c0 = prox_body_cyl(&ba), c1 = prox_body_cyl(&bb);
    double S = fmax(prox_v3_dist(ba.c, bb.c), fmax(fmax(c0.h, c1.h), fmax(c0.r, c1.r)));
    prox_test_result v = prox_sat_cyl(&c0, &c1);
    prox_signed_result g = {0};
    if (!v.intersect) g = sup_signed_distance(&ba, &bb, &v.direction);
    if (v.intersect || !(g.sd > 0.0)) {
        /* overlapping, or touching: no direction with a positive gap (the verdict's within rounding);
         * a touching pair's witnesses are a pair of points |p2 - p1| apart: start from their middle */
        prox_vec3 start = v.intersect ? prox_v3_scale(prox_v3_add(c0.c, c1.c), 0.5) : prox_v3_scale(prox_v3_add(g.p1, g.p2), 0.5);
        overlap_answer(&c0, &c1, S, start, &r);
    } else {
        r.p1 = g.p1;
        r.p2 = g.p2;
        r.distance = prox_v3_dist(g.p1, g.p2);
        /* every direction gives a true lower bound (weak duality): the witnesses' normal, the
         * separating direction, and -phi at the search's best direction (g.sd); keep the largest */
        r.certificate_gap = fmax(fmax(prox_cyl_gap(&c0, &c1, g.normal), prox_cyl_gap(&c0, &c1, v.direction)), g.sd);
        r.certified = r.distance - r.certificate_gap <= PROX_TOL_CERT * S;
    }
    r.distance /= f;
    r.certificate_gap /= f;
    r.p1 = prox_v3_mad(o, 1.0 / f, r.p1);
    r.p2 = prox_v3_mad(o, 1.0 / f, r.p2);
    return r;
}
