/* Support-function engine: signed distance of two centrally symmetric convex bodies.
 *
 * Source: the projection formulation of Eberly, "Intersection of Cylinders", Secs. 3-4, Eq. (4)
 * (support function of a cylinder) and Eq. (6) (the combined separation function f(D)), turned from
 * a sign test into an optimisation: with phi(D) = h_A(D) + h_B(-D),
 *     disjoint:     distance = max_{|D|<=1} -phi(D)   (duality: distance from Delta to K = A_c + B_c)
 *     overlapping:  depth    = min_{|D|=1}   phi(D)   (distance from Delta to the boundary of K)
 * and in both cases sd = -min_{|D|=1} phi(D). Every evaluated unit D gives a valid bound (a lower
 * bound on the distance, an upper bound on the depth); the search tries to make it tight.
 *
 * phi is piecewise smooth on the sphere. Its kinks are the great circles D.w = 0 ("ridges": w a
 * cylinder axis or a box edge, where |D.w| is not differentiable) and the isolated points D = +-W of
 * a cylinder axis ("cones", where |P D| is not differentiable). A minimiser lies on a stratum:
 *   0-dim: a cone point or the crossing of two ridges (face normals, W_A x W_B, ...): evaluated;
 *   1-dim: on one ridge: sampled, then safeguarded Newton on the angle;
 *   2-dim: inside a cell: Riemannian Newton on the sphere with backtracking.
 * Disjoint pairs have a quasi-convex problem (sublevel sets of phi/|D| below 0 are convex cones),
 * so a local minimum is global; overlapping pairs are not (a small body deep in a big one has one
 * local minimum per face), hence the global sampling of all strata.
 *
 * The bodies and their support functions are the core's (core/body.h: prox_cyl, prox_bframe). For a
 * cylinder pair the caller may pass as a hint the separating direction of the verdict (rcc_sat.c),
 * which is Minkowski portal refinement with a certified bound after Eberly's axis tests, with Eberly's
 * bisection only as a last resort; a separating direction found here (GJK, samples) needs no verdict.
 * The witnesses of a disjoint answer are the exact closest pair of the two support sets along the
 * final normal (sup_witnesses), over a few candidate normals (disjoint_witnesses). */
#include "sup_engine.h"

#include "core/plane2.h"
#include "core/tol.h"

#include <float.h>

#define SUP_TOPK 4
#define SUP_RIDGE_SAMPLES 64

/* ---- single bodies (core/body.h) ---------------------------------------------------------- */

/* d / |d| for directions of moderate length (no overflow possible here). */
static prox_vec3 unit(prox_vec3 d) { return prox_v3_scale(d, 1.0 / sqrt(prox_v3_norm2(d))); }

static double sgn(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

/* Hessian of hc at d applied to v (zero for a box; defined off the kinks). */
static prox_vec3 sup_hess(const prox_body *b, prox_vec3 d, prox_vec3 v)
{
    if (b->kind == PROX_BODY_CYL) {
        prox_vec3 perp = prox_cyl_perp(&b->cyl, d);
        double n = sqrt(prox_v3_norm2(perp));
        if (!(n > 0.0)) return prox_v3(0, 0, 0);
        prox_vec3 p = prox_v3_scale(perp, 1.0 / n);
        prox_vec3 x = prox_v3_mad(prox_v3_mad(v, -prox_v3_dot(v, b->cyl.w), b->cyl.w), -prox_v3_dot(v, p), p);
        return prox_v3_scale(x, b->cyl.r / n);
    }
    if (b->kind == PROX_BODY_SPH) {
        double n = sqrt(prox_v3_norm2(d));
        prox_vec3 u = prox_v3_scale(d, 1.0 / n);
        return prox_v3_scale(prox_v3_mad(v, -prox_v3_dot(v, u), u), b->r / n);
    }
    return prox_v3(0, 0, 0);
}

/* Ridge normals and cone axes of a body. */
static int sup_ridges(const prox_body *b, prox_vec3 out[3])
{
    if (b->kind == PROX_BODY_CYL) { out[0] = b->cyl.w; return 1; }
    if (b->kind == PROX_BODY_BOX) { out[0] = b->box.a[0]; out[1] = b->box.a[1]; out[2] = b->box.a[2]; return 3; }
    return 0;
}

/* ---- the pair search ---------------------------------------------------------------------- */

typedef struct sup_search {
    const prox_body *a, *b;
    prox_vec3 delta;
    double scale;                /* max(|Delta|, sizes) */
    double best_phi;
    prox_vec3 best_d;
    int nk;                      /* top-k distinct starts for the cell search */
    double kphi[SUP_TOPK];
    prox_vec3 kd[SUP_TOPK];
} sup_search;

static double phi_eval(const sup_search *s, prox_vec3 d)
{
    return prox_body_hc(s->a, d) + prox_body_hc(s->b, d) - prox_v3_dot(d, s->delta);
}
/* Gradient of phi: support point of K minus Delta (a subgradient on the kinks). */
static prox_vec3 phi_grad(const sup_search *s, prox_vec3 d)
{
    return prox_v3_sub(prox_v3_add(prox_body_pc(s->a, d), prox_body_pc(s->b, d)), s->delta);
}
static prox_vec3 phi_hess(const sup_search *s, prox_vec3 d, prox_vec3 v)
{
    return prox_v3_add(sup_hess(s->a, d, v), sup_hess(s->b, d, v));
}

/* Records a unit direction with its value: global best and the list of distinct good starts. */
static void record(sup_search *s, prox_vec3 d, double f)
{
    if (f < s->best_phi) { s->best_phi = f; s->best_d = d; }
    for (int i = 0; i < s->nk; ++i)
        if (prox_v3_dot(d, s->kd[i]) > 1.0 - PROX_TOL_SAME_START) {
            if (f < s->kphi[i]) { s->kphi[i] = f; s->kd[i] = d; }
            return;
        }
    int slot = s->nk < SUP_TOPK ? s->nk++ : -1;
    if (slot < 0) { /* replace the worst if better */
        slot = 0;
        for (int i = 1; i < SUP_TOPK; ++i)
            if (s->kphi[i] > s->kphi[slot]) slot = i;
        if (!(f < s->kphi[slot])) return;
    }
    s->kphi[slot] = f;
    s->kd[slot] = d;
}

static double consider(sup_search *s, prox_vec3 d)
{
    double n = sqrt(prox_v3_norm2(d));
    if (!(n > 0.0)) return INFINITY;
    d = prox_v3_scale(d, 1.0 / n);
    double f = phi_eval(s, d);
    record(s, d, f);
    return f;
}

/* 0-dim strata: cone points +-W and crossings +-(w_i x w_j) of ridges of both bodies. */
static void search_points(sup_search *s)
{
    prox_vec3 r[6];
    int n = sup_ridges(s->a, r);
    n += sup_ridges(s->b, r + n);
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            prox_vec3 x = prox_v3_cross(r[i], r[j]);
            if (prox_v3_norm(x) < PROX_TOL_PARALLEL) continue; /* parallel ridges: the 1-dim search covers it */
            consider(s, x);
            consider(s, prox_v3_neg(x));
        }
    const prox_body *bs[2] = {s->a, s->b};
    for (int k = 0; k < 2; ++k)
        if (bs[k]->kind == PROX_BODY_CYL) {
            consider(s, bs[k]->cyl.w);
            consider(s, prox_v3_neg(bs[k]->cyl.w));
        }
    if (prox_v3_norm2(s->delta) > 0.0) {
        prox_vec3 u = prox_v3_normalize(s->delta);
        consider(s, u);
        consider(s, prox_v3_neg(u));
    }
}

