/* Penetration depth of two overlapping solid cylinders by enumeration of the strata of the depth
 * function (derivation in docs/algorithms/sat.md, "Fast depth by strata").
 *
 * phi(D) = rA|P_A D| + hA|D.WA| + rB|P_B D| + hB|D.WB| - D.Delta (Eberly, "Intersection of
 * Cylinders", Eqs. (4) and (6), with the sign of D.Delta kept), depth = min_{|D|=1} phi(D).
 * A minimiser D* with witnesses p1 (support of A in D*), p2 (support of B in -D*) has
 * p2 - p1 = -depth D*, and lies on one stratum:
 *   points:  D = +-WA, +-WB (an end disk), +-(WA x WB) (two lateral lines);
 *   ridge D.WA = 0 (A's lateral line against a rim point q of B): q - cA projected off WA is
 *            parallel to D, i.e. q is a stationary point of dist^2(rim of B, axis line of A)
 *            (Agarwal et al. Sec. 3.3 quartic, prox_circle_line_stationary); same with A and B swapped;
 *   cell (rim point against rim point): (p1, p2) is a critical pair of |p1 - p2|^2 over the two
 *            rim circles, and phi(D*) = |p1 - p2|. A critical pair where p2 is the closest point of
 *            B's rim to p1 is a stationary point of dist^2(point of A's rim, B's rim) (Agarwal Sec.
 *            3.5, prox_circle_circle_stationary); with p1 closest to p2 the same with A and B
 *            swapped; the remaining (farthest, farthest) pairs have |p1 - p2|^2 >= |p1 - cB|^2 + rB^2,
 *            and where that bound does not exceed the best (deep overlaps) they are solved too: the
 *            stationary points of the far-point distance (dp_cells_far).
 * Cells are excluded by lower bounds of the circle-circle distance (centres, planes, spheres), by
 * chords of phi over the cell's lune of directions (sup_rim_lune_lb), then by a certified scan of
 * the rim's angle (dp_cell_may: the normal-cone, value and stationarity conditions of a cell
 * minimiser, each bounded over an interval by its Lipschitz constant, some also by a bound of their
 * second derivative). Where the scan proves the stationarity strictly monotone its one root is
 * solved on the interval (dp_cell_roots); only a cell with an interval the scan cannot settle is
 * solved whole (degree 8). A cell or case that cannot be settled returns 0 and the caller runs the
 * global search of sup_engine.c. */
#include "sat_internal.h"
#include "sup_engine.h"

#include "core/circle.h"
#include "core/minmax.h"
#include "core/tol.h"

#include <float.h>

/* Best direction and value so far. */
typedef struct dp_state {
    const prox_body *a, *b;
    prox_vec3 delta;
    double best;
    prox_vec3 best_d;
} dp_state;

/* Evaluates +-v / |v| (v need not be unit); ignores v = 0. Both cylinders are centrally symmetric,
 * so the support part hc_A(D) + hc_B(D) of phi is even (exactly, in floating point: prox_cyl_hc uses
 * D only through products that change sign with it) and one evaluation serves both signs:
 * phi(+-D) = hc_A(D) + hc_B(D) -+ D.Delta. */
static void dp_consider_pm(dp_state *s, prox_vec3 v)
{
    double n = sqrt(prox_v3_norm2(v));
    if (!(n > 0.0)) return;
    v = prox_v3_scale(v, 1.0 / n);
    double e = prox_cyl_hc(&s->a->cyl, v) + prox_cyl_hc(&s->b->cyl, v), dd = prox_v3_dot(v, s->delta);
    double f = e - dd, g = e + dd;
    if (f < s->best) { s->best = f; s->best_d = v; }
    if (g < s->best) { s->best = g; s->best_d = prox_v3_neg(v); }
}

/* Rim circle of cylinder c at end e (+1 top, -1 bottom), in absolute coordinates: the core's rim of
 * the centred cylinder, moved to the centre. */
static prox_fcircle dp_rim(const prox_body *c, int e)
{
    prox_fcircle f = prox_cyl_rim(&c->cyl, e > 0);
    f.c = prox_v3_add(f.c, c->c);
    return f;
}

/* Tangent (length r) of circle c at its point p. */
static prox_vec3 dp_tangent(const prox_fcircle *c, prox_vec3 p)
{
    return prox_v3_cross(c->n, prox_v3_sub(p, c->c));
}

/* Where the rim circle c lies seen from the other cylinder k: its axial coordinate (q - c_k).w over
 * its points q in [zlo, zhi] (the centre's value +- r_c |w x n_c|), its distance from k's axis in
 * [rlo, rhi] (the centre's rho -+ r_c: the rim projects off the axis onto an ellipse of semi-axes
 * <= r_c; rlo may be negative). Each rim is seen once from the other cylinder, for its ridge and its
 * cells. */
typedef struct dp_band {
    double zlo, zhi, rlo, rhi;
} dp_band;

static dp_band dp_band_of(const prox_fcircle *c, const prox_body *k)
{
    prox_vec3 d = prox_v3_sub(c->c, k->c);
    double z = prox_v3_dot(d, k->cyl.w), sp = c->r * prox_v3_norm(prox_v3_cross(k->cyl.w, c->n));
    double rho = prox_v3_norm(prox_v3_reject(d, k->cyl.w));
    return (dp_band){z - sp, z + sp, rho - c->r, rho + c->r};
}

