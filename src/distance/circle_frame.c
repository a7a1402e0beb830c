/* Public circle frames: the angle parameter convention of core/circle.h (prox_fcircle_make). */
#include "core/circle.h"

PROX_API void prox_circle_frame(const prox_circle *c, prox_vec3 *u, prox_vec3 *v)
{
    *u = prox_v3_any_perp(c->normal);
    *v = prox_v3_cross(c->normal, *u);
}

PROX_API prox_vec3 prox_circle_point(const prox_circle *c, double theta)
{
    prox_fcircle f = prox_fcircle_make(c->center, c->normal, c->radius);
    return prox_fcircle_point(&f, theta);
}
