/* Internal (core): the prepared representations of the curved macrobodies added to RCC and SPH: the
 * truncated cone (TRC), the elliptical cylinder (REC) and the ellipsoid of revolution (ELL). Each is
 * kept relative to a reference point c (the middle of the axis; the centre of the ellipsoid), so that
 * a body far from the origin keeps its relative precision, and each offers what every method uses:
 * centred support function and point, membership, closest point and boundary distance.
 *
 * Support functions (P_w d = d - (d.w) w, the part of d across the axis):
 *   TRC  hc(d) = max( -hh d.w + r1 |P_w d|,  hh d.w + r2 |P_w d| )        (the hull of its two rims)
 *   REC  hc(d) = hh |d.w| + sqrt((a1 d.u1)^2 + (a2 d.u2)^2)                (two elliptical disks)
 *   ELL  hc(d) = sqrt(b^2 |d|^2 + (a^2 - b^2) (d.w)^2)                      (sqrt(d^T M d)) */
#ifndef PROX_CORE_CURVED_H
#define PROX_CORE_CURVED_H

#include "prox/shapes.h"

/* TRC: base rim (radius r1) at -hh w, top rim (radius r2) at +hh w. */
typedef struct prox_cone {
    prox_vec3 w;      /* unit axis, base to top */
    double hh;        /* half height */
    double r1, r2;    /* base and top radii */
} prox_cone;

/* REC: ellipses a1 u1 cos t + a2 u2 sin t at -+hh w. */
typedef struct prox_ecyl {
    prox_vec3 w, u1, u2; /* orthonormal: axis, major and minor directions */
    double hh, a1, a2;   /* half height, semi-axes */
} prox_ecyl;

/* ELL: semi-axis a along w, equatorial radius b. */
typedef struct prox_ellb {
    prox_vec3 w;
    double a, b;
} prox_ellb;

/* Preparation of a valid shape; each returns the reference point c (absolute). */
prox_vec3 prox_cone_make(const prox_trc *t, prox_cone *k);
prox_vec3 prox_ecyl_make(const prox_rec *r, prox_ecyl *k);
prox_vec3 prox_ellb_make(const prox_ell *e, prox_ellb *k);

/* Centred support function and a support point (coordinates relative to c). */
double prox_cone_hc(const prox_cone *k, prox_vec3 d);
prox_vec3 prox_cone_pc(const prox_cone *k, prox_vec3 d);
double prox_ecyl_hc(const prox_ecyl *k, prox_vec3 d);
prox_vec3 prox_ecyl_pc(const prox_ecyl *k, prox_vec3 d);
double prox_ellb_hc(const prox_ellb *k, prox_vec3 d);
prox_vec3 prox_ellb_pc(const prox_ellb *k, prox_vec3 d);

/* 1 when y (relative to c) lies in the solid enlarged by tol >= 0 (absolute distance). */
int prox_cone_contains(const prox_cone *k, prox_vec3 y, double tol);
int prox_ecyl_contains(const prox_ecyl *k, prox_vec3 y, double tol);
int prox_ellb_contains(const prox_ellb *k, prox_vec3 y, double tol);

/* Closest point of the solid to y (y itself inside). */
prox_vec3 prox_cone_closest(const prox_cone *k, prox_vec3 y);
prox_vec3 prox_ecyl_closest(const prox_ecyl *k, prox_vec3 y);
prox_vec3 prox_ellb_closest(const prox_ellb *k, prox_vec3 y);
/* The same, warm-started along a sequence of nearby points (core/ellipse2.h; *warm NAN at first). */
prox_vec3 prox_ellb_closest_warm(const prox_ellb *k, prox_vec3 y, double *warm);

/* The outward unit normal of a cone's lateral surface in a meridian half-plane: nt along the axis,
 * nr across it, (r1 - r2, 2 hh) / |(2 hh, r2 - r1)|. */
void prox_cone_lateral_normal(const prox_cone *k, double *nt, double *nr);
/* The nearest point *q of the lateral surface to y (relative to c) in y's meridian half-plane: the
 * foot on the generator there, clamped to its rims; *n the lateral normal on that generator. 2 for a
 * foot inside the generator, 1 at a rim (where the normal is not unique), 0 for y on the axis. */
int prox_cone_lateral_foot(const prox_cone *k, prox_vec3 y, prox_vec3 *q, prox_vec3 *n);

/* Signed distance from y to the boundary (< 0 inside) and the closest boundary point *q. */
double prox_cone_boundary(const prox_cone *k, prox_vec3 y, prox_vec3 *q);
double prox_ecyl_boundary(const prox_ecyl *k, prox_vec3 y, prox_vec3 *q);
double prox_ellb_boundary(const prox_ellb *k, prox_vec3 y, prox_vec3 *q);

#endif
