/// @file sat.h
/// Separating axes for two solid cylinders (Eberly, "Intersection of Cylinders"), signed distance,
/// penetration depth and repositioning through support functions, and the cross-check of the two
/// cylinder methods.
#ifndef PROX_SAT_H
#define PROX_SAT_H

#include "shapes.h"

/// Which test decided a SAT verdict.
typedef enum prox_sat_axis {
    PROX_SAT_NONE = 0,
    PROX_SAT_W0,         ///< axis of A
    PROX_SAT_W1,         ///< axis of B
    PROX_SAT_W0xW1,      ///< cross product of the axes
    PROX_SAT_PARALLEL,   ///< parallel-axes case
    PROX_SAT_PERP_W0,    ///< a direction perpendicular to W0 (convex F(t))
    PROX_SAT_PERP_W1,    ///< a direction perpendicular to W1
    PROX_SAT_OTHER,      ///< another direction (convex G over the tangent plane)
    PROX_SAT_CERTIFIED   ///< no separating direction: certified lower bound on the overlap
} prox_sat_axis;

/// Result of the test-intersection query.
typedef struct prox_sat_result {
    prox_status status;
    int intersect;           ///< 1 when the solids intersect (touching counts as intersecting)
    prox_vec3 direction;     ///< unit separating direction when separated (from A towards B)
    double value;            ///< the value that decided: the gap along `direction` (> 0 separated),
                             ///< or the certified bound proving no separating direction exists
    prox_sat_axis decided_by;
} prox_sat_result;

/// Signed distance of two convex shapes: > 0 distance, <= 0 minus the penetration depth.
typedef struct prox_signed_result {
    prox_status status;
    double sd;          ///< signed distance
    prox_vec3 normal;   ///< unit direction from A towards B: moving B by -sd*normal (sd < 0) separates
    prox_vec3 p1;       ///< witness in A
    prox_vec3 p2;       ///< witness in B; p2 - p1 = sd * normal
} prox_signed_result;

/// Eberly's separating-axis verdict for two solid cylinders, certified.
PROX_API prox_sat_result prox_rcc_sat(const prox_rcc *a, const prox_rcc *b);
/// Signed distance of two solid cylinders by support-function optimisation (both signs).
PROX_API prox_signed_result prox_rcc_signed_distance(const prox_rcc *a, const prox_rcc *b);

#endif
