/* BOX-BOX: separating-axis verdict, exact distance and proximal points, exact penetration depth.
 * Replaces the TRX report's Sec. 3.1 (LA-UR-13-26757, Eqs. (19)-(41): the 12 edge lines of B against the
 * 6 face planes of A), which misses B wholly inside A, A inside B, and crossings where only A's edges
 * pierce B; its Eq. (39) also divides by a_Ak + a_Ak~ b_Ak (typo for the 2x2 determinant).
 * Verdict and depth: the 15 candidate axes (3 + 3 face normals, 9 edge cross products); the minimum
 * overlap over them is the exact penetration depth, since the Minkowski difference of two boxes has
 * only these facet normals. Distance: the closest pair of two disjoint convex polytopes can be chosen
 * vertex-solid or edge-edge, so min over 16 point-box and 144 segment-segment distances is exact; the
 * candidates are pruned by projection lower bounds along the SAT axis and the best pair's direction
 * (docs/algorithms/box_speed.md), which leaves that minimum unchanged.
 * Fast path before the pruned search (docs/algorithms/polytopes.md, "BOX-BOX fast path"): the segment
 * between the centres finds a common point of most intersecting pairs; then the 15 axes, whose best
 * axis of a disjoint pair selects a face and the other box's support vertex, or two support edges,
 * whose exact distance is accepted when the gap along that axis proves it (gap >= distance -
 * PROX_TOL_CERT S: face-vertex and crossing edge-edge contacts). Alternating projections and the
 * support features of a direction (certified the same way) take most of the rest. Only undecided
 * pairs reach the pruned search, so every answer is still exact or certified. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "core/tol.h"
#include "distance/box_internal.h"
#include "distance/poly_internal.h"

/* Overlap of the projections of A and B on the unit axis L (negative: separated along L). */
static double axis_overlap(const prox_bframe *A, const prox_bframe *B, prox_vec3 L)
{
    double ra = 0.0, rb = 0.0;
    for (int k = 0; k < 3; ++k) {
        ra += A->h[k] * fabs(prox_v3_dot(A->a[k], L));
        rb += B->h[k] * fabs(prox_v3_dot(B->a[k], L));
    }
    return ra + rb - fabs(prox_v3_dot(prox_v3_sub(B->m, A->m), L));
}

/* Candidate axis i of 15: 0-2 A's normals, 3-5 B's, 6-14 a_i x b_j. Returns 0 for a null cross product. */
static int sat_axis(const prox_bframe *A, const prox_bframe *B, int i, prox_vec3 *L)
{
    if (i < 3) *L = A->a[i];
    else if (i < 6) *L = B->a[i - 3];
    else {
        prox_vec3 c = prox_v3_cross(A->a[(i - 6) / 3], B->a[(i - 6) % 3]);
        double n = prox_v3_norm(c);
        if (!(n > PROX_TOL_EDGE_AXIS)) return 0; /* near-parallel edges (standard SAT practice): see core/tol.h */
        *L = prox_v3_divs(c, n);
    }
    return 1;
}

/* Minimum overlap over the 15 axes and the axis achieving it (oriented from A towards B): the same
 * values as axis_overlap on each sat_axis, from the dot products of the two frames and the centre
 * offset computed once. The 6 face axes and the 9 cross axes are two steps (sat_faces, sat_cross), so
 * that a pair certified along a face axis skips the cross products. A cross axis c = a_i x b_j is
 * used unnormalised (c . a_i = c . b_j = 0): its overlap o_c / |c| is compared without a square root
 * or a division (below), and only a new best is divided. The pair is at unit scale (unit_pair), where
 * no square here under- or overflows. */
typedef struct sat_state {
    prox_vec3 D;                  /* m_B - m_A */
    double R[3][3], da[3], db[3]; /* |a_i . b_j|, D . a_i, D . b_j */
    double best, best_l;          /* least overlap so far; |c| of its cross axis */
    int bi;                       /* its axis */
    prox_vec3 best_c;             /* its cross axis, oriented along D */
} sat_state;

static void sat_faces(const prox_bframe *A, const prox_bframe *B, sat_state *t)
{
    t->D = prox_v3_sub(B->m, A->m);
    t->best = INFINITY;
    t->best_l = 1.0;
    t->bi = 0;
    t->best_c = prox_v3(0, 0, 0);
    for (int i = 0; i < 3; ++i) {
        t->da[i] = prox_v3_dot(t->D, A->a[i]);
        t->db[i] = prox_v3_dot(t->D, B->a[i]);
        for (int j = 0; j < 3; ++j) t->R[i][j] = fabs(prox_v3_dot(A->a[i], B->a[j]));
    }
    for (int i = 0; i < 3; ++i) { /* A's face normals */
        double ga = 0.0;
        for (int k = 0; k < 3; ++k) ga += A->h[k] * fabs(prox_v3_dot(A->a[i], A->a[k]));
        double o = ga + B->h[0] * t->R[i][0] + B->h[1] * t->R[i][1] + B->h[2] * t->R[i][2] - fabs(t->da[i]);
        if (o < t->best) t->best = o, t->bi = i;
    }
    for (int j = 0; j < 3; ++j) { /* B's face normals */
        double gb = 0.0;
        for (int k = 0; k < 3; ++k) gb += B->h[k] * fabs(prox_v3_dot(B->a[j], B->a[k]));
        double o = A->h[0] * t->R[0][j] + A->h[1] * t->R[1][j] + A->h[2] * t->R[2][j] + gb - fabs(t->db[j]);
        if (o < t->best) t->best = o, t->bi = 3 + j;
    }
}

