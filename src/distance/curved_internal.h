/* Internal (distance): closed forms for pairs of curved macrobodies (src/distance/curved_pairs.c).
 *
 * Coaxial solids of revolution: RCC, TRC, ELL and SPH whose axes lie on one line (a sphere's axis is
 * any line through its centre). Such a pair is symmetric under every rotation about the common axis,
 * so (docs/algorithms/curved.md, "Coaxial pairs"):
 *   - the distance and the signed distance are those of the two meridian sections in a plane
 *     through the axis (each section the full, mirror-symmetric convex section: a rectangle, an
 *     isosceles trapezoid or triangle, an ellipse), computed in 2D as
 *         sd = -min over unit n of [h_A(n) + h_B(-n)]
 *     over a finite set of candidate directions that contains the minimiser (edge normals,
 *     vertex-vertex directions, vertex-ellipse normals) or, for two ellipses, a safeguarded Newton
 *     iteration on the angle;
 *   - the solids meet exactly when their axis segments overlap (two convex sections symmetric about
 *     the axis that share a point (t, r) share (t, -r) and so (t, 0)), a common point then lying on
 *     the axis.
 * This is the configuration where the iterative methods are degenerate (a whole circle of optimal
 * directions), so the query layer can route it here. */
#ifndef PROX_DISTANCE_CURVED_INTERNAL_H
#define PROX_DISTANCE_CURVED_INTERNAL_H

#include "core/body.h"
#include "prox/result.h"
#include "prox/shapes.h"

/* 1 when a and b (valid shapes) are both RCC, TRC, ELL or SPH (not two spheres) on a common axis:
 * their axes parallel within PROX_TOL_COAXIAL_REV rad and each one's axis point (base centre of an
 * RCC or TRC, centre of an ELL or SPH) within PROX_TOL_COAXIAL_REV x the pair's scale, plus 8 ulps
 * of the coordinates, of the common axis line. */
int prox_coaxial_pair(const prox_shape *a, const prox_shape *b);

/* Signed distance of a coaxial pair (validated here; PROX_EUNSUPPORTED when not coaxial):
 * p2 - p1 = sd normal, p1 in a, p2 in b, normal from a towards b. */
prox_signed_result prox_coaxial_signed_distance(const prox_shape *a, const prox_shape *b);

/* Distance of a coaxial pair: intersect with a common point on the axis, or the distance, the
 * proximal points, the certificate gap from the 3D support functions (certified when it closes to
 * PROX_TOL_CERT x scale), and point_set when the proximal points are not unique (a circle about the
 * axis or parallel facets). */
prox_distance_result prox_coaxial_distance(const prox_shape *a, const prox_shape *b);

/* Distance of two disjoint rim solids, a TRC against a TRC or an RCC (bodies of valid shapes, either
 * order), by feature prediction (distance/rim_pair.c): 1 with the certified answer in *r and, when
 * normal is not NULL, the unit direction of its certificate in *normal (from A to B); 1 with a common
 * point (r->intersect) when a candidate found one; 0 when no candidate certified (overlapping,
 * touching, or missed: the caller runs the support method). */
int prox_rim_pair_distance(const prox_body *a, const prox_body *b, prox_distance_result *r, prox_vec3 *normal);

#endif
