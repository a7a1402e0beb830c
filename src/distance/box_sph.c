/* BOX-SPH: exact distance, proximal points and signed distance of a box and a sphere.
 * Replaces the TRX report's Sec. 3.3 (LA-UR-13-26757, Eqs. (49)-(51): edge lines against the sphere),
 * which misses a sphere inside the box, a sphere through a face, and a box inside the sphere. Here the
 * closest point of the box to the sphere's centre decides: dist = |c - q| - R, exactly; inside the box
 * the signed distance of the centre is -(distance to the nearest face). Tangency within
 * PROX_QUERY_REL_TOL x scale counts as intersecting, as in the box-box and box-cylinder verdicts. */
#include "distance/box_internal.h"

PROX_API prox_signed_result prox_box_sph_signed_distance(const prox_box *a, const prox_sph *b)
{
    prox_signed_result r = {0};
    r.status = prox_valid2(prox_box_validate(a), prox_sph_validate(b));
    if (r.status != PROX_OK) return r;
    prox_bframe f = prox_bframe_make(a);
    prox_vec3 q, n;
    double sdp = prox_bframe_signed(&f, b->center, &q, &n);
    if (!(prox_v3_norm2(n) > 0.0)) n = f.a[2]; /* centre on the surface: a face normal is valid */
    r = prox_sph_signed_from_point(sdp, q, n, b);
    prox_signed_closed_form(&r, fabs(sdp) + 2.0 * b->radius + prox_bframe_size(&f)); /* the exact point distance */
    return r;
}

PROX_API prox_distance_result prox_box_sph_distance(const prox_box *a, const prox_sph *b)
{
    prox_distance_result r = {0};
    r.status = prox_valid2(prox_box_validate(a), prox_sph_validate(b));
    if (r.status != PROX_OK) return r;
    prox_bframe f = prox_bframe_make(a);
    double d;
    prox_vec3 q = prox_bframe_closest(&f, b->center, &d);
    double scale = fmax(fmax(prox_v3_dist(f.m, b->center), prox_bframe_size(&f)), 2.0 * b->radius);
    if (d - b->radius <= PROX_QUERY_REL_TOL * scale) { /* q in the box, within R (+ tol) of the centre */
        r.intersect = 1;
        r.p1 = r.p2 = q;
        return r;
    }
    prox_vec3 n = prox_v3_divs(prox_v3_sub(b->center, q), d);
    return prox_sph_distance_from_point(d, q, n, b, prox_bframe_support(&f, n));
}
