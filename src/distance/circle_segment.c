/* P(C, L) of Agarwal et al. (2016) Sec. 3.3: circle to segment.
 * The stationary angles of the circle-to-line distance (the quartic g2 of Sec. 3.3) come from
 * prox_circle_line_stationary (core/circle_line.c, which derives them).
 * The segment minimum is the smallest of: the stationary angles whose foot t falls in the segment, and
 * the two endpoints against the circle (point_circle.c); the constrained minimum of
 * |P(th) - a - t(b - a)|^2 over t in [0, 1] is one of those. */
#include "distance/prim_common.h"

/* An endpoint (or axis point) x at parameter t against the circle; p1 on the circle, p2 = x. */
static void consider_point(prox_prim_result *best, const prox_fcircle *f, prox_vec3 x, double t)
{
    prox_circle cc = {f->c, f->n, f->r};
    prox_prim_result r = prox_point_circle(x, &cc);
    if (r.status == PROX_OK && r.distance < best->distance) {
        best->distance = r.distance;
        best->p1 = r.p2;
        best->p2 = x;
        best->s1[0] = r.s2[0];
        best->s2[0] = t;
        best->set = r.set;
    }
}

PROX_API prox_prim_result prox_circle_segment(const prox_circle *c, const prox_segment *s)
{
    prox_prim_result best = {0};
    prox_fcircle f;
    if ((best.status = prox_prim_circle_segment_check(c, s, &f)) != PROX_OK) return best;
    best.distance = INFINITY;
    prox_vec3 d = prox_v3_sub(s->b, s->a);
    double dd = prox_v3_norm2(d);
    if (dd > 0.0) {
        double th[4];
        int n = 0;
        prox_vec3 w = prox_v3_scale(d, 1.0 / sqrt(dd));
        int rc = prox_circle_line_stationary(&f, s->a, w, th, &n);
        if (rc < 0) { /* the quartic could not be solved: no answer rather than a wrong one */
            prox_prim_result fail = {0};
            fail.status = (prox_status)(-rc);
            return fail;
        }
        if (rc == 1) { /* segment on the axis */
            double t = prox_prim_clamp01(prox_v3_dot(prox_v3_sub(f.c, s->a), d) / dd);
            consider_point(&best, &f, prox_v3_mad(s->a, t, d), t);
            best.set = 1;
        }
        for (int i = 0; i < n; ++i) { /* interior stationary pairs whose foot lies on the segment */
            prox_vec3 x = prox_fcircle_point(&f, th[i]);
            double t = prox_v3_dot(prox_v3_sub(x, s->a), d) / dd;
            if (!(t >= 0.0 && t <= 1.0)) continue;
            prox_vec3 y = prox_v3_mad(s->a, t, d);
            double dist = prox_v3_dist(x, y);
            if (dist < best.distance) {
                best.distance = dist;
                best.p1 = x;
                best.p2 = y;
                best.s1[0] = th[i];
                best.s2[0] = t;
                best.set = 0;
            }
        }
    }
    consider_point(&best, &f, s->a, 0.0);
    consider_point(&best, &f, s->b, 1.0);
    best.status = PROX_OK;
    return best;
}
