/* Penetration depth of an overlapping convex polytope (RHP, WED, ARB) and cylinder by enumerating the
 * strata of the depth function in closed form: the box-cylinder enumeration of box_rcc_depth.c carried
 * over to any convex polytope P (corners v_i relative to its reference point, face normals n_f, edges).
 *
 * phi(D) = hc_P(D) + hc_B(D) - D.Delta (hc_P(D) = max_i D.v_i, hc_B(D) = r |P_w D| + hh |D.w| for the
 * cylinder B with unit axis w, radius r, half height hh; Delta = c_B - c_P; Eberly's Eq. (4)); the depth
 * is its minimum over unit D. A minimiser has p1 - p2 = depth D with p1 in P's support set along D and
 * p2 in B's along -D, and these sets name its stratum:
 *   P face (D = n_f), cylinder disk (D = +-w), P edge e and cylinder side (D = +-e x w): points,
 *        evaluated;
 *   P vertex v and cylinder side (D.w = 0): on that great circle phi is r plus the support function
 *        of P's shadow along w minus D.Delta, least at an edge normal of the shadow (a direction
 *        +-e x w) or at the shadow vertex nearest the axis: D = +-P_w(v - c_B) / |..|;
 *   P vertex v and a rim point q: D is normal to the rim at q and along v - q, so q is the nearest
 *        or the farthest point of the rim circle from v: D = (v - q) / |v - q|, where phi >= |v - q|
 *        (v in P, q in B), so a rim point farther than the best value cannot improve it;
 *   P edge along e and a rim point (D.e = 0): on that great circle h_P is the support function of
 *        P's shadow G along e and hc_B that of the cylinder's shadow, an ellipse E (the rim disk's,
 *        semi-axes r along e1 = unit(e x w) and r |e.w| along e2 = e x e1) swept along the segment
 *        [-d, d] (the half axis's shadow), so phi = h_{G + [-d, d]}(D) + h_E(D) - D.Delta. On the
 *        normal arc of a vertex g of G + [-d, d] (the hull of the points g_i +- d, g_i the corners'
 *        shadows) it is h_E(D) - D.(Delta - g), stationary at the normals of E at the feet from
 *        Delta - g (sup_ellipse_feet); the arcs' ends are D = n_f of the faces at the edge and
 *        D = e x w, evaluated above. A vertex whose arc's lower bound (the least h_E on the arc less
 *        the largest D.(Delta - g) there) cannot beat the best value by more than the search
 *        tolerance is skipped.
 * Every candidate is evaluated exactly (any direction is an upper bound of the depth), and every
 * stratum's stationary points are among them, so their minimum is the depth. The witnesses are the
 * general engine's pair of support sets at that direction (convex.h). Degenerate poses (a
 * vertex on the cylinder's axis, an edge within PROX_TOL_RIDGE_THIN of perpendicular to the axis: a
 * needle shadow, a shadow point at a circle's centre) return 0: the global search answers. */
#include "sup_engine.h"

#include "convex.h"
#include "core/tol.h"
#include "prox/support.h"
#include "sat_internal.h"

typedef struct pd_state {
    const prox_polytope *p;
    const prox_cyl *c;
    prox_vec3 delta; /* c_B - c_P */
    double best;
    prox_vec3 best_d;
} pd_state;

/* Evaluates v / |v| (v need not be unit; v = 0 is ignored). */
static void pd_one(pd_state *s, prox_vec3 v)
{
    double n = prox_v3_norm(v);
    if (!(n > 0.0) || !isfinite(n)) return;
    v = prox_v3_scale(v, 1.0 / n);
    double f = prox_polytope_hc(s->p, v) + prox_cyl_hc(s->c, v) - prox_v3_dot(v, s->delta);
    if (f < s->best) s->best = f, s->best_d = v;
}

static void pd_pm(pd_state *s, prox_vec3 v)
{
    pd_one(s, v);
    pd_one(s, prox_v3_neg(v));
}

/* Each corner against the cylinder's side and its rims. 0 when a corner lies on the axis. */
static int pd_vertices(pd_state *s, double tol)
{
    const prox_cyl *c = s->c;
    for (int i = 0; i < s->p->nv; ++i) {
        prox_vec3 v = s->p->v[i], rel = prox_v3_sub(v, s->delta), perp = prox_v3_reject(rel, c->w);
        pd_pm(s, perp); /* the corner against the side: its shadow nearest the axis */
        double pn = prox_v3_norm(perp);
        if (!(pn > PROX_TOL_RADIAL * (prox_v3_norm(rel) + c->r))) return 0; /* on the axis: every rim point */
        prox_vec3 u = prox_v3_scale(perp, 1.0 / pn);
        double ax = prox_v3_dot(rel, c->w);
        for (int e = -1; e <= 1; e += 2) {
            prox_vec3 rc = prox_v3_mad(s->delta, e * c->hh, c->w);
            double z = ax - e * c->hh;
            if (sqrt((pn - c->r) * (pn - c->r) + z * z) < s->best - tol) /* the nearest rim point */
                pd_one(s, prox_v3_sub(v, prox_v3_mad(rc, c->r, u)));
            if (sqrt((pn + c->r) * (pn + c->r) + z * z) < s->best - tol) /* the farthest */
                pd_one(s, prox_v3_sub(v, prox_v3_mad(rc, -c->r, u)));
        }
    }
    return 1;
}

