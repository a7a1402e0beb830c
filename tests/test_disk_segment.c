/* disk_segment.c (P(D, L)) against an independent long-double brute force: the distance from a segment
 * point to the disk (closed form in long double) is convex in t, minimised by sampling + golden section;
 * hand-made parallel, piercing, in-plane, perpendicular, huge/tiny and far cases. */
#include "test_brute.h"

typedef struct prob {
    lv3 c, n, a, d;
    ld r;
} prob;
/* Distance from x to the disk: height and radial excess. */
static ld ldisk(const prob *P, lv3 x) { return tb_disk_dist(x, P->c, P->n, P->r); }
/* Distance from the segment point at t to the disk: convex in t. */
static ld fval(const void *ctx, ld t)
{
    const prob *P = ctx;
    return ldisk(P, ladd(P->a, lsc(P->d, t)));
}
static ld brute(const prob *P) { return tb_min_unit(fval, P, 64, 0); }

static prox_prim_result check(prox_disk dk, prox_segment s)
{
    prox_prim_result res = prox_disk_segment(&dk, &s);
    assert_int_equal(res.status, PROX_OK);
    double tol = 1e-12 * tb_seg_scale(&s, dk.center, dk.radius);
    prob P = {L(dk.center), lunit(L(dk.normal)), L(s.a), lsub(L(s.b), L(s.a)), dk.radius};
    assert_near(res.distance, (double)brute(&P), tol);
    assert_near(prox_v3_dist(res.p1, res.p2), res.distance, tol);
    assert_near((double)ldisk(&P, L(res.p1)), 0, tol); /* p1 on the disk */
    assert_true(res.s2[0] >= 0 && res.s2[0] <= 1);
    assert_near(tb_seg_point_err(res.p2, P.a, P.d, res.s2[0]), 0, tol);
    prox_circle cu = dk;
    cu.normal = prox_v3_normalize(dk.normal);
    prox_vec3 u, v;
    prox_circle_frame(&cu, &u, &v);
    prox_vec3 q = prox_v3_add(dk.center, prox_v3_add(prox_v3_scale(u, res.s1[1] * cos(res.s1[0])), prox_v3_scale(v, res.s1[1] * sin(res.s1[0]))));
    assert_near(prox_v3_dist(q, res.p1), 0, 4 * tol);
    return res;
}

static void test_disk_segment_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(909);
    for (int i = 0; i < 20000; ++i) {
        double s = tb_random_scale(&r);
        prox_vec3 o = tb_random_origin(&r, i, s);
        prox_disk dk = tb_random_circle(&r, o, s);
        prox_segment sg = tb_random_segment(&r, o, 2 * s);
        prox_vec3 u, v;
        prox_circle_frame(&dk, &u, &v);
        switch (i % 8) {
        case 1: /* parallel to the plane at some height */
            sg.b = prox_v3_add(sg.a, prox_v3_add(prox_v3_scale(u, s * test_range(&r, -2, 2)), prox_v3_scale(v, s * test_range(&r, -2, 2))));
            break;
        case 2: sg.b = sg.a; break;
        case 3: /* in the plane */
            sg.a = prox_v3_add(dk.center, prox_v3_add(prox_v3_scale(u, s * test_range(&r, -2, 2)), prox_v3_scale(v, s * test_range(&r, -2, 2))));
            sg.b = prox_v3_add(dk.center, prox_v3_add(prox_v3_scale(u, s * test_range(&r, -2, 2)), prox_v3_scale(v, s * test_range(&r, -2, 2))));
            break;
        case 4: sg.b = prox_v3_mad(sg.a, s * test_range(&r, -2, 2), dk.normal); break; /* perpendicular */
        default: break;
        }
        check(dk, sg);
    }
}

static void test_disk_segment_special(void **st)
{
    (void)st;
    prox_disk dk = {prox_v3(0, 0, 0), prox_v3(0, 0, 5), 1};
    /* piercing */
    prox_prim_result res = check(dk, (prox_segment){prox_v3(0.3, 0.2, -1), prox_v3(0.1, -0.4, 2)});
    assert_near(res.distance, 0, 0);
    assert_int_equal(res.set, 0);
    /* perpendicular above the centre */
    res = check(dk, (prox_segment){prox_v3(0.5, 0, 2), prox_v3(0.5, 0, 7)});
    assert_near(res.distance, 2, 1e-15);
    assert_near(res.s2[0], 0, 0);
    /* parallel above, overlapping: set */
    res = check(dk, (prox_segment){prox_v3(-3, 0.5, 2), prox_v3(3, 0.5, 2)});
    assert_near(res.distance, 2, 1e-15);
    assert_int_equal(res.set, 1);
    /* parallel beside: not a set, rim */
    res = check(dk, (prox_segment){prox_v3(-3, 4, 3), prox_v3(3, 4, 3)});
    assert_near(res.distance, sqrt(18.0), 1e-15);
    assert_int_equal(res.set, 0);
    /* in the plane across the disk: zero on a set */
    res = check(dk, (prox_segment){prox_v3(-3, 0.5, 0), prox_v3(3, 0.5, 0)});
    assert_near(res.distance, 0, 0);
    assert_int_equal(res.set, 1);
    /* in the plane outside */
    res = check(dk, (prox_segment){prox_v3(-3, 2, 0), prox_v3(3, 2, 0)});
    assert_near(res.distance, 1, 1e-15);
    /* passing just outside the rim through the plane */
    res = check(dk, (prox_segment){prox_v3(2, 0, -1), prox_v3(2, 0, 1)});
    assert_near(res.distance, 1, 1e-15);
    /* touching the rim */
    res = check(dk, (prox_segment){prox_v3(1, 0, -1), prox_v3(1, 0, 1)});
    assert_near(res.distance, 0, 1e-15);
    /* end on the disk */
    res = check(dk, (prox_segment){prox_v3(0.2, 0.2, 0), prox_v3(1, 1, 1)});
    assert_near(res.distance, 0, 0);
    check((prox_disk){prox_v3(1e6, 0, 0), prox_v3(1, 2, 3), 1e6}, (prox_segment){prox_v3(0, 3e6, 0), prox_v3(2e6, -1e6, 5e5)});
    check((prox_disk){prox_v3(1e-6, 0, 0), prox_v3(1, 2, 3), 1e-6}, (prox_segment){prox_v3(0, 3e-6, 0), prox_v3(2e-6, -1e-6, 5e-7)});
    res = check((prox_disk){prox_v3(1e8, 1e8, 1e8), prox_v3(0, 0, 1), 1}, (prox_segment){prox_v3(1e8, 1e8, 1e8 + 3), prox_v3(1e8 + 1, 1e8, 1e8 + 3)});
    assert_near(res.distance, 3, 1e-7);
    assert_int_equal(res.set, 1);
    prox_segment sg = {prox_v3(0, 0, 0), prox_v3(1, 0, 0)};
    prox_disk bad = dk;
    bad.radius = -2;
    assert_int_equal(prox_disk_segment(&bad, &sg).status, PROX_EINVAL_RADIUS);
    bad = dk;
    bad.normal = prox_v3(0, 0, 0);
    assert_int_equal(prox_disk_segment(&bad, &sg).status, PROX_EINVAL_AXIS);
    bad = dk;
    bad.center.x = NAN;
    assert_int_equal(prox_disk_segment(&bad, &sg).status, PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_disk_segment(&dk, NULL).status, PROX_EINVAL_ARG);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_disk_segment_random),
        cmocka_unit_test(test_disk_segment_special),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