/* Lower bound of phi at a minimiser on the ridge of `lat` (radius r, half height hh) whose other
 * support point q lies on the rim of band g: phi = |p2 - p1| with p1 = q's partner on lat's support
 * segment (radius r from the axis, |axial offset| <= hh). */
static double dp_ridge_lb(const dp_band *g, const prox_body *lat)
{
    const prox_cyl *k = &lat->cyl;
    double lb = prox_max2(g->rlo - k->r, k->r - g->rhi);
    lb = prox_max2(lb, prox_max2(g->zlo, -g->zhi) - k->hh);
    return prox_max2(lb, 0.0);
}

/* Necessary condition for a minimiser with value phi <= cut whose support point p on body k is a
 * point of k's lateral line (e = 0: D.w = 0) or of k's rim at end e (+-1), and whose other support
 * point q lies on the rim of band g. With D = alpha e w + beta u (u radial at p, alpha, beta >= 0,
 * unit; alpha = 0 on the lateral line) and q = p - phi D (p2 - p1 = sd D for A's point p, the mirror
 * for B's):
 *   axial coordinate of q:  e (q - c_k).w = hh - phi alpha, in [hh - cut, hh] (rim), in [-hh, hh] (lateral);
 *   distance of q from k's axis: |r - phi beta|, in [max(0, r - cut), max(r, cut - r)].
 * 0 when the rim has no point in both ranges (the stratum holds no minimiser at or below cut). */
static int dp_reach(const dp_band *g, const prox_body *k, int e, double cut, double tol)
{
    double r = k->cyl.r, hh = k->cyl.hh;
    if (e != 0) {
        double l = e > 0 ? g->zlo : -g->zhi, h = e > 0 ? g->zhi : -g->zlo; /* range of e (q - c_k).w */
        if (l > hh + tol || h < hh - cut - tol) return 0;
    } else if (g->zlo > hh + tol || g->zhi < -hh - tol)
        return 0;
    return !(prox_max2(0.0, g->rlo) > prox_max2(r, cut - r) + tol || g->rhi < r - cut - tol);
}

/* Ridge D.w = 0 of cylinder `lat` (its lateral line) against the rims rr[0] (bottom), rr[1] (top) of
 * `rim` (gr: their bands seen from lat): every stationary point q of dist^2(rim, axis of lat) gives
 * D = +-(q - c_lat) projected off w. 0 when degenerate. */
static int dp_ridge(dp_state *s, const prox_body *lat, const prox_body *rim, const prox_fcircle rr[2],
                    const dp_band gr[2], double tol)
{
    if (sup_ridge_shadow_lb(lat, rim, s->delta) > s->best + tol) return 1;
    prox_vec3 w = lat->cyl.w;
    int need[2];
    for (int i = 0; i < 2; ++i)
        need[i] = !(dp_ridge_lb(&gr[i], lat) > s->best + tol || !dp_reach(&gr[i], lat, 0, s->best, tol));
    if (!need[0] && !need[1]) return 1;
    /* the whole ridge in its plane (rcc_ridge_shadow.c: its minimiser is among the candidates); the
     * rims' quartics when it is degenerate */
    prox_vec3 cand[24];
    int nc = sup_ridge_shadow_min(lat, rim, s->delta, cand, 24);
    if (nc >= 0) {
        for (int i = 0; i < nc; ++i) dp_consider_pm(s, prox_v3_reject(cand[i], w));
        return 1;
    }
    for (int e = -1; e <= 1; e += 2) {
        prox_fcircle c = rr[(e + 1) / 2];
        if (!need[(e + 1) / 2]) continue;
        double th[4];
        int cnt = 0;
        int rc = prox_circle_line_stationary(&c, lat->c, w, th, &cnt);
        if (rc < 0) return 0; /* the quartic could not be rooted: the global search decides */
        if (rc == 1) { /* rim coaxial with lat */
            dp_consider_pm(s, prox_v3_any_perp(w));
            continue;
        }
        for (int i = 0; i < cnt; ++i) {
            prox_vec3 v = prox_v3_reject(prox_v3_sub(prox_fcircle_point(&c, th[i]), lat->c), w);
            v = prox_v3_reject(v, w); /* second pass: v may be short */
            if (!(prox_v3_norm2(v) > PROX_TOL_RADIAL * PROX_TOL_RADIAL * lat->size * lat->size)) return 0; /* rim point on the axis */
            dp_consider_pm(s, v);
            dp_consider_pm(s, prox_v3_cross(w, dp_tangent(&c, prox_fcircle_point(&c, th[i]))));
        }
    }
    return 1;
}

/* Range [dmin, dmax] of |q - x| over the points q of circle c. */
static void dp_circle_range(const prox_fcircle *c, prox_vec3 x, double *dmin, double *dmax)
{
    prox_vec3 d = prox_v3_sub(c->c, x);
    double dd = prox_v3_norm2(d), pd = prox_v3_norm(prox_v3_reject(d, c->n));
    *dmin = sqrt(prox_max2(0.0, dd + c->r * c->r - 2.0 * c->r * pd));
    *dmax = sqrt(dd + c->r * c->r + 2.0 * c->r * pd);
}

