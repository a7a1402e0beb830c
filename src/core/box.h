/* Internal (core): the one prepared representation of a box (BOX, and RPP as the box it describes):
 * centre m, unit edge directions a[k], half-lengths h[k]. Local coordinates l_k = (x - m).a_k make
 * the box the product of intervals [-h_k, h_k]. Support function h(d) = d.m + sum_k h_k |d.a_k|. */
#ifndef PROX_CORE_BOX_H
#define PROX_CORE_BOX_H

#include <math.h>

#include "core/tol.h"
#include "prox/shapes.h"

/* a / s by components: unlike a * (1 / s) it stays finite for subnormal s (a
 * fuzz regression input: a subnormal edge length made 1 / s overflow). */
static inline prox_vec3 prox_v3_divs(prox_vec3 a, double s) { return prox_v3(a.x / s, a.y / s, a.z / s); }

typedef struct prox_bframe {
    prox_vec3 m;    /* centre */
    prox_vec3 a[3]; /* unit edge directions */
    double h[3];    /* half edge lengths */
} prox_bframe;

/* Frame of a validated box. */
static inline prox_bframe prox_bframe_make(const prox_box *b)
{
    prox_bframe f;
    f.m = b->corner;
    for (int k = 0; k < 3; ++k) {
        double len = prox_v3_norm(b->edge[k]);
        f.a[k] = prox_v3_divs(b->edge[k], len);
        f.h[k] = 0.5 * len;
        f.m = prox_v3_mad(f.m, 0.5, b->edge[k]);
    }
    return f;
}

/* Local coordinates of x. */
static inline void prox_bframe_local(const prox_bframe *f, prox_vec3 x, double l[3])
{
    prox_vec3 d = prox_v3_sub(x, f->m);
    for (int k = 0; k < 3; ++k) l[k] = prox_v3_dot(d, f->a[k]);
}

/* Point at local coordinates l. */
static inline prox_vec3 prox_bframe_point(const prox_bframe *f, const double l[3])
{
    prox_vec3 p = f->m;
    for (int k = 0; k < 3; ++k) p = prox_v3_mad(p, l[k], f->a[k]);
    return p;
}

/* Vertex i (bit k of i: + or - h_k along a_k). */
static inline prox_vec3 prox_bframe_vertex(const prox_bframe *f, int i)
{
    double l[3];
    for (int k = 0; k < 3; ++k) l[k] = (i >> k & 1) ? f->h[k] : -f->h[k];
    return prox_bframe_point(f, l);
}

/* Edge j of 12: direction k = j / 4, the other two signs from bits of j % 4. */
static inline void prox_bframe_edge(const prox_bframe *f, int j, prox_vec3 *p, prox_vec3 *q)
{
    int k = j / 4, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    double l[3];
    l[k1] = (j & 1) ? f->h[k1] : -f->h[k1];
    l[k2] = (j & 2) ? f->h[k2] : -f->h[k2];
    l[k] = -f->h[k];
    *p = prox_bframe_point(f, l);
    l[k] = f->h[k];
    *q = prox_bframe_point(f, l);
}

/* Support function of the box: max over the box of d.x. */
static inline double prox_bframe_support(const prox_bframe *f, prox_vec3 d)
{
    return prox_v3_dot(d, f->m) + f->h[0] * fabs(prox_v3_dot(d, f->a[0])) + f->h[1] * fabs(prox_v3_dot(d, f->a[1])) +
           f->h[2] * fabs(prox_v3_dot(d, f->a[2]));
}

/* Closest point of the solid box to x; *dist receives the distance computed in local coordinates. */
static inline prox_vec3 prox_bframe_closest(const prox_bframe *f, prox_vec3 x, double *dist)
{
    double l[3], d2 = 0.0, e[3];
    prox_bframe_local(f, x, l);
    for (int k = 0; k < 3; ++k) {
        double c = l[k] < -f->h[k] ? -f->h[k] : (l[k] > f->h[k] ? f->h[k] : l[k]);
        e[k] = l[k] - c;
        l[k] = c;
    }
    d2 = prox_v3_norm(prox_v3(e[0], e[1], e[2]));
    if (dist) *dist = d2;
    return prox_bframe_point(f, l);
}

/* Signed distance of x to the box (negative inside), the boundary point q nearest to x and the outward
 * unit normal n at q, with x = q + sd n. */
static inline double prox_bframe_signed(const prox_bframe *f, prox_vec3 x, prox_vec3 *q, prox_vec3 *n)
{
    double l[3];
    prox_bframe_local(f, x, l);
    int inside = 1;
    for (int k = 0; k < 3; ++k)
        if (fabs(l[k]) > f->h[k]) inside = 0;
    if (!inside) {
        double d;
        *q = prox_bframe_closest(f, x, &d);
        *n = prox_v3_normalize(prox_v3_sub(x, *q));
        return d;
    }
    int kb = 0; /* nearest face: largest |l_k| - h_k (least negative) */
    for (int k = 1; k < 3; ++k)
        if (fabs(l[k]) - f->h[k] > fabs(l[kb]) - f->h[kb]) kb = k;
    double sd = fabs(l[kb]) - f->h[kb];
    *n = l[kb] >= 0.0 ? f->a[kb] : prox_v3_neg(f->a[kb]);
    l[kb] = l[kb] >= 0.0 ? f->h[kb] : -f->h[kb];
    *q = prox_bframe_point(f, l);
    return sd;
}

/* Clips the segment p + s (q - p), s in [0,1], to the box enlarged by tol (Liang-Barsky in local
 * coordinates). Returns 1 and the parameter interval when they meet. */
