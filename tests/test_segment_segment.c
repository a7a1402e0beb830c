/* segment_segment.c against an independent brute force in long double: nested minimisation
 * (golden section over t1 of the clamped-projection distance, which is convex in t1), plus hand-made
 * parallel, near-parallel, crossing, zero-length, huge/tiny and far-from-origin cases. */
#include "test_brute.h"

/* The two segments in long double. */
typedef struct segpair {
    lv3 a1, d1, a2, d2;
} segpair;
/* dist(a1 + t1 d1, segment 2), convex in t1. */
static ld seg_eval(const void *ctx, ld t1)
{
    const segpair *P = ctx;
    return lseg_dist(ladd(P->a1, lsc(P->d1, t1)), P->a2, P->d2);
}
/* min over t1 in [0,1] of dist(a1 + t1 d1, segment 2): dense samples then golden section. */
static ld brute(const prox_segment *s1, const prox_segment *s2)
{
    segpair P = {L(s1->a), lsub(L(s1->b), L(s1->a)), L(s2->a), lsub(L(s2->b), L(s2->a))};
    return tb_min_unit(seg_eval, &P, 64, 0);
}

static double seg_scale(const prox_segment *s1, const prox_segment *s2)
{
    double m = fmax(fmax(prox_v3_maxabs(s1->a), prox_v3_maxabs(s1->b)), fmax(prox_v3_maxabs(s2->a), prox_v3_maxabs(s2->b)));
    return fmax(m, fmax(prox_v3_dist(s1->a, s1->b), prox_v3_dist(s2->a, s2->b)));
}

static prox_prim_result check(prox_segment s1, prox_segment s2)
{
    prox_prim_result res = prox_segment_segment(&s1, &s2);
    assert_int_equal(res.status, PROX_OK);
    double tol = 1e-12 * seg_scale(&s1, &s2);
    assert_near(res.distance, (double)brute(&s1, &s2), tol);
    assert_near(prox_v3_dist(res.p1, res.p2), res.distance, tol);
    assert_true(res.s1[0] >= 0 && res.s1[0] <= 1 && res.s2[0] >= 0 && res.s2[0] <= 1);
    lv3 a1 = L(s1.a), d1 = lsub(L(s1.b), a1), a2 = L(s2.a), d2 = lsub(L(s2.b), a2);
    assert_near(tb_seg_point_err(res.p1, a1, d1, res.s1[0]), 0, tol);
    assert_near(tb_seg_point_err(res.p2, a2, d2, res.s2[0]), 0, tol);
    return res;
}

static void test_segment_segment_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(404);
    for (int i = 0; i < 20000; ++i) {
        double s = tb_random_scale(&r);
        prox_vec3 o = tb_random_origin(&r, i, s);
        prox_segment s1 = tb_random_segment(&r, o, s), s2 = tb_random_segment(&r, o, s);
        prox_vec3 d1 = prox_v3_sub(s1.b, s1.a);
        switch (i % 8) {
        case 1: /* exactly parallel (scaled copy of the direction) */
            s2.b = prox_v3_mad(s2.a, test_range(&r, -2, 2), d1);
            break;
        case 2: { /* near parallel: tilt by a tiny angle */
            double eps = pow(10.0, test_range(&r, -15, -5));
            prox_vec3 t = prox_v3_scale(test_unit(&r), eps * prox_v3_norm(d1));
            s2.b = prox_v3_add(prox_v3_mad(s2.a, test_range(&r, -2, 2), d1), t);
            break;
        }
        case 3: /* crossing: both through a common point */
        {
            prox_vec3 x = prox_v3_mad(s1.a, test_range(&r, 0, 1), d1);
            s2.b = prox_v3_mad(x, test_range(&r, 0.1, 1), prox_v3_sub(x, s2.a));
            break;
        }
        case 4: s1.b = s1.a; break; /* zero length */
        case 5: s1.b = s1.a; s2.b = s2.a; break;
        default: break;
        }
        check(s1, s2);
    }
}