/* Lower bound of the distance between circles a and b: centres, each plane, each sphere (every
 * point of b lies on the sphere of radius rb around its centre). *far_a (*far_b): lower bound of
 * |p1 - p2| over pairs where p1 is the farthest point of a from p2 (p2 the farthest of b from p1):
 * the farthest point q of a circle (centre c, radius r) from x has |x - q|^2 >= |x - c|^2 + r^2. */
static double dp_circle_lb(const prox_fcircle *a, const prox_fcircle *b, double *far_a, double *far_b)
{
    prox_vec3 d = prox_v3_sub(a->c, b->c);
    double lb = prox_v3_norm(d) - a->r - b->r;
    double sn = prox_v3_norm(prox_v3_cross(a->n, b->n));
    lb = prox_max2(lb, fabs(prox_v3_dot(b->n, d)) - a->r * sn);
    lb = prox_max2(lb, fabs(prox_v3_dot(a->n, d)) - b->r * sn);
    double amin, amax, bmin, bmax;
    dp_circle_range(a, b->c, &amin, &amax);
    dp_circle_range(b, a->c, &bmin, &bmax);
    lb = prox_max2(lb, prox_max2(amin - b->r, b->r - amax));
    lb = prox_max2(lb, prox_max2(bmin - a->r, a->r - bmax));
    *far_a = prox_max2(lb, sqrt(bmin * bmin + a->r * a->r));
    *far_b = prox_max2(lb, sqrt(amin * amin + b->r * b->r));
    return prox_max2(lb, 0.0);
}

/* Upper bound of D.v over the unit D of the lune D.al >= 0, D.be >= 0 (al, be unit; al x be = x, |x|
 * = nx): |v| when v lies in the lune, else the largest of the boundary arcs' maxima, |P_al v| on the
 * arc D.al = 0 when that projection has D.be >= 0 (the same with al and be swapped) and |v.x| / nx at
 * the arcs' ends +-x / nx. Nearly parallel axes (nx < 1/16, where x / nx carries eps / nx) take |v|. */
static double dp_lune_max(prox_vec3 v, prox_vec3 al, prox_vec3 be, prox_vec3 x, double nx)
{
    double va = prox_v3_dot(v, al), vb = prox_v3_dot(v, be);
    if ((va >= 0.0 && vb >= 0.0) || nx < 0.0625) return prox_v3_norm(v);
    double m = fabs(prox_v3_dot(v, x)) / nx;
    prox_vec3 pa = prox_v3_mad(v, -va, al), pb = prox_v3_mad(v, -vb, be);
    if (prox_v3_dot(pa, be) >= 0.0) m = prox_max2(m, prox_v3_norm(pa));
    if (prox_v3_dot(pb, al) >= 0.0) m = prox_max2(m, prox_v3_norm(pb));
    return m;
}

/* Lower bound of phi over the directions of the cell of A's rim ca (end ea) and B's rim cb (end eb).
 * There A's support lies on rim ea and B's (in -D) on rim eb, so D lies in the lune D.al >= 0,
 * D.be >= 0 (al = ea wA, be = -eb wB) and phi(D) = rA g(D.al) + rB g(D.be) - D.m, g(t) = sqrt(1 -
 * t^2), m = cb.c - ca.c (the end terms hh|D.w| join Delta into the rim centres). Over the lune D.al
 * and D.be range over [0, top], top = 1 when al.be >= 0 (al lies in the lune) and |P_be al| =
 * sqrt(1 - (al.be)^2) otherwise (1 again for a lune too thin to take its width from rounded
 * cosines). g is concave there, so it is at least the smaller of its chords over [0, k top] and
 * [k top, top] (k = 3/4); each choice of chords for the two terms makes phi >= c0 - D.v with v =
 * m - rA s_a al - rB s_b be (s the chords' slopes), whose minimum over the lune is c0 minus
 * dp_lune_max. The bound is the least of the four. Rounding (a few eps (|m| + rA + rB)) stays far
 * below the PROX_TOL_SEARCH x S margin of the cut it is compared with. */
double sup_rim_lune_lb(const prox_fcircle *ca, prox_vec3 al, const prox_fcircle *cb, prox_vec3 be)
{
    prox_vec3 m = prox_v3_sub(cb->c, ca->c), x = prox_v3_cross(al, be);
    double c = prox_v3_dot(al, be), nx = prox_v3_norm(x);
    double top = c >= 0.0 || !(1.0 - c * c > 1e-6) ? 1.0 : sqrt(1.0 - c * c); /* [0, 1] holds any range */
    double t[3] = {0.0, 0.75 * top, top}, g[3], sl[2];
    for (int i = 0; i < 3; ++i) g[i] = sqrt(1.0 - t[i] * t[i]);
    for (int i = 0; i < 2; ++i) sl[i] = (g[i + 1] - g[i]) / (t[i + 1] - t[i]);
    double lb = INFINITY;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            double c0 = ca->r * (g[i] - sl[i] * t[i]) + cb->r * (g[j] - sl[j] * t[j]);
            prox_vec3 v = prox_v3_mad(prox_v3_mad(m, -ca->r * sl[i], al), -cb->r * sl[j], be);
            lb = prox_min2(lb, c0 - dp_lune_max(v, al, be, x, nx));
        }
    return lb;
}