/* The point at angle th of the great circle cos(th) u + sin(th) v. */
static prox_vec3 circle_at(prox_vec3 u, prox_vec3 v, double th)
{
    return prox_v3_add(prox_v3_scale(u, cos(th)), prox_v3_scale(v, sin(th)));
}

/* Kinks of phi along the circle cos(th) u + sin(th) v inside (lo, hi): its crossings with the other
 * ridges D.w = 0. Newton cannot converge onto a kink (it bisected ~45 times there), so each kink in
 * the bracket is settled first from three values 1e-7 rad apart: a local minimum at the kink is
 * recorded and ends the refinement (1), otherwise the bracket shrinks to the side that descends. */
static int ridge_kinks(sup_search *s, prox_vec3 u, prox_vec3 v, double *lo, double *hi, double *th)
{
    prox_vec3 r[6];
    int n = sup_ridges(s->a, r);
    n += sup_ridges(s->b, r + n);
    const double dl = PROX_TOL_KINK_PROBE, noise = PROX_TOL_PHI_ROUND * s->scale; /* noise: rounding of phi */
    for (int i = 0; i < n; ++i) {
        double ru = prox_v3_dot(u, r[i]), rv = prox_v3_dot(v, r[i]);
        if (fabs(ru) + fabs(rv) < PROX_TOL_PARALLEL) continue; /* this ridge itself (or parallel to it) */
        double tk = atan2(-ru, rv);
        for (int k = 0; k < 3; ++k) {
            double t = tk + (k - 1) * PROX_PI;
            while (t - 2.0 * PROX_PI > *lo) t -= 2.0 * PROX_PI;
            while (t < *lo) t += 2.0 * PROX_PI;
            if (!(t > *lo + dl && t < *hi - dl)) continue;
            prox_vec3 d = circle_at(u, v, t);
            double f = phi_eval(s, d), fl = phi_eval(s, circle_at(u, v, t - dl)), fr = phi_eval(s, circle_at(u, v, t + dl));
            record(s, d, f);
            /* Differences within rounding of phi decide nothing: in a very flat stretch (a rim
             * seen edge-on) a kink that is not a minimum looked like one and ended the search. */
            if (fl > f + noise && fr > f + noise) return 1;
            if (fabs(fl - fr) <= noise) continue;
            if (fl < fr) *hi = t; else *lo = t;
            if (!(*th > *lo && *th < *hi)) *th = 0.5 * (*lo + *hi);
        }
    }
    return 0;
}

/* Safeguarded Newton on phi(theta) along the great circle cos(th) u + sin(th) v in [lo, hi]. */
static void ridge_refine(sup_search *s, prox_vec3 u, prox_vec3 v, double lo, double hi, double th)
{
    if (ridge_kinks(s, u, v, &lo, &hi, &th)) return;
    for (int it = 0; it < 80; ++it) {
        double c = cos(th), sn = sin(th);
        prox_vec3 d = prox_v3_add(prox_v3_scale(u, c), prox_v3_scale(v, sn));
        prox_vec3 dt = prox_v3_add(prox_v3_scale(u, -sn), prox_v3_scale(v, c));
        double f = phi_eval(s, d);
        record(s, d, f);
        double g1 = prox_v3_dot(phi_grad(s, d), dt);
        double g2 = prox_v3_dot(dt, phi_hess(s, d, dt)) - f;
        if (g1 > 0.0) hi = th; else if (g1 < 0.0) lo = th; else return;
        if (g2 > 0.0 && 0.5 * g1 * g1 / g2 <= PROX_TOL_DECREMENT * s->scale) return; /* decrement: converged */
        double tn = g2 > 0.0 ? th - g1 / g2 : 0.5 * (lo + hi);
        if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
        if (fabs(tn - th) <= PROX_TOL_ANGLE * (1.0 + fabs(th)) || hi - lo <= PROX_TOL_ANGLE) return;
        th = tn;
    }
}

/* 1-dim strata: each ridge circle, sampled (64 points) with the slope of phi along it, every
 * discrete local minimum refined, and so is every interval whose slope turns from falling to
 * rising: a valley between two samples that no sample's value shows.  Sweeps of overlapping
 * BOX-RCC pairs found 16 samples by value alone missing the deepest valley for ~6 in 10^4 pairs (a
 * depth up to 2e-3 x scale too large); now ~1 in 10^6 (docs/algorithms/sat.md 2 (f)). */
static void search_ridge(sup_search *s, prox_vec3 w)
{
    prox_vec3 u = prox_v3_any_perp(w), v = prox_v3_cross(w, u);
    double f[SUP_RIDGE_SAMPLES], g[SUP_RIDGE_SAMPLES];
    const double step = 2.0 * PROX_PI / SUP_RIDGE_SAMPLES;
    for (int k = 0; k < SUP_RIDGE_SAMPLES; ++k) {
        double c = cos(k * step), sn = sin(k * step);
        prox_vec3 d = prox_v3_add(prox_v3_scale(u, c), prox_v3_scale(v, sn));
        f[k] = consider(s, d);
        g[k] = prox_v3_dot(phi_grad(s, d), prox_v3_add(prox_v3_scale(u, -sn), prox_v3_scale(v, c)));
    }
    for (int k = 0; k < SUP_RIDGE_SAMPLES; ++k) {
        int kp = (k + SUP_RIDGE_SAMPLES - 1) % SUP_RIDGE_SAMPLES, kn = (k + 1) % SUP_RIDGE_SAMPLES;
        if (f[k] <= f[kp] && f[k] <= f[kn]) ridge_refine(s, u, v, (k - 1) * step, (k + 1) * step, k * step);
        /* also beside a discrete minimum: a second valley can hide in the next interval */
        if (g[k] < 0.0 && g[kn] > 0.0) ridge_refine(s, u, v, k * step, (k + 1) * step, (k + 0.5) * step);
    }
}

/* Centre of the subdifferential of phi at d: near a cone point of a cylinder (|P D| tiny) the
 * radial part of its support point is dropped (it is arbitrary there). */
static prox_vec3 phi_grad_centre(const sup_search *s, prox_vec3 d)
{
    prox_vec3 g = prox_v3_neg(s->delta);
    const prox_body *bs[2] = {s->a, s->b};
    for (int k = 0; k < 2; ++k) {
        const prox_body *b = bs[k];
        if (b->kind == PROX_BODY_CYL) {
            double dw = prox_v3_dot(d, b->cyl.w);
            prox_vec3 perp = prox_cyl_perp(&b->cyl, d);
            double n = sqrt(prox_v3_norm2(perp));
            g = prox_v3_mad(g, b->cyl.hh * sgn(dw), b->cyl.w);
            if (n > PROX_TOL_CONE_PERP) g = prox_v3_mad(g, b->cyl.r / n, perp);
        } else g = prox_v3_add(g, prox_body_pc(b, d));
    }
    return g;
}

