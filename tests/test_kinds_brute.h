/* Long-double toolkit of the all-kinds tests (test_query_all_kinds.c, test_contain_all_kinds.c):
 * random shapes of the ten macrobodies, and for each shape, written here from the card definitions
 * and independent of the library, its support function and support point, membership, and sampled
 * brute-force answers (distance over pairs of support points, depth and clearance minimised over
 * sampled directions and refined). The library is called only to validate a generated shape. */
#ifndef PROX_TEST_KINDS_BRUTE_H
#define PROX_TEST_KINDS_BRUTE_H

#include "test_brute.h"

#include <string.h>

/* A shape in the test's own terms: a frame (centre c, unit axis w, e1, e2 across it), its sizes, and
 * for a polytope its corners and face planes n.x <= d. */
typedef struct tk_body {
    prox_shape_kind kind;
    lv3 c, w, e1, e2;
    ld hh, r, r1, r2, a1, a2; /* half height; radius; TRC radii; REC / ELL semi-axes (ELL: a1 axial, a2 equatorial) */
    int nv, nf;
    lv3 v[12], n[40];
    ld d[40];
} tk_body;

static inline lv3 tk_any_perp(lv3 w)
{
    lv3 a = fabsl(w.x) < 0.6L ? (lv3){1, 0, 0} : (lv3){0, 1, 0};
    return lunit(lsub(a, lsc(w, ldot(a, w))));
}

/* Face planes of the hull of the corners: every plane through three corners with all corners behind. */
static inline void tk_faces(tk_body *b)
{
    ld S = 0;
    for (int i = 0; i < b->nv; ++i) S = fmaxl(S, lnorm(lsub(b->v[i], b->c)));
    b->nf = 0;
    for (int i = 0; i < b->nv; ++i)
        for (int j = i + 1; j < b->nv; ++j)
            for (int k = j + 1; k < b->nv; ++k) {
                lv3 n = lcross(lsub(b->v[j], b->v[i]), lsub(b->v[k], b->v[i]));
                ld len = lnorm(n);
                if (!(len > 1e-9L * S * S)) continue;
                n = lsc(n, 1 / len);
                ld d = ldot(n, b->v[i]);
                int pos = 0, neg = 0;
                for (int m = 0; m < b->nv; ++m) {
                    ld s = ldot(n, b->v[m]) - d;
                    pos += s > 1e-12L * S, neg += s < -1e-12L * S;
                }
                if (pos && neg) continue;
                if (pos) n = lsc(n, -1), d = -d;
                int dup = 0;
                for (int f = 0; f < b->nf; ++f)
                    if (ldot(b->n[f], n) > 1 - 1e-15L && fabsl(b->d[f] - d) <= 1e-12L * S) dup = 1;
                if (!dup && b->nf < 40) b->n[b->nf] = n, b->d[b->nf] = d, b->nf++;
            }
}

