/* Point to circle distance. Agarwal et al. (2016) Sec. 3.3 with the segment shrunk to a point:
 * the circle point is p1 = c + r (cos th u + sin th v) (Eq. (14) with s1 = 1), h(th) = |p1 - p|^2 and
 * f = h'(th) = 0 gives tan th = (p - c).v / (p - c).u: the radial projection of p onto the circle's
 * plane, scaled to radius r. The distance is hypot(height, rho - r) with rho the distance of p from the
 * axis. When rho = 0 (p on the axis) h is constant: set = 1 and the point at th = 0 is returned.
 * Input: radius > 0; the normal is normalised (any finite non-zero vector is accepted). */
#include "distance/prim_common.h"

PROX_API prox_prim_result prox_point_circle(prox_vec3 p, const prox_circle *c)
{
    prox_prim_result res = {0};
    prox_fcircle f;
    if (!prox_v3_isfinite(p)) {
        res.status = PROX_EINVAL_NONFINITE;
        return res;
    }
    if ((res.status = prox_prim_circle_frame(c, &f)) != PROX_OK) return res;
    prox_prim_local l = prox_prim_local_of(&f, p);
    double h = l.h, du = l.du, dv = l.dv, rho = l.rho;
    double scale = fmax(f.r, fmax(fabs(h), prox_v3_maxabs(f.c)));
    double th = 0.0;
    if (rho <= PROX_TOL_AXIS * scale) {
        res.set = 1; /* every circle point is equidistant */
    } else {
        th = prox_prim_angle(dv, du);
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