/* The core's circle-circle stationary angles (Agarwal Sec. 3.5, degree 8): 0 solved, 1 degenerate
 * (coaxial: a set of pairs), a negative prox_status when the root finder failed. */
static int dp_cc_stationary(const prox_fcircle *a, const prox_fcircle *b, double th[8], int *cnt)
{
    return prox_circle_circle_stationary(a, b, PROX_ROOTS_CHAIN, th, cnt);
}

/* Critical pairs of one circle pair where the point of `b` is the closest of b to the point of `a`;
 * each gives D = +-(p_a - p_b), and D = +-(t_a x t_b) (D is normal to both rims' tangents: exact
 * also when the pair nearly touches and p_a - p_b is rounding). 1 solved, 0 degenerate (the caller
 * falls back to the global search), a negative prox_status when the solver failed. */
static int dp_cells_closest(dp_state *s, const prox_fcircle *a, const prox_fcircle *b)
{
    double th[8];
    int cnt = 0;
    int rc = dp_cc_stationary(a, b, th, &cnt);
    if (rc < 0) return rc;
    if (rc != 0) return 0;
    for (int i = 0; i < cnt; ++i) {
        int deg = 0;
        prox_vec3 pa = prox_fcircle_point(a, th[i]), pb = prox_fcircle_closest(b, pa, &deg);
        if (deg) return 0;
        dp_consider_pm(s, prox_v3_sub(pa, pb));
        dp_consider_pm(s, prox_v3_cross(dp_tangent(a, pa), dp_tangent(b, pb)));
    }
    return 1;
}

/* Critical pairs of one circle pair where the point of `b` is the FARTHEST of b from the point of
 * `a`: the stationary points on `a` of the far-point distance (the core's solver with b's radius
 * negated: the same degree-8 polynomial, the roots its closest-point filter drops), each partner the
 * point of b opposite the closest one. With dp_cells_closest(a, b) they give every critical pair of
 * |p_a - p_b|^2 over the two rims (the partner of a point on a circle is its closest or farthest
 * point there). Returns as dp_cells_closest. */
static int dp_cells_far(dp_state *s, const prox_fcircle *a, const prox_fcircle *b)
{
    prox_fcircle bn = *b;
    bn.r = -b->r;
    double th[8];
    int cnt = 0;
    int rc = dp_cc_stationary(a, &bn, th, &cnt);
    if (rc < 0) return rc;
    if (rc != 0) return 0;
    for (int i = 0; i < cnt; ++i) {
        int deg = 0;
        prox_vec3 pa = prox_fcircle_point(a, th[i]), pc = prox_fcircle_closest(b, pa, &deg);
        if (deg) return 0;
        prox_vec3 pb = prox_v3_sub(prox_v3_scale(b->c, 2.0), pc);
        dp_consider_pm(s, prox_v3_sub(pa, pb));
        dp_consider_pm(s, prox_v3_cross(dp_tangent(a, pa), dp_tangent(b, pb)));
    }
    return 1;
}

enum { DP_NROOT = 4 }; /* stationary points a cell's scan may hand to the local solve */

/* One cell's parametrised rim x(theta) (circle P of body kp at end ep) against rim Q of body kq at
 * end eq, for the certified exclusion below, with the per-cell coefficients of its conditions as
 * trigonometric polynomials of theta (dp_cell_prep): x - c_Q = d0 + r_P (c u + s v), its offset
 * from Q's axis rad(theta) = R0 + c Ru + s Rv, and the dot products the conditions take of it. */
typedef struct dp_cell {
    const prox_fcircle *p, *q;
    double cut, tol;
    double lq; /* bound of |q - c_P| + r_P: the turn rate of f[4] from its direction u_P */
    double a1; /* amplitude r_P |wq x n_P| of f[1], a trigonometric polynomial of degree 1 */
    int budget; /* evaluations left before the scan gives up (the cell is then solved) */
    int far;    /* q is the farthest point of rim Q from x (dp_cells_far), not the closest */
    int nroot;  /* intervals holding exactly one stationary point (dp_cell_span), solved locally */
    double root[DP_NROOT][2];
    prox_vec3 r0, ru, rv;           /* rad = r0 + c ru + s rv */
    double z0, zu, zv;              /* f[1] = ezq.(x - c_Q) = z0 + c zu + s zv */
    double e0, e0r, eur, evr;       /* ezp.(c_Q - c_P), and ezp.rad = e0r + c eur + s evr */
    double gu, gv, ru0, rv0;        /* (c_P - c_Q).u, .v; R0.u, R0.v */
    double puu, puv, pvv, quv, qd, qvu; /* rad.u_P(x) - c ru0 - s rv0 = c^2 puu + cs puv + s^2 pvv;
                                         * rad.t_P(x) - c rv0 + s ru0 = c^2 quv + cs qd - s^2 qvu */
} dp_cell;

enum { DP_NCOND = 7, DP_NVAL = 9 }; /* the conditions, then cos and sin of the angle */

/* The coefficients of dp_cell from the two circles and Q's axis wq, the end normals ezq = eq wq and
 * ezp = ep wp. */