/* 1 when d is within PROX_TOL_KINK rad of a ridge or PROX_TOL_CONE of a cone point of either body. */
static int near_kink(const sup_search *s, prox_vec3 d)
{
    const prox_body *bs[2] = {s->a, s->b};
    for (int k = 0; k < 2; ++k) {
        const prox_body *b = bs[k];
        if (b->kind == PROX_BODY_CYL) {
            double dw = fabs(prox_v3_dot(d, b->cyl.w));
            if (dw < PROX_TOL_KINK || dw > 1.0 - PROX_TOL_CONE) return 1;
        } else if (b->kind == PROX_BODY_BOX)
            for (int i = 0; i < 3; ++i)
                if (fabs(prox_v3_dot(d, b->box.a[i])) < PROX_TOL_KINK) return 1;
    }
    return 0;
}

/* Leaves a kink (cone point or ridge) where Newton stalls: steps of decreasing length along minus
 * the tangential centre subgradient; 1 when phi decreased. */
static int escape_kink(sup_search *s, prox_vec3 *d, double *f)
{
    prox_vec3 g = phi_grad_centre(s, *d);
    prox_vec3 gt = prox_v3_mad(g, -prox_v3_dot(g, *d), *d);
    double gn = sqrt(prox_v3_norm2(gt));
    if (!(gn > 0.0)) return 0;
    for (double th = 0.1; th > 1e-10; th *= 0.1) {
        prox_vec3 dn = unit(prox_v3_mad(*d, -th / gn, gt));
        double fn = phi_eval(s, dn);
        if (fn < *f) { *d = dn; *f = fn; record(s, dn, fn); return 1; }
    }
    return 0;
}

/* One Newton (or steepest-descent) step on the tangent plane with backtracking; returns the
 * accepted step length, 0 when no decrease was found. */
static double newton_step(sup_search *s, prox_vec3 *dp, double *fp)
{
    prox_vec3 d = *dp;
    double f = *fp;
    prox_vec3 t1 = prox_v3_any_perp(d), t2 = prox_v3_cross(d, t1);
    prox_vec3 g = phi_grad(s, d);
    double g1 = prox_v3_dot(g, t1), g2 = prox_v3_dot(g, t2);
    prox_vec3 h1 = phi_hess(s, d, t1), h2 = phi_hess(s, d, t2);
    double a = prox_v3_dot(t1, h1) - f, b = prox_v3_dot(t1, h2), c = prox_v3_dot(t2, h2) - f;
    double det = a * c - b * b, x1, x2;
    if (a > 0.0 && det > 0.0) {
        x1 = -(c * g1 - b * g2) / det;
        x2 = -(a * g2 - b * g1) / det;
        /* Newton decrement below rounding of phi: converged (no line search needed). */
        if (-0.5 * (g1 * x1 + g2 * x2) <= PROX_TOL_DECREMENT * s->scale) return 0.0;
    } else { /* not locally convex: steepest descent, length scaled by |phi| */
        double sc = fabs(f) > 0.0 ? fabs(f) : 1.0;
        x1 = -g1 / sc;
        x2 = -g2 / sc;
    }
    double len = hypot(x1, x2);
    if (!(len > 0.0)) return 0.0;
    if (len > 0.5) { x1 *= 0.5 / len; x2 *= 0.5 / len; len = 0.5; }
    for (int ls = 0; ls < 14; ++ls) {
        prox_vec3 dn = unit(prox_v3_add(d, prox_v3_add(prox_v3_scale(t1, x1), prox_v3_scale(t2, x2))));
        double fn = phi_eval(s, dn);
        if (fn < f) { *dp = dn; *fp = fn; record(s, dn, fn); return len; }
        x1 *= 0.5; x2 *= 0.5; len *= 0.5;
    }
    return 0.0;
}

/* 2-dim strata: Riemannian Newton on the unit sphere from d, with backtracking on phi. The
 * Riemannian Hessian of a degree-1 homogeneous phi is T^T H T - phi I on the tangent plane T.
 * Where it stalls (on a kink the minimiser is not at) it escapes along the centre subgradient. */
static void cell_newton(sup_search *s, prox_vec3 d)
{
    double f = phi_eval(s, d);
    int escapes = 0;
    for (int it = 0; it < 40; ++it) {
        double len = newton_step(s, &d, &f);
        if (len < PROX_TOL_STEP) {
            if (!near_kink(s, d) || escapes++ >= 3 || !escape_kink(s, &d, &f)) break;
        }
    }
}

/* Fixed global samples: the 26 directions of the cube's faces, edges and corners. */
static void search_samples(sup_search *s)
{
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k)
                if (i || j || k) consider(s, prox_v3(i, j, k));
}

/* ---- GJK: a separating direction where sampling finds none ------------------------------------ */

/* The foot of the origin on the affine hull of a vertex (m = 1), an edge (2) or a triangle (3),
 * computed so that its direction is accurate: perpendicular to the edge to rounding (a second
 * rejection), or along the triangle's normal, a cross product free of cancellation.  For a long
 * feature passing close to the origin the barycentric combination carries an error of
 * eps |feature| in every direction, and phi, which is kinked across the feature, would lose
 * |feature| times its angle. */
static prox_vec3 face_foot(const prox_vec3 *p, int m)
{
    if (m == 1) return p[0];
    prox_vec3 e = prox_v3_sub(p[1], p[0]);
    if (m == 2) {
        double ee = prox_v3_norm2(e);
        prox_vec3 v = prox_v3_mad(p[0], -prox_v3_dot(p[0], e) / ee, e);
        return prox_v3_mad(v, -prox_v3_dot(v, e) / ee, e);
    }
    prox_vec3 nrm = prox_v3_cross(e, prox_v3_sub(p[2], p[0]));
    return prox_v3_scale(nrm, prox_v3_dot(p[0], nrm) / prox_v3_norm2(nrm));
}

/* Closest point v to the origin of the hull of the n <= 4 points p (Johnson's distance
 * subalgorithm, by enumeration): the closest point lies in the relative interior of one face of the
 * simplex, where it is the affine projection of the origin with positive barycentric coordinates,
 * so it is the nearest such projection over all faces.  That face's vertices replace p.  Returns 1
 * when the origin is inside the tetrahedron (n = 4, all four coordinates positive). */
