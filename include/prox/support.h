/// @file support.h
/// Support functions of the ten macrobodies and a generic signed distance of two convex shapes
/// computed from them alone (minimisation of h_A(D) + h_B(-D) over unit directions D).
#ifndef PROX_SUPPORT_H
#define PROX_SUPPORT_H

#include "result.h"
#include "shapes.h"

/// Support function h(d) = max over x in s of d.x (d need not be unit; h(0) = 0). The shape is not
/// validated here (hot path): call prox_shape_validate first.
PROX_API double prox_shape_support(const prox_shape *s, prox_vec3 d);
/// A point of s attaining prox_shape_support(s, d) (for d = 0: the centre of s).
PROX_API prox_vec3 prox_shape_support_point(const prox_shape *s, prox_vec3 d);
/// Reference point of a shape: the centre of symmetry of RCC, BOX, RPP, SPH, REC, ELL, RHP; the middle
/// of the axis of a TRC; the corners' centroid of a WED or an ARB. It lies inside the solid.
PROX_API prox_vec3 prox_shape_center(const prox_shape *s);
/// Size of a shape used for tolerances: largest edge, height, diameter.
PROX_API double prox_shape_size(const prox_shape *s);

/// Signed distance of two convex macrobodies from their support functions (any pair of kinds):
/// sd = -min over unit D of [h_A(D) + h_B(-D)]; > 0 is the distance, <= 0 minus the penetration depth.
/// normal is the minimising D (from A towards B), p1 in A, p2 in B with p2 - p1 = sd * normal
/// (up to the stated tolerance on degenerate, face-like contacts). Pairs of RCC, BOX, RPP and SPH run the
/// ridge search of docs/algorithms/sat.md; pairs with any other kind the general certified method of
/// docs/algorithms/convex_engine.md.
PROX_API prox_signed_result prox_shape_signed_distance_support(const prox_shape *a, const prox_shape *b);

#endif