/* The shadow's hull: the corners of G + [-d, d] in counter-clockwise order (Andrew's monotone
 * chain), collinear points dropped. Returns how many (0 .. n). */
static int pd_hull(double (*q)[2], int n, int *h)
{
    for (int i = 1; i < n; ++i) /* sort by x, then y (insertion: n <= 2 PROX_POLY_MAXV) */
        for (int j = i; j > 0 && (q[j][0] < q[j - 1][0] || (q[j][0] == q[j - 1][0] && q[j][1] < q[j - 1][1])); --j) {
            double t0 = q[j][0], t1 = q[j][1];
            q[j][0] = q[j - 1][0], q[j][1] = q[j - 1][1], q[j - 1][0] = t0, q[j - 1][1] = t1;
        }
    int m = 0;
    for (int pass = 0; pass < 2; ++pass) {
        int base = m;
        for (int k = 0; k < n; ++k) {
            int i = pass ? n - 1 - k : k;
            while (m >= base + 2) {
                const double *a = q[h[m - 2]], *b = q[h[m - 1]];
                if ((b[0] - a[0]) * (q[i][1] - a[1]) - (b[1] - a[1]) * (q[i][0] - a[0]) > 0.0) break;
                --m;
            }
            h[m++] = i;
        }
        --m; /* the chain's last point starts the other */
    }
    return m;
}

/* The arc of unit directions from a to b (counter-clockwise, less than a half turn) holds D, to
 * slack: a sign within rounding counts as inside (the bound only weakens). */
static int pd_in_arc(const double a[2], const double b[2], double d0, double d1)
{
    return a[0] * d1 - a[1] * d0 >= -1e-12 && d0 * b[1] - d1 * b[0] >= -1e-12;
}

/* A lower bound of h_E(D) - D.p over the arc from a to b: the least h_E there (eb where the arc holds
 * +-e2, h_E's minima, else at an end: h_E is unimodal between them) minus the largest D.p (|p| where
 * the arc holds p's direction, else at an end). */
static double pd_arc_lb(const double a[2], const double b[2], double ea, double eb, double p0, double p1)
{
    double ha = sqrt(ea * ea * a[0] * a[0] + eb * eb * a[1] * a[1]), hb = sqrt(ea * ea * b[0] * b[0] + eb * eb * b[1] * b[1]);
    double hmin = pd_in_arc(a, b, 0.0, 1.0) || pd_in_arc(a, b, 0.0, -1.0) ? eb : (ha < hb ? ha : hb);
    double pn = sqrt(p0 * p0 + p1 * p1), da = a[0] * p0 + a[1] * p1, db = b[0] * p0 + b[1] * p1;
    double dmax = pn > 0.0 && pd_in_arc(a, b, p0 / pn, p1 / pn) ? pn : (da > db ? da : db);
    return hmin - dmax;
}

/* The ridge D.e = 0 of the unit edge direction e: 0 when degenerate. On the normal arc of each corner
 * g of the shadow's hull phi = h_E(D) - D.(Delta - g); a corner whose arc's bound (pd_arc_lb) cannot
 * beat the best value by more than tol holds no better stationary point, and its feet are not
 * solved. The corners are visited in the order of that bound, so the best value falls early. */