static int simplex_closest(prox_vec3 p[4], int *n, prox_vec3 *v)
{
    double best = INFINITY;
    int best_mask = 1, inside = 0;
    for (int mask = 1; mask < (1 << *n); ++mask) {
        prox_vec3 q[4], e[3];
        int m = 0;
        for (int i = 0; i < *n; ++i)
            if (mask >> i & 1) q[m++] = p[i];
        /* x = q0 + sum mu_i (q_i - q0), G mu = r, G_ij = e_i.e_j, r_i = -e_i.q0 (elimination) */
        double G[3][4] = {{0}}, mu[3] = {0, 0, 0};
        for (int i = 1; i < m; ++i) e[i - 1] = prox_v3_sub(q[i], q[0]);
        for (int i = 0; i < m - 1; ++i) {
            for (int j = 0; j < m - 1; ++j) G[i][j] = prox_v3_dot(e[i], e[j]);
            G[i][3] = -prox_v3_dot(e[i], q[0]);
        }
        int ok = 1;
        for (int c = 0; c < m - 1 && ok; ++c) { /* Gauss on a symmetric positive semidefinite G */
            if (!(G[c][c] > 1e-24 * (G[0][0] + 1e-300))) ok = 0;
            for (int r = c + 1; r < m - 1 && ok; ++r) {
                double f = G[r][c] / G[c][c];
                for (int k = c; k < 4; ++k) G[r][k] -= f * G[c][k];
            }
        }
        if (!ok) continue; /* a degenerate face: its hull is covered by its sub-faces */
        for (int c = m - 2; c >= 0; --c) {
            double t = G[c][3];
            for (int k = c + 1; k < m - 1; ++k) t -= G[c][k] * mu[k];
            mu[c] = t / G[c][c];
        }
        double l0 = 1.0;
        int pos = 1;
        for (int i = 0; i < m - 1; ++i) l0 -= mu[i], pos &= mu[i] > 0.0;
        if (!(pos && l0 > 0.0)) continue;
        if (m == 4) { inside = 1; best_mask = mask; *v = prox_v3(0, 0, 0); break; }
        prox_vec3 x = q[0];
        for (int i = 0; i < m - 1; ++i) x = prox_v3_mad(x, mu[i], e[i]);
        double xx = prox_v3_norm2(x);
        if (xx < best) { best = xx; best_mask = mask; *v = x; }
    }
    int m = 0;
    for (int i = 0; i < *n; ++i)
        if (best_mask >> i & 1) p[m++] = p[i];
    *n = m;
    if (!inside) *v = face_foot(p, m);
    return inside;
}

/* GJK (Gilbert, Johnson & Keerthi 1988) on P = A_c + B_c - Delta, whose support point in D is
 * phi_grad(D) and support function phi(D): the origin is in P iff the bodies overlap, and for a
 * disjoint pair the point v of P nearest the origin gives the minimiser D = -v/|v| of phi.  Returns 1
 * for a disjoint pair (a separating direction, phi < 0, recorded), iterating on until the upper
 * bound |v| and the lower bound -phi(D) meet within a few ulps of the scale (exact for polytopes in
 * finitely many steps; for curved bodies the Newton searches refine).  Returns 0 when the origin was
 * enclosed, came within rounding of P, or progress stalled (overlapping or touching pairs).  Every
 * direction tried is recorded.  It finds the narrow cone of separating directions of a near-touching
 * disjoint pair that the fixed samples miss, and the vertex contacts of boxes, where phi is linear in
 * each cell and the sphere Newton crawls. */
static int gjk_separate(sup_search *s)
{
    prox_vec3 p[4] = {prox_v3_neg(s->delta)}, v = p[0]; /* the point of P at both centres */
    int n = 1, separated = 0;
    double tol = PROX_TOL_SNAP * s->scale, floor2 = 256.0 * tol * tol;
    for (int it = 0; it < 128; ++it) {
        double vv = prox_v3_norm2(v);
        if (!(vv > floor2)) return separated;
        prox_vec3 d = prox_v3_scale(v, -1.0 / sqrt(vv));
        double f = phi_eval(s, d);
        record(s, d, f);
        separated |= f < 0.0;
        if (separated && sqrt(vv) + f <= tol) return 1; /* |v| = -phi(d) to rounding: converged */
        prox_vec3 w = phi_grad(s, d);
        for (int i = 0; i < n; ++i)
            if (prox_v3_norm2(prox_v3_sub(w, p[i])) <= floor2) return separated; /* no new point */
        p[n++] = w;
        if (simplex_closest(p, &n, &v)) return 0;
        if (!(prox_v3_norm2(v) < vv)) return separated; /* no progress (rounding) */
    }
    return separated;
}

/* ---- witness points ------------------------------------------------------------------------ */

/* A support set: point (dim 0), segment (dim 1: c +- s0 e0), disk (c, normal n, radius rad) or
 * rectangle (c + x e0 + y e1, |x| <= s0, |y| <= s1). */
typedef struct sup_face {
    int dim, disk;
    prox_vec3 c, e0, e1, n;
    double s0, s1, rad;
} sup_face;

static double clampd(double x, double m) { return x < -m ? -m : (x > m ? m : x); }

/* Support set of body b in unit direction d (absolute position), near-faces within ftol included
 * (|sin| of the angle between d and the face normal, or d and the side). */
static sup_face face_of_tol(const prox_body *b, prox_vec3 d, double ftol)
{
    sup_face f = {0};
    if (b->kind == PROX_BODY_CYL) {
        double dw = prox_v3_dot(d, b->cyl.w);
        prox_vec3 perp = prox_cyl_perp(&b->cyl, d);
        double pn = prox_v3_norm(perp);
        if (pn <= ftol) {
            f.dim = 2; f.disk = 1; f.n = b->cyl.w; f.rad = b->cyl.r;
            f.c = prox_v3_mad(b->c, dw >= 0.0 ? b->cyl.hh : -b->cyl.hh, b->cyl.w);
        } else if (fabs(dw) <= ftol) {
            f.dim = 1; f.e0 = b->cyl.w; f.s0 = b->cyl.hh;
            f.c = prox_v3_mad(b->c, b->cyl.r / pn, perp);
        } else f.c = prox_v3_add(b->c, prox_body_pc(b, d));
        return f;
    }
    f.c = b->c;
    if (b->kind == PROX_BODY_SPH) { f.c = prox_v3_mad(b->c, b->r, d); return f; }
    for (int i = 0; i < 3; ++i) {
        double di = prox_v3_dot(d, b->box.a[i]);
        if (fabs(di) <= ftol && f.dim < 2) {
            if (f.dim == 0) { f.e0 = b->box.a[i]; f.s0 = b->box.h[i]; }
            else { f.e1 = b->box.a[i]; f.s1 = b->box.h[i]; }
            f.dim++;
        } else f.c = prox_v3_mad(f.c, di >= 0.0 ? b->box.h[i] : -b->box.h[i], b->box.a[i]);
    }
    return f;
}

/* The support set with near-faces within PROX_TOL_FACE (MCNP decks print directions to ~10 digits). */
static sup_face face_of(const prox_body *b, prox_vec3 d) { return face_of_tol(b, d, PROX_TOL_FACE); }

/* Nearest point of a support set to x. */
static prox_vec3 face_proj(const sup_face *f, prox_vec3 x)
{
    prox_vec3 r = prox_v3_sub(x, f->c);
    if (f->dim == 0) return f->c;
    if (f->disk) {
        prox_vec3 q = prox_v3_mad(r, -prox_v3_dot(r, f->n), f->n);
        double qn = prox_v3_norm(q);
        if (qn > f->rad) q = prox_v3_scale(q, f->rad / qn);
        return prox_v3_add(f->c, q);
    }
    prox_vec3 p = prox_v3_mad(f->c, clampd(prox_v3_dot(r, f->e0), f->s0), f->e0);
    if (f->dim == 2) p = prox_v3_mad(p, clampd(prox_v3_dot(r, f->e1), f->s1), f->e1);
    return p;
}

/* ---- exact closest pair of two support sets, in the plane perpendicular to n -------------------- */

/* Points of that plane (coordinates along u, v): core/plane2.h. */
typedef prox_v2 v2;