static void dp_cell_prep(dp_cell *g, prox_vec3 wq, prox_vec3 ezq, prox_vec3 ezp)
{
    const prox_fcircle *p = g->p, *q = g->q;
    prox_vec3 d0 = prox_v3_sub(p->c, q->c);
    g->r0 = prox_v3_reject(d0, wq);
    g->ru = prox_v3_scale(prox_v3_reject(p->u, wq), p->r);
    g->rv = prox_v3_scale(prox_v3_reject(p->v, wq), p->r);
    g->z0 = prox_v3_dot(d0, ezq), g->zu = p->r * prox_v3_dot(p->u, ezq), g->zv = p->r * prox_v3_dot(p->v, ezq);
    g->e0 = -prox_v3_dot(d0, ezp), g->e0r = prox_v3_dot(g->r0, ezp);
    g->eur = prox_v3_dot(g->ru, ezp), g->evr = prox_v3_dot(g->rv, ezp);
    g->gu = prox_v3_dot(d0, p->u), g->gv = prox_v3_dot(d0, p->v);
    g->ru0 = prox_v3_dot(g->r0, p->u), g->rv0 = prox_v3_dot(g->r0, p->v);
    g->puu = prox_v3_dot(g->ru, p->u), g->pvv = prox_v3_dot(g->rv, p->v);
    g->puv = prox_v3_dot(g->ru, p->v) + prox_v3_dot(g->rv, p->u);
    g->quv = prox_v3_dot(g->ru, p->v), g->qvu = prox_v3_dot(g->rv, p->u);
    g->qd = prox_v3_dot(g->rv, p->v) - prox_v3_dot(g->ru, p->u);
}

/* The conditions at x = x(theta), each <= 0 at a cell minimiser (dp_cell_may), q the closest point
 * of rim Q to x: f[0] = rho_Q(x) - r_Q, f[1] = ezq.(x - c_Q), f[2] = |x - q| - cut (1-Lipschitz in
 * x); f[3] = ezp.(q - c_P), f[4] = (q - x).u_P(x) (through q; -inf when x is on Q's axis); f[5] the
 * stationarity (q - x).t_P(x); f[6] = rho_Q(x). With far, q is the farthest point of Q: f[0] (no
 * radial condition there) is -rho_Q - r_Q <= 0, and |x - q| = sqrt((rho + r_Q)^2 + z^2), again
 * 1-Lipschitz in x (the largest distance to a set). With q = c_Q + k rad (k = +-r_Q / rho) and
 * x = c_P + r_P u_P(x): q - x = -(c_P - c_Q) - r_P u_P + k rad, u_P.t_P = 0, so
 * f[3] = ezp.(c_Q - c_P) + k ezp.rad, f[4] = -(c gu + s gv) - r_P + k rad.u_P,
 * f[5] = -(c gv - s gu) + k rad.t_P, each from the coefficients of dp_cell_prep. */
static void dp_cell_vals(dp_cell *g, double c, double s, double f[DP_NVAL])
{
    --g->budget;
    f[7] = c, f[8] = s;
    prox_vec3 rad = prox_v3_add(g->r0, prox_v3_add(prox_v3_scale(g->ru, c), prox_v3_scale(g->rv, s)));
    double z = g->z0 + c * g->zu + s * g->zv;
    double rho = prox_v3_norm(rad);
    double dr = g->far ? rho + g->q->r : rho - g->q->r;
    f[0] = g->far ? -dr : dr;
    f[1] = z;
    f[2] = sqrt(dr * dr + z * z) - g->cut;
    f[6] = rho;
    if (!(rho > 0.0)) {
        f[3] = f[4] = -INFINITY;
        f[5] = 0.0;
        return;
    }
    double k = (g->far ? -g->q->r : g->q->r) / rho, cc = c * c, cs = c * s, ss = s * s;
    f[3] = g->e0 + k * (g->e0r + c * g->eur + s * g->evr);
    f[4] = k * (c * g->ru0 + s * g->rv0 + cc * g->puu + cs * g->puv + ss * g->pvv) - (c * g->gu + s * g->gv) - g->p->r;
    f[5] = k * (c * g->rv0 - s * g->ru0 + cc * g->quv + cs * g->qd - ss * g->qvu) - (c * g->gv - s * g->gu);
}

/* 0 when no angle of [t0, t1] satisfies all the conditions: an f with |df/dtheta| <= L is >= (f(t0)
 * + f(t1) - L (t1 - t0)) / 2 on the interval. x moves at speed r_P, so L = r_P for f[0..2]; q moves at
 * most r_Q / rho_Q times as fast as x (rho_Q >= rho_lo on the interval, from f[0]), so L = r_P r_Q /
 * rho_lo for f[3], plus the turn of u_P times |q - x| <= |q - c_P| + r_P for f[4]. An f with
 * |d2f/dtheta2| <= M stays within M w^2 / 8 of its chord, so it is >= min(f(t0), f(t1)) - M w^2 / 8 on
 * an interval of width w: tighter on short intervals, used for f[1], rho_Q and f[3]. Undecided
 * intervals are halved `depth` more times while the evaluation budget lasts (undecided: 1). */
