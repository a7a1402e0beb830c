/* Internal: exact distance and signed distance of two convex polytopes (core/polytope.h: BOX, RPP,
 * RHP/HEX, WED, ARB), and the BOX-BOX fast paths. docs/algorithms/polytopes.md gives the method.
 *
 * A polytope's corners are relative to its reference point; ca and cb are the reference points
 * returned by prox_polytope_make (absolute). Inputs are valid polytopes (the caller validates the
 * shapes); results are absolute. */
#ifndef PROX_DISTANCE_POLY_INTERNAL_H
#define PROX_DISTANCE_POLY_INTERNAL_H

#include "core/body.h"
#include "core/box.h"
#include "core/polytope.h"
#include "prox/result.h"

/* Exact distance: disjoint, the nearest vertex-face, face-vertex or edge-edge pair, p1 on A and p2
 * on B, certified by the gap along (p2 - p1) / |p2 - p1|; overlapping (no separating face normal or
 * edge-edge cross product), intersect = 1, distance 0 and p1 = p2 a point of both solids (the mean
 * of the corners of the intersection found), certified when it lies in both to PROX_TOL_TOUCH S. */
prox_distance_result prox_poly_distance(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b, prox_vec3 cb);

/* Exact signed distance: disjoint, the distance with normal (p2 - p1) / |p2 - p1|; overlapping,
 * sd = -(penetration depth) = the largest separation over the face normals of both and the
 * edge-edge cross products (the facet normals of the Minkowski difference), with witnesses from
 * the two support features along that normal: p2 - p1 = sd normal, p1 on A's boundary, p2 on B's. */
prox_signed_result prox_poly_signed(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b, prox_vec3 cb);

/* The same answers by the exhaustive method alone (feature enumeration, every separating axis), with
 * no GJK fast path: the reference the fast path is tested against. */
prox_distance_result prox_poly_distance_exhaustive(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b,
                                                   prox_vec3 cb);
prox_signed_result prox_poly_signed_exhaustive(const prox_polytope *a, prox_vec3 ca, const prox_polytope *b,
                                               prox_vec3 cb);

/* GJK on two corner sets (distance/poly_gjk.c): the closest point of A - B to the origin as the
 * convex combination sum l[k] (va[ia[k]] - vb[ib[k]]) of n <= 4 corner pairs. dir: a first search
 * direction (from A towards B); S the pair's scale; touch: a closest point nearer the origin than
 * touch counts as overlap. Returns PROX_GJK_DISJOINT (converged, uncertified), PROX_GJK_OVERLAP (the
 * simplex encloses the origin or comes within touch of it) or PROX_GJK_FAIL (no convergence). */
typedef struct prox_gjk_simplex {
    int n;
    int ia[4], ib[4];
    double l[4];
} prox_gjk_simplex;

enum { PROX_GJK_FAIL = 0, PROX_GJK_DISJOINT = 1, PROX_GJK_OVERLAP = 2 };

int prox_gjk_polytopes(const prox_vec3 *va, int na, const prox_vec3 *vb, int nb, prox_vec3 dir, double S, double touch,
                       prox_gjk_simplex *out);

/* A polytope against a curved body (core/body.h: RCC, TRC, REC, ELL) by alternating projections and
 * feature pairs (distance/poly_body.c): PROX_PB_DISJOINT with a closest pair certified by weak
 * duality (r: distance, p1 on P, p2 on B, certificate_gap, certified), PROX_PB_MEET with a common
 * point checked in both solids to PROX_TOL_TOUCH S, the engine's test (r: intersect, p1 = p2), or
 * PROX_PB_OPEN (nothing settled: the caller asks the certified support-function engine). S is the
 * pair's scale. */
enum { PROX_PB_OPEN = 0, PROX_PB_DISJOINT, PROX_PB_MEET };
int prox_poly_body_fast(const prox_polytope *p, prox_vec3 cp, const prox_body *b, double S, prox_distance_result *r);

/* BOX-BOX on prepared frames (core/box.h): the fast paths behind prox_box_box_distance and
 * prox_box_box_signed_distance, for callers that already hold the frames (scenes, dispatch). */
prox_distance_result prox_box_pair_distance(const prox_bframe *A, const prox_bframe *B);
prox_signed_result prox_box_pair_signed(const prox_bframe *A, const prox_bframe *B);

#endif
