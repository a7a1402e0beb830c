/* Circle to circle (src/distance/circle_circle.c): seeded random pairs against an independent brute
 * force (dense sampling of circle a in long double with the closed-form closest point on b, then
 * golden-section refinement of every sampled local minimum), plus hand-made special cases. */
#include "test_util.h"
#include "core/circle.h"
#include <float.h>

typedef long double ld;

/* Brute-force reference for one pair, in coordinates relative to a's centre. */
typedef struct bf_pair {
    ld cb[3], na[3], nb[3], ua[3], va[3], ra, rb;
} bf_pair;

static void bf_unit(prox_vec3 n, ld out[3])
{
    ld x = n.x, y = n.y, z = n.z, m = sqrtl(x * x + y * y + z * z);
    out[0] = x / m, out[1] = y / m, out[2] = z / m;
}

/* An independent frame for a (not prox_circle_frame): u from the axis of smallest |n_k|. */
static bf_pair bf_make(const prox_circle *a, const prox_circle *b)
{
    bf_pair p;
    p.cb[0] = (ld)b->center.x - a->center.x, p.cb[1] = (ld)b->center.y - a->center.y;
    p.cb[2] = (ld)b->center.z - a->center.z;
    bf_unit(a->normal, p.na), bf_unit(b->normal, p.nb);
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (fabsl(p.na[i]) < fabsl(p.na[k])) k = i;
    ld e[3] = {0, 0, 0}, d;
    e[k] = 1;
    d = e[0] * p.na[0] + e[1] * p.na[1] + e[2] * p.na[2];
    for (int i = 0; i < 3; ++i) p.ua[i] = e[i] - d * p.na[i];
    d = sqrtl(p.ua[0] * p.ua[0] + p.ua[1] * p.ua[1] + p.ua[2] * p.ua[2]);
    for (int i = 0; i < 3; ++i) p.ua[i] /= d;
    p.va[0] = p.na[1] * p.ua[2] - p.na[2] * p.ua[1];
    p.va[1] = p.na[2] * p.ua[0] - p.na[0] * p.ua[2];
    p.va[2] = p.na[0] * p.ua[1] - p.na[1] * p.ua[0];
    p.ra = a->radius, p.rb = b->radius;
    return p;
}

/* Distance from a's point at angle t to circle b. */
static ld bf_dist(const bf_pair *p, ld t)
{
    ld c = cosl(t), s = sinl(t), d[3], h = 0, rho2 = 0;
    for (int i = 0; i < 3; ++i) d[i] = p->ra * (c * p->ua[i] + s * p->va[i]) - p->cb[i];
    for (int i = 0; i < 3; ++i) h += d[i] * p->nb[i];
    for (int i = 0; i < 3; ++i) rho2 += (d[i] - h * p->nb[i]) * (d[i] - h * p->nb[i]);
    return hypotl(sqrtl(rho2) - p->rb, h);
}

/* Golden-section minimum of bf_dist on [lo, hi]. */
static ld bf_golden(const bf_pair *p, ld lo, ld hi, ld *tmin)
{
    const ld g = 0.61803398874989484820L;
    ld x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = bf_dist(p, x1), f2 = bf_dist(p, x2);
    for (int it = 0; it < 80; ++it) {
        if (f1 < f2) hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = bf_dist(p, x1);
        else lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = bf_dist(p, x2);
    }
    *tmin = f1 < f2 ? x1 : x2;
    return f1 < f2 ? f1 : f2;
}

