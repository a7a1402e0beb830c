/* RCC-SPH: exact distance, proximal points and signed distance of a cylinder and a sphere.
 * Replaces the TRX report's Sec. 3.5 (LA-UR-13-26757, Eqs. (145)-(173), Configurations 1-3 and
 * Types 1-4 built on the foot d_1 of the centre on the axis, Eq. (157)): the closest point of the solid
 * cylinder to the centre gives the distance |c - q| - R exactly in every configuration, and inside the
 * cylinder the signed distance of the centre is -min(t, h - t, r - rho) (prox_cyl_signed, core/cyl.c). */
#include "distance/box_internal.h"

PROX_API prox_signed_result prox_rcc_sph_signed_distance(const prox_rcc *a, const prox_sph *b)
{
    prox_signed_result r = {0};
    r.status = prox_valid2(prox_rcc_validate(a), prox_sph_validate(b));
    if (r.status != PROX_OK) return r;
    prox_cyl k = prox_cyl_make(a, prox_v3(0, 0, 0));
    prox_vec3 q, n;
    double sdp = prox_cyl_signed(&k, b->center, &q, &n);
    r = prox_sph_signed_from_point(sdp, q, n, b);
    prox_signed_closed_form(&r, fabs(sdp) + 2.0 * b->radius + k.h + 2.0 * k.r); /* the exact point distance */
    return r;
}

PROX_API prox_distance_result prox_rcc_sph_distance(const prox_rcc *a, const prox_sph *b)
{
    prox_distance_result r = {0};
    r.status = prox_valid2(prox_rcc_validate(a), prox_sph_validate(b));
    if (r.status != PROX_OK) return r;
    prox_cyl k = prox_cyl_make(a, prox_v3(0, 0, 0));
    prox_vec3 q, n;
    double sdp = prox_cyl_signed(&k, b->center, &q, &n);
    double scale = fmax(fmax(prox_v3_dist(k.c, b->center), fmax(k.h, 2.0 * k.r)), 2.0 * b->radius);
    if (sdp - b->radius <= PROX_QUERY_REL_TOL * scale) { /* tangency within tol counts as touching */
        r.intersect = 1;
        r.p1 = r.p2 = sdp <= 0.0 ? b->center : q;
        return r;
    }
    return prox_sph_distance_from_point(sdp, q, n, b, prox_cyl_support(&k, n));
}
