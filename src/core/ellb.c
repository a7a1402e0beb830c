/* The ellipsoid of revolution ELL (core/curved.h): semi-axis a along the unit axis w, equatorial
 * radius b (prolate a > b, oblate a < b). In the half-plane through the axis and a point y, with
 * (t, rho) = (axial, radial) coordinates, it is the half of the ellipse (t/a)^2 + (rho/b)^2 <= 1,
 * and every query is that meridian ellipse's (core/ellipse2.h): the nearest point of a solid of
 * revolution lies in the point's half-plane. */
#include <math.h>
#include <stddef.h>

#include "core/axis.h"
#include "core/curved.h"
#include "core/curved_normal.h"
#include "core/ellipse2.h"

/* The half-plane coordinates of y: t, rho and the radial unit vector *u (core/axis.h). */
static double half_plane(const prox_ellb *k, prox_vec3 y, double *rho, prox_vec3 *u)
{
    *u = prox_axis_radial(y, k->w, rho);
    return prox_v3_dot(y, k->w);
}

prox_vec3 prox_ellb_make(const prox_ell *e, prox_ellb *k)
{
    double a = prox_v3_norm(e->axis);
    k->w = prox_v3(e->axis.x / a, e->axis.y / a, e->axis.z / a);
    k->a = a;
    k->b = e->radius;
    return e->center;
}

/* hc(d) = sqrt(d^T M d) = |(a d.w, b |P d|)| with M = a^2 w w^T + b^2 (I - w w^T). */
double prox_ellb_hc(const prox_ellb *k, prox_vec3 d)
{
    return prox_hypot2(k->a * prox_v3_dot(d, k->w), k->b * prox_v3_norm(prox_axis_across(d, k->w)));
}

/* pc(d) = M d / hc(d): the point whose outward normal is d. */
prox_vec3 prox_ellb_pc(const prox_ellb *k, prox_vec3 d)
{
    double pw = k->a * prox_v3_dot(d, k->w);
    prox_vec3 pd = prox_axis_across(d, k->w);
    double h = prox_hypot2(pw, k->b * prox_v3_norm(pd));
    if (!(h > 0.0)) return prox_v3(0, 0, 0);
    return prox_v3_mad(prox_v3_scale(k->w, k->a * (pw / h)), k->b * (k->b / h), pd);
}

int prox_ellb_contains(const prox_ellb *k, prox_vec3 y, double tol)
{
    double rho, q0, q1;
    prox_vec3 u;
    double t = half_plane(k, y, &rho, &u);
    int w = prox_ellipse2_within(k->a, k->b, t, rho, tol); /* the meridian section's quadratic forms */
    if (w >= 0) return w;
    return prox_ellipse2_closest(k->a, k->b, t, rho, &q0, &q1) <= tol;
}

prox_vec3 prox_ellb_closest_warm(const prox_ellb *k, prox_vec3 y, double *warm)
{
    double rho, q0, q1;
    prox_vec3 u;
    double t = half_plane(k, y, &rho, &u);
    if (prox_ellipse2_inside(k->a, k->b, t, rho)) return y;
    prox_ellipse2_closest_warm(k->a, k->b, t, rho, warm, &q0, &q1);
    return prox_v3_mad(prox_v3_scale(k->w, q0), q1, u);
}

prox_vec3 prox_ellb_closest(const prox_ellb *k, prox_vec3 y) { return prox_ellb_closest_warm(k, y, NULL); }

double prox_ellb_boundary(const prox_ellb *k, prox_vec3 y, prox_vec3 *q)
{
    prox_vec3 n;
    return prox_ellb_boundary_n(k, y, q, &n);
}

/* The outward normal at q is the gradient direction (q0/a^2, q1/b^2) of the meridian ellipse. */
double prox_ellb_boundary_n(const prox_ellb *k, prox_vec3 y, prox_vec3 *q, prox_vec3 *n)
{
    double rho, q0, q1;
    prox_vec3 u;
    double t = half_plane(k, y, &rho, &u);
    double s = prox_ellipse2_closest(k->a, k->b, t, rho, &q0, &q1);
    *q = prox_v3_mad(prox_v3_scale(k->w, q0), q1, u);
    double g0 = q0 / k->a / k->a, g1 = q1 / k->b / k->b, gl = prox_hypot2(g0, g1);
    *n = prox_v3_mad(prox_v3_scale(k->w, g0 / gl), g1 / gl, u);
    return s;
}
