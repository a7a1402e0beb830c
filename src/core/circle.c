/* Circles with their frames (core/circle.h): the angle parameter convention shared by every circle
 * solver, and the closest point of a circle to a point. */
#include "core/circle.h"

prox_fcircle prox_fcircle_make(prox_vec3 center, prox_vec3 unit_normal, double radius)
{
    prox_fcircle f;
    f.c = center;
    f.n = unit_normal;
    f.u = prox_v3_any_perp(unit_normal);
    f.v = prox_v3_cross(unit_normal, f.u);
    f.r = radius;
    return f;
}

/* Closest point of circle b to x: the radial projection of x onto b's plane, scaled to radius r. */
prox_vec3 prox_fcircle_closest(const prox_fcircle *b, prox_vec3 x, int *degenerate)
{
    prox_vec3 d = prox_v3_sub(x, b->c);
    double du = prox_v3_dot(d, b->u), dv = prox_v3_dot(d, b->v);
    double rho = prox_hypot2(du, dv);
    if (degenerate) *degenerate = 0;
    if (!(rho > 0.0)) {
        if (degenerate) *degenerate = 1;
        return prox_v3_mad(b->c, b->r, b->u);
    }
    double s = b->r / rho;
    return prox_v3_add(b->c, prox_v3_add(prox_v3_scale(b->u, du * s), prox_v3_scale(b->v, dv * s)));
}