#define BF_N 2048
/* All sampled local minima refined; returns the global one. mins/angs receive up to 16 of them. */
static ld bf_minima(const bf_pair *p, ld *mins, ld *angs, int *nm)
{
    static ld f[BF_N];
    const ld step = 2 * 3.14159265358979323846264338327950288L / BF_N;
    for (int i = 0; i < BF_N; ++i) f[i] = bf_dist(p, i * step);
    ld best = INFINITY;
    *nm = 0;
    for (int i = 0; i < BF_N; ++i) {
        ld fl = f[(i + BF_N - 1) % BF_N], fr = f[(i + 1) % BF_N];
        if (!(f[i] <= fl && f[i] <= fr)) continue;
        ld t, v = bf_golden(p, (i - 1) * step, (i + 1) * step, &t);
        if (*nm < 16) mins[*nm] = v, angs[*nm] = t, ++*nm;
        if (v < best) best = v;
    }
    return best;
}

/* Distance from x to circle c in long double, relative to origin o (for on-circle checks). */
static double on_circle_err(prox_vec3 x, const prox_circle *c)
{
    ld d[3] = {(ld)x.x - c->center.x, (ld)x.y - c->center.y, (ld)x.z - c->center.z}, n[3], h = 0, r2 = 0;
    bf_unit(c->normal, n);
    for (int i = 0; i < 3; ++i) h += d[i] * n[i];
    for (int i = 0; i < 3; ++i) r2 += (d[i] - h * n[i]) * (d[i] - h * n[i]);
    return (double)hypotl(sqrtl(r2) - c->radius, h);
}

static double pair_scale(const prox_circle *a, const prox_circle *b)
{
    return fmax(fmax(a->radius, b->radius), prox_v3_dist(a->center, b->center));
}

/* Checks one pair against the brute force: distance, witness points, parameters and (when
 * all_minima) that every local minimum of the distance along a is among the stationary angles. */
static void check_pair(const prox_circle *a, const prox_circle *b, double tol_rel, int all_minima)
{
    prox_prim_result r = prox_circle_circle(a, b);
    assert_int_equal(r.status, PROX_OK);
    bf_pair p = bf_make(a, b);
    ld mins[16], angs[16];
    int nm;
    double ref = (double)bf_minima(&p, mins, angs, &nm);
    double scale = pair_scale(a, b);
    double coord = fmax(prox_v3_maxabs(a->center), prox_v3_maxabs(b->center));
    double ptol = tol_rel * scale + 4 * DBL_EPSILON * coord;
    if (!(fabs(r.distance - ref) <= tol_rel * scale)) {
        print_error("a c=(%.17g,%.17g,%.17g) n=(%.17g,%.17g,%.17g) r=%.17g\n", a->center.x, a->center.y,
                    a->center.z, a->normal.x, a->normal.y, a->normal.z, a->radius);
        print_error("b c=(%.17g,%.17g,%.17g) n=(%.17g,%.17g,%.17g) r=%.17g\n", b->center.x, b->center.y,
                    b->center.z, b->normal.x, b->normal.y, b->normal.z, b->radius);
    }
    assert_near(r.distance, ref, tol_rel * scale);
    assert_true(on_circle_err(r.p1, a) <= ptol);
    assert_true(on_circle_err(r.p2, b) <= ptol);
    assert_near(prox_v3_dist(r.p1, r.p2), r.distance, 2 * ptol);
    assert_true(r.s1[0] >= 0 && r.s1[0] < 2 * PROX_PI && r.s2[0] >= 0 && r.s2[0] < 2 * PROX_PI);
    assert_true(prox_v3_dist(prox_circle_point(a, r.s1[0]), r.p1) <= ptol);
    assert_true(prox_v3_dist(prox_circle_point(b, r.s2[0]), r.p2) <= ptol);
    if (!all_minima) return;
    /* Every local minimum along a appears among the stationary angles (the RCC query needs them). */
    prox_fcircle fa = prox_fcircle_make(a->center, prox_v3_normalize(a->normal), a->radius);
    prox_fcircle fb = prox_fcircle_make(b->center, prox_v3_normalize(b->normal), b->radius);
    double th[8];
    int n;
    assert_int_equal(prox_circle_circle_stationary(&fa, &fb, PROX_ROOTS_CHAIN, th, &n), 0);
    for (int m = 0; m < nm; ++m) {
        prox_vec3 x = prox_fcircle_point(&fa, 0); /* locate the brute angle in fa's frame */
        ld t = angs[m];
        prox_vec3 pt = prox_v3(a->center.x + (double)(p.ra * (cosl(t) * p.ua[0] + sinl(t) * p.va[0])),
                               a->center.y + (double)(p.ra * (cosl(t) * p.ua[1] + sinl(t) * p.va[1])),
                               a->center.z + (double)(p.ra * (cosl(t) * p.ua[2] + sinl(t) * p.va[2])));
        (void)x;
        double tm = atan2(prox_v3_dot(prox_v3_sub(pt, fa.c), fa.v), prox_v3_dot(prox_v3_sub(pt, fa.c), fa.u));
        int found = 0;
        for (int i = 0; i < n && !found; ++i) {
            double d = fabs(remainder(th[i] - tm, 2 * PROX_PI));
            double gi = on_circle_err(prox_fcircle_point(&fa, th[i]), b);
            if (d <= 1e-5 || (d <= 0.05 && fabs(gi - (double)mins[m]) <= 1e-11 * scale)) found = 1;
        }
        if (!found) print_error("local minimum %.17g at angle %.17g not among %d stationary angles\n",
                                (double)mins[m], tm, n);
        assert_true(found);
    }
}

