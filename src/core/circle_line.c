/* Stationary points of the distance from a circle to an infinite line (Agarwal et al. (2016)
 * Sec. 3.3, P(C, L)), the local minimiser of the RCC-RCC fast path, the largest distance of a circle
 * from a line, all declared in core/circle.h.
 * Circle point P(th) = c + r (cos th u + sin th v) (Eq. (14) with s1 = 1); line x(t) = p + t w, |w| = 1.
 * Eq. (16): f_t = 0 is linear in t, t = (P(th) - p).w. Substituting it into f_th = 0 gives g1 = 0; in the
 * normalised frame (lengths divided by r, p the foot of c on the line, e = (c - p) / r) it reads
 *   h(th) = A sin th + B cos th + C cos 2th + D sin 2th = 0,
 *   A = (e.w)(u.w) - e.u,  B = e.v - (e.w)(v.w),  C = -(u.w)(v.w),  D = ((u.w)^2 - (v.w)^2) / 2,
 * (h = g'(th) / (2 r^2), g = dist^2). The half-angle substitution x = tan(th/2) turns h (1 + x^2)^2 into
 * the quartic g2 of Sec. 3.3:
 *   (C - B) x^4 + (2A - 4D) x^3 - 6C x^2 + (2A + 4D) x + (B + C) = 0.
 * Its leading coefficient is h(pi): the angle pi is sent to infinity by the substitution, so pi is added
 * whenever h(pi) is small. Roots come from prox_poly_real_roots (closed form for quartics) and are
 * polished by Newton on the exact h. h == 0 identically (A = B = C = D = 0) exactly when the line is the
 * circle's axis. */
#include "core/angle.h"
#include "core/axis.h"
#include "core/circle.h"
#include "core/poly.h"
#include "core/tol.h"

#include <float.h>
#include <stddef.h>

/* h(th) and h'(th) of the normalised problem. */
typedef struct cl_coef {
    double A, B, C, D;
} cl_coef;
static double cl_h_cs(const cl_coef *k, double c, double s, double *dh)
{
    double s2 = 2.0 * s * c, c2 = (c - s) * (c + s);
    if (dh) *dh = k->A * c - k->B * s - 2.0 * k->C * s2 + 2.0 * k->D * c2;
    return k->A * s + k->B * c + k->C * c2 + k->D * s2;
}
static double cl_h(const cl_coef *k, double th, double *dh) { return cl_h_cs(k, cos(th), sin(th), dh); }

/* Newton on h from the angle's unit vector a; returns the iterate with the smallest |h| (steps
 * limited to 0.5 rad; prox_unit2_step: no trigonometric call per step). */
static prox_unit2 cl_polish_u(const cl_coef *k, prox_unit2 a)
{
    double dh, h = cl_h_cs(k, a.c, a.s, &dh), hb = fabs(h);
    prox_unit2 best = a;
    for (int it = 0; it < 12 && hb > 0.0; ++it) {
        if (!(fabs(dh) > 0.0)) break;
        double step = h / dh;
        if (!(fabs(step) <= 0.5)) break;
        a = prox_unit2_step(a, step);
        h = cl_h_cs(k, a.c, a.s, &dh); /* one evaluation per iteration: value and derivative */
        if (fabs(h) < hb) {
            hb = fabs(h);
            best = a;
        }
        if (fabs(step) <= 8.0 * DBL_EPSILON) break; /* a step at the rounding of the angle */
    }
    return best;
}

/* The same from an angle, returning an angle in (-pi, pi]. */
static double cl_polish(const cl_coef *k, double th)
{
    prox_unit2 a = cl_polish_u(k, (prox_unit2){cos(th), sin(th)});
    return atan2(a.s, a.c);
}

/* The angle 2 atan(t) of a root t of the half-angle polynomial, as a unit vector without a
 * trigonometric call: (cos, sin) = ((1 - t^2), 2t) / (1 + t^2), written in 1/t for |t| > 1. */
static prox_unit2 unit2_of_half_tan(double t)
{
    if (fabs(t) <= 1.0) {
        double q = 1.0 / (1.0 + t * t);
        return (prox_unit2){(1.0 - t * t) * q, 2.0 * t * q};
    }
    double u = 1.0 / t, q = 1.0 / (u * u + 1.0);
    return (prox_unit2){(u * u - 1.0) * q, 2.0 * u * q};
}

