/* The right elliptical cylinder REC (core/curved.h): the product of the axial interval
 * [-hh, hh] and the solid ellipse (x1/a1)^2 + (x2/a2)^2 <= 1 of its cross-section. Its nearest point
 * to y is the product of the nearest points (clamped t, the ellipse's nearest point in the
 * cross-section: core/ellipse2.h); from inside, the nearer of the caps and the lateral surface. */
#include <math.h>

#include "core/curved.h"
#include "core/curved_normal.h"
#include "core/ellipse2.h"

prox_vec3 prox_ecyl_make(const prox_rec *r, prox_ecyl *k)
{
    double h = prox_v3_norm(r->axis), l1 = prox_v3_norm(r->a1), l2 = prox_v3_norm(r->a2);
    k->w = prox_v3(r->axis.x / h, r->axis.y / h, r->axis.z / h);
    k->hh = 0.5 * h;
    /* The longer semi-axis is the major one whatever the card's order; its direction is made exactly
     * orthogonal to the axis (the validator allows PROX_BOX_ORTHO_TOL) and u2 completes the frame
     * (the ellipse is symmetric, so u2's sign is free). */
    prox_vec3 a = l1 >= l2 ? r->a1 : r->a2;
    k->a1 = fmax(l1, l2);
    k->a2 = fmin(l1, l2);
    prox_vec3 u = prox_v3_scale(a, 1.0 / k->a1);
    u = prox_v3_reject(u, k->w);
    u = prox_v3_normalize(prox_v3_reject(u, k->w));
    k->u1 = u;
    k->u2 = prox_v3_cross(k->w, u);
    return prox_v3_mad(r->base, 0.5, r->axis);
}

/* hc(d) = hh |d.w| + |(a1 d.u1, a2 d.u2)|: the two elliptical caps' support functions. */
double prox_ecyl_hc(const prox_ecyl *k, prox_vec3 d)
{
    return k->hh * fabs(prox_v3_dot(d, k->w)) + prox_hypot2(k->a1 * prox_v3_dot(d, k->u1), k->a2 * prox_v3_dot(d, k->u2));
}

/* The cap point (a1^2 d1 u1 + a2^2 d2 u2) / |(a1 d1, a2 d2)| on the side d.w points to; d.w = 0 gives
 * the middle of the lateral segment, d along the axis the centre of the cap. */
prox_vec3 prox_ecyl_pc(const prox_ecyl *k, prox_vec3 d)
{
    double dw = prox_v3_dot(d, k->w), p1 = k->a1 * prox_v3_dot(d, k->u1), p2 = k->a2 * prox_v3_dot(d, k->u2);
    prox_vec3 x = prox_v3_scale(k->w, dw > 0.0 ? k->hh : (dw < 0.0 ? -k->hh : 0.0));
    double n = prox_hypot2(p1, p2);
    if (!(n > 0.0)) return x;
    x = prox_v3_mad(x, k->a1 * (p1 / n), k->u1);
    return prox_v3_mad(x, k->a2 * (p2 / n), k->u2);
}

/* Local coordinates (t, x1, x2) of y. */
static void local(const prox_ecyl *k, prox_vec3 y, double l[3])
{
    l[0] = prox_v3_dot(y, k->w);
    l[1] = prox_v3_dot(y, k->u1);
    l[2] = prox_v3_dot(y, k->u2);
}

static prox_vec3 point(const prox_ecyl *k, double t, double x1, double x2)
{
    return prox_v3_mad(prox_v3_mad(prox_v3_scale(k->w, t), x1, k->u1), x2, k->u2);
}

int prox_ecyl_contains(const prox_ecyl *k, prox_vec3 y, double tol)
{
    double l[3], q1, q2;
    local(k, y, l);
    double dt = fabs(l[0]) - k->hh;
    if (dt > tol) return 0;
    if (prox_ellipse2_inside(k->a1, k->a2, l[1], l[2])) return 1;
    int w = prox_ellipse2_within(k->a1, k->a2, l[1], l[2], tol); /* the section's quadratic forms */
    if (w == 0 || (w == 1 && dt <= 0.0)) return w; /* within tol across and inside along the axis */
    double dr = prox_ellipse2_closest(k->a1, k->a2, l[1], l[2], &q1, &q2);
    return prox_hypot2(fmax(dt, 0.0), dr) <= tol;
}

prox_vec3 prox_ecyl_closest(const prox_ecyl *k, prox_vec3 y)
{
    double l[3], q1 = 0.0, q2 = 0.0;
    local(k, y, l);
    int in_t = fabs(l[0]) <= k->hh, in_e = prox_ellipse2_inside(k->a1, k->a2, l[1], l[2]);
    if (in_t && in_e) return y;
    double tc = in_t ? l[0] : (l[0] > 0.0 ? k->hh : -k->hh);
    if (in_e)
        q1 = l[1], q2 = l[2];
    else
        prox_ellipse2_closest(k->a1, k->a2, l[1], l[2], &q1, &q2);
    return point(k, tc, q1, q2);
}

double prox_ecyl_boundary(const prox_ecyl *k, prox_vec3 y, prox_vec3 *q)
{
    prox_vec3 n;
    return prox_ecyl_boundary_n(k, y, q, &n);
}

/* Outward normals: a cap's +-w, the lateral surface's ellipse normal (q1/a1^2, q2/a2^2) in the
 * cross-section, and on a rim (outside both) the combination dt (+-w) + dr nu, which is y - q itself
 * and lies in the rim's normal cone whatever the rounding of dt, dr >= 0. */
double prox_ecyl_boundary_n(const prox_ecyl *k, prox_vec3 y, prox_vec3 *q, prox_vec3 *n)
{
    double l[3], q1, q2;
    local(k, y, l);
    double dt = fabs(l[0]) - k->hh;
    double dr = prox_ellipse2_closest(k->a1, k->a2, l[1], l[2], &q1, &q2);
    int in_e = prox_ellipse2_inside(k->a1, k->a2, l[1], l[2]);
    double tc = l[0] > k->hh ? k->hh : (l[0] < -k->hh ? -k->hh : l[0]);
    prox_vec3 cap = l[0] >= 0.0 ? k->w : prox_v3_neg(k->w);
    double g1 = q1 / k->a1 / k->a1, g2 = q2 / k->a2 / k->a2, gl = prox_hypot2(g1, g2);
    prox_vec3 nu = prox_v3_mad(prox_v3_scale(k->u1, g1 / gl), g2 / gl, k->u2);
    if (dt > 0.0 || !in_e) { /* outside: the product of the nearest points */
        double et = fmax(dt, 0.0), er = in_e ? 0.0 : fmax(dr, 0.0), d = prox_hypot2(et, er);
        if (in_e) q1 = l[1], q2 = l[2];
        *q = point(k, tc, q1, q2);
        if (er == 0.0)
            *n = cap;
        else if (et == 0.0)
            *n = nu;
        else
            *n = prox_v3_mad(prox_v3_scale(cap, et / d), er / d, nu);
        return d;
    }
    if (dt >= dr) { /* the nearer cap (dt, dr <= 0) */
        *q = point(k, l[0] >= 0.0 ? k->hh : -k->hh, l[1], l[2]);
        *n = cap;
        return dt;
    }
    *q = point(k, l[0], q1, q2);
    *n = nu;
    return dr;
}