static prox_circle rand_circle(test_rng *g, double spread, double rlo, double rhi)
{
    prox_circle c = {prox_v3(test_range(g, -spread, spread), test_range(g, -spread, spread),
                             test_range(g, -spread, spread)),
                     test_unit(g), test_range(g, rlo, rhi)};
    return c;
}

static void test_circle_circle_random(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(2024);
    for (int i = 0; i < 3000; ++i) {
        prox_circle a = rand_circle(&g, 2, 0.2, 2), b = rand_circle(&g, 2, 0.2, 2);
        check_pair(&a, &b, 1e-12, 1);
    }
}

/* Near-touching and crossing pairs: b is built through a point of a, then moved by 1e-14..1e-2. */
static void test_circle_circle_near_touching(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(77);
    for (int i = 0; i < 1500; ++i) {
        prox_circle a = rand_circle(&g, 1, 0.5, 2);
        prox_vec3 x = prox_circle_point(&a, test_range(&g, 0, 2 * PROX_PI));
        prox_vec3 nb = test_unit(&g), w = prox_v3_normalize(prox_v3_reject(test_unit(&g), nb));
        double rb = test_range(&g, 0.2, 3), off = pow(10.0, test_range(&g, -14, -2)) * (i % 5 == 0 ? 0 : 1);
        prox_circle b = {prox_v3_add(prox_v3_mad(x, rb, w), prox_v3_scale(test_unit(&g), off)), nb, rb};
        check_pair(&a, &b, 1e-12, 1);
    }
}

/* Minima near th = pi of a's frame, where the half-angle polynomial's leading coefficient vanishes
 * (t = tan(th/2) -> infinity): b's nearest point to a lies at pi + delta, delta = +-1e-9..1e-2, b
 * tilted up to 0.5 rad and 1.5..5 away, where the solver takes the frame a quarter turn away (or both):
 * every local minimum found by brute force must be among its stationary angles. */
static void test_circle_circle_near_pi(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(31);
    prox_circle a = {prox_v3(0.1, -0.2, 0.3), prox_v3_normalize(prox_v3(0.2, -0.1, 1)), 1.0};
    prox_vec3 u, v;
    prox_circle_frame(&a, &u, &v);
    for (int i = 0; i < 600; ++i) {
        double delta = (i % 2 ? 1 : -1) * pow(10.0, test_range(&g, -9, -2)), th = PROX_PI + delta;
        prox_vec3 dir = prox_v3_add(prox_v3_scale(u, cos(th)), prox_v3_scale(v, sin(th)));
        double far = test_range(&g, 1.5, 5), rb = test_range(&g, 0.2, 3), tilt = test_range(&g, 0, 0.5);
        prox_vec3 nb = prox_v3_normalize(prox_v3_add(a.normal, prox_v3_scale(test_unit(&g), tilt)));
        prox_circle b = {prox_v3_mad(a.center, far + rb, dir), nb, rb};
        check_pair(&a, &b, 1e-12, 1);
    }
}