/* The test's body of a valid shape. */
static inline tk_body tk_make(const prox_shape *s)
{
    tk_body b;
    memset(&b, 0, sizeof b);
    b.kind = s->kind;
    switch (s->kind) {
    case PROX_SHAPE_RCC: case PROX_SHAPE_TRC: case PROX_SHAPE_REC: {
        prox_vec3 base = s->kind == PROX_SHAPE_RCC ? s->u.rcc.base : (s->kind == PROX_SHAPE_TRC ? s->u.trc.base : s->u.rec.base);
        prox_vec3 ax = s->kind == PROX_SHAPE_RCC ? s->u.rcc.axis : (s->kind == PROX_SHAPE_TRC ? s->u.trc.axis : s->u.rec.axis);
        b.hh = lnorm(L(ax)) / 2;
        b.w = lunit(L(ax));
        b.c = ladd(L(base), lsc(L(ax), 0.5L));
        b.e1 = tk_any_perp(b.w);
        if (s->kind == PROX_SHAPE_RCC) b.r = s->u.rcc.radius;
        if (s->kind == PROX_SHAPE_TRC) b.r1 = s->u.trc.r1, b.r2 = s->u.trc.r2;
        if (s->kind == PROX_SHAPE_REC) {
            b.a1 = lnorm(L(s->u.rec.a1)), b.a2 = lnorm(L(s->u.rec.a2));
            b.e1 = lunit(L(s->u.rec.a1));
            b.e1 = lunit(lsub(b.e1, lsc(b.w, ldot(b.e1, b.w))));
        }
        b.e2 = lcross(b.w, b.e1);
        break;
    }
    case PROX_SHAPE_SPH: b.c = L(s->u.sph.center), b.r = s->u.sph.radius; break;
    case PROX_SHAPE_ELL:
        b.c = L(s->u.ell.center), b.w = lunit(L(s->u.ell.axis));
        b.a1 = lnorm(L(s->u.ell.axis)), b.a2 = s->u.ell.radius;
        break;
    case PROX_SHAPE_BOX: case PROX_SHAPE_RPP: {
        prox_box x = s->kind == PROX_SHAPE_BOX ? s->u.box : prox_rpp_to_box(&s->u.rpp);
        b.nv = 8;
        for (int i = 0; i < 8; ++i) {
            lv3 p = L(x.corner);
            for (int k = 0; k < 3; ++k)
                if (i >> k & 1) p = ladd(p, L(x.edge[k]));
            b.v[i] = p;
        }
        break;
    }
    case PROX_SHAPE_RHP: {
        const prox_rhp *h = &s->u.rhp;
        lv3 r[6];
        for (int i = 0; i < 3; ++i) r[i] = L(h->r[i]), r[i + 3] = lsc(L(h->r[i]), -1);
        lv3 w = lunit(L(h->axis));
        b.nv = 12;
        for (int i = 0; i < 6; ++i) { /* corner of sides i and i+1: v.r = |r|^2 for both, v.w = 0 */
            lv3 p = r[i], q = r[(i + 1) % 6];
            ld pp = ldot(p, p), qq = ldot(q, q), pq = ldot(p, q), det = pp * qq - pq * pq;
            ld al = (pp * qq - qq * pq) / det, be = (qq * pp - pp * pq) / det;
            lv3 v = ladd(L(h->base), ladd(lsc(p, al), lsc(q, be)));
            b.v[i] = v;
            b.v[i + 6] = ladd(v, L(h->axis));
            (void)w;
        }
        break;
    }
    case PROX_SHAPE_WED: {
        const prox_wed *x = &s->u.wed;
        lv3 o = L(x->vertex), tri[3] = {o, ladd(o, L(x->v1)), ladd(o, L(x->v2))};
        b.nv = 6;
        for (int i = 0; i < 3; ++i) b.v[i] = tri[i], b.v[i + 3] = ladd(tri[i], L(x->v3));
        break;
    }
    default: { /* ARB: the corners its faces name */
        unsigned m = 0;
        for (int f = 0; f < 6; ++f)
            for (int x = s->u.arb.face[f]; x > 0; x /= 10)
                if (x % 10) m |= 1u << (x % 10 - 1);
        for (int i = 0; i < 8; ++i)
            if (m >> i & 1) b.v[b.nv++] = L(s->u.arb.corner[i]);
        break;
    }
    }
    if (b.nv) {
        b.c = (lv3){0, 0, 0};
        for (int i = 0; i < b.nv; ++i) b.c = ladd(b.c, lsc(b.v[i], 1.0L / b.nv));
        tk_faces(&b);
    }
    return b;
}

