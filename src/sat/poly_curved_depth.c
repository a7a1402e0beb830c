/* Penetration depth of an overlapping convex polytope (BOX, RPP, RHP, WED, ARB) and a cylinder (RCC)
 * or a spheroid (ELL) by enumerating the strata of the depth function in closed form: the
 * box-cylinder enumeration of box_rcc_depth.c carried over to any convex polytope P (corners v_i
 * relative to its reference point, face normals n_f, edges) and to a smooth body of revolution.
 *
 * phi(D) = hc_P(D) + hc_B(D) - D.Delta (hc_P(D) = max_i D.v_i; for the cylinder B with unit axis w,
 * radius r, half height hh, hc_B(D) = r |P_w D| + hh |D.w|; for the spheroid with semi-axis a along w
 * and b across, hc_B(D) = |(a D.w, b |P_w D|)|; Delta = c_B - c_P; Eberly's Eq. (4)); the depth is
 * its minimum over unit D. A minimiser has p1 - p2 = depth D with p1 in P's support set along D and
 * p2 in B's along -D, and these sets name its stratum:
 *   P face (D = n_f), cylinder disk (D = +-w), P edge e and cylinder side (D = +-e x w): points,
 *        evaluated;
 *   P vertex v and cylinder side (D.w = 0): on that great circle phi is r plus the support function
 *        of P's shadow along w minus D.Delta, least at an edge normal of the shadow (a direction
 *        +-e x w) or at the shadow vertex nearest the axis: D = +-P_w(v - c_B) / |..|;
 *   P vertex v and a rim point q: D is normal to the rim at q and along v - q, so q is the nearest
 *        or the farthest point of the rim circle from v: D = (v - q) / |v - q|, where phi >= |v - q|
 *        (v in P, q in B), so a rim point farther than the best value cannot improve it;
 *   P vertex v and the spheroid's surface: phi = hc_B(D) - D.(Delta - v), stationary at the normals
 *        of B at the feet of the perpendiculars from Delta - v (relative to B's centre), which lie in
 *        that point's meridian plane: the meridian ellipse's feet (sup_ellipse_feet);
 *   P edge along e and a rim point, or the spheroid's surface (D.e = 0): on that great circle h_P is
 *        the support function of P's shadow G along e and hc_B that of B's shadow: an ellipse E
 *        (semi-axes along e1 = unit(e x w) and e2 = e x e1: r and r |e.w| for the rim disk, b and
 *        |(a w.e2, b |e2 - (w.e2) w|)| for the spheroid), swept for the cylinder along the segment
 *        [-d, d] (the half axis's shadow), so phi = h_{G + [-d, d]}(D) + h_E(D) - D.Delta. On the
 *        normal arc of a vertex g of G + [-d, d] (the hull of the points g_i +- d, g_i the corners'
 *        shadows) it is h_E(D) - D.(Delta - g), stationary at the normals of E at the feet from
 *        Delta - g; the arcs' ends are D = n_f of the faces at the edge and D = e x w, evaluated
 *        above. A vertex whose arc's lower bound (the least h_E on the arc less the largest
 *        D.(Delta - g) there) cannot beat the best value by more than the search tolerance is
 *        skipped.
 * Every candidate is evaluated exactly (any direction is an upper bound of the depth), and every
 * stratum's stationary points are among them, so their minimum is the depth. The witnesses are the
 * general engine's pair of support sets at that direction (convex.h). Degenerate poses (a vertex on
 * the cylinder's axis or Delta - v on the spheroid's, an edge within PROX_TOL_RIDGE_THIN of
 * perpendicular to a cylinder's axis: a needle shadow, a flat shadow, a shadow point at a circle's
 * centre) return 0: the global search answers. */
#include "sup_engine.h"

#include "convex.h"
#include "core/axis.h"
#include "core/plane2.h"
#include "core/tol.h"
#include "prox/support.h"
#include "sat_internal.h"

typedef struct pd_state {
    const prox_polytope *p;
    const prox_body *b; /* the cylinder (PROX_BODY_CYL) or the spheroid (PROX_BODY_ELL) */
    prox_vec3 w;        /* its unit axis */
    prox_vec3 delta;    /* c_B - c_P */
    double best;
    prox_vec3 best_d;
} pd_state;

