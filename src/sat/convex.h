/* Internal: the certified support-function method for ANY pair of convex bodies (core/body.h), the
 * fallback of every pair with no closed form (docs/algorithms/convex_engine.md). It uses only what
 * every body offers: the centred support function hc and point pc, membership, closest point; and,
 * per kind, the Hessian of hc where it is smooth and the directions where it is not (its kinks).
 *
 * With phi(D) = h_A(D) + h_B(-D) (D from A towards B; hc of the added kinds need not be even):
 *   disjoint:    distance = max_{|D|=1} -phi(D)   every D proves a lower bound (weak duality);
 *   overlapping: depth    = min_{|D|=1}  phi(D)   every D gives an upper bound (a separating move).
 * Both bodies are absolute (prox_body_make of VALIDATED shapes); the pair is solved relative to A's
 * reference point and at unit scale, and the answer is returned in the caller's coordinates. */
#ifndef PROX_SAT_CONVEX_H
#define PROX_SAT_CONVEX_H

#include "core/body.h"
#include "prox/result.h"

/* What an answer proved (caller's units). Disjoint: lower = the best -phi(D) (a proven lower bound
 * on the distance), upper = |p2 - p1| (an achieved pair); certified when upper - lower <=
 * PROX_TOL_CERT x S. Overlapping: upper = the depth reported (phi at the normal: a separating move of
 * that length exists), lower = a lower bound on the depth proved by an inner polytope of A - B
 * (epa.h), by tangent balls at the witnesses, or by covering the sphere of directions (a cap's bound
 * from the convexity of h and each body's exact minimum over the cap); certified when
 * upper - lower <= PROX_TOL_DEPTH_CERT x S. The distance query's overlap answer is certified when its
 * common point lies in both solids within PROX_TOL_TOUCH x S; lower = upper = 0 then. */
typedef struct prox_convex_info {
    int intersect;   /* 1 when the solids were found to share a point (or touch within the band) */
    int certified;   /* see above */
    double lower;    /* proven lower bound (distance or depth) */
    double upper;    /* upper bound (distance or depth) */
    int global;      /* 1 when the slow global search ran (counted by prox_convex_global_count) */
    long cells;      /* cells of the sphere of directions the depth certificate examined */
} prox_convex_info;

/* Distance: intersect, distance = |p2 - p1| (p1 in A, p2 in B), certificate_gap = the proven lower
 * bound (result.h), certified, method = PROX_METHOD_SUPPORT. Overlapping: p1 = p2 a common point. */
prox_distance_result prox_convex_distance(const prox_body *a, const prox_body *b);

/* Signed distance: sd > 0 the distance, sd <= 0 minus the penetration depth; normal the unit
 * direction from A towards B (moving B by -sd normal separates it when sd < 0); p1 on A's boundary,
 * p2 on B's, p2 - p1 = sd normal (within 1e-12 S disjoint, 1e-9 S overlapping). What it proved is
 * passed on for the enclosure (prox_body_signed_bounds): sd_lower = the duality bound when disjoint;
 * certified with sd_upper = -(the cover's lower bound of the depth) when the cover completed. */
prox_signed_result prox_convex_signed(const prox_body *a, const prox_body *b);

/* The witnesses of an overlap's depth already known: along the unit n with signed distance sd < 0
 * (n minimising phi), the pair of the support sets of A along n and B along -n whose difference is
 * nearest sd n (the sets seen along n meet there), as the engine's own answers take them. */
void prox_convex_overlap_witnesses(const prox_body *a, const prox_body *b, prox_vec3 n, double sd, prox_vec3 *p1,
                                   prox_vec3 *p2);

/* The same, with what it certified (info may be NULL). */
prox_signed_result prox_convex_signed_ex(const prox_body *a, const prox_body *b, prox_convex_info *info);
prox_distance_result prox_convex_distance_ex(const prox_body *a, const prox_body *b, prox_convex_info *info);

/* The same without the early exits (GJK's and Newton's certificates of a disjoint pair; the
 * depth's quick search, proved by an inner polytope (epa.h) or by tangent balls): the full search
 * and its certificate, the reference the tests hold the early exits to. */
prox_distance_result prox_convex_distance_full(const prox_body *a, const prox_body *b, prox_convex_info *info);
prox_signed_result prox_convex_signed_full(const prox_body *a, const prox_body *b, prox_convex_info *info);

/* Distance queries answered by an early exit since the start of the process (all threads). */
unsigned long prox_convex_gjk_certified_count(void);

/* How many times the slow global search has run since the start of the process (all threads): the
 * disjoint search's sweep of every kink circle when the local search could not certify (rare), and
 * the cover of the sphere that certifies a depth the quick search did not prove. */
unsigned long prox_convex_global_count(void);

#endif
