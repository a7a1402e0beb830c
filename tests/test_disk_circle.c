/* disk_circle.c (P(D, C)) against an independent long-double brute force: the distance from a circle
 * point to the solid disk (closed form in long double) sampled densely over the circle angle and refined
 * by golden section; hand-made parallel, concentric, coaxial, crossing, touching, scaled and far cases. */
#include "test_brute.h"
#include "core/circle.h"

typedef struct prob {
    lv3 c1, n1, c2, u2, v2, n2;
    ld r1, r2;
} prob;
static ld ldisk(const prob *P, lv3 x) { return tb_disk_dist(x, P->c1, P->n1, P->r1); }
static lv3 cpt(const prob *P, ld th) { return ladd(P->c2, lsc(ladd(lsc(P->u2, cosl(th)), lsc(P->v2, sinl(th))), P->r2)); }
/* Distance from the circle point at th to the disk. */
static ld fval(const void *ctx, ld th)
{
    const prob *P = ctx;
    return ldisk(P, cpt(P, th));
}
static ld brute(const prob *P) { return tb_min_periodic(fval, P, 512); }

static prox_prim_result check(prox_disk dk, prox_circle c)
{
    prox_prim_result res = prox_disk_circle(&dk, &c);
    assert_int_equal(res.status, PROX_OK);
    double sc = fmax(fmax(prox_v3_maxabs(dk.center), prox_v3_maxabs(c.center)), fmax(dk.radius, c.radius));
    double tol = 1e-12 * sc;
    prox_fcircle f2 = prox_fcircle_make(c.center, prox_v3_normalize(c.normal), c.radius);
    prob P = {L(dk.center), lunit(L(dk.normal)), L(f2.c), L(f2.u), L(f2.v), L(f2.n), dk.radius, c.radius};
    assert_near(res.distance, (double)brute(&P), tol);
    assert_near(prox_v3_dist(res.p1, res.p2), res.distance, tol);
    assert_near((double)ldisk(&P, L(res.p1)), 0, tol); /* p1 on the disk */
    assert_near((double)lnorm(lsub(L(res.p2), cpt(&P, res.s2[0]))), 0, 4 * tol); /* p2 on the circle at s2[0] */
    prox_fcircle f1 = prox_fcircle_make(dk.center, prox_v3_normalize(dk.normal), dk.radius);
    prox_vec3 q = prox_v3_add(f1.c, prox_v3_add(prox_v3_scale(f1.u, res.s1[1] * cos(res.s1[0])), prox_v3_scale(f1.v, res.s1[1] * sin(res.s1[0]))));
    assert_near(prox_v3_dist(q, res.p1), 0, 4 * tol);
    return res;
}

static void test_disk_circle_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(1001);
    for (int i = 0; i < 4000; ++i) {
        double s = tb_random_scale(&r);
        prox_vec3 o = tb_random_origin(&r, i, s);
        prox_disk dk = tb_random_circle(&r, o, s);
        prox_circle c = tb_random_circle(&r, o, s);
        switch (i % 8) {
        case 1: c.normal = dk.normal; break;                 /* parallel planes */
        case 2: c.normal = prox_v3_neg(dk.normal); break;    /* antiparallel */
        case 3: /* coplanar */
            c.normal = dk.normal;
            c.center = prox_v3_add(dk.center, prox_v3_reject(prox_v3_sub(c.center, dk.center), dk.normal));
            break;
        case 4: /* perpendicular planes */
            c.normal = prox_v3_normalize(prox_v3_reject(c.normal, dk.normal));
            break;
        case 5: /* circle centre in the disk's plane: usually crossing */
            c.center = prox_v3_add(dk.center, prox_v3_reject(prox_v3_sub(c.center, dk.center), dk.normal));
            break;
        default: break;
        }
        check(dk, c);
    }
}

