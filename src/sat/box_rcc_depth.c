/* Penetration depth of an overlapping box and cylinder by enumerating every stratum of the depth
 * function in closed form (the derivation is below; it replaces the sampled global search of
 * sup_engine.c, which remains the fallback for degenerate poses).
 *
 * phi(D) = h_A(D) + h_B(-D) = sum_i h_i |D.a_i| + r |P D| + hh |D.w| - D.Delta (box A with unit
 * edges a_i and half edges h_i, cylinder B with unit axis w, radius r, half height hh; Eberly's
 * Eq. (4)); depth = min over unit D. A minimiser has p2 - p1 = -depth D with p1 in A's support set
 * along D and p2 in B's along -D, and these sets name its stratum:
 *   box face (D = +-a_i), cylinder disk (D = +-w), box edge and cylinder side (D = +-a_i x w):
 *        points, evaluated;
 *   box vertex v and cylinder side (D.w = 0): on that great circle phi is r plus the support
 *        function of the box's shadow along w minus D.Delta, whose minimum is at an edge normal of
 *        the shadow (one of the points +-a_i x w) or, when the shadow misses the cylinder's axis, at
 *        the shadow vertex nearest it: D = P_w(c_B - v) / |..|;
 *   box vertex v and a rim point q: D is normal to the rim at q and along v - q, so q is the
 *        nearest or the farthest point of the rim circle from v: D = +-(v - q) / |v - q|;
 *   box edge along a_i and a rim point (D.a_i = 0): on that great circle phi is the support
 *        function of the shadow along a_i of the box (a rectangle) plus the cylinder's (an ellipse E
 *        swept along a segment), minus D.Delta; on each normal arc of a vertex g of the rectangle
 *        swept along the segment it is h_E(D) - D.(delta - g), stationary at the normals of E at the
 *        feet from delta - g (sup_ellipse_feet, as the cylinder pair's ridges).
 * Every candidate is evaluated exactly (any direction is an upper bound of the depth), and every
 * stratum's stationary points are among them, so their minimum is the depth. Degenerate poses
 * (a vertex on the rim's axis, the cylinder axis within PROX_TOL_RIDGE_THIN of a box face plane, a
 * shadow point at a circle's centre, the touching band) return 0: the global search answers. */
#include "sup_engine.h"

#include "core/circle.h"
#include "core/tol.h"
#include "prox/support.h"
#include "sat_internal.h"

typedef struct bd_state {
    const prox_body *a, *b;
    prox_vec3 delta;
    double best;
    prox_vec3 best_d;
} bd_state;

/* Evaluates v / |v| (v need not be unit; v = 0 is ignored). */
static void bd_one(bd_state *s, prox_vec3 v)
{
    double n = prox_v3_norm(v);
    if (!(n > 0.0) || !isfinite(n)) return;
    v = prox_v3_scale(v, 1.0 / n);
    double f = prox_body_hc(s->a, v) + prox_body_hc(s->b, v) - prox_v3_dot(v, s->delta);
    if (f < s->best) s->best = f, s->best_d = v;
}

/* Evaluates +-v / |v|. */
static void bd_pm(bd_state *s, prox_vec3 v)
{
    bd_one(s, v);
    bd_one(s, prox_v3_neg(v));
}

/* Vertex k (bits: signs along a_0, a_1, a_2) of the box, absolute. */
static prox_vec3 bd_vertex(const prox_body *a, int k)
{
    prox_vec3 v = a->c;
    for (int i = 0; i < 3; ++i) v = prox_v3_mad(v, (k >> i & 1) ? a->box.h[i] : -a->box.h[i], a->box.a[i]);
    return v;
}

/* Box vertex against the cylinder's side and its rims. 0 when a vertex lies on a rim's axis. */
static int bd_vertices(bd_state *s, double tol)
{
    const prox_cyl *c = &s->b->cyl;
    for (int k = 0; k < 8; ++k) {
        prox_vec3 v = bd_vertex(s->a, k);
        prox_vec3 rel = prox_v3_sub(v, s->b->c), perp = prox_v3_reject(rel, c->w);
        bd_pm(s, perp); /* vertex against the side: the shadow vertex nearest the axis */
        double pn = prox_v3_norm(perp);
        if (!(pn > PROX_TOL_RADIAL * (prox_v3_norm(rel) + c->r))) return 0; /* on the axis: every rim point */
        /* D = (v - q) / |v - q| (p1 - p2 = depth D), where phi >= D.(v - q) = |v - q|: a rim
         * point farther from v than the best value cannot improve it */
        prox_vec3 u = prox_v3_scale(perp, 1.0 / pn);
        double ax = prox_v3_dot(rel, c->w);
        for (int e = -1; e <= 1; e += 2) {
            prox_vec3 rc = prox_v3_mad(s->b->c, e * c->hh, c->w);
            double z = ax - e * c->hh;
            if (hypot(pn - c->r, z) <= s->best + tol) /* the nearest rim point */
                bd_one(s, prox_v3_sub(v, prox_v3_mad(rc, c->r, u)));
            if (hypot(pn + c->r, z) <= s->best + tol) /* the farthest */
                bd_one(s, prox_v3_sub(v, prox_v3_mad(rc, -c->r, u)));
        }
    }
    return 1;
}