/* Scales 1e-6..1e6 and translations up to 1e8 from the origin: relative accuracy is kept. */
static void test_circle_circle_scales(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(5);
    const double scales[] = {1e-6, 1e-3, 1e3, 1e6};
    const double offs[] = {0, 1e3, 1e8};
    for (int i = 0; i < 600; ++i) {
        double s = scales[i % 4], o = offs[(i / 4) % 3] * s;
        prox_circle a = rand_circle(&g, 2, 0.2, 2), b = rand_circle(&g, 2, 0.2, 2);
        prox_vec3 off = prox_v3(o, -0.7 * o, 0.3 * o);
        a.center = prox_v3_add(prox_v3_scale(a.center, s), off), a.radius *= s;
        b.center = prox_v3_add(prox_v3_scale(b.center, s), off), b.radius *= s;
        check_pair(&a, &b, 1e-12, 0);
    }
}

/* Parallel planes, coplanar and nearly coaxial pairs. */
static void test_circle_circle_special_random(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(11);
    for (int i = 0; i < 1500; ++i) {
        prox_circle a = rand_circle(&g, 2, 0.2, 2), b = rand_circle(&g, 2, 0.2, 2);
        int kind = i % 3;
        b.normal = (i & 1) ? a.normal : prox_v3_neg(a.normal);
        if (kind == 0) { /* coplanar */
            b.center = prox_v3_mad(b.center, -prox_v3_dot(prox_v3_sub(b.center, a.center), a.normal), a.normal);
        } else if (kind == 2) { /* nearly coaxial: tilted and shifted by 1e-10..1e-4 */
            double e = pow(10.0, test_range(&g, -10, -4));
            b.center = prox_v3_mad(prox_v3_mad(a.center, test_range(&g, -2, 2), a.normal), e, test_unit(&g));
            b.normal = prox_v3_normalize(prox_v3_mad(b.normal, e, test_unit(&g)));
        }
        check_pair(&a, &b, 1e-12, kind != 2);
    }
}