static double pd_hc(const pd_state *s, prox_vec3 d)
{
    return s->b->kind == PROX_BODY_CYL ? prox_cyl_hc(&s->b->cyl, d) : prox_ellb_hc(&s->b->x.ell, d);
}

/* Evaluates v / |v| (v need not be unit; v = 0 is ignored). */
static void pd_one(pd_state *s, prox_vec3 v)
{
    double n = prox_v3_norm(v);
    if (!(n > 0.0) || !isfinite(n)) return;
    v = prox_v3_scale(v, 1.0 / n);
    double f = prox_polytope_hc(s->p, v) + pd_hc(s, v) - prox_v3_dot(v, s->delta);
    if (f < s->best) s->best = f, s->best_d = v;
}

/* The normals at the feet from y (coordinates y0, y1 along the unit e0, e1) to the ellipse of
 * semi-axes s0, s1 along e0, e1, evaluated (sup_ellipse_feet takes the major axis first); `across`
 * rejects e from each (0: none). 0 when y is the centre of a circle. */
static int pd_feet(pd_state *s, double s0, double s1, double y0, double y1, prox_vec3 e0, prox_vec3 e1,
                   const prox_vec3 *across)
{
    prox_vec3 cand[48];
    int nc = 0, r = s0 >= s1 ? sup_ellipse_feet(s0, s1, y0, y1, e0, e1, cand, &nc, 48)
                             : sup_ellipse_feet(s1, s0, y1, y0, e1, e0, cand, &nc, 48);
    if (r < 0) return 0;
    for (int t = 0; t < nc; ++t) pd_one(s, across ? prox_v3_reject(cand[t], *across) : cand[t]);
    return 1;
}

static void pd_pm(pd_state *s, prox_vec3 v)
{
    pd_one(s, v);
    pd_one(s, prox_v3_neg(v));
}