/* A lower bound of phi on the ridge D.a_i = 0: the shadow E of the rim disk contains the disk of
 * radius b = r |a_i.w|, so phi >= b + h_G(D) - D.delta there, G the rectangle swept along the
 * segment (edge normals +-a_j, +-a_k, +-e1); when delta lies in G the minimum of the latter is its
 * smallest value at those normals (the depth of delta in G), else b minus an upper bound of the
 * distance from delta to G. */
static double bd_ridge_lb(const bd_state *s, int i)
{
    const prox_bframe *f = &s->a->box;
    const prox_cyl *c = &s->b->cyl;
    prox_vec3 ai = f->a[i], x = prox_v3_cross(ai, c->w);
    double xn = prox_v3_norm(x), b = c->r * fabs(prox_v3_dot(ai, c->w));
    int j = (i + 1) % 3, k = (i + 2) % 3;
    prox_vec3 n[3] = {f->a[j], f->a[k], xn > PROX_TOL_PARALLEL ? prox_v3_scale(x, 1.0 / xn) : f->a[j]};
    double m = INFINITY;
    for (int q = 0; q < 3; ++q) {
        double hg = f->h[j] * fabs(prox_v3_dot(n[q], f->a[j])) + f->h[k] * fabs(prox_v3_dot(n[q], f->a[k])) +
                    c->hh * fabs(prox_v3_dot(n[q], c->w)), dd = prox_v3_dot(n[q], s->delta);
        m = fmin(m, fmin(hg - dd, hg + dd));
    }
    if (m >= 0.0) return b + m;
    /* delta outside G: its distance to G is at most that to the point of G nearest along the
     * segment then within the rectangle (shadow coordinates along a_j, a_k) */
    prox_vec3 d = prox_v3_reject(prox_v3_scale(c->w, c->hh), ai), dl = prox_v3_reject(s->delta, ai);
    double dd2 = prox_v3_norm2(d), t = dd2 > 0.0 ? fmax(-1.0, fmin(1.0, prox_v3_dot(dl, d) / dd2)) : 0.0;
    prox_vec3 r = prox_v3_mad(dl, -t, d);
    double cj = fmax(-f->h[j], fmin(f->h[j], prox_v3_dot(r, f->a[j])));
    double ck = fmax(-f->h[k], fmin(f->h[k], prox_v3_dot(r, f->a[k])));
    prox_vec3 g = prox_v3_mad(prox_v3_mad(prox_v3_scale(d, t), cj, f->a[j]), ck, f->a[k]);
    return b - prox_v3_dist(dl, g);
}

/* The ridge D.a_i = 0 (an edge of the box along a_i against a rim point): 0 when degenerate. */
static int bd_edge_ridge(bd_state *s, int i)
{
    const prox_bframe *f = &s->a->box;
    const prox_cyl *c = &s->b->cyl;
    prox_vec3 ai = f->a[i], x = prox_v3_cross(ai, c->w);
    double cw = fabs(prox_v3_dot(ai, c->w)), xn = prox_v3_norm(x);
    double ea = c->r, eb = c->r * cw;
    if (!(eb > PROX_TOL_RIDGE_THIN * ea)) return 0; /* the axis nearly in the face plane: a needle shadow */
    prox_vec3 e1 = xn > PROX_TOL_PARALLEL ? prox_v3_scale(x, 1.0 / xn) : prox_v3_any_perp(ai);
    prox_vec3 e2 = prox_v3_cross(ai, e1);
    if (!(xn > PROX_TOL_PARALLEL)) eb = ea;
    /* the point delta - g in the plane, g = rectangle corner + s d (d the half axis's shadow) */
    int j = (i + 1) % 3, k = (i + 2) % 3;
    double d1 = c->hh * prox_v3_dot(c->w, e1), d2 = c->hh * prox_v3_dot(c->w, e2);
    double q1 = prox_v3_dot(s->delta, e1), q2 = prox_v3_dot(s->delta, e2);
    double j1 = f->h[j] * prox_v3_dot(f->a[j], e1), j2 = f->h[j] * prox_v3_dot(f->a[j], e2);
    double k1 = f->h[k] * prox_v3_dot(f->a[k], e1), k2 = f->h[k] * prox_v3_dot(f->a[k], e2);
    prox_vec3 cand[48];
    /* d's components along a_j, a_k: the corner (sj, sk) moved by sd d is a vertex of G iff some
     * D in the corner's quadrant has sign(D.d) = sd, i.e. unless both sj d_j sd and sk d_k sd are
     * negative (a half axis d = 0 leaves the four corners, taken once) */
    double dj = c->hh * prox_v3_dot(c->w, f->a[j]), dk = c->hh * prox_v3_dot(c->w, f->a[k]);
    for (int m = 0; m < 8; ++m) {
        double sj = (m & 1) ? 1.0 : -1.0, sk = (m & 2) ? 1.0 : -1.0, sd = (m & 4) ? 1.0 : -1.0;
        if (sj * dj * sd < 0.0 && sk * dk * sd < 0.0) continue;
        if (dj == 0.0 && dk == 0.0 && sd < 0.0) continue;
        double g1 = sj * j1 + sk * k1 + sd * d1, g2 = sj * j2 + sk * k2 + sd * d2;
        int n = 0;
        if (sup_ellipse_feet(ea, eb, q1 - g1, q2 - g2, e1, e2, cand, &n, 48) < 0) return 0;
        for (int t = 0; t < n; ++t) bd_one(s, prox_v3_reject(cand[t], ai)); /* outward normals of E: the sign is D's */
    }
    return 1;
}

