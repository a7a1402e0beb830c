/* Internal: every tolerance of the library, named once, each with why it has its value.
 * Relative tolerances multiply the pair's scale S (max of the centre distance and the sizes, as in
 * tests/data/README.md) unless the line says otherwise; eps is DBL_EPSILON. */
#ifndef PROX_CORE_TOL_H
#define PROX_CORE_TOL_H

#include <float.h>

/* Certificate slack: a disjoint answer is proved when gap(n) >= |p2 - p1| - PROX_TOL_CERT S.
 * gap(n) and |p2 - p1| are each computed to a few ulps of S, so 64 eps covers both roundings. */
#define PROX_TOL_CERT (64.0 * DBL_EPSILON)

/* Two unit directions are parallel when |u x v| <= PROX_TOL_PARALLEL: the primitive solvers then
 * take their parallel branch (a set of closest points), and the point-set flags are raised. Below
 * it the feet of a common perpendicular move by more than 1e-4 S per ulp of the directions. */
#define PROX_TOL_PARALLEL 1e-12

/* Feet of the common perpendicular of two axes are well conditioned when |wA x wB| >= this (about
 * 1e-3 rad): an error e in the directions moves the feet by e/|wA x wB| <= 1e3 e, which keeps Case 1's
 * uncertified S-S answer at 1e-13 S. Below it the S-S normal comes from rejections and the answer
 * goes through the certificate. Squared form: PROX_TOL_WELL_COND2. */
#define PROX_TOL_WELL_COND 1e-3
#define PROX_TOL_WELL_COND2 1e-6

/* Two candidate distances within PROX_TOL_TIE S are a tie: the one with the more informative
 * feature pair is kept (the answer is the same to 1e-9 S, the flags differ). */
#define PROX_TOL_TIE 1e-9

/* A direction within |sin| <= PROX_TOL_FACE of a face normal or of perpendicular to a cylinder axis
 * supports the whole face or side segment: witness points are then taken from that set, not from
 * its one extreme point. MCNP decks print directions to about 10 digits, so flush faces in a deck
 * are parallel to ~1e-10. */
#define PROX_TOL_FACE 1e-9

/* A radial offset below 64 eps (|offset| + r) is rounding noise: its direction means nothing
 * (coaxial circles, a point on an axis). */
#define PROX_TOL_NOISE (64.0 * DBL_EPSILON)

/* Relative stopping tolerance of the support-function searches (separating axis, portal
 * refinement): the bound they certify is within 1e-13 S of the optimum, below the 1e-12 S the
 * answers promise. */
#define PROX_TOL_SEARCH 1e-13

/* The touching band: pairs within PROX_TOL_TOUCH S of touching may be reported either way (the
 * accuracy the answers promise). A touching pair's solids may share no point at all in floating point,
 * so a common point within this of both solids is accepted as the overlap witness. */
#define PROX_TOL_TOUCH 1e-12

/* Scene broad phase: bounding volumes are enlarged by this relative slack, so that a pair whose
 * exact distance equals the query's threshold is never culled by the rounding of a bound. */
#define PROX_TOL_BROAD 1e-13

/* ---- primitive and circle geometry (src/core/circle*.c, src/distance primitives, boxes) ---- */

/* A point within PROX_TOL_AXIS (8 eps) x the scale of an axis lies on it: every angle around the axis is
 * then equidistant (the set case of point-circle, point-surface, circle-circle contacts). */
#define PROX_TOL_AXIS (8.0 * DBL_EPSILON)

/* A radial offset below PROX_TOL_RADIAL x (axial coordinate, offset, radius) is rounding noise of the
 * rejection from the axis: any perpendicular direction is then as good as the computed one
 * (prox_cyl_signed: the outward normal of a point on the axis). */
#define PROX_TOL_RADIAL 1e-12

/* A segment parameter within PROX_TOL_PARAM of [0, 1] is an endpoint up to the rounding of the
 * parameter (a crossing at an endpoint): it is clamped onto the segment instead of dropped. */
#define PROX_TOL_PARAM 1e-12

/* Closest points of two segments: when sin^2 of their angle is below PROX_TOL_SEG_PARALLEL2 the 2x2
 * system is singular to rounding and s = 0 is taken; the endpoint pairs tried within 1e-3 rad of
 * parallel (PROX_TOL_WELL_COND2) then give the answer. */
#define PROX_TOL_SEG_PARALLEL2 1e-14

/* Box-box separating axes: edge cross products a_i x b_j shorter than this (the sine of the edges'
 * angle) are skipped; the face axes and the other cross axes decide. Skipping costs at most this x scale
 * in depth (the Minkowski facet of two edges at angle e differs from the facets of the plane
 * orthogonal to them by O(e size)), far inside the 1e-9 S depth accuracy. */
#define PROX_TOL_EDGE_AXIS 1e-10

/* An angle below PROX_TOL_FLAT (radians) changes a cosine by at most 5e-17 (second order): a circle
 * whose normal is that close to a line's direction projects along it onto a circle to 5e-17 r, and an
 * axis that close to a circle's plane is taken parallel to it. */
#define PROX_TOL_FLAT 1e-8

/* Circle-circle stationary points (Agarwal Sec. 3.5): after polishing, |h| = g'/2 below
 * PROX_TOL_CC_STAT x scale^2 is stationary; a spurious root of the squared degree-8 equation keeps
 * |h| = 2 |C.P'|, of the order of the scale. */
#define PROX_TOL_CC_STAT 1e-8

/* Two circles are coaxial (the distance from one to the other is constant) when the normal of b is
 * along a's and b's centre on a's axis to 16 eps (relative): the degree-8 equation vanishes there. */