/* Each corner against the cylinder's side and its rims. 0 when a corner lies on the axis. */
static int pd_vertices_cyl(pd_state *s, double tol)
{
    const prox_cyl *c = &s->b->cyl;
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

/* Each corner v against the spheroid's surface: phi = hc_E(D) - D.y on v's normal cone, y = Delta - v,
 * stationary at the normals of E at the feet from y, which lie in the meridian plane of y (axis w,
 * radial u): the meridian ellipse's feet. hc_E >= min(a, b) and D.y <= |y| bound the cone from below.
 * 0 when some y lies on the axis (its feet a whole circle). */
static int pd_vertices_ell(pd_state *s, double tol)
{
    const prox_ellb *k = &s->b->x.ell;
    double smin = k->a < k->b ? k->a : k->b;
    for (int i = 0; i < s->p->nv; ++i) {
        prox_vec3 y = prox_v3_sub(s->delta, s->p->v[i]);
        double yn = prox_v3_norm(y);
        if (smin - yn >= s->best - tol) continue;
        double t = prox_v3_dot(y, k->w), rho;
        prox_vec3 u = prox_axis_radial(y, k->w, &rho);
        if (!(rho > PROX_TOL_RADIAL * (yn + smin))) return 0;
        if (!pd_feet(s, k->a, k->b, t, rho, k->w, u, NULL)) return 0;
    }
    return 1;
}

/* The arc of unit directions from a to b (counter-clockwise, less than a half turn) holds D, to
 * slack: a sign within rounding counts as inside (the bound only weakens). */
static int pd_in_arc(const double a[2], const double b[2], double d0, double d1)
{
    return a[0] * d1 - a[1] * d0 >= -1e-12 && d0 * b[1] - d1 * b[0] >= -1e-12;
}

/* A lower bound of h_E(D) - D.p over the arc from a to b, E the ellipse of semi-axes s0, s1 along
 * the coordinates: the least h_E there (the minor semi-axis where the arc holds the minor axis's
 * direction, h_E's minima, else at an end: h_E is unimodal between them) minus the largest D.p (|p|
 * where the arc holds p's direction, else at an end). */
static double pd_arc_lb(const double a[2], const double b[2], double s0, double s1, double p0, double p1)
{
    double ha = sqrt(s0 * s0 * a[0] * a[0] + s1 * s1 * a[1] * a[1]), hb = sqrt(s0 * s0 * b[0] * b[0] + s1 * s1 * b[1] * b[1]);
    int minor1 = s1 <= s0; /* the minor axis is coordinate 1 */
    double m0 = minor1 ? 0.0 : 1.0, m1 = minor1 ? 1.0 : 0.0;
    double hmin = pd_in_arc(a, b, m0, m1) || pd_in_arc(a, b, -m0, -m1) ? (minor1 ? s1 : s0) : (ha < hb ? ha : hb);
    double pn = sqrt(p0 * p0 + p1 * p1), da = a[0] * p0 + a[1] * p1, db = b[0] * p0 + b[1] * p1;
    double dmax = pn > 0.0 && pd_in_arc(a, b, p0 / pn, p1 / pn) ? pn : (da > db ? da : db);
    return hmin - dmax;
}

/* The shadow of the curved body along the unit e on the plane of e1, e2 (unit, e1 = e x w / |..|): an
 * ellipse of semi-axes s0 along e1 and s1 along e2 swept along [-d, d], d = (0, d1) (the cylinder's
 * half axis; 0 for the spheroid). A cylinder: its rim disk's shadow, s0 = r, s1 = r |e.w|; 0 when
 * s1 <= PROX_TOL_RIDGE_THIN s0 (the edge nearly across the axis: a needle shadow). A spheroid
 * (semi-axis a along w, b across): the 2 x 2 section of its support matrix, s0 = b and
 * s1 = |(a w.e2, b |e2 - (w.e2) w|)|. */
static int pd_shadow(const pd_state *s, prox_vec3 e, prox_vec3 *e1, prox_vec3 *e2, double *s0, double *s1, double *d1)
{
    prox_vec3 x = prox_v3_cross(e, s->w);
    double xn = prox_v3_norm(x);
    int par = !(xn > PROX_TOL_PARALLEL);
    *e1 = par ? prox_v3_any_perp(e) : prox_v3_scale(x, 1.0 / xn);
    *e2 = prox_v3_cross(e, *e1);
    double w2 = prox_v3_dot(s->w, *e2);
    if (s->b->kind == PROX_BODY_CYL) {
        const prox_cyl *c = &s->b->cyl;
        *s0 = c->r, *s1 = par ? c->r : c->r * fabs(prox_v3_dot(e, c->w)), *d1 = c->hh * w2;
        return *s1 > PROX_TOL_RIDGE_THIN * *s0;
    }
    const prox_ellb *k = &s->b->x.ell;
    double across = 1.0 - w2 * w2;
    *s0 = k->b, *s1 = sqrt(k->a * k->a * w2 * w2 + k->b * k->b * (across > 0.0 ? across : 0.0)), *d1 = 0.0;
    return 1;
}

/* The ridge D.e = 0 of the unit edge direction e: 0 when degenerate. On the normal arc of each corner
 * g of the shadow's hull phi = h_E(D) - D.(Delta - g); a corner whose arc's bound (pd_arc_lb) cannot
 * beat the best value by more than tol holds no better stationary point, and its feet are not
 * solved. The corners are visited in the order of that bound, so the best value falls early. */
static int pd_ridge(pd_state *s, prox_vec3 e, double tol)
{
    prox_vec3 e1, e2;
    double s0, s1, d2;
    if (!pd_shadow(s, e, &e1, &e2, &s0, &s1, &d2)) return 0;
    double q1 = prox_v3_dot(s->delta, e1), q2 = prox_v3_dot(s->delta, e2);
    _Static_assert(2 * PROX_POLY_MAXV <= PROX_V2_HULL_MAX, "the shadow's corners fit prox_v2_hull");
    prox_v2 pts[2 * PROX_POLY_MAXV]; /* the corners' shadows moved by -+d: the hull's candidates */
    int n = 0, h[4 * PROX_POLY_MAXV + 2];
    for (int i = 0; i < s->p->nv; ++i) {
        double g1 = prox_v3_dot(s->p->v[i], e1), g2 = prox_v3_dot(s->p->v[i], e2);
        pts[n++] = (prox_v2){g1, g2 - d2};
        if (d2 != 0.0) pts[n++] = (prox_v2){g1, g2 + d2};
    }
    int m = prox_v2_hull(pts, n, h);
    if (m < 3) return 0; /* a flat shadow: the global search */
    double lb[2 * PROX_POLY_MAXV], nrm[2 * PROX_POLY_MAXV + 1][2];
    int ord[2 * PROX_POLY_MAXV];
    for (int k = 0; k < m; ++k) { /* the outward unit normal of the hull's edge k -> k + 1 */
        prox_v2 a = pts[h[k]], b = pts[h[k + 1 < m ? k + 1 : 0]];
        double t0 = b.y - a.y, t1 = a.x - b.x, tn = sqrt(t0 * t0 + t1 * t1);
        nrm[k][0] = t0 / tn, nrm[k][1] = t1 / tn;
    }
    for (int k = 0; k < m; ++k) { /* corner k's arc: from the normal of edge k - 1 to that of edge k */
        const double *a = nrm[k ? k - 1 : m - 1], *b = nrm[k];
        lb[k] = pd_arc_lb(a, b, s0, s1, q1 - pts[h[k]].x, q2 - pts[h[k]].y);
        int at = k;
        for (; at > 0 && lb[ord[at - 1]] > lb[k]; --at) ord[at] = ord[at - 1];
        ord[at] = k;
    }
    for (int v = 0; v < m; ++v) {
        int k = ord[v];
        if (lb[k] >= s->best - tol) break;
        if (!pd_feet(s, s0, s1, q1 - pts[h[k]].x, q2 - pts[h[k]].y, e1, e2, &e)) return 0; /* outward normals of E */
    }
    return 1;
}

int sup_poly_curved_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res)
{
    const prox_polytope *p = &a->x.poly;
    prox_vec3 w = b->kind == PROX_BODY_CYL ? b->cyl.w : b->x.ell.w;
    pd_state s = {.p = p, .b = b, .w = w, .delta = prox_v3_sub(b->c, a->c), .best = INFINITY, .best_d = w};
    pd_pm(&s, w);
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
        if (b->kind == PROX_BODY_CYL) pd_pm(&s, prox_v3_cross(e, w)); /* the edge against the side */
    }
    /* a stratum that cannot improve the best value by more than tol = 1e-13 S (far below the 1e-9 S
     * the depth promises) is skipped */
    double tol = PROX_TOL_SEARCH * fmax(prox_v3_norm(s.delta), fmax(a->size, b->size));
    int ok = b->kind == PROX_BODY_CYL ? pd_vertices_cyl(&s, tol) : pd_vertices_ell(&s, tol);
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

