/* Internal: results shared by the box, sphere and containment solvers. The prepared shapes they
 * work on are the core's: prox_bframe (core/box.h) and prox_cyl (core/cyl.h). */
#ifndef PROX_DISTANCE_BOX_INTERNAL_H
#define PROX_DISTANCE_BOX_INTERNAL_H

#include "core/box.h"
#include "core/body.h"
#include "core/cyl.h"
#include "prox/distance.h"
#include "prox/pairs.h"
#include "prox/query.h"


/* Signed result of disjoint solids (d->distance > 0): sd = distance, unit normal from p1 to p2,
 * normalised by |p2 - p1| itself (the distance, a certified gap, differs from it by rounding of S:
 * two boxes 2e-10 S apart had a normal 8e-8 short of unit length). */
static inline prox_signed_result prox_signed_from_disjoint(const prox_distance_result *d)
{
    prox_signed_result r = {0};
    r.sd = d->distance;
    r.normal = prox_v3_normalize(prox_v3_sub(d->p2, d->p1));
    r.p1 = d->p1;
    r.p2 = d->p2;
    r.sd_lower = d->certified ? d->certificate_gap : 0.0; /* the duality certificate, if any */
    r.certified = d->certified;
    return r;
}

/* First failing status of two validations (both inputs are validated; validation is side-effect free). */
static inline prox_status prox_valid2(prox_status x, prox_status y) { return x != PROX_OK ? x : y; }

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

/* SPH-SPH on spheres already validated (prepared solids): the public solvers after their checks. */
prox_distance_result prox_sph_sph_distance_valid(const prox_sph *a, const prox_sph *b);
prox_signed_result prox_sph_sph_signed_valid(const prox_sph *a, const prox_sph *b);

#endif