#define PROX_TOL_COAXIAL (16.0 * DBL_EPSILON)

/* Circle a meets b's axis when the crossing point is within PROX_TOL_CC_AXIS_MEET x r_a of the circle:
 * the distance has a cusp there that Newton cannot polish, so the angle is offered as it is (a wrong
 * extra angle is only one more candidate, never a wrong answer). */
#define PROX_TOL_CC_AXIS_MEET 1e-6

/* Stationary angles closer than this (radians) are one point: circle-circle (polished to ~1e-12 on
 * the trigonometric form), circle-line (the quartic's roots are polished further). */
#define PROX_TOL_CC_DEDUP 1e-9
#define PROX_TOL_CL_DEDUP 1e-10

/* Circle-line quartic in tan(theta/2): theta = pi is sent to infinity, so it is added when h(pi), the
 * leading coefficient, is below PROX_TOL_CL_PI x the largest coefficient (an extra angle is harmless). */
#define PROX_TOL_CL_PI 1e-6

/* Newton on an angle: a step below PROX_TOL_NEWTON_QUAD rad is in the quadratic regime (the error left
 * is of order step^2, below 1e-17); below PROX_TOL_DESCENT_ROUND rad a descent step's decrease of the
 * distance is rounding, so convergence is judged by |h| instead. */
#define PROX_TOL_NEWTON_QUAD 1e-9
#define PROX_TOL_DESCENT_ROUND 1e-7

/* ---- the fast RCC-RCC method (src/distance/rcc_rcc.c) ---- */

/* Axes with |wA x wB| <= PROX_TOL_NO_FEET have no usable common perpendicular: its feet, divided by
 * |wA x wB|^2, would move by more than 0.1 S per ulp of the directions, so Agarwal's first-level
 * classification and the S-S candidate are skipped and the other candidates decide. */
#define PROX_TOL_NO_FEET 1e-15

/* Prediction of the feature supporting a direction n (a guess, every candidate it selects is
 * certified): the end disk when n is within PROX_PREDICT_ANGLE rad (~0.57 degree) of the axis, the
 * lateral surface when within that angle of perpendicular to it, else a rim. */
#define PROX_PREDICT_ANGLE 1e-2

/* ---- support-function search (src/sat/sup_engine.c, rcc_depth.c) ---- */

/* A unit direction D is near a kink of phi when |D.w| < PROX_TOL_KINK (a ridge: a lateral line or a
 * box face supports) or 1 - |D.W| < PROX_TOL_CONE (a cone point: a disk supports; |P D| < 1e-5 there).
 * The nonsmooth search stalls a few 1e-7 rad off a kink; within these it is snapped onto the kink,
 * escaped from along the centre subgradient, or polished on it. */
#define PROX_TOL_KINK 1e-5
#define PROX_TOL_CONE 5e-11

/* Near a cone point (|P D| below PROX_TOL_CONE_PERP) the radial part of a cylinder's support point is
 * arbitrary: the centre of the subdifferential drops it. */
#define PROX_TOL_CONE_PERP 1e-6

/* Three values of phi PROX_TOL_KINK_PROBE rad apart decide whether a kink on a ridge is a minimum
 * (Newton cannot converge onto a kink); wider than the search's stall, narrower than any feature. */
#define PROX_TOL_KINK_PROBE 1e-7

/* Two search starts closer than 1 - cos = PROX_TOL_SAME_START are one. */
#define PROX_TOL_SAME_START 1e-8

/* Newton on the sphere has converged when its decrement is below PROX_TOL_DECREMENT x S (phi's own
 * rounding is ~1e-16 S), or its step below PROX_TOL_STEP rad (the direction's rounding). */
#define PROX_TOL_DECREMENT 1e-17
#define PROX_TOL_STEP 1e-13

/* Rounding of phi: values within PROX_TOL_PHI_ROUND x S are equal (a kink's three-point test, the
 * snap onto a kink accepts a value that much worse). */
#define PROX_TOL_PHI_ROUND (16.0 * DBL_EPSILON)

/* The snap onto a kink accepts a value of phi at most PROX_TOL_SNAP x S worse (its rounding): any
 * more and the distance it reports falls short of the true one (face-lat pairs 3e-12 short when the
 * snap accepted 1e-12 S). GJK on the support points of K stops when its two bounds meet to the same. */
#define PROX_TOL_SNAP (4.0 * DBL_EPSILON)

/* A Newton bracket on an angle narrower than PROX_TOL_ANGLE rad is at the rounding of the angle. */
#define PROX_TOL_ANGLE 1e-14

/* Rim-rim contact normal: the line between the points when they are more than PROX_TOL_CC_NEAR S
 * apart (its direction error eps S / d is then below 1e-12, and the certificate loses only its square);
 * nearer, the cross product of the two tangents, which stays accurate as the points meet. */
#define PROX_TOL_CC_NEAR 1e-4

/* The tangents' cross product is used as that normal only when it exceeds PROX_TOL_TANGENT x |tangent|
 * (tangents not parallel to ~1e-6 rad): nearer to parallel its direction is rounding noise. */
#define PROX_TOL_TANGENT 1e-6

/* Circle-circle degree-8 polynomial, built in the frame of circle a normalised by its radius: its
 * coefficients grow as M^4, M = (|cb - ca| + ra + rb) / ra, so it is formed only for M <= PROX_CC_RANGE
 * (M^4 <= 1e256, far from overflow). Beyond it circle a is a point to within 1e-64 of the pair's extent,
 * and the pair is solved from circle b, or (both beyond) any rim point stands for each rim. */
#define PROX_CC_RANGE 1e64

#endif
