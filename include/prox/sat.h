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

/// Result of prox_rcc_crosscheck: the closed-form distance (prox_rcc_distance) against the
/// separating-axis verdict (prox_rcc_sat) and the support-function signed distance.
typedef struct prox_crosscheck_result {
    prox_status status;
    int agree;               ///< 1 when verdicts and (disjoint) distances agree, or the pair is within tol of touching
    int verdict_agree;       ///< the two intersect verdicts are equal
    int intersect_distance;  ///< verdict of prox_rcc_distance (its `interfere`)
    int intersect_sat;       ///< verdict of prox_rcc_sat
    double distance;         ///< prox_rcc_distance's distance
    double sd;               ///< the support-function signed distance (independent of prox_rcc_distance)
    double sat_value;        ///< prox_rcc_sat's deciding value (gap when separated)
    double distance_diff;    ///< |distance - max(sd, 0)| (by duality 0 for disjoint pairs)
    double margin;           ///< |sd| / scale: distance of the pair from touching, relative
    double scale;            ///< prox_rcc_pair_scale
    double tol;              ///< absolute tolerance used: 1e-12 x scale + 8 eps x coordinate size
} prox_crosscheck_result;

/// Eberly's separating-axis verdict for two solid cylinders, certified.
PROX_API prox_sat_result prox_rcc_sat(const prox_rcc *a, const prox_rcc *b);
/// Signed distance of two solid cylinders by support-function optimisation (both signs).
PROX_API prox_signed_result prox_rcc_signed_distance(const prox_rcc *a, const prox_rcc *b);

/// Runs both cylinder methods and reports whether they agree (verdict; distance against the
/// support-function gap for disjoint pairs), with the margin.
PROX_API prox_crosscheck_result prox_rcc_crosscheck(const prox_rcc *a, const prox_rcc *b);

#endif
