/* Internal: the parts of the generic dispatch (src/query/) that live in their own files, and the entry
 * points of query.c that hand back intermediate results to other parts of the library (the scene's
 * RELATION mode), so that a pair's dear solver runs once. docs/algorithms/dispatch.md. */
#ifndef PROX_QUERY_QUERY_INTERNAL_H
#define PROX_QUERY_QUERY_INTERNAL_H

#include "prox/pairs.h"
#include "prox/query.h"

/* prox_shape_relation, also returning the signed distance it computed (normal and witness points
 * included) in *s when s is not NULL. */
prox_relation_result prox_shape_relation_with_signed(const prox_shape *a, const prox_shape *b, double tol,
                                                     prox_signed_result *s);

/* ---- a sphere against any macrobody (sphere_any.c) ----
 * Solid b (any kind) against the sphere s, answered from the signed distance of the centre to b:
 * p1 on b, p2 on the sphere, the normal from b towards the sphere. Both are validated here,
 * the sphere first when sphere_first (the order of the public call: its first shape reports first). */
prox_signed_result prox_query_sph_signed(const prox_shape *b, const prox_sph *s, int sphere_first);
prox_distance_result prox_query_sph_distance(const prox_shape *b, const prox_sph *s, int sphere_first);
/* The same for a pair already validated (prepared solids): no validation, b first; h2 an RCC's squared
 * height |axis|^2 (0 for another kind). */
prox_signed_result prox_query_sph_signed_valid(const prox_shape *b, const prox_sph *s, double h2);
prox_distance_result prox_query_sph_distance_valid(const prox_shape *b, const prox_sph *s, double h2);
prox_test_result prox_query_sph_test(const prox_shape *b, const prox_sph *s, int sphere_first);

/* BOX-RCC distance (box_rcc_signed.c): prox_box_rcc_distance, whose disjoint answer a pair 1e-10 ..
 * 1e-3 S apart often leaves short of its certificate (a corner or a rim that near the other body
 * knows the normal only to eps S over the gap: 30-40 % of such random pairs), then the support-function
 * engine's, which searches the kinks, when that one is certified and disjoint. */
prox_distance_result prox_query_box_rcc_distance(const prox_box *a, const prox_rcc *b);

/* Centre and size of a valid shape, as prox_shape_center and prox_shape_size give them, without
 * building the generic body (the pair scale of every decision tolerance). */
void prox_query_center_size(const prox_shape *s, prox_vec3 *c, double *size);

/* Signed distance from x to a valid shape (< 0 inside), exact (core's boundary functions). */
double prox_query_point_signed(const prox_shape *s, prox_vec3 x);

/* ---- containment of any pair (contain_any.c) ----
 * A inside B for valid shapes of any kinds (the caller validates): the clearance min over A of the
 * distance to B's boundary (exact when A is inside B; < 0 otherwise, its magnitude at most how far A
 * sticks out). *certified receives 1 when the value is exact to rounding (closed forms), 0 when it
 * comes from a branch-and-bound over normals (certified to PROX_TOL_CONTAIN_BB x scale). */
double prox_query_clearance(const prox_shape *a, const prox_shape *b, int *certified);

#endif
