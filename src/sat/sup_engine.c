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
 * local minimum per face), hence the global sampling of all strata. */
#include "sup_engine.h"

#include "prox/primitives.h"

#include <float.h>

#define SUP_TOPK 4
#define SUP_RIDGE_SAMPLES 64
#define SUP_FACE_TOL 1e-9 /* |sin| below which a near-face/near-line support set is treated as one */

/* ---- single bodies ---------------------------------------------------------------------- */

sup_body sup_body_make(const prox_shape *s)
{
    sup_body b = {0};
    switch (s->kind) {
    case PROX_SHAPE_RCC: {
        const prox_rcc *c = &s->u.rcc;
        double h = prox_v3_norm(c->axis);
        b.kind = SUP_CYL;
        b.w = prox_v3_scale(c->axis, 1.0 / h);
        b.c = prox_v3_mad(c->base, 0.5, c->axis);
        b.r = c->radius;
        b.hh = 0.5 * h;
        b.size = h > 2.0 * c->radius ? h : 2.0 * c->radius;
        break;
    }
    case PROX_SHAPE_BOX:
    case PROX_SHAPE_RPP: {
        prox_box bx = s->kind == PROX_SHAPE_BOX ? s->u.box : prox_rpp_to_box(&s->u.rpp);
        b.kind = SUP_BOX;
        b.c = bx.corner;
        for (int i = 0; i < 3; ++i) {
            double l = prox_v3_norm(bx.edge[i]);
            b.e[i] = prox_v3_scale(bx.edge[i], 1.0 / l);
            b.ext[i] = 0.5 * l;
            b.c = prox_v3_mad(b.c, 0.5, bx.edge[i]);
            if (l > b.size) b.size = l;
        }
        break;
    }
    case PROX_SHAPE_SPH:
        b.kind = SUP_SPH;
        b.c = s->u.sph.center;
        b.r = s->u.sph.radius;
        b.size = 2.0 * b.r;
        break;
    }
    return b;
}

double sup_hc(const sup_body *b, prox_vec3 d)
{
    switch (b->kind) {
    case SUP_CYL: {
        double dw = prox_v3_dot(d, b->w);
        return b->r * sqrt(prox_v3_norm2(prox_v3_mad(d, -dw, b->w))) + b->hh * fabs(dw);
    }
    case SUP_BOX:
        return b->ext[0] * fabs(prox_v3_dot(d, b->e[0])) + b->ext[1] * fabs(prox_v3_dot(d, b->e[1])) +
               b->ext[2] * fabs(prox_v3_dot(d, b->e[2]));
    default: return b->r * sqrt(prox_v3_norm2(d));
    }
}

/* Second Gram-Schmidt pass: d - (d.w)w keeps an O(eps |d|) component along w, which is large
 * relative to a short result (d nearly along the axis) and would put the support point off the
 * cylinder by up to r eps |d| / |perp|. */
static prox_vec3 reortho(prox_vec3 perp, prox_vec3 w) { return prox_v3_mad(perp, -prox_v3_dot(perp, w), w); }

/* d / |d| for directions of moderate length (no overflow possible here). */
static prox_vec3 unit(prox_vec3 d) { return prox_v3_scale(d, 1.0 / sqrt(prox_v3_norm2(d))); }