static void sat_cross(const prox_bframe *A, const prox_bframe *B, sat_state *t)
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            prox_vec3 c = prox_v3_cross(A->a[i], B->a[j]);
            double l2 = prox_v3_norm2(c); /* at unit scale: no under- or overflow */
            if (!(l2 > PROX_TOL_EDGE_AXIS * PROX_TOL_EDGE_AXIS)) continue; /* near-parallel edges: see core/tol.h */
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            double cd = prox_v3_dot(c, t->D);
            double o = A->h[i1] * fabs(prox_v3_dot(c, A->a[i1])) + A->h[i2] * fabs(prox_v3_dot(c, A->a[i2])) +
                       B->h[j1] * fabs(prox_v3_dot(c, B->a[j1])) + B->h[j2] * fabs(prox_v3_dot(c, B->a[j2])) - fabs(cd);
            /* o / l < best as o |o| < best |best| l^2 (x |x| is increasing): no square root in the loop */
            if (o * fabs(o) < t->best * fabs(t->best) * l2) {
                t->best_l = sqrt(l2);
                t->best = o / t->best_l, t->bi = 6 + 3 * i + j, t->best_c = cd >= 0.0 ? c : prox_v3_neg(c);
            }
        }
}

/* The least overlap so far, its axis index and unit axis oriented from A towards B. */
static double sat_result(const prox_bframe *A, const prox_bframe *B, const sat_state *t, int *best_i, prox_vec3 *best_L)
{
    int bi = t->bi;
    *best_i = bi;
    if (bi < 3) *best_L = t->da[bi] >= 0.0 ? A->a[bi] : prox_v3_neg(A->a[bi]);
    else if (bi < 6) *best_L = t->db[bi - 3] >= 0.0 ? B->a[bi - 3] : prox_v3_neg(B->a[bi - 3]);
    else *best_L = prox_v3_divs(t->best_c, t->best_l);
    return t->best;
}

static double sat_min_overlap(const prox_bframe *A, const prox_bframe *B, int *best_i, prox_vec3 *best_L)
{
    sat_state t;
    sat_faces(A, B, &t);
    sat_cross(A, B, &t);
    return sat_result(A, B, &t, best_i, best_L);
}

static double bb_scale(const prox_bframe *A, const prox_bframe *B)
{
    double s = prox_v3_dist(A->m, B->m), sa = prox_bframe_size(A), sb = prox_bframe_size(B);
    return s > sa ? (s > sb ? s : sb) : (sa > sb ? sa : sb);
}

static int bb_intersect(const prox_bframe *A, const prox_bframe *B);
static void unit_pair(const prox_bframe *pA, const prox_bframe *pB, prox_bframe *A, prox_bframe *B, double *u);

PROX_API prox_test_result prox_box_box_test(const prox_box *a, const prox_box *b)
{
    prox_test_result r = {0};
    r.status = prox_valid2(prox_box_validate(a), prox_box_validate(b));
    if (r.status != PROX_OK) return r;
    prox_bframe A0 = prox_bframe_make(a), B0 = prox_bframe_make(b), A, B;
    double u;
    unit_pair(&A0, &B0, &A, &B, &u);
    r.intersect = bb_intersect(&A, &B);
    return r;
}

/* Minimum over the vertex-box and edge-edge features: the distance of disjoint boxes (exhaustive; kept for
 * the rare intersecting fallback of the witness search). */
static double feature_distance(const prox_bframe *A, const prox_bframe *B, prox_vec3 *p1, prox_vec3 *p2)
{
    double best = INFINITY, d;
    for (int i = 0; i < 8; ++i) {
        prox_vec3 v = prox_bframe_vertex(A, i), q = prox_bframe_closest(B, v, &d);
        if (d < best) best = d, *p1 = v, *p2 = q;
        v = prox_bframe_vertex(B, i);
        q = prox_bframe_closest(A, v, &d);
        if (d < best) best = d, *p1 = q, *p2 = v;
    }
    for (int i = 0; i < 12; ++i) {
        prox_vec3 pa, qa, c1, c2;
        prox_bframe_edge(A, i, &pa, &qa);
        for (int j = 0; j < 12; ++j) {
            prox_vec3 pb, qb;
            prox_bframe_edge(B, j, &pb, &qb);
            d = prox_seg_seg(pa, qa, pb, qb, &c1, &c2);
            if (d < best) best = d, *p1 = c1, *p2 = c2;
        }
    }
    return best;
}

/* Vertex indices (prox_bframe_vertex numbering) of the ends of edge j (prox_bframe_edge numbering): the
 * same points, bit for bit, as prox_bframe_edge. */
static void edge_ends(int j, int *p, int *q)
{
    int k = j / 4, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    *p = ((j & 1) << k1) | (((j >> 1) & 1) << k2);
    *q = *p | (1 << k);
}

/* Index of the vertex of F extreme along d (bit k set when d.a_k > 0). */
static int support_vertex(const prox_bframe *F, prox_vec3 d)
{
    int i = 0;
    for (int k = 0; k < 3; ++k)
        if (prox_v3_dot(d, F->a[k]) > 0.0) i |= 1 << k;
    return i;
}

/* State of the pruned search: vertices, the best pair so far, and which vertices are done. */
typedef struct bb_search {
    prox_vec3 va[8], vb[8];
    double best;
    prox_vec3 p1, p2;
    unsigned done_a, done_b;
} bb_search;

