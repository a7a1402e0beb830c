/* Independent long-double description of the polytope macrobodies for the polytope tests
 * (test_polytope.c, test_poly_pairs.c): each body's face planes written straight from the MCNP card
 * definitions (with their facet numbers), its corners (RHP's by enumerating triples of planes), the
 * support function and plane residual from those; and random cards of every kind, including
 * near-degenerate ones. No library polytope code is used here. */
#ifndef PROX_TEST_POLY_BRUTE_H
#define PROX_TEST_POLY_BRUTE_H

#include "test_brute.h"

typedef struct tp_body {
    int nv, nf;
    lv3 v[16];
    lv3 n[8];
    ld d[8];
    int facet[8];
    ld size;
} tp_body;

static inline void tp_plane(tp_body *B, lv3 n, lv3 through, int facet)
{
    n = lunit(n);
    B->n[B->nf] = n;
    B->d[B->nf] = ldot(n, through);
    B->facet[B->nf] = facet;
    B->nf++;
}

/* Plane with normal +-n through x, turned to face away from the interior point g. */
static inline void tp_plane_away(tp_body *B, lv3 n, lv3 x, lv3 g, int facet)
{
    if (ldot(n, lsub(x, g)) < 0) n = lsc(n, -1);
    tp_plane(B, n, x, facet);
}

static inline void tp_size(tp_body *B)
{
    B->size = 0;
    for (int i = 0; i < B->nv; ++i)
        for (int j = 0; j < B->nv; ++j) {
            ld d = lnorm(lsub(B->v[i], B->v[j]));
            if (d > B->size) B->size = d;
        }
}

/* Corners as the points where three planes meet inside all the others (Cramer's rule). */
static inline void tp_corners_from_planes(tp_body *B, ld tol)
{
    B->nv = 0;
    for (int i = 0; i < B->nf; ++i)
        for (int j = i + 1; j < B->nf; ++j)
            for (int k = j + 1; k < B->nf; ++k) {
                lv3 a = B->n[i], b = B->n[j], c = B->n[k];
                lv3 bc = lcross(b, c);
                ld det = ldot(a, bc);
                if (fabsl(det) < 1e-12L) continue;
                lv3 x = lsc(ladd(ladd(lsc(bc, B->d[i]), lsc(lcross(c, a), B->d[j])), lsc(lcross(a, b), B->d[k])),
                            1.0L / det);
                int ok = 1;
                for (int f = 0; f < B->nf && ok; ++f) ok = ldot(B->n[f], x) - B->d[f] <= tol;
                for (int m = 0; m < B->nv && ok; ++m) ok = lnorm(lsub(B->v[m], x)) > tol;
                if (ok && B->nv < 16) B->v[B->nv++] = x;
            }
}

static inline tp_body tp_from_box(const prox_box *b)
{
    tp_body B = {0};
    for (int i = 0; i < 8; ++i) {
        lv3 x = L(b->corner);
        for (int k = 0; k < 3; ++k)
            if (i >> k & 1) x = ladd(x, L(b->edge[k]));
        B.v[B.nv++] = x;
    }
    for (int k = 0; k < 3; ++k) { /* MCNP BOX: 2k+1 at the end of a_k, 2k+2 at its start */
        tp_plane(&B, L(b->edge[k]), ladd(L(b->corner), L(b->edge[k])), 2 * k + 1);
        tp_plane(&B, lsc(L(b->edge[k]), -1), L(b->corner), 2 * k + 2);
    }
    tp_size(&B);
    return B;
}

static inline tp_body tp_from_rpp(const prox_rpp *r)
{
    tp_body B = {0};
    const double lo[3] = {r->xmin, r->ymin, r->zmin}, hi[3] = {r->xmax, r->ymax, r->zmax};
    for (int i = 0; i < 8; ++i)
        B.v[B.nv++] = (lv3){(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]};
    for (int k = 0; k < 3; ++k) { /* MCNP RPP: 1 xmax, 2 xmin, 3 ymax, ... */
        lv3 e = {k == 0, k == 1, k == 2};
        lv3 ph = {k == 0 ? hi[0] : 0, k == 1 ? hi[1] : 0, k == 2 ? hi[2] : 0};
        lv3 pl = {k == 0 ? lo[0] : 0, k == 1 ? lo[1] : 0, k == 2 ? lo[2] : 0};
        tp_plane(&B, e, ph, 2 * k + 1);
        tp_plane(&B, lsc(e, -1), pl, 2 * k + 2);
    }
    tp_size(&B);
    return B;
}

