/* segment_cylsurf.c and cylsurf_cylsurf.c against independent long-double computations:
 * segment vs infinite surface by dense sampling of |rho(t) - r| plus golden-section refinement;
 * P(S,S) by the normal equations of the two axes solved in long double; hand-made special cases. */
#include "test_brute.h"

/* Distance of x from the axis (base o, unit w). */
static ld lrho(lv3 x, lv3 o, lv3 w)
{
    lv3 d = lsub(x, o);
    return lnorm(lsub(d, lsc(w, ldot(d, w))));
}

typedef struct segsurf {
    lv3 a, d, o, w;
    ld r;
} segsurf;
/* Distance |rho(t) - r| of the segment point at t from the surface (not convex: every sampled local
 * minimum is refined). */
static ld ss_eval(const void *ctx, ld t)
{
    const segsurf *S = ctx;
    return fabsl(lrho(ladd(S->a, lsc(S->d, t)), S->o, S->w) - S->r);
}
static ld ss_brute(const segsurf *S) { return tb_min_unit(ss_eval, S, 200, 1); }

static prox_prim_result check_seg_surf(prox_segment sg, prox_cylsurf cs)
{
    prox_prim_result res = prox_segment_cylsurf_inf(&sg, &cs);
    assert_int_equal(res.status, PROX_OK);
    double tol = 1e-12 * tb_seg_scale(&sg, cs.base, cs.radius);
    segsurf S = {L(sg.a), lsub(L(sg.b), L(sg.a)), L(cs.base), lunit(L(cs.dir)), cs.radius};
    assert_near(res.distance, (double)ss_brute(&S), tol);
    assert_near(prox_v3_dist(res.p1, res.p2), res.distance, tol);
    assert_true(res.s1[0] >= 0 && res.s1[0] <= 1);
    assert_near(tb_seg_point_err(res.p1, S.a, S.d, res.s1[0]), 0, tol);
    assert_near((double)lrho(L(res.p2), S.o, S.w), cs.radius, tol);
    assert_near(res.s2[0], (double)ldot(lsub(L(res.p2), S.o), S.w), tol);
    prox_vec3 w = prox_v3_normalize(cs.dir);
    prox_circle ring = {prox_v3_mad(cs.base, res.s2[0], w), w, cs.radius};
    assert_near(prox_v3_dist(prox_circle_point(&ring, res.s2[1]), res.p2), 0, 4 * tol);
    return res;
}

static void test_segment_cylsurf_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(505);
    for (int i = 0; i < 4000; ++i) {
        double s = tb_random_scale(&r);
        prox_vec3 o = tb_random_origin(&r, i, s);
        prox_cylsurf cs = tb_random_cylsurf(&r, o, s);
        prox_segment sg = tb_random_segment(&r, o, 2 * s);
        switch (i % 6) {
        case 1: sg.b = prox_v3_mad(sg.a, s * test_range(&r, -2, 2), cs.dir); break; /* parallel to the axis */
        case 2: sg.b = sg.a; break;                                                 /* zero length */
        case 3: /* inside: both ends within the cylinder */
            sg.a = prox_v3_add(prox_v3_mad(cs.base, s * test_range(&r, -2, 2), cs.dir), prox_v3_scale(prox_v3_any_perp(cs.dir), 0.4 * cs.radius));
            sg.b = prox_v3_mad(cs.base, s * test_range(&r, -2, 2), cs.dir);
            break;
        default: break;
        }
        check_seg_surf(sg, cs);
    }
}