int prox_sat_poly_curved_depth(const prox_body *poly, const prox_body *curved, prox_signed_result *res)
{
    prox_vec3 o = poly->c;
    double S = fmax(prox_v3_dist(poly->c, curved->c), fmax(poly->size, curved->size)), f = prox_unit_scale(S);
    prox_body a, b;
    prox_body_scaled_at(&a, poly, prox_v3(0, 0, 0), f);
    prox_body_scaled_at(&b, curved, prox_v3_sub(curved->c, o), f);
    prox_signed_result r = {0};
    if (!sup_poly_curved_depth_enum(&a, &b, &r)) {
        atomic_fetch_add_explicit(&g_poly_depth_fallbacks, 1, memory_order_relaxed);
        return 0;
    }
    r.sd /= f, r.sd_lower /= f;
    prox_convex_overlap_witnesses(poly, curved, r.normal, r.sd, &r.p1, &r.p2); /* the general support sets */
    /* witnesses that miss p2 - p1 = sd n by more than the touching band (a needle or a flat spheroid,
     * 1e-10 as thin as it is wide, whose support sets at the exact direction carry that much rounding):
     * the global search's, which polishes its candidates */
    if (!(prox_v3_norm(prox_v3_sub(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd))) <= PROX_TOL_TOUCH * S)) {
        atomic_fetch_add_explicit(&g_poly_depth_fallbacks, 1, memory_order_relaxed);
        return 0;
    }
    *res = r;
    return 1;
}