static inline tp_body tp_from_rhp(const prox_rhp *h)
{
    tp_body B = {0};
    lv3 base = L(h->base), top = ladd(base, L(h->axis));
    for (int i = 0; i < 3; ++i) { /* MCNP RHP: 1 +r, 2 -r, 3 +s, 4 -s, 5 +t, 6 -t, 7 top, 8 base */
        tp_plane(&B, L(h->r[i]), ladd(base, L(h->r[i])), 2 * i + 1);
        tp_plane(&B, lsc(L(h->r[i]), -1), lsub(base, L(h->r[i])), 2 * i + 2);
    }
    tp_plane(&B, L(h->axis), top, 7);
    tp_plane(&B, lsc(L(h->axis), -1), base, 8);
    ld sc = lnorm(L(h->axis)) + lnorm(L(h->r[0])) + lnorm(L(h->r[1])) + lnorm(L(h->r[2]));
    tp_corners_from_planes(&B, 1e-13L * sc);
    tp_size(&B);
    return B;
}

static inline tp_body tp_from_wed(const prox_wed *w)
{
    tp_body B = {0};
    lv3 v = L(w->vertex), a = L(w->v1), b = L(w->v2), h = L(w->v3);
    lv3 tri[3] = {v, ladd(v, a), ladd(v, b)};
    for (int i = 0; i < 3; ++i) B.v[B.nv++] = tri[i];
    for (int i = 0; i < 3; ++i) B.v[B.nv++] = ladd(tri[i], h);
    lv3 g = ladd(lsc(ladd(ladd(tri[0], tri[1]), tri[2]), 1.0L / 3), lsc(h, 0.5L));
    /* MCNP WED: 1 slant, 2 the side of v2 and v3, 3 the side of v1 and v3, 4 top, 5 base */
    tp_plane_away(&B, lcross(lsub(b, a), h), tri[1], g, 1);
    tp_plane_away(&B, lcross(b, h), v, g, 2);
    tp_plane_away(&B, lcross(a, h), v, g, 3);
    tp_plane(&B, h, ladd(v, h), 4);
    tp_plane(&B, lsc(h, -1), v, 5);
    tp_size(&B);
    return B;
}

static inline tp_body tp_from_arb(const prox_arb *a)
{
    tp_body B = {0};
    int used[9] = {0};
    for (int f = 0; f < 6; ++f)
        for (int x = a->face[f]; x > 0; x /= 10) used[x % 10] = 1;
    lv3 g = {0, 0, 0};
    for (int c = 1; c <= 8; ++c)
        if (used[c]) B.v[B.nv++] = L(a->corner[c - 1]), g = ladd(g, L(a->corner[c - 1]));
    g = lsc(g, 1.0L / B.nv);
    for (int f = 0; f < 6; ++f) {
        if (a->face[f] == 0) continue;
        int d0 = a->face[f] / 1000, d1 = a->face[f] / 100 % 10, d2 = a->face[f] / 10 % 10;
        lv3 p0 = L(a->corner[d0 - 1]), p1 = L(a->corner[d1 - 1]), p2 = L(a->corner[d2 - 1]);
        tp_plane_away(&B, lcross(lsub(p1, p0), lsub(p2, p0)), p0, g, f + 1); /* MCNP ARB: k-th face entry */
    }
    tp_size(&B);
    return B;
}

