/* Internal (core): the one prepared representation of a solid right circular cylinder that every
 * module uses: frame, support function and support point, exact point membership, closest point,
 * and the rim circles.
 *
 * Support function (Eberly, "Intersection of Cylinders", Eq. 4):
 *   h(D) = D.C + r |D - (D.W)W| + (h/2)|D.W|,  C the centre, W the unit axis, h the height, r the radius.
 * The centred part hc(D) = h(D) - D.C is even in D (the body is centrally symmetric). */
#ifndef PROX_CORE_CYL_H
#define PROX_CORE_CYL_H

#include <math.h>

#include "core/axis.h"
#include "core/circle.h"
#include "core/tol.h"
#include "prox/shapes.h"

typedef struct prox_cyl {
    prox_vec3 b;      /* base centre */
    prox_vec3 w;      /* unit axis, base to top */
    prox_vec3 c;      /* centre */
    prox_vec3 cap[2]; /* centres of the base (0) and top (1) disks */
    double h, hh, r;  /* height, half height, radius */
} prox_cyl;

/* A validated cylinder with height h = |axis|, in coordinates relative to origin (pass the zero
 * vector for absolute coordinates; a pair far from the origin keeps its relative precision when
 * both cylinders are prepared relative to a point of the pair: the subtraction is exact by Sterbenz). */
static inline prox_cyl prox_cyl_make_h(const prox_rcc *c, double h, prox_vec3 origin)
{
    prox_cyl k;
    k.h = h;
    k.hh = 0.5 * h;
    k.w = prox_v3(c->axis.x / h, c->axis.y / h, c->axis.z / h);
    k.r = c->radius;
    k.b = prox_v3_sub(c->base, origin);
    k.c = prox_v3_mad(k.b, k.hh, k.w);
    k.cap[0] = k.b;
    k.cap[1] = prox_v3_mad(k.b, h, k.w);
    return k;
}

/* The same with the height computed here. */
static inline prox_cyl prox_cyl_make(const prox_rcc *c, prox_vec3 origin)
{
    return prox_cyl_make_h(c, prox_v3_norm(c->axis), origin);
}

/* Centre of the cylinder in absolute coordinates (base + axis / 2). */
static inline prox_vec3 prox_rcc_center(const prox_rcc *c) { return prox_v3_mad(c->base, 0.5, c->axis); }

/* Component of d perpendicular to the axis (core/axis.h). */
static inline prox_vec3 prox_cyl_perp(const prox_cyl *k, prox_vec3 d) { return prox_axis_across(d, k->w); }

/* Centred support function hc(d) = r |d - (d.w)w| + (h/2)|d.w| (d need not be unit). */
static inline double prox_cyl_hc(const prox_cyl *k, prox_vec3 d)
{
    double dw = prox_v3_dot(d, k->w);
    return k->r * prox_v3_norm(prox_v3_mad(d, -dw, k->w)) + k->hh * fabs(dw);
}

/* Support function h(d) = max over the cylinder of d.x. */
static inline double prox_cyl_support(const prox_cyl *k, prox_vec3 d)
{
    return prox_v3_dot(d, k->c) + prox_cyl_hc(k, d);
}

/* Centred support point: x - c for a point x of the cylinder with d.x = h(d). d.w = 0 gives the
 * middle of the side segment, d along the axis the centre of the disk (the middle of the support set).
 * A radial part at the rounding of d is d along the axis (prox_axis_radial): its direction is noise,
 * and may even lie along w, which would put the point off the cylinder. */
static inline prox_vec3 prox_cyl_support_point_c(const prox_cyl *k, prox_vec3 d)
{
    double dw = prox_v3_dot(d, k->w);
    prox_vec3 p = prox_v3_scale(k->w, dw > 0.0 ? k->hh : (dw < 0.0 ? -k->hh : 0.0));
    double n;
    prox_vec3 u = prox_axis_radial(d, k->w, &n);
    return n > 0.0 ? prox_v3_mad(p, k->r, u) : p;
}

/* Support point in the cylinder's coordinates. */
static inline prox_vec3 prox_cyl_support_point(const prox_cyl *k, prox_vec3 d)
{
    return prox_v3_add(k->c, prox_cyl_support_point_c(k, d));
}

/* Separation of the projections of A and B on the unit direction n (from A towards B):
 * gap(n) = -h_B(-n) - h_A(n). By weak duality gap(n) <= distance(A, B) for every unit n. */
