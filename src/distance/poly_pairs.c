/* Two convex polytopes (BOX, RPP, RHP/HEX, WED, ARB): exact distance with witness points and exact
 * penetration depth (docs/algorithms/polytopes.md).
 *
 * Separation along a unit n (from A towards B): s(n) = min_B n.y - max_A n.x. The signed distance is
 * max over unit n of s(n). The Minkowski difference B - A is a polytope whose facet normals are among
 * A's face normals, -(B's face normals) and the cross products of an edge direction of A with one of B
 * (both signs); when the solids overlap, the depth min_n -s(n) is attained at a facet normal (the
 * nearest boundary point of B - A to the origin lies in a facet), and any other direction bounds it
 * from above, so the least depth over these candidates is exact. Its witnesses: the two support
 * features F_A(n), F_B(-n) have projections on the plane orthogonal to n that meet (the foot sd n lies
 * in the facet F_B(-n) - F_A(n)); a point of that meeting, lifted onto each feature, gives p1 and p2.
 *
 * Disjoint solids: the closest pair of two convex polytopes can be chosen vertex-face, face-vertex or
 * edge-edge, so the least of those distances is exact; candidates are skipped by the lower bound of
 * their projections on a separating axis. Certificate: s(n) at n = (p2 - p1) / |p2 - p1|.
 *
 * Fast path (tried first; the enumeration above is its exact fallback): GJK on the corners
 * (poly_gjk.c) gives p1 and p2 as convex combinations of corners; a disjoint answer is accepted only
 * when the gap s(n) along their direction (or their features' contact direction) proves it to
 * PROX_TOL_CERT S, an overlap only when the common point lies in both solids to PROX_TOL_TOUCH S. The
 * depth of an overlapping pair keeps every candidate axis that can matter: all face normals (the
 * support loop stops once an axis cannot come within the touch band of the best so far) and the edge
 * pairs whose Gauss-map arcs cross (Gregorius, GDC 2013): only those cross products are facet normals
 * of B - A, and their separation is read off the two edges' corners. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "core/tol.h"
#include "distance/poly_internal.h"

/* A polytope placed in the pair's frame (A's reference point at the origin). */
typedef struct placed {
    const prox_polytope *p;
    prox_vec3 v[PROX_POLY_MAXV];
    double d[PROX_POLY_MAXF];
    prox_vec3 u[PROX_POLY_MAXE]; /* distinct unit edge directions */
    int nu;
} placed;

/* Corners and planes moved by off and multiplied by u (a power of two: exact), so that the pair's
 * scale becomes 1 .. 2 and no product of the solvers over- or underflows (a segment pair's |d1|^2 |d2|^2
 * at sizes 1e-90 is 1e-360). The edge directions wait for place_dirs (only the enumeration needs them). */
static void place(placed *P, const prox_polytope *p, prox_vec3 off, double u)
{
    P->p = p;
    for (int i = 0; i < p->nv; ++i) P->v[i] = prox_v3_scale(prox_v3_add(p->v[i], off), u);
    for (int f = 0; f < p->nf; ++f) P->d[f] = (p->d[f] + prox_v3_dot(p->n[f], off)) * u;
    P->nu = -1;
}

/* The distinct unit edge directions of a placed polytope (once). */
static void place_dirs(placed *P)
{
    if (P->nu >= 0) return;
    const prox_polytope *p = P->p;
    P->nu = 0;
    for (int e = 0; e < p->ne; ++e) {
        prox_vec3 w = prox_v3_normalize(prox_v3_sub(p->v[p->e[e][1]], p->v[p->e[e][0]]));
        int dup = 0;
        for (int k = 0; k < P->nu && !dup; ++k) dup = prox_v3_norm(prox_v3_cross(w, P->u[k])) <= PROX_TOL_EDGE_AXIS;
        if (!dup) P->u[P->nu++] = w;
    }
}

/* Support values by comparison (fmax is a library call that the hot loops cannot afford). */
static double hmax(const placed *P, prox_vec3 n)
{
    double m = prox_v3_dot(n, P->v[0]);
    for (int i = 1; i < P->p->nv; ++i) {
        double t = prox_v3_dot(n, P->v[i]);
        m = t > m ? t : m;
    }
    return m;
}

static double hmin(const placed *P, prox_vec3 n)
{
    double m = prox_v3_dot(n, P->v[0]);
    for (int i = 1; i < P->p->nv; ++i) {
        double t = prox_v3_dot(n, P->v[i]);
        m = t < m ? t : m;
    }
    return m;
}

/* Both ends of P's projection on n. */
static void hrange(const placed *P, prox_vec3 n, double *lo, double *hi)
{
    double a = prox_v3_dot(n, P->v[0]), b = a;
    for (int i = 1; i < P->p->nv; ++i) {
        double t = prox_v3_dot(n, P->v[i]);
        a = t < a ? t : a;
        b = t > b ? t : b;
    }
    *lo = a, *hi = b;
}

/* s(n) = min_B n.y - max_A n.x. */
static double sep(const placed *A, const placed *B, prox_vec3 n) { return hmin(B, n) - hmax(A, n); }

/* Free directions of the feature of P holding the boundary point p: a face's two in-plane
 * directions, an edge's direction, none at a corner (planes within tol of p). */
static int free_dirs(const placed *P, prox_vec3 p, double tol, prox_vec3 *out)
{
    int on[PROX_POLY_MAXF], k = 0;
    for (int f = 0; f < P->p->nf; ++f)
        if (fabs(prox_v3_dot(P->p->n[f], p) - P->d[f]) <= tol) on[k++] = f;
    if (k == 1) {
        out[0] = prox_v3_normalize(prox_v3_any_perp(P->p->n[on[0]]));
        out[1] = prox_v3_cross(P->p->n[on[0]], out[0]);
        return 2;
    }
    if (k == 2) {
        out[0] = prox_v3_normalize(prox_v3_cross(P->p->n[on[0]], P->p->n[on[1]]));
        return 1;
    }
    return 0;
}

/* The contact direction of a closest pair rebuilt from the free directions of their features:
 * orthogonal to all of them, the one nearest n. For a tiny distance d the direction (p2 - p1) / d
 * carries a rounding of eps S / d, and the gap along it falls off linearly with that tilt across a
 * face or along an edge; across the features' free directions it does not. */
