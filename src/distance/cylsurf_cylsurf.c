/* P(S, S) of Agarwal et al. (2016) Sec. 3.1: two infinite cylindrical surfaces.
 * Eq. (13): g1 = m(th1) k, g2 = j(th2) k. Case (a) (k != 0, m = j = 0) gives the isolated stationary
 * points: the surface points on the common perpendicular of the two axes, i.e. the feet of the axes'
 * common perpendicular moved by r1 and r2 along it; case (b) (k = 0) is the curve of intersection.
 * prox keeps the case (a) pair and reports the SIGNED value (axis distance) - r1 - r2 measured along the
 * common perpendicular, which is what the cylinder query needs (negative: the infinite cylinders
 * interpenetrate along that line).
 * Feet of the common perpendicular (t1 on a, t2 on b, unit axes d1, d2, n = d1 x d2, D = b.base - a.base):
 *   t1 = ((D x d2).n) / |n|^2, t2 = ((D x d1).n) / |n|^2, signed axis distance (D.n)/|n|;
 * cross products rather than the normal equations (no cancellation in the determinant).
 * Parallel axes (|n| <= PROX_TOL_PARALLEL; Sec. 3.1 "q1 = q2 = 0"): f3 = -f4 and every axial position is a
 * solution: set = 1, feet at a.base and its projection on b's axis.
 * Parameters: s[0] = axial parameter of the foot (length units), s[1] = angle of the surface point in
 * the frame prox_fcircle_make(base, dir, r). Input: radii > 0, dirs finite non-zero (normalised); heights
 * are ignored. */
#include "distance/prim_common.h"

/* Angle in [0, 2pi) of direction e in the frame of the circle with unit normal w. */
static double frame_angle(prox_vec3 w, prox_vec3 e)
{
    prox_fcircle f = prox_fcircle_make(prox_v3(0, 0, 0), w, 1.0);
    return prox_prim_angle(prox_v3_dot(e, f.v), prox_v3_dot(e, f.u));
}

PROX_API prox_prim_result prox_cylsurf_cylsurf_inf(const prox_cylsurf *a, const prox_cylsurf *b)
{
    prox_prim_result res = {0};
    prox_vec3 d1, d2;
    if ((res.status = prox_prim_cylsurf_check(a, 0, &d1)) != PROX_OK ||
        (res.status = prox_prim_cylsurf_check(b, 0, &d2)) != PROX_OK)
        return res;
    prox_vec3 D = prox_v3_sub(b->base, a->base);
    if (!prox_v3_isfinite(D)) {
        res.status = PROX_EINVAL_NONFINITE;
        return res;
    }
    prox_vec3 n = prox_v3_cross(d1, d2), e;
    double nn = prox_v3_norm(n), t1, t2, axis_dist;
    if (nn <= PROX_TOL_PARALLEL) { /* parallel axes: a continuum of feet, representative at a.base */
        t1 = 0.0;
        t2 = -prox_v3_dot(D, d2);
        prox_vec3 perp = prox_v3_reject(D, d2); /* from a.base to its foot on b's axis */
        axis_dist = prox_v3_norm(perp);
        e = axis_dist > 0.0 ? prox_v3_scale(perp, 1.0 / axis_dist) : prox_v3_any_perp(d1);
        res.set = 1;
    } else {
        t1 = prox_v3_dot(prox_v3_cross(D, d2), n) / (nn * nn);
        t2 = prox_v3_dot(prox_v3_cross(D, d1), n) / (nn * nn);
        double sd = prox_v3_dot(D, n) / nn;
        e = prox_v3_scale(n, (sd >= 0.0 ? 1.0 : -1.0) / nn);
        axis_dist = fabs(sd);
    }
    prox_vec3 f1 = prox_v3_mad(a->base, t1, d1), f2 = prox_v3_mad(b->base, t2, d2);
    res.p1 = prox_v3_mad(f1, a->radius, e);
    res.p2 = prox_v3_mad(f2, -b->radius, e);
    res.s1[0] = t1;
    res.s2[0] = t2;
    res.s1[1] = frame_angle(d1, e);
    res.s2[1] = frame_angle(d2, prox_v3_neg(e));
    res.distance = axis_dist - a->radius - b->radius;
    res.status = PROX_OK;
    return res;
}
