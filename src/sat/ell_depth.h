/* A proved lower bound of the penetration depth of two overlapping ellipsoids (ELL or SPH bodies) by
 * an ellipsoid inside their Minkowski difference (ell_depth.c). */
#ifndef PROX_SAT_ELL_DEPTH_H
#define PROX_SAT_ELL_DEPTH_H

#include "core/body.h"

/* 1 when both bodies are ellipsoids (PROX_BODY_ELL or PROX_BODY_SPH). */
int prox_ell_pair(const prox_body *a, const prox_body *b);

/* A lower bound of min over unit D of h_A(D) + h_B(-D) - D.delta (the depth of the pair whose centres
 * differ by delta = c_B - c_A; a and b are read centred), tight when n is the deepest direction;
 * -INFINITY when no ellipsoid proves a positive bound. S: the pair's scale (the bound's rounding is
 * subtracted from it). */
double prox_ell_depth_lower(const prox_body *a, const prox_body *b, prox_vec3 delta, prox_vec3 n, double S);

#endif
