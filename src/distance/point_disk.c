/* Point to solid disk distance. Agarwal et al. (2016) Sec. 3.2, Eq. (14): the disk point is
 * c + r s1 (cos th u + sin th v), s1 in [0, 1]. For a point, f = 0 gives th = the angle of p's radial
 * projection and s1 = rho / r; when s1 > 1 the constraint is active and the closest point is on the
 * rim (the P(C, .) fallback of Sec. 3.2). The minimiser is unique (the disk is convex), so set = 0.
 * Parameters of p2: s2[0] = angle (0 when p projects onto the centre), s2[1] = radial distance in length
 * units. Input: radius > 0; the normal is normalised. */
#include "distance/prim_common.h"

PROX_API prox_prim_result prox_point_disk(prox_vec3 p, const prox_disk *d)
{
    prox_prim_result res = {0};
    prox_fcircle f;
    if (!prox_v3_isfinite(p)) {
        res.status = PROX_EINVAL_NONFINITE;
        return res;
    }
    if ((res.status = prox_prim_circle_frame(d, &f)) != PROX_OK) return res;
    prox_prim_local l = prox_prim_local_of(&f, p);
    double h = l.h, du = l.du, dv = l.dv, rho = l.rho;
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
    res.s2[0] = prox_prim_local_angle(&l);
    res.status = PROX_OK;
    return res;
}