static inline tp_body tp_from_shape(const prox_shape *s)
{
    switch (s->kind) {
    case PROX_SHAPE_BOX: return tp_from_box(&s->u.box);
    case PROX_SHAPE_RPP: return tp_from_rpp(&s->u.rpp);
    case PROX_SHAPE_RHP: return tp_from_rhp(&s->u.rhp);
    case PROX_SHAPE_WED: return tp_from_wed(&s->u.wed);
    default: return tp_from_arb(&s->u.arb);
    }
}

static inline ld tp_support(const tp_body *B, lv3 n)
{
    ld m = ldot(n, B->v[0]);
    for (int i = 1; i < B->nv; ++i) m = fmaxl(m, ldot(n, B->v[i]));
    return m;
}

/* max_f n_f.x - d_f: <= 0 inside, 0 on the boundary (a distance within the body's size). */
static inline ld tp_resid(const tp_body *B, lv3 x)
{
    ld m = -INFINITY;
    for (int f = 0; f < B->nf; ++f) m = fmaxl(m, ldot(B->n[f], x) - B->d[f]);
    return m;
}

/* Separation of B2 from B1 along the unit n: min_{B2} n.y - max_{B1} n.x. */
static inline ld tp_sep(const tp_body *B1, const tp_body *B2, lv3 n)
{
    return -tp_support(B2, lsc(n, -1)) - tp_support(B1, n);
}

/* ---- random cards ---- */

/* Unit vector orthogonal to the unit w, at a random angle. */
static inline prox_vec3 tp_perp(test_rng *g, prox_vec3 w)
{
    prox_vec3 e = prox_v3_normalize(prox_v3_reject(test_unit(g), w));
    return e;
}

static inline prox_shape tp_rand_box(test_rng *g, prox_vec3 o, double s)
{
    test_rot R = test_random_rot(g);
    prox_box b;
    b.corner = o;
    for (int k = 0; k < 3; ++k)
        b.edge[k] = prox_v3_scale(test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2)), s * test_range(g, 0.2, 1));
    return prox_shape_from_box(b);
}

static inline prox_shape tp_rand_rpp(test_rng *g, prox_vec3 o, double s)
{
    prox_rpp r = {o.x, o.x + s * test_range(g, 0.2, 1), o.y, o.y + s * test_range(g, 0.2, 1), o.z,
                  o.z + s * test_range(g, 0.2, 1)};
    return prox_shape_from_rpp(r);
}

/* RHP: regular (9-entry form) or a general hexagon (15 entries: s and t at 60 and 120 degrees give or
 * take 15, lengths 0.8 .. 1.2 of r's); height hfrac x s. */
static inline prox_shape tp_rand_rhp(test_rng *g, prox_vec3 o, double s, int regular, double hfrac)
{
    prox_vec3 w = test_unit(g), e1 = tp_perp(g, w), e2 = prox_v3_cross(w, e1);
    prox_vec3 axis = prox_v3_scale(w, s * hfrac);
    double r0 = 0.5 * s * test_range(g, 0.5, 1);
    prox_rhp h;
    if (regular) {
        prox_status st = prox_rhp_regular(o, axis, prox_v3_scale(e1, r0), &h);
        if (st != PROX_OK) fail();
    } else {
        h.base = o;
        h.axis = axis;
        h.r[0] = prox_v3_scale(e1, r0);
        for (int i = 1; i < 3; ++i) {
            double th = (i * 60.0 + test_range(g, -15, 15)) * PROX_PI / 180.0;
            double len = r0 * test_range(g, 0.8, 1.2);
            h.r[i] = prox_v3_scale(prox_v3_add(prox_v3_scale(e1, cos(th)), prox_v3_scale(e2, sin(th))), len);
        }
    }
    return prox_shape_from_rhp(h);
}

