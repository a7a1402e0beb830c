/* Internal: geometry of one box in its own frame (centre m, unit axes a[k], half-lengths h[k]) and of
 * cylinders seen as point sets, shared by the box, sphere and containment solvers.
 * Local coordinates l_k = (x - m).a_k make the box the product of intervals [-h_k, h_k]. */
#ifndef PROX_DISTANCE_BOX_INTERNAL_H
#define PROX_DISTANCE_BOX_INTERNAL_H

#include "core/box.h"
#include "core/cyl.h"
#include "prox/distance.h"
#include "prox/pairs.h"
#include "prox/query.h"


/* Signed result of disjoint solids (d->distance > 0): sd = distance, unit normal from p1 to p2. */
static inline prox_signed_result prox_signed_from_disjoint(const prox_distance_result *d)
{
    prox_signed_result r = {0};
    r.sd = d->distance;
    r.normal = prox_v3_divs(prox_v3_sub(d->p2, d->p1), d->distance);
    r.p1 = d->p1;
    r.p2 = d->p2;
    return r;
}

/* First failing status of two validations (both inputs are validated; validation is side-effect free). */
static inline prox_status prox_valid2(prox_status x, prox_status y) { return x != PROX_OK ? x : y; }

/* Frame of a validated cylinder: base, unit axis w, a right-handed orthonormal (u, v) of the end
 * planes, height h and radius r. */
typedef struct prox_cframe {
    prox_vec3 base, w, u, v;
    double h, r;
} prox_cframe;

static inline prox_cframe prox_cframe_make(const prox_rcc *c)
{
    prox_cframe f;
    f.base = c->base;
    f.h = prox_v3_norm(c->axis);
    f.w = prox_v3_divs(c->axis, f.h);
    f.u = prox_v3_any_perp(f.w);
    f.v = prox_v3_cross(f.w, f.u);
    f.r = c->radius;
    return f;
}

/* Centre of the rim circle `top` (0 base, 1 top). */
static inline prox_vec3 prox_cframe_rim_center(const prox_cframe *c, int top)
{
    return prox_v3_mad(c->base, top ? c->h : 0.0, c->w);
}

/* Solid A against the sphere b, from the signed distance sdp of b's centre to A, A's boundary point q
 * nearest to the centre and the outward unit normal n there (centre = q + sdp n): the signed result. */
static inline prox_signed_result prox_sph_signed_from_point(double sdp, prox_vec3 q, prox_vec3 n, const prox_sph *b)
{
    prox_signed_result r = {0};
    r.sd = sdp - b->radius;
    r.normal = n;
    r.p1 = q;
    r.p2 = prox_v3_mad(b->center, -b->radius, n);
    return r;
}

/* Disjoint solid A and sphere b, from the distance d of b's centre to A, A's nearest point q and the unit
 * direction n from q to the centre; support_n is A's support value along n (for the certificate). */
static inline prox_distance_result prox_sph_distance_from_point(double d, prox_vec3 q, prox_vec3 n, const prox_sph *b,
                                                                double support_n)
{
    prox_distance_result r = {0};
    r.distance = d - b->radius;
    r.p1 = q;
    r.p2 = prox_v3_mad(b->center, -b->radius, n);
    r.certificate_gap = (prox_v3_dot(n, b->center) - b->radius) - support_n;
    return r;
}

/* Signed distance of x to the solid cylinder c (negative inside), nearest boundary point and outward
 * normal with x = q + sd n. Defined in rcc_sph.c. */
double prox_rcc_point_signed(const prox_rcc *c, prox_vec3 x, prox_vec3 *q, prox_vec3 *n);

#endif
