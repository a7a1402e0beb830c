/* Long-double brute-force toolkit shared by the primitive-solver tests (test_point_primitives.c,
 * test_segment_segment.c, test_cylsurf.c, test_disk_segment.c, test_circle_segment.c,
 * test_disk_circle.c): vector arithmetic in long double, dense sampling + golden-section minimisers of
 * a one-parameter function, closed-form distances to segments and disks, and the random-case builders
 * the tests share. Independent of the library code under test: only prox_vec3 helpers (vec3.h) and the
 * seeded RNG of test_util.h are used; no solver is called here. */
#ifndef PROX_TEST_BRUTE_H
#define PROX_TEST_BRUTE_H

#include "test_util.h"

typedef long double ld;
typedef struct lv3 {
    ld x, y, z;
} lv3;
static inline lv3 L(prox_vec3 v) { lv3 r = {v.x, v.y, v.z}; return r; }
static inline lv3 ladd(lv3 a, lv3 b) { lv3 r = {a.x + b.x, a.y + b.y, a.z + b.z}; return r; }
static inline lv3 lsub(lv3 a, lv3 b) { lv3 r = {a.x - b.x, a.y - b.y, a.z - b.z}; return r; }
static inline lv3 lsc(lv3 a, ld s) { lv3 r = {a.x * s, a.y * s, a.z * s}; return r; }
static inline ld ldot(lv3 a, lv3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline ld lnorm(lv3 a) { return sqrtl(ldot(a, a)); }
static inline lv3 lcross(lv3 a, lv3 b)
{
    lv3 r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    return r;
}
static inline lv3 lunit(lv3 a) { return lsc(a, 1.0L / lnorm(a)); }

/* Distance from x to the segment [a, a + d] by clamped projection (d = 0: the point a). */
static inline ld lseg_dist(lv3 x, lv3 a, lv3 d)
{
    ld dd = ldot(d, d), t = dd > 0 ? ldot(lsub(x, a), d) / dd : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    return lnorm(lsub(x, ladd(a, lsc(d, t))));
}

/* |x - (a + t d)|: how far x is from the segment point at parameter t (a parameter check). */
static inline double tb_seg_point_err(prox_vec3 x, lv3 a, lv3 d, double t)
{
    return (double)lnorm(lsub(L(x), ladd(a, lsc(d, t))));
}

/* Distance from x to the solid disk (centre c, unit normal n, radius r): height and radial excess. */
static inline ld tb_disk_dist(lv3 x, lv3 c, lv3 n, ld r)
{
    lv3 q = lsub(x, c);
    ld h = ldot(q, n), rho = lnorm(lsub(q, lsc(n, h)));
    ld e = rho > r ? rho - r : 0;
    return sqrtl(h * h + e * e);
}

/* A function of one parameter with its data: what the minimisers below sample. */
typedef ld (*tb_fn)(const void *ctx, ld t);

/* Golden-section search (90 steps) for the minimum of sign * f on [lo, hi] (sign = -1: a maximum of
 * f). Returns f there; *arg (if non-null) receives the abscissa. */
static inline ld tb_golden(tb_fn f, const void *ctx, ld lo, ld hi, ld sign, ld *arg)
{
    const ld g = 0.6180339887498948482L;
    ld c = hi - g * (hi - lo), d = lo + g * (hi - lo), fc = sign * f(ctx, c), fd = sign * f(ctx, d);
    for (int it = 0; it < 90; ++it) {
        if (fc < fd) { hi = d; d = c; fd = fc; c = hi - g * (hi - lo); fc = sign * f(ctx, c); }
        else { lo = c; c = d; fc = fd; d = lo + g * (hi - lo); fd = sign * f(ctx, d); }
    }
    if (arg) *arg = fc < fd ? c : d;
    return sign * (fc < fd ? fc : fd);
}

/* Most samples the minimisers take. */
enum { TB_MAX_SAMPLES = 1024 };

/* Minimum of a 2pi-periodic f: n samples at i 2pi / n, every sampled local minimum refined by golden
 * section over its two neighbouring intervals; the smallest sample or refined value. */
static inline ld tb_min_periodic(tb_fn f, const void *ctx, int n)
{
    ld v[TB_MAX_SAMPLES], best = 1e300L, step = 2 * (ld)PROX_PI / n;
    assert_true(n >= 3 && n <= TB_MAX_SAMPLES);
    for (int i = 0; i < n; ++i) v[i] = f(ctx, i * step);
    for (int i = 0; i < n; ++i) {
        if (v[i] < best) best = v[i];
        if (v[i] <= v[(i + n - 1) % n] && v[i] <= v[(i + 1) % n]) {
            ld m = tb_golden(f, ctx, (i - 1) * step, (i + 1) * step, 1, NULL);
            if (m < best) best = m;
        }
    }
    return best;
}

/* A circle (centre c, orthonormal u, v in its plane, radius r) against a line (point p, unit w). */
typedef struct tb_circle_line {
    lv3 c, u, v, p, w;
    ld r;
} tb_circle_line;

/* Minus the distance of the circle point at angle t from the line (for tb_min_periodic). */
static inline ld tb_neg_dist_from_line(const void *ctx, ld t)
{
    const tb_circle_line *k = ctx;
    lv3 x = lsub(ladd(k->c, ladd(lsc(k->u, k->r * cosl(t)), lsc(k->v, k->r * sinl(t)))), k->p);
    return -lnorm(lsub(x, lsc(k->w, ldot(x, k->w))));
}

/* Largest distance of the circle (centre c, unit normal n, radius r) from the line (p, unit w): 1024
 * samples, every local maximum refined by golden section. */
static inline ld tb_circle_line_max_dist(prox_vec3 c, prox_vec3 n, double r, prox_vec3 p, prox_vec3 w)
{
    prox_vec3 u = prox_v3_any_perp(n);
    tb_circle_line k = {L(c), L(u), L(prox_v3_cross(n, u)), L(p), L(w), r};
    return -tb_min_periodic(tb_neg_dist_from_line, &k, TB_MAX_SAMPLES);
}

/* Minimum of f on [0, 1]: n + 1 samples at i / n, refined by golden section over the neighbouring
 * intervals of the best sample (every_local_min = 0: enough for a convex f) or of every sampled
 * local minimum (every_local_min = 1); the smallest sample or refined value. */
static inline ld tb_min_unit(tb_fn f, const void *ctx, int n, int every_local_min)
{
    ld v[TB_MAX_SAMPLES + 1], best = 1e300L;
    int ib = 0;
    assert_true(n >= 2 && n <= TB_MAX_SAMPLES);
    for (int i = 0; i <= n; ++i) {
        v[i] = f(ctx, (ld)i / n);
        if (v[i] < best) {
            best = v[i];
            ib = i;
        }
    }
    for (int i = 0; i <= n; ++i) {
        int local = (i == 0 || v[i] <= v[i - 1]) && (i == n || v[i] <= v[i + 1]);
        if (every_local_min ? !local : i != ib) continue;
        ld m = tb_golden(f, ctx, (ld)(i > 0 ? i - 1 : 0) / n, (ld)(i < n ? i + 1 : n) / n, 1, NULL);
        if (m < best) best = m;
    }
    return best;
}

/* Random-case builders shared by the tests: a scale 10^U(-6, 6), an origin (every fifth case 1e8 away,
 * else within 3 scales) and a point within s of o. */
static inline double tb_random_scale(test_rng *r) { return pow(10.0, test_range(r, -6, 6)); }
static inline prox_vec3 tb_random_origin(test_rng *r, int i, double s)
{
    return (i % 5 == 0) ? prox_v3_scale(test_unit(r), 1e8) : prox_v3_scale(test_unit(r), s * test_range(r, 0, 3));
}
static inline prox_vec3 tb_rp(test_rng *r, prox_vec3 o, double s)
{
    return prox_v3_mad(o, s * test_range(r, 0, 1), test_unit(r));
}
/* A random segment with both ends within s of o. */
static inline prox_segment tb_random_segment(test_rng *r, prox_vec3 o, double s)
{
    prox_segment sg = {tb_rp(r, o, s), tb_rp(r, o, s)};
    return sg;
}
/* A random circle or disk: centre within s of o, random unit normal, radius s U(0.1, 1.5). */
static inline prox_circle tb_random_circle(test_rng *r, prox_vec3 o, double s)
{
    prox_circle c = {tb_rp(r, o, s), test_unit(r), s * test_range(r, 0.1, 1.5)};
    return c;
}
/* A random cylindrical surface (height 0): base within s of o, random unit axis, radius s U(0.05, 1.5). */
static inline prox_cylsurf tb_random_cylsurf(test_rng *r, prox_vec3 o, double s)
{
    prox_cylsurf cs = {tb_rp(r, o, s), test_unit(r), 0, s * test_range(r, 0.05, 1.5)};
    return cs;
}

/* Coordinate scale of a segment against a round primitive (centre c, radius r): the largest coordinate,
 * radius or segment length; tolerances are 1e-12 of it. */
static inline double tb_seg_scale(const prox_segment *s, prox_vec3 c, double r)
{
    double sc = fmax(fmax(prox_v3_maxabs(s->a), prox_v3_maxabs(s->b)), fmax(prox_v3_maxabs(c), r));
    return fmax(sc, prox_v3_dist(s->a, s->b));
}

#endif