static int pd_ridge(pd_state *s, prox_vec3 e, double tol)
{
    const prox_cyl *c = s->c;
    prox_vec3 x = prox_v3_cross(e, c->w);
    double cw = fabs(prox_v3_dot(e, c->w)), xn = prox_v3_norm(x);
    double ea = c->r, eb = c->r * cw;
    if (!(eb > PROX_TOL_RIDGE_THIN * ea)) return 0; /* the edge nearly across the axis: a needle shadow */
    prox_vec3 e1 = xn > PROX_TOL_PARALLEL ? prox_v3_scale(x, 1.0 / xn) : prox_v3_any_perp(e);
    prox_vec3 e2 = prox_v3_cross(e, e1);
    if (!(xn > PROX_TOL_PARALLEL)) eb = ea;
    double d2 = c->hh * prox_v3_dot(c->w, e2); /* the half axis's shadow: (0, d2), as w.e1 = 0 */
    double q1 = prox_v3_dot(s->delta, e1), q2 = prox_v3_dot(s->delta, e2);
    double pts[2 * PROX_POLY_MAXV][2];
    int n = 0, h[4 * PROX_POLY_MAXV + 2];
    for (int i = 0; i < s->p->nv; ++i) {
        double g1 = prox_v3_dot(s->p->v[i], e1), g2 = prox_v3_dot(s->p->v[i], e2);
        pts[n][0] = g1, pts[n++][1] = g2 - d2;
        pts[n][0] = g1, pts[n++][1] = g2 + d2;
    }
    int m = pd_hull(pts, n, h);
    if (m < 3) return 0; /* a flat shadow: the global search */
    double lb[2 * PROX_POLY_MAXV], nrm[2 * PROX_POLY_MAXV + 1][2];
    int ord[2 * PROX_POLY_MAXV];
    for (int k = 0; k < m; ++k) { /* the outward unit normal of the hull's edge k -> k + 1 */
        const double *a = pts[h[k]], *b = pts[h[k + 1 < m ? k + 1 : 0]];
        double t0 = b[1] - a[1], t1 = a[0] - b[0], tn = sqrt(t0 * t0 + t1 * t1);
        nrm[k][0] = t0 / tn, nrm[k][1] = t1 / tn;
    }
    for (int k = 0; k < m; ++k) { /* corner k's arc: from the normal of edge k - 1 to that of edge k */
        const double *g = pts[h[k]], *a = nrm[k ? k - 1 : m - 1], *b = nrm[k];
        lb[k] = pd_arc_lb(a, b, ea, eb, q1 - g[0], q2 - g[1]);
        int at = k;
        for (; at > 0 && lb[ord[at - 1]] > lb[k]; --at) ord[at] = ord[at - 1];
        ord[at] = k;
    }
    prox_vec3 cand[48];
    for (int v = 0; v < m; ++v) {
        int k = ord[v], nc = 0;
        if (lb[k] >= s->best - tol) break;
        const double *g = pts[h[k]];
        if (sup_ellipse_feet(ea, eb, q1 - g[0], q2 - g[1], e1, e2, cand, &nc, 48) < 0) return 0;
        for (int t = 0; t < nc; ++t) pd_one(s, prox_v3_reject(cand[t], e)); /* outward normals of E */
    }
    return 1;
}

int sup_poly_cyl_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res)
{
    const prox_polytope *p = &a->x.poly;
    const prox_cyl *c = &b->cyl;
    pd_state s = {.p = p, .c = c, .delta = prox_v3_sub(b->c, a->c), .best = INFINITY, .best_d = c->w};
    pd_pm(&s, c->w);
    for (int f = 0; f < p->nf; ++f) pd_one(&s, p->n[f]);
    /* the distinct edge directions (parallel edges share their ridge and their e x w) */
    prox_vec3 dirs[PROX_POLY_MAXE];
    int nd = 0;
    for (int k = 0; k < p->ne; ++k) {
        prox_vec3 e = prox_v3_normalize(prox_v3_sub(p->v[p->e[k][1]], p->v[p->e[k][0]]));
        int dup = 0;
        for (int j = 0; j < nd && !dup; ++j) dup = prox_v3_norm(prox_v3_cross(e, dirs[j])) <= PROX_TOL_EDGE_AXIS;
        if (dup) continue;
        dirs[nd++] = e;
        pd_pm(&s, prox_v3_cross(e, c->w));
    }
    /* a stratum that cannot improve the best value by more than tol = 1e-13 S (far below the 1e-9 S
     * the depth promises) is skipped */
    double tol = PROX_TOL_SEARCH * fmax(prox_v3_norm(s.delta), fmax(a->size, b->size));
    int ok = pd_vertices(&s, tol);
    for (int k = 0; ok && k < nd; ++k) ok = pd_ridge(&s, dirs[k], tol);
    res->status = PROX_OK;
    res->sd = -s.best;
    res->normal = s.best_d;
    if (!ok || !(s.best > 0.0)) return 0;
    res->sd_lower = -s.best; /* -phi at the best direction: a lower bound of sd (weak duality) */
    res->certified = 1;      /* every stratum enumerated or bounded: the depth is proved */
    return 1;
}

#include <stdatomic.h>

static atomic_ullong g_poly_depth_fallbacks;

unsigned long long prox_sat_poly_depth_fallbacks(void)
{
    return atomic_load_explicit(&g_poly_depth_fallbacks, memory_order_relaxed);
}

int prox_sat_poly_rcc_depth(const prox_body *poly, const prox_body *cyl, prox_signed_result *res)
{
    prox_vec3 o = poly->c;
    double S = fmax(prox_v3_dist(poly->c, cyl->c), fmax(poly->size, cyl->size)), f = prox_unit_scale(S);
    prox_body a = *poly, b = *cyl;
    a.c = prox_v3(0, 0, 0), b.c = prox_v3_sub(cyl->c, o);
    a = prox_body_scaled(&a, f), b = prox_body_scaled(&b, f);
    prox_signed_result r = {0};
    if (!sup_poly_cyl_depth_enum(&a, &b, &r)) {
        atomic_fetch_add_explicit(&g_poly_depth_fallbacks, 1, memory_order_relaxed);
        return 0;
    }
    r.sd /= f, r.sd_lower /= f;
    prox_convex_overlap_witnesses(poly, cyl, r.normal, r.sd, &r.p1, &r.p2); /* the general support sets */
    *res = r;
    return 1;
}
