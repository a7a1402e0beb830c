/* RCC-SPH: exact distance, proximal points and signed distance of a cylinder and a sphere.
 * Replaces the TRX report's Sec. 3.5 (LA-UR-13-26757, Eqs. (145)-(173), Configurations 1-3 and
 * Types 1-4 built on the foot d_1 of the centre on the axis, Eq. (157)): the closest point of the solid
 * cylinder to the centre gives the distance |c - q| - R exactly in every configuration, and inside the
 * cylinder the signed distance of the centre is -min(t, h - t, r - rho). */
#include "distance/box_internal.h"

/* Signed distance of x to the solid cylinder; q nearest boundary point, n outward normal. */
double prox_rcc_point_signed(const prox_rcc *c, prox_vec3 x, prox_vec3 *q, prox_vec3 *n)
{
    double h = prox_v3_norm(c->axis);
    prox_vec3 w = prox_v3_divs(c->axis, h);
    prox_vec3 d = prox_v3_sub(x, c->base);
    double t = prox_v3_dot(d, w);
    prox_vec3 rad = prox_v3_mad(d, -t, w);
    double rho = prox_v3_norm(rad);
    /* Radial unit direction. Near the axis rad is rounding noise with a component along w: below
     * 1e-12 x size any perpendicular direction is as good; above it, re-orthogonalise to w. */
    prox_vec3 e;
    if (rho > 1e-12 * fmax(fmax(fabs(t), rho), c->radius))
        e = prox_v3_normalize(prox_v3_reject(prox_v3_divs(rad, rho), w));
    else
        e = prox_v3_any_perp(w);
    if (t >= 0.0 && t <= h && rho <= c->radius) { /* inside: nearest of the base, top and side */
        double db = t, dt = h - t, ds = c->radius - rho;
        if (ds <= db && ds <= dt) {
            *n = e;
            *q = prox_v3_mad(x, ds, e);
            return -ds;
        }
        *n = db <= dt ? prox_v3_neg(w) : w;
        *q = prox_v3_mad(x, db <= dt ? -db : dt, w);
        return -(db <= dt ? db : dt);
    }
    /* outside: clamp axially and radially; the distance from the two offsets */
    double tc = t < 0.0 ? 0.0 : (t > h ? h : t);
    double rc = rho > c->radius ? c->radius : rho;
    double dist = prox_hypot2(t - tc, rho - rc);
    *q = prox_v3_mad(prox_v3_mad(c->base, tc, w), rc, e);
    *n = prox_v3_normalize(prox_v3_sub(x, *q));
    return dist;
}

PROX_API prox_signed_result prox_rcc_sph_signed_distance(const prox_rcc *a, const prox_sph *b)
{
    prox_signed_result r = {0};
    r.status = prox_valid2(prox_rcc_validate(a), prox_sph_validate(b));
    if (r.status != PROX_OK) return r;
    prox_vec3 q, n;
    double sdp = prox_rcc_point_signed(a, b->center, &q, &n);
    return prox_sph_signed_from_point(sdp, q, n, b);
}

PROX_API prox_distance_result prox_rcc_sph_distance(const prox_rcc *a, const prox_sph *b)
{
    prox_distance_result r = {0};
    r.status = prox_valid2(prox_rcc_validate(a), prox_sph_validate(b));
    if (r.status != PROX_OK) return r;
    prox_vec3 q, n;
    double sdp = prox_rcc_point_signed(a, b->center, &q, &n);
    double h = prox_v3_norm(a->axis);
    prox_vec3 ca = prox_v3_mad(a->base, 0.5, a->axis);
    double scale = fmax(fmax(prox_v3_dist(ca, b->center), fmax(h, 2.0 * a->radius)), 2.0 * b->radius);
    if (sdp - b->radius <= PROX_QUERY_REL_TOL * scale) { /* tangency within tol counts as touching */
        r.intersect = 1;
        r.p1 = r.p2 = sdp <= 0.0 ? b->center : q;
        return r;
    }
    return prox_sph_distance_from_point(sdp, q, n, b, prox_rcc_support(a, n));
}