int sup_box_cyl_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res)
{
    bd_state s = {.a = a, .b = b, .delta = prox_v3_sub(b->c, a->c), .best = INFINITY};
    s.best_d = b->cyl.w;
    bd_pm(&s, b->cyl.w);
    for (int i = 0; i < 3; ++i) {
        bd_pm(&s, a->box.a[i]);
        bd_pm(&s, prox_v3_cross(a->box.a[i], b->cyl.w));
    }
    double tol = PROX_TOL_SEARCH * fmax(prox_v3_norm(s.delta), fmax(a->size, b->size));
    int ok = bd_vertices(&s, tol);
    /* the edge ridges, the most promising first; one whose bound exceeds the best is skipped */
    double lb[3];
    int ord[3] = {0, 1, 2};
    for (int i = 0; i < 3; ++i) lb[i] = bd_ridge_lb(&s, i);
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (lb[ord[j]] < lb[ord[i]]) { int t = ord[i]; ord[i] = ord[j]; ord[j] = t; }
    for (int i = 0; ok && i < 3; ++i)
        if (!(lb[ord[i]] > s.best + tol)) ok = bd_edge_ridge(&s, ord[i]);
    res->status = PROX_OK;
    res->sd = -s.best;
    res->normal = s.best_d;
    if (!ok || !(s.best > 0.0)) return 0;
    sup_overlap_answer(a, b, s.best_d, res);
    return 1;
}

#include <stdatomic.h>

/* Overlapping box-cylinder pairs the enumeration could not settle (degenerate poses), answered by
 * the global search. */
static atomic_ullong g_box_depth_fallbacks;

unsigned long long prox_sat_box_depth_fallbacks(void)
{
    return atomic_load_explicit(&g_box_depth_fallbacks, memory_order_relaxed);
}

prox_signed_result prox_sat_box_rcc_depth(const prox_box *a, const prox_rcc *b)
{
    prox_signed_result r = {0};
    if (!a || !b) { r.status = PROX_EINVAL_ARG; return r; }
    prox_shape sa = prox_shape_from_box(*a), sb = prox_shape_from_rcc(*b);
    if ((r.status = prox_shape_validate(&sa)) != PROX_OK || (r.status = prox_shape_validate(&sb)) != PROX_OK) return r;
    /* relative to A's centre and at unit scale (a power of two, exact), as the support engine's
     * entry point (support.c) */
    prox_body ba = prox_body_make(&sa), bb = prox_body_make(&sb);
    prox_vec3 o = ba.c;
    ba.c = prox_v3(0, 0, 0);
    bb.c = prox_v3_sub(bb.c, o);
    double f = prox_unit_scale(fmax(prox_v3_norm(bb.c), fmax(ba.size, bb.size)));
    ba = prox_body_scaled(&ba, f);
    bb = prox_body_scaled(&bb, f);
    if (!sup_box_cyl_depth_enum(&ba, &bb, &r)) {
        atomic_fetch_add_explicit(&g_box_depth_fallbacks, 1, memory_order_relaxed);
        r = sup_signed_distance(&ba, &bb, NULL);
    }
    r.sd /= f;
    r.p1 = prox_v3_mad(o, 1.0 / f, r.p1);
    r.p2 = prox_v3_mad(o, 1.0 / f, r.p2);
    return r;
}