/* Vertex i of A against the solid B (side 0) or vertex i of B against A (side 1), once. */
static void bb_vertex(bb_search *s, const prox_bframe *A, const prox_bframe *B, int side, int i)
{
    double d;
    if (side == 0) {
        if (s->done_a >> i & 1) return;
        s->done_a |= 1u << i;
        prox_vec3 q = prox_bframe_closest(B, s->va[i], &d);
        if (d < s->best) s->best = d, s->p1 = s->va[i], s->p2 = q;
    } else {
        if (s->done_b >> i & 1) return;
        s->done_b |= 1u << i;
        prox_vec3 q = prox_bframe_closest(A, s->vb[i], &d);
        if (d < s->best) s->best = d, s->p1 = q, s->p2 = s->vb[i];
    }
}

/* Projections of the 8 vertices on the unit direction n; *ext their max (hi != 0) or min. */
static void project8(const prox_vec3 v[8], prox_vec3 n, double out[8], int hi, double *ext)
{
    double e = hi ? -INFINITY : INFINITY;
    for (int i = 0; i < 8; ++i) {
        out[i] = prox_v3_dot(n, v[i]);
        e = hi ? (out[i] > e ? out[i] : e) : (out[i] < e ? out[i] : e);
    }
    *ext = e;
}

/* The same minimum as feature_distance for disjoint A, B separated along the unit SAT axis L (from A
 * towards B), with candidates skipped by valid lower bounds. For any unit n and any x in a feature of
 * A, y in a feature of B: |y - x| >= n.(y - x) >= min_{y in fB} n.y - max_{x in fA} n.x, and the extremes
 * over a vertex, an edge or a whole box are those over its vertices. Two directions are used: the SAT
 * axis L and the direction n of the best pair found by the seeds (the support vertices along L, then
 * along n, twice). A candidate whose bound is >= the best distance so far cannot lower the minimum, so
 * skipping it leaves the minimum (up to rounding of the bound, ~1e-16 x scale). */
static double pruned_feature_distance(const prox_bframe *A, const prox_bframe *B, prox_vec3 L, prox_vec3 *p1,
                                      prox_vec3 *p2)
{
    bb_search s;
    for (int i = 0; i < 8; ++i) s.va[i] = prox_bframe_vertex(A, i), s.vb[i] = prox_bframe_vertex(B, i);
    s.best = INFINITY;
    s.done_a = s.done_b = 0;
    s.p1 = s.va[0];
    s.p2 = s.vb[0];
    prox_vec3 n = L;
    for (int it = 0; it < 3; ++it) { /* seeds: support vertices along L, then along the best pair's direction */
        bb_vertex(&s, A, B, 0, support_vertex(A, n));
        bb_vertex(&s, A, B, 1, support_vertex(B, prox_v3_neg(n)));
        if (!(s.best > 0.0)) break;
        n = prox_v3_divs(prox_v3_sub(s.p2, s.p1), s.best);
    }
    double aL[8], bL[8], an[8], bn[8], maxAL, minBL, maxAn, minBn;
    project8(s.va, L, aL, 1, &maxAL);
    project8(s.vb, L, bL, 0, &minBL);
    project8(s.va, n, an, 1, &maxAn);
    project8(s.vb, n, bn, 0, &minBn);
    for (int i = 0; i < 8; ++i) {
        if (fmax(minBL - aL[i], minBn - an[i]) < s.best) bb_vertex(&s, A, B, 0, i);
        if (fmax(bL[i] - maxAL, bn[i] - maxAn) < s.best) bb_vertex(&s, A, B, 1, i);
    }
    /* Edge pairs: per edge, the extreme projections of its ends; rows of A pruned against all of B. */
    double ebL[12], ebn[12];
    int ebp[12], ebq[12];
    for (int j = 0; j < 12; ++j) {
        edge_ends(j, &ebp[j], &ebq[j]);
        ebL[j] = fmin(bL[ebp[j]], bL[ebq[j]]);
        ebn[j] = fmin(bn[ebp[j]], bn[ebq[j]]);
    }
    for (int i = 0; i < 12; ++i) {
        int pa, qa;
        edge_ends(i, &pa, &qa);
        double eaL = fmax(aL[pa], aL[qa]), ean = fmax(an[pa], an[qa]);
        if (fmax(minBL - eaL, minBn - ean) >= s.best) continue;
        for (int j = 0; j < 12; ++j) {
            if (fmax(ebL[j] - eaL, ebn[j] - ean) >= s.best) continue;
            prox_vec3 c1, c2;
            double d = prox_seg_seg(s.va[pa], s.va[qa], s.vb[ebp[j]], s.vb[ebq[j]], &c1, &c2);
            if (d < s.best) s.best = d, s.p1 = c1, s.p2 = c2;
        }
    }
    *p1 = s.p1;
    *p2 = s.p2;
    return s.best;
}

/* ---- fast path: support features and a duality certificate ---- */

/* A support feature of a box: centre c and up to two free unit axes u[k] with half-lengths h[k] (a
 * vertex, an edge or a face). */
typedef struct bfeat {
    prox_vec3 c, u[2];
    double h[2];
    int nfree, fixed; /* fixed: an axis not free (the face's normal axis when nfree == 2) */
} bfeat;

/* Support feature of F along n: axes with |n.a_k| <= PROX_TOL_FACE are free (at most two). */
static bfeat bfeat_of(const prox_bframe *F, prox_vec3 n)
{
    bfeat f;
    f.c = F->m;
    f.nfree = 0;
    f.fixed = 0;
    for (int k = 0; k < 3; ++k) {
        double c = prox_v3_dot(n, F->a[k]);
        if (fabs(c) <= PROX_TOL_FACE && f.nfree < 2) {
            f.u[f.nfree] = F->a[k];
            f.h[f.nfree++] = F->h[k];
        } else {
            f.c = prox_v3_mad(f.c, c > 0.0 ? F->h[k] : -F->h[k], F->a[k]);
            f.fixed = k;
        }
    }
    return f;
}