static prox_vec3 contact_dir(prox_vec3 n, const prox_vec3 *dirs, int m)
{
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j) {
            prox_vec3 c = prox_v3_cross(dirs[i], dirs[j]);
            double l = prox_v3_norm(c);
            if (l > PROX_TOL_EDGE_AXIS) {
                c = prox_v3_scale(c, 1.0 / l);
                return prox_v3_dot(c, n) >= 0.0 ? c : prox_v3_neg(c);
            }
        }
    if (m >= 1) {
        prox_vec3 r = prox_v3_reject(n, dirs[0]);
        double l = prox_v3_norm(r);
        if (l > 0.0) return prox_v3_scale(r, 1.0 / l);
    }
    return n;
}

/* Certificate of a closest pair p1 on A, p2 on B with unit direction n: the larger gap along n and
 * along the contact direction of their features. */
static double pair_gap(const placed *A, const placed *B, prox_vec3 p1, prox_vec3 p2, prox_vec3 n, double S)
{
    prox_vec3 dirs[4];
    double tol = PROX_TOL_FACE * S;
    int m = free_dirs(A, p1, tol, dirs);
    m += free_dirs(B, p2, tol, dirs + m);
    return fmax(sep(A, B, n), sep(A, B, contact_dir(n, dirs, m)));
}

/* ---- candidate axes ---- */

#define POLY_MAXAX (2 * PROX_POLY_MAXF + 2 * PROX_POLY_MAXE * PROX_POLY_MAXE)

typedef struct axes {
    int n;
    prox_vec3 ax[POLY_MAXAX];
    double s[POLY_MAXAX];
    int best;
} axes;

static void add_axis(axes *X, prox_vec3 n, double s)
{
    X->ax[X->n] = n;
    X->s[X->n] = s;
    if (X->n == 0 || s > X->s[X->best]) X->best = X->n;
    X->n++;
}

/* Separation along every candidate axis, face normals first; stops at the first axis with s > 0
 * when stop_positive (the solids are then disjoint). Returns the largest separation. */
static double all_axes(const placed *A, const placed *B, int stop_positive, axes *X)
{
    X->n = 0;
    X->best = 0;
    for (int f = 0; f < A->p->nf; ++f) {
        add_axis(X, A->p->n[f], sep(A, B, A->p->n[f]));
        if (stop_positive && X->s[X->n - 1] > 0.0) return X->s[X->best];
    }
    for (int g = 0; g < B->p->nf; ++g) {
        prox_vec3 n = prox_v3_neg(B->p->n[g]);
        add_axis(X, n, sep(A, B, n));
        if (stop_positive && X->s[X->n - 1] > 0.0) return X->s[X->best];
    }
    for (int i = 0; i < A->nu; ++i)
        for (int j = 0; j < B->nu; ++j) {
            prox_vec3 c = prox_v3_cross(A->u[i], B->u[j]);
            double l = prox_v3_norm(c);
            if (!(l > PROX_TOL_EDGE_AXIS)) continue; /* parallel edges: no facet of their own (core/tol.h) */
            c = prox_v3_scale(c, 1.0 / l);
            double sp = sep(A, B, c), sm = sep(A, B, prox_v3_neg(c));
            add_axis(X, sp >= sm ? c : prox_v3_neg(c), fmax(sp, sm));
            if (stop_positive && X->s[X->n - 1] > 0.0) return X->s[X->best];
        }
    return X->s[X->best];
}

/* ---- disjoint: features ---- */

/* Is the foot x (on face f's plane) inside the face polygon of P? The edges' directions come from the
 * polytope's own frame: a face far smaller than the pair (an ARB 1 across beside a box 1e28 across)
 * collapses to one point when placed, and its placed edges, of length zero, would take any foot in. */
static int in_face(const placed *P, int f, prox_vec3 x)
{
    const prox_polytope *p = P->p;
    int m = p->fnv[f];
    for (int i = 0; i < m; ++i) {
        int ia = p->fv[f][i], ib = p->fv[f][i + 1 < m ? i + 1 : 0];
        prox_vec3 w = prox_v3_cross(prox_v3_sub(p->v[ib], p->v[ia]), p->n[f]);
        if (prox_v3_dot(w, prox_v3_sub(x, P->v[ia])) > 0.0) return 0;
    }
    return 1;
}

typedef struct best_pair {
    double d;
    prox_vec3 p1, p2;
} best_pair;

/* Vertices of V against the faces of F (the vertex's foot inside a face it is in front of). swap:
 * V is B. */
static void vertex_face(const placed *V, const placed *F, int swap, const double *vproj, double fmin_proj,
                        best_pair *bp)
{
    for (int i = 0; i < V->p->nv; ++i) {
        if (fabs(vproj[i] - fmin_proj) >= bp->d) continue; /* projection bound along the separating axis */
        prox_vec3 x = V->v[i];
        for (int f = 0; f < F->p->nf; ++f) {
            double h = prox_v3_dot(F->p->n[f], x) - F->d[f];
            if (!(h > 0.0) || h >= bp->d) continue;
            prox_vec3 foot = prox_v3_mad(x, -h, F->p->n[f]);
            if (!in_face(F, f, foot)) continue;
            bp->d = h;
            bp->p1 = swap ? foot : x;
            bp->p2 = swap ? x : foot;
        }
    }
}

/* The least vertex-face, face-vertex and edge-edge distance of disjoint A and B separated along the
 * unit axis L (s(L) > 0): every candidate's distance is at least the gap of its projections on L,
 * so candidates whose gap reaches the best so far are skipped. */
