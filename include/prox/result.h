/// @file result.h
/// The result types of prox: one per question, shared by every pair of shapes and every method, with
/// the same field names everywhere. Every result starts with a `status`; when it is not PROX_OK the
/// other fields are zero.
///
/// | question | result | answered by |
/// |---|---|---|
/// | do they intersect? | prox_test_result | prox_shape_test, prox_rcc_sat |
/// | how far apart, where? | prox_distance_result | prox_shape_distance, prox_rcc_distance(_ex) |
/// | signed distance / depth | prox_signed_result | prox_shape_signed_distance, prox_rcc_signed_distance |
/// | is A inside B? | prox_contain_result | prox_shape_contains |
/// | how do they lie? | prox_relation_result | prox_shape_relation |
/// | how far to move B? | prox_reposition_result | prox_shape_reposition |
#ifndef PROX_RESULT_H
#define PROX_RESULT_H

#include "status.h"
#include "vec3.h"

/// The method that answers a cylinder-pair question (docs/design.md, "Three cylinder methods").
/// The three share only the geometric core (src/core/): each is exact on its own, so comparing two
/// of them is an independent cross-check.
typedef enum prox_method {
    PROX_METHOD_FAST = 0,     ///< prediction of the deciding feature pair + duality certificate;
                              ///< falls back to PROX_METHOD_CLOSED_FORM when it cannot certify
    PROX_METHOD_CLOSED_FORM,  ///< Agarwal's complete primitive decomposition (every feature pair, the
                              ///< degree-8 circle-circle polynomial rooted by GSL) with the certificate
    PROX_METHOD_SUPPORT,      ///< separating axes and certified support-function optimisation (Eberly)
    PROX_METHOD_COUNT_
} prox_method;

/// The cylinder feature a proximal point lies on.
typedef enum prox_feature {
    PROX_FEAT_NONE = 0,
    PROX_FEAT_LATERAL,  ///< the cylindrical surface S
    PROX_FEAT_BASE,     ///< interior of the base disk D^b
    PROX_FEAT_TOP,      ///< interior of the top disk D^t
    PROX_FEAT_RIM_BASE, ///< the base circle C^b
    PROX_FEAT_RIM_TOP,  ///< the top circle C^t
    PROX_FEAT_INSIDE    ///< the point is interior (overlap witness)
} prox_feature;

/// Which primitive pair produced the minimum.
typedef enum prox_pair_kind {
    PROX_PAIR_NONE = 0,  ///< no minimum computed (error), another shape pair, or the support method
    PROX_PAIR_SS,        ///< surface-surface P(S,S); a disk against a side (perpendicular axes) is
                         ///< reported as CS, its minimum being attained at a rim point too
    PROX_PAIR_CS,        ///< circle (rim of one) - surface (of the other), P(C,L) - r
    PROX_PAIR_CD,        ///< circle - disk interior, P(D,C); parallel end faces (D-D) are reported
                         ///< here with point_set, as their minimum is also attained at a rim point
    PROX_PAIR_CC,        ///< circle - circle P(C,C)
    PROX_PAIR_OVERLAP    ///< the solids overlap; p1 = p2 is a common point
} prox_pair_kind;

/// Agarwal's case of the initial P(S1,S2) classification (Fig. 3): 1 both feet on the cylinders,
/// 21 / 22 one foot off (Case 2.1 / 2.2), 3 both off. 0 when parallel axes skip it.
typedef enum prox_agarwal_case {
    PROX_CASE_NONE = 0,
    PROX_CASE_1 = 10,
    PROX_CASE_2_1 = 21,
    PROX_CASE_2_2 = 22,
    PROX_CASE_3 = 30
} prox_agarwal_case;

/// Which test decided a verdict of the separating-axis method.
typedef enum prox_sat_axis {
    PROX_SAT_NONE = 0,   ///< not decided by an axis test (another method or shape pair)
    PROX_SAT_W0,         ///< axis of A
    PROX_SAT_W1,         ///< axis of B
    PROX_SAT_W0xW1,      ///< cross product of the axes
    PROX_SAT_PARALLEL,   ///< parallel-axes case
    PROX_SAT_PERP_W0,    ///< a direction perpendicular to W0 (convex F(t))
    PROX_SAT_PERP_W1,    ///< a direction perpendicular to W1
    PROX_SAT_OTHER,      ///< another direction (convex G over the tangent plane)
    PROX_SAT_CERTIFIED   ///< no separating direction: certified lower bound on the overlap
} prox_sat_axis;

/// Result of an intersection test (the verdict question).
typedef struct prox_test_result {
    prox_status status;
    int intersect;           ///< 1 when the closed solids share at least one point (touching counts)
    prox_vec3 direction;     ///< unit separating direction from A towards B when one was found, else 0
    double value;            ///< the value that decided: the gap along `direction` (> 0 separated), or
                             ///< the certified bound proving no separating direction exists (<= 0); 0
                             ///< when the pair's solver decides by features
    prox_sat_axis decided_by;
} prox_test_result;

