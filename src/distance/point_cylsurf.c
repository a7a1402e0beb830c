/* Point to the finite lateral surface of a cylinder. Agarwal et al. (2016) Sec. 3.1: a surface point is
 * base + z dir + r (cos th u + sin th v) with z in [0, height]; h = |p1 - p|^2 gives, as in Sec. 3.1,
 * f_z = 0 linear in z (the axial coordinate of p, clamped to [0, height]) and f_th = 0 the angle of p's
 * radial component. The distance is hypot(z_p - z, rho - r). When p is on the axis (rho = 0) every
 * angle is equidistant: set = 1, angle 0 returned.
 * Parameters of p2: s2[0] = axial parameter z (length units), s2[1] = angle in the frame of
 * prox_fcircle_make(base, dir, r). Input: radius > 0, height >= 0 (finite); dir is normalised. */
#include "distance/prim_common.h"

PROX_API prox_prim_result prox_point_cylsurf(prox_vec3 p, const prox_cylsurf *s)
{
    prox_prim_result res = {0};
    prox_vec3 w;
    if (!prox_v3_isfinite(p)) {
        res.status = PROX_EINVAL_NONFINITE;
        return res;
    }
    if ((res.status = prox_prim_cylsurf_check(s, 1, &w)) != PROX_OK) return res;
    prox_fcircle f = prox_fcircle_make(s->base, w, s->radius);
    prox_prim_local l = prox_prim_local_of(&f, p);
    double z = l.h, du = l.du, dv = l.dv, rho = l.rho;
    double zc = z < 0.0 ? 0.0 : (z > s->height ? s->height : z);
    double scale = fmax(f.r, fmax(fabs(z), fmax(s->height, prox_v3_maxabs(f.c))));
    double cu = 1.0, cv = 0.0, th = 0.0;
    if (rho <= PROX_TOL_AXIS * scale) {
        res.set = 1;
    } else {
        cu = du / rho;
        cv = dv / rho;
        th = prox_prim_angle(dv, du);
    }
    prox_vec3 axis_pt = prox_v3_mad(f.c, zc, f.n);
    res.p1 = p;
    res.p2 = prox_v3_add(axis_pt, prox_v3_add(prox_v3_scale(f.u, f.r * cu), prox_v3_scale(f.v, f.r * cv)));
    res.s2[0] = zc;
    res.s2[1] = th;
    res.distance = hypot(z - zc, rho - f.r);
    res.status = PROX_OK;
    return res;
}