static int dp_cell_span(dp_cell *g, double t0, const double *f0, double t1, const double *f1, int depth)
{
    double w = t1 - t0 + 64.0 * DBL_EPSILON, L = g->p->r * w, sag = 0.125 * w * w;
    for (int k = 0; k < 3; ++k)
        if (0.5 * (f0[k] + f1[k] - L) > g->tol) return 0;
    /* f[1] is a sinusoid of amplitude a1: within a1 (1 - cos(w / 2)) <= a1 w^2 / 8 of its chord, a
     * bound tighter than the slope's on short intervals */
    if ((f0[1] < f1[1] ? f0[1] : f1[1]) - g->a1 * sag > g->tol) return 0;
    double rho_lo = g->far ? 0.5 * (f0[6] + f1[6] - L) : 0.5 * (f0[0] + f1[0] - L) + g->q->r;
    if (rho_lo > 0.0) {
        /* rho_Q = |y|, y(theta) the offset from Q's axis with |y'|, |y''| <= r_P: |rho''| <= r_P +
         * r_P^2 / rho, so rho is within (r_P + r_P^2 / rho_lo) w^2 / 8 of its chord too */
        double rho2 = (f0[6] < f1[6] ? f0[6] : f1[6]) - (g->p->r + g->p->r * g->p->r / rho_lo) * sag;
        if (rho2 > rho_lo) rho_lo = rho2;
        if (!g->far && rho_lo - g->q->r > g->tol) return 0;
        double irho = 1.0 / rho_lo, Lq = L * g->q->r * irho;
        if (0.5 * (f0[3] + f1[3] - Lq) > g->tol) return 0;
        /* q = c_Q + r_Q y / |y|: |(y / |y|)''| <= |y''| / rho + 3 |y'|^2 / rho^2, so f[3] = ezp.(q - c_P)
         * is within r_Q r_P / rho_lo (1 + 3 r_P / rho_lo) w^2 / 8 of its chord */
        if ((f0[3] < f1[3] ? f0[3] : f1[3]) - g->q->r * g->p->r * irho * (1.0 + 3.0 * g->p->r * irho) * sag > g->tol)
            return 0;
        if (0.5 * (f0[4] + f1[4] - Lq - g->lq * w) > g->tol) return 0;
        /* stationarity f[5] = 0: excluded when f[5] keeps one sign with |f[5]| above its drift */
        double dhi = 0.5 * (f0[2] + f1[2] + L) + g->cut;
        if (f0[5] * f1[5] > 0.0 && 0.5 * (fabs(f0[5]) + fabs(f1[5]) - L - Lq - dhi * w) > g->tol) return 0;
        /* f[5] = (q - x).t_P has f5'' = q''.t_P - 2 q'.u_P - f5, so |f5''| <= M = r_Q r_P / rho_lo (3 + 3
         * r_P / rho_lo) + dhi (the bounds of |q''| and |q'| above, |f5| <= |q - x|). By the mean value
         * theorem f5' = (f5(t1) - f5(t0)) / w somewhere on the interval, so |f5(t1) - f5(t0)| > M w^2
         * keeps f5' from vanishing there: f5 is strictly monotone, and the interval holds no stationary
         * point when both ends have one sign, else exactly one, which the local solve finds
         * (dp_cell_roots) in place of the degree-8 polynomial */
        if (!g->far) {
            double m = g->q->r * g->p->r * irho * (3.0 + 3.0 * g->p->r * irho) + dhi;
            if (fabs(f1[5] - f0[5]) > m * w * w + 2.0 * g->tol) {
                if (f0[5] * f1[5] > 0.0 && fabs(f0[5]) > g->tol && fabs(f1[5]) > g->tol) return 0;
                if (g->nroot < DP_NROOT) {
                    g->root[g->nroot][0] = t0, g->root[g->nroot][1] = t1;
                    ++g->nroot;
                    return 0;
                }
            }
        }
    }
    if (depth == 0 || g->budget <= 0) return 1;
    /* the middle angle's cos and sin: the normalised sum of the ends' (no trigonometric call; the
     * interval is at most pi/4, and the angle carries a few ulps, which the 64 eps added to every
     * width below covers) */
    double tm = 0.5 * (t0 + t1), fm[DP_NVAL], cm = f0[7] + f1[7], sm = f0[8] + f1[8], nm = prox_hypot2(cm, sm);
    dp_cell_vals(g, cm / nm, sm / nm, fm);
    return dp_cell_span(g, t0, f0, tm, fm, depth - 1) || dp_cell_span(g, tm, fm, t1, f1, depth - 1);
}

/* f[5] at the angle th. */
static double dp_cell_f5(dp_cell *g, double th)
{
    double f[DP_NVAL];
    dp_cell_vals(g, cos(th), sin(th), f);
    return f[5];
}

/* The stationary point in [a, b], where f[5] is strictly monotone (dp_cell_span): regula falsi with
 * the Illinois halving, bisection when a secant step leaves the bracket, to the bracket's rounding.
 * Ends of one sign (a root within tol of an end, or beyond it) give the end nearer to zero. */
