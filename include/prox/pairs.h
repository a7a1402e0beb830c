/// @file pairs.h
/// The advanced layer: the specialised solver of each pair of shape kinds, which prox_shape_* (query.h)
/// dispatches to. Call them directly to skip the dispatch (a few ns) when the kinds are known; each
/// validates its input and returns the same result types as the generic queries (result.h). An RPP
/// is passed as the BOX it describes (prox_rpp_to_box).
#ifndef PROX_PAIRS_H
#define PROX_PAIRS_H

#include "result.h"
#include "shapes.h"


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