/* WED with the triangle's angle at the vertex in [amin, amax] rad. */
static inline prox_shape tp_rand_wed(test_rng *g, prox_vec3 o, double s, double amin, double amax)
{
    prox_vec3 w = test_unit(g), e1 = tp_perp(g, w), e2 = prox_v3_cross(w, e1);
    double th = test_range(g, amin, amax);
    if (test_uniform(g) < 0.5) th = -th; /* either turn about the height */
    prox_wed x;
    x.vertex = o;
    x.v1 = prox_v3_scale(e1, s * test_range(g, 0.3, 1));
    x.v2 = prox_v3_scale(prox_v3_add(prox_v3_scale(e1, cos(th)), prox_v3_scale(e2, sin(th))), s * test_range(g, 0.3, 1));
    x.v3 = prox_v3_scale(w, s * test_range(g, 0.2, 1));
    return prox_shape_from_wed(x);
}

/* ARB of type 0 tetrahedron, 1 square pyramid, 2 frustum of a square pyramid, 3 parallelepiped,
 * 4 prism over a quadrilateral whose angle at one corner is pi - flat (two nearly coplanar faces):
 * built in a local frame, then rotated and placed at o; face entries in a random order of loops. */
static inline prox_shape tp_rand_arb(test_rng *g, prox_vec3 o, double s, int type, double flat)
{
    prox_arb a = {0};
    prox_vec3 c[8];
    int nc = 0, faces[6] = {0};
    switch (type) {
    case 0:
        for (;;) {
            for (int i = 0; i < 4; ++i) c[i] = prox_v3(test_range(g, -1, 1), test_range(g, -1, 1), test_range(g, -1, 1));
            double vol = prox_v3_dot(prox_v3_sub(c[1], c[0]), prox_v3_cross(prox_v3_sub(c[2], c[0]), prox_v3_sub(c[3], c[0])));
            if (fabs(vol) > 0.2) break;
        }
        nc = 4;
        faces[0] = 1230, faces[1] = 1240, faces[2] = 1340, faces[3] = 2340;
        break;
    case 1: {
        double hx = test_range(g, 0.3, 1), hy = test_range(g, 0.3, 1);
        c[0] = prox_v3(-hx, -hy, 0), c[1] = prox_v3(hx, -hy, 0), c[2] = prox_v3(hx, hy, 0), c[3] = prox_v3(-hx, hy, 0);
        c[4] = prox_v3(test_range(g, -0.5, 0.5), test_range(g, -0.5, 0.5), test_range(g, 0.3, 1));
        nc = 5;
        faces[0] = 1234, faces[1] = 1250, faces[2] = 2350, faces[3] = 3450, faces[4] = 4150;
        break;
    }
    case 2: {
        double hx = test_range(g, 0.3, 1), hy = test_range(g, 0.3, 1), lam = test_range(g, 0.2, 0.9), z = test_range(g, 0.3, 1);
        prox_vec3 sh = prox_v3(test_range(g, -0.3, 0.3), test_range(g, -0.3, 0.3), z);
        c[0] = prox_v3(-hx, -hy, 0), c[1] = prox_v3(hx, -hy, 0), c[2] = prox_v3(hx, hy, 0), c[3] = prox_v3(-hx, hy, 0);
        for (int i = 0; i < 4; ++i) c[4 + i] = prox_v3_add(prox_v3_scale(c[i], lam), sh);
        nc = 8;
        faces[0] = 1234, faces[1] = 5678, faces[2] = 1265, faces[3] = 2376, faces[4] = 3487, faces[5] = 4158;
        break;
    }
    case 3: {
        prox_vec3 e[3];
        for (;;) {
            for (int k = 0; k < 3; ++k) e[k] = prox_v3_scale(test_unit(g), test_range(g, 0.4, 1));
            if (fabs(prox_v3_dot(e[0], prox_v3_cross(e[1], e[2]))) > 0.1) break;
        }
        for (int i = 0; i < 8; ++i) {
            prox_vec3 x = prox_v3(0, 0, 0);
            for (int k = 0; k < 3; ++k)
                if (i >> k & 1) x = prox_v3_add(x, e[k]);
            c[i] = x;
        }
        nc = 8; /* corners by bits: 1 (000) 2 (100) 3 (010) 4 (110) 5 (001) ... */
        faces[0] = 1243, faces[1] = 5687, faces[2] = 1265, faces[3] = 3487, faces[4] = 1375, faces[5] = 2486;
        break;
    }
    default: {
        double z = test_range(g, 0.3, 1);
        c[0] = prox_v3(-1, 0, 0), c[1] = prox_v3(0, -test_range(g, 0.5, 1), 0), c[2] = prox_v3(1, 0, 0);
        c[3] = prox_v3(0, flat, 0);
        for (int i = 0; i < 4; ++i) c[4 + i] = prox_v3_add(c[i], prox_v3(0, 0, z));
        nc = 8;
        faces[0] = 1234, faces[1] = 5678, faces[2] = 1265, faces[3] = 2376, faces[4] = 3487, faces[5] = 4158;
        break;
    }
    }
    test_rot R = test_random_rot(g);
    for (int i = 0; i < nc; ++i) a.corner[i] = prox_v3_add(o, prox_v3_scale(test_rot_apply(&R, c[i]), 0.5 * s));
    int nf = 0;
    for (int i = 0; i < 6; ++i)
        if (faces[i]) ++nf;
    for (int i = nf - 1; i > 0; --i) { /* shuffle the face entries */
        int j = (int)(test_uniform(g) * (i + 1));
        int t = faces[i];
        faces[i] = faces[j];
        faces[j] = t;
    }
    for (int i = 0; i < 6; ++i) a.face[i] = faces[i];
    return prox_shape_from_arb(a);
}