static inline int prox_bframe_clip_segment(const prox_bframe *f, prox_vec3 p, prox_vec3 q, double tol, double *s0,
                                           double *s1)
{
    double lp[3], lq[3], lo = 0.0, hi = 1.0;
    prox_bframe_local(f, p, lp);
    prox_bframe_local(f, q, lq);
    for (int k = 0; k < 3; ++k) {
        double d = lq[k] - lp[k], a = -f->h[k] - tol, b = f->h[k] + tol;
        if (d == 0.0) {
            if (lp[k] < a || lp[k] > b) return 0;
            continue;
        }
        double inv = 1.0 / d, t0 = (a - lp[k]) * inv, t1 = (b - lp[k]) * inv; /* one division per slab */
        if (t0 > t1) {
            double t = t0;
            t0 = t1;
            t1 = t;
        }
        if (t0 > lo) lo = t0;
        if (t1 < hi) hi = t1;
        if (lo > hi) return 0;
    }
    *s0 = lo;
    *s1 = hi;
    return 1;
}

/* Clips the segment p + s (q - p), s in [0,1], to a solid enlarged by tol: 1 and the parameter
 * interval [s0, s1] when they meet. */
typedef int (*prox_clip_fn)(const void *solid, prox_vec3 p, prox_vec3 q, double tol, double *s0, double *s1);

/* Does an edge of the box E meet the solid (enlarged by tol)? Edges in order 0..11; *x receives the
 * midpoint of the first meeting edge's clipped part. */
static inline int prox_bframe_edges_meet(const prox_bframe *E, prox_clip_fn clip, const void *solid, double tol,
                                         prox_vec3 *x)
{
    for (int j = 0; j < 12; ++j) {
        prox_vec3 p, q;
        double s0, s1;
        prox_bframe_edge(E, j, &p, &q);
        if (clip(solid, p, q, tol, &s0, &s1)) {
            *x = prox_v3_mad(p, 0.5 * (s0 + s1), prox_v3_sub(q, p));
            return 1;
        }
    }
    return 0;
}

/* Closest points of segments [p1,q1] and [p2,q2] (Ericson, Real-Time Collision Detection 5.1.9,
 * clamped in the order s, t, s; near-parallel segments also try their endpoints, see below);
 * returns the distance, *c1 and *c2 the points. */
static inline double prox_seg_seg(prox_vec3 p1, prox_vec3 q1, prox_vec3 p2, prox_vec3 q2, prox_vec3 *c1, prox_vec3 *c2)
{
    prox_vec3 d1 = prox_v3_sub(q1, p1), d2 = prox_v3_sub(q2, p2), r = prox_v3_sub(p1, p2);
    double a = prox_v3_dot(d1, d1), e = prox_v3_dot(d2, d2), fb = prox_v3_dot(d2, r);
    double s = 0.0, t = 0.0;
    if (a <= 0.0 && e <= 0.0) {
        s = t = 0.0;
    } else if (a <= 0.0) {
        t = fb / e;
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    } else {
        double c = prox_v3_dot(d1, r);
        if (e <= 0.0) {
            s = -c / a;
            s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
        } else {
            double b = prox_v3_dot(d1, d2);
            double denom = a * e - b * b;
            /* Non-parallel: unconstrained s clamped; parallel (denom tiny): any s, take 0. */
            if (denom > PROX_TOL_SEG_PARALLEL2 * a * e) {
                s = (b * fb - c * e) / denom;
                s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
            }
            t = (b * s + fb) / e;
            if (t < 0.0) {
                t = 0.0;
                s = -c / a;
                s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
            } else if (t > 1.0) {
                t = 1.0;
                s = (b - c) / a;
                s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
            }
        }
    }
    *c1 = prox_v3_mad(p1, s, d1);
    *c2 = prox_v3_mad(p2, t, d2);
    double best = prox_v3_dist(*c1, *c2);
    /* Within 1e-3 rad of parallel, s above moves by ~eps / angle^2 with rounding (or is set to 0),
     * and away from the closest approach the distance changes at angle x |ds| x length per unit of
     * s: up to ~1e-8 x length (a capsule lower bound built on it pruned a true minimum in
     * test_box_rcc). The minimum there is at an endpoint of one segment, or on the valley of the
     * closest approach where the computed pair is off only to second order: so the four
     * endpoint-to-segment pairs are offered as well, and the nearest pair of all is returned. */
    if (a > 0.0 && e > 0.0) {
        double b = prox_v3_dot(d1, d2);
        if (a * e - b * b <= PROX_TOL_WELL_COND2 * a * e) {
            prox_vec3 ends[4] = {p1, q1, p2, q2};
            for (int k = 0; k < 4; ++k) {
                int on1 = k < 2; /* the endpoint is on segment 1: project it onto segment 2 */
                prox_vec3 o = on1 ? p2 : p1, dd = on1 ? d2 : d1;
                double u = prox_v3_dot(prox_v3_sub(ends[k], o), dd) / (on1 ? e : a);
                u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
                prox_vec3 x = prox_v3_mad(o, u, dd);
                double dk = prox_v3_dist(ends[k], x);
                if (dk < best) {
                    best = dk;
                    *c1 = on1 ? ends[k] : x;
                    *c2 = on1 ? x : ends[k];
                }
            }
        }
    }
    return best;
}

/* Largest absolute coordinate and size of a box, for scales. */
static inline double prox_bframe_size(const prox_bframe *f)
{
    double s = f->h[0];
    if (f->h[1] > s) s = f->h[1];
    if (f->h[2] > s) s = f->h[2];
    return 2.0 * s;
}


#endif