/* Closest point of the feature to x: the free coordinates clamped. */
static prox_vec3 bfeat_closest(const bfeat *f, prox_vec3 x)
{
    prox_vec3 q = f->c, d = prox_v3_sub(x, f->c);
    for (int k = 0; k < f->nfree; ++k) {
        double t = prox_v3_dot(d, f->u[k]);
        t = t < -f->h[k] ? -f->h[k] : (t > f->h[k] ? f->h[k] : t);
        q = prox_v3_mad(q, t, f->u[k]);
    }
    return q;
}

/* Corners of the feature in cyclic order (1, 2 or 4). */
static int bfeat_corners(const bfeat *f, prox_vec3 out[4])
{
    static const int cyc[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    int m = f->nfree == 0 ? 1 : (f->nfree == 1 ? 2 : 4);
    for (int i = 0; i < m; ++i) {
        prox_vec3 x = f->c;
        if (f->nfree >= 1) x = prox_v3_mad(x, (f->nfree == 1 ? (i ? 1 : -1) : cyc[i][0]) * f->h[0], f->u[0]);
        if (f->nfree == 2) x = prox_v3_mad(x, cyc[i][1] * f->h[1], f->u[1]);
        out[i] = x;
    }
    return m;
}

/* Exact distance of two features (convex polygons, segments or points): the least corner-feature and
 * edge-edge distance. */
static double bfeat_distance(const bfeat *fa, const bfeat *fb, prox_vec3 *p1, prox_vec3 *p2)
{
    prox_vec3 ca[4], cb[4];
    int ma = bfeat_corners(fa, ca), mb = bfeat_corners(fb, cb);
    double best = INFINITY;
    for (int i = 0; i < ma; ++i) {
        prox_vec3 q = bfeat_closest(fb, ca[i]);
        double d = prox_v3_dist(ca[i], q);
        if (d < best) best = d, *p1 = ca[i], *p2 = q;
    }
    for (int j = 0; j < mb; ++j) {
        prox_vec3 q = bfeat_closest(fa, cb[j]);
        double d = prox_v3_dist(q, cb[j]);
        if (d < best) best = d, *p1 = q, *p2 = cb[j];
    }
    if (ma < 2 || mb < 2) return best;
    int ea = ma == 2 ? 1 : 4, eb = mb == 2 ? 1 : 4;
    for (int i = 0; i < ea; ++i)
        for (int j = 0; j < eb; ++j) {
            prox_vec3 c1, c2;
            double d = prox_seg_seg(ca[i], ca[(i + 1) % ma], cb[j], cb[(j + 1) % mb], &c1, &c2);
            if (d < best) best = d, *p1 = c1, *p2 = c2;
        }
    return best;
}

/* Gap of B beyond A along the unit n: min_B n.y - max_A n.x (a lower bound on the distance). */
static double bb_gap(const prox_bframe *A, const prox_bframe *B, prox_vec3 n)
{
    return -prox_bframe_support(B, prox_v3_neg(n)) - prox_bframe_support(A, n);
}

/* Largest gap over the direction of the pair and the features' own normals (a face's normal, the
 * cross product of two edges): the certificate of a pair of features. */
static double bfeat_gap(const prox_bframe *A, const prox_bframe *B, const bfeat *fa, const bfeat *fb, prox_vec3 n)
{
    double g = bb_gap(A, B, n);
    if (fa->nfree == 2) g = fmax(g, bb_gap(A, B, prox_v3_dot(n, A->a[fa->fixed]) >= 0.0 ? A->a[fa->fixed] : prox_v3_neg(A->a[fa->fixed])));
    if (fb->nfree == 2) g = fmax(g, bb_gap(A, B, prox_v3_dot(n, B->a[fb->fixed]) >= 0.0 ? B->a[fb->fixed] : prox_v3_neg(B->a[fb->fixed])));
    if (fa->nfree >= 1 && fb->nfree >= 1) {
        prox_vec3 c = prox_v3_cross(fa->u[0], fb->u[0]);
        double l = prox_v3_norm(c);
        if (l > PROX_TOL_EDGE_AXIS) {
            c = prox_v3_divs(c, l);
            g = fmax(g, bb_gap(A, B, prox_v3_dot(n, c) >= 0.0 ? c : prox_v3_neg(c)));
        }
    }
    return g;
}

/* Free directions of the box feature that holds the boundary point p: the axes along which p is
 * not at a face (|l_k| < h_k - tol). */
static int free_dirs(const prox_bframe *F, prox_vec3 p, double tol, prox_vec3 *out)
{
    double l[3];
    int m = 0;
    prox_bframe_local(F, p, l);
    for (int k = 0; k < 3; ++k)
        if (fabs(l[k]) < F->h[k] - tol) out[m++] = F->a[k];
    return m;
}

/* The contact direction of a closest pair p1, p2 rebuilt from the free directions of their features
 * (core/tol.h PROX_TOL_FACE): orthogonal to all of them, the one nearest n. For a tiny distance d the
 * direction (p2 - p1) / d carries a rounding of eps S / d, and the gap along it falls off linearly
 * with that tilt across a face or along an edge; across the features' free directions it does not. */
static prox_vec3 contact_dir(prox_vec3 n, const prox_vec3 *dirs, int m)
{
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j) {
            prox_vec3 c = prox_v3_cross(dirs[i], dirs[j]);
            double l = prox_v3_norm(c);
            if (l > PROX_TOL_EDGE_AXIS) {
                c = prox_v3_divs(c, l);
                return prox_v3_dot(c, n) >= 0.0 ? c : prox_v3_neg(c);
            }
        }
    if (m >= 1) {
        prox_vec3 r = prox_v3_reject(n, dirs[0]);
        double l = prox_v3_norm(r);
        if (l > 0.0) return prox_v3_divs(r, l);
    }
    return n;
}

