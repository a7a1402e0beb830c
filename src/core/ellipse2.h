/* Internal (core): the closest point of an ellipse (x0/e0)^2 + (x1/e1)^2 = 1 to a point of its
 * plane, shared by the elliptical cylinder (its cross-section) and the ellipsoid of revolution (its
 * meridian section). Eberly, "Distance from a Point to an Ellipse, an Ellipsoid, or a Hyperellipsoid"
 * (Geometric Tools, 2013, Sec. 2): the secular equation of the Lagrange multiplier t, solved here in
 * the variable w = (t + e1^2) / e0^2 (precise near the major axis, free of overflow) with a
 * safeguarded Newton iteration in place of plain bisection; see docs/algorithms/curved.md. */
#ifndef PROX_CORE_ELLIPSE2_H
#define PROX_CORE_ELLIPSE2_H

/* Signed distance (< 0 inside) from (y0, y1) to the ellipse curve with semi-axes e0 (along the first
 * coordinate) and e1 (> 0, either order), and the nearest point (*x0, *x1) of the curve; the point
 * keeps the signs of y (a zero coordinate gives the + side). */
double prox_ellipse2_closest(double e0, double e1, double y0, double y1, double *x0, double *x1);

/* prox_ellipse2_closest warm-started: *warm holds the root w of the secular equation of an earlier
 * call on the same ellipse (NAN: none), the Newton start when it lies in this call's bracket, and
 * receives this call's root. Along a sequence of nearby points (a root search along a segment) Newton
 * then needs a step or two instead of ~4.5 from the bracket's end; the answer meets the same stopping
 * test. */
double prox_ellipse2_closest_warm(double e0, double e1, double y0, double y1, double *warm, double *x0, double *x1);

/* 1 when (y0, y1) lies in the closed solid ellipse: (y0/e0)^2 + (y1/e1)^2 <= 1. */
int prox_ellipse2_inside(double e0, double e1, double y0, double y1);

/* Whether (y0, y1) lies within tol >= 0 of the solid ellipse, by its quadratic forms alone: 1 when
 * inside the ellipse of semi-axes e0 + tol, e1 + tol, which lies in E + B(tol) (its support function
 * |((e0 + tol) d0, (e1 + tol) d1)| is at most |(e0 d0, e1 d1)| + tol |d|, Minkowski's inequality);
 * 0 when outside (1 + tol / min(e0, e1)) E, which holds E + B(tol) (B(tol) lies in tol / min E);
 * -1 in the thin shell between, where the closest point decides. */
int prox_ellipse2_within(double e0, double e1, double y0, double y1, double tol);

#endif
