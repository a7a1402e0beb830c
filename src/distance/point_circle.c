/* Point to circle distance. Agarwal et al. (2016) Sec. 3.3 with the segment shrunk to a point:
 * the circle point is p1 = c + r (cos th u + sin th v) (Eq. (14) with s1 = 1), h(th) = |p1 - p|^2 and
 * f = h'(th) = 0 gives tan th = (p - c).v / (p - c).u: the radial projection of p onto the circle's
 * plane, scaled to radius r. The distance is hypot(height, rho - r) with rho the distance of p from the
 * axis. When rho = 0 (p on the axis) h is constant: set = 1 and the point at th = 0 is returned.
 * Input: radius > 0; the normal is normalised (any finite non-zero vector is accepted). */
#include "distance/stationary.h"

/* Relative size below which the distance from the axis counts as zero (the set case). */
#define AXIS_TOL (8.0 * 2.220446049250313e-16)

/* Validates a circle and returns it with a unit normal. */
static prox_status check_circle(const prox_circle *c, prox_circle *out)
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

PROX_API prox_prim_result prox_point_circle(prox_vec3 p, const prox_circle *c)
{
    prox_prim_result res = {0};
    prox_circle cc;
    if (!prox_v3_isfinite(p)) {
        res.status = PROX_EINVAL_NONFINITE;
        return res;
    }
    if ((res.status = check_circle(c, &cc)) != PROX_OK) return res;
    prox_fcircle f = prox_fcircle_make(cc.center, cc.normal, cc.radius);
    prox_vec3 d = prox_v3_sub(p, f.c);
    double h = prox_v3_dot(d, f.n), du = prox_v3_dot(d, f.u), dv = prox_v3_dot(d, f.v);
    double rho = hypot(du, dv);
    double scale = fmax(f.r, fmax(fabs(h), prox_v3_maxabs(f.c)));
    double th = 0.0;
    if (rho <= AXIS_TOL * scale) {
        res.set = 1; /* every circle point is equidistant */
    } else {
        th = angle_0_2pi(dv, du);
    }
    res.p1 = p;
    res.p2 = res.set ? prox_v3_mad(f.c, f.r, f.u)
                     : prox_v3_add(f.c, prox_v3_add(prox_v3_scale(f.u, f.r * (du / rho)),
                                                    prox_v3_scale(f.v, f.r * (dv / rho))));
    res.s2[0] = th;
    res.distance = hypot(h, rho - f.r);
    res.status = PROX_OK;
    return res;
}