static double dp_cell_root(dp_cell *g, double a, double b)
{
    double fa = dp_cell_f5(g, a), fb = dp_cell_f5(g, b);
    if (fa == 0.0) return a;
    if (fb == 0.0 || fa * fb > 0.0) return fabs(fb) <= fabs(fa) ? b : a;
    int side = 0;
    for (int it = 0; it < 64 && b - a > 4.0 * DBL_EPSILON * (fabs(a) + fabs(b)); ++it) {
        double x = (a * fb - b * fa) / (fb - fa);
        if (!(x > a && x < b)) x = 0.5 * (a + b);
        double fx = dp_cell_f5(g, x);
        if (fx == 0.0) return x;
        if (fx * fb > 0.0) {
            b = x, fb = fx;
            if (side == 1) fa *= 0.5;
            side = 1;
        } else {
            a = x, fa = fx;
            if (side == -1) fb *= 0.5;
            side = -1;
        }
    }
    return fabs(fa) <= fabs(fb) ? a : b;
}

/* The candidates of the stationary points dp_cell_span located: as dp_cells_closest does for the
 * polynomial's roots. 0 when a partner is degenerate (x on rim Q's axis: the caller solves). */
static int dp_cell_roots(dp_state *s, dp_cell *g)
{
    for (int i = 0; i < g->nroot; ++i) {
        int deg = 0;
        prox_vec3 pa = prox_fcircle_point(g->p, dp_cell_root(g, g->root[i][0], g->root[i][1]));
        prox_vec3 pb = prox_fcircle_closest(g->q, pa, &deg);
        if (deg) return 0;
        dp_consider_pm(s, prox_v3_sub(pa, pb));
        dp_consider_pm(s, prox_v3_cross(dp_tangent(g->p, pa), dp_tangent(g->q, pb)));
    }
    return 1;
}

/* Certified exclusion of a cell, or the location of its minimisers, before its degree-8 solve. At a
 * cell minimiser with value <= cut, p1 on A's rim, p2 on B's, p1 - p2 = phi D, D in A's normal
 * cone at p1 and -D in B's at p2 (the cones of a rim point: alpha e w + beta u, alpha, beta >= 0, u
 * radial). Let x be the point whose
 * partner q on the other rim Q is its closest point: x - q = dn e_Q w_Q + (rho_Q(x) - r_Q) u_Q(q), and
 * x - q (= p1 - p2 when q = p2, = p2 - p1 when q = p1) lies in minus Q's normal cone at q and in P's
 * normal cone at x. Hence dn <= 0 (x on the body side of Q's end plane), rho_Q(x) <= r_Q (x within
 * Q's radius), |x - q| <= cut, e_P w_P.(q - c_P) <= 0 (q on the body side of P's end plane) and
 * (q - x).u_P(x) <= 0. With far, q is the farthest point of Q from x: x - q = dn e_Q w_Q - (rho_Q(x)
 * + r_Q) u_Q(q) meets the same cones with the radial condition always true, and the other four
 * conditions stand. Returns 0 when a grid of the angle of x with the Lipschitz bounds of
 * dp_cell_span proves that no point of rim P meets them all but in intervals where the stationarity
 * is strictly monotone: the cell then holds no minimiser at or below cut but the stationary points of
 * those intervals, which are solved there and added to st (dp_cell_roots). Returns 1 when the cell
 * needs its degree-8 solve. */
static int dp_cell_may(dp_state *st, const prox_fcircle *p, const prox_body *kp, int ep, const prox_fcircle *q,
                       const prox_body *kq, int eq, double cut, double tol, int far)
{
    enum { N = 8, DEPTH = 12, BUDGET = 256 };
    dp_cell g = {.p = p,
                 .q = q,
                 .cut = cut,
                 .tol = tol,
                 .lq = prox_v3_dist(q->c, p->c) + q->r + p->r,
                 .a1 = p->r * prox_v3_norm(prox_v3_cross(kq->cyl.w, p->n)),
                 .budget = BUDGET,
                 .far = far};
    dp_cell_prep(&g, kq->cyl.w, prox_v3_scale(kq->cyl.w, (double)eq), prox_v3_scale(kp->cyl.w, (double)ep));
    /* cos and sin of the grid's angles k pi / 4 (no trigonometric call; within an ulp of the angle,
     * which the 64 eps added to every width covers) */
#define DP_H 0.70710678118654752440 /* sqrt(1/2) */
    static const double gc[N] = {1.0, DP_H, 0.0, -DP_H, -1.0, -DP_H, 0.0, DP_H};
    static const double gs[N] = {0.0, DP_H, 1.0, DP_H, 0.0, -DP_H, -1.0, -DP_H};
#undef DP_H
    double f[2][DP_NVAL], f0[DP_NVAL]; /* the grid's first angle; its current interval's ends, in turn */
    dp_cell_vals(&g, 1.0, 0.0, f0);
    const double *fa = f0;
    for (int k = 1; k <= N; ++k) {
        double *fb = f[k & 1];
        if (k < N) dp_cell_vals(&g, gc[k], gs[k], fb);
        else fb = f0;
        if (dp_cell_span(&g, (k - 1) * (2.0 * PROX_PI / N), fa, k * (2.0 * PROX_PI / N), fb, DEPTH)) return 1;
        fa = fb;
    }
    return g.nroot > 0 && !dp_cell_roots(st, &g);
}