/* Sorts, merges angles closer than PROX_TOL_CL_DEDUP (also across 0 / 2pi) and keeps at most 4 (smallest |h|). */
static int cl_dedup(const cl_coef *k, double *th, int n)
{
    for (int i = 1; i < n; ++i) /* insertion sort */
        for (int j = i; j > 0 && th[j] < th[j - 1]; --j) {
            double t = th[j];
            th[j] = th[j - 1];
            th[j - 1] = t;
        }
    int m = 0;
    for (int i = 0; i < n; ++i)
        if (m == 0 || th[i] - th[m - 1] > PROX_TOL_CL_DEDUP) th[m++] = th[i];
    if (m > 1 && th[0] + 2.0 * PROX_PI - th[m - 1] <= PROX_TOL_CL_DEDUP) --m;
    while (m > 4) { /* more than a trigonometric quartic can have: drop the worst residual */
        int w = 0;
        for (int i = 1; i < m; ++i)
            if (fabs(cl_h(k, th[i], NULL)) > fabs(cl_h(k, th[w], NULL))) w = i;
        th[w] = th[--m];
    }
    return m;
}

/* Coefficients of h in the normalised frame: origin at the foot of c on the line, lengths in r. */
static cl_coef cl_make(const prox_fcircle *c, prox_vec3 p, prox_vec3 w, prox_vec3 *e_out)
{
    prox_vec3 foot = prox_v3_mad(p, prox_v3_dot(prox_v3_sub(c->c, p), w), w);
    prox_vec3 e = prox_v3_scale(prox_v3_sub(c->c, foot), 1.0 / c->r);
    double al = prox_v3_dot(e, w), be = prox_v3_dot(c->u, w), ga = prox_v3_dot(c->v, w);
    cl_coef k = {al * be - prox_v3_dot(e, c->u), prox_v3_dot(e, c->v) - al * ga, -be * ga,
                 0.5 * (be - ga) * (be + ga)};
    *e_out = e;
    return k;
}

/* A local MINIMUM of a function g of the angle near a (a candidate must be a minimum; Newton on g'
 * alone may stop at the maximum or wander to the other minimum). Safeguarded Newton on the unit
 * vector of the angle (prox_unit2_step, no trigonometric call): the Newton step where g'' > 0, else a
 * descent step of 0.5 rad, halved until g decreases; below PROX_TOL_DESCENT_ROUND rad (quadratic
 * regime, where the decrease is rounding) until |g'| does. eval returns g and sets g' and g''. */
typedef double (*u2_eval)(const void *ctx, prox_unit2 a, double *d1, double *d2);

static prox_unit2 u2_newton_min(u2_eval eval, const void *ctx, prox_unit2 a)
{
    double d1, d2, g = eval(ctx, a, &d1, &d2);
    for (int it = 0; it < 40 && d1 != 0.0; ++it) {
        double step = d2 > 0.0 ? d1 / d2 : (d1 > 0.0 ? 0.5 : -0.5);
        if (!(fabs(step) <= 0.5)) step = step > 0.0 ? 0.5 : -0.5;
        /* A Newton step in the quadratic regime leaves an error of order step^2: take it and stop. */
        if (d2 > 0.0 && fabs(step) <= PROX_TOL_NEWTON_QUAD) return prox_unit2_step(a, step);
        int moved = 0;
        for (int j = 0; j < 8 && !moved; ++j, step *= 0.5) {
            prox_unit2 an = prox_unit2_step(a, step);
            double e1, e2, gn = eval(ctx, an, &e1, &e2);
            if (gn < g || (fabs(step) <= PROX_TOL_DESCENT_ROUND && fabs(e1) < fabs(d1))) {
                a = an, g = gn, d1 = e1, d2 = e2, moved = 1;
                break;
            }
            if (fabs(step) <= PROX_TOL_DESCENT_ROUND) break; /* quadratic regime: no decrease means converged */
        }
        if (!moved) break;
    }
    return a;
}

/* The circle-to-line distance for the RCC-RCC fast path: g/2 up to a constant,
 * (e.u) cos + (e.v) sin - ((e.w) + (u.w) cos + (v.w) sin)^2 / 2, its derivatives h and h'. */
typedef struct cl_local {
    cl_coef k;
    double eu, ev, al, be, ga;
} cl_local;

static double cl_local_eval(const void *ctx, prox_unit2 a, double *d1, double *d2)
{
    const cl_local *l = ctx;
    double t = l->al + l->be * a.c + l->ga * a.s;
    *d1 = cl_h_cs(&l->k, a.c, a.s, d2);
    return l->eu * a.c + l->ev * a.s - 0.5 * t * t;
}