static inline double prox_cyl_gap(const prox_cyl *a, const prox_cyl *b, prox_vec3 n)
{
    return -prox_cyl_support(b, prox_v3_neg(n)) - prox_cyl_support(a, n);
}

/* 1 when x lies in the closed solid cylinder enlarged by tol (tol >= 0, absolute). */
static inline int prox_cyl_contains(const prox_cyl *k, prox_vec3 x, double tol)
{
    prox_vec3 d = prox_v3_sub(x, k->b);
    double t = prox_v3_dot(d, k->w);
    if (t < -tol || t > k->h + tol) return 0;
    double rt = k->r + tol; /* squared comparison: no square root on this hot path */
    return prox_v3_norm2(prox_v3_mad(d, -t, k->w)) <= rt * rt;
}

/* 1 when x lies in the closed solid cylinder of a card c (x and c->base in the same frame): the
 * squared tests on the card itself, no root and no prepared cylinder (prox_rcc_contains_point builds
 * one), for a quick routing test on a query's hot path. */
static inline int prox_rcc_holds(const prox_rcc *c, prox_vec3 x)
{
    prox_vec3 d = prox_v3_sub(x, c->base);
    double t = prox_v3_dot(d, c->axis), hh = prox_v3_norm2(c->axis);
    return t >= 0.0 && t <= hh && prox_v3_norm2(d) * hh - t * t <= c->radius * c->radius * hh;
}

/* Closest point of the solid cylinder to x (x itself when inside). */
prox_vec3 prox_cyl_closest(const prox_cyl *k, prox_vec3 x);

/* Signed distance of x to the solid cylinder (negative inside), the boundary point q nearest to x
 * and the outward unit normal n at q, with x = q + sd n. */
double prox_cyl_signed(const prox_cyl *k, prox_vec3 x, prox_vec3 *q, prox_vec3 *n);

/* Clips the segment p + s (q - p), s in [0, 1], to the solid cylinder `cyl` (a const prox_cyl *)
 * enlarged by tol: prox_segment_clip_solid_cyl in the form of a prox_clip_fn (core/box.h). */
int prox_cyl_clip_segment(const void *cyl, prox_vec3 p, prox_vec3 q, double tol, double *s0, double *s1);

/* ---- containment (core/cyl_contain.c) ---- */

/* 1 when the circle (centre c, unit normal n, radius r) lies in the closed solid cylinder k enlarged
 * by tol (absolute): its axial range within [-tol, h + tol] and its farthest point from k's axis
 * within r + tol. Cheap accept / reject tests first, the exact farthest point only between them. */
int prox_cyl_contains_circle(const prox_cyl *k, prox_vec3 c, prox_vec3 n, double r, double tol);

/* Clearance of that circle in k: min over the circle of the distance to k's boundary when inside
 * (< 0 when it sticks out: minus how far, axially or radially): min(tc - r|n x w|, h - tc - r|n x w|,
 * k.r - farthest distance from the axis). */
double prox_cyl_circle_clearance(const prox_cyl *k, prox_vec3 c, prox_vec3 n, double r);

/* 1 when the solid cylinder `in` lies in the solid cylinder `out` enlarged by tol: both rims of `in`
 * do (out is convex, in the hull of its rims). Agarwal Fig. 2's nesting test. */
int prox_cyl_in_cyl(const prox_cyl *in, const prox_cyl *out, double tol);

/* Clearance of `in` in `out`: the smaller of its rims' clearances (inside, the distance to out's
 * boundary is concave, so its minimum over `in` is attained at an extreme point, i.e. on a rim). */
double prox_cyl_in_cyl_clearance(const prox_cyl *in, const prox_cyl *out);

/* Rim circle `end` (0 base, 1 top) with a frame: Duff et al.'s branch-free orthonormal basis of the
 * axis ("Building an orthonormal basis, revisited", JCGT 2017); both rims share it. */
prox_fcircle prox_cyl_rim(const prox_cyl *k, int end);

/* A point common to the solids a and b (src/core/common_point.c): each axis clipped by the other
 * solid, the mid-disks' common chord, then Douglas-Rachford between the solids shrunk by margins from
 * a quarter of the smallest dimension down to 0, `iters` steps each, started at `start`. Every point
 * is checked with prox_cyl_contains(., ., tol) in both. Returns 1 with the point in *out, else 0 with
 * the last iterate (a point of a) in *out. */
int prox_cyl_common_point(const prox_cyl *a, const prox_cyl *b, prox_vec3 start, int iters, double tol,
                          prox_vec3 *out);

#endif
