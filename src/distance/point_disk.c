/* Point to solid disk distance. Agarwal et al. (2016) Sec. 3.2, Eq. (14): the disk point is
 * c + r s1 (cos th u + sin th v), s1 in [0, 1]. For a point, f = 0 gives th = the angle of p's radial
 * projection and s1 = rho / r; when s1 > 1 the constraint is active and the closest point is on the
 * rim (the P(C, .) fallback of Sec. 3.2). The minimiser is unique (the disk is convex), so set = 0.
 * Parameters of p2: s2[0] = angle (0 when p projects onto the centre), s2[1] = radial distance in length
 * units. Input: radius > 0; the normal is normalised. */
#include "distance/stationary.h"

/* Validates a disk and returns it with a unit normal. */
static prox_status check_disk(const prox_disk *c, prox_disk *out)
{
    if (!c) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(c->center) || !prox_v3_isfinite(c->normal) || !isfinite(c->radius))
        return PROX_EINVAL_NONFINITE;
    if (!(c->radius > 0.0)) return PROX_EINVAL_RADIUS;
    double n = prox_v3_norm(c->normal);
    if (!(n > 0.0)) return PROX_EINVAL_AXIS;
    *out = *c;
    out->normal = prox_v3(c->normal.x / n, c->normal.y / n, c->normal.z / n);
    return PROX_OK;
}

/* Angle of (x, y) in [0, 2pi). */
static double angle_0_2pi(double y, double x)
{
    double a = atan2(y, x);
    if (a < 0.0) a += 2.0 * PROX_PI;
    return a < 2.0 * PROX_PI ? a : 0.0;
}

PROX_API prox_prim_result prox_point_disk(prox_vec3 p, const prox_disk *d)
{
    prox_prim_result res = {0};
    prox_disk dd;
    if (!prox_v3_isfinite(p)) {
        res.status = PROX_EINVAL_NONFINITE;
        return res;
    }
    if ((res.status = check_disk(d, &dd)) != PROX_OK) return res;
    prox_fcircle f = prox_fcircle_make(dd.center, dd.normal, dd.radius);
    prox_vec3 q = prox_v3_sub(p, f.c);
    double h = prox_v3_dot(q, f.n), du = prox_v3_dot(q, f.u), dv = prox_v3_dot(q, f.v);
    double rho = hypot(du, dv);
    res.p1 = p;
    if (rho <= f.r) { /* projection inside: the foot of the perpendicular */
        res.p2 = prox_v3_mad(p, -h, f.n);
        res.distance = fabs(h);
        res.s2[1] = rho;
    } else { /* rim point in the direction of p */
        double k = f.r / rho;
        res.p2 = prox_v3_add(f.c, prox_v3_add(prox_v3_scale(f.u, du * k), prox_v3_scale(f.v, dv * k)));
        res.distance = hypot(h, rho - f.r);
        res.s2[1] = f.r;
    }
    res.s2[0] = rho > 0.0 ? angle_0_2pi(dv, du) : 0.0;
    res.status = PROX_OK;
    return res;
}