/* Gap along the contact direction of the pair (p1 on A, p2 on B, n their unit direction). */
static double contact_gap(const prox_bframe *A, const prox_bframe *B, prox_vec3 p1, prox_vec3 p2, prox_vec3 n, double S)
{
    prox_vec3 dirs[6];
    double tol = PROX_TOL_FACE * S;
    int m = free_dirs(A, p1, tol, dirs);
    m += free_dirs(B, p2, tol, dirs + m);
    return bb_gap(A, B, contact_dir(n, dirs, m));
}

/* The certificate of a pair: the larger gap along n and along the contact direction. */
static double pair_gap(const prox_bframe *A, const prox_bframe *B, prox_vec3 p1, prox_vec3 p2, prox_vec3 n, double S)
{
    return fmax(bb_gap(A, B, n), contact_gap(A, B, p1, p2, n, S));
}

/* A disjoint answer proved by its gap: distance d between p1 and p2, g the proven lower bound. */
static int certified_answer(prox_distance_result *r, double d, prox_vec3 p1, prox_vec3 p2, double g)
{
    r->distance = d;
    r->p1 = p1;
    r->p2 = p2;
    r->certificate_gap = g;
    r->certified = 1;
    return 1;
}

/* Distance of disjoint boxes separated along the unit L: the support features along L (then along
 * the pair's direction) and their exact distance d, accepted when a gap proves it (d - gap <=
 * PROX_TOL_CERT S: the gap is a lower bound and d an upper bound). Returns 0 when three rounds leave
 * it unproved (the exhaustive pruned search then answers). */
static int certified_distance(const prox_bframe *A, const prox_bframe *B, prox_vec3 L, double S, int rounds,
                              prox_distance_result *r)
{
    prox_vec3 n = L;
    for (int it = 0; it < rounds; ++it) {
        bfeat fa = bfeat_of(A, n), fb = bfeat_of(B, prox_v3_neg(n));
        prox_vec3 p1, p2;
        double d = bfeat_distance(&fa, &fb, &p1, &p2);
        if (!(d > 0.0)) return 0;
        n = prox_v3_divs(prox_v3_sub(p2, p1), d);
        double g = contact_gap(A, B, p1, p2, n, S); /* usually proves it alone */
        if (d - g > PROX_TOL_CERT * S) g = fmax(g, bfeat_gap(A, B, &fa, &fb, n));
        if (d - g <= PROX_TOL_CERT * S) return certified_answer(r, d, p1, p2, g);
    }
    return 0;
}

/* The segment between the centres meets both boxes; when the part in A (from A's centre) and the part
 * in B (to B's centre) overlap, their common stretch is in both: 1 and its midpoint *x. With
 * D = m_B - m_A, the point m_A + s D is in A (enlarged by tol) for s <= a1 = min_k (h_k + tol) / |D.a_k|
 * and in B for s >= b0 = 1 - min_k (h_k + tol) / |D.b_k| (Liang-Barsky from the centres, where the
 * local coordinates are 0 and +-D.a_k; a zero D.a_k gives no bound: the quotient is infinite). */
static int centre_line(const prox_bframe *A, const prox_bframe *B, double tol, prox_vec3 *x)
{
    prox_vec3 D = prox_v3_sub(B->m, A->m);
    double a1 = 1.0, tb = 1.0;
    for (int k = 0; k < 3; ++k) {
        double ta = (A->h[k] + tol) / fabs(prox_v3_dot(D, A->a[k])), t = (B->h[k] + tol) / fabs(prox_v3_dot(D, B->a[k]));
        a1 = ta < a1 ? ta : a1;
        tb = t < tb ? t : tb;
    }
    double b0 = 1.0 - tb;
    if (b0 > a1) return 0;
    *x = prox_v3_mad(A->m, 0.5 * (b0 + a1), D);
    return 1;
}

/* Alternating projections (von Neumann): y in A, z in B, from B's centre. Returns 1 with *x a point
 * of A within tol of B (a common point) when an iterate finds one; else 0 with the last pair (y, z),
 * whose direction z - y approaches the contact direction of disjoint boxes. */
static int alternate(const prox_bframe *A, const prox_bframe *B, double tol, prox_vec3 *x, prox_vec3 *z)
{
    prox_vec3 y = prox_bframe_closest(A, B->m, NULL);
    for (int it = 0; it < 2; ++it) {
        double d;
        *z = prox_bframe_closest(B, y, &d);
        if (d <= tol) {
            *x = y;
            return 1;
        }
        prox_vec3 y2 = prox_bframe_closest(A, *z, &d);
        if (d <= tol) {
            *x = *z;
            return 1;
        }
        y = y2;
    }
    *x = y;
    return 0;
}

/* Clips a segment to the box `solid` (a prox_bframe) enlarged by tol. */
static int clip_box(const void *solid, prox_vec3 p, prox_vec3 q, double tol, double *s0, double *s1)
{
    return prox_bframe_clip_segment(solid, p, q, tol, s0, s1);
}

/* A common point of two intersecting boxes: some edge of one meets the other (a vertex of the
 * intersection polytope lies on an edge of A or of B). Returns 0 when none is found within tol. */