/* A support set seen along n: a convex polygon of nv vertices in cyclic order (1 a point, 2 a
 * segment, 4 a rectangle) or a disk (centre q, radius R). */
typedef struct set2 {
    int nv, disk;
    v2 v[4], q;
    double R;
} set2;

/* The plane's frame: origin o, unit u, v perpendicular to n. */
typedef struct frame2 {
    prox_vec3 o, u, v;
} frame2;

static v2 to2(const frame2 *F, prox_vec3 x)
{
    prox_vec3 d = prox_v3_sub(x, F->o);
    v2 r = {prox_v3_dot(d, F->u), prox_v3_dot(d, F->v)};
    return r;
}

static set2 face_2d(const frame2 *F, const sup_face *f)
{
    set2 s = {0};
    if (f->disk) {
        s.disk = 1;
        s.q = to2(F, f->c);
        s.R = f->rad;
        return s;
    }
    if (f->dim == 0) {
        s.nv = 1;
        s.v[0] = to2(F, f->c);
    } else if (f->dim == 1) {
        s.nv = 2;
        s.v[0] = to2(F, prox_v3_mad(f->c, -f->s0, f->e0));
        s.v[1] = to2(F, prox_v3_mad(f->c, f->s0, f->e0));
    } else {
        static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
        s.nv = 4;
        for (int i = 0; i < 4; ++i)
            s.v[i] = to2(F, prox_v3_mad(prox_v3_mad(f->c, sx[i] * f->s0, f->e0), sy[i] * f->s1, f->e1));
    }
    return s;
}

/* Closest point of a polygon set to q (q itself when inside). */
static v2 poly2_closest(const set2 *P, v2 q) { return prox_v2_poly_closest(P->v, P->nv, q); }

/* Closest pair of two convex polygon sets: a pair of disjoint convex polygons has a closest pair with
 * a vertex of one of them; overlapping ones have a vertex inside the other or two crossing edges. */
static void poly2_pair(const set2 *P, const set2 *Q, v2 *x, v2 *y)
{
    double bd = INFINITY;
    for (int i = 0; i < P->nv; ++i) prox_v2_pair_offer(P->v[i], poly2_closest(Q, P->v[i]), x, y, &bd);
    for (int j = 0; j < Q->nv; ++j) prox_v2_pair_offer(poly2_closest(P, Q->v[j]), Q->v[j], x, y, &bd);
    int ep = P->nv == 2 ? 1 : (P->nv == 4 ? 4 : 0), eq = Q->nv == 2 ? 1 : (Q->nv == 4 ? 4 : 0);
    for (int i = 0; i < ep; ++i)
        for (int j = 0; j < eq; ++j) {
            v2 a = P->v[i], b = P->v[(i + 1) % P->nv], c = Q->v[j], d = Q->v[(j + 1) % Q->nv];
            double d1 = prox_v2_cross(prox_v2_sub(b, a), prox_v2_sub(c, a)), d2 = prox_v2_cross(prox_v2_sub(b, a), prox_v2_sub(d, a));
            double d3 = prox_v2_cross(prox_v2_sub(d, c), prox_v2_sub(a, c)), d4 = prox_v2_cross(prox_v2_sub(d, c), prox_v2_sub(b, c));
            if (d1 * d2 < 0.0 && d3 * d4 < 0.0) { /* proper crossing */
                v2 z = prox_v2_mad(a, d3 / (d3 - d4), prox_v2_sub(b, a));
                prox_v2_pair_offer(z, z, x, y, &bd);
            }
        }
}

/* Closest pair (x in S, y in T) of two support sets seen along n. The distance from a convex set to a
 * disk is its distance to the centre less the radius, attained at the set's point closest to the
 * centre. */
static void set2_pair(const set2 *S, const set2 *T, v2 *x, v2 *y)
{
    if (!S->disk && !T->disk) { poly2_pair(S, T, x, y); return; }
    if (S->disk && T->disk) {
        v2 e = prox_v2_sub(T->q, S->q);
        double L = prox_v2_norm(e);
        if (!(L > 0.0)) { *x = *y = S->q; return; } /* concentric: the common centre */
        /* along the centre line S covers [-R_S, R_S], T covers [L - R_T, L + R_T] */
        double lo = fmax(-S->R, L - T->R), hi = fmin(S->R, L + T->R);
        if (lo <= hi) { *x = *y = prox_v2_mad(S->q, 0.5 * (lo + hi) / L, e); return; }
        *x = prox_v2_mad(S->q, S->R / L, e);
        *y = prox_v2_mad(T->q, -T->R / L, e);
        return;
    }
    const set2 *P = S->disk ? T : S, *D = S->disk ? S : T;
    v2 p = poly2_closest(P, D->q), dq = prox_v2_sub(p, D->q), d;
    double l = prox_v2_norm(dq);
    d = l > D->R ? prox_v2_mad(D->q, D->R / l, dq) : p;
    *x = S->disk ? d : p;
    *y = S->disk ? p : d;
}

/* The point of support set f seen at X: lifted onto the set's plane and projected into the set. */
static prox_vec3 lift2(const frame2 *F, const sup_face *f, v2 X)
{
    return face_proj(f, prox_v3_mad(prox_v3_mad(F->o, X.x, F->u), X.y, F->v));
}

/* Witness points. Disjoint pairs: the closest pair of the two support sets. The sets lie in planes
 * perpendicular to n (a disk or a side line supports exactly on a kink, where the search snaps the
 * direction), so the pair closest along n is the pair closest in 3D: solved exactly in the plane. A
 * near-face (within PROX_TOL_FACE of a kink, not snapped) is tilted by less than that: it is tried as
 * the face and as its extreme point (sets_pair); the pair is then polished by exact projections onto
 * the solids (prox_body_closest), which never increase |p2 - p1| and keep p1 in A, p2 in B. Overlapping pairs: p2 - p1 as close to sd n as the sets allow
 * (the closest pair of A's set and B's set moved by -sd n). */
/* The closest pair of support sets fa (of a) and fb (of b) along n, polished; returns |p2 - p1|. */
static double set_pair(const prox_body *a, const prox_body *b, const sup_face *fa, const sup_face *fb, prox_vec3 n,
                       prox_vec3 *p1, prox_vec3 *p2)
{
    frame2 F = {fa->c, prox_v3_any_perp(n), {0, 0, 0}};
    F.v = prox_v3_cross(n, F.u);
    set2 sa = face_2d(&F, fa), sb = face_2d(&F, fb);
    v2 X = {0, 0}, Y = {0, 0};
    set2_pair(&sa, &sb, &X, &Y);
    prox_vec3 x = lift2(&F, fa, X), y = lift2(&F, fb, Y);
    double d = prox_v3_dist(x, y);
    for (int it = 0; it < 8; ++it) { /* polish: alternating exact projections onto the solids */
        prox_vec3 yn = prox_body_closest(b, x), xn = prox_body_closest(a, yn);
        double dn = prox_v3_dist(xn, yn);
        if (!(dn < d)) break;
        x = xn, y = yn, d = dn;
    }
    *p1 = x;
    *p2 = y;
    return d;
}

/* The same over the readings of each support set: a near-face tilted by more than rounding
 * (PROX_TOL_NOISE) but within PROX_TOL_FACE is tried both as the face and as its one extreme point.
 * As a face its lift carries the tilt x radius (4e-11 on a disk facing a disk tilted by 5e-11: the
 * middle of the overlap is not the lowest point of the tilted disk); as a point it is exact. */