static double feature_distance(const placed *A, const placed *B, prox_vec3 L, prox_vec3 *p1, prox_vec3 *p2)
{
    const prox_polytope *a = A->p, *b = B->p;
    double pa[PROX_POLY_MAXV], pb[PROX_POLY_MAXV], maxA = -INFINITY, minB = INFINITY;
    for (int i = 0; i < a->nv; ++i) maxA = fmax(maxA, pa[i] = prox_v3_dot(L, A->v[i]));
    for (int i = 0; i < b->nv; ++i) minB = fmin(minB, pb[i] = prox_v3_dot(L, B->v[i]));
    best_pair bp = {INFINITY, A->v[0], B->v[0]};
    /* seed: the support vertices along L */
    int ia = 0, ib = 0;
    for (int i = 1; i < a->nv; ++i) ia = pa[i] > pa[ia] ? i : ia;
    for (int i = 1; i < b->nv; ++i) ib = pb[i] < pb[ib] ? i : ib;
    bp.d = prox_v3_dist(A->v[ia], B->v[ib]);
    bp.p1 = A->v[ia];
    bp.p2 = B->v[ib];
    double la[PROX_POLY_MAXV];
    for (int i = 0; i < a->nv; ++i) la[i] = minB - pa[i]; /* >= 0: gap of corner i to all of B */
    vertex_face(A, B, 0, pa, minB, &bp);
    vertex_face(B, A, 1, pb, maxA, &bp);
    for (int i = 0; i < a->ne; ++i) {
        int a0 = a->e[i][0], a1 = a->e[i][1];
        double ga = fmin(la[a0], la[a1]);
        if (ga >= bp.d) continue;
        double ea = fmax(pa[a0], pa[a1]);
        for (int j = 0; j < b->ne; ++j) {
            int b0 = b->e[j][0], b1 = b->e[j][1];
            if (fmin(pb[b0], pb[b1]) - ea >= bp.d) continue;
            prox_vec3 c1, c2;
            double d = prox_seg_seg(A->v[a0], A->v[a1], B->v[b0], B->v[b1], &c1, &c2);
            if (d < bp.d) bp.d = d, bp.p1 = c1, bp.p2 = c2;
        }
    }
    *p1 = bp.p1;
    *p2 = bp.p2;
    return bp.d;
}

/* ---- overlapping: a common point ---- */

/* Clips the segment [p, q] to the solid P enlarged by tol (Cyrus-Beck); 1 with [s0, s1] when it meets. */
static int clip_segment(const placed *P, prox_vec3 p, prox_vec3 q, double tol, double *s0, double *s1)
{
    double lo = 0.0, hi = 1.0;
    prox_vec3 dq = prox_v3_sub(q, p);
    for (int f = 0; f < P->p->nf; ++f) {
        double num = P->d[f] + tol - prox_v3_dot(P->p->n[f], p), den = prox_v3_dot(P->p->n[f], dq);
        if (den == 0.0) {
            if (num < 0.0) return 0;
        } else if (den > 0.0) hi = fmin(hi, num / den);
        else lo = fmax(lo, num / den);
        if (lo > hi) return 0;
    }
    *s0 = lo;
    *s1 = hi;
    return 1;
}

static int contains(const placed *P, prox_vec3 x, double tol)
{
    for (int f = 0; f < P->p->nf; ++f)
        if (prox_v3_dot(P->p->n[f], x) > P->d[f] + tol) return 0;
    return 1;
}

/* Adds the points of E's corners in S and the ends of E's edges clipped to S. */
static void meet_points(const placed *E, const placed *S, double tol, prox_vec3 *sum, int *cnt)
{
    for (int i = 0; i < E->p->nv; ++i)
        if (contains(S, E->v[i], tol)) *sum = prox_v3_add(*sum, E->v[i]), ++*cnt;
    for (int e = 0; e < E->p->ne; ++e) {
        prox_vec3 p = E->v[E->p->e[e][0]], q = E->v[E->p->e[e][1]];
        double s0, s1;
        if (!clip_segment(S, p, q, tol, &s0, &s1)) continue;
        prox_vec3 dq = prox_v3_sub(q, p);
        *sum = prox_v3_add(*sum, prox_v3_add(prox_v3_mad(p, s0, dq), prox_v3_mad(p, s1, dq)));
        *cnt += 2;
    }
}

/* A point of both solids: the mean of the corners of A n B found on the edges and corners of both
 * (every corner of the intersection lies on an edge of A or of B). Returns 0 when none is found. */
static int common_point(const placed *A, const placed *B, double tol, prox_vec3 *x)
{
    prox_vec3 sum = prox_v3(0, 0, 0);
    int cnt = 0;
    meet_points(A, B, tol, &sum, &cnt);
    meet_points(B, A, tol, &sum, &cnt);
    if (!cnt) return 0;
    *x = prox_v3_scale(sum, 1.0 / cnt);
    return 1;
}

/* ---- overlapping: witnesses of the depth ---- */

/* A support feature: its corners in loop order (a face's loop, an edge's two ends, or a corner). */
typedef struct feature {
    int m, face;
    prox_vec3 x[PROX_POLY_MAXFV];
} feature;

/* Support feature of P along the unit n: the corners within tol of max n.x; three or more give the
 * face best aligned with n. */
static feature support_feature(const placed *P, prox_vec3 n, double tol)
{
    feature F = {0, -1, {{0, 0, 0}}};
    double h = hmax(P, n);
    int idx[PROX_POLY_MAXV], k = 0;
    for (int i = 0; i < P->p->nv; ++i)
        if (prox_v3_dot(n, P->v[i]) >= h - tol) idx[k++] = i;
    if (k >= 3) {
        int best = 0;
        for (int f = 1; f < P->p->nf; ++f)
            if (prox_v3_dot(P->p->n[f], n) > prox_v3_dot(P->p->n[best], n)) best = f;
        F.face = best;
        F.m = P->p->fnv[best];
        for (int i = 0; i < F.m; ++i) F.x[i] = P->v[P->p->fv[best][i]];
        return F;
    }
    F.m = k;
    for (int i = 0; i < k; ++i) F.x[i] = P->v[idx[i]];
    return F;
}

typedef struct v2 {
    double x, y;
} v2;

