/// @file scene.h
/// Scenes of many bodies, query modes that skip work, and a batch API.
///
/// Every pair question runs a ladder of tests from cheapest to dearest and stops at the first rung
/// that decides it: axis-aligned boxes, bounding spheres, support-function bounds along the line of
/// centres (a lower and an upper bound on the distance), the separating-axis verdict, and only then
/// the exact solver the mode asks for (query.h). A scene adds a broad phase (a bounding volume
/// hierarchy over the bodies' boxes) so that pairs whose boxes lie farther apart than the question
/// cares about are never looked at one by one: its work grows with the bodies and the pairs near
/// enough to test, not with the square of the bodies. See docs/scene.md and docs/PERFORMANCE.md ("Scenes").
#ifndef PROX_SCENE_H
#define PROX_SCENE_H

#include <stddef.h>

#include "query.h"
#include "shapes.h"

/// Axis-aligned bounding box.
typedef struct prox_aabb {
    prox_vec3 lo, hi;
} prox_aabb;

/// The tight axis-aligned box of a valid shape of any of the ten kinds (for TRC, REC, ELL, RHP, WED
/// and ARB: the support function along +-x, +-y, +-z), widened by a few ulps so that it always
/// contains the solid.
PROX_API prox_aabb prox_shape_aabb(const prox_shape *s);
/// A bounding sphere of a valid shape: the centre of symmetry (RCC, BOX, RPP, SPH) or the body's
/// reference point (the other kinds: middle of the axis, centre, corners' centroid) and the distance
/// to its farthest point, widened so that rounding cannot make it miss the solid.
PROX_API prox_sph prox_shape_bounding_sphere(const prox_shape *s);

/// How much a pair query computes. Each mode computes what the previous ones do, plus more.
typedef enum prox_query_mode {
    PROX_MODE_VERDICT = 0, ///< intersect or not (with a threshold d > 0: the same as CLOSER)
    PROX_MODE_CLOSER,      ///< is the distance <= d? decided by the cheapest rung that can
    PROX_MODE_DISTANCE,    ///< exact distance (the solvers give the points at no extra cost today)
    PROX_MODE_POINTS,      ///< exact distance and proximal points
    PROX_MODE_SIGNED,      ///< signed distance, witness points, depth and repositioning of b
    PROX_MODE_RELATION     ///< disjoint / touching / crossing / nested, with points, depth, reposition
} prox_query_mode;

/// Which rung of the ladder decided a pair.
typedef enum prox_decided_by {
    PROX_DECIDED_NONE = 0,
    PROX_DECIDED_BOUNDS,  ///< bounding boxes or bounding spheres
    PROX_DECIDED_SUPPORT, ///< support-function bounds along the line of centres
    PROX_DECIDED_TEST,    ///< separating-axis verdict (prox_shape_test)
    PROX_DECIDED_EXACT    ///< an exact solver (distance, signed distance or relation)
} prox_decided_by;

/// Result of one pair query. Fields beyond what the mode computes are left at 0 (see each field).
typedef struct prox_pair_result {
    prox_status status;
    prox_query_mode mode;
    prox_decided_by decided_by;
    int intersect;           ///< 1 the solids share a point, 0 they do not, -1 not decided (CLOSER early-out)
    int closer;              ///< distance <= d (every mode; d = 0 for VERDICT without a threshold)
    double distance;         ///< DISTANCE and up: exact distance (0 when intersecting)
    prox_vec3 p1, p2;        ///< POINTS: proximal points; SIGNED: witnesses; RELATION: see docs/scene.md
    double signed_distance;  ///< SIGNED, RELATION: > 0 distance, <= 0 minus the penetration depth
    double depth;            ///< SIGNED, RELATION: penetration depth (>= 0)
    prox_vec3 reposition;    ///< SIGNED, RELATION: translation of b that makes the pair touch (0 if disjoint)
    prox_relation relation;  ///< RELATION
    double clearance;        ///< RELATION, nested pairs: clearance of the inner solid inside the outer one
} prox_pair_result;

