/* Internal (core): circles with their frames, and the stationary points of the primitive-pair distance
 * functions that involve circles (shared by every method that meets a rim).
 * The RCC-RCC query (rcc_rcc.c) needs every stationary point, not only the global minimum of a
 * primitive pair, because a local minimum of one primitive pair can be the global minimum of the
 * solids while the pair's own global minimum lies outside the finite cylinder. */
#ifndef PROX_CORE_CIRCLE_H
#define PROX_CORE_CIRCLE_H

#include "core/poly.h"
#include "prox/primitives.h"

/* A circle with its frame: point(theta) = c + r (cos theta u + sin theta v); n = u x v. */
typedef struct prox_fcircle {
    prox_vec3 c, u, v, n;
    double r;
} prox_fcircle;

/* A point of the unit circle (cos theta, sin theta): the fast paths carry angles this way, so that
 * no sine, cosine or arctangent is evaluated per Newton step. */
typedef struct prox_unit2 {
    double c, s;
} prox_unit2;

/* The unit vector of (x, y); (1, 0) when it has no direction. */
static inline prox_unit2 prox_unit2_of(double x, double y)
{
    double l = sqrt(x * x + y * y);
    prox_unit2 a = {1.0, 0.0};
    if (l > 0.0 && isfinite(l)) a.c = x / l, a.s = y / l;
    return a;
}

/* a rotated by -atan(d): the Newton update theta - d, with atan(d) = d - d^3/3 + ... in place of d,
 * which keeps the quadratic convergence (the difference is of third order in the step). */
static inline prox_unit2 prox_unit2_step(prox_unit2 a, double d)
{
    double k = 1.0 / sqrt(1.0 + d * d);
    prox_unit2 b = {(a.c + d * a.s) * k, (a.s - d * a.c) * k};
    return b;
}

/* Builds the frame with the same convention as prox_circle_frame (n must be unit); core/circle.c. */
prox_fcircle prox_fcircle_make(prox_vec3 center, prox_vec3 unit_normal, double radius);
static inline prox_vec3 prox_fcircle_point(const prox_fcircle *c, double th)
{
    return prox_v3_add(c->c, prox_v3_add(prox_v3_scale(c->u, c->r * cos(th)), prox_v3_scale(c->v, c->r * sin(th))));
}
/* The circle point at the angle given by its unit vector. */
static inline prox_vec3 prox_fcircle_at(const prox_fcircle *c, prox_unit2 a)
{
    return prox_v3_add(c->c, prox_v3_add(prox_v3_scale(c->u, c->r * a.c), prox_v3_scale(c->v, c->r * a.s)));
}

/* Every stationary angle of f(theta) = dist^2(point(theta), line) for the infinite line through p
 * with unit direction w (Agarwal Sec. 3.3, quartic in tan(theta/2); the angle pi is included when it
 * is stationary). Angles are polished by Newton on f'(theta) and returned in th[0..count-1], count <= 4.
 * Returns 1 when f is constant (line along the circle's axis): then count = 0; -PROX_ENUMERIC when the
 * quartic cannot be solved (then count = 0: callers must not read it as the constant case).
 * Implemented in core/circle_line.c with the two below. */
int prox_circle_line_stationary(const prox_fcircle *c, prox_vec3 p, prox_vec3 w, double th[4], int *count);

/* A stationary angle of the same function near a0 (Newton only, trig-free): the RCC-RCC fast path,
 * whose answer is then certified. */
prox_unit2 prox_circle_line_local(const prox_fcircle *c, prox_vec3 p, prox_vec3 w, prox_unit2 a0);

/* A local minimum near a0 of k t + rho over circle c, t and rho the axial and radial coordinates of its
 * points about the line through p with unit direction w: the distance to a cone's lateral surface
 * rho = rho0 - k t, up to a constant factor (k = 0: a cylinder's). Safeguarded Newton, trig-free: the
 * TRC pairs' fast path (distance/rim_pair.c), whose answer is then certified. */
prox_unit2 prox_circle_cone_local(const prox_fcircle *c, prox_vec3 p, prox_vec3 w, double k, prox_unit2 a0);

/* The parameter interval [*s0, *s1] within [0, 1] of the segment p + s (q - p) that lies in the solid
 * cylinder (base, unit axis w, height h, radius r) enlarged by tol; 0 when they do not meet. The
 * radial part is measured around the closest approach to the axis, not by the discriminant
 * B^2 - AC, which cancels for a long segment passing a thin cylinder. Implemented in core/cyl.c
 * (prox_cyl_clip_segment there takes a prepared prox_cyl). */
int prox_segment_clip_solid_cyl(prox_vec3 p, prox_vec3 q, prox_vec3 base, prox_vec3 w, double h, double r, double tol,
                                double *s0, double *s1);

/* The largest distance from the circle (centre, unit normal, radius; no frame needed) to the infinite
 * line through p with unit direction w
 * (the global maximum of the same function, without the quartic: the farthest point of the ellipse
 * c projects onto, one bracketed monotone root). */
double prox_circle_line_max_dist(prox_vec3 centre, prox_vec3 unit_normal, double radius, prox_vec3 p, prox_vec3 w);

/* Every stationary angle theta_a on circle a of g(theta_a) = dist^2(point_a(theta_a), circle b)
 * (Agarwal Sec. 3.5, degree 8 in tan(theta_a/2), rooted by the finder m: PROX_ROOTS_CHAIN or
 * PROX_ROOTS_GSL, core/poly.h; the angle pi is included when stationary), polished by Newton on the
 * trigonometric form; count <= 8. Implemented in core/circle_circle_stat.c.
 * The partner on b of a point x is the closest point of b to x (prox_fcircle_closest below).
 * Returns 1 when g is constant on a (coaxial circles, or a lies on b's axis... i.e. degenerate):
 * then count = 0 and callers treat the contact as a set. Returns -PROX_ENUMERIC when the root finder
 * fails (never 0 with a partial list). */
int prox_circle_circle_stationary(const prox_fcircle *a, const prox_fcircle *b, prox_root_method m, double th[8],
                                  int *count);

/* A stationary angle on circle a of dist^2(point_a(theta), circle b) near a0 (safeguarded Newton on
 * the trigonometric form, no polynomial, trig-free): the fast path of RCC-RCC, whose answer is then
 * certified. */
prox_unit2 prox_circle_circle_local(const prox_fcircle *a, const prox_fcircle *b, prox_unit2 a0);

/* Closest point of circle b to point x; *degenerate = 1 when x is on b's axis (every point of b is
 * closest: an arbitrary one is returned). */
prox_vec3 prox_fcircle_closest(const prox_fcircle *b, prox_vec3 x, int *degenerate);

#endif