static double sets_pair(const prox_body *a, const prox_body *b, prox_vec3 n, prox_vec3 *p1, prox_vec3 *p2)
{
    sup_face fa[2] = {face_of(a, n), face_of_tol(a, n, PROX_TOL_NOISE)};
    sup_face fb[2] = {face_of(b, prox_v3_neg(n)), face_of_tol(b, prox_v3_neg(n), PROX_TOL_NOISE)};
    int na = fa[1].dim != fa[0].dim ? 2 : 1, nb = fb[1].dim != fb[0].dim ? 2 : 1;
    double best = INFINITY;
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j) {
            prox_vec3 x, y;
            double d = set_pair(a, b, &fa[i], &fb[j], n, &x, &y);
            if (d < best) best = d, *p1 = x, *p2 = y;
        }
    return best;
}

/* Overlapping pairs: support sets fa (of a along n) and fb (of b along -n) lie in two planes
 * perpendicular to n, -sd apart along n at the minimiser; seen along n (in the plane of the frame)
 * their shadows meet, and a common point of the shadows lifted onto each set is a pair with
 * p2 - p1 = sd n up to the planes' gap. Exact in the plane (set2_pair: points, segments, disks,
 * rectangles), no iteration. Returns |p2 - p1 - sd n|. */
static double overlap_set_pair(const sup_face *fa, const sup_face *fb, prox_vec3 n, double sd, prox_vec3 *p1,
                               prox_vec3 *p2)
{
    frame2 F = {fa->c, prox_v3_any_perp(n), {0, 0, 0}};
    F.v = prox_v3_cross(n, F.u);
    set2 sa = face_2d(&F, fa), sb = face_2d(&F, fb);
    v2 X = {0, 0}, Y = {0, 0};
    set2_pair(&sa, &sb, &X, &Y);
    *p1 = lift2(&F, fa, X);
    *p2 = lift2(&F, fb, Y);
    return prox_v3_norm(prox_v3_mad(prox_v3_sub(*p2, *p1), -sd, n));
}

/* Overlapping pairs by alternating projections between the sets (A's set and B's set moved by
 * -sd n); two segments by their exact closest pair. Returns |p2 - p1 - sd n|. */
static double overlap_alternating(const prox_body *a, const prox_body *b, prox_vec3 n, double sd, prox_vec3 *p1,
                                  prox_vec3 *p2);

void sup_witnesses(const prox_body *a, const prox_body *b, prox_vec3 n, double sd, prox_vec3 *p1, prox_vec3 *p2)
{
    if (sd > 0.0) {
        sets_pair(a, b, n, p1, p2);
        return;
    }
    /* the shadows of each reading of the support sets (exact and near-faces, as sets_pair), then
     * alternating projections unless a shadow pair is already exact to PROX_TOL_SEARCH; the pair
     * closest to p2 - p1 = sd n is kept */
    double best = INFINITY;
    sup_face fa[2] = {face_of(a, n), face_of_tol(a, n, PROX_TOL_NOISE)};
    sup_face fb[2] = {face_of(b, prox_v3_neg(n)), face_of_tol(b, prox_v3_neg(n), PROX_TOL_NOISE)};
    int na = fa[1].dim != fa[0].dim ? 2 : 1, nb = fb[1].dim != fb[0].dim ? 2 : 1;
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j) {
            prox_vec3 x, y;
            double e = overlap_set_pair(&fa[i], &fb[j], n, sd, &x, &y);
            if (e < best) best = e, *p1 = x, *p2 = y;
        }
    if (best <= PROX_TOL_SEARCH * (prox_v3_maxabs(*p1) + prox_v3_maxabs(*p2) + fabs(sd))) return;
    prox_vec3 x, y;
    if (overlap_alternating(a, b, n, sd, &x, &y) < best) *p1 = x, *p2 = y;
}

prox_vec3 sup_consistent_normal(prox_vec3 n, double sd, prox_vec3 p1, prox_vec3 p2)
{
    prox_vec3 m = prox_v3_sub(p1, p2);
    double mn = prox_v3_norm(m);
    if (!(mn > 0.0) || sd > 0.0) return n;
    prox_vec3 u = prox_v3_scale(m, 1.0 / mn);
    if (!(prox_v3_dot(u, n) > 1.0 - PROX_TOL_NORMAL_AGREE)) return n; /* not the same contact */
    double en = prox_v3_norm(prox_v3_mad(m, sd, n)), eu = fabs(mn + sd);
    return eu < en ? u : n;
}

static double overlap_alternating(const prox_body *a, const prox_body *b, prox_vec3 n, double sd, prox_vec3 *p1,
                                  prox_vec3 *p2)
{
    sup_face fa = face_of(a, n), fb = face_of(b, prox_v3_neg(n));
    if (fa.dim == 1 && fb.dim == 1) {
        /* two segments (two lateral lines): alternating projections converge like cos^2 of their
         * angle, far too slowly for nearly parallel axes; the closest points of A's segment and
         * B's segment moved by -sd n are the exact pair */
        prox_vec3 cb = prox_v3_mad(fb.c, -sd, n), q1, q2;
        prox_seg_seg(prox_v3_mad(fa.c, -fa.s0, fa.e0), prox_v3_mad(fa.c, fa.s0, fa.e0), prox_v3_mad(cb, -fb.s0, fb.e0),
                     prox_v3_mad(cb, fb.s0, fb.e0), &q1, &q2);
        *p1 = q1;
        *p2 = prox_v3_mad(q2, sd, n);
        return prox_v3_norm(prox_v3_mad(prox_v3_sub(*p2, *p1), -sd, n));
    }
    prox_vec3 x = fa.c, y = face_proj(&fb, prox_v3_mad(x, sd, n));
    if (fa.dim > 0 || fb.dim > 0)
        for (int it = 0; it < 64; ++it) {
            prox_vec3 xn = face_proj(&fa, prox_v3_mad(y, -sd, n));
            prox_vec3 yn = face_proj(&fb, prox_v3_mad(xn, sd, n));
            double mv = prox_v3_dist(xn, x) + prox_v3_dist(yn, y);
            x = xn; y = yn;
            if (mv <= PROX_TOL_DECREMENT * (prox_v3_maxabs(x) + prox_v3_maxabs(y) + fabs(sd))) break; /* at rounding */
        }
    *p1 = x;
    *p2 = y;
    return prox_v3_norm(prox_v3_mad(prox_v3_sub(y, x), -sd, n));
}

/* Snaps the best direction onto a kink it is within PROX_TOL_KINK of (cone point +-W, ridge D.w = 0),
 * when phi there is no worse (up to rounding, PROX_TOL_SNAP x scale): the nonsmooth search ends a few 1e-7 rad off a
 * kink, where the support set of a cylinder jumps from a disk or a segment to one point and the
 * witnesses would be off by radius x angle. On the kink the support set is the whole face. */
