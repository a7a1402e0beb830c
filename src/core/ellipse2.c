/* Point-ellipse distance (core/ellipse2.h), Eberly's method (Sec. 2 of "Distance from a Point to an
 * Ellipse, an Ellipsoid, or a Hyperellipsoid"). In the first quadrant with e0 >= e1, the nearest point
 * x of the curve to y satisfies x_i = e_i^2 y_i / (t + e_i^2) for the largest root t > -e1^2 of
 *   F(t) = (e0 y0 / (t + e0^2))^2 + (e1 y1 / (t + e1^2))^2 - 1.
 * Eberly solves it in s = t / e1^2 (s + 1 in (0, ...)); here the unknown is w = (t + e1^2) / e0^2 > 0,
 *   F(w) = (N / (w + D))^2 + (Z / w)^2 - 1,  N = y0 / e0,  Z = (y1 / e0) (e1 / e0),  D = 1 - (e1 / e0)^2,
 * so that (i) w keeps its full relative precision near the major axis inside, where the root tends to
 * 0 and Eberly's s to -1 (s + 1 would lose all the digits of x1 = e1 Z / w), and (ii) no parameter
 * overflows however far the point or however flat the ellipse (Eberly's r0 z0 = e0 y0 / e1^2 does at
 * aspect ratios ~1e150 in the supported range). F is decreasing and convex on w > 0, with F(lo) >= 0
 * at lo = max(Z, N - D) and F(hi) <= 0 at hi = e1^2/e0^2 (y inside: t = 0) or |(N, Z)| (outside).
 * Then x0 = e0 N / (w + D), x1 = e1 Z / w. The on-axis cases are Eberly's closed forms. */
#include "core/ellipse2.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "core/minmax.h"
#include "core/tol.h"
#include "prox/vec3.h"

int prox_ellipse2_inside(double e0, double e1, double y0, double y1)
{
    double z0 = y0 / e0, z1 = y1 / e1;
    return z0 * z0 + z1 * z1 <= 1.0;
}

int prox_ellipse2_within(double e0, double e1, double y0, double y1, double tol)
{
    if (prox_ellipse2_inside(e0 + tol, e1 + tol, y0, y1)) return 1;
    double z0 = y0 / e0, z1 = y1 / e1, g = 1.0 + tol / (e0 < e1 ? e0 : e1);
    return z0 * z0 + z1 * z1 > g * g ? 0 : -1;
}

/* F(w) and F'(w) of the secular equation. */
static double secular(double n, double z, double d, double w, double *df)
{
    double a = n / (w + d), b = z / w;
    *df = -2.0 * (a * a / (w + d) + b * b / w);
    return a * a + b * b - 1.0;
}

/* The root of F in [lo, hi] (F(lo) >= 0 >= F(hi)): Newton from u in the bracket (its left end, where
 * Newton converges monotonically, F being convex decreasing, or a warm start), with a bisection
 * whenever a step would leave the bracket or fails to halve the step before it (Numerical Recipes'
 * rtsafe safeguard); a Newton step in the quadratic regime is the last. */
static double secular_root(double n, double z, double d, double lo, double hi, double u)
{
    double df, f = secular(n, z, d, u, &df);
    if (f > 0.0) lo = u;
    else if (f < 0.0) hi = u;
    double dx = hi - lo, dxold = dx;
    for (int it = 0; it < PROX_ELLIPSE_MAXIT && f != 0.0; ++it) {
        if (((u - hi) * df - f) * ((u - lo) * df - f) > 0.0 || fabs(2.0 * f) > fabs(dxold * df)) {
            dxold = dx;
            dx = 0.5 * (hi - lo);
            u = lo + dx;
            if (u == lo || u == hi) break;
        } else {
            dxold = dx;
            dx = f / df;
            double prev = u;
            u -= dx;
            /* a Newton step in the quadratic regime: F''/|F'| <= 3 / w, so the error it leaves is at
             * most 1.5 (dx / w)^2 w, below 1e-17 of w once dx is below PROX_TOL_NEWTON_QUAD w */
            if (u == prev || fabs(dx) <= PROX_TOL_NEWTON_QUAD * u) break;
        }
        if (fabs(dx) <= PROX_ELLIPSE_STEP * u) break;
        f = secular(n, z, d, u, &df);
        if (f > 0.0)
            lo = u;
        else
            hi = u;
    }
    return u;
}

/* First quadrant, e0 >= e1 > 0, y0, y1 >= 0: the nearest curve point and the signed distance; warm
 * (or NULL) as in prox_ellipse2_closest_warm. */
static double quadrant(double e0, double e1, double y0, double y1, double *x0, double *x1, double *warm)
{
    double r = e1 / e0, dd = (1.0 - r) * (1.0 + r), z0 = y0 / e0;
    double zz = (y1 / e0) * r; /* Z; 0 when y1 is so close to the major axis that it underflows */
    if (zz > 0.0 && y1 > PROX_ELLIPSE_AXIS_Z * e1) { /* else on the major axis (tol.h) */
        if (y0 > 0.0) {
            double z1 = y1 / e1, g = z0 * z0 + z1 * z1 - 1.0;
            if (g == 0.0) {
                *x0 = y0, *x1 = y1;
                return 0.0;
            }
            double lo = prox_max2(zz, z0 - dd), hi = g < 0.0 ? r * r : prox_hypot2(z0, zz);
            if (hi < lo) hi = lo; /* rounding at the very boundary */
            double u = warm && *warm > lo && *warm < hi ? *warm : lo;
            double w = secular_root(z0, zz, dd, lo, hi, u);
            if (warm) *warm = w;
            *x0 = e0 * (z0 / (w + dd));
            *x1 = e1 * (zz / w);
            double dist = prox_hypot2(*x0 - y0, *x1 - y1);
            return g < 0.0 ? -dist : dist;
        }
        /* on the minor axis: the co-vertex is nearest (from inside too, e0 >= e1) */
        *x0 = 0.0, *x1 = e1;
        return y1 - e1;
    }
    /* on the major axis: inside, between the centre and the centre of curvature of the vertex
     * (y0 < e0 - e1^2 / e0), the nearest points leave the axis at x0 = y0 / D; else the vertex */
    if (z0 < dd) {
        double xd = z0 / dd;
        *x0 = e0 * xd;
        *x1 = e1 * sqrt((1.0 - xd) * (1.0 + xd));
        return -prox_hypot2(*x0 - y0, *x1 - y1);
    }
    *x0 = e0, *x1 = 0.0;
    return y0 - e0;
}

double prox_ellipse2_closest_warm(double e0, double e1, double y0, double y1, double *warm, double *x0, double *x1)
{
    double a0 = fabs(y0), a1 = fabs(y1), q0, q1, s;
    if (e0 >= e1) {
        s = quadrant(e0, e1, a0, a1, &q0, &q1, warm);
    } else {
        s = quadrant(e1, e0, a1, a0, &q1, &q0, warm);
    }
    *x0 = y0 < 0.0 ? -q0 : q0;
    *x1 = y1 < 0.0 ? -q1 : q1;
    return s;
}

double prox_ellipse2_closest(double e0, double e1, double y0, double y1, double *x0, double *x1)
{
    return prox_ellipse2_closest_warm(e0, e1, y0, y1, NULL, x0, x1);
}