static int common_point(const prox_bframe *A, const prox_bframe *B, double tol, prox_vec3 *x)
{
    return prox_bframe_edges_meet(A, clip_box, B, tol, x) || prox_bframe_edges_meet(B, clip_box, A, tol, x);
}

/* The verdict: a common point within tol (alternating projections), a certified distance above tol,
 * or else the 15 axes (least overlap >= -tol). */
static int bb_intersect(const prox_bframe *A, const prox_bframe *B)
{
    double S = bb_scale(A, B), tol = PROX_QUERY_REL_TOL * S;
    prox_vec3 y, z;
    if (centre_line(A, B, tol, &y) || alternate(A, B, tol, &y, &z)) return 1;
    double dz = prox_v3_dist(z, y);
    prox_distance_result r = {0};
    if (dz > 0.0 && certified_distance(A, B, prox_v3_divs(prox_v3_sub(z, y), dz), S, 1, &r) && r.distance > tol)
        return 0;
    int i = 0;
    prox_vec3 L = {0, 0, 0};
    return sat_min_overlap(A, B, &i, &L) >= -tol;
}

PROX_API prox_distance_result prox_box_box_distance(const prox_box *a, const prox_box *b)
{
    prox_distance_result r = {0};
    r.status = prox_valid2(prox_box_validate(a), prox_box_validate(b));
    if (r.status != PROX_OK) return r;
    prox_bframe A = prox_bframe_make(a), B = prox_bframe_make(b);
    return prox_box_pair_distance(&A, &B);
}

/* The pair in A's frame at unit scale: centres moved by -A's centre and sizes multiplied by *u, a
 * power of two (exact), so that the scale is 1 .. 2 and no product of the solvers over- or underflows
 * (a segment pair's |d1|^2 |d2|^2 at sizes 1e-90 is 1e-360). */
static void unit_pair(const prox_bframe *pA, const prox_bframe *pB, prox_bframe *A, prox_bframe *B, double *u)
{
    *A = *pA;
    *B = *pB;
    B->m = prox_v3_sub(pB->m, pA->m);
    A->m = prox_v3(0, 0, 0);
    double s = bb_scale(A, B);
    uint64_t bits;
    memcpy(&bits, &s, sizeof bits);
    int e = (int)((bits >> 52) & 0x7ff) - 1023; /* ilogb(s) of a normal s, without a libm call */
    if (e > -1022 && e < 1023) {
        uint64_t ub = (uint64_t)(1023 - e) << 52;
        memcpy(u, &ub, sizeof ub);
    } else {
        *u = ldexp(1.0, -ilogb(s));
    }
    B->m = prox_v3_scale(B->m, *u);
    for (int k = 0; k < 3; ++k) A->h[k] *= *u, B->h[k] *= *u;
}

/* Back from unit scale: iu = 1 / u is exact (a power of two), so p * iu is p / u bit for bit. */
static prox_vec3 unit_back(prox_vec3 p, double iu, prox_vec3 o) { return prox_v3_add(prox_v3_scale(p, iu), o); }

static prox_distance_result unit_distance(const prox_bframe *pA, const prox_bframe *pB);

prox_distance_result prox_box_pair_distance(const prox_bframe *pA, const prox_bframe *pB)
{
    prox_bframe A, B;
    double u;
    unit_pair(pA, pB, &A, &B, &u);
    prox_distance_result r = unit_distance(&A, &B);
    double iu = 1.0 / u;
    r.distance *= iu;
    r.certificate_gap *= iu;
    r.p1 = unit_back(r.p1, iu, pA->m);
    r.p2 = unit_back(r.p2, iu, pA->m);
    return r;
}

/* The closest pair realised by the best separating axis i (unit L from A towards B, gap g > 0 along
 * it recomputed by bb_gap: a near-parallel cross axis's overlap from sat_min_overlap carries a
 * rounding of eps S / |a_i x b_j|, up to 1e-6 S): a face axis pairs that face with the other box's
 * support vertex along it, a cross axis the two support edges. Their exact distance d is an upper
 * bound and g a lower bound; accepted, certified, when d - g <= PROX_TOL_CERT S and d > tol (a
 * face-vertex or crossing edge-edge contact, most disjoint pairs). Returns 0 otherwise (vertex-vertex,
 * vertex-edge and parallel contacts, where no axis of the 15 is the contact direction). */
static int sat_certified(const prox_bframe *A, const prox_bframe *B, int i, prox_vec3 L, double g, double S, double tol,
                         prox_distance_result *r)
{
    prox_vec3 p1, p2;
    double d;
    if (i < 3) { /* face of A: B's support vertex along -L */
        p2 = prox_bframe_vertex(B, support_vertex(B, prox_v3_neg(L)));
        p1 = prox_bframe_closest(A, p2, &d);
    } else if (i < 6) { /* face of B: A's support vertex along L */
        p1 = prox_bframe_vertex(A, support_vertex(A, L));
        p2 = prox_bframe_closest(B, p1, &d);
    } else { /* edge a_ea of A against edge b_eb of B, each through its support vertex */
        int ea = (i - 6) / 3, eb = (i - 6) % 3;
        int va = support_vertex(A, L) & ~(1 << ea), vb = support_vertex(B, prox_v3_neg(L)) & ~(1 << eb);
        prox_vec3 pa = prox_bframe_vertex(A, va), pb = prox_bframe_vertex(B, vb);
        d = prox_seg_seg(pa, prox_v3_mad(pa, 2.0 * A->h[ea], A->a[ea]), pb, prox_v3_mad(pb, 2.0 * B->h[eb], B->a[eb]), &p1,
                         &p2);
    }
    if (!(d > tol) || d - g > PROX_TOL_CERT * S) return 0;
    return certified_answer(r, d, p1, p2, g);
}

