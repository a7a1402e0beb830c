/* A point common to two solid cylinders (core/cyl.h): the overlap witness of every cylinder method.
 *
 * Exact constructions first, for intersections too thin for projections to enter quickly (a needle
 * through a pancake, two pancakes crossing): each axis segment clipped by the other solid, and the
 * chord where the two mid-disks meet. Then Douglas-Rachford iterations between the two solids shrunk
 * by a margin: when the shrunk solids still intersect, the shadow iterate enters them after finitely
 * many steps and so lies strictly inside both originals (plain projections only approach the
 * intersection from outside), and Douglas-Rachford is much faster than alternating projections where
 * the surfaces meet at a shallow angle. Every point returned is checked against both solids. */
#include "core/cyl.h"

/* Closest point to x of the cylinder k shrunk by delta (radius r - delta, axial range
 * [delta, h - delta]); x itself when inside. */
static prox_vec3 shrunk_project(const prox_cyl *k, prox_vec3 x, double delta)
{
    prox_vec3 d = prox_v3_sub(x, k->b);
    double t = prox_v3_dot(d, k->w);
    prox_vec3 radial = prox_v3_mad(d, -t, k->w);
    double rho = prox_v3_norm(radial), r = k->r - delta;
    double tc = t < delta ? delta : (t > k->h - delta ? k->h - delta : t);
    if (tc == t && rho <= r) return x;
    if (rho > r) radial = prox_v3_scale(radial, r / rho);
    return prox_v3_add(prox_v3_mad(k->b, tc, k->w), radial);
}

/* The part of seg's axis segment inside the solid k: 1 and its midpoint in *x when not empty. */
static int axis_inside(const prox_cyl *seg, const prox_cyl *k, prox_vec3 *x)
{
    double s0, s1;
    if (!prox_segment_clip_solid_cyl(seg->b, seg->cap[1], k->b, k->w, k->h, k->r, 0.0, &s0, &s1)) return 0;
    *x = prox_v3_mad(seg->b, 0.5 * (s0 + s1) * seg->h, seg->w);
    return 1;
}

/* Where the mid-planes of the two cylinders meet, the middle of the overlap of the two mid-disks'
 * chords on that line: a point of both mid-disks, so of both solids. The case of two thin disks
 * crossing, which neither axis reaches. Parallel mid-planes (|wA x wB|^2 <= 1e-24) have no line. */
static int middisks_meet(const prox_cyl *A, const prox_cyl *B, prox_vec3 *x)
{
    prox_vec3 l = prox_v3_cross(A->w, B->w);
    double ll = prox_v3_norm2(l);
    if (!(ll > 1e-24)) return 0;
    /* the point of the line nearest to A's centre: x = cA + a (wA x l) with (x - cB).wB = 0 */
    prox_vec3 m = prox_v3_cross(A->w, l);
    double den = prox_v3_dot(m, B->w);
    if (den == 0.0) return 0;
    prox_vec3 p = prox_v3_mad(A->c, prox_v3_dot(prox_v3_sub(B->c, A->c), B->w) / den, m);
    prox_vec3 u = prox_v3_scale(l, 1.0 / sqrt(ll));
    double lo = -INFINITY, hi = INFINITY;
    const prox_cyl *k2[2] = {A, B};
    for (int i = 0; i < 2; ++i) { /* |p + t u - c|^2 <= r^2 on the line (u lies in the plane) */
        prox_vec3 e = prox_v3_sub(p, k2[i]->c);
        double b = prox_v3_dot(e, u), c = prox_v3_norm2(e) - k2[i]->r * k2[i]->r, disc = b * b - c;
        if (disc < 0.0) return 0;
        double sq = sqrt(disc);
        lo = fmax(lo, -b - sq);
        hi = fmin(hi, -b + sq);
    }
    if (!(lo <= hi)) return 0;
    *x = prox_v3_mad(p, 0.5 * (lo + hi), u);
    return 1;
}

/* x is a common point when it lies in both solids enlarged by tol. */
static int in_both(const prox_cyl *a, const prox_cyl *b, prox_vec3 x, double tol)
{
    return prox_cyl_contains(a, x, tol) && prox_cyl_contains(b, x, tol);
}

int prox_cyl_common_point(const prox_cyl *a, const prox_cyl *b, prox_vec3 start, int iters, double tol,
                          prox_vec3 *out)
{
    prox_vec3 c;
    if (axis_inside(a, b, &c) && in_both(a, b, c, tol)) return *out = c, 1;
    if (axis_inside(b, a, &c) && in_both(a, b, c, tol)) return *out = c, 1;
    if (middisks_meet(a, b, &c) && in_both(a, b, c, tol)) return *out = c, 1;
    /* Margins from a quarter of the smallest dimension down to 0 (the last one can only approach a
     * touching contact, within tol). */
    static const double margins[] = {0.25, 0.02, 1e-3, 1e-5, 0.0};
    const double dim = fmin(fmin(a->r, a->hh), fmin(b->r, b->hh));
    prox_vec3 last = start;
    for (int m = 0; m < (int)(sizeof margins / sizeof margins[0]); ++m) {
        const double delta = margins[m] * dim;
        prox_vec3 z = start;
        for (int i = 0; i < iters; ++i) { /* z <- z + P_B(2 P_A(z) - z) - P_A(z) */
            prox_vec3 pa = shrunk_project(a, z, delta);
            if (in_both(a, b, pa, tol)) return *out = pa, 1;
            prox_vec3 pb = shrunk_project(b, prox_v3_sub(prox_v3_scale(pa, 2.0), z), delta);
            if (in_both(a, b, pb, tol)) return *out = pb, 1;
            z = prox_v3_add(z, prox_v3_sub(pb, pa));
            last = pa;
        }
    }
    *out = last;
    return 0;
}