prox_unit2 prox_circle_line_local(const prox_fcircle *c, prox_vec3 p, prox_vec3 w, prox_unit2 a)
{
    prox_vec3 e;
    cl_local l;
    l.k = cl_make(c, p, w, &e);
    l.eu = prox_v3_dot(e, c->u), l.ev = prox_v3_dot(e, c->v);
    l.al = prox_v3_dot(e, w), l.be = prox_v3_dot(c->u, w), l.ga = prox_v3_dot(c->v, w);
    return u2_newton_min(cl_local_eval, &l, a);
}

int prox_circle_line_stationary(const prox_fcircle *c, prox_vec3 p, prox_vec3 w, double th[4], int *count)
{
    *count = 0;
    prox_vec3 e;
    cl_coef k = cl_make(c, p, w, &e);
    /* the offset in units of r overflows (sizes 1e300 apart): the quartic is meaningless, and the
     * constant-case test below would compare inf with inf */
    if (!prox_v3_isfinite(e) || !isfinite(k.A + k.B + k.C + k.D)) return -(int)PROX_ENUMERIC;
    double kmax = fmax(fmax(fabs(k.A), fabs(k.B)), fmax(fabs(k.C), fabs(k.D)));
    if (kmax <= PROX_TOL_NOISE * (1.0 + prox_v3_norm(e))) return 1; /* line along the axis: rounding noise */
    double poly[5] = {k.B + k.C, 2.0 * k.A + 4.0 * k.D, -6.0 * k.C, 2.0 * k.A - 4.0 * k.D, k.C - k.B};
    double roots[8], cand[8];
    int nr = 0, n = 0;
    /* A failed root solve is reported, not replaced by a search that could miss a pair of close
     * roots: the callers' answers would be silently wrong. */
    if (prox_poly_real_roots(poly, 4, roots, &nr) != PROX_OK) return -(int)PROX_ENUMERIC;
    for (int i = 0; i < nr; ++i) {
        prox_unit2 a = cl_polish_u(&k, unit2_of_half_tan(roots[i]));
        cand[n++] = atan2(a.s, a.c);
    }
    if (fabs(k.C - k.B) <= PROX_TOL_CL_PI * kmax) cand[n++] = cl_polish(&k, PROX_PI);
    for (int i = 0; i < n; ++i) cand[i] = prox_prim_wrap_2pi(cand[i]);
    n = cl_dedup(&k, cand, n);
    for (int i = 0; i < n; ++i) th[i] = cand[i];
    *count = n;
    return 0;
}

/* Farthest distance from the point (q0, q1) >= 0 to the ellipse x^2/a^2 + y^2/b^2 = 1, a >= b >= 0.
 * The farthest point lies in the opposite quadrant, at x = -a^2 q0 / tau, y = -b^2 q1 / (tau + c),
 * c = a^2 - b^2, where tau > 0 is the root of G(tau) = (a q0 / tau)^2 + (b q1 / (tau + c))^2 = 1
 * (Lagrange multiplier mu = tau + a^2 > a^2; G is convex and decreasing, so the root is unique and
 * bracketed by [a q0, sqrt(a^2 q0^2 + b^2 q1^2)]; Newton from the left end approaches it monotonically).
 * q0 = 0 with G(0+) <= 1 is the limit tau = 0: two farthest points share y = -b^2 q1 / c. The point
 * is put back on the ellipse before measuring, so that the error left in tau is of second order. */
static double ellipse_farthest(double a, double b, double q0, double q1)
{
    double c = (a - b) * (a + b);
    if (b == 0.0) return hypot(a + q0, q1); /* a segment: its far end */
    if (!(q0 > 0.0) && b * q1 <= c) { /* the limit case (c > 0 here unless q1 = 0 too) */
        double y = c > 0.0 ? -b * b * q1 / c : 0.0, x = a * sqrt(fmax(0.0, 1.0 - (y / b) * (y / b)));
        return hypot(x, q1 - y);
    }
    double aq = a * q0, bq = b * q1, tau = aq > 0.0 ? aq : fmax(bq - c, 0.0);
    for (int it = 0; it < 100; ++it) {
        double g0 = tau > 0.0 ? aq / tau : 0.0, g1 = bq / (tau + c);
        double G = g0 * g0 + g1 * g1 - 1.0;
        if (!(G > 0.0)) break;
        double dG = 2.0 * ((tau > 0.0 ? g0 * g0 / tau : 0.0) + g1 * g1 / (tau + c));
        double step = G / dG;
        if (!(step > 1e-17 * tau)) break; /* below a tenth of an ulp: tau cannot change any more */
        tau += step;
    }
    double x = tau > 0.0 ? a * aq / tau : a, y = b * bq / (tau + c); /* magnitudes of the point */
    double k = 1.0 / sqrt((x / a) * (x / a) + (y / b) * (y / b));
    return hypot(q0 + k * x, q1 + k * y);
}