/* prox_box_pair_distance of a pair at unit scale (docs/algorithms/box_speed.md). In order: the centre
 * segment (a common point); the 15 axes and the features of the best one (a certified distance); for
 * a pair less than tol apart along every axis, alternating projections (a common point) and the
 * support features along their direction; no separating axis: a common point on an edge; else the
 * support features along the best axis, three rounds, and the pruned exhaustive search. */
static prox_distance_result unit_distance(const prox_bframe *pA, const prox_bframe *pB)
{
    prox_distance_result r = {0};
    const prox_bframe A = *pA, B = *pB;
    double S = bb_scale(&A, &B), tol = PROX_QUERY_REL_TOL * S;
    prox_vec3 y, z;
    if (centre_line(&A, &B, tol, &y)) {
        r.intersect = 1;
        r.p1 = r.p2 = y;
        r.certified = 1;
        return r;
    }
    int i = 0;
    prox_vec3 L = {0, 0, 0};
    sat_state t;
    sat_faces(&A, &B, &t); /* a face-vertex contact is certified before the cross axes are formed */
    double o = sat_result(&A, &B, &t, &i, &L);
    double g = o < 0.0 ? bb_gap(&A, &B, L) : -INFINITY; /* a proved gap along the best axis */
    if (g > tol && sat_certified(&A, &B, i, L, g, S, tol, &r)) return r;
    sat_cross(&A, &B, &t);
    if (t.bi != i) {
        o = sat_result(&A, &B, &t, &i, &L);
        g = o < 0.0 ? bb_gap(&A, &B, L) : -INFINITY;
        if (g > tol && sat_certified(&A, &B, i, L, g, S, tol, &r)) return r;
    }
    int apart = g > tol; /* more than tol apart: no common point within tol to look for */
    if (!apart && alternate(&A, &B, tol, &y, &z)) {
        r.intersect = 1;
        r.p1 = r.p2 = y;
        r.certified = 1;
        return r;
    }
    if (!apart && o < 0.0) {
        double dz = prox_v3_dist(z, y);
        if (dz > 0.0 && certified_distance(&A, &B, prox_v3_divs(prox_v3_sub(z, y), dz), S, 1, &r)) return r;
    }
    if (o >= 0.0) { /* no separating axis: the boxes intersect */
        r.intersect = 1;
        r.certified = common_point(&A, &B, tol, &r.p1);
        if (!r.certified) feature_distance(&A, &B, &r.p1, &r.p2);
        r.p2 = r.p1;
        return r;
    }
    if (certified_distance(&A, &B, L, S, 3, &r)) return r;
    r.distance = pruned_feature_distance(&A, &B, L, &r.p1, &r.p2);
    prox_vec3 n = r.distance > 0.0 ? prox_v3_normalize(prox_v3_sub(r.p2, r.p1)) : L; /* unit: the gap along it */
    r.certificate_gap = pair_gap(&A, &B, r.p1, r.p2, n, S);
    r.certified = r.distance - r.certificate_gap <= PROX_TOL_CERT * S;
    return r;
}

/* Vertices of the support feature of F in direction n (vertex, edge or face, in cyclic order). */
static int support_feature(const prox_bframe *F, prox_vec3 n, prox_vec3 out[4])
{
    double l[3];
    int free_k[2], nf = 0;
    for (int k = 0; k < 3; ++k) {
        double c = prox_v3_dot(n, F->a[k]);
        if (fabs(c) <= PROX_TOL_FACE) { /* near-parallel face: the feature is an edge or a face */
            if (nf < 2) free_k[nf++] = k;
            l[k] = 0.0;
        } else l[k] = c > 0.0 ? F->h[k] : -F->h[k];
    }
    static const int cyc[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    int count = nf == 0 ? 1 : (nf == 1 ? 2 : 4);
    for (int v = 0; v < count; ++v) {
        if (nf >= 1) l[free_k[0]] = (nf == 1 ? (v ? 1 : -1) : cyc[v][0]) * F->h[free_k[0]];
        if (nf == 2) l[free_k[1]] = cyc[v][1] * F->h[free_k[1]];
        out[v] = prox_bframe_point(F, l);
    }
    return count;
}

/* Sutherland-Hodgman: keeps the part of the convex polygon with a.x <= c. */
static int clip_poly(prox_vec3 *poly, int n, prox_vec3 a, double c)
{
    prox_vec3 out[8];
    int m = 0;
    for (int i = 0; i < n; ++i) {
        prox_vec3 p = poly[i], q = poly[(i + 1) % n];
        double dp = prox_v3_dot(a, p) - c, dq = prox_v3_dot(a, q) - c;
        if (dp <= 0.0) out[m++] = p;
        if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0))
            out[m++] = prox_v3_mad(p, dp / (dp - dq), prox_v3_sub(q, p));
        if (m >= 8) break;
    }
    for (int i = 0; i < m; ++i) poly[i] = out[i];
    return m;
}

/* Witness on the feature of S (support in direction dir) that lies under the face k of F: the
 * feature clipped by F's side slabs, averaged. Returns 0 when nothing of the feature lies under the
 * face (the axis is then not the facet that realises the depth). */