int sup_rcc_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res)
{
    dp_state s = {.a = a, .b = b, .delta = prox_v3_sub(b->c, a->c), .best = INFINITY};
    s.best_d = a->cyl.w;
    double scale = prox_max2(prox_v3_norm(s.delta), prox_max2(a->size, b->size));
    int ok = 1;
    /* points */
    dp_consider_pm(&s, a->cyl.w);
    dp_consider_pm(&s, b->cyl.w);
    dp_consider_pm(&s, prox_v3_cross(a->cyl.w, b->cyl.w));
    /* ridges */
    prox_fcircle ra[2] = {dp_rim(a, -1), dp_rim(a, 1)}, rb[2] = {dp_rim(b, -1), dp_rim(b, 1)}; /* bottom, top */
    dp_band ga[2] = {dp_band_of(&ra[0], b), dp_band_of(&ra[1], b)};
    dp_band gb[2] = {dp_band_of(&rb[0], a), dp_band_of(&rb[1], a)};
    ok = dp_ridge(&s, a, b, rb, gb, PROX_TOL_SEARCH * scale) && ok;
    ok = dp_ridge(&s, b, a, ra, ga, PROX_TOL_SEARCH * scale) && ok;
    /* cells: rim of A at end ea against rim of B at end eb, the lowest bound first (a deep overlap's
     * best cell then excludes the others) */
    prox_fcircle rims[4][2];
    double lbs[4], fars[4][2];
    int ord[4];
    for (int k = 0; k < 4; ++k) {
        rims[k][0] = ra[k & 1], rims[k][1] = rb[(k & 2) >> 1];
        lbs[k] = dp_circle_lb(&rims[k][0], &rims[k][1], &fars[k][0], &fars[k][1]);
        int j = k;
        for (; j > 0 && lbs[ord[j - 1]] > lbs[k]; --j) ord[j] = ord[j - 1];
        ord[j] = k;
    }
    int deferred[4], nd = 0; /* deep cells whose far partners are solved last */
    for (int o = 0; ok && o < 4; ++o) {
        int k = ord[o], ea = k & 1 ? 1 : -1, eb = k & 2 ? 1 : -1;
        prox_fcircle ca = rims[k][0], cb = rims[k][1];
        double far_a = fars[k][0], far_b = fars[k][1], lb = lbs[k];
        double cut = s.best + PROX_TOL_SEARCH * scale; /* a bound within rounding of the best cannot improve it */
        if (lb > cut) continue;
        /* A's point on rim ea, B's on rim eb: each must reach the other's corner band */
        double tol = PROX_TOL_SEARCH * scale;
        if (!dp_reach(&gb[(eb + 1) / 2], a, ea, s.best, tol) || !dp_reach(&ga[(ea + 1) / 2], b, eb, s.best, tol))
            continue;
        prox_vec3 al = prox_v3_scale(a->cyl.w, (double)ea), be = prox_v3_scale(b->cyl.w, (double)-eb);
        if (sup_rim_lune_lb(&ca, al, &cb, be) > cut) continue;
        /* pairs with p2 closest on B's rim to p1: stationary points on A's rim (one degree-8
         * solve); with p1 closest on A's rim: on B's rim. The rest has p1 farthest (>= far_a)
         * or p2 farthest (>= far_b): one solve suffices when either bound exceeds the best;
         * else two, the closest and the farthest partners of A's rim points. */
        if (far_a > cut && !(far_b > cut && ca.r > cb.r)) { /* both serve: the larger rim scanned */
            if (!dp_cell_may(&s, &cb, b, eb, &ca, a, ea, cut, tol, 0)) continue;
            ok = dp_cells_closest(&s, &cb, &ca);
        } else if (far_b > cut) {
            if (!dp_cell_may(&s, &ca, a, ea, &cb, b, eb, cut, tol, 0)) continue;
            ok = dp_cells_closest(&s, &ca, &cb);
        } else { /* a deep overlap: both kinds of partner on B's rim; the far ones after every
                  * other cell, whose values may by then exclude them (far_b > cut) */
            ok = dp_cell_may(&s, &ca, a, ea, &cb, b, eb, cut, tol, 0) ? dp_cells_closest(&s, &ca, &cb) : 1;
            deferred[nd++] = k;
        }
        if (ok < 0) return ok; /* a circle solver failed: PROX_ENUMERIC for the caller */
    }
    for (int i = 0; ok == 1 && i < nd; ++i) {
        int k = deferred[i];
        double cut = s.best + PROX_TOL_SEARCH * scale;
        int ea = k & 1 ? 1 : -1, eb = k & 2 ? 1 : -1;
        if (lbs[k] > cut || fars[k][1] > cut) continue;
        if (!dp_cell_may(&s, &rims[k][0], a, ea, &rims[k][1], b, eb, cut, PROX_TOL_SEARCH * scale, 1)) continue;
        ok = dp_cells_far(&s, &rims[k][0], &rims[k][1]);
        if (ok < 0) return ok;
    }
    res->status = PROX_OK;
    res->sd = -s.best;
    res->normal = s.best_d;
    if (!ok || !(s.best > 0.0)) return 0; /* touching band or an unsettled stratum: global search */
    sup_overlap_answer(a, b, s.best_d, res);
    res->sd_lower = -s.best; /* -phi at the best direction: a lower bound of sd (weak duality) */
    res->certified = 1; /* every stratum enumerated: the depth is proved (prox_body_signed_bounds) */
    return 1;
}
