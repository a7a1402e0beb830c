/* Internal: the support-function engine shared by the signed distance of any two macrobodies, the
 * support method's cylinder distance and the penetration depth. A shape is a core prox_body
 * (core/body.h): its centre c plus a centred support function hc(d) = h(d) - d.c with
 * hc(-d) = hc(d). For a pair, phi(D) = h_A(D) + h_B(-D) = hcA(D) + hcB(D) - D.Delta, Delta = cB - cA,
 * and sd = -min_{|D|=1} phi. */
#ifndef PROX_SAT_SUP_ENGINE_H
#define PROX_SAT_SUP_ENGINE_H

#include "core/body.h"
#include "prox/result.h"

#include <stddef.h>

/* Witness points for the minimising unit direction n and signed distance sd: p1 in the support set
 * of a in n, p2 in that of b in -n. Disjoint pairs (sd > 0): the closest pair of the two support sets
 * (points, segments, disks, rectangles), solved exactly in the plane perpendicular to n, then
 * polished by exact projections onto the bodies; p1 in A, p2 in B always. Overlapping pairs: p2 - p1
 * as close to sd n as the sets allow. */
void sup_witnesses(const prox_body *a, const prox_body *b, prox_vec3 n, double sd, prox_vec3 *p1, prox_vec3 *p2);

/* The normal of an overlapping answer (sd <= 0) with witnesses p1, p2 found along n: (p1 - p2) /
 * |p1 - p2| when that makes p2 - p1 = sd normal hold more closely than n and lies within
 * PROX_TOL_NORMAL_AGREE of n (the witnesses of a direction polished to 1e-8 rad are exact to second
 * order, the direction itself only to first: r x 1e-8 on a deep pair), else n. Disjoint: n. */
prox_vec3 sup_consistent_normal(prox_vec3 n, double sd, prox_vec3 p1, prox_vec3 p2);

/* The answer of an overlapping pair (sd <= 0) from its minimising direction n0: n0 and its Newton
 * polish in the cell and on each ridge within PROX_TOL_KINK (the direction of a search or a root is
 * right to ~1e-8 rad, the support points then move by r x 1e-8), each with its witnesses
 * (sup_witnesses) and normal (sup_consistent_normal); the candidate whose p2 - p1 agrees best with
 * sd normal is kept, among those whose phi is within PROX_TOL_SNAP x scale of phi(n0). Fills sd,
 * normal, p1, p2 of *res. For RCC, BOX and SPH bodies only: this engine's support sets read any other
 * kind as a box (the added kinds' witnesses: prox_convex_overlap_witnesses, sat/convex.h). */
void sup_overlap_answer(const prox_body *a, const prox_body *b, prox_vec3 n0, prox_signed_result *res);

/* The normals (in the plane of the unit axes e1, e2; not unit) at the feet of the perpendiculars
 * from the point y0 e1 + y1 e2 to the ellipse of semi-axes a >= b > 0 along e1, e2, the farthest
 * foot excepted (it maximises h_E(D) - D.y), appended to out[*n..max). Returns 0, or -1 when the
 * point is the centre of a circle (every direction stationary). rcc_ridge_shadow.c. */
int sup_ellipse_feet(double a, double b, double y0, double y1, prox_vec3 e1, prox_vec3 e2, prox_vec3 *out, int *n,
                     int max);

/* Candidate directions (not unit, each to be taken with both signs) holding every stationary point
 * of phi on the ridge D.w = 0 of cylinder `lat` against cylinder `oth` (both PROX_BODY_CYL; delta =
 * centre of B - centre of A, as in phi): the ridge solved in its plane, the other cylinder's shadow
 * an ellipse swept along a segment (rcc_ridge_shadow.c). Returns how many (<= max; max >= 16
 * suffices), or -1 when the shadow is degenerate (the other axis within PROX_TOL_RIDGE_THIN of the
 * ridge plane, or delta at a circular shadow's centre): the caller then solves the rims' quartics. */
int sup_ridge_shadow(const prox_body *lat, const prox_body *oth, prox_vec3 delta, prox_vec3 *out, int max);

/* Penetration depth of an overlapping box a (PROX_BODY_BOX) and cylinder b (PROX_BODY_CYL) by
 * enumerating every stratum in closed form (box_rcc_depth.c): 1 and *res filled when settled, 0
 * when the pose is degenerate or touching and the caller must run the global search. */
int sup_box_cyl_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res);

/* The same for an overlapping convex polytope a (PROX_BODY_POLY: BOX, RPP, RHP, WED, ARB) and a
 * cylinder or a spheroid b (PROX_BODY_CYL, PROX_BODY_ELL), every stratum in closed form
 * (poly_curved_depth.c): *res gets sd, normal, sd_lower and certified, not the witnesses
 * (prox_sat_poly_curved_depth adds them). */
int sup_poly_curved_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res);

/* Penetration depth of two overlapping cylinders (both PROX_BODY_CYL) by enumerating the stationary
 * directions of each stratum (docs/algorithms/sat.md, "fast depth"); 1 and *res filled when every
 * stratum was either solved exactly or excluded by a lower bound, 0 when the caller must fall back
 * to the global search; a negative prox_status when a circle solver failed. *res always holds the
 * best direction found (a valid upper bound). */
int sup_rcc_depth_enum(const prox_body *a, const prox_body *b, prox_signed_result *res);

/* Lower bound of phi over the directions of one rim-rim cell of two cylinders (rcc_depth.c): A's
 * support on rim circle ca and B's (in -D) on rim circle cb, i.e. D in the lune D.al >= 0, D.be >= 0
 * with al = e_A w_A and be = -e_B w_B (e the rims' ends). Chords of the concave radial terms make it a
 * minimum of linear functions over the lune, each minimised exactly. */
double sup_rim_lune_lb(const prox_fcircle *ca, prox_vec3 al, const prox_fcircle *cb, prox_vec3 be);

/* Signed distance of two bodies (see the file comment); status is always PROX_OK. hint (may be
 * NULL): a direction to try first, e.g. a separating direction from the SAT. */
prox_signed_result sup_signed_distance(const prox_body *a, const prox_body *b, const prox_vec3 *hint);

#endif