static inline ld tk_sgn(ld x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

/* The part of d across the unit axis w, rejected twice (one pass leaves a residual along w that
 * normalising a nearly axial d would blow up). */
static inline lv3 tk_across(lv3 d, lv3 w)
{
    lv3 p = lsub(d, lsc(w, ldot(d, w)));
    return lsub(p, lsc(w, ldot(p, w)));
}

/* Support point (d need not be unit). */
static inline lv3 tk_support_point(const tk_body *b, lv3 d)
{
    lv3 pd = tk_across(d, b->w);
    ld dw = ldot(d, b->w), np = lnorm(pd);
    switch (b->kind) {
    case PROX_SHAPE_SPH: return ladd(b->c, lsc(d, b->r / lnorm(d)));
    case PROX_SHAPE_RCC: {
        lv3 p = ladd(b->c, lsc(b->w, b->hh * tk_sgn(dw)));
        return np > 0 ? ladd(p, lsc(pd, b->r / np)) : p;
    }
    case PROX_SHAPE_TRC: {
        ld vb = -b->hh * dw + b->r1 * np, vt = b->hh * dw + b->r2 * np;
        int top = vt >= vb;
        lv3 p = ladd(b->c, lsc(b->w, top ? b->hh : -b->hh));
        return np > 0 ? ladd(p, lsc(pd, (top ? b->r2 : b->r1) / np)) : p;
    }
    case PROX_SHAPE_REC: {
        ld d1 = b->a1 * ldot(d, b->e1), d2 = b->a2 * ldot(d, b->e2), h = sqrtl(d1 * d1 + d2 * d2);
        lv3 p = ladd(b->c, lsc(b->w, b->hh * tk_sgn(dw)));
        return h > 0 ? ladd(p, ladd(lsc(b->e1, b->a1 * d1 / h), lsc(b->e2, b->a2 * d2 / h))) : p;
    }
    case PROX_SHAPE_ELL: { /* M d / sqrt(d^T M d) */
        lv3 md = ladd(lsc(b->w, b->a1 * b->a1 * dw), lsc(pd, b->a2 * b->a2));
        return ladd(b->c, lsc(md, 1 / sqrtl(ldot(d, md))));
    }
    default: {
        int best = 0;
        for (int i = 1; i < b->nv; ++i)
            if (ldot(d, b->v[i]) > ldot(d, b->v[best])) best = i;
        return b->v[best];
    }
    }
}

/* Support function h(d) in closed form (d need not be unit): Eberly's Eq. (4) for the cylinder, the
 * hull of the two rims for the cone, the caps' ellipses for REC, sqrt(d^T M d) for the ellipsoid. */
static inline ld tk_support(const tk_body *b, lv3 d)
{
    ld dw = ldot(d, b->w), np = lnorm(tk_across(d, b->w)), dc = ldot(d, b->c);
    switch (b->kind) {
    case PROX_SHAPE_SPH: return dc + b->r * lnorm(d);
    case PROX_SHAPE_RCC: return dc + b->hh * fabsl(dw) + b->r * np;
    case PROX_SHAPE_TRC: return dc + fmaxl(-b->hh * dw + b->r1 * np, b->hh * dw + b->r2 * np);
    case PROX_SHAPE_REC: return dc + b->hh * fabsl(dw) + sqrtl(powl(b->a1 * ldot(d, b->e1), 2) + powl(b->a2 * ldot(d, b->e2), 2));
    case PROX_SHAPE_ELL: return dc + sqrtl(powl(b->a1 * dw, 2) + powl(b->a2 * np, 2));
    default: return ldot(d, tk_support_point(b, d));
    }
}

/* x in the solid enlarged by tol (curved kinds: within tol of it or slightly less for the ellipses,
 * whose test scales them by 1 + tol / (smallest semi-axis)). */
static inline int tk_inside(const tk_body *b, lv3 x, ld tol)
{
    lv3 y = lsub(x, b->c);
    ld t = ldot(y, b->w), rho = lnorm(lsub(y, lsc(b->w, t)));
    switch (b->kind) {
    case PROX_SHAPE_SPH: return lnorm(y) <= b->r + tol;
    case PROX_SHAPE_RCC: return fabsl(t) <= b->hh + tol && rho <= b->r + tol;
    case PROX_SHAPE_TRC: {
        ld k = (b->r2 - b->r1) / (2 * b->hh), rt = (b->r1 + b->r2) / 2 + k * t;
        return fabsl(t) <= b->hh + tol && (rho - rt) / sqrtl(1 + k * k) <= tol;
    }
    case PROX_SHAPE_REC: {
        ld x1 = ldot(y, b->e1) / b->a1, x2 = ldot(y, b->e2) / b->a2, s = 1 + tol / fminl(b->a1, b->a2);
        return fabsl(t) <= b->hh + tol && x1 * x1 + x2 * x2 <= s * s;
    }
    case PROX_SHAPE_ELL: {
        ld x1 = t / b->a1, x2 = rho / b->a2, s = 1 + tol / fminl(b->a1, b->a2);
        return x1 * x1 + x2 * x2 <= s * s;
    }
    default:
        for (int f = 0; f < b->nf; ++f)
            if (ldot(b->n[f], x) > b->d[f] + tol) return 0;
        return 1;
    }
}

/* Largest distance from the centre (for scales). */
static inline ld tk_radius(const tk_body *b)
{
    ld r = 0;
    for (int i = 0; i < 64; ++i) {
        ld z = 1 - (2 * i + 1) / 64.0L, s = sqrtl(1 - z * z), ph = 2.399963229728653L * i;
        lv3 d = {s * cosl(ph), s * sinl(ph), z};
        r = fmaxl(r, lnorm(lsub(tk_support_point(b, d), b->c)));
    }
    return r;
}

/* The i-th of n directions spread over the sphere (Fibonacci lattice). */
static inline lv3 tk_dir(int i, int n)
{
    ld z = 1 - (2 * i + 1) / (ld)n, s = sqrtl(fmaxl(0, 1 - z * z)), ph = 2.399963229728653L * i;
    lv3 d = {s * cosl(ph), s * sinl(ph), z};
    return d;
}

/* Brute distance: the nearest pair among support points of A and B over n directions each (pairs of
 * points of the solids: never below the distance). */
static inline ld tk_brute_distance(const tk_body *a, const tk_body *b, int n)
{
    static lv3 pa[2048], pb[2048];
    if (n > 2048) n = 2048;
    for (int i = 0; i < n; ++i) pa[i] = tk_support_point(a, tk_dir(i, n)), pb[i] = tk_support_point(b, tk_dir(i, n));
    ld best = INFINITY;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) best = fminl(best, lnorm(lsub(pa[i], pb[j])));
    return best;
}

