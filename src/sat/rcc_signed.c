/* Signed distance of two solid cylinders by the support method alone (both signs), and the
 * penetration depth of an overlapping pair (sat_internal.h).
 *
 * Overlapping pairs: depth = min over unit D of h_A(D) + h_B(-D) (h from Eberly's Eq. (4)), minimised
 * by enumerating the stationary directions of each stratum (rcc_depth.c), or by the global search of
 * the support-function engine (sup_engine.c) when a stratum cannot be settled; sd = -depth.
 * Disjoint pairs: the SAT's separating direction starts the certified minimisation of the same
 * function (quasi-convex there, so the local search is global); sd = distance. */
#include "sat_internal.h"

#include "sup_engine.h"

#include <stdatomic.h>

/* Overlapping pairs the enumeration could not settle, answered by the global search (rare). */
static atomic_ullong g_depth_fallbacks;

unsigned long long prox_sat_depth_fallbacks(void) { return atomic_load_explicit(&g_depth_fallbacks, memory_order_relaxed); }

/* prox_body_scaled in place for a cylinder body (its centre, cylinder and size: the only fields a
 * PROX_BODY_CYL uses), without copying the whole body twice. */
static void body_scale(prox_body *b, double f)
{
    b->c = prox_v3_scale(b->c, f);
    b->cyl = prox_cyl_scaled(&b->cyl, f);
    b->size *= f;
}

/* Bodies of a validated pair, both relative to A's base (exact by Sterbenz for a pair far from the
 * origin, which keeps its relative precision) and at unit scale (a power of two, exact): *o and *f
 * receive that origin and scale. */
static void pair_bodies(const prox_rcc *a, const prox_rcc *b, prox_body *ba, prox_body *bb, prox_vec3 *o, double *f)
{
    *o = a->base;
    prox_rcc ra = *a, rb = *b;
    ra.base = prox_v3(0, 0, 0);
    rb.base = prox_v3_sub(b->base, a->base);
    prox_body_make_cyl(&ra, ba);
    prox_body_make_cyl(&rb, bb);
    *f = prox_unit_scale(fmax(prox_v3_dist(ba->c, bb->c), fmax(fmax(ba->cyl.h, bb->cyl.h), fmax(ba->cyl.r, bb->cyl.r))));
    body_scale(ba, *f);
    body_scale(bb, *f);
}

/* A result of the scaled, relative pair in the caller's coordinates (the bounds of sd scale with it). */
static prox_signed_result absolute(prox_signed_result r, prox_vec3 o, double f)
{
    if (r.status != PROX_OK) return r;
    r.sd /= f;
    r.sd_lower /= f;
    r.sd_upper /= f;
    r.p1 = prox_v3_mad(o, 1.0 / f, r.p1);
    r.p2 = prox_v3_mad(o, 1.0 / f, r.p2);
    return r;
}

/* Depth of the bodies of an overlapping pair: the enumeration, else the global search. The
 * enumeration is an accelerator: when one of its circle solvers cannot root its polynomial (rims whose
 * sizes are ~1e80 apart overflow the degree-8 coefficients), the global search, which needs no
 * polynomial, answers instead. */
static prox_signed_result depth_bodies(const prox_body *ba, const prox_body *bb)
{
    prox_signed_result r = {0};
    int rc = sup_rcc_depth_enum(ba, bb, &r);
    if (rc == 1) return r;
    atomic_fetch_add_explicit(&g_depth_fallbacks, 1, memory_order_relaxed);
    return sup_signed_distance(ba, bb, NULL);
}

static prox_status validate_pair(const prox_rcc *a, const prox_rcc *b)
{
    if (!a || !b) return PROX_EINVAL_ARG;
    prox_status s = prox_rcc_validate(a);
    return s == PROX_OK ? prox_rcc_validate(b) : s;
}

/* A validated pair as bodies at unit scale (pair_bodies); the status of the first invalid input. */
static prox_status prepare(const prox_rcc *a, const prox_rcc *b, prox_body *ba, prox_body *bb, prox_vec3 *o,
                           double *f)
{
    prox_status s = validate_pair(a, b);
    if (s == PROX_OK) pair_bodies(a, b, ba, bb, o, f);
    return s;
}

prox_signed_result prox_sat_rcc_depth(const prox_rcc *a, const prox_rcc *b)
{
    prox_signed_result r = {0};
    prox_body ba, bb;
    prox_vec3 o;
    double f;
    if ((r.status = prepare(a, b, &ba, &bb, &o, &f)) != PROX_OK) return r;
    return absolute(depth_bodies(&ba, &bb), o, f);
}

prox_signed_result prox_sat_rcc_depth_bounded(const prox_rcc *a, const prox_rcc *b, int *bounded)
{
    prox_signed_result r = {0};
    prox_body ba, bb;
    prox_vec3 o;
    double f;
    *bounded = 0;
    if ((r.status = prepare(a, b, &ba, &bb, &o, &f)) != PROX_OK) return r;
    r = depth_bodies(&ba, &bb);
    /* an overlapping answer's enclosure depends on the pair only through centre differences, support
     * functions and sizes: the scaled, relative bodies give it, scaled back below */
    if (r.status == PROX_OK && r.sd <= 0.0) {
        prox_body_signed_bounds(&ba, &bb, &r);
        *bounded = 1;
    }
    return absolute(r, o, f);
}

prox_signed_result prox_sat_rcc_signed(const prox_rcc *a, const prox_rcc *b)
{
    prox_signed_result r = {0};
    prox_body ba, bb;
    prox_vec3 o;
    double f;
    if ((r.status = prepare(a, b, &ba, &bb, &o, &f)) != PROX_OK) return r;
    prox_cyl c0 = prox_body_cyl(&ba), c1 = prox_body_cyl(&bb); /* the verdict on the same cylinders */
    prox_test_result s = prox_sat_cyl(&c0, &c1);
    if (s.intersect) return absolute(depth_bodies(&ba, &bb), o, f);
    return absolute(sup_signed_distance(&ba, &bb, &s.direction), o, f);
}
