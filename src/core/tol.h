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

/* Scene broad phase: bounding volumes are enlarged by this relative slack, so that a pair whose
 * exact distance equals the query's threshold is never culled by the rounding of a bound. */
#define PROX_TOL_BROAD 1e-13

#endif