/* A function on the unit sphere (minimised over sampled directions, then by a pattern search on
 * the two angles of a frame about the best direction). */
typedef ld (*tk_sphere_fn)(const tk_body *a, const tk_body *b, lv3 d);

/* Pattern search from *d: steps along eight directions of the tangent plane (axes and diagonals, so
 * that a V-shaped valley along a diagonal cannot stall it), halved when none improves. */
static inline ld tk_refine(tk_sphere_fn f, const tk_body *a, const tk_body *b, lv3 *d, ld v, ld step)
{
    for (int it = 0; it < 3000 && step > 1e-14L; ++it) {
        lv3 u = tk_any_perp(*d), w = lcross(*d, u);
        int moved = 0;
        for (int k = 0; k < 8; ++k) {
            ld ang = k * 0.78539816339744830962L;
            lv3 t = ladd(lsc(u, cosl(ang)), lsc(w, sinl(ang)));
            lv3 e = lunit(ladd(*d, lsc(t, step)));
            ld x = f(a, b, e);
            if (x < v) v = x, *d = e, moved = 1;
        }
        if (!moved) step *= 0.5L;
    }
    return v;
}

/* The outward normal at angle phi of the lateral surface of an RCC, TRC or REC: (u - k w) / |u - k w|
 * with u across the axis and k the cone's slope of the radius (0 for the cylinders). */
static inline lv3 tk_lateral_dir(const tk_body *b, ld phi)
{
    lv3 u = ladd(lsc(b->e1, cosl(phi)), lsc(b->e2, sinl(phi)));
    ld k = b->kind == PROX_SHAPE_TRC ? (b->r2 - b->r1) / (2 * b->hh) : 0;
    return lunit(lsub(u, lsc(b->w, k)));
}

/* Candidate directions of a body where support differences have kinks: face normals, the axis. */
static inline int tk_special_dirs(const tk_body *b, lv3 *out, int n)
{
    for (int f = 0; f < b->nf && n < 120; ++f) out[n++] = b->n[f];
    if (lnorm(b->w) > 0.5L && n < 118) out[n++] = b->w, out[n++] = lsc(b->w, -1);
    return n;
}

/* Minimum of f over unit directions: n sampled directions and the special ones of both bodies, the
 * best six refined. */
