/* Internal: a proven lower bound on the penetration depth of two overlapping convex bodies by an
 * expanding inner polytope (the expanding polytope algorithm, van den Bergen 2001, turned into a
 * certificate; docs/algorithms/convex_engine.md).
 *
 * P = A - B contains the origin; its depth is min over unit D of h_P(D). Points of P (support
 * points) joined by a closed mesh of triangles that wraps the origin (every triangle seen
 * counter-clockwise from it, or their signed solid angles adding up to 4 pi) meet every ray from the
 * origin, and the point where a ray meets a
 * triangle is in P (a convex combination) and no nearer than the triangle's distance from the
 * origin. So the ball of radius min_f dist(0, f) lies in P: a lower bound on the depth. No convexity
 * or orientation of the triangles is needed, and each triangle's distance is bounded below by weak
 * duality (min over its corners of u . corner for a unit u), robust for slivers. Each step takes the
 * support point in the direction of the nearest triangle's nearest point and replaces that triangle
 * (with the one across its side when that point lies on the side) and those the point sees beyond
 * their planes by a fan from it; near the deepest direction the triangles shrink until their
 * distances are within tol of h_P. */
#ifndef PROX_SAT_EPA_H
#define PROX_SAT_EPA_H

#include "prox/vec3.h"

/* The support point of P in the unit direction d; *h = h_P(d) (an upper bound on the depth). */
typedef prox_vec3 (*prox_epa_support)(void *ctx, prox_vec3 d, double *h);

typedef struct prox_epa_result {
    double lower;   /* proven: the ball of this radius about the origin lies in P (-INFINITY: none) */
    double upper;   /* the least h_P(D) seen (the caller's upper bound included) */
    prox_vec3 dir;  /* the direction of that least h_P */
    int points;     /* support points the mesh took */
} prox_epa_result;

/* Starts from the points v[0..nv-1] (support points of P, nv <= 12) joined by the closed mesh of
 * triangles tri[0..nt-1] (nt <= 20, counter-clockwise seen from outside; one that does not wrap the
 * origin returns 0 at once, out->points = 0) and refines until lower >=
 * upper - tol, upper starting at the caller's upper (with its direction dir). slack: how far a
 * computed support point may lie from P (rounding), subtracted from the bound. Returns 1 when proved
 * (out->lower the bound), 0 when max_points was reached or the mesh could not be continued (no point
 * beyond the nearest triangle, a pinched rim), out->lower then -INFINITY; out->upper and dir hold
 * the least h_P seen either way. */
int prox_epa_depth(prox_epa_support f, void *ctx, const prox_vec3 *v, int nv, const unsigned char (*tri)[3], int nt,
                   double upper, prox_vec3 dir, double tol, double slack, int max_points, prox_epa_result *out);

#endif