/// One pair query with the ladder of tests. d is the threshold of CLOSER (and of VERDICT when > 0):
/// d >= 0, or INFINITY. Invalid shapes or d give a status, never a number.
PROX_API prox_pair_result prox_pair_query(const prox_shape *a, const prox_shape *b, prox_query_mode mode, double d);

/// Batch: out[i] = prox_pair_query(a[i], b[i], mode, d) for i < n, across `threads` OpenMP threads
/// when the library was built with OpenMP (threads <= 0: OpenMP's default; ignored without OpenMP).
/// Returns PROX_EINVAL_ARG for null arrays; per-pair problems are in out[i].status.
PROX_API prox_status prox_batch_query(const prox_shape *a, const prox_shape *b, size_t n, prox_query_mode mode,
                                      double d, int threads, prox_pair_result *out);
/// 1 when the library was built with OpenMP.
PROX_API int prox_batch_has_openmp(void);

/// A set of bodies. Opaque; create with prox_scene_create.
typedef struct prox_scene prox_scene;

/// Counters of one scene query: how much work the broad phase and the ladder skipped.
typedef struct prox_scene_stats {
    size_t bodies;
    size_t naive_pairs;     ///< n (n - 1) / 2
    size_t candidates;      ///< pairs whose bounding boxes came within the threshold (broad phase output)
    size_t bound_rejects;   ///< candidates dropped by bounding spheres
    size_t support_decided; ///< decided by support-function bounds
    size_t tests;           ///< decided by the separating-axis verdict
    size_t exact;           ///< exact solver calls
    size_t reported;        ///< pairs in the report
} prox_scene_stats;

/// A reported pair: body indices (in order of addition, a < b) and the query result.
typedef struct prox_scene_pair {
    size_t a, b;
    prox_pair_result r;
} prox_scene_pair;

/// Answer of a scene query; free with prox_scene_report_free.
typedef struct prox_scene_report {
    prox_status status;
    prox_scene_pair *pairs; ///< sorted by (a, b)
    size_t npairs;
    prox_scene_stats stats;
} prox_scene_report;

/// An empty scene (NULL when out of memory).
PROX_API prox_scene *prox_scene_create(void);
/// Frees a scene (NULL is allowed).
PROX_API void prox_scene_destroy(prox_scene *s);
/// Adds a validated copy of the shape; its index is the number of bodies before the call.
PROX_API prox_status prox_scene_add(prox_scene *s, const prox_shape *shape);
/// Number of bodies.
PROX_API size_t prox_scene_count(const prox_scene *s);
/// The body at index i (NULL when out of range).
PROX_API const prox_shape *prox_scene_body(const prox_scene *s, size_t i);
/// Threads used by scene queries, for the broad phase and the ladder alike (POSIX threads; default 1;
/// <= 0: one per processor, OpenMP's default when the library is built with OpenMP). The answers do
/// not depend on the thread count.
PROX_API void prox_scene_set_threads(prox_scene *s, int threads);

/// Every pair within `clearance` (>= 0; INFINITY: every pair), evaluated in `mode`:
/// VERDICT/CLOSER report pairs with distance <= clearance (clearance 0: the intersecting pairs),
/// DISTANCE/POINTS those with exact distance <= clearance, SIGNED those with signed distance <=
/// clearance, RELATION those that are not disjoint or are within clearance.
PROX_API prox_scene_report prox_scene_pairs(const prox_scene *s, double clearance, prox_query_mode mode);
/// The pairs that share a point (touching, crossing or nested), with depth and repositioning when
/// mode >= SIGNED. Same as prox_scene_pairs(s, 0, mode).
PROX_API prox_scene_report prox_scene_intersecting(const prox_scene *s, prox_query_mode mode);
/// The pair at the smallest distance (POINTS mode; ties: smallest (a, b)); npairs = 0 for fewer than
/// two bodies.
PROX_API prox_scene_report prox_scene_nearest(const prox_scene *s);
/// The same questions answered without the broad phase (every pair through the ladder): the
/// reference for tests and the naive count for bench/.
PROX_API prox_scene_report prox_scene_pairs_naive(const prox_scene *s, double clearance, prox_query_mode mode);
/// Frees the pairs of a report and zeroes it.
PROX_API void prox_scene_report_free(prox_scene_report *r);

#endif