/* A random polytope of kind k (0 BOX, 1 RPP, 2 RHP regular, 3 RHP general, 4 WED, 5-9 ARB types 0-4)
 * of size about s at o. */
#define TP_KINDS 10
static inline prox_shape tp_rand_kind(test_rng *g, int k, prox_vec3 o, double s)
{
    switch (k) {
    case 0: return tp_rand_box(g, o, s);
    case 1: return tp_rand_rpp(g, o, s);
    case 2: return tp_rand_rhp(g, o, s, 1, test_range(g, 0.2, 1.5));
    case 3: return tp_rand_rhp(g, o, s, 0, test_range(g, 0.2, 1.5));
    case 4: return tp_rand_wed(g, o, s, 0.3, 2.8);
    default: return tp_rand_arb(g, o, s, k - 5, 0.3);
    }
}

/* Near-degenerate polytopes: 0 a flat WED (vertex angle 1e-6 .. 1e-4 rad), 1 an ARB prism with two
 * faces at pi - 1e-7 .. 1e-5, 2 a nearly flat RHP (height 1e-6 of the hexagon). */
#define TP_DEGEN_KINDS 3
static inline prox_shape tp_rand_degen(test_rng *g, int k, prox_vec3 o, double s)
{
    switch (k) {
    case 0: return tp_rand_wed(g, o, s, 1e-6, 1e-4);
    case 1: return tp_rand_arb(g, o, s, 4, pow(10.0, test_range(g, -7, -5)));
    default: return tp_rand_rhp(g, o, s, test_uniform(g) < 0.5, 1e-6);
    }
}

/* ---- exhaustive long-double distance of two disjoint bodies ---- */

/* On plane f (within tol)? */
static inline int tp_on(const tp_body *B, int f, lv3 x, ld tol) { return fabsl(ldot(B->n[f], x) - B->d[f]) <= tol; }

