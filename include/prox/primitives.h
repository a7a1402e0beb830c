/// @file primitives.h
/// Distance between the geometric primitives a cylinder decomposes into (Agarwal et al. 2016, Sec. 3):
/// points, segments (the axis L), circles (the rims C), disks (the end caps D) and cylindrical surfaces (S).
/// Every solver returns the global minimum distance, a pair of closest points and their parameters,
/// and sets `set` when the minimum is attained on a continuum (parallel, concentric, coplanar) rather
/// than at isolated points; then p1, p2 is one representative pair.
#ifndef PROX_PRIMITIVES_H
#define PROX_PRIMITIVES_H

#include "status.h"
#include "vec3.h"

/// Line segment from a to b (a == b is allowed: a point).
typedef struct prox_segment {
    prox_vec3 a, b;
} prox_segment;

/// Circle (or, as prox_disk, the flat disk it bounds): centre, unit normal, radius > 0.
typedef struct prox_circle {
    prox_vec3 center;
    prox_vec3 normal;
    double radius;
} prox_circle;
typedef prox_circle prox_disk;

/// Cylindrical surface (lateral surface only) of radius `radius` around the axis through `base` with
/// unit direction `dir`, between axial parameters 0 and `height`. Infinite-surface solvers ignore
/// `height`.
typedef struct prox_cylsurf {
    prox_vec3 base;
    prox_vec3 dir;
    double height;
    double radius;
} prox_cylsurf;

/// Result of a primitive-pair distance query.
/// Parameters: segment -> t in [0,1] from a to b; circle -> angle in [0, 2pi) in the circle's frame
/// (prox_circle_frame); disk -> angle in s, radial distance in the second slot; cylindrical surface
/// -> axial parameter (length units) in s, angle in the second slot; point -> unused.
typedef struct prox_prim_result {
    prox_status status;
    double distance; ///< >= 0, except where a solver documents a signed value
    prox_vec3 p1;    ///< closest point on the first primitive
    prox_vec3 p2;    ///< closest point on the second primitive
    double s1[2];    ///< parameters of p1
    double s2[2];    ///< parameters of p2
    int set;         ///< 1 when the minimum is attained on a positive-dimensional set
} prox_prim_result;

/// Orthonormal frame (u, v, n) of a circle: u = any unit vector orthogonal to n chosen by
/// prox_v3_any_perp(n), v = n x u. The angle parameter theta gives center + r (cos th u + sin th v).
PROX_API void prox_circle_frame(const prox_circle *c, prox_vec3 *u, prox_vec3 *v);
/// The point of a circle at angle theta (see prox_circle_frame).
PROX_API prox_vec3 prox_circle_point(const prox_circle *c, double theta);

/// Point p to segment s.
PROX_API prox_prim_result prox_point_segment(prox_vec3 p, const prox_segment *s);
/// Point p to circle c (set when p is on the circle's axis).
PROX_API prox_prim_result prox_point_circle(prox_vec3 p, const prox_circle *c);
/// Point p to solid disk d.
PROX_API prox_prim_result prox_point_disk(prox_vec3 p, const prox_disk *d);
/// Point p to the finite lateral surface s (set when p is on the axis).
PROX_API prox_prim_result prox_point_cylsurf(prox_vec3 p, const prox_cylsurf *s);
/// Segment to segment; robust when near-parallel or zero-length (set when parallel with overlap).
PROX_API prox_prim_result prox_segment_segment(const prox_segment *a, const prox_segment *b);
/// Segment to the infinite cylindrical surface of s (height ignored).
PROX_API prox_prim_result prox_segment_cylsurf_inf(const prox_segment *a, const prox_cylsurf *s);
/// P(S,S) of Agarwal Sec. 3.1: two infinite cylindrical surfaces. distance is SIGNED:
/// (distance between the axes) - r1 - r2, measured along the common perpendicular of the axes; p1, p2
/// lie on the surfaces on that perpendicular; s1[0], s2[0] are the axial parameters of the feet.
/// Parallel axes give set = 1 and the feet at the base of a.
PROX_API prox_prim_result prox_cylsurf_cylsurf_inf(const prox_cylsurf *a, const prox_cylsurf *b);
/// P(D,L) of Agarwal Sec. 3.2: solid disk to segment.
PROX_API prox_prim_result prox_disk_segment(const prox_disk *d, const prox_segment *s);
/// P(C,L) of Agarwal Sec. 3.3: circle to segment (quartic in the half-angle tangent).
PROX_API prox_prim_result prox_circle_segment(const prox_circle *c, const prox_segment *s);
/// P(D,C) of Agarwal Sec. 3.4: solid disk to circle.
PROX_API prox_prim_result prox_disk_circle(const prox_disk *d, const prox_circle *c);
/// P(C,C) of Agarwal Sec. 3.5: circle to circle (degree-8 polynomial).
PROX_API prox_prim_result prox_circle_circle(const prox_circle *a, const prox_circle *b);

#endif
