/// @file query.h
/// One entry point for every pair of MCNP macrobodies (RCC, BOX, RPP, SPH): intersection verdict,
/// exact distance and proximal points, signed distance (penetration depth), containment, relation and
/// repositioning. The generic prox_shape_* functions dispatch to the specialised pair solvers declared
/// below (an RPP is treated as the BOX it describes), so callers never switch on pair types.
/// Sources: the LANL TRX report LA-UR-13-26757 (Set 1 containment, Set 2 intersection, the
/// "prescription to reposition"), generalised and corrected; see docs/errata-trx.md and
/// docs/algorithms/boxes_spheres.md.
#ifndef PROX_QUERY_H
#define PROX_QUERY_H

#include "sat.h"
#include "shapes.h"

/// Default relative tolerance of the decisions (touching, nested): tol = PROX_QUERY_REL_TOL x scale.
#define PROX_QUERY_REL_TOL 1e-12

/// Result of prox_shape_test.
typedef struct prox_test_result {
    prox_status status;
    int intersect; ///< 1 when the closed solids share at least one point (touching counts)
} prox_test_result;

/// Result of a distance query. Start from {0}.
typedef struct prox_distance_result {
    prox_status status;
    int intersect;          ///< 1 when the solids share a point; then distance = 0 and p1 = p2 is one
    double distance;        ///< exact minimum distance (0 when intersecting)
    prox_vec3 p1;           ///< proximal point on A (a common point when intersecting)
    prox_vec3 p2;           ///< proximal point on B
    double certificate_gap; ///< disjoint: -h_B(-n) - h_A(n) for n = (p2-p1)/|p2-p1|, a lower bound on
                            ///< the distance from support functions; equal to it when certified
} prox_distance_result;

/// Result of prox_shape_contains: is A inside B (closed sets)?
typedef struct prox_contain_result {
    prox_status status;
    int inside;       ///< 1 when A lies in B (clearance >= -tol)
    double clearance; ///< min over A of the distance to B's boundary (>= 0 inside, < 0 when A sticks out)
} prox_contain_result;

/// How two solids lie relative to each other.
typedef enum prox_relation {
    PROX_REL_DISJOINT = 0, ///< positive distance
    PROX_REL_TOUCHING,     ///< boundaries meet, interiors disjoint (|signed distance| <= tol)
    PROX_REL_CROSSING,     ///< the surfaces intersect (penetration > tol), neither contains the other
    PROX_REL_A_IN_B,       ///< A is nested in B (possibly touching B's boundary from inside)
    PROX_REL_B_IN_A        ///< B is nested in A
} prox_relation;

/// Result of prox_shape_relation. Convention (docs/algorithms/boxes_spheres.md): nested takes precedence
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

/// Result of prox_shape_reposition.
typedef struct prox_reposition_result {
    prox_status status;
    int moved;              ///< 0 when B already clears A by the margin (translation = 0)
    prox_vec3 translation;  ///< add to B's position so that dist(A, B) = margin exactly
    double signed_distance; ///< signed distance before the move
    prox_vec3 normal;       ///< unit direction of the move (from A towards B)
} prox_reposition_result;

/// Scale of a pair used for tolerances: max of the centre distance and the sizes of both shapes.
/// Returns 0 for invalid shapes.
PROX_API double prox_shape_pair_scale(const prox_shape *a, const prox_shape *b);

/// Intersection verdict for any pair (exact up to PROX_QUERY_REL_TOL x scale at tangency).
PROX_API prox_test_result prox_shape_test(const prox_shape *a, const prox_shape *b);
/// Exact minimum distance and proximal points of any pair.
PROX_API prox_distance_result prox_shape_distance(const prox_shape *a, const prox_shape *b);
/// Signed distance of any pair: distance when disjoint, minus the penetration depth when overlapping,
/// with the unit normal (from A towards B) and witness points (p2 - p1 = sd normal).
PROX_API prox_signed_result prox_shape_signed_distance(const prox_shape *a, const prox_shape *b);
/// Does A lie entirely inside B (any position and orientation)?
PROX_API prox_contain_result prox_shape_contains(const prox_shape *a, const prox_shape *b);
/// Disjoint, touching, crossing or nested. tol < 0 selects PROX_QUERY_REL_TOL x scale; tol >= 0 is used
/// as given (tol = 0 leaves flush contacts to rounding). Nested wins over touching (see the result).
PROX_API prox_relation_result prox_shape_relation(const prox_shape *a, const prox_shape *b, double tol);
/// The translation to apply to B so that it clears A by `margin` (>= 0): zero when it already does,
/// otherwise (margin - sd) along the signed-distance normal (the TRX "prescription to reposition"),
/// then corrected once along the moved pair's own witness direction so that it ends margin apart.
PROX_API prox_reposition_result prox_shape_reposition(const prox_shape *a, const prox_shape *b, double margin);
/// B translated by t (any kind; an RPP stays an RPP). A null s gives a shape of invalid kind, so that
/// any query on it reports PROX_EINVAL_SHAPE_KIND; prox_shape_translated reports the status itself.
PROX_API prox_shape prox_shape_translate(const prox_shape *s, prox_vec3 t);
/// *out = s translated by t. PROX_EINVAL_ARG for a null pointer, PROX_EINVAL_NONFINITE for a non-finite
/// t, otherwise the validation status of the translated shape (*out is written only when PROX_OK).
PROX_API prox_status prox_shape_translated(const prox_shape *s, prox_vec3 t, prox_shape *out);

