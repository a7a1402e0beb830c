/// @file distance.h
/// Exact minimum distance and proximal points between two solid right circular cylinders
/// (Agarwal, Srivatsan & Bandyopadhyay 2016, with a dual certificate that makes the answer exact).
#ifndef PROX_DISTANCE_H
#define PROX_DISTANCE_H

#include "result.h"
#include "shapes.h"

/// Minimum distance, proximal points, interference and containment of two solid cylinders by the
/// default method (PROX_METHOD_FAST).
PROX_API prox_distance_result prox_rcc_distance(const prox_rcc *a, const prox_rcc *b);
/// The same question answered by the chosen method (prox_method). Every method is exact; they share
/// only the geometric core, so two of them check each other (prox_rcc_crosscheck).
PROX_API prox_distance_result prox_rcc_distance_ex(const prox_rcc *a, const prox_rcc *b, prox_method method);
/// Name of a method ("fast", "closed-form", "support"); NULL for an unknown value.
PROX_API const char *prox_method_name(prox_method m);
/// The method named s (as prox_method_name gives it); returns 0 and leaves *m alone when unknown.
PROX_API int prox_method_parse(const char *s, prox_method *m);

/// Scale of a pair used for tolerances: max(|cA - cB|, hA, hB, rA, rB), c the centres.
PROX_API double prox_rcc_pair_scale(const prox_rcc *a, const prox_rcc *b);

/// Support function of a cylinder in direction d (not necessarily unit): max over x in the cylinder of d.x.
PROX_API double prox_rcc_support(const prox_rcc *c, prox_vec3 d);
/// A point of the cylinder attaining prox_rcc_support(c, d).
PROX_API prox_vec3 prox_rcc_support_point(const prox_rcc *c, prox_vec3 d);
/// Closest point of the solid cylinder to x (x itself when inside).
PROX_API prox_vec3 prox_rcc_closest_point(const prox_rcc *c, prox_vec3 x);
/// 1 when x lies in the closed solid cylinder enlarged by tol (tol >= 0, absolute).
PROX_API int prox_rcc_contains_point(const prox_rcc *c, prox_vec3 x, double tol);

#endif