static void test_segment_segment_special(void **st)
{
    (void)st;
    /* perpendicular, skew */
    prox_prim_result res = check((prox_segment){prox_v3(-1, 0, 0), prox_v3(1, 0, 0)}, (prox_segment){prox_v3(0, -1, 2), prox_v3(0, 1, 2)});
    assert_near(res.distance, 2, 1e-15);
    assert_near(res.s1[0], 0.5, 1e-15);
    assert_int_equal(res.set, 0);
    /* parallel with overlap: set */
    res = check((prox_segment){prox_v3(0, 0, 0), prox_v3(4, 0, 0)}, (prox_segment){prox_v3(3, 1, 0), prox_v3(9, 1, 0)});
    assert_near(res.distance, 1, 1e-15);
    assert_int_equal(res.set, 1);
    /* antiparallel with overlap */
    res = check((prox_segment){prox_v3(0, 0, 0), prox_v3(4, 0, 0)}, (prox_segment){prox_v3(9, 0, 1), prox_v3(3, 0, 1)});
    assert_int_equal(res.set, 1);
    /* parallel without overlap: endpoints, not a set */
    res = check((prox_segment){prox_v3(0, 0, 0), prox_v3(1, 0, 0)}, (prox_segment){prox_v3(4, 3, 0), prox_v3(9, 3, 0)});
    assert_near(res.distance, sqrt(18.0), 1e-15);
    assert_int_equal(res.set, 0);
    /* collinear overlapping: distance 0, set */
    res = check((prox_segment){prox_v3(0, 0, 0), prox_v3(2, 0, 0)}, (prox_segment){prox_v3(1, 0, 0), prox_v3(3, 0, 0)});
    assert_near(res.distance, 0, 0);
    assert_int_equal(res.set, 1);
    /* crossing at interior points */
    res = check((prox_segment){prox_v3(-1, -1, 0), prox_v3(1, 1, 0)}, (prox_segment){prox_v3(-1, 1, 0), prox_v3(1, -1, 0)});
    assert_near(res.distance, 0, 1e-16);
    /* touching at an endpoint */
    res = check((prox_segment){prox_v3(0, 0, 0), prox_v3(1, 0, 0)}, (prox_segment){prox_v3(1, 0, 0), prox_v3(1, 5, 7)});
    assert_near(res.distance, 0, 0);
    /* huge, tiny, far */
    check((prox_segment){prox_v3(-1e6, 0, 0), prox_v3(1e6, 1, 0)}, (prox_segment){prox_v3(0, -1e6, 3e5), prox_v3(1, 1e6, 3e5)});
    res = check((prox_segment){prox_v3(-1e-6, 0, 0), prox_v3(1e-6, 0, 0)}, (prox_segment){prox_v3(0, -1e-6, 3e-7), prox_v3(0, 1e-6, 3e-7)});
    assert_near(res.distance, 3e-7, 1e-20);
    res = check((prox_segment){prox_v3(1e8 - 1, 1e8, 1e8), prox_v3(1e8 + 1, 1e8, 1e8)}, (prox_segment){prox_v3(1e8, 1e8 - 1, 1e8 + 2), prox_v3(1e8, 1e8 + 1, 1e8 + 2)});
    assert_near(res.distance, 2, 1e-7);
    /* nearly parallel long segments, tilted by 1e-13: the minimum is at an end, distance known */
    res = check((prox_segment){prox_v3(0, 0, 0), prox_v3(1, 0, 0)}, (prox_segment){prox_v3(0, 1, 0), prox_v3(1, 1 + 1e-13, 0)});
    assert_near(res.distance, 1, 1e-15);
    /* invalid */
    prox_segment ok = {prox_v3(0, 0, 0), prox_v3(1, 0, 0)}, bad = {prox_v3(0, NAN, 0), prox_v3(1, 0, 0)};
    assert_int_equal(prox_segment_segment(&ok, &bad).status, PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_segment_segment(NULL, &ok).status, PROX_EINVAL_ARG);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_segment_segment_random),
        cmocka_unit_test(test_segment_segment_special),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