static void snap_to_kinks(sup_search *s)
{
    prox_vec3 r[6];
    int n = sup_ridges(s->a, r);
    n += sup_ridges(s->b, r + n);
    for (int pass = 0; pass < 2; ++pass)
        for (int i = 0; i < n; ++i) {
            prox_vec3 d = s->best_d, c;
            double dw = prox_v3_dot(d, r[i]);
            if (fabs(dw) < PROX_TOL_KINK && dw != 0.0) c = prox_v3_mad(d, -dw, r[i]);
            else if (fabs(dw) > 1.0 - PROX_TOL_CONE && fabs(dw) != 1.0) c = dw > 0.0 ? r[i] : prox_v3_neg(r[i]);
            else continue;
            c = unit(c);
            double f = phi_eval(s, c);
            if (f <= s->best_phi + PROX_TOL_SNAP * s->scale) { s->best_phi = f; s->best_d = c; }
        }
}

/* ---- directions for the witnesses ----------------------------------------------------------- */

/* The search stops when phi no longer decreases beyond its rounding, which leaves the direction off
 * by up to sqrt(rounding / curvature) ~ 1e-8 rad; phi is then right to 1e-17 S, but the support
 * points move by radius x angle, and a near-touching pair's |p2 - p1| is off by (r angle)^2 / d.
 * The witnesses need the direction itself: pure Newton steps on the tangential gradient, accepted
 * while its norm decreases (quadratic convergence takes 1e-8 to rounding in one or two steps). */
static double tgrad_norm(const sup_search *s, prox_vec3 d)
{
    prox_vec3 g = phi_grad(s, d);
    return prox_v3_norm(prox_v3_mad(g, -prox_v3_dot(g, d), d));
}

/* In a cell (both support points smooth: rims, sphere). */
static prox_vec3 polish_cell(const sup_search *s, prox_vec3 d)
{
    double gn = tgrad_norm(s, d);
    for (int it = 0; it < 6 && gn > 0.0; ++it) {
        double f = phi_eval(s, d);
        prox_vec3 t1 = prox_v3_any_perp(d), t2 = prox_v3_cross(d, t1), g = phi_grad(s, d);
        double g1 = prox_v3_dot(g, t1), g2 = prox_v3_dot(g, t2);
        prox_vec3 h1 = phi_hess(s, d, t1), h2 = phi_hess(s, d, t2);
        double a = prox_v3_dot(t1, h1) - f, b = prox_v3_dot(t1, h2), c = prox_v3_dot(t2, h2) - f, det = a * c - b * b;
        if (!(a > 0.0 && det > 0.0)) break;
        double x1 = -(c * g1 - b * g2) / det, x2 = -(a * g2 - b * g1) / det;
        prox_vec3 dn = unit(prox_v3_add(d, prox_v3_add(prox_v3_scale(t1, x1), prox_v3_scale(t2, x2))));
        double gnn = tgrad_norm(s, dn);
        if (!(gnn < gn)) break;
        d = dn, gn = gnn;
    }
    return d;
}

/* On the ridge D.w = 0 (a lateral line or a box face supports): Newton along the great circle. */
static prox_vec3 polish_ridge(const sup_search *s, prox_vec3 w, prox_vec3 d)
{
    d = prox_v3_reject(d, w);
    d = prox_v3_reject(d, w);
    double dn2 = prox_v3_norm2(d);
    if (!(dn2 > 0.0)) return d;
    d = unit(d);
    double g1o = INFINITY;
    for (int it = 0; it < 6; ++it) {
        prox_vec3 dt = prox_v3_cross(w, d);
        double f = phi_eval(s, d), g1 = prox_v3_dot(phi_grad(s, d), dt), g2 = prox_v3_dot(dt, phi_hess(s, d, dt)) - f;
        if (!(fabs(g1) < g1o) || !(g2 > 0.0)) break;
        g1o = fabs(g1);
        prox_vec3 dn = prox_v3_reject(prox_v3_mad(d, -g1 / g2, dt), w);
        d = unit(prox_v3_reject(dn, w));
    }
    return d;
}

/* Witnesses for the disjoint answer: every direction below names a pair of support sets, every pair
 * taken from them is a pair of points of A x B, so the closest of the candidates is kept. Candidates:
 * the search's direction before and after snapping onto a kink, its Newton polish, its polish on each
 * ridge it is close to, and the cone points (disk normals) it is close to: a face against a side line
 * tilted by 1e-9 has its exact pair at the disk normal, while the snap may have chosen the ridge.
 * Returns the candidate direction of the pair kept (the normal of the answer). */
static prox_vec3 disjoint_witnesses(const sup_search *s, prox_vec3 d0, double sd, prox_vec3 *p1, prox_vec3 *p2)
{
    prox_vec3 cand[24];
    int nc = 0;
    cand[nc++] = s->best_d;
    cand[nc++] = d0;
    cand[nc++] = polish_cell(s, d0);
    prox_vec3 r[6];
    int nr = sup_ridges(s->a, r);
    nr += sup_ridges(s->b, r + nr);
    for (int i = 0; i < nr && nc < 16; ++i) {
        double dw = prox_v3_dot(d0, r[i]);
        if (fabs(dw) < PROX_TOL_KINK) cand[nc++] = polish_ridge(s, r[i], d0);
        else if (fabs(dw) > 1.0 - PROX_TOL_CONE) cand[nc++] = dw > 0.0 ? r[i] : prox_v3_neg(r[i]);
        /* the crossing of two ridges it is close to (two side lines: n = W_A x W_B) */
        for (int j = i + 1; j < nr && nc < 16; ++j) {
            prox_vec3 x = prox_v3_cross(r[i], r[j]);
            if (fabs(dw) < PROX_TOL_KINK && fabs(prox_v3_dot(d0, r[j])) < PROX_TOL_KINK && prox_v3_norm(x) > PROX_TOL_PARALLEL)
                cand[nc++] = unit(prox_v3_dot(x, d0) >= 0.0 ? x : prox_v3_neg(x));
        }
    }
    /* the closest pair; among pairs equally close to rounding, the candidate along which p2 - p1
     * points best (a kink the search ended 1e-8 rad off gives the same pair) */
    double best = INFINITY, align = INFINITY, tie = PROX_TOL_SNAP * s->scale;
    prox_vec3 n = s->best_d;
    for (int k = 0; k < nc; ++k) {
        if (!(prox_v3_norm2(cand[k]) > 0.0)) continue;
        prox_vec3 x, y;
        sup_witnesses(s->a, s->b, cand[k], sd, &x, &y);
        double dk = prox_v3_dist(x, y), ak = prox_v3_norm(prox_v3_mad(prox_v3_sub(y, x), -dk, cand[k]));
        if (dk < best - tie || (dk <= best + tie && ak < align)) {
            if (dk < best) best = dk;
            align = ak, *p1 = x, *p2 = y, n = cand[k];
        }
    }
    return n;
}

/* The witnesses of a support set's extreme point: y = B's support point along -n (on B's supporting
 * plane exactly) and x = y - sd n on A's supporting plane, kept when x lies in A; or the same from
 * A's side. Then p2 - p1 = sd n holds to rounding. It settles a face against a side line tilted by
 * 1e-9 rad, where a point of the side line's support set (faces within PROX_TOL_FACE) sits off the
 * supporting plane by the tilt times its length. Replaces res's pair when it is in the solids and
 * better than the residual `best`. */
