/* The capsule approximation of a cylinder pair : each cylinder
 * is replaced by the capsule around its axis segment with the same radius, and the distance is
 * segment-segment distance minus both radii (negative: the capsules overlap). It is exact only when
 * the closest points fall on the lateral surfaces; it is the cost floor prox aims at.
 * Segment-segment: minimise |A(s) - B(t)|^2 over [0,1]^2 (A(s) = a0 + s u, B(t) = b0 + t v): the
 * unconstrained stationary s is clamped to [0,1], t follows from s and is clamped, then s is
 * recomputed from the clamped t and clamped (the minimum of a convex quadratic on a square lies on
 * the edge found this way). Parallel segments (u x v ~ 0) take s = 0. */
#include "bench_pairs.h"

static double clamp01(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

/* Closest points of two segments; returns the distance. */
static double segseg(prox_vec3 a0, prox_vec3 u, prox_vec3 b0, prox_vec3 v, prox_vec3 *pa, prox_vec3 *pb)
{
    prox_vec3 w = prox_v3_sub(a0, b0);
    double A = prox_v3_dot(u, u), B = prox_v3_dot(u, v), C = prox_v3_dot(v, v);
    double D = prox_v3_dot(u, w), E = prox_v3_dot(v, w), den = A * C - B * B;
    double s = den > 1e-14 * A * C ? clamp01((B * E - C * D) / den) : 0.0;
    double t = (B * s + E) / C;
    if (t < 0.0 || t > 1.0) {
        t = clamp01(t);
        s = clamp01((B * t - D) / A);
    }
    *pa = prox_v3_mad(a0, s, u);
    *pb = prox_v3_mad(b0, t, v);
    return prox_v3_dist(*pa, *pb);
}

static void capsule_run(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    (void)cfg;
    prox_vec3 pa, pb;
    double d = segseg(a->base, a->axis, b->base, b->axis, &pa, &pb);
    double sd = d - a->radius - b->radius;
    prox_vec3 n = d > 0 ? prox_v3_scale(prox_v3_sub(pb, pa), 1.0 / d) : prox_v3(0, 0, 1);
    out->ok = 1;
    out->value = sd > 0 ? sd : 0.0;
    out->intersect = sd <= 0;
    out->p1 = prox_v3_mad(pa, a->radius, n);
    out->p2 = prox_v3_mad(pb, -b->radius, n);
    out->has_points = sd > 0;
}

const bench_method bench_capsule_method = {"capsule", BENCH_DIST, capsule_run, NULL};

/* The harness floor: what every method's figure includes besides the method itself (the case's
 * function-pointer call, the method's call, reading both cylinders and filling the answer), measured
 * with a method that does no geometry.  Subtract it to compare with a bare loop. */
static void harness_run(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    (void)cfg;
    out->ok = 1;
    out->value = a->radius + b->radius;
    out->intersect = 0;
    out->p1 = a->base, out->p2 = b->base;
    out->has_points = 0;
}

const bench_method bench_harness_method = {"harness-floor", BENCH_DIST, harness_run, NULL};
