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
 * stratum's stationary points are among them, so their minimum is the depth. A stratum whose lower
 * bound (a vertex's octant, a ridge, a shadow vertex's normal arc: bd_cone_lb, bd_ridge_lb,
 * bd_arc_lb) cannot beat the best value found by more than the search tolerance is skipped: the
 * strata are visited cheapest first, so on random pairs most ridges' feet are never solved.
 * Degenerate poses (a vertex on the rim's axis, the cylinder axis within PROX_TOL_RIDGE_THIN of a box
 * face plane, a shadow point at a circle's centre, the touching band) return 0: the global search
 * answers. */
#include "sup_engine.h"

#include "core/circle.h"
#include "core/tol.h"
#include "prox/support.h"
#include "sat_internal.h"

typedef struct bd_state {
    const prox_body *a, *b;
    prox_vec3 delta;
    double dl[3], hcmin; /* delta along the box's axes; min(r, hh), the least of hc_B */
    double best;
    prox_vec3 best_d;
} bd_state;

/* |(x, y)| without hypot's guards: the pair is at unit scale (prox_sat_box_rcc_depth_bounded), where no
 * square can overflow or underflow. */
static inline double bd_len(double x, double y) { return sqrt(x * x + y * y); }

/* Evaluates v / |v| (v need not be unit; v = 0 is ignored). */
static void bd_one(bd_state *s, prox_vec3 v)
{
    double n = prox_v3_norm(v);
    if (!(n > 0.0) || !isfinite(n)) return;
    v = prox_v3_scale(v, 1.0 / n);
    double f = prox_bframe_support(&s->a->box, v) + prox_cyl_hc(&s->b->cyl, v) - prox_v3_dot(v, s->delta);
    if (f < s->best) s->best = f, s->best_d = v;
}

/* Evaluates +-v / |v|: both centred support functions are even, so phi(-D) = phi(D) + 2 D.delta
 * (the same floating-point value as evaluating -D afresh: negation is exact). */
static void bd_pm(bd_state *s, prox_vec3 v)
{
    double n = prox_v3_norm(v);
    if (!(n > 0.0) || !isfinite(n)) return;
    v = prox_v3_scale(v, 1.0 / n);
    double h = prox_bframe_support(&s->a->box, v) + prox_cyl_hc(&s->b->cyl, v), d = prox_v3_dot(v, s->delta);
    if (h - d < s->best) s->best = h - d, s->best_d = v;
    if (h + d < s->best) s->best = h + d, s->best_d = prox_v3_neg(v);
}

/* Vertex k (bits: signs along a_0, a_1, a_2) of the box, absolute. */
static prox_vec3 bd_vertex(const prox_body *a, int k)
{
    prox_vec3 v = a->c;
    for (int i = 0; i < 3; ++i) v = prox_v3_mad(v, (k >> i & 1) ? a->box.h[i] : -a->box.h[i], a->box.a[i]);
    return v;
}

/* A lower bound of phi over the unit D whose box support set holds g = sum of s_l h_l a_l over the
 * axes l of `used` (bits), D.a_l = 0 on the others: a vertex's octant (all three) or an edge's
 * quarter of its ridge (two). There h_A(D) = D.g, so phi(D) = hc_B(D) - D.(delta - g), and hc_B >=
 * min(r, hh) (the cylinder holds the ball of that radius about its centre), while D.q over the cone is
 * at most the length of q's components s_l q.a_l clamped at 0 (the cone's unit vector nearest q). */
static double bd_cone_lb(const bd_state *s, const double sg[3], unsigned used)
{
    double m2 = 0.0;
    for (int l = 0; l < 3; ++l) {
        double ql = sg[l] * s->dl[l] - s->a->box.h[l];
        if ((used >> l & 1) && ql > 0.0) m2 += ql * ql;
    }
    return s->hcmin - sqrt(m2);
}

/* Box vertex against the cylinder's side and its rims. 0 when a vertex lies on a rim's axis. A vertex
 * whose octant cannot beat the best value (bd_cone_lb) is skipped. */
static int bd_vertices(bd_state *s, double tol)
{
    const prox_cyl *c = &s->b->cyl;
    for (int k = 0; k < 8; ++k) {
        double sg[3] = {(k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0};
        if (bd_cone_lb(s, sg, 7u) >= s->best - tol) continue;
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
            if (bd_len(pn - c->r, z) < s->best - tol) /* the nearest rim point */
                bd_one(s, prox_v3_sub(v, prox_v3_mad(rc, c->r, u)));
            if (bd_len(pn + c->r, z) < s->best - tol) /* the farthest */
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
        double v = hg - fabs(dd);
        if (v < m) m = v;
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

/* The normal arcs of the vertices of G on a ridge (the plane's unit D, coordinates along e1, e2): the
 * arc of the vertex with signs (s_j, s_k, s_d) is {D : s_j D.J >= 0, s_k D.K >= 0, s_d D.d >= 0}
 * (J, K the rectangle's half edges, d the half axis, in the plane). Its ends are among the six unit
 * directions perpendicular to J, K or d, kept here with their dot products and h_E. */
typedef struct bd_arcs {
    double c[3][2], slack[3]; /* J, K, d and the slack of their sign tests */
    double ray[6][2], dot[6][3], he[6];
    int n;
} bd_arcs;

static void bd_arcs_make(bd_arcs *A, const double c[3][2], double ea, double eb)
{
    A->n = 0;
    for (int q = 0; q < 3; ++q) {
        A->c[q][0] = c[q][0], A->c[q][1] = c[q][1];
        double cn = bd_len(c[q][0], c[q][1]);
        A->slack[q] = 1e-9 * cn; /* a sign within rounding counts as both: the bounds only weaken */
        if (!(cn > 0.0)) continue;
        for (int sg = -1; sg <= 1; sg += 2) {
            double r0 = -sg * c[q][1] / cn, r1 = sg * c[q][0] / cn;
            A->ray[A->n][0] = r0, A->ray[A->n][1] = r1;
            for (int t = 0; t < 3; ++t) A->dot[A->n][t] = c[t][0] * r0 + c[t][1] * r1;
            A->he[A->n++] = bd_len(ea * r0, eb * r1);
        }
    }
}

/* Is D (dot products dd with J, K, d) on the arc of signs sg? */
static int bd_on_arc(const bd_arcs *A, const double sg[3], const double dd[3])
{
    return sg[0] * dd[0] >= -A->slack[0] && sg[1] * dd[1] >= -A->slack[1] && sg[2] * dd[2] >= -A->slack[2];
}

/* A lower bound of h_E(D) - D.p over the arc of signs sg: the least h_E on it (b when it holds +-e2,
 * where h_E is least, else at an end: h_E is unimodal between its minima at +-e2) minus the largest
 * D.p (|p| when it holds p's direction, else at an end). Candidate ends that pass the sign tests only
 * by the slack can only lower the bound. */
static double bd_arc_lb(const bd_arcs *A, const double sg[3], double eb, double p0, double p1)
{
    double pn = bd_len(p0, p1), dd[3], hmin = INFINITY, dmax = -INFINITY;
    for (int t = 0; t < 3; ++t) dd[t] = A->c[t][1];
    int e2 = bd_on_arc(A, sg, dd);
    for (int t = 0; t < 3; ++t) dd[t] = -dd[t];
    e2 = e2 || bd_on_arc(A, sg, dd);
    for (int t = 0; t < 3; ++t) dd[t] = pn > 0.0 ? (A->c[t][0] * p0 + A->c[t][1] * p1) / pn : 0.0;
    if (!(pn > 0.0) || bd_on_arc(A, sg, dd)) dmax = pn;
    for (int r = 0; r < A->n; ++r) {
        if (!bd_on_arc(A, sg, A->dot[r])) continue;
        double v = A->ray[r][0] * p0 + A->ray[r][1] * p1; /* (no fmin/fmax: libm calls on this path) */
        if (A->he[r] < hmin) hmin = A->he[r];
        if (v > dmax) dmax = v;
    }
    if (e2 || hmin == INFINITY) hmin = eb;
    if (dmax == -INFINITY) dmax = pn;
    return hmin - dmax;
}

/* The ridge D.a_i = 0 (an edge of the box along a_i against a rim point): 0 when degenerate. On
 * the normal arc of the vertex g of G (the D of the plane with sign(D.a_j) = s_j, sign(D.a_k) =
 * s_k, sign(D.d) = s_d), phi = h_E(D) - D.(delta - g), at least the least h_E on the arc minus the
 * largest D.(delta - g) there (bd_arc_lb): a vertex whose bound exceeds the best value by more than
 * tol cannot hold a better stationary point, and its feet are not solved. The vertices are visited
 * in the order of that bound, so the best value falls early. */
static int bd_edge_ridge(bd_state *s, int i, double tol)
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
    double p1[8], p2[8], lb[8];
    int ord[8], nv = 0;
    bd_arcs A;
    bd_arcs_make(&A, (const double[3][2]){{j1, j2}, {k1, k2}, {d1, d2}}, ea, eb);
    for (int m = 0; m < 8; ++m) {
        double sj = (m & 1) ? 1.0 : -1.0, sk = (m & 2) ? 1.0 : -1.0, sd = (m & 4) ? 1.0 : -1.0;
        if (sj * dj * sd < 0.0 && sk * dk * sd < 0.0) continue;
        if (dj == 0.0 && dk == 0.0 && sd < 0.0) continue;
        double g1 = sj * j1 + sk * k1 + sd * d1, g2 = sj * j2 + sk * k2 + sd * d2;
        p1[m] = q1 - g1, p2[m] = q2 - g2, lb[m] = bd_arc_lb(&A, (const double[3]){sj, sk, sd}, eb, p1[m], p2[m]);
        int at = nv++;
        for (; at > 0 && lb[ord[at - 1]] > lb[m]; --at) ord[at] = ord[at - 1];
        ord[at] = m;
    }
    for (int v = 0; v < nv; ++v) {
        int m = ord[v], n = 0;
        if (lb[m] >= s->best - tol) break;
        if (sup_ellipse_feet(ea, eb, p1[m], p2[m], e1, e2, cand, &n, 48) < 0) return 0;
        for (int t = 0; t < n; ++t) bd_one(s, prox_v3_reject(cand[t], ai)); /* outward normals of E: the sign is D's */
    }
    return 1;
}

int sup_box_cyl_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res)
{
    bd_state s = {.a = a, .b = b, .delta = prox_v3_sub(b->c, a->c), .best = INFINITY};
    s.best_d = b->cyl.w;
    for (int l = 0; l < 3; ++l) s.dl[l] = prox_v3_dot(s.delta, a->box.a[l]);
    s.hcmin = b->cyl.r < b->cyl.hh ? b->cyl.r : b->cyl.hh;
    bd_pm(&s, b->cyl.w);
    for (int i = 0; i < 3; ++i) {
        bd_pm(&s, a->box.a[i]);
        bd_pm(&s, prox_v3_cross(a->box.a[i], b->cyl.w));
    }
    /* A stratum whose lower bound is within tol of the best value (or above it) can improve the depth
     * by at most tol = 1e-13 S, far below the 1e-9 S the depth promises: it is skipped (the arcs'
     * bounds are often exact at an arc's end, a direction already evaluated above). */
    double tol = PROX_TOL_SEARCH * fmax(prox_v3_norm(s.delta), fmax(a->size, b->size));
    int ok = bd_vertices(&s, tol);
    /* the edge ridges, the most promising first; one whose bound reaches the best is skipped */
    double lb[3];
    int ord[3] = {0, 1, 2};
    for (int i = 0; i < 3; ++i) { /* and the least of its four quarters' bounds */
        lb[i] = bd_ridge_lb(&s, i);
        double lq = INFINITY, sg[3];
        for (int q = 0; q < 4; ++q) {
            sg[i] = 0.0, sg[(i + 1) % 3] = (q & 1) ? 1.0 : -1.0, sg[(i + 2) % 3] = (q & 2) ? 1.0 : -1.0;
            double v = bd_cone_lb(&s, sg, 7u & ~(1u << i));
            if (v < lq) lq = v;
        }
        if (lq > lb[i]) lb[i] = lq;
    }
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (lb[ord[j]] < lb[ord[i]]) { int t = ord[i]; ord[i] = ord[j]; ord[j] = t; }
    for (int i = 0; ok && i < 3; ++i)
        if (lb[ord[i]] < s.best - tol) ok = bd_edge_ridge(&s, ord[i], tol);
    res->status = PROX_OK;
    res->sd = -s.best;
    res->normal = s.best_d;
    if (!ok || !(s.best > 0.0)) return 0;
    sup_overlap_answer(a, b, s.best_d, res);
    res->sd_lower = -s.best; /* -phi at the best direction: a lower bound of sd (weak duality) */
    res->certified = 1; /* every stratum enumerated or bounded: the depth is proved (prox_body_signed_bounds) */
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

/* The box and the cylinder as support-engine bodies relative to the box centre *o, scaled by *f (a
 * power of two: exact) to unit scale, as the engine's entry point (support.c) prepares them, built
 * here without the generic constructor's copies of the whole body. */
static void bd_bodies(const prox_box *a, const prox_rcc *b, prox_body *ba, prox_body *bb, prox_vec3 *o, double *f)
{
    ba->kind = PROX_BODY_BOX;
    ba->cyl = (prox_cyl){0}, ba->r = 0.0; /* the other kinds' parts (prox_body_make_cyl clears B's) */
    ba->box = prox_bframe_make(a);
    *o = ba->box.m;
    ba->box.m = prox_v3(0, 0, 0);
    ba->size = prox_bframe_size(&ba->box);
    prox_body_make_cyl(b, bb);
    bb->c = prox_v3_sub(bb->c, *o);
    double S = prox_v3_norm(bb->c);
    S = ba->size > S ? ba->size : S;
    S = bb->size > S ? bb->size : S;
    *f = prox_unit_scale(S);
    ba->c = prox_v3(0, 0, 0);
    for (int k = 0; k < 3; ++k) ba->box.h[k] *= *f;
    ba->size *= *f;
    bb->c = prox_v3_scale(bb->c, *f);
    bb->cyl = prox_cyl_scaled(&bb->cyl, *f);
    bb->size *= *f;
}

prox_signed_result prox_sat_box_rcc_depth_bounded(const prox_box *a, const prox_rcc *b, int *bounded)
{
    prox_signed_result r = {0};
    *bounded = 0;
    if (!a || !b) { r.status = PROX_EINVAL_ARG; return r; }
    if ((r.status = prox_box_validate(a)) != PROX_OK || (r.status = prox_rcc_validate(b)) != PROX_OK) return r;
    prox_body ba, bb;
    prox_vec3 o;
    double f;
    bd_bodies(a, b, &ba, &bb, &o, &f);
    if (!sup_box_cyl_depth_enum(&ba, &bb, &r)) {
        atomic_fetch_add_explicit(&g_box_depth_fallbacks, 1, memory_order_relaxed);
        r = sup_signed_distance(&ba, &bb, NULL);
    }
    /* an overlapping answer's enclosure depends on the pair only through centre differences,
     * support functions and sizes: the scaled, relative bodies give it, scaled back below */
    if (r.status == PROX_OK && r.sd <= 0.0) {
        prox_body_signed_bounds(&ba, &bb, &r);
        *bounded = 1;
    }
    r.sd /= f;
    r.sd_lower /= f;
    r.sd_upper /= f;
    r.p1 = prox_v3_mad(o, 1.0 / f, r.p1);
    r.p2 = prox_v3_mad(o, 1.0 / f, r.p2);
    return r;
}