static void test_segment_cylsurf_special(void **st)
{
    (void)st;
    prox_cylsurf cs = {prox_v3(0, 0, 0), prox_v3(0, 0, 3), 99, 1}; /* non-unit dir; height ignored */
    prox_prim_result res = check_seg_surf((prox_segment){prox_v3(3, -5, 0), prox_v3(3, 5, 7)}, cs);
    assert_near(res.distance, 2, 1e-15); /* outside, perpendicular-ish */
    res = check_seg_surf((prox_segment){prox_v3(-3, 0, 1), prox_v3(3, 0, 1)}, cs); /* crossing */
    assert_near(res.distance, 0, 0);
    assert_near(res.p1.x, -1, 1e-15);
    res = check_seg_surf((prox_segment){prox_v3(0.5, 0, 1), prox_v3(-0.2, 0, 1)}, cs); /* inside */
    assert_near(res.distance, 0.5, 1e-15);
    res = check_seg_surf((prox_segment){prox_v3(2, 0, -1), prox_v3(2, 0, 9)}, cs); /* parallel outside */
    assert_near(res.distance, 1, 1e-15);
    assert_int_equal(res.set, 1);
    res = check_seg_surf((prox_segment){prox_v3(0, 0, -1), prox_v3(0, 0, 9)}, cs); /* on the axis */
    assert_near(res.distance, 1, 1e-15);
    assert_int_equal(res.set, 1);
    res = check_seg_surf((prox_segment){prox_v3(1, 0, -1), prox_v3(0, 1, -1)}, cs); /* chord: ends on S */
    assert_near(res.distance, 0, 0);
    res = check_seg_surf((prox_segment){prox_v3(1, -1, 0), prox_v3(1, 1, 0)}, cs); /* tangent */
    assert_near(res.distance, 0, 1e-15);
    check_seg_surf((prox_segment){prox_v3(1e8 + 3, 1e8, 1e8), prox_v3(1e8 - 3, 1e8 + 1, 1e8)},
                   (prox_cylsurf){prox_v3(1e8, 1e8, 1e8), prox_v3(0, 0, 1), 0, 2});
    check_seg_surf((prox_segment){prox_v3(3e6, -1e6, 0), prox_v3(3e6, 1e6, 1e6)}, (prox_cylsurf){prox_v3(0, 0, 0), prox_v3(0, 1, 1), 0, 1e6});
    check_seg_surf((prox_segment){prox_v3(3e-6, -1e-6, 0), prox_v3(3e-6, 1e-6, 1e-6)}, (prox_cylsurf){prox_v3(0, 0, 0), prox_v3(0, 1, 1), 0, 1e-6});
    prox_cylsurf bad = cs;
    bad.radius = 0;
    prox_segment sg = {prox_v3(0, 0, 0), prox_v3(1, 0, 0)};
    assert_int_equal(prox_segment_cylsurf_inf(&sg, &bad).status, PROX_EINVAL_RADIUS);
    bad = cs;
    bad.dir = prox_v3(0, 0, 0);
    assert_int_equal(prox_segment_cylsurf_inf(&sg, &bad).status, PROX_EINVAL_AXIS);
    sg.a.x = NAN;
    assert_int_equal(prox_segment_cylsurf_inf(&sg, &cs).status, PROX_EINVAL_NONFINITE);
}

/* --- P(S,S) --- */
/* Signed axis distance - r1 - r2 from the long-double normal equations of the two axes. */
static ld ss_signed_brute(const prox_cylsurf *a, const prox_cylsurf *b, ld *t1o, ld *t2o)
{
    lv3 d1 = lunit(L(a->dir)), d2 = lunit(L(b->dir)), D = lsub(L(b->base), L(a->base));
    ld c = ldot(d1, d2), e1 = ldot(D, d1), e2 = ldot(D, d2), det = 1 - c * c;
    /* t1 - c t2 = e1, c t1 - t2 = e2 */
    ld t1 = (e1 - c * e2) / det, t2 = (c * e1 - e2) / det;
    *t1o = t1;
    *t2o = t2;
    return lnorm(lsub(ladd(L(a->base), lsc(d1, t1)), ladd(L(b->base), lsc(d2, t2)))) - a->radius - b->radius;
}

static prox_prim_result check_ss(prox_cylsurf a, prox_cylsurf b, int compare)
{
    prox_prim_result res = prox_cylsurf_cylsurf_inf(&a, &b);
    assert_int_equal(res.status, PROX_OK);
    double sc = fmax(fmax(prox_v3_maxabs(a.base), prox_v3_maxabs(b.base)), fmax(a.radius, b.radius));
    sc = fmax(sc, fmax(fabs(res.s1[0]), fabs(res.s2[0])));
    double tol = 1e-12 * sc;
    lv3 d1 = lunit(L(a.dir)), d2 = lunit(L(b.dir));
    if (compare) {
        ld t1, t2, bf = ss_signed_brute(&a, &b, &t1, &t2);
        assert_near(res.distance, (double)bf, tol);
        assert_near(res.s1[0], (double)t1, tol);
        assert_near(res.s2[0], (double)t2, tol);
    }
    assert_near(prox_v3_dist(res.p1, res.p2), fabs(res.distance), tol);
    assert_near((double)lrho(L(res.p1), L(a.base), d1), a.radius, tol);
    assert_near((double)lrho(L(res.p2), L(b.base), d2), b.radius, tol);
    assert_near((double)ldot(lsub(L(res.p1), L(a.base)), d1), res.s1[0], tol);
    assert_near((double)ldot(lsub(L(res.p2), L(b.base)), d2), res.s2[0], tol);
    /* the pair lies on a common perpendicular */
    lv3 q = lsub(L(res.p2), L(res.p1));
    assert_near((double)ldot(q, d1), 0, tol);
    assert_near((double)ldot(q, d2), 0, tol);
    return res;
}

static void test_cylsurf_cylsurf_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(606);
    for (int i = 0; i < 20000; ++i) {
        double s = tb_random_scale(&r);
        prox_vec3 o = tb_random_origin(&r, i, s);
        prox_cylsurf a = tb_random_cylsurf(&r, o, s);
        prox_cylsurf b = tb_random_cylsurf(&r, o, s);
        int compare = prox_v3_norm(prox_v3_cross(a.dir, b.dir)) > 1e-2;
        if (i % 10 == 3) { /* near parallel: properties only */
            b.dir = prox_v3_normalize(prox_v3_mad(a.dir, pow(10.0, test_range(&r, -11, -3)), test_unit(&r)));
            compare = 0;
        }
        if (i % 10 == 4) { /* exactly parallel or antiparallel */
            b.dir = (i % 20 == 4) ? a.dir : prox_v3_neg(a.dir);
            compare = 0;
            prox_prim_result res = check_ss(a, b, 0);
            assert_int_equal(res.set, 1);
            double ad = (double)lrho(L(b.base), L(a.base), lunit(L(a.dir)));
            assert_near(res.distance, ad - a.radius - b.radius, 1e-12 * fmax(s, prox_v3_maxabs(o)));
            continue;
        }
        check_ss(a, b, compare);
    }
}

