/* P(D, L) of Agarwal et al. (2016) Sec. 3.2: solid disk to segment.
 * Disk point c + r s1 (cos th u + sin th v), s1 in [0, 1] (Eq. (14)); segment a + t (b - a).
 * Sec. 3.2 solves f_t = 0 for t, then g1 = g2 = 0 (linear in s1) and g3 (linear in cos th, sin th). For a
 * line that is not parallel to the disk's plane those interior solutions are the plane crossing itself
 * (distance 0); when the line is parallel to the plane (z1.z2 = 0), g1, g2 factor as in Eq. (15) and the
 * solutions form a curve (the segment's projection across the disk): the set case. When s1 falls
 * outside [0, 1] the paper switches to P(C, L) with the bounding circle (Sec. 3.3).
 * Implemented equivalently as:
 *  1. crossing: if the segment meets the plane (heights of a and b of opposite signs) at a point whose
 *     radial distance is <= r, the distance is 0 (a segment lying in the plane: 0 when it meets the disk);
 *  2. otherwise the minimum of the convex distance is attained with the disk point either interior (then
 *     the segment point is an endpoint, distance = point_disk) or on the rim (P(C, L), circle_segment.c):
 *     the smallest of point_disk(a), point_disk(b) and circle_segment(rim, s).
 * set = 1 when the segment (positive length) is parallel to the plane and its projection meets the open
 * disk (the minimum |h| is attained along a sub-segment), including a segment in the plane across the
 * disk. Parameters: s1 = (angle, radial distance in length units) on the disk, s2[0] = t.
 * Input: radius > 0, normal finite non-zero (normalised). */
#include "distance/prim_common.h"

/* Radial distance of the projection of x from the centre (and its angle) in the disk frame. */
static double radial(const prox_fcircle *f, prox_vec3 x, double *ang)
{
    prox_prim_local l = prox_prim_local_of(f, x);
    *ang = prox_prim_local_angle(&l);
    return l.rho;
}

/* Distance 0 when the segment meets the disk (step 1); returns 1 and fills res then. */
static int crossing(const prox_fcircle *f, const prox_segment *s, prox_prim_result *res)
{
    prox_vec3 d = prox_v3_sub(s->b, s->a);
    double ha = prox_v3_dot(prox_v3_sub(s->a, f->c), f->n), hb = prox_v3_dot(prox_v3_sub(s->b, f->c), f->n);
    if ((ha > 0.0 && hb > 0.0) || (ha < 0.0 && hb < 0.0)) return 0;
    double t;
    if (ha == hb) { /* both zero: in the plane; the point nearest the centre */
        double dd = prox_v3_norm2(d);
        t = prox_prim_clamp01(dd > 0.0 ? prox_v3_dot(prox_v3_sub(f->c, s->a), d) / dd : 0.0);
    } else {
        t = ha / (ha - hb);
    }
    prox_vec3 x = prox_prim_segment_point(s, t);
    double ang, rho = radial(f, x, &ang);
    if (!(rho <= f->r)) return 0;
    res->distance = 0.0;
    res->p1 = prox_v3_mad(x, -prox_v3_dot(prox_v3_sub(x, f->c), f->n), f->n);
    res->p2 = x;
    res->s1[0] = ang;
    res->s1[1] = rho;
    res->s2[0] = t;
    res->set = ha == hb && prox_v3_norm2(d) > 0.0 && rho < f->r;
    return 1;
}

/* Segment parallel to the plane whose projection meets the open disk. */
static int parallel_over_disk(const prox_fcircle *f, const prox_segment *s)
{
    prox_vec3 d = prox_v3_sub(s->b, s->a);
    double len = prox_v3_norm(d);
    if (!(len > 0.0) || !(fabs(prox_v3_dot(d, f->n)) <= PROX_TOL_PARALLEL * len)) return 0;
    prox_vec3 dp = prox_v3_reject(d, f->n), ap = prox_v3_reject(prox_v3_sub(s->a, f->c), f->n);
    double dd = prox_v3_norm2(dp), t = prox_prim_clamp01(dd > 0.0 ? -prox_v3_dot(ap, dp) / dd : 0.0);
    return prox_v3_norm(prox_v3_mad(ap, t, dp)) < f->r;
}

PROX_API prox_prim_result prox_disk_segment(const prox_disk *d, const prox_segment *s)
{
    prox_prim_result res = {0};
    prox_fcircle f;
    if ((res.status = prox_prim_circle_segment_check(d, s, &f)) != PROX_OK) return res;
    prox_disk dk = {f.c, f.n, f.r}; /* unit normal */
    if (crossing(&f, s, &res)) return res; /* status is PROX_OK */
    /* Step 2: endpoints against the disk, the segment against the rim. */
    prox_prim_result best = prox_circle_segment(&dk, s);
    if (best.status != PROX_OK) return best; /* the rim's quartic failed (PROX_ENUMERIC) */
    best.s1[1] = f.r;
    prox_vec3 ends[2] = {s->a, s->b};
    for (int i = 0; i < 2; ++i) {
        prox_prim_result e = prox_point_disk(ends[i], &dk);
        if (e.status == PROX_OK && e.distance < best.distance) {
            best.distance = e.distance;
            best.p1 = e.p2;
            best.p2 = e.p1;
            best.s1[0] = e.s2[0];
            best.s1[1] = e.s2[1];
            best.s2[0] = (double)i;
        }
    }
    best.set = parallel_over_disk(&f, s);
    best.status = PROX_OK;
    return best;
}