/// Result of a distance query (any pair of shapes, any method). Start from {0}.
typedef struct prox_distance_result {
    prox_status status;
    int intersect;          ///< 1 when the solids share a point; then distance = 0 and p1 = p2 is one
    double distance;        ///< exact minimum distance (0 when intersecting)
    prox_vec3 p1;           ///< proximal point on A (a common point when intersecting)
    prox_vec3 p2;           ///< proximal point on B
    double certificate_gap; ///< disjoint: a lower bound on the distance from a separating direction n,
                            ///< -h_B(-n) - h_A(n) (support functions); equal to it when certified
    int certified;          ///< 1 when the answer is proved: disjoint with distance - certificate_gap
                            ///< within PROX_TOL_CERT x scale, or a common point checked in both solids
    int a_in_b;             ///< A lies inside B (closed sets); set by the cylinder-pair methods
    int b_in_a;             ///< B lies inside A
    prox_method method;     ///< the method that produced the answer (cylinder pairs)
    /* Cylinder-pair details (Agarwal's terms); zero for other shape pairs and the support method. */
    prox_pair_kind pair;        ///< primitive pair that produced the minimum
    prox_feature feature1;      ///< feature of A holding p1
    prox_feature feature2;      ///< feature of B holding p2
    prox_agarwal_case agarwal;  ///< the case of Agarwal's first-level classification
    int hierarchy_exact;        ///< 1 when Agarwal's hierarchy alone gave the certified minimum
    int point_set;              ///< proximal points form a set (parallel faces or axes); one pair given
} prox_distance_result;

/// Signed distance of two convex shapes: > 0 distance, <= 0 minus the penetration depth.
typedef struct prox_signed_result {
    prox_status status;
    double sd;          ///< signed distance
    prox_vec3 normal;   ///< unit direction from A towards B: moving B by -sd*normal (sd < 0) separates
    prox_vec3 p1;       ///< witness in A
    prox_vec3 p2;       ///< witness in B; p2 - p1 = sd * normal
    /* What is proved about sd: an enclosure sd_lower <= sd* <= sd_upper of the true signed distance
     * sd*, from the support functions at the answer's normal and the answer's own proof. */
    double sd_lower;    ///< gap of the projections along normal, -h_A(n) - h_B(-n) (weak duality: a
                        ///< lower bound for every unit n), less its rounding
    double sd_upper;    ///< disjoint: |p2 - p1| with p1 in A and p2 in B, plus their rounding;
                        ///< overlapping: sd (plus rounding) when the method proved the depth (every
                        ///< deciding feature enumerated, or the directions covered), else 0 (a common point)
    int certified;      ///< 1 when sd_upper - sd_lower is within the accuracy bar: 1e-12 x scale
                        ///< (PROX_TOL_TOUCH) when disjoint, 1e-9 x scale (PROX_TOL_DEPTH_BAR) when overlapping
} prox_signed_result;

/// Result of a containment query: is A inside B (closed sets)?
typedef struct prox_contain_result {
    prox_status status;
    int inside;       ///< 1 when A lies in B (clearance >= -tol)
    double clearance; ///< nested: min over A of the distance to B's boundary (exact); when A sticks out, a
                      ///< negative number whose magnitude is at most how far A sticks out
} prox_contain_result;

/// How two solids lie relative to each other.
typedef enum prox_relation {
    PROX_REL_DISJOINT = 0, ///< positive distance
    PROX_REL_TOUCHING,     ///< boundaries meet, interiors disjoint (|signed distance| <= tol)
    PROX_REL_CROSSING,     ///< the surfaces intersect (penetration > tol), neither contains the other
    PROX_REL_A_IN_B,       ///< A is nested in B (possibly touching B's boundary from inside)
    PROX_REL_B_IN_A        ///< B is nested in A
} prox_relation;

/// Result of a relation query. Convention (docs/algorithms/boxes_spheres.md): nested takes precedence
/// over touching: an inner solid touching the outer boundary from inside (clearance in [-tol, tol]) is
/// A_IN_B / B_IN_A with `contact` = 1; TOUCHING is reserved for contact from outside.
typedef struct prox_relation_result {
    prox_status status;
    prox_relation relation;
    double signed_distance; ///< > 0 distance, <= 0 minus the penetration depth
    double clearance;       ///< nested: clearance of the inner solid inside the outer one
    double tol;             ///< the absolute tolerance used
    int contact;            ///< 1 when the boundaries meet: touching, crossing, or nested with clearance <= tol
} prox_relation_result;

/// Result of a reposition query.
typedef struct prox_reposition_result {
    prox_status status;
    int moved;              ///< 0 when B already clears A by the margin (translation = 0)
    prox_vec3 translation;  ///< add to B's position so that dist(A, B) = margin exactly
    double signed_distance; ///< signed distance before the move
    prox_vec3 normal;       ///< unit direction of the move (from A towards B)
} prox_reposition_result;

#endif