static int face_witness(const prox_bframe *F, int k, const prox_bframe *S, prox_vec3 dir, prox_vec3 *w)
{
    prox_vec3 poly[8];
    int n = support_feature(S, dir, poly);
    for (int j = 0; j < 3 && n > 0; ++j) {
        if (j == k) continue;
        double c = prox_v3_dot(F->a[j], F->m);
        n = clip_poly(poly, n, F->a[j], c + F->h[j]);
        if (n > 0) n = clip_poly(poly, n, prox_v3_neg(F->a[j]), F->h[j] - c);
    }
    if (n == 0) return 0;
    prox_vec3 avg = {0, 0, 0};
    for (int i = 0; i < n; ++i) avg = prox_v3_mad(avg, 1.0 / n, poly[i]);
    *w = avg;
    return 1;
}

/* Witnesses p1 in A, p2 = p1 - o n in B for SAT axis i (unit n from A towards B, overlap o). Returns 0
 * when the axis does not realise the depth: nothing of the opposite support feature under the face,
 * or two support edges that do not cross (closest points at an end, off the axis). */
static int axis_witness(const prox_bframe *A, const prox_bframe *B, int i, prox_vec3 n, double o, double tol,
                        prox_vec3 *p1, prox_vec3 *p2)
{
    if (i < 3) { /* face of A: B's deepest feature under it */
        if (!face_witness(A, i, B, prox_v3_neg(n), p2)) return 0;
        *p1 = prox_v3_mad(*p2, o, n);
        return 1;
    }
    if (i < 6) { /* face of B: A's deepest feature under it */
        if (!face_witness(B, i - 3, A, n, p1)) return 0;
        *p2 = prox_v3_mad(*p1, -o, n);
        return 1;
    }
    /* edge-edge: the support edges of A (along n) and B (along -n) */
    int ea = (i - 6) / 3, eb = (i - 6) % 3;
    double la[3], lb[3];
    for (int k = 0; k < 3; ++k) {
        la[k] = prox_v3_dot(n, A->a[k]) >= 0.0 ? A->h[k] : -A->h[k];
        lb[k] = prox_v3_dot(n, B->a[k]) <= 0.0 ? B->h[k] : -B->h[k];
    }
    la[ea] = -A->h[ea];
    lb[eb] = -B->h[eb];
    prox_vec3 pa = prox_bframe_point(A, la), pb = prox_bframe_point(B, lb);
    prox_vec3 qa = prox_v3_mad(pa, 2.0 * A->h[ea], A->a[ea]), qb = prox_v3_mad(pb, 2.0 * B->h[eb], B->a[eb]);
    prox_seg_seg(pa, qa, pb, qb, p1, p2);
    return prox_v3_dist(*p2, prox_v3_mad(*p1, -o, n)) <= tol;
}

PROX_API prox_signed_result prox_box_box_signed_distance(const prox_box *a, const prox_box *b)
{
    prox_signed_result r = {0};
    r.status = prox_valid2(prox_box_validate(a), prox_box_validate(b));
    if (r.status != PROX_OK) return r;
    prox_bframe A = prox_bframe_make(a), B = prox_bframe_make(b);
    r = prox_box_pair_signed(&A, &B);
    r.certified = 1; /* the 15 axes examined */
    prox_shape sa = prox_shape_from_box(*a), sb = prox_shape_from_box(*b);
    prox_shape_signed_bounds(&sa, &sb, &r);
    return r;
}

static prox_signed_result unit_signed(const prox_bframe *pA, const prox_bframe *pB);

prox_signed_result prox_box_pair_signed(const prox_bframe *pA, const prox_bframe *pB)
{
    prox_bframe A, B;
    double u;
    unit_pair(pA, pB, &A, &B, &u);
    prox_signed_result r = unit_signed(&A, &B);
    double iu = 1.0 / u;
    r.sd *= iu;
    r.sd_lower *= iu;
    r.p1 = unit_back(r.p1, iu, pA->m);
    r.p2 = unit_back(r.p2, iu, pA->m);
    return r;
}

/* prox_box_pair_signed of a pair at unit scale. */
static prox_signed_result unit_signed(const prox_bframe *pA, const prox_bframe *pB)
{
    prox_signed_result r = {0};
    prox_distance_result d = unit_distance(pA, pB);
    if (!d.intersect && d.distance > 0.0) return prox_signed_from_disjoint(&d);
    /* Depth: the least overlap over the 15 axes (exact). Witness: the axes in increasing overlap until
     * one realises it (ties between a face and an edge axis, e.g. an edge lying across a face, can put
     * first an axis whose support features do not meet). */
    const prox_bframe A = *pA, B = *pB;
    double ov[15], tol = PROX_TOL_TIE * bb_scale(&A, &B); /* overlaps within it are a tie */
    prox_vec3 ax[15];
    int order[15], m = 0;
    for (int i = 0; i < 15; ++i) {
        if (!sat_axis(&A, &B, i, &ax[i])) continue;
        ov[i] = axis_overlap(&A, &B, ax[i]);
        if (prox_v3_dot(prox_v3_sub(B.m, A.m), ax[i]) < 0.0) ax[i] = prox_v3_neg(ax[i]);
        int j = m++;
        for (; j > 0 && ov[order[j - 1]] > ov[i]; --j) order[j] = order[j - 1];
        order[j] = i;
    }
    double o = ov[order[0]];
    r.sd = -o;
    for (int k = 0; k < m; ++k) {
        int i = order[k];
        if (ov[i] > o + tol) break;
        if (axis_witness(&A, &B, i, ax[i], o, tol, &r.p1, &r.p2)) {
            r.normal = ax[i];
            return r;
        }
    }
    r.normal = ax[order[0]]; /* not reached in exact arithmetic: keep the least axis */
    axis_witness(&A, &B, order[0], r.normal, o, tol, &r.p1, &r.p2);
    return r;
}
