/* Internal (core): points of a plane and the closest-point pieces both support-function engines use
 * to pair two support sets seen along a normal (src/sat/sup_engine.c for the cylinder, box and
 * sphere pairs, src/sat/convex.c for any convex pair). */
#ifndef PROX_CORE_PLANE2_H
#define PROX_CORE_PLANE2_H

#include <math.h>

#include "prox/vec3.h"

typedef struct prox_v2 {
    double x, y;
} prox_v2;

static inline prox_v2 prox_v2_sub(prox_v2 a, prox_v2 b) { prox_v2 r = {a.x - b.x, a.y - b.y}; return r; }
static inline prox_v2 prox_v2_mad(prox_v2 a, double s, prox_v2 b) { prox_v2 r = {a.x + s * b.x, a.y + s * b.y}; return r; }
static inline double prox_v2_dot(prox_v2 a, prox_v2 b) { return a.x * b.x + a.y * b.y; }
static inline double prox_v2_cross(prox_v2 a, prox_v2 b) { return a.x * b.y - a.y * b.x; }
static inline double prox_v2_norm(prox_v2 a) { return prox_hypot2(a.x, a.y); }

/* Closest point of the segment [a, b] to q. */
static inline prox_v2 prox_v2_seg_closest(prox_v2 a, prox_v2 b, prox_v2 q)
{
    prox_v2 e = prox_v2_sub(b, a);
    double ee = prox_v2_dot(e, e), t = ee > 0.0 ? prox_v2_dot(prox_v2_sub(q, a), e) / ee : 0.0;
    return prox_v2_mad(a, t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t), e);
}

/* Convex hull of p[0..n-1] (n <= PROX_V2_HULL_MAX) by Andrew's monotone chain: its corners'
 * indices into h (room for 2 n + 2), counter-clockwise, collinear points dropped; returns how many
 * (0 for n = 0; a segment or a point when the points are collinear). */
#define PROX_V2_HULL_MAX 32
static inline int prox_v2_hull(const prox_v2 *p, int n, int *h)
{
    int ord[PROX_V2_HULL_MAX];
    for (int i = 0; i < n; ++i) ord[i] = i;
    for (int i = 1; i < n; ++i) /* insertion sort by (x, y) */
        for (int j = i; j > 0 && (p[ord[j]].x < p[ord[j - 1]].x ||
                                  (p[ord[j]].x == p[ord[j - 1]].x && p[ord[j]].y < p[ord[j - 1]].y)); --j) {
            int t = ord[j];
            ord[j] = ord[j - 1], ord[j - 1] = t;
        }
    int m = 0;
    for (int pass = 0; pass < 2; ++pass) {
        int start = m;
        for (int ii = 0; ii < n; ++ii) {
            int i = pass == 0 ? ord[ii] : ord[n - 1 - ii];
            while (m >= start + 2 && prox_v2_cross(prox_v2_sub(p[h[m - 1]], p[h[m - 2]]), prox_v2_sub(p[i], p[h[m - 2]])) <= 0.0) --m;
            h[m++] = i;
        }
        --m; /* the last point starts the other chain */
    }
    if (m < 1 && n > 0) m = 1, h[0] = ord[0];
    return m < 0 ? 0 : m;
}

/* Closest point to q of the convex polygon v[0..nv-1] in cyclic order, either orientation (a point
 * for nv = 1, a segment for nv = 2); q itself when inside. */
static inline prox_v2 prox_v2_poly_closest(const prox_v2 *v, int nv, prox_v2 q)
{
    if (nv == 1) return v[0];
    if (nv == 2) return prox_v2_seg_closest(v[0], v[1], q);
    int pos = 1, neg = 1;
    for (int i = 0; i < nv; ++i) {
        double c = prox_v2_cross(prox_v2_sub(v[(i + 1) % nv], v[i]), prox_v2_sub(q, v[i]));
        pos &= c >= 0.0;
        neg &= c <= 0.0;
    }
    if (pos || neg) return q;
    prox_v2 best = v[0];
    double bd = INFINITY;
    for (int i = 0; i < nv; ++i) {
        prox_v2 x = prox_v2_seg_closest(v[i], v[(i + 1) % nv], q);
        double d = prox_v2_norm(prox_v2_sub(x, q));
        if (d < bd) bd = d, best = x;
    }
    return best;
}

/* Keeps (x, y) in (*bx, *by) when closer than the best pair so far, *bd. */
static inline void prox_v2_pair_offer(prox_v2 x, prox_v2 y, prox_v2 *bx, prox_v2 *by, double *bd)
{
    double d = prox_v2_norm(prox_v2_sub(x, y));
    if (d < *bd) *bd = d, *bx = x, *by = y;
}

#endif