static void test_cylsurf_cylsurf_special(void **st)
{
    (void)st;
    /* perpendicular axes 5 apart: 5 - 1 - 2 */
    prox_prim_result res = check_ss((prox_cylsurf){prox_v3(0, 0, 0), prox_v3(1, 0, 0), 0, 1}, (prox_cylsurf){prox_v3(7, 3, 5), prox_v3(0, 1, 0), 0, 2}, 1);
    assert_near(res.distance, 2, 1e-15);
    assert_near(res.s1[0], 7, 1e-15);
    assert_near(res.s2[0], -3, 1e-15);
    assert_near(res.p1.z, 1, 1e-15);
    assert_near(res.p2.z, 3, 1e-15);
    /* interpenetrating: negative */
    res = check_ss((prox_cylsurf){prox_v3(0, 0, 0), prox_v3(1, 0, 0), 0, 1}, (prox_cylsurf){prox_v3(0, 0, 0.5), prox_v3(0, 1, 0), 0, 2}, 1);
    assert_near(res.distance, -2.5, 1e-15);
    /* intersecting axes: axis distance 0 */
    res = check_ss((prox_cylsurf){prox_v3(0, 0, 0), prox_v3(1, 1, 0), 0, 1}, (prox_cylsurf){prox_v3(0, 0, 0), prox_v3(0, 1, 0), 0, 1}, 1);
    assert_near(res.distance, -2, 1e-15);
    /* parallel, antiparallel, coaxial */
    res = check_ss((prox_cylsurf){prox_v3(0, 0, 0), prox_v3(0, 0, 1), 0, 1}, (prox_cylsurf){prox_v3(3, 4, 17), prox_v3(0, 0, 2), 0, 1}, 0);
    assert_int_equal(res.set, 1);
    assert_near(res.distance, 3, 1e-15);
    assert_near(res.s1[0], 0, 0);
    assert_near(res.s2[0], -17, 1e-14);
    res = check_ss((prox_cylsurf){prox_v3(0, 0, 0), prox_v3(0, 0, 1), 0, 1}, (prox_cylsurf){prox_v3(3, 4, 17), prox_v3(0, 0, -1), 0, 1}, 0);
    assert_int_equal(res.set, 1);
    assert_near(res.distance, 3, 1e-15);
    res = check_ss((prox_cylsurf){prox_v3(0, 0, 0), prox_v3(0, 0, 1), 0, 1}, (prox_cylsurf){prox_v3(0, 0, 5), prox_v3(0, 0, 1), 0, 3}, 0);
    assert_int_equal(res.set, 1);
    assert_near(res.distance, -4, 1e-15);
    /* huge, tiny, far */
    check_ss((prox_cylsurf){prox_v3(1e6, 0, 0), prox_v3(1, 2, 3), 0, 1e6}, (prox_cylsurf){prox_v3(0, 4e6, 1e6), prox_v3(-3, 1, 0), 0, 5e5}, 1);
    check_ss((prox_cylsurf){prox_v3(1e-6, 0, 0), prox_v3(1, 2, 3), 0, 1e-6}, (prox_cylsurf){prox_v3(0, 4e-6, 1e-6), prox_v3(-3, 1, 0), 0, 5e-7}, 1);
    res = check_ss((prox_cylsurf){prox_v3(1e8, 1e8, 1e8), prox_v3(1, 0, 0), 0, 1}, (prox_cylsurf){prox_v3(1e8, 1e8, 1e8 + 4), prox_v3(0, 1, 0), 0, 1}, 1);
    assert_near(res.distance, 2, 1e-8);
    prox_cylsurf ok = {prox_v3(0, 0, 0), prox_v3(1, 0, 0), 0, 1}, bad = ok;
    bad.radius = -1;
    assert_int_equal(prox_cylsurf_cylsurf_inf(&ok, &bad).status, PROX_EINVAL_RADIUS);
    bad = ok;
    bad.dir.y = INFINITY;
    assert_int_equal(prox_cylsurf_cylsurf_inf(&bad, &ok).status, PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_cylsurf_cylsurf_inf(&ok, NULL).status, PROX_EINVAL_ARG);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_segment_cylsurf_random),
        cmocka_unit_test(test_segment_cylsurf_special),
        cmocka_unit_test(test_cylsurf_cylsurf_random),
        cmocka_unit_test(test_cylsurf_cylsurf_special),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
