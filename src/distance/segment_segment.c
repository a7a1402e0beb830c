/* Segment to segment distance. Agarwal et al. (2016) Sec. 3, Eq. (11)-(12) with x = [t1, t2]:
 * h(t1, t2) = |a1 + t1 d1 - a2 - t2 d2|^2 is convex, so its minimum over [0,1]^2 is either the
 * interior stationary point (f1 = f2 = 0, the common perpendicular of the two lines) or lies on the
 * boundary of the square, i.e. an endpoint of one segment against the other segment.
 * Robustness:
 * - the interior point is solved with cross products, t1 = ((a2-a1) x d2).n / |n|^2 and
 *   t2 = ((a2-a1) x d1).n / |n|^2 with n = d1 x d2, instead of the normal equations whose determinant
 *   |d1|^2 |d2|^2 - (d1.d2)^2 cancels catastrophically for near-parallel segments;
 * - it is used only when |n| > PROX_TOL_PARALLEL |d1| |d2| and both parameters fall in [0, 1]; the four
 *   endpoint-to-segment candidates (point_segment.c) are always evaluated and the smallest distance
 *   wins, so an ill-conditioned interior point can only be replaced by an equally good boundary pair;
 * - zero-length segments have d = 0, hence n = 0: only endpoint candidates remain.
 * set = 1 when the segments are parallel (|n| <= PROX_TOL_PARALLEL |d1||d2|), both have positive length and their
 * projections on the common direction overlap in an interval of positive length. */
#include "distance/prim_common.h"

/* Sine of the angle below which two segments count as parallel. */
/* Replaces the best pair when (t1, t2) is closer. */
static void consider(prox_prim_result *best, const prox_segment *s1, double t1, const prox_segment *s2, double t2)
{
    prox_vec3 p = prox_prim_segment_point(s1, t1), q = prox_prim_segment_point(s2, t2);
    double d = prox_v3_dist(p, q);
    if (d < best->distance) {
        best->distance = d;
        best->p1 = p;
        best->p2 = q;
        best->s1[0] = t1;
        best->s2[0] = t2;
    }
}

/* Interior stationary point of h, when the lines are not parallel and it lies in [0,1]^2. */
static void interior_candidate(prox_prim_result *best, const prox_segment *s1, const prox_segment *s2)
{
    prox_vec3 d1 = prox_v3_sub(s1->b, s1->a), d2 = prox_v3_sub(s2->b, s2->a);
    prox_vec3 n = prox_v3_cross(d1, d2);
    double nn = prox_v3_norm(n);
    if (!(nn > PROX_TOL_PARALLEL * prox_v3_norm(d1) * prox_v3_norm(d2))) return;
    prox_vec3 r = prox_v3_sub(s2->a, s1->a);
    double t1 = prox_v3_dot(prox_v3_cross(r, d2), n) / (nn * nn);
    double t2 = prox_v3_dot(prox_v3_cross(r, d1), n) / (nn * nn);
    if (t1 >= 0.0 && t1 <= 1.0 && t2 >= 0.0 && t2 <= 1.0) consider(best, s1, t1, s2, t2);
}

/* Parallel segments of positive length whose projections overlap in a positive-length interval. */
static int parallel_overlap(const prox_segment *s1, const prox_segment *s2)
{
    prox_vec3 d1 = prox_v3_sub(s1->b, s1->a), d2 = prox_v3_sub(s2->b, s2->a);
    double l1 = prox_v3_norm(d1), l2 = prox_v3_norm(d2);
    if (!(l1 > 0.0) || !(l2 > 0.0)) return 0;
    if (prox_v3_norm(prox_v3_cross(d1, d2)) > PROX_TOL_PARALLEL * l1 * l2) return 0;
    double ua = prox_v3_dot(prox_v3_sub(s2->a, s1->a), d1) / (l1 * l1);
    double ub = prox_v3_dot(prox_v3_sub(s2->b, s1->a), d1) / (l1 * l1);
    double lo = fmax(fmin(ua, ub), 0.0), hi = fmin(fmax(ua, ub), 1.0);
    return hi > lo;
}

PROX_API prox_prim_result prox_segment_segment(const prox_segment *a, const prox_segment *b)
{
    prox_prim_result best = {0};
    if ((best.status = prox_prim_segment_check(a)) != PROX_OK || (best.status = prox_prim_segment_check(b)) != PROX_OK)
        return best;
    best.distance = INFINITY;
    interior_candidate(&best, a, b);
    /* Boundary of the parameter square: each endpoint against the other segment. */
    prox_prim_result e;
    e = prox_point_segment(a->a, b);
    consider(&best, a, 0.0, b, e.s2[0]);
    e = prox_point_segment(a->b, b);
    consider(&best, a, 1.0, b, e.s2[0]);
    e = prox_point_segment(b->a, a);
    consider(&best, a, e.s2[0], b, 0.0);
    e = prox_point_segment(b->b, a);
    consider(&best, a, e.s2[0], b, 1.0);
    best.set = parallel_overlap(a, b);
    best.status = PROX_OK;
    return best;
}