static void test_circle_circle_hand_made(void **state)
{
    (void)state;
    const prox_vec3 z = prox_v3(0, 0, 1);
    prox_circle a = {prox_v3(0, 0, 0), z, 1};
    /* Coplanar disjoint: closest at (1,0,0)-(2,0,0). */
    prox_circle b = {prox_v3(3, 0, 0), z, 1};
    prox_prim_result r = prox_circle_circle(&a, &b);
    assert_near(r.distance, 1, 1e-15);
    assert_near(r.p1.x, 1, 1e-15);
    assert_near(r.p2.x, 2, 1e-15);
    assert_int_equal(r.set, 0);
    check_pair(&a, &b, 1e-12, 1);
    /* Coplanar nested concentric: a set at distance 2. */
    b = (prox_circle){prox_v3(0, 0, 0), prox_v3(0, 0, -1), 3};
    r = prox_circle_circle(&a, &b);
    assert_near(r.distance, 2, 1e-15);
    assert_int_equal(r.set, 1);
    /* Coaxial in different planes: distance hypot(1, 2), a set. */
    b = (prox_circle){prox_v3(0, 0, 2), z, 2};
    r = prox_circle_circle(&a, &b);
    assert_near(r.distance, sqrt(5.0), 1e-15);
    assert_int_equal(r.set, 1);
    assert_near(prox_v3_dist(r.p1, r.p2), r.distance, 1e-15);
    /* Parallel planes, offset: (1,0,0)-(4,0,1). */
    b = (prox_circle){prox_v3(5, 0, 1), z, 1};
    r = prox_circle_circle(&a, &b);
    assert_near(r.distance, sqrt(10.0), 1e-15);
    assert_near(r.p2.x, 4, 1e-14);
    /* Crossing rings: b in the xz plane through (1,0,0): distance 0 there. */
    b = (prox_circle){prox_v3(1, 0, 0.5), prox_v3(0, 1, 0), 0.5};
    r = prox_circle_circle(&a, &b);
    assert_near(r.distance, 0, 1e-15);
    assert_near(r.p1.x, 1, 1e-8);
    check_pair(&a, &b, 1e-12, 1);
    /* Interlocked rings (chain links) and a tangent to b's axis: b centred at (1,0,0) in the xz plane
     * has its axis along y through a's point (1,0,0): every point of b is at distance 0.5 (a set). */
    b = (prox_circle){prox_v3(1, 0, 0), prox_v3(0, 1, 0), 0.5};
    r = prox_circle_circle(&a, &b);
    assert_near(r.distance, 0.5, 1e-15);
    assert_int_equal(r.set, 1);
    check_pair(&a, &b, 1e-12, 1);
    /* Interlocked generic: brute force. */
    b = (prox_circle){prox_v3(0.9, 0.1, 0), prox_v3_normalize(prox_v3(0.1, 1, 0.05)), 0.7};
    check_pair(&a, &b, 1e-12, 1);
    /* Touching externally in a plane: distance 1e-12. */
    b = (prox_circle){prox_v3(2 + 1e-12, 0, 0), z, 1};
    r = prox_circle_circle(&a, &b);
    assert_near(r.distance, 1e-12, 1e-15);
    /* Circle through the other's axis transversally (cusp, not a minimum). */
    b = (prox_circle){prox_v3(0, 1, 0), prox_v3(1, 0, 0), 0.3};
    check_pair(&a, &b, 1e-12, 1);
    /* The minimum at th = pi exactly (t = infinity). */
    prox_vec3 u, v;
    prox_circle_frame(&a, &u, &v);
    b = (prox_circle){prox_v3_scale(u, -3), z, 1};
    r = prox_circle_circle(&a, &b);
    assert_near(r.distance, 1, 1e-15);
    assert_near(r.s1[0], PROX_PI, 1e-8);
    check_pair(&a, &b, 1e-12, 1);
    b.normal = prox_v3_normalize(prox_v3(0.3, 0.2, 1));
    check_pair(&a, &b, 1e-12, 1);
}

static void test_circle_circle_bad_input(void **state)
{
    (void)state;
    prox_circle a = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1}, b = a;
    b.radius = 0;
    assert_int_equal(prox_circle_circle(&a, &b).status, PROX_EINVAL_RADIUS);
    b.radius = NAN;
    assert_int_equal(prox_circle_circle(&a, &b).status, PROX_EINVAL_NONFINITE);
    b.radius = 1, b.normal = prox_v3(0, 0, 0);
    assert_int_equal(prox_circle_circle(&a, &b).status, PROX_EINVAL_AXIS);
    b.normal = prox_v3(0, 0, 1), b.center.x = INFINITY;
    assert_int_equal(prox_circle_circle(&b, &a).status, PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_circle_circle(NULL, &a).status, PROX_EINVAL_ARG);
    /* A non-unit normal is normalised. */
    b = (prox_circle){prox_v3(3, 0, 0), prox_v3(0, 0, 5), 1};
    assert_near(prox_circle_circle(&a, &b).distance, 1, 1e-15);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_circle_circle_hand_made),    cmocka_unit_test(test_circle_circle_bad_input),
        cmocka_unit_test(test_circle_circle_random),       cmocka_unit_test(test_circle_circle_near_touching),
        cmocka_unit_test(test_circle_circle_scales),       cmocka_unit_test(test_circle_circle_special_random),
        cmocka_unit_test(test_circle_circle_near_pi),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
