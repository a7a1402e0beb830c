/* Internal: input validation and local frames shared by the public primitive solvers (point_*.c,
 * segment_*.c, cylsurf_cylsurf.c, disk_*.c, circle_*.c); the angle conventions (core/angle.h), circle
 * frames and stationary points (core/circle.h) and tolerances (core/tol.h) are the core's, which the
 * other modules use without this header. One copy of each rule, so that
 * every primitive entry point rejects the same inputs with the same status, in the same order:
 * null pointer -> PROX_EINVAL_ARG, non-finite value -> PROX_EINVAL_NONFINITE, radius <= 0 ->
 * PROX_EINVAL_RADIUS, zero axis / normal -> PROX_EINVAL_AXIS. */
#ifndef PROX_DISTANCE_PRIM_COMMON_H
#define PROX_DISTANCE_PRIM_COMMON_H

#include "core/angle.h"
#include "core/circle.h"
#include "core/tol.h"

/* Coordinates of a point x in the frame of circle f: height h along n, components du, dv along u, v
 * and the distance rho = hypot(du, dv) from the axis. */
typedef struct prox_prim_local {
    double h, du, dv, rho;
} prox_prim_local;
static inline prox_prim_local prox_prim_local_of(const prox_fcircle *f, prox_vec3 x)
{
    prox_vec3 q = prox_v3_sub(x, f->c);
    prox_prim_local l;
    l.h = prox_v3_dot(q, f->n);
    l.du = prox_v3_dot(q, f->u);
    l.dv = prox_v3_dot(q, f->v);
    l.rho = hypot(l.du, l.dv);
    return l;
}
/* The angle of x's radial component in [0, 2pi); 0 on the axis (rho = 0). */
static inline double prox_prim_local_angle(const prox_prim_local *l)
{
    return l->rho > 0.0 ? prox_prim_angle(l->dv, l->du) : 0.0;
}

/* v / n component-wise (the unit normal or axis from a vector of norm n > 0). */
static inline prox_vec3 prox_prim_unit(prox_vec3 v, double n)
{
    return prox_v3(v.x / n, v.y / n, v.z / n);
}

/* t clamped to [0, 1]; NaN gives 0. */
static inline double prox_prim_clamp01(double t)
{
    return t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
}

/* Point of segment s at parameter t: the endpoints exactly, interior points relative to a (no
 * cancellation from far origins). */
static inline prox_vec3 prox_prim_segment_point(const prox_segment *s, double t)
{
    if (t == 0.0) return s->a;
    if (t == 1.0) return s->b;
    return prox_v3_mad(s->a, t, prox_v3_sub(s->b, s->a));
}

/* Validates a segment: non-null, finite endpoints and a finite difference b - a (two finite points
 * can be an overflowing distance apart). */
static inline prox_status prox_prim_segment_check(const prox_segment *s)
{
    if (!s) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(s->a) || !prox_v3_isfinite(s->b) || !prox_v3_isfinite(prox_v3_sub(s->b, s->a)))
        return PROX_EINVAL_NONFINITE;
    return PROX_OK;
}

/* Validates a circle or disk (non-null, finite, radius > 0, normal non-zero); *norm = |normal|. */
static inline prox_status prox_prim_circle_check(const prox_circle *c, double *norm)
{
    if (!c) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(c->center) || !prox_v3_isfinite(c->normal) || !isfinite(c->radius))
        return PROX_EINVAL_NONFINITE;
    if (!(c->radius > 0.0)) return PROX_EINVAL_RADIUS;
    double n = prox_v3_norm(c->normal);
    if (!(n > 0.0)) return PROX_EINVAL_AXIS;
    *norm = n;
    return PROX_OK;
}

/* Validates a circle or disk and returns its frame (prox_fcircle_make) with the normal divided by
 * its norm. */
static inline prox_status prox_prim_circle_frame(const prox_circle *c, prox_fcircle *f)
{
    double n;
    prox_status st = prox_prim_circle_check(c, &n);
    if (st != PROX_OK) return st;
    *f = prox_fcircle_make(c->center, prox_prim_unit(c->normal, n), c->radius);
    return PROX_OK;
}

/* Validates a circle or disk c and a segment s together: a null pointer first, then non-finite
 * values of either, then the circle's radius and normal; *f is c's frame (prox_prim_circle_frame). */
static inline prox_status prox_prim_circle_segment_check(const prox_circle *c, const prox_segment *s,
                                                         prox_fcircle *f)
{
    if (!c || !s) return PROX_EINVAL_ARG;
    prox_status st = prox_prim_segment_check(s);
    if (st != PROX_OK) return st;
    return prox_prim_circle_frame(c, f);
}

/* Validates a cylindrical surface (non-null, finite base / dir / radius, radius > 0, dir non-zero) and
 * returns its unit axis in *w. with_height: the finite surface, height must also be finite
 * (PROX_EINVAL_NONFINITE) and >= 0 (PROX_EINVAL_ARG, checked after the radius); otherwise the
 * surface is infinite and the height is ignored. */
static inline prox_status prox_prim_cylsurf_check(const prox_cylsurf *s, int with_height, prox_vec3 *w)
{
    if (!s) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(s->base) || !prox_v3_isfinite(s->dir) || !isfinite(s->radius) ||
        (with_height && !isfinite(s->height)))
        return PROX_EINVAL_NONFINITE;
    if (!(s->radius > 0.0)) return PROX_EINVAL_RADIUS;
    if (with_height && !(s->height >= 0.0)) return PROX_EINVAL_ARG;
    double n = prox_v3_norm(s->dir);
    if (!(n > 0.0)) return PROX_EINVAL_AXIS;
    *w = prox_prim_unit(s->dir, n);
    return PROX_OK;
}

#endif
