/* Point to segment distance: the foot of the perpendicular, clamped to the segment.
 * Agarwal et al. (2016) Sec. 3, Eq. (11)-(12) with one parameter t: h(t) = |a + t(b - a) - p|^2 is a
 * convex quadratic, f = h'(t) = 0 is linear in t, and the constrained minimiser is its root clamped to
 * [0, 1]. A zero-length segment is the point a (t = 0). */
#include "distance/prim_common.h"

/* Foot parameter of p on the segment, clamped to [0, 1]; 0 for a zero-length segment. */
static double foot_param(prox_vec3 p, prox_vec3 a, prox_vec3 d)
{
    double dd = prox_v3_norm2(d);
    if (!(dd > 0.0)) return 0.0;
    double t = prox_v3_dot(prox_v3_sub(p, a), d) / dd;
    return prox_prim_clamp01(t); /* NaN -> 0 also catches dd underflow giving nonsense */
}

PROX_API prox_prim_result prox_point_segment(prox_vec3 p, const prox_segment *s)
{
    prox_prim_result r = {0};
    if ((r.status = prox_prim_segment_check(s)) != PROX_OK) return r;
    if (!prox_v3_isfinite(p)) {
        r.status = PROX_EINVAL_NONFINITE;
        return r;
    }
    double t = foot_param(p, s->a, prox_v3_sub(s->b, s->a));
    prox_vec3 q = prox_prim_segment_point(s, t);
    r.p1 = p;
    r.p2 = q;
    r.s2[0] = t;
    r.distance = prox_v3_dist(p, q);
    r.status = PROX_OK;
    return r;
}
