/// @file sat.h
/// The support-function method for two solid cylinders: the intersection verdict by separating axes
/// (Eberly, "Intersection of Cylinders": the axis tests, then Minkowski portal refinement with a
/// certified bound where no axis test decides), and signed distance, distance and penetration depth
/// by certified minimisation of h_A(D) + h_B(-D) over unit directions D. The support method
/// (prox_rcc_sat, prox_rcc_distance_support) uses nothing of the fast or closed-form method but the
/// geometric core, so that prox_rcc_crosscheck compares independent answers; prox_rcc_signed_distance
/// and prox_rcc_crosscheck compose the methods (the fast distance when disjoint, the support method's
/// depth when overlapping).
#ifndef PROX_SAT_H
#define PROX_SAT_H

#include "result.h"
#include "shapes.h"

/// Result of prox_rcc_crosscheck: two independent cylinder methods on the same pair.
typedef struct prox_crosscheck_result {
    prox_status status;
    int agree;               ///< 1 when verdicts and (disjoint) distances agree, or the pair is within tol of touching
    int verdict_agree;       ///< the two intersect verdicts are equal
    int intersect_distance;  ///< verdict of the first method (closed form or fast)
    int intersect_sat;       ///< verdict of the separating-axis test (prox_rcc_sat)
    double distance;         ///< the first method's distance
    double sd;               ///< the support method's signed distance
    double sat_value;        ///< prox_rcc_sat's deciding value (gap when separated)
    double distance_diff;    ///< |distance - max(sd, 0)| (by duality 0 for disjoint pairs)
    double margin;           ///< |sd| / scale: distance of the pair from touching, relative
    double scale;            ///< prox_rcc_pair_scale
    double tol;              ///< absolute tolerance used: 1e-12 x scale + 8 eps x coordinate size
} prox_crosscheck_result;

/// Intersection verdict of two solid cylinders by separating axes, certified.
PROX_API prox_test_result prox_rcc_sat(const prox_rcc *a, const prox_rcc *b);
/// Signed distance of two solid cylinders: the exact distance when disjoint, minus the penetration
/// depth when overlapping, with the normal and witness points.
PROX_API prox_signed_result prox_rcc_signed_distance(const prox_rcc *a, const prox_rcc *b);
/// Distance and proximal points by the support-function method alone (PROX_METHOD_SUPPORT):
/// prox_rcc_distance_ex(a, b, PROX_METHOD_SUPPORT) calls this. Disjoint pairs: distance = |p2 - p1|
/// for the closest pair of the support sets along the optimal normal, certificate_gap the lower bound
/// along it. Overlapping pairs: a common point checked in both solids and the containment flags; the
/// Agarwal fields (pair, features, case) stay zero.
PROX_API prox_distance_result prox_rcc_distance_support(const prox_rcc *a, const prox_rcc *b);

/// Runs the closed-form method and the support method (which share only the geometric core) and
/// reports whether they agree (verdict; distance against the support-function gap for disjoint
/// pairs), with the margin.
PROX_API prox_crosscheck_result prox_rcc_crosscheck(const prox_rcc *a, const prox_rcc *b);

#endif
