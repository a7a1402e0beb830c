/* P(D, C) of Agarwal et al. (2016) Sec. 3.4: solid disk to circle.
 * Disk point c1 + r1 s1 (cos th1 u1 + sin th1 v1) (Eq. (14)); circle point P(th2) = c2 + r2 (cos th2 u2 +
 * sin th2 v2). Eq. (17) gives s1 from f3 = 0; the remaining system factors (the resultant g5 splits into
 * two quartics g6, g7). Geometrically, with h(th2) = (P(th2) - c1).n1 = h0 + r2 (a cos th2 + b sin th2),
 * a = u2.n1, b = v2.n1, the stationary points with s1 in (0, 1) are the disk-plane foot of a circle point
 * where h' = 0 (the lowest / highest point of the circle w.r.t. the disk's plane: th2 = phi, phi + pi,
 * phi = atan2(b, a)) or where h = 0 (the circle crosses the plane, distance 0); when s1 > 1 the paper
 * switches to P(C, C) with the rim. So the minimum is the smallest of:
 *   - 0 when a crossing point th2 = phi +- acos(-h0 / (r2 hypot(a, b))) projects into the disk;
 *   - |h| at the lowest / highest point when it projects into the disk;
 *   - prox_circle_circle(rim, circle) (Sec. 3.5, circle_circle.c).
 * Parallel planes (z1.z2 = +-1, Eq. (18): the factor g3 gives a one-dimensional solution, the projection
 * of the circle onto the disk): h is constant; when some circle point projects into the open disk
 * (|delta - r2| < r1, delta the in-plane offset of the centres) the distance is |h0| on an arc: set = 1;
 * otherwise the minimum is rim against circle.
 * Parameters: s1 = (angle, radial distance in length units) on the disk, s2[0] = angle on the circle.
 * Input: radii > 0, normals finite non-zero (normalised). */
#include "distance/prim_common.h"

/* Candidate: circle point at th2 against the disk interior. Accepted when its projection lies in the
 * disk; distance |h| (0 when force_zero: a crossing point). */
static void consider_foot(prox_prim_result *best, const prox_fcircle *d, const prox_fcircle *c, double th2,
                          int force_zero)
{
    prox_vec3 x = prox_fcircle_point(c, th2);
    prox_prim_local l = prox_prim_local_of(d, x);
    if (!(l.rho <= d->r)) return;
    double dist = force_zero ? 0.0 : fabs(l.h);
    if (!(dist < best->distance)) return;
    best->distance = dist;
    best->p1 = prox_v3_mad(x, -l.h, d->n);
    best->p2 = x;
    best->s1[0] = prox_prim_local_angle(&l);
    best->s1[1] = l.rho;
    best->s2[0] = prox_prim_wrap_2pi(th2);
    best->set = 0;
}

/* Rim of the disk against the circle (P(C, C)). */
static void consider_rim(prox_prim_result *best, const prox_fcircle *d, const prox_fcircle *c)
{
    prox_circle rim = {d->c, d->n, d->r}, cc = {c->c, c->n, c->r};
    prox_prim_result r = prox_circle_circle(&rim, &cc);
    if (r.status != PROX_OK) {
        best->status = r.status;
        return;
    }
    if (r.distance < best->distance) {
        *best = r;
        best->s1[1] = d->r;
    }
}

/* Parallel planes: the circle at constant height h0 over the disk's plane. Returns 1 when some circle
 * point projects into the open disk (then best holds |h0|, set = 1). */
static int parallel_over_disk(prox_prim_result *best, const prox_fcircle *d, const prox_fcircle *c)
{
    prox_vec3 off = prox_v3_reject(prox_v3_sub(d->c, c->c), d->n); /* from c2' towards c1 in the plane */
    double delta = prox_v3_norm(off);
    if (!(fabs(delta - c->r) < d->r)) return 0;
    double th2 = 0.0;
    if (delta > 0.0) th2 = atan2(prox_v3_dot(off, c->v), prox_v3_dot(off, c->u));
    double keep = best->distance;
    best->distance = INFINITY;
    consider_foot(best, d, c, th2, 0);
    if (!(best->distance < INFINITY)) { /* rounding at the rim: should not happen */
        best->distance = keep;
        return 0;
    }
    best->set = 1;
    return 1;
}

PROX_API prox_prim_result prox_disk_circle(const prox_disk *d, const prox_circle *c)
{
    prox_prim_result best = {0};
    prox_fcircle fd, fc;
    if ((best.status = prox_prim_circle_frame(d, &fd)) != PROX_OK ||
        (best.status = prox_prim_circle_frame(c, &fc)) != PROX_OK)
        return best;
    best.distance = INFINITY;
    double a = prox_v3_dot(fc.u, fd.n), b = prox_v3_dot(fc.v, fd.n), ab = hypot(a, b);
    double h0 = prox_v3_dot(prox_v3_sub(fc.c, fd.c), fd.n);
    if (ab <= PROX_TOL_PARALLEL) {
        if (parallel_over_disk(&best, &fd, &fc)) return best;
        consider_rim(&best, &fd, &fc);
        return best;
    }
    double phi = atan2(b, a), R = fc.r * ab;
    if (fabs(h0) <= R) { /* the circle meets the plane at phi +- acos(-h0 / R) */
        double w = acos(fmax(-1.0, fmin(1.0, -h0 / R)));
        consider_foot(&best, &fd, &fc, phi + w, 1);
        consider_foot(&best, &fd, &fc, phi - w, 1);
        if (best.distance == 0.0) return best;
    }
    consider_foot(&best, &fd, &fc, phi, 0);           /* highest point */
    consider_foot(&best, &fd, &fc, phi + PROX_PI, 0); /* lowest point */
    consider_rim(&best, &fd, &fc);
    return best;
}