static void test_disk_circle_special(void **st)
{
    (void)st;
    prox_disk dk = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 2};
    /* parallel above, overlapping: set, |h0| */
    prox_prim_result res = check(dk, (prox_circle){prox_v3(1, 0, 3), prox_v3(0, 0, 1), 1.5});
    assert_near(res.distance, 3, 1e-15);
    assert_int_equal(res.set, 1);
    /* concentric parallel (coaxial), inside the disk's projection */
    res = check(dk, (prox_circle){prox_v3(0, 0, -2), prox_v3(0, 0, -1), 1});
    assert_near(res.distance, 2, 1e-15);
    assert_int_equal(res.set, 1);
    /* coaxial, larger than the disk: rim to circle, a set */
    res = check(dk, (prox_circle){prox_v3(0, 0, 4), prox_v3(0, 0, 1), 5});
    assert_near(res.distance, 5, 1e-14);
    assert_int_equal(res.set, 1);
    /* parallel beside */
    res = check(dk, (prox_circle){prox_v3(6, 0, 4), prox_v3(0, 0, 1), 1});
    assert_near(res.distance, sqrt(9.0 + 16.0), 1e-14);
    assert_int_equal(res.set, 0);
    /* coplanar overlapping: 0 */
    res = check(dk, (prox_circle){prox_v3(2.5, 0, 0), prox_v3(0, 0, 1), 1});
    assert_near(res.distance, 0, 0);
    /* vertical circle crossing the disk */
    res = check(dk, (prox_circle){prox_v3(0.5, 0, 0.3), prox_v3(0, 1, 0), 1});
    assert_near(res.distance, 0, 1e-15);
    /* vertical circle above: lowest point over the disk */
    res = check(dk, (prox_circle){prox_v3(0.5, 0, 3), prox_v3(0, 1, 0), 1});
    assert_near(res.distance, 2, 1e-15);
    assert_int_equal(res.set, 0);
    /* vertical circle beside: rim */
    res = check(dk, (prox_circle){prox_v3(5, 0, 0), prox_v3(0, 1, 0), 1});
    assert_near(res.distance, 2, 1e-15);
    /* touching from above */
    res = check(dk, (prox_circle){prox_v3(0, 0, 1), prox_v3(1, 0, 0), 1});
    assert_near(res.distance, 0, 1e-15);
    /* linked with the rim (passes through the plane outside the disk and inside) */
    res = check(dk, (prox_circle){prox_v3(2, 0, 0), prox_v3(0, 1, 0), 1});
    assert_near(res.distance, 0, 1e-15);
    check((prox_disk){prox_v3(1e6, 0, 0), prox_v3(1, 2, 3), 1e6}, (prox_circle){prox_v3(0, 3e6, 0), prox_v3(2, -1, 5), 7e5});
    check((prox_disk){prox_v3(1e-6, 0, 0), prox_v3(1, 2, 3), 1e-6}, (prox_circle){prox_v3(0, 3e-6, 0), prox_v3(2, -1, 5), 7e-7});
    res = check((prox_disk){prox_v3(1e8, 1e8, 1e8), prox_v3(0, 0, 1), 2}, (prox_circle){prox_v3(1e8 + 0.5, 1e8, 1e8 + 3), prox_v3(0, 1, 0), 1});
    assert_near(res.distance, 2, 1e-7);
    prox_circle ok = {prox_v3(0, 0, 5), prox_v3(0, 0, 1), 1}, bad = ok;
    bad.radius = 0;
    assert_int_equal(prox_disk_circle(&dk, &bad).status, PROX_EINVAL_RADIUS);
    bad = ok;
    bad.normal = prox_v3(0, 0, 0);
    assert_int_equal(prox_disk_circle(&bad, &ok).status, PROX_EINVAL_AXIS);
    bad = ok;
    bad.center.z = NAN;
    assert_int_equal(prox_disk_circle(&dk, &bad).status, PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_disk_circle(NULL, &ok).status, PROX_EINVAL_ARG);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_disk_circle_random),
        cmocka_unit_test(test_disk_circle_special),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
