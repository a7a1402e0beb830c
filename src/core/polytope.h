/* Internal (core): the one prepared representation of a convex polytope, shared by BOX, RPP, RHP/HEX,
 * WED and ARB wherever they meet a polytope method (polytope pairs, cells' facets, membership). A BOX
 * or RPP keeps its faster prox_bframe (core/box.h) in the generic body; prox_polytope_make also builds
 * the polytope of a box for the polytope-pair solvers.
 *
 * Coordinates are relative to the body's reference point c (the vertex centroid), returned by
 * prox_polytope_make, so that a body far from the origin keeps its relative precision. The solid is
 * { y : n_f . y <= d_f for every face f }; vertices, edges and face loops describe its boundary. */
#ifndef PROX_CORE_POLYTOPE_H
#define PROX_CORE_POLYTOPE_H

#include "prox/shapes.h"

#define PROX_POLY_MAXV 12  /* RHP: 12 corners */
#define PROX_POLY_MAXF 8   /* RHP: six sides and two hexagonal ends */
#define PROX_POLY_MAXE 18  /* RHP: 18 edges */
#define PROX_POLY_MAXFV 6  /* corners of one face (a hexagonal end) */

typedef struct prox_polytope {
    int nv, nf, ne;
    prox_vec3 v[PROX_POLY_MAXV];                       /* corners, relative to c */
    prox_vec3 n[PROX_POLY_MAXF];                       /* unit outward face normals */
    double d[PROX_POLY_MAXF];                          /* the solid is n_f . y <= d_f */
    int facet[PROX_POLY_MAXF];                         /* MCNP facet number k of face f (for n.k) */
    int fnv[PROX_POLY_MAXF];                           /* corners of face f */
    unsigned char fv[PROX_POLY_MAXF][PROX_POLY_MAXFV]; /* face loop, counter-clockwise seen from outside */
    unsigned char e[PROX_POLY_MAXE][2];                /* edge corners */
    unsigned char ef[PROX_POLY_MAXE][2];               /* the two faces meeting at each edge */
    double size;                                       /* largest corner-to-corner distance */
    prox_vec3 lo, hi;                                  /* the corners' bounding box (relative to c) */
} prox_polytope;

/* The polytope of a valid BOX, RPP, RHP, WED or ARB; returns its reference point c (absolute). */
prox_vec3 prox_polytope_make(const prox_shape *s, prox_polytope *p);

/* The shape's validation (its kind's validator: RHP, WED, ARB, BOX, RPP) and, when it passes, its
 * polytope (*p, reference point *c) built once for both. */
prox_status prox_polytope_checked(const prox_shape *s, prox_polytope *p, prox_vec3 *c);

/* The two halves of prox_polytope_checked. prox_polytope_fast: 1 when cheap sufficient tests prove
 * an RHP, WED or ARB valid (and *p, *c built: the very polytope of the full checks), else 0 (no
 * verdict; *p undefined). prox_polytope_checked_full: the ordered checks that name each fault. The
 * first never accepts what the second rejects (tests/test_poly_fastpath.c). */
int prox_polytope_fast(const prox_shape *s, prox_polytope *p, prox_vec3 *c);
prox_status prox_polytope_checked_full(const prox_shape *s, prox_polytope *p, prox_vec3 *c);

/* Centred support function hc(d) = max_i d.v_i and a support point (a corner; a zero component
 * along a face or an edge picks one of its corners). */
double prox_polytope_hc(const prox_polytope *p, prox_vec3 d);
prox_vec3 prox_polytope_pc(const prox_polytope *p, prox_vec3 d);

/* 1 when y (relative to c) lies in the solid enlarged by tol >= 0: every face plane moved out by tol,
 * and within tol of the corners' bounding box. */
int prox_polytope_contains(const prox_polytope *p, prox_vec3 y, double tol);

/* The parameter t in [0, 1] of the closest point a + t (b - a) of the segment [a, b] to y. */
static inline double prox_seg_param(prox_vec3 a, prox_vec3 b, prox_vec3 y)
{
    prox_vec3 ab = prox_v3_sub(b, a);
    double l2 = prox_v3_norm2(ab);
    double t = l2 > 0.0 ? prox_v3_dot(prox_v3_sub(y, a), ab) / l2 : 0.0;
    return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
}

/* Closest point of the segment [a, b] to y. */
static inline prox_vec3 prox_seg_closest(prox_vec3 a, prox_vec3 b, prox_vec3 y)
{
    return prox_v3_mad(a, prox_seg_param(a, b, y), prox_v3_sub(b, a));
}

/* Closest point of the solid to y (y itself inside), relative to c. */
prox_vec3 prox_polytope_closest(const prox_polytope *p, prox_vec3 y);

/* The same closest point *q with the feature it lies on: PROX_POLY_INSIDE (y in the solid, *q = y),
 * PROX_POLY_FACE (the interior of face *i), PROX_POLY_EDGE (the segment from corner *i to corner *j,
 * at the fraction *t of it) or PROX_POLY_CORNER (corner *i). */
enum { PROX_POLY_INSIDE = 0, PROX_POLY_FACE, PROX_POLY_EDGE, PROX_POLY_CORNER };
int prox_polytope_closest_feature(const prox_polytope *p, prox_vec3 y, prox_vec3 *q, int *i, int *j, double *t);

/* The foot *x of y on the plane of face f; 1 when it lies in the face (inside every side). */
int prox_polytope_face_foot(const prox_polytope *p, int f, prox_vec3 y, prox_vec3 *x);

/* The hexagon of an RHP in its base plane: in-plane axes e1, e2, the six side normals nl[k] and
 * offsets dl[k] in those axes sorted by angle, their MCNP facet numbers fk[k], and corner k where
 * side lines k and k + 1 meet (x[k], by Cramer's rule with determinant det[k]). Computed once and
 * shared by the validator (which checks that the lines bound a convex hexagon) and the builder. */
typedef struct prox_rhp_section {
    prox_vec3 e1, e2;
    double nl[6][2], dl[6];
    int fk[6];
    double x[6][2], det[6];
} prox_rhp_section;

void prox_rhp_hexagon(const prox_rhp *h, prox_rhp_section *hx);

/* The polytope of an RHP from its section (prox_rhp_hexagon); returns its reference point. */
prox_vec3 prox_polytope_rhp(const prox_rhp *h, const prox_rhp_section *hx, prox_polytope *p);

/* Corner indices (0-based) of ARB face entry f in order round the face, however the card names them;
 * returns their count (0 for an unused entry). */
int prox_arb_face_loop(const prox_arb *a, int f, int idx[4]);

/* 1 when the sides p -> q and r -> s of a plane loop with normal n cross (each side's line
 * separates the other's ends): a four-corner face named out of order round the face. */
int prox_sides_cross(prox_vec3 p, prox_vec3 q, prox_vec3 r, prox_vec3 s, prox_vec3 n);

/* The polytope of an ARB (valid card entries; the solid itself is checked by the validator) and
 * *least, the smallest squared distance between two of its corners; returns its reference point.
 * Each face loop is turned outwards by its Newell normal; quick = 1 decides by the loop's first
 * three corners instead, which only the validator's fast path may use (it confirms every face's
 * outcome; prox_polytope_make builds with quick = 0). */
prox_vec3 prox_polytope_arb(const prox_arb *a, prox_polytope *p, double *least, int quick);

/* Signed distance from y to the boundary (< 0 inside) and the closest boundary point *q. */
double prox_polytope_boundary(const prox_polytope *p, prox_vec3 y, prox_vec3 *q);

#endif
