/* Internal (core): the boundary queries of core/curved.h with the outward unit normal at the nearest
 * boundary point: y = q + sd n (q, n relative to the body's reference point c, like y). The normal
 * comes from the feature q lies on (a cap's axis direction, the generator's normal, the ellipse's
 * gradient; on a rim the direction to y clamped into the rim's normal cone), not from y - q, whose
 * direction is rounding noise when y is within a few ulps of the boundary (the sphere pairs'
 * witness c - r n needs it exact). Implemented in core/cone.c, ecyl.c, ellb.c. */
#ifndef PROX_CORE_CURVED_NORMAL_H
#define PROX_CORE_CURVED_NORMAL_H

#include "core/curved.h"

double prox_cone_boundary_n(const prox_cone *k, prox_vec3 y, prox_vec3 *q, prox_vec3 *n);
double prox_ecyl_boundary_n(const prox_ecyl *k, prox_vec3 y, prox_vec3 *q, prox_vec3 *n);
double prox_ellb_boundary_n(const prox_ellb *k, prox_vec3 y, prox_vec3 *q, prox_vec3 *n);

#endif