static double cross2(v2 a, v2 b, v2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

/* Sutherland-Hodgman: the part of the polygon (or segment, or point) q[0..k-1] inside the convex
 * polygon P[0..m-1] (turning sign orient), each edge's line moved out by tol. */
static int clip2(v2 *q, int k, const v2 *P, int m, double orient, double tol)
{
    for (int e = 0; e < m && k > 0; ++e) {
        v2 a = P[e], b = P[e + 1 < m ? e + 1 : 0], out[2 * PROX_POLY_MAXFV + 4];
        double len = hypot(b.x - a.x, b.y - a.y);
        int o = 0;
        for (int i = 0; i < k; ++i) {
            v2 p = q[i], r = q[(i + 1) % k];
            double dp = orient * cross2(a, b, p) + tol * len, dr = orient * cross2(a, b, r) + tol * len;
            if (dp >= 0.0) out[o++] = p;
            if ((dp > 0.0 && dr < 0.0) || (dp < 0.0 && dr > 0.0)) {
                double t = dp / (dp - dr);
                out[o++] = (v2){p.x + t * (r.x - p.x), p.y + t * (r.y - p.y)};
            }
            if (o >= 2 * PROX_POLY_MAXFV + 2) break;
        }
        for (int i = 0; i < o; ++i) q[i] = out[i];
        k = o;
    }
    return k;
}

/* Closest points of the 2-D segments [a0, a1] and [b0, b1] (points when degenerate), by the 3-D
 * routine in the plane z = 0. */
static double seg2(v2 a0, v2 a1, v2 b0, v2 b1, v2 *ca, v2 *cb)
{
    prox_vec3 c1, c2;
    double d = prox_seg_seg(prox_v3(a0.x, a0.y, 0), prox_v3(a1.x, a1.y, 0), prox_v3(b0.x, b0.y, 0),
                            prox_v3(b1.x, b1.y, 0), &c1, &c2);
    *ca = (v2){c1.x, c1.y};
    *cb = (v2){c2.x, c2.y};
    return d;
}

/* The point of feature F (3-D) whose projection is w: on a face, its plane along n; on an edge, the
 * point with the nearest projection; a corner itself. */
static prox_vec3 lift(const placed *P, const feature *F, v2 w, prox_vec3 e1, prox_vec3 e2, prox_vec3 n)
{
    prox_vec3 x = prox_v3_add(prox_v3_scale(e1, w.x), prox_v3_scale(e2, w.y));
    if (F->face >= 0) {
        prox_vec3 nf = P->p->n[F->face];
        double den = prox_v3_dot(nf, n);
        return prox_v3_mad(x, (P->d[F->face] - prox_v3_dot(nf, x)) / den, n);
    }
    if (F->m == 2) {
        prox_vec3 a = F->x[0], ab = prox_v3_sub(F->x[1], a);
        prox_vec3 abp = prox_v3_reject(ab, n);
        double l2 = prox_v3_norm2(abp), t = l2 > 0.0 ? prox_v3_dot(prox_v3_sub(x, a), abp) / l2 : 0.0;
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        return prox_v3_mad(a, t, ab);
    }
    return F->x[0];
}

static double area2(const v2 *q, int m)
{
    double s = 0.0;
    for (int i = 0; i < m; ++i) {
        int j = i + 1 < m ? i + 1 : 0;
        s += q[i].x * q[j].y - q[j].x * q[i].y;
    }
    return s;
}

/* Witnesses of axis n (unit, from A towards B): p1 on F_A(n), p2 on F_B(-n) with projections that
 * meet. Returns the residual |p2 - p1 - s n| (0 in exact arithmetic for a facet normal of B - A). */
static double axis_witness(const placed *A, const placed *B, prox_vec3 n, double s, double ftol, double ctol,
                           prox_vec3 *p1, prox_vec3 *p2)
{
    feature FA = support_feature(A, n, ftol), FB = support_feature(B, prox_v3_neg(n), ftol);
    prox_vec3 e1 = prox_v3_normalize(prox_v3_any_perp(n)), e2 = prox_v3_cross(n, e1);
    v2 qa[PROX_POLY_MAXFV], qb[2 * PROX_POLY_MAXFV + 4];
    for (int i = 0; i < FA.m; ++i) qa[i] = (v2){prox_v3_dot(e1, FA.x[i]), prox_v3_dot(e2, FA.x[i])};
    for (int i = 0; i < FB.m; ++i) qb[i] = (v2){prox_v3_dot(e1, FB.x[i]), prox_v3_dot(e2, FB.x[i])};
    v2 wa = qa[0], wb = qb[0];
    int done = 0;
    /* A polygon clips the other feature; the mean of what is left lies in both projections. */
    const v2 *P = NULL;
    v2 clip[2 * PROX_POLY_MAXFV + 4];
    int m = 0, k = 0;
    if (FA.m >= 3) {
        P = qa, m = FA.m, k = FB.m;
        for (int i = 0; i < k; ++i) clip[i] = qb[i];
    } else if (FB.m >= 3) {
        P = qb, m = FB.m, k = FA.m;
        for (int i = 0; i < k; ++i) clip[i] = qa[i];
    }
    if (P) {
        double ar = area2(P, m);
        k = ar != 0.0 ? clip2(clip, k, P, m, ar > 0.0 ? 1.0 : -1.0, ctol) : 0;
        if (k > 0) {
            v2 c = {0, 0};
            for (int i = 0; i < k; ++i) c.x += clip[i].x / k, c.y += clip[i].y / k;
            wa = wb = c;
            done = 1;
        }
    }
    if (!done) { /* nearest pair of the features' edges (or corners) in projection */
        double bd = INFINITY;
        for (int i = 0; i < FA.m; ++i)
            for (int j = 0; j < FB.m; ++j) {
                v2 ca, cb;
                double d = seg2(qa[i], qa[(i + 1) % FA.m], qb[j], qb[(j + 1) % FB.m], &ca, &cb);
                if (d < bd) bd = d, wa = ca, wb = cb;
            }
    }
    *p1 = lift(A, &FA, wa, e1, e2, n);
    *p2 = lift(B, &FB, wb, e1, e2, n);
    return prox_v3_norm(prox_v3_sub(prox_v3_sub(*p2, *p1), prox_v3_scale(n, s)));
}

/* ---- fast path: alternating projections, support features, certificate ---- */

static prox_vec3 seg_closest(prox_vec3 a, prox_vec3 b, prox_vec3 x)
{
    prox_vec3 ab = prox_v3_sub(b, a);
    double l2 = prox_v3_norm2(ab), t = l2 > 0.0 ? prox_v3_dot(prox_v3_sub(x, a), ab) / l2 : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return prox_v3_mad(a, t, ab);
}

/* Closest point of a feature (a face's polygon, a segment, a corner) to x. */
static prox_vec3 feature_closest(const placed *P, const feature *F, prox_vec3 x)
{
    if (F->face >= 0) {
        prox_vec3 n = P->p->n[F->face];
        prox_vec3 foot = prox_v3_mad(x, P->d[F->face] - prox_v3_dot(n, x), n);
        if (in_face(P, F->face, foot)) return foot;
    }
    if (F->m == 1) return F->x[0];
    prox_vec3 best = F->x[0];
    double bd = INFINITY;
    int ne = F->m == 2 ? 1 : F->m;
    for (int i = 0; i < ne; ++i) {
        prox_vec3 q = seg_closest(F->x[i], F->x[(i + 1) % F->m], x);
        double d = prox_v3_norm2(prox_v3_sub(q, x));
        if (d < bd) bd = d, best = q;
    }
    return best;
}

/* Closest point of the solid P to x: x itself inside, else the nearest over the faces x sees. */
static prox_vec3 solid_closest(const placed *P, prox_vec3 x, double *dist)
{
    prox_vec3 best = x;
    double bd = INFINITY;
    for (int f = 0; f < P->p->nf; ++f) {
        if (prox_v3_dot(P->p->n[f], x) <= P->d[f]) continue;
        feature F = {P->p->fnv[f], f, {{0, 0, 0}}};
        for (int i = 0; i < F.m; ++i) F.x[i] = P->v[P->p->fv[f][i]];
        prox_vec3 q = feature_closest(P, &F, x);
        double d = prox_v3_norm2(prox_v3_sub(q, x));
        if (d < bd) bd = d, best = q;
    }
    *dist = bd < INFINITY ? sqrt(bd) : 0.0;
    return best;
}

/* Alternating projections from B's reference point: 1 with *x a point of A within tol of B; else 0
 * with the last pair y in A, z in B. */
static int alternate(const placed *A, const placed *B, prox_vec3 cb, double tol, prox_vec3 *x, prox_vec3 *z)
{
    double d;
    prox_vec3 y = solid_closest(A, cb, &d);
    for (int it = 0; it < 2; ++it) {
        *z = solid_closest(B, y, &d);
        if (d <= tol) {
            *x = y;
            return 1;
        }
        prox_vec3 y2 = solid_closest(A, *z, &d);
        if (d <= tol) {
            *x = *z;
            return 1;
        }
        y = y2;
    }
    *x = y;
    return 0;
}

/* Exact distance of two features: the least corner-feature and edge-edge distance. */
static double features_distance(const placed *A, const feature *FA, const placed *B, const feature *FB, prox_vec3 *p1,
                                prox_vec3 *p2)
{
    double best = INFINITY;
    for (int i = 0; i < FA->m; ++i) {
        prox_vec3 q = feature_closest(B, FB, FA->x[i]);
        double d = prox_v3_dist(FA->x[i], q);
        if (d < best) best = d, *p1 = FA->x[i], *p2 = q;
    }
    for (int j = 0; j < FB->m; ++j) {
        prox_vec3 q = feature_closest(A, FA, FB->x[j]);
        double d = prox_v3_dist(q, FB->x[j]);
        if (d < best) best = d, *p1 = q, *p2 = FB->x[j];
    }
    if (FA->m < 2 || FB->m < 2) return best;
    int ea = FA->m == 2 ? 1 : FA->m, eb = FB->m == 2 ? 1 : FB->m;
    for (int i = 0; i < ea; ++i)
        for (int j = 0; j < eb; ++j) {
            prox_vec3 c1, c2;
            double d = prox_seg_seg(FA->x[i], FA->x[(i + 1) % FA->m], FB->x[j], FB->x[(j + 1) % FB->m], &c1, &c2);
            if (d < best) best = d, *p1 = c1, *p2 = c2;
        }
    return best;
}

/* Largest gap over the pair's direction n and the features' own normals (a face's normal; two
 * segments' cross product). */
static double features_gap(const placed *A, const feature *FA, const placed *B, const feature *FB, prox_vec3 n)
{
    double g = sep(A, B, n);
    if (FA->face >= 0) g = fmax(g, sep(A, B, A->p->n[FA->face]));
    if (FB->face >= 0) g = fmax(g, sep(A, B, prox_v3_neg(B->p->n[FB->face])));
    if (FA->m == 2 && FB->m == 2) {
        prox_vec3 c = prox_v3_cross(prox_v3_sub(FA->x[1], FA->x[0]), prox_v3_sub(FB->x[1], FB->x[0]));
        double l = prox_v3_norm(c);
        if (l > 0.0) {
            c = prox_v3_scale(c, 1.0 / l);
            g = fmax(g, sep(A, B, prox_v3_dot(c, n) >= 0.0 ? c : prox_v3_neg(c)));
        }
    }
    return g;
}

/* Support features along n (then along the pair's direction), their exact distance d, accepted when
 * a gap proves it: d - gap <= PROX_TOL_CERT S (gap a lower bound, d an upper bound). */
static int certified(const placed *A, const placed *B, prox_vec3 n, double S, int rounds, prox_distance_result *r)
{
    double ftol = PROX_TOL_FACE * S;
    for (int it = 0; it < rounds; ++it) {
        feature FA = support_feature(A, n, ftol), FB = support_feature(B, prox_v3_neg(n), ftol);
        prox_vec3 p1, p2;
        double d = features_distance(A, &FA, B, &FB, &p1, &p2);
        if (!(d > 0.0)) return 0;
        n = prox_v3_scale(prox_v3_sub(p2, p1), 1.0 / d);
        double g = fmax(features_gap(A, &FA, B, &FB, n), pair_gap(A, B, p1, p2, n, S));
        if (d - g <= PROX_TOL_CERT * S) {
            r->distance = d;
            r->p1 = p1;
            r->p2 = p2;
            r->certificate_gap = g;
            r->certified = 1;
            return 1;
        }
    }
    return 0;
}

/* The fast path: 1 = intersecting (r->p1 = r->p2 common), 2 = disjoint and certified, 0 = undecided. */
static int fast_path(const placed *A, const placed *B, prox_vec3 cb, double S, prox_distance_result *r)
{
    prox_vec3 y, z;
    if (alternate(A, B, cb, PROX_TOL_TOUCH * S, &y, &z)) {
        r->intersect = 1;
        r->p1 = r->p2 = y;
        r->certified = 1;
        return 1;
    }
    double dz = prox_v3_dist(z, y);
    if (dz > 0.0 && certified(A, B, prox_v3_scale(prox_v3_sub(z, y), 1.0 / dz), S, 1, r)) return 2;
    return 0;
}

/* ---- GJK fast path: corner pairs, duality certificate ---- */

/* p1 = sum l_k a_(i_k) in A and p2 = sum l_k b_(j_k) in B from GJK's simplex. */
static void gjk_points(const placed *A, const placed *B, const prox_gjk_simplex *g, prox_vec3 *p1, prox_vec3 *p2)
{
    *p1 = *p2 = prox_v3(0, 0, 0);
    for (int k = 0; k < g->n; ++k) {
        *p1 = prox_v3_mad(*p1, g->l[k], A->v[g->ia[k]]);
        *p2 = prox_v3_mad(*p2, g->l[k], B->v[g->ib[k]]);
    }
}

/* GJK on the corners from B's reference point direction D: 1 = a common point (r->p1 = r->p2, in
 * both solids to PROX_TOL_TOUCH S), 2 = disjoint with the distance proved by the gap along the
 * witnesses' direction (or their features' contact direction) to PROX_TOL_CERT S, 0 = undecided. */
static int gjk_path(const placed *A, const placed *B, prox_vec3 D, double S, prox_distance_result *r)
{
    prox_gjk_simplex g;
    double tol = PROX_TOL_TOUCH * S;
    int st = prox_gjk_polytopes(A->v, A->p->nv, B->v, B->p->nv, D, S, tol, &g);
    if (st == PROX_GJK_FAIL) return 0;
    prox_vec3 p1, p2;
    gjk_points(A, B, &g, &p1, &p2);
    if (st == PROX_GJK_OVERLAP) {
        prox_vec3 x = prox_v3_scale(prox_v3_add(p1, p2), 0.5);
        if (!contains(A, x, tol) || !contains(B, x, tol)) return 0;
        r->intersect = 1;
        r->p1 = r->p2 = x;
        r->certified = 1;
        return 1;
    }
    double d = prox_v3_dist(p1, p2);
    if (!(d > 0.0)) return 0;
    prox_vec3 n = prox_v3_scale(prox_v3_sub(p2, p1), 1.0 / d);
    double gap = sep(A, B, n);
    if (d - gap > PROX_TOL_CERT * S) gap = fmax(gap, pair_gap(A, B, p1, p2, n, S));
    if (!(d - gap <= PROX_TOL_CERT * S)) return 0;
    r->distance = d;
    r->p1 = p1;
    r->p2 = p2;
    r->certificate_gap = gap;
    r->certified = 1;
    return 2;
}

/* ---- overlapping: the depth axes without the hopeless ones ---- */

/* Gauss-map arc tables of the edges (Gregorius, "The Separating Axis Test between Convex Polyhedra",
 * GDC 2013): A's edge i between faces a, b has the arc from n_a to n_b; B's edge j between faces c, d
 * the arc from -n_c to -n_d (B enters the difference negated). The cross product of the two edges is a
 * facet normal of B - A only when the arcs cross: sign(c.(b x a)) != sign(d.(b x a)), sign(a.(d x c))
 * != sign(b.(d x c)) and sign(c.(b x a)) = sign(b.(d x c)) (the crossing, not its antipode). */
typedef struct arcs {
    double ta[PROX_POLY_MAXE][PROX_POLY_MAXF]; /* -n_g(B) . (n_b x n_a) of A's edge i */
    double tb[PROX_POLY_MAXE][PROX_POLY_MAXF]; /* n_f(A) . (n_d x n_c) of B's edge j */
    unsigned pa[PROX_POLY_MAXE], na[PROX_POLY_MAXE]; /* B's faces with ta clearly > 0, clearly < 0 */
    unsigned pb[PROX_POLY_MAXE], nb[PROX_POLY_MAXE]; /* A's faces with tb clearly > 0, clearly < 0 */
    unsigned fa[PROX_POLY_MAXE], fb[PROX_POLY_MAXE]; /* the two faces of each edge of A, of B */
} arcs;

static void arc_row(const prox_polytope *q, prox_vec3 axis, double sign, double *t, unsigned *pos, unsigned *neg)
{
    unsigned p = 0, m = 0;
    axis = prox_v3_scale(axis, sign);
    for (int g = 0; g < q->nf; ++g) {
        double v = prox_v3_dot(q->n[g], axis);
        t[g] = v;
        p |= (unsigned)(v > PROX_TOL_GAUSS_ARC) << g;
        m |= (unsigned)(v < -PROX_TOL_GAUSS_ARC) << g;
    }
    *pos = p, *neg = m;
}

static void arc_tables(const prox_polytope *a, const prox_polytope *b, arcs *T)
{
    for (int i = 0; i < a->ne; ++i) {
        arc_row(b, prox_v3_cross(a->n[a->ef[i][1]], a->n[a->ef[i][0]]), -1.0, T->ta[i], &T->pa[i], &T->na[i]);
        T->fa[i] = (1u << a->ef[i][0]) | (1u << a->ef[i][1]);
    }
    for (int j = 0; j < b->ne; ++j) {
        arc_row(a, prox_v3_cross(b->n[b->ef[j][1]], b->n[b->ef[j][0]]), 1.0, T->tb[j], &T->pb[j], &T->nb[j]);
        T->fb[j] = (1u << b->ef[j][0]) | (1u << b->ef[j][1]);
    }
}

/* Arc test of A's edge i against B's edge j with the margin PROX_TOL_GAUSS_ARC on every sign:
 * 1 the arcs cross, -1 they do not, 0 too close to tell (the axis is then taken by its supports). */
static int arcs_cross(const prox_polytope *a, const prox_polytope *b, const arcs *T, int i, int j)
{
    unsigned cd = T->fb[j], ab = T->fa[i];
    if ((T->pa[i] & cd) == cd || (T->na[i] & cd) == cd || (T->pb[j] & ab) == ab || (T->nb[j] & ab) == ab) return -1;
    if (((T->pa[i] | T->na[i]) & cd) != cd || ((T->pb[j] | T->nb[j]) & ab) != ab) return 0;
    return T->ta[i][b->ef[j][0]] * T->tb[j][a->ef[i][1]] > 0.0 ? 1 : -1;
}

/* 1 when the arcs of A's edge i and B's edge j clearly do not meet: both faces of one edge clearly on
 * one side of the other edge's great circle (the first two conditions of arcs_cross, inline). */
static inline int arcs_apart(const arcs *T, int i, int j)
{
    unsigned cd = T->fb[j], ab = T->fa[i];
    return (T->pa[i] & cd) == cd || (T->na[i] & cd) == cd || (T->pb[j] & ab) == ab || (T->nb[j] & ab) == ab;
}

/* Separation along a face normal n with A's support value ha, or -INFINITY once B's running minimum
 * shows it stays below floor (it cannot come within the touch band of the best axis). */
static double face_sep(const placed *P, prox_vec3 n, double ha, double floor)
{
    double m = INFINITY;
    for (int i = 0; i < P->p->nv; ++i) {
        double t = prox_v3_dot(n, P->v[i]);
        m = t < m ? t : m;
        if (m - ha < floor) return -INFINITY;
    }
    return m - ha;
}

/* The edge pair's axis (the unit cross product, oriented from A towards B) and its separation: by the
 * two edges' corners when the arcs cross clearly and the edges are far from parallel (the axis then
 * lies inside both normal cones: A's maximum and B's minimum are at the edges), by the supports when
 * undecided. Returns 0 for parallel edges, pairs whose arcs do not cross, and corner-evaluated axes
 * whose separation stays below floor (the unnormalised value compared with floor |c|: no root). */
static int edge_axis(const placed *A, const placed *B, const arcs *T, int i, int j, double floor, prox_vec3 *n,
                     double *s)
{
    const prox_polytope *a = A->p, *b = B->p;
    int cross = arcs_cross(a, b, T, i, j);
    if (cross < 0) return 0;
    prox_vec3 x0 = A->v[a->e[i][0]], y0 = B->v[b->e[j][0]];
    prox_vec3 ea = prox_v3_sub(A->v[a->e[i][1]], x0), eb = prox_v3_sub(B->v[b->e[j][1]], y0);
    prox_vec3 c = prox_v3_cross(ea, eb);
    double l2 = prox_v3_norm2(c), e2 = prox_v3_norm2(ea) * prox_v3_norm2(eb);
    /* parallel edges: no facet of their own (core/tol.h) */
    if (!(l2 > PROX_TOL_EDGE_AXIS * PROX_TOL_EDGE_AXIS * e2)) return 0;
    if (cross > 0 && l2 >= PROX_TOL_GAUSS_AXIS * PROX_TOL_GAUSS_AXIS * e2) {
        if (prox_v3_dot(c, prox_v3_add(a->n[a->ef[i][0]], a->n[a->ef[i][1]])) < 0.0) c = prox_v3_neg(c);
        double su = prox_v3_dot(c, prox_v3_sub(y0, x0)); /* = s |c| */
        if (floor < 0.0 && su < 0.0 && su * su >= floor * floor * l2) return 0;
        if (floor >= 0.0 && !(su > 0.0 && su * su > floor * floor * l2)) return 0;
        double l = sqrt(l2);
        *n = prox_v3_scale(c, 1.0 / l);
        *s = su / l;
        return 1;
    }
    c = prox_v3_scale(c, 1.0 / sqrt(l2));
    double alo, ahi, blo, bhi;
    hrange(A, c, &alo, &ahi);
    hrange(B, c, &blo, &bhi);
    double sp = blo - ahi, sm = alo - bhi; /* along c and along -c */
    *n = sp >= sm ? c : prox_v3_neg(c);
    *s = sp >= sm ? sp : sm;
    return 1;
}

/* The candidate axes of the depth: every face normal (unless its separation provably stays more than
 * band below the best so far) and the edge pairs whose Gauss-map arcs cross (or may). The largest
 * separation over them equals the largest over all axes, and every axis within band of it is listed. */
static double depth_axes(const placed *A, const placed *B, double band, axes *X)
{
    const prox_polytope *a = A->p, *b = B->p;
    X->n = 0;
    X->best = 0;
    double best = -INFINITY;
    for (int f = 0; f < a->nf; ++f) {
        double s = face_sep(B, a->n[f], A->d[f], best - band);
        if (s > -INFINITY) add_axis(X, a->n[f], s), best = X->s[X->best];
    }
    for (int g = 0; g < b->nf; ++g) { /* axis -n_g: min_B (-n_g).y - max_A (-n_g).x = min_A n_g.x - d_g */
        double s = face_sep(A, b->n[g], B->d[g], best - band);
        if (s > -INFINITY) add_axis(X, prox_v3_neg(b->n[g]), s), best = X->s[X->best];
    }
    arcs T;
    arc_tables(a, b, &T);
    for (int i = 0; i < a->ne; ++i)
        for (int j = 0; j < b->ne; ++j) {
            prox_vec3 n;
            double s;
            if (!arcs_apart(&T, i, j) && edge_axis(A, B, &T, i, j, X->s[X->best] - band, &n, &s)) add_axis(X, n, s);
        }
    return X->s[X->best];
}

/* The depth's witnesses: among the axes within a touch of the largest separation s, face normals
 * first, the first whose support features meet in projection. */
static void depth_witness(const placed *A, const placed *B, const axes *X, double s, double S, prox_signed_result *r)
{
    double ftol = PROX_TOL_POLY_FEATURE * S, ctol = PROX_TOL_TOUCH * S, best_res = INFINITY;
    for (int i = 0; i < X->n; ++i) {
        if (X->s[i] < s - PROX_TOL_TOUCH * S) continue;
        prox_vec3 q1, q2;
        double res = axis_witness(A, B, X->ax[i], X->s[i], ftol, ctol, &q1, &q2);
        if (res < best_res) {
            best_res = res;
            r->sd = X->s[i];
            r->normal = X->ax[i];
            r->p1 = q1;
            r->p2 = q2;
        }
        if (res <= ctol) break;
    }
}

/* ---- entry points ---- */

static double pair_scale(const prox_polytope *a, const prox_polytope *b, prox_vec3 D)
{
    double s = prox_v3_norm(D); /* finite values: comparisons, not fmax calls */
    s = a->size > s ? a->size : s;
    return b->size > s ? b->size : s;
}

/* 2^-ilogb(S) read off S's exponent bits for a normal S (ldexp and ilogb are library calls); the
 * library otherwise. */
static double unit_scale(double S)
{
    uint64_t bits;
    memcpy(&bits, &S, sizeof bits);
    int e = (int)((bits >> 52) & 0x7ff); /* biased exponent: S in [2^(e-1023), 2^(e-1022)) */
    if (e < 1 || e > 2045) return ldexp(1.0, -ilogb(S));
    bits = (uint64_t)(2046 - e) << 52;  /* 2^(1023-e) */
    double u;
    memcpy(&u, &bits, sizeof u);
    return u;
}

/* The pair placed in A's frame at unit scale: *u the power of two applied (S u in [1, 2)), *S1 = S u. */
static void place_pair(const prox_polytope *a, const prox_polytope *b, prox_vec3 D, placed *A, placed *B, double *u,
                       double *S1)
{
    double S = pair_scale(a, b, D);
    *u = unit_scale(S);
    *S1 = S * *u;
    place(A, a, prox_v3(0, 0, 0), *u);
    place(B, b, D, *u);
}

/* A point of the unit-scale frame back in absolute coordinates. */
static prox_vec3 unplace(prox_vec3 p, double u, prox_vec3 ca) { return prox_v3_add(prox_v3_scale(p, 1.0 / u), ca); }

/* Distance of disjoint placed polytopes separated along L, with the certificate along p2 - p1. */
static void disjoint_distance(const placed *A, const placed *B, prox_vec3 L, double S, prox_distance_result *r)
{
    r->distance = feature_distance(A, B, L, &r->p1, &r->p2);
    prox_vec3 n = r->distance > 0.0 ? prox_v3_scale(prox_v3_sub(r->p2, r->p1), 1.0 / r->distance) : L;
    r->certificate_gap = pair_gap(A, B, r->p1, r->p2, n, S);
    r->certified = r->distance - r->certificate_gap <= PROX_TOL_CERT * S;
}

/* The exhaustive distance of a placed pair (Dp: B's reference point in the placed frame). */
static void distance_exhaustive(placed *A, placed *B, prox_vec3 Dp, double S, prox_distance_result *r)
{
    axes X;
    place_dirs(A);
    place_dirs(B);
    if (fast_path(A, B, Dp, S, r)) {
        /* decided: a common point, or a certified distance */
    } else if (all_axes(A, B, 1, &X) > 0.0) {
        if (!certified(A, B, X.ax[X.best], S, 3, r)) disjoint_distance(A, B, X.ax[X.best], S, r);
    } else {
        double tol = PROX_TOL_TOUCH * S;
        prox_vec3 x;
        if (common_point(A, B, tol, &x)) {
            r->intersect = 1;
            r->p1 = r->p2 = x;
            r->certified = contains(A, x, tol) && contains(B, x, tol);
        } else { /* not reached for solids with no separating axis; answer by the features */
            disjoint_distance(A, B, X.ax[X.best], S, r);
            r->certified = 0;
        }
    }
}

/* A disjoint pair's signed result from its distance. */
static void signed_from_distance(const prox_distance_result *d, prox_signed_result *r)
{
    r->sd = d->distance;
    r->normal = prox_v3_scale(prox_v3_sub(d->p2, d->p1), 1.0 / d->distance);
    r->p1 = d->p1;
    r->p2 = d->p2;
    r->sd_lower = d->certified ? d->certificate_gap : 0.0;
}

/* The exhaustive signed distance of a placed pair. */
static void signed_exhaustive(placed *A, placed *B, prox_vec3 Dp, double S, prox_signed_result *r)
{
    axes X;
    prox_distance_result d = {0};
    place_dirs(A);
    place_dirs(B);
    int fp = fast_path(A, B, Dp, S, &d);
    double s = fp == 2 ? 1.0 : all_axes(A, B, 0, &X);
    if (fp == 2) {
        signed_from_distance(&d, r);
    } else if (s > 0.0) {
        if (!certified(A, B, X.ax[X.best], S, 3, &d)) disjoint_distance(A, B, X.ax[X.best], S, &d);
        signed_from_distance(&d, r);
    } else {
        depth_witness(A, B, &X, s, S, r);
    }
}

static prox_distance_result distance_entry(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b, prox_vec3 cb,
                                           int exhaustive)
{
    prox_distance_result r = {0};
    prox_vec3 D = prox_v3_sub(cb, ca);
    placed A, B;
    double u, S;
    place_pair(a, b, D, &A, &B, &u, &S);
    prox_vec3 Dp = prox_v3_scale(D, u);
    if (exhaustive || !gjk_path(&A, &B, Dp, S, &r)) {
        r = (prox_distance_result){0};
        distance_exhaustive(&A, &B, Dp, S, &r);
    }
    r.distance /= u;
    r.certificate_gap /= u;
    r.p1 = unplace(r.p1, u, ca);
    r.p2 = unplace(r.p2, u, ca);
    /* A common point is checked again in each polytope's own frame: in the pair's frame a speck 1e-25
     * of the pair's scale loses its planes' offsets to rounding (a box 1e-67 across, 1.4e-5 S from a
     * sliver wedge, was taken as meeting it). Beside the band, the rounding of the point's and the
     * references' coordinates. */
    if (r.intersect) {
        double tol = PROX_TOL_TOUCH * S / u + 4.0 * DBL_EPSILON * (prox_v3_maxabs(r.p1) + prox_v3_maxabs(ca) + prox_v3_maxabs(cb));
        if (!(prox_polytope_contains(a, prox_v3_sub(r.p1, ca), tol) && prox_polytope_contains(b, prox_v3_sub(r.p1, cb), tol)))
            r.certified = 0;
    }
    return r;
}

/* The signed distance: GJK decides disjoint pairs (certified) and finds the overlapping ones, whose
 * depth comes from the pruned axes (depth_axes); anything undecided takes the exhaustive method. */
static prox_signed_result signed_entry(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b, prox_vec3 cb,
                                       int exhaustive)
{
    prox_signed_result r = {0};
    prox_vec3 D = prox_v3_sub(cb, ca);
    placed A, B;
    double u, S;
    place_pair(a, b, D, &A, &B, &u, &S);
    prox_vec3 Dp = prox_v3_scale(D, u);
    prox_distance_result d = {0};
    int fp = exhaustive ? 0 : gjk_path(&A, &B, Dp, S, &d);
    if (fp == 2) {
        signed_from_distance(&d, &r);
    } else if (fp == 1) {
        axes X;
        double s = depth_axes(&A, &B, PROX_TOL_TOUCH * S, &X);
        /* GJK put the solids within PROX_TOL_TOUCH S of each other: a positive separation up to that
         * is a touching contact (its axis and witnesses stand for the distance within the band);
         * more would contradict GJK, and the exhaustive method decides. */
        if (s <= PROX_TOL_TOUCH * S) {
            depth_witness(&A, &B, &X, s, S, &r);
            if (r.sd > 0.0) r.sd_lower = r.sd; /* the separation along the axis: a dual bound */
        } else {
            signed_exhaustive(&A, &B, Dp, S, &r);
        }
    } else {
        signed_exhaustive(&A, &B, Dp, S, &r);
    }
    r.sd /= u;
    r.sd_lower /= u;
    r.p1 = unplace(r.p1, u, ca);
    r.p2 = unplace(r.p2, u, ca);
    return r;
}

prox_distance_result prox_poly_distance(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b, prox_vec3 cb)
{
    return distance_entry(a, ca, b, cb, 0);
}

prox_distance_result prox_poly_distance_exhaustive(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b,
                                                   prox_vec3 cb)
{
    return distance_entry(a, ca, b, cb, 1);
}

prox_signed_result prox_poly_signed(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b, prox_vec3 cb)
{
    return signed_entry(a, ca, b, cb, 0);
}

prox_signed_result prox_poly_signed_exhaustive(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b,
                                               prox_vec3 cb)
{
    return signed_entry(a, ca, b, cb, 1);
}