/* ---- Specialised pair solvers (validated inputs; public so that bench/ can time them) ---- */

/// BOX-BOX: separating-axis verdict over the 15 candidate axes.
PROX_API prox_test_result prox_box_box_test(const prox_box *a, const prox_box *b);
/// BOX-BOX exact distance: vertex-box and edge-edge features; a common point when overlapping.
PROX_API prox_distance_result prox_box_box_distance(const prox_box *a, const prox_box *b);
/// BOX-BOX signed distance; the depth is exact from the 15 SAT axes.
PROX_API prox_signed_result prox_box_box_signed_distance(const prox_box *a, const prox_box *b);

/// BOX-SPH exact distance (closest point of the box to the centre).
PROX_API prox_distance_result prox_box_sph_distance(const prox_box *a, const prox_sph *b);
/// BOX-SPH exact signed distance (signed distance of the centre to the box minus the radius).
PROX_API prox_signed_result prox_box_sph_signed_distance(const prox_box *a, const prox_sph *b);

/// SPH-SPH exact distance.
PROX_API prox_distance_result prox_sph_sph_distance(const prox_sph *a, const prox_sph *b);
/// SPH-SPH exact signed distance.
PROX_API prox_signed_result prox_sph_sph_signed_distance(const prox_sph *a, const prox_sph *b);

/// RCC-SPH exact distance (closest point of the cylinder to the centre).
PROX_API prox_distance_result prox_rcc_sph_distance(const prox_rcc *a, const prox_sph *b);
/// RCC-SPH exact signed distance (signed distance of the centre to the cylinder minus the radius).
PROX_API prox_signed_result prox_rcc_sph_signed_distance(const prox_rcc *a, const prox_sph *b);

/// BOX-RCC verdict: a box edge meets the cylinder, a rim circle meets the box, or the axis meets the box.
PROX_API prox_test_result prox_box_rcc_test(const prox_box *a, const prox_rcc *b);
/// BOX-RCC exact distance by features (box vertices and edges against the solid cylinder, rim circles
/// against box faces), certified by the support-function gap.
PROX_API prox_distance_result prox_box_rcc_distance(const prox_box *a, const prox_rcc *b);
/// BOX-RCC signed distance: exact distance when disjoint, support-function depth when overlapping.
PROX_API prox_signed_result prox_box_rcc_signed_distance(const prox_box *a, const prox_rcc *b);

/// Containment of A in B for the 9 ordered pairs (exact: A's extreme points against B).
PROX_API prox_contain_result prox_box_in_box(const prox_box *a, const prox_box *b);
PROX_API prox_contain_result prox_box_in_rcc(const prox_box *a, const prox_rcc *b);
PROX_API prox_contain_result prox_box_in_sph(const prox_box *a, const prox_sph *b);
PROX_API prox_contain_result prox_rcc_in_box(const prox_rcc *a, const prox_box *b);
PROX_API prox_contain_result prox_rcc_in_rcc(const prox_rcc *a, const prox_rcc *b);
PROX_API prox_contain_result prox_rcc_in_sph(const prox_rcc *a, const prox_sph *b);
PROX_API prox_contain_result prox_sph_in_box(const prox_sph *a, const prox_box *b);
PROX_API prox_contain_result prox_sph_in_rcc(const prox_sph *a, const prox_rcc *b);
PROX_API prox_contain_result prox_sph_in_sph(const prox_sph *a, const prox_sph *b);

#endif