static inline ld tk_minimise(tk_sphere_fn f, const tk_body *a, const tk_body *b, int n, lv3 *arg)
{
    enum { K = 6 };
    ld bv[K];
    lv3 bd[K], sp[120];
    for (int k = 0; k < K; ++k) bv[k] = INFINITY, bd[k] = (lv3){0, 0, 1};
    int ns = tk_special_dirs(b, sp, tk_special_dirs(a, sp, 0));
    for (int i = 0; i < n + ns; ++i) {
        lv3 d = i < n ? tk_dir(i, n) : sp[i - n];
        ld v = f(a, b, d);
        int k = K;
        while (k > 0 && v < bv[k - 1]) --k;
        if (k == K) continue;
        for (int j = K - 1; j > k; --j) bv[j] = bv[j - 1], bd[j] = bd[j - 1];
        bv[k] = v, bd[k] = d;
    }
    ld best = INFINITY;
    lv3 bestd = bd[0];
    for (int k = 0; k < K; ++k) {
        if (!(bv[k] < INFINITY)) continue;
        ld v = tk_refine(f, a, b, &bd[k], bv[k], 2.0L / sqrtl((ld)n));
        if (v < best) best = v, bestd = bd[k];
    }
    /* the kink circles of the cylinders and cones (their lateral normals): a one-angle search */
    for (int which = 0; which < 2; ++which) {
        const tk_body *c = which ? b : a;
        if (c->kind != PROX_SHAPE_RCC && c->kind != PROX_SHAPE_TRC && c->kind != PROX_SHAPE_REC) continue;
        ld bp = 0, bvp = INFINITY;
        for (int i = 0; i < 720; ++i) {
            ld v = f(a, b, tk_lateral_dir(c, 6.283185307179586477L * i / 720));
            if (v < bvp) bvp = v, bp = 6.283185307179586477L * i / 720;
        }
        ld step = 0.01L;
        for (int it = 0; it < 3000 && step > 1e-15L; ++it) {
            ld v1 = f(a, b, tk_lateral_dir(c, bp - step)), v2 = f(a, b, tk_lateral_dir(c, bp + step));
            if (v1 < bvp) bvp = v1, bp -= step;
            else if (v2 < bvp) bvp = v2, bp += step;
            else step *= 0.5L;
        }
        lv3 d = tk_lateral_dir(c, bp);
        bvp = tk_refine(f, a, b, &d, bvp, 1e-3L);
        if (bvp < best) best = bvp, bestd = d;
    }
    /* the kink arcs of the polytopes: great-circle arcs between two face normals */
    for (int which = 0; which < 2; ++which) {
        const tk_body *c = which ? b : a;
        for (int fa = 0; fa < c->nf; ++fa)
            for (int h = fa + 1; h < c->nf; ++h) {
                if (ldot(c->n[fa], c->n[h]) < -0.999L) continue;
                ld bt = 0, bvt = INFINITY;
                for (int i = 0; i <= 64; ++i) {
                    ld v = f(a, b, lunit(ladd(lsc(c->n[fa], 1 - i / 64.0L), lsc(c->n[h], i / 64.0L))));
                    if (v < bvt) bvt = v, bt = i / 64.0L;
                }
                ld step = 1 / 128.0L;
                for (int it = 0; it < 3000 && step > 1e-16L; ++it) {
                    ld t1 = fmaxl(0, bt - step), t2 = fminl(1, bt + step);
                    ld v1 = f(a, b, lunit(ladd(lsc(c->n[fa], 1 - t1), lsc(c->n[h], t1))));
                    ld v2 = f(a, b, lunit(ladd(lsc(c->n[fa], 1 - t2), lsc(c->n[h], t2))));
                    if (v1 < bvt) bvt = v1, bt = t1;
                    else if (v2 < bvt) bvt = v2, bt = t2;
                    else step *= 0.5L;
                }
                if (bvt < best) best = bvt, bestd = lunit(ladd(lsc(c->n[fa], 1 - bt), lsc(c->n[h], bt)));
            }
    }
    if (arg) *arg = bestd;
    return best;
}

/* phi(D) = h_A(D) + h_B(-D): its minimum is minus the signed distance (D from A towards B). */
static inline ld tk_phi(const tk_body *a, const tk_body *b, lv3 d) { return tk_support(a, d) + tk_support(b, lsc(d, -1)); }

/* h_B(n) - h_A(n): its minimum over unit n is the clearance of A in B (min over A of the distance to
 * B's boundary when inside; minus how far A sticks out otherwise). */
static inline ld tk_hdiff(const tk_body *a, const tk_body *b, lv3 d) { return tk_support(b, d) - tk_support(a, d); }

/* ---- random shapes ---- */

static inline prox_vec3 tk_rot(const test_rot *R, double x, double y, double z) { return test_rot_apply(R, prox_v3(x, y, z)); }