/* Distance from x to face f's polygon (its corners sorted by angle about their mean). */
static inline ld tp_face_dist(const tp_body *B, int f, lv3 x, ld tol)
{
    int idx[16], m = 0;
    for (int i = 0; i < B->nv; ++i)
        if (tp_on(B, f, B->v[i], tol)) idx[m++] = i;
    lv3 g = {0, 0, 0};
    for (int i = 0; i < m; ++i) g = ladd(g, B->v[idx[i]]);
    g = lsc(g, 1.0L / m);
    lv3 n = B->n[f], e1 = lunit(lsub(B->v[idx[0]], g)), e2 = lcross(n, e1);
    ld ang[16];
    for (int i = 0; i < m; ++i) {
        lv3 r = lsub(B->v[idx[i]], g);
        ang[i] = atan2l(ldot(r, e2), ldot(r, e1));
    }
    for (int i = 1; i < m; ++i)
        for (int j = i; j > 0 && ang[j - 1] > ang[j]; --j) {
            ld t = ang[j]; ang[j] = ang[j - 1]; ang[j - 1] = t;
            int k = idx[j]; idx[j] = idx[j - 1]; idx[j - 1] = k;
        }
    lv3 foot = lsub(x, lsc(n, ldot(n, x) - B->d[f]));
    int inside = 1;
    for (int i = 0; i < m && inside; ++i) {
        lv3 a = B->v[idx[i]], b = B->v[idx[(i + 1) % m]];
        if (ldot(lcross(lsub(b, a), lsub(foot, a)), n) < 0) inside = 0;
    }
    if (inside) return fabsl(ldot(n, x) - B->d[f]);
    ld best = INFINITY;
    for (int i = 0; i < m; ++i) {
        lv3 a = B->v[idx[i]], b = B->v[idx[(i + 1) % m]];
        best = fminl(best, lseg_dist(x, a, lsub(b, a)));
    }
    return best;
}

/* Distance from x (outside) to the solid: the least over the faces it is in front of. */
static inline ld tp_point_dist(const tp_body *B, lv3 x)
{
    ld tol = 1e-10L * B->size, best = INFINITY;
    for (int f = 0; f < B->nf; ++f)
        if (ldot(B->n[f], x) - B->d[f] > 0) best = fminl(best, tp_face_dist(B, f, x, tol));
    return best < INFINITY ? best : 0;
}

/* Distance of two segments: the interior stationary point when it lies inside both, else the least
 * endpoint-segment distance. */
static inline ld tp_seg_seg(lv3 p1, lv3 q1, lv3 p2, lv3 q2)
{
    lv3 d1 = lsub(q1, p1), d2 = lsub(q2, p2), r = lsub(p1, p2);
    ld a = ldot(d1, d1), e = ldot(d2, d2), b = ldot(d1, d2), c = ldot(d1, r), f = ldot(d2, r);
    ld den = a * e - b * b, best = INFINITY;
    if (den > 1e-24L * a * e) {
        ld s = (b * f - c * e) / den, t = (a * f - b * c) / den;
        if (s >= 0 && s <= 1 && t >= 0 && t <= 1) best = lnorm(lsub(ladd(p1, lsc(d1, s)), ladd(p2, lsc(d2, t))));
    }
    best = fminl(best, lseg_dist(p1, p2, d2));
    best = fminl(best, lseg_dist(q1, p2, d2));
    best = fminl(best, lseg_dist(p2, p1, d1));
    best = fminl(best, lseg_dist(q2, p1, d1));
    return best;
}

/* Edges: corner pairs sharing two planes. */
static inline int tp_edges(const tp_body *B, int e[][2])
{
    ld tol = 1e-10L * B->size;
    int m = 0;
    for (int i = 0; i < B->nv; ++i)
        for (int j = i + 1; j < B->nv; ++j) {
            int k = 0;
            for (int f = 0; f < B->nf; ++f) k += tp_on(B, f, B->v[i], tol) && tp_on(B, f, B->v[j], tol);
            if (k >= 2) e[m][0] = i, e[m][1] = j, ++m;
        }
    return m;
}

/* Exhaustive distance of disjoint bodies: corners against the other solid, edges against edges. */
static inline ld tp_distance(const tp_body *A, const tp_body *B)
{
    ld best = INFINITY;
    for (int i = 0; i < A->nv; ++i) best = fminl(best, tp_point_dist(B, A->v[i]));
    for (int i = 0; i < B->nv; ++i) best = fminl(best, tp_point_dist(A, B->v[i]));
    int ea[64][2], eb[64][2], na = tp_edges(A, ea), nb = tp_edges(B, eb);
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j)
            best = fminl(best, tp_seg_seg(A->v[ea[i][0]], A->v[ea[i][1]], B->v[eb[j][0]], B->v[eb[j][1]]));
    return best;
}

#endif
