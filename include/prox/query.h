/// @file query.h
/// One entry point for every pair of the ten MCNP macrobodies (RCC, BOX, RPP, SPH, TRC, REC, ELL,
/// RHP/HEX, WED, ARB): intersection verdict, exact distance and proximal points, signed distance
/// (penetration depth), containment, relation and repositioning. The generic prox_shape_* functions
/// dispatch to the cheapest exact solver of each pair (docs/algorithms/dispatch.md): the specialised
/// pair solvers of pairs.h among RCC, BOX, RPP (as the BOX it describes) and SPH; a sphere against
/// anything by the exact point-to-body distance; polytope pairs by features; every other pair by the
/// certified support-function method. Callers never switch on pair types.
/// Sources: the LANL TRX report LA-UR-13-26757 (Set 1 containment, Set 2 intersection, the
/// "prescription to reposition"), generalised and corrected; see docs/errata-trx.md and
/// docs/algorithms/boxes_spheres.md.
#ifndef PROX_QUERY_H
#define PROX_QUERY_H

#include "result.h"
#include "shapes.h"

/// Default relative tolerance of the decisions (touching, nested): tol = PROX_QUERY_REL_TOL x scale.
#define PROX_QUERY_REL_TOL 1e-12

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
/// *out = s translated by t. PROX_EINVAL_ARG for a null pointer, PROX_EINVAL_NONFINITE for a non-finite
/// t, otherwise the validation status of the translated shape (*out is written only when PROX_OK).
PROX_API prox_status prox_shape_translated(const prox_shape *s, prox_vec3 t, prox_shape *out);

#endif