/* A random valid shape of kind k centred near c with sizes about s (from 0.3 s to 1.5 s). */
static inline prox_shape tk_random_shape(test_rng *g, prox_shape_kind k, prox_vec3 c, double s)
{
    for (;;) {
        test_rot R = test_random_rot(g);
        double h = s * test_range(g, 0.3, 1.5), r = s * test_range(g, 0.3, 1.5), q = s * test_range(g, 0.3, 1.5);
        prox_vec3 ax = tk_rot(&R, 0, 0, h), base = prox_v3_mad(c, -0.5, ax);
        prox_shape out;
        switch (k) {
        case PROX_SHAPE_RCC: out = prox_shape_from_rcc((prox_rcc){base, ax, r}); break;
        case PROX_SHAPE_BOX:
            out = prox_shape_from_box((prox_box){prox_v3_sub(c, tk_rot(&R, r / 2, q / 2, h / 2)),
                                                 {tk_rot(&R, r, 0, 0), tk_rot(&R, 0, q, 0), ax}});
            break;
        case PROX_SHAPE_RPP:
            out = prox_shape_from_rpp((prox_rpp){c.x - r / 2, c.x + r / 2, c.y - q / 2, c.y + q / 2, c.z - h / 2, c.z + h / 2});
            break;
        case PROX_SHAPE_SPH: out = prox_shape_from_sph((prox_sph){c, r / 2}); break;
        case PROX_SHAPE_TRC: {
            double r2 = test_uniform(g) < 0.25 ? 0.0 : q / 2;
            out = prox_shape_from_trc((prox_trc){base, ax, r / 2, r2});
            break;
        }
        case PROX_SHAPE_REC: out = prox_shape_from_rec((prox_rec){base, ax, tk_rot(&R, r / 2, 0, 0), tk_rot(&R, 0, q / 2, 0)}); break;
        case PROX_SHAPE_ELL: out = prox_shape_from_ell((prox_ell){c, prox_v3_scale(ax, 0.5), r / 2}); break;
        case PROX_SHAPE_RHP: {
            prox_rhp x;
            x.base = base, x.axis = ax;
            for (int i = 0; i < 3; ++i) {
                double th = i * PROX_PI / 3 + test_range(g, -0.15, 0.15), len = r / 2 * test_range(g, 0.85, 1.15);
                x.r[i] = tk_rot(&R, len * cos(th), len * sin(th), 0);
            }
            out = prox_shape_from_rhp(x);
            break;
        }
        case PROX_SHAPE_WED: {
            double al = test_range(g, 0.4, 2.6);
            prox_vec3 v1 = tk_rot(&R, r, 0, 0), v2 = tk_rot(&R, q * cos(al), q * sin(al), 0);
            prox_vec3 o = prox_v3_sub(c, prox_v3_scale(prox_v3_add(prox_v3_add(v1, v2), ax), 1.0 / 3.0));
            out = prox_shape_from_wed((prox_wed){o, v1, v2, ax});
            break;
        }
        default: { /* ARB: a frustum of a pyramid (planar faces), corners 1-4 at the bottom, 5-8 on top */
            prox_arb x;
            memset(&x, 0, sizeof x);
            double f = test_range(g, 0.3, 0.9);
            prox_vec3 apex = prox_v3_add(c, tk_rot(&R, test_range(g, -0.3, 0.3) * s, test_range(g, -0.3, 0.3) * s, h));
            double bx[4] = {-r / 2, r / 2, r / 2, -r / 2}, by[4] = {-q / 2, -q / 2, q / 2, q / 2};
            for (int i = 0; i < 4; ++i) {
                x.corner[i] = prox_v3_add(c, tk_rot(&R, bx[i], by[i], -h / 2));
                x.corner[i + 4] = prox_v3_add(apex, prox_v3_scale(prox_v3_sub(x.corner[i], apex), f));
            }
            int faces[6] = {4321, 5678, 1265, 2376, 3487, 4158};
            memcpy(x.face, faces, sizeof faces);
            out = prox_shape_from_arb(x);
            if (prox_shape_validate(&out) != PROX_OK) { /* the other orientation of the loops */
                int rev[6] = {1234, 8765, 5621, 6732, 7843, 8514};
                memcpy(out.u.arb.face, rev, sizeof rev);
            }
            break;
        }
        }
        if (prox_shape_validate(&out) == PROX_OK) return out;
    }
}

/* The pair under test (set by each test), printed with a failure of check / check_near. */
static char ctx[128];
#define check(c)                                                \
    do {                                                        \
        if (!(c)) {                                             \
            print_error("%s: %s\n", ctx, #c);                   \
            fail();                                             \
        }                                                       \
    } while (0)
#define check_near(x, y, t)                                     \
    do {                                                        \
        if (!(fabs((double)(x) - (double)(y)) <= (t))) print_error("%s\n", ctx); \
        assert_near(x, y, t);                                   \
    } while (0)

#endif
