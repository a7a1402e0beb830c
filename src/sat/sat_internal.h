/* Internal: the support method's entry points for the composition layer (src/query/). Everything here
 * uses only the geometric core (src/core/), never the closed-form or fast distance (src/distance/), so
 * that comparing the two is an independent cross-check.
 *
 *   prox_sat_rcc_signed  the support method alone for both signs (the second method of the cross-check);
 *   prox_sat_rcc_depth   the penetration depth of a pair already known to overlap (for the public
 *                        signed distance: the fast distance when disjoint, this when overlapping);
 *   prox_rcc_distance_support (prox/sat.h) and prox_shape_signed_distance_support (prox/support.h) are
 *                        public. */
#ifndef PROX_SAT_INTERNAL_H
#define PROX_SAT_INTERNAL_H

#include "core/body.h"
#include "core/cyl.h"
#include "prox/result.h"
#include "prox/shapes.h"

#include <stddef.h>

/* The separating-axis verdict on prepared cylinders (both relative to the same origin). */
prox_test_result prox_sat_cyl(const prox_cyl *a, const prox_cyl *b);

/* A common point of two overlapping prepared cylinders from the final portal of the Minkowski portal
 * refinement (rcc_sat.c, portal_apart): 1 and *x when the portal certified the overlap (or ended in
 * the touching band, the point then within PROX_TOL_SEARCH x scale of both); 0 when the pair is
 * separated or the portal degenerate. The caller verifies the point (prox_cyl_contains). */
int prox_sat_common_point(const prox_cyl *a, const prox_cyl *b, prox_vec3 *x);

/* Signed distance of two solid cylinders by the support method alone (both signs): the SAT's
 * separating direction starts the certified minimisation of h_A(D) + h_B(-D); overlapping pairs take
 * the depth of prox_sat_rcc_depth. Validates both (status PROX_EINVAL_* on bad input, PROX_ENUMERIC
 * when a circle solver failed). */
prox_signed_result prox_sat_rcc_signed(const prox_rcc *a, const prox_rcc *b);

/* Penetration depth of two solid cylinders known to overlap (sd <= 0 up to the touching band):
 * enumeration of the strata (rcc_depth.c), the global search of sup_engine.c when a stratum cannot be
 * settled. Validates both. */
prox_signed_result prox_sat_rcc_depth(const prox_rcc *a, const prox_rcc *b);

/* prox_sat_rcc_depth with the proved enclosure of an overlapping answer (prox_body_signed_bounds,
 * evaluated on the pair at unit scale relative to A's base, then scaled back): *bounded = 1 when
 * sd_lower, sd_upper and certified are set (sd <= 0), else 0 and the caller bounds the answer. */
prox_signed_result prox_sat_rcc_depth_bounded(const prox_rcc *a, const prox_rcc *b, int *bounded);

/* Penetration depth of a box and a cylinder known to overlap: the closed-form enumeration of
 * box_rcc_depth.c, the global search of sup_engine.c for a degenerate pose (counted below), with the
 * proved enclosure of an overlapping answer as prox_sat_rcc_depth_bounded (*bounded = 1 when set).
 * Validates both. */
prox_signed_result prox_sat_box_rcc_depth_bounded(const prox_box *a, const prox_rcc *b, int *bounded);

/* How many overlapping box-cylinder pairs since start-up prox_sat_box_rcc_depth_bounded handed to the
 * global search. */
unsigned long long prox_sat_box_depth_fallbacks(void);

/* Penetration depth of an overlapping polytope (a POLY body) and a cylinder or a spheroid (a CYL or
 * ELL body), any scale and position: the closed-form enumeration of poly_curved_depth.c on the pair
 * at unit scale relative to the polytope, scaled back. 1 and *res (sd, normal, witnesses; sd_lower
 * and certified of the enumeration) when settled; 0 when the pair is degenerate, touching or
 * disjoint, counted below: the caller runs the global search. */
int prox_sat_poly_curved_depth(const prox_body *poly, const prox_body *curved, prox_signed_result *res);

/* How many pairs since start-up prox_sat_poly_curved_depth handed back to the global search. */
unsigned long long prox_sat_poly_depth_fallbacks(void);

/* How many overlapping cylinder pairs since start-up the depth enumeration could not settle and
 * handed to the global search of sup_engine.c (a rare fallback; the tests and the bench read it). */
unsigned long long prox_sat_depth_fallbacks(void);

/* sup_ridge_shadow (sup_engine.h) reduced to what the depth enumeration needs: candidate directions
 * (not unit, each with both signs) holding a MINIMISER of phi on the ridge D.w = 0 of `lat` (not every
 * stationary point: a half circle whose nearest-point foot lies inside it skips its middle-branch
 * feet). Same returns as sup_ridge_shadow (rcc_ridge_shadow.c). */
struct prox_body;
int sup_ridge_shadow_min(const struct prox_body *lat, const struct prox_body *oth, prox_vec3 delta, prox_vec3 *out,
                         int max);

/* Lower bound of phi over the ridge D.w = 0 of `lat` (rcc_ridge_shadow.c): r minus an upper bound of
 * the distance from delta's shadow to the other cylinder's shadow. The depth enumeration skips a
 * ridge whose bound exceeds its best value. */
double sup_ridge_shadow_lb(const struct prox_body *lat, const struct prox_body *oth, prox_vec3 delta);

#endif
