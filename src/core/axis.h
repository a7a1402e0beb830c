/* The part of a vector across a unit axis w, shared by the bodies of revolution (RCC, TRC, ELL):
 * their support points and half-plane coordinates all split a vector into its axial and radial
 * parts. */
#ifndef PROX_CORE_AXIS_H
#define PROX_CORE_AXIS_H

#include <math.h>

#include "core/tol.h"
#include "prox/vec3.h"

/* d - (d.w) w, rejected twice: for d nearly along the axis one pass leaves an O(eps |d|) residual
 * along w that normalising would blow up. */
static inline prox_vec3 prox_axis_across(prox_vec3 d, prox_vec3 w)
{
    prox_vec3 p = prox_v3_mad(d, -prox_v3_dot(d, w), w);
    return prox_v3_mad(p, -prox_v3_dot(p, w), w);
}

/* The unit radial direction of d about w, its length |d - (d.w) w| in *len. A radial part at the
 * rounding of d (|P d| <= PROX_TOL_NOISE max |d_i|) is d on the axis: its direction is noise and, for d
 * along w = (1, 1, 1) / sqrt 3 whose residual has three equal components, lies along w itself, which
 * would put a rim point on the axis beyond the cap. Then *len = 0 and any perpendicular is returned.
 * One square root (this is on every closest-point query of a TRC or an ELL); below 2^-1000 the
 * length's reciprocal would overflow, and prox_v3_normalize rescales first. */
static inline prox_vec3 prox_axis_radial(prox_vec3 d, prox_vec3 w, double *len)
{
    prox_vec3 p = prox_axis_across(d, w);
    /* the largest |d_i| by comparisons: fmax is a library call, and this runs on every support point */
    double ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z), m = ax > ay ? ax : ay, n = prox_v3_norm(p);
    m = m > az ? m : az;
    if (!(n > PROX_TOL_NOISE * m)) {
        *len = 0.0;
        return prox_v3_any_perp(w);
    }
    *len = n;
    return n >= 0x1p-1000 ? prox_v3_scale(p, 1.0 / n) : prox_v3_normalize(p);
}

#endif