static double sgn(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

prox_vec3 sup_pc(const sup_body *b, prox_vec3 d)
{
    switch (b->kind) {
    case SUP_CYL: {
        double dw = prox_v3_dot(d, b->w);
        prox_vec3 p = prox_v3_scale(b->w, b->hh * sgn(dw));
        prox_vec3 perp = reortho(prox_v3_mad(d, -dw, b->w), b->w);
        double n = sqrt(prox_v3_norm2(perp));
        return n > 0.0 ? prox_v3_mad(p, b->r / n, perp) : p;
    }
    case SUP_BOX: {
        prox_vec3 p = prox_v3(0, 0, 0);
        for (int i = 0; i < 3; ++i) p = prox_v3_mad(p, b->ext[i] * sgn(prox_v3_dot(d, b->e[i])), b->e[i]);
        return p;
    }
    default: {
        double n = sqrt(prox_v3_norm2(d));
        return n > 0.0 ? prox_v3_scale(d, b->r / n) : d;
    }
    }
}

/* Hessian of hc at d applied to v (zero for a box; defined off the kinks). */
static prox_vec3 sup_hess(const sup_body *b, prox_vec3 d, prox_vec3 v)
{
    if (b->kind == SUP_CYL) {
        double dw = prox_v3_dot(d, b->w);
        prox_vec3 perp = reortho(prox_v3_mad(d, -dw, b->w), b->w);
        double n = sqrt(prox_v3_norm2(perp));
        if (!(n > 0.0)) return prox_v3(0, 0, 0);
        prox_vec3 p = prox_v3_scale(perp, 1.0 / n);
        prox_vec3 x = prox_v3_mad(prox_v3_mad(v, -prox_v3_dot(v, b->w), b->w), -prox_v3_dot(v, p), p);
        return prox_v3_scale(x, b->r / n);
    }
    if (b->kind == SUP_SPH) {
        double n = sqrt(prox_v3_norm2(d));
        prox_vec3 u = prox_v3_scale(d, 1.0 / n);
        return prox_v3_scale(prox_v3_mad(v, -prox_v3_dot(v, u), u), b->r / n);
    }
    return prox_v3(0, 0, 0);
}

/* Ridge normals and cone axes of a body. */
static int sup_ridges(const sup_body *b, prox_vec3 out[3])
{
    if (b->kind == SUP_CYL) { out[0] = b->w; return 1; }
    if (b->kind == SUP_BOX) { out[0] = b->e[0]; out[1] = b->e[1]; out[2] = b->e[2]; return 3; }
    return 0;
}

/* ---- the pair search ---------------------------------------------------------------------- */

typedef struct sup_search {
    const sup_body *a, *b;
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
    return sup_hc(s->a, d) + sup_hc(s->b, d) - prox_v3_dot(d, s->delta);
}
/* Gradient of phi: support point of K minus Delta (a subgradient on the kinks). */
static prox_vec3 phi_grad(const sup_search *s, prox_vec3 d)
{
    return prox_v3_sub(prox_v3_add(sup_pc(s->a, d), sup_pc(s->b, d)), s->delta);
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
        if (prox_v3_dot(d, s->kd[i]) > 1.0 - 1e-8) {
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
            if (prox_v3_norm(x) < 1e-12) continue; /* parallel ridges: the 1-dim search covers it */
            consider(s, x);
            consider(s, prox_v3_neg(x));
        }
    const sup_body *bs[2] = {s->a, s->b};
    for (int k = 0; k < 2; ++k)
        if (bs[k]->kind == SUP_CYL) {
            consider(s, bs[k]->w);
            consider(s, prox_v3_neg(bs[k]->w));
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
    const double dl = 1e-7, noise = 16.0 * DBL_EPSILON * s->scale; /* noise: rounding of phi */
    for (int i = 0; i < n; ++i) {
        double ru = prox_v3_dot(u, r[i]), rv = prox_v3_dot(v, r[i]);
        if (fabs(ru) + fabs(rv) < 1e-12) continue; /* this ridge itself (or parallel to it) */
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
        if (g2 > 0.0 && 0.5 * g1 * g1 / g2 <= 1e-17 * s->scale) return; /* decrement: converged */
        double tn = g2 > 0.0 ? th - g1 / g2 : 0.5 * (lo + hi);
        if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
        if (fabs(tn - th) <= 1e-15 * (1.0 + fabs(th)) || hi - lo <= 1e-14) return;
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
    const sup_body *bs[2] = {s->a, s->b};
    for (int k = 0; k < 2; ++k) {
        const sup_body *b = bs[k];
        if (b->kind == SUP_CYL) {
            double dw = prox_v3_dot(d, b->w);
            prox_vec3 perp = reortho(prox_v3_mad(d, -dw, b->w), b->w);
            double n = sqrt(prox_v3_norm2(perp));
            g = prox_v3_mad(g, b->hh * sgn(dw), b->w);
            if (n > 1e-6) g = prox_v3_mad(g, b->r / n, perp);
        } else g = prox_v3_add(g, sup_pc(b, d));
    }
    return g;
}

/* 1 when d is within 1e-5 rad of a ridge or a cone point of either body. */
static int near_kink(const sup_search *s, prox_vec3 d)
{
    const sup_body *bs[2] = {s->a, s->b};
    for (int k = 0; k < 2; ++k) {
        const sup_body *b = bs[k];
        if (b->kind == SUP_CYL) {
            double dw = fabs(prox_v3_dot(d, b->w));
            if (dw < 1e-5 || dw > 1.0 - 5e-11) return 1;
        } else if (b->kind == SUP_BOX)
            for (int i = 0; i < 3; ++i)
                if (fabs(prox_v3_dot(d, b->e[i])) < 1e-5) return 1;
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
        if (-0.5 * (g1 * x1 + g2 * x2) <= 1e-17 * s->scale) return 0.0;
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
        if (len < 1e-13) {
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
    double tol = 4.0 * DBL_EPSILON * s->scale, floor2 = 256.0 * tol * tol;
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

/* Support set of body b in unit direction d (absolute position), near-faces included. */
static sup_face face_of(const sup_body *b, prox_vec3 d)
{
    sup_face f = {0};
    if (b->kind == SUP_CYL) {
        double dw = prox_v3_dot(d, b->w);
        prox_vec3 perp = reortho(prox_v3_mad(d, -dw, b->w), b->w);
        double pn = prox_v3_norm(perp);
        if (pn <= SUP_FACE_TOL) {
            f.dim = 2; f.disk = 1; f.n = b->w; f.rad = b->r;
            f.c = prox_v3_mad(b->c, dw >= 0.0 ? b->hh : -b->hh, b->w);
        } else if (fabs(dw) <= SUP_FACE_TOL) {
            f.dim = 1; f.e0 = b->w; f.s0 = b->hh;
            f.c = prox_v3_mad(b->c, b->r / pn, perp);
        } else f.c = prox_v3_add(b->c, sup_pc(b, d));
        return f;
    }
    f.c = b->c;
    if (b->kind == SUP_SPH) { f.c = prox_v3_mad(b->c, b->r, d); return f; }
    for (int i = 0; i < 3; ++i) {
        double di = prox_v3_dot(d, b->e[i]);
        if (fabs(di) <= SUP_FACE_TOL && f.dim < 2) {
            if (f.dim == 0) { f.e0 = b->e[i]; f.s0 = b->ext[i]; }
            else { f.e1 = b->e[i]; f.s1 = b->ext[i]; }
            f.dim++;
        } else f.c = prox_v3_mad(f.c, di >= 0.0 ? b->ext[i] : -b->ext[i], b->e[i]);
    }
    return f;
}

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

/* Witness points for the minimising direction n: p1 in the support set of A in n, p2 in that of B
 * in -n, with p2 - p1 as close to sd n as the sets allow (alternating projections). */
void sup_witnesses(const sup_body *a, const sup_body *b, prox_vec3 n, double sd, prox_vec3 *p1, prox_vec3 *p2)
{
    sup_face fa = face_of(a, n), fb = face_of(b, prox_v3_neg(n));
    if (fa.dim == 1 && fb.dim == 1) {
        /* two segments (two lateral lines): alternating projections converge like cos^2 of their
         * angle, far too slowly for nearly parallel axes; the closest points of A's segment and
         * B's segment moved by -sd n are the exact pair */
        prox_segment sa = {prox_v3_mad(fa.c, -fa.s0, fa.e0), prox_v3_mad(fa.c, fa.s0, fa.e0)};
        prox_vec3 cb = prox_v3_mad(fb.c, -sd, n);
        prox_segment sb = {prox_v3_mad(cb, -fb.s0, fb.e0), prox_v3_mad(cb, fb.s0, fb.e0)};
        prox_prim_result q = prox_segment_segment(&sa, &sb);
        if (q.status == PROX_OK) {
            *p1 = q.p1;
            *p2 = prox_v3_mad(q.p2, sd, n);
            return;
        }
    }
    prox_vec3 x = fa.c, y = face_proj(&fb, prox_v3_mad(x, sd, n));
    if (fa.dim > 0 || fb.dim > 0)
        for (int it = 0; it < 64; ++it) {
            prox_vec3 xn = face_proj(&fa, prox_v3_mad(y, -sd, n));
            prox_vec3 yn = face_proj(&fb, prox_v3_mad(xn, sd, n));
            double mv = prox_v3_dist(xn, x) + prox_v3_dist(yn, y);
            x = xn; y = yn;
            if (mv <= 1e-17 * (prox_v3_maxabs(x) + prox_v3_maxabs(y) + fabs(sd))) break; /* at rounding */
        }
    *p1 = x;
    *p2 = y;
}

/* Snaps the best direction onto a kink it is within 1e-5 rad of (cone point +-W, ridge D.w = 0),
 * when phi there is no worse (up to rounding, 4 eps x scale): the nonsmooth search ends a few 1e-7 rad off a
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
            if (fabs(dw) < 1e-5 && dw != 0.0) c = prox_v3_mad(d, -dw, r[i]);
            else if (fabs(dw) > 1.0 - 5e-11 && fabs(dw) != 1.0) c = dw > 0.0 ? r[i] : prox_v3_neg(r[i]);
            else continue;
            c = unit(c);
            double f = phi_eval(s, c);
            if (f <= s->best_phi + 4.0 * DBL_EPSILON * s->scale) { s->best_phi = f; s->best_d = c; }
        }
}

/* The result from the best direction found. */
static prox_signed_result finish(sup_search *s)
{
    snap_to_kinks(s);
    prox_signed_result res = {0};
    res.status = PROX_OK;
    res.sd = -s->best_phi;
    res.normal = s->best_d;
    sup_witnesses(s->a, s->b, s->best_d, res.sd, &res.p1, &res.p2);
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

prox_signed_result sup_signed_distance(const sup_body *a, const sup_body *b, const prox_vec3 *hint)
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
        /* disjoint: local search, then every ridge (a stalled local search ends on one) */
        search_disjoint(&s, r, n);
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