static void overlap_exact_pair(const prox_body *a, const prox_body *b, double scale, double best, prox_signed_result *res)
{
    prox_vec3 n = res->normal;
    double sd = res->sd, tol = PROX_TOL_TOUCH * scale;
    for (int side = 0; side < 2; ++side) {
        prox_vec3 x, y;
        if (side == 0) y = prox_body_support_point(b, prox_v3_neg(n)), x = prox_v3_mad(y, -sd, n);
        else x = prox_body_support_point(a, n), y = prox_v3_mad(x, sd, n);
        if (!prox_body_contains(a, x, tol) || !prox_body_contains(b, y, tol)) continue;
        double e = prox_v3_norm(prox_v3_mad(prox_v3_sub(y, x), -sd, n));
        if (e < best) best = e, res->p1 = x, res->p2 = y;
    }
}

void sup_overlap_answer(const prox_body *a, const prox_body *b, prox_vec3 n0, prox_signed_result *res)
{
    sup_search s = {.a = a, .b = b, .delta = prox_v3_sub(b->c, a->c), .best_phi = INFINITY};
    s.scale = fmax(prox_v3_norm(s.delta), fmax(a->size, b->size));
    prox_vec3 cand[8];
    int nc = 0;
    cand[nc++] = n0;
    double phi0 = phi_eval(&s, n0), best = INFINITY;
    for (int k = 0; k < nc; ++k) {
        if (fabs(prox_v3_norm(cand[k]) - 1.0) < 0.5) {
            double f = k ? phi_eval(&s, cand[k]) : phi0;
            if (f <= phi0 + PROX_TOL_SNAP * s.scale) { /* a polish may not cost depth */
                prox_vec3 x, y;
                sup_witnesses(a, b, cand[k], -f, &x, &y);
                prox_vec3 nk = sup_consistent_normal(cand[k], -f, x, y);
                double e = prox_v3_norm(prox_v3_mad(prox_v3_sub(y, x), f, nk));
                if (e < best) best = e, res->sd = -f, res->normal = nk, res->p1 = x, res->p2 = y;
                if (best <= PROX_TOL_SEARCH * s.scale) return; /* exact to rounding: no other candidate can matter */
            }
        }
        if (k > 0) continue;
        /* n0 itself not exact: its cell polish, then the ridges and axes it lies on */
        cand[nc++] = polish_cell(&s, n0);
        prox_vec3 r[6];
        int nr = sup_ridges(a, r);
        nr += sup_ridges(b, r + nr);
        for (int i = 0; i < nr && nc < 8; ++i) {
            double dw = prox_v3_dot(n0, r[i]);
            if (fabs(dw) < PROX_TOL_KINK) cand[nc++] = polish_ridge(&s, r[i], n0);
            else if (fabs(dw) > 1.0 - PROX_TOL_CONE) cand[nc++] = dw > 0.0 ? r[i] : prox_v3_neg(r[i]);
        }
    }
    overlap_exact_pair(a, b, s.scale, best, res);
}

/* The result from the best direction found. */
static prox_signed_result finish(sup_search *s)
{
    prox_vec3 d0 = s->best_d;
    snap_to_kinks(s);
    prox_signed_result res = {0};
    res.status = PROX_OK;
    res.sd = -s->best_phi;
    res.normal = s->best_d;
    if (res.sd > 0.0) {
        /* the normal is the candidate direction of the witness pair: polished, it makes
         * p2 - p1 = sd n hold (the search's direction may be 1e-8 rad off, which |p2 - p1| times
         * would exceed). Not (p2 - p1) / |p2 - p1|: along parallel faces the pair may slide by
         * sqrt(eps d) sideways at no cost in |p2 - p1|, and a direction that far off a face normal
         * loses r sqrt(eps d) of the gap. */
        res.normal = disjoint_witnesses(s, d0, res.sd, &res.p1, &res.p2);
    } else {
        sup_overlap_answer(s->a, s->b, s->best_d, &res);
    }
    return res;
}

/* Minimum along the ridge D.w = 0 near d (a bracket of +-0.1 rad around d's projection). */
static void ridge_local(sup_search *s, prox_vec3 w, prox_vec3 d)
{
    prox_vec3 p = prox_v3_mad(d, -prox_v3_dot(d, w), w);
    double pn = sqrt(prox_v3_norm2(p));
    if (!(pn > 0.0)) return;
    prox_vec3 u = prox_v3_scale(p, 1.0 / pn), v = prox_v3_cross(w, u);
    consider(s, u);
    ridge_refine(s, u, v, -0.1, 0.1, 0.0);
}

/* Disjoint pairs (some unit D already has phi < 0): the problem is quasi-convex, so a local
 * search from the best direction is global. Newton in the cell, then the ridges it came close
 * to (a lateral contact's minimiser lies exactly on one), then Newton again. */
static void search_disjoint(sup_search *s, const prox_vec3 *r, int n)
{
    cell_newton(s, s->best_d);
    for (int pass = 0; pass < 2; ++pass) {
        prox_vec3 d0 = s->best_d;
        for (int i = 0; i < n; ++i)
            if (fabs(prox_v3_dot(d0, r[i])) < 0.05) ridge_local(s, r[i], d0);
        if (prox_v3_dot(d0, s->best_d) == 1.0) break;
        cell_newton(s, s->best_d);
    }
}

prox_signed_result sup_signed_distance(const prox_body *a, const prox_body *b, const prox_vec3 *hint)
{
    sup_search s = {.a = a, .b = b, .delta = prox_v3_sub(b->c, a->c), .best_phi = INFINITY};
    s.scale = fmax(prox_v3_norm(s.delta), fmax(a->size, b->size));
    s.best_d = prox_v3(0, 0, 1);
    if (hint) consider(&s, *hint);
    search_points(&s);
    gjk_separate(&s); /* a separating cone too narrow for the samples; box vertex contacts */
    prox_vec3 r[6];
    int n = sup_ridges(a, r);
    n += sup_ridges(b, r + n);
    if (s.best_phi < 0.0) {
        /* disjoint: local search, then every ridge (a stalled local search ends on one), unless the
         * local search's answer is already proved: its witnesses |p2 - p1| (an upper bound) meet
         * -phi (a lower bound, weak duality) within PROX_TOL_CERT x scale */
        search_disjoint(&s, r, n);
        sup_search t = s;
        prox_signed_result early = finish(&t);
        if (prox_v3_dist(early.p1, early.p2) - early.sd <= PROX_TOL_CERT * s.scale) return early;
        for (int i = 0; i < n; ++i) search_ridge(&s, r[i]);
        cell_newton(&s, s.best_d);
        search_disjoint(&s, r, n);
        return finish(&s);
    }
    for (int i = 0; i < n; ++i) search_ridge(&s, r[i]);
    search_samples(&s);
    prox_vec3 starts[SUP_TOPK];
    int ns = s.nk;
    for (int i = 0; i < ns; ++i) starts[i] = s.kd[i];
    for (int i = 0; i < ns; ++i) cell_newton(&s, starts[i]);
    cell_newton(&s, s.best_d);
    /* A separating direction found only now (a near-touching disjoint pair whose cone neither the
     * samples nor GJK entered): the disjoint problem is quasi-convex, so refine it as such. */
    if (s.best_phi < 0.0) search_disjoint(&s, r, n);
    return finish(&s);
}
