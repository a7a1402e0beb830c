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
 *            swapped; the remaining (farthest, farthest) pairs have |p1 - p2|^2 >= |p1 - cB|^2 + rB^2.
 * Cells are excluded by lower bounds of the circle-circle distance (centres, planes, spheres); only
 * a cell that could beat the best value found so far is solved (degree 8). A cell or case that cannot
 * be settled returns 0 and the caller runs the global search of sup_engine.c. */
#include "sup_engine.h"

#include "core/circle.h"
#include "core/tol.h"

#include <float.h>

/* Best direction and value so far. */
typedef struct dp_state {
    const prox_body *a, *b;
    prox_vec3 delta;
    double best;
    prox_vec3 best_d;
} dp_state;

static double dp_phi(const dp_state *s, prox_vec3 d)
{
    return prox_body_hc(s->a, d) + prox_body_hc(s->b, d) - prox_v3_dot(d, s->delta);
}

/* Evaluates +-v / |v| (v need not be unit); ignores v = 0. */
static void dp_consider_pm(dp_state *s, prox_vec3 v)
{
    double n = sqrt(prox_v3_norm2(v));
    if (!(n > 0.0)) return;
    v = prox_v3_scale(v, 1.0 / n);
    for (int k = 0; k < 2; ++k, v = prox_v3_neg(v)) {
        double f = dp_phi(s, v);
        if (f < s->best) { s->best = f; s->best_d = v; }
    }
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

/* Lower bound of phi at a minimiser on the ridge of `lat` whose other support point q lies on rim
 * circle c: phi = |p2 - p1| with p1 = q's partner on lat's support segment (radius r from the axis,
 * |axial offset| <= hh). The rim projects off the axis onto an ellipse centred at the projected
 * centre with semi-axes <= r_c, and along the axis onto an interval of half length r_c |w x n_c|. */
static double dp_ridge_lb(const prox_fcircle *c, const prox_body *lat)
{
    const prox_cyl *k = &lat->cyl;
    prox_vec3 d = prox_v3_sub(c->c, lat->c);
    double ax = prox_v3_dot(d, k->w), rho = prox_v3_norm(prox_v3_reject(d, k->w));
    double lb = fmax(rho - c->r - k->r, k->r - rho - c->r);
    lb = fmax(lb, fabs(ax) - c->r * prox_v3_norm(prox_v3_cross(k->w, c->n)) - k->hh);
    return fmax(lb, 0.0);
}

/* Ridge D.w = 0 of cylinder `lat` (its lateral line) against the rims of `rim`: every stationary
 * point q of dist^2(rim, axis of lat) gives D = +-(q - c_lat) projected off w. 0 when degenerate. */
static int dp_ridge(dp_state *s, const prox_body *lat, const prox_body *rim, double tol)
{
    prox_vec3 w = lat->cyl.w;
    for (int e = -1; e <= 1; e += 2) {
        prox_fcircle c = dp_rim(rim, e);
        if (dp_ridge_lb(&c, lat) > s->best + tol) continue;
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
    *dmin = sqrt(fmax(0.0, dd + c->r * c->r - 2.0 * c->r * pd));
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
    lb = fmax(lb, fabs(prox_v3_dot(b->n, d)) - a->r * sn);
    lb = fmax(lb, fabs(prox_v3_dot(a->n, d)) - b->r * sn);
    double amin, amax, bmin, bmax;
    dp_circle_range(a, b->c, &amin, &amax);
    dp_circle_range(b, a->c, &bmin, &bmax);
    lb = fmax(lb, fmax(amin - b->r, b->r - amax));
    lb = fmax(lb, fmax(bmin - a->r, a->r - bmax));
    *far_a = fmax(lb, sqrt(bmin * bmin + a->r * a->r));
    *far_b = fmax(lb, sqrt(amin * amin + b->r * b->r));
    return fmax(lb, 0.0);
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

int sup_rcc_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res)
{
    dp_state s = {.a = a, .b = b, .delta = prox_v3_sub(b->c, a->c), .best = INFINITY};
    s.best_d = a->cyl.w;
    double scale = fmax(prox_v3_norm(s.delta), fmax(a->size, b->size));
    int ok = 1;
    /* points */
    dp_consider_pm(&s, a->cyl.w);
    dp_consider_pm(&s, b->cyl.w);
    dp_consider_pm(&s, prox_v3_cross(a->cyl.w, b->cyl.w));
    /* ridges */
    ok = dp_ridge(&s, a, b, PROX_TOL_SEARCH * scale) && ok;
    ok = dp_ridge(&s, b, a, PROX_TOL_SEARCH * scale) && ok;
    /* cells: rim of A at end ea against rim of B at end eb */
    for (int ea = -1; ok && ea <= 1; ea += 2)
        for (int eb = -1; ok && eb <= 1; eb += 2) {
            prox_fcircle ca = dp_rim(a, ea), cb = dp_rim(b, eb);
            double far_a, far_b, lb = dp_circle_lb(&ca, &cb, &far_a, &far_b);
            double cut = s.best + PROX_TOL_SEARCH * scale; /* a bound within rounding of the best cannot improve it */
            if (lb > cut) continue;
            /* pairs with p2 closest on B's rim to p1: stationary points on A's rim (one degree-8
             * solve); with p1 closest on A's rim: on B's rim. The rest has p1 farthest (>= far_a)
             * or p2 farthest (>= far_b): one solve suffices when either bound exceeds the best. */
            if (far_a > cut) ok = dp_cells_closest(&s, &cb, &ca);
            else if (far_b > cut) ok = dp_cells_closest(&s, &ca, &cb);
            else ok = 0;
            if (ok < 0) return ok; /* a circle solver failed: PROX_ENUMERIC for the caller */
        }
    res->status = PROX_OK;
    res->sd = -s.best;
    res->normal = s.best_d;
    if (!ok || !(s.best > 0.0)) return 0; /* touching band or an unsettled stratum: global search */
    sup_witnesses(a, b, s.best_d, res->sd, &res->p1, &res->p2);
    return 1;
}
