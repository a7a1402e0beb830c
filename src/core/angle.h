/* Internal (core): the angle conventions of every circle solver: angles in [0, 2pi). */
#ifndef PROX_CORE_ANGLE_H
#define PROX_CORE_ANGLE_H

#include <math.h>

#include "prox/vec3.h"

/* Angle of the direction (x, y) in [0, 2pi) (atan2 wrapped; 2pi after rounding becomes 0). */
static inline double prox_prim_angle(double y, double x)
{
    double a = atan2(y, x);
    if (a < 0.0) a += 2.0 * PROX_PI;
    return a < 2.0 * PROX_PI ? a : 0.0;
}

/* Any finite angle wrapped into [0, 2pi). Equals prox_prim_angle(y, x) on t = atan2(y, x): fmod is
 * exact and |atan2| < 2pi. */
static inline double prox_prim_wrap_2pi(double t)
{
    t = fmod(t, 2.0 * PROX_PI);
    if (t < 0.0) t += 2.0 * PROX_PI;
    return t < 2.0 * PROX_PI ? t : 0.0;
}

#endif