/* Max over the circle C of the distance to the line (base, unit w), in closed form up to one
 * monotone root (replaces the quartic of Agarwal Sec. 3.3 where only the maximum is wanted): along w the circle projects onto an ellipse with semi-axes r (along u, normal to
 * w and to the rim's normal n) and r |n.w| (along w x u), centred at the rim centre's offset E from
 * the axis; the answer is the ellipse's farthest point from the axis (ellipse_farthest). Within
 * PROX_TOL_FLAT of n || w the ellipse is a circle to 5e-17 r: |E| + r. */
double prox_circle_line_max_dist(prox_vec3 centre, prox_vec3 n, double r, prox_vec3 base, prox_vec3 w)
{
    prox_vec3 E = prox_v3_reject(prox_v3_sub(centre, base), w);
    prox_vec3 x = prox_v3_reject(prox_v3_cross(w, n), w);
    double sn = prox_v3_norm(x);
    if (!(sn > PROX_TOL_FLAT)) return prox_v3_norm(E) + r;
    prox_vec3 u = prox_v3_scale(x, 1.0 / sn), e = prox_v3_cross(w, u);
    double b = r * fabs(prox_v3_dot(n, w));
    return ellipse_farthest(r, fmin(b, r), fabs(prox_v3_dot(E, u)), fabs(prox_v3_dot(E, e)));
}

/* Local refinement of a rim against the lateral surface of a cone (TRC) or cylinder: a local minimum
 * near a of F(theta) = k t + rho, t = (x - p).w and rho = |P (x - p)| the axial and radial coordinates
 * of the circle's point x(theta) about the line through p along w (P across w). F is the distance to
 * the surface rho = rho0 - k t (k = (r0 - r1) / h, the radius' decrease per unit height) up to the
 * constant factor cos of the half-angle. Safeguarded Newton on the unit vector of the angle, as
 * prox_circle_line_local; F' and F'' in closed form from y = P (x - p) and its derivatives:
 * rho' = y.y' / rho, rho'' = (y'.y' + y.y'') / rho - rho'^2 / rho (u2_newton_min). A circle point on
 * the line (rho = 0, F not differentiable) ends the search there. */
typedef struct cc_cone {
    prox_vec3 pe, pu, pv; /* P (c - p), r P u, r P v */
    double k, al, be, ga; /* t = al + be cos + ga sin */
} cc_cone;

static double cc_cone_eval(const void *ctx, prox_unit2 a, double *d1, double *d2)
{
    const cc_cone *q = ctx;
    prox_vec3 rad = prox_v3_add(prox_v3_scale(q->pu, a.c), prox_v3_scale(q->pv, a.s));
    prox_vec3 y = prox_v3_add(q->pe, rad), y1 = prox_v3_sub(prox_v3_scale(q->pv, a.c), prox_v3_scale(q->pu, a.s));
    double rho = prox_v3_norm(y), t = q->al + q->be * a.c + q->ga * a.s;
    if (!(rho > 0.0)) {
        *d1 = *d2 = 0.0;
        return q->k * t;
    }
    double r1 = prox_v3_dot(y, y1) / rho;
    *d1 = q->k * (q->ga * a.c - q->be * a.s) + r1;
    *d2 = -q->k * (q->be * a.c + q->ga * a.s) + (prox_v3_norm2(y1) - prox_v3_dot(y, rad)) / rho - r1 * r1 / rho;
    return q->k * t + rho;
}

prox_unit2 prox_circle_cone_local(const prox_fcircle *c, prox_vec3 p, prox_vec3 w, double k, prox_unit2 a)
{
    prox_vec3 e = prox_v3_sub(c->c, p);
    cc_cone q = {prox_axis_across(e, w), prox_v3_scale(prox_axis_across(c->u, w), c->r),
                 prox_v3_scale(prox_axis_across(c->v, w), c->r), k, prox_v3_dot(e, w),
                 c->r * prox_v3_dot(c->u, w), c->r * prox_v3_dot(c->v, w)};
    return u2_newton_min(cc_cone_eval, &q, a);
}
