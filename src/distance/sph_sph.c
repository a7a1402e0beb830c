/* SPH-SPH: exact distance, proximal points and signed distance of two spheres.
 * TRX report LA-UR-13-26757 Sec. 3.6, Eq. (174): they intersect iff d_AB <= R_A + R_B; the signed
 * distance d_AB - R_A - R_B along the line of centres is also the exact penetration depth. */
#include "distance/box_internal.h"

/* Unit direction from a to b; an arbitrary fixed axis when the centres coincide. */
static prox_vec3 centre_dir(prox_vec3 a, prox_vec3 b, double *d)
{
    prox_vec3 v = prox_v3_sub(b, a);
    *d = prox_v3_norm(v);
    return *d > 0.0 ? prox_v3_divs(v, *d) : prox_v3(0, 0, 1);
}

PROX_API prox_signed_result prox_sph_sph_signed_distance(const prox_sph *a, const prox_sph *b)
{
    prox_status st = prox_valid2(prox_sph_validate(a), prox_sph_validate(b));
    if (st != PROX_OK) return (prox_signed_result){.status = st};
    return prox_sph_sph_signed_valid(a, b);
}

prox_signed_result prox_sph_sph_signed_valid(const prox_sph *a, const prox_sph *b)
{
    prox_signed_result r = {0};
    double d;
    r.normal = centre_dir(a->center, b->center, &d);
    r.sd = d - a->radius - b->radius;
    r.p1 = prox_v3_mad(a->center, a->radius, r.normal);
    r.p2 = prox_v3_mad(b->center, -b->radius, r.normal);
    /* Proved: the gap of the projections on the line of centres is sd itself (weak duality below),
     * and the witnesses on the spheres are |sd| apart (above); rounding aside. */
    prox_signed_closed_form(&r, fmax(d, 2.0 * fmax(a->radius, b->radius)));
    return r;
}

/* The distance on its own (the hot path of every sphere pair): one square root and no signed result
 * formed first. Same answers as the signed solver: sd = d - R_A - R_B along the unit n = (c_B - c_A) / d,
 * witnesses c_A + R_A n and c_B - R_B n, gap along n exactly sd. */
PROX_API prox_distance_result prox_sph_sph_distance(const prox_sph *a, const prox_sph *b)
{
    prox_status st = prox_valid2(prox_sph_validate(a), prox_sph_validate(b));
    if (st != PROX_OK) return (prox_distance_result){.status = st};
    return prox_sph_sph_distance_valid(a, b);
}

prox_distance_result prox_sph_sph_distance_valid(const prox_sph *a, const prox_sph *b)
{
    prox_distance_result r = {0};
    prox_vec3 v = prox_v3_sub(b->center, a->center);
    double d = prox_v3_norm(v), ra = a->radius, rb = b->radius, sd = d - ra - rb;
    double rmax = ra > rb ? ra : rb, scale = d > 2.0 * rmax ? d : 2.0 * rmax; /* no NaN: validated */
    if (sd > PROX_QUERY_REL_TOL * scale) { /* tangency within tol counts as touching; d > 0 here */
        prox_vec3 n = prox_v3_divs(v, d);
        r.distance = sd;
        r.p1 = prox_v3_mad(a->center, ra, n);
        r.p2 = prox_v3_mad(b->center, -rb, n);
        r.certificate_gap = sd; /* the support gap along the line of centres is exactly sd */
        return r;
    }
    /* Overlap: the point of the segment of centres at the same depth in both spheres is common. */
    r.intersect = 1;
    r.p1 = r.p2 = prox_v3_mad(a->center, ra / (ra + rb), v);
    /* Nested spheres: the smaller centre is common. */
    if (d + ra <= rb) r.p1 = r.p2 = a->center;
    else if (d + rb <= ra) r.p1 = r.p2 = b->center;
    return r;
}
