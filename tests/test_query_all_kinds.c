/* The generic queries (query.h) on every ordered pair of the ten macrobodies: distance, signed
 * distance, verdict and repositioning, each checked against the test's own long-double geometry
 * (test_kinds_brute.h): support functions for a duality certificate of the distance, membership of
 * the witnesses, a brute-force distance over pairs of support points, a brute-force depth minimised
 * over directions; the swapped pair must give the mirrored answer; the sphere pairs must agree with
 * the specialised solvers; invalid shapes of each new kind must be named. */
#include "test_kinds_brute.h"

#define NK PROX_SHAPE_KIND_COUNT_

static void set_ctx(const prox_shape *a, const prox_shape *b, int t)
{
    snprintf(ctx, sizeof ctx, "%s-%s trial %d", prox_shape_kind_name(a->kind), prox_shape_kind_name(b->kind), t);
}
#define TRIALS 3
/* p2 - p1 against sd normal for an overlapping pair: the depth's accuracy (src/sat/convex.h: the
 * support method's witnesses lie on the support sets along its normal to 1e-9 S). */
#define WITNESS_TOL 1e-9

/* A random pair: A of kind ka at the origin, B of kind kb at a distance of 0.3 .. 3.5 (both about
 * unit size): disjoint and overlapping pairs both occur. */
static void random_pair(test_rng *g, int ka, int kb, prox_shape *a, prox_shape *b)
{
    *a = tk_random_shape(g, (prox_shape_kind)ka, prox_v3(0, 0, 0), 1.0);
    prox_vec3 c = prox_v3_scale(test_unit(g), test_range(g, 0.3, 3.5));
    *b = tk_random_shape(g, (prox_shape_kind)kb, c, 1.0);
}

static double scale_of(const prox_shape *a, const prox_shape *b)
{
    double s = prox_shape_pair_scale(a, b);
    check(s > 0.0);
    return s;
}

/* A disjoint distance result against the test's geometry: witnesses in the solids and |p2 - p1| the
 * distance, the gap of the support functions along the witness direction (a lower bound on the
 * distance, weak duality) equal to it, and no pair of sampled points nearer. */
static void check_disjoint(const tk_body *A, const tk_body *B, prox_distance_result d, double S)
{
    double tol = 1e-12 * S;
    check(tk_inside(A, L(d.p1), tol));
    check(tk_inside(B, L(d.p2), tol));
    lv3 v = lsub(L(d.p2), L(d.p1));
    ld len = lnorm(v);
    check_near((double)len, d.distance, tol);
    lv3 n = lsc(v, 1 / len);
    ld gap = -tk_support(B, lsc(n, -1)) - tk_support(A, n);
    check(gap >= d.distance - tol);
    check(tk_brute_distance(A, B, 150) >= d.distance - tol);
}

static void test_distance_every_pair(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(11);
    int n_dis = 0, n_ov = 0;
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < TRIALS; ++t) {
                prox_shape a, b;
                random_pair(&g, ka, kb, &a, &b);
                set_ctx(&a, &b, t);
                double S = scale_of(&a, &b), tol = 1e-12 * S;
                tk_body A = tk_make(&a), B = tk_make(&b);
                prox_distance_result d = prox_shape_distance(&a, &b), e = prox_shape_distance(&b, &a);
                assert_int_equal(d.status, PROX_OK);
                assert_int_equal(e.status, PROX_OK);
                check_near(e.distance, d.distance, tol); /* symmetry */
                if (!d.intersect) {
                    ++n_dis;
                    check_disjoint(&A, &B, d, S);
                    check(!e.intersect);
                    check_disjoint(&B, &A, e, S);
                } else {
                    ++n_ov;
                    check(tk_inside(&A, L(d.p1), tol) && tk_inside(&B, L(d.p1), tol));
                    if (!e.intersect) check(e.distance <= tol);
                }
            }
    check(n_dis > 50 && n_ov > 50);
}

/* Signed distance: disjoint equal to the distance; overlapping, minus the least phi over directions
 * (the brute force finds no direction with a smaller overlap) and realised by the normal. */
static void test_signed_every_pair(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(12);
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < TRIALS; ++t) {
                prox_shape a, b;
                random_pair(&g, ka, kb, &a, &b);
                set_ctx(&a, &b, t);
                double S = scale_of(&a, &b), tol = 1e-9 * S;
                tk_body A = tk_make(&a), B = tk_make(&b);
                prox_signed_result s = prox_shape_signed_distance(&a, &b), m = prox_shape_signed_distance(&b, &a);
                assert_int_equal(s.status, PROX_OK);
                assert_int_equal(m.status, PROX_OK);
                check_near(m.sd, s.sd, tol); /* symmetry */
                check_near(prox_v3_norm(s.normal), 1.0, 1e-12);
                if (fabs(s.sd) > tol) check(prox_v3_dot(s.normal, m.normal) < -1.0 + 1e-6);
                ld brute = -tk_minimise(tk_phi, &A, &B, 1500, NULL);
                check(s.sd >= brute - tol); /* no direction overlaps less */
                check_near((double)-tk_phi(&A, &B, L(s.normal)), s.sd, tol);
                /* the witnesses: p2 - p1 = sd normal (overlapping curved pairs: to the depth's accuracy) */
                check_near(prox_v3_dist(prox_v3_sub(s.p2, s.p1), prox_v3_scale(s.normal, s.sd)), 0.0,
                           s.sd > 0.0 ? 1e-12 * S : WITNESS_TOL * S);
                if (s.sd > 1e-9 * S) {
                    prox_distance_result d = prox_shape_distance(&a, &b);
                    check_near(s.sd, d.distance, 1e-12 * S);
                }
            }
}

/* The verdict agrees with the distance, both ways round. */
static void test_verdict_every_pair(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(13);
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < TRIALS; ++t) {
                prox_shape a, b;
                random_pair(&g, ka, kb, &a, &b);
                set_ctx(&a, &b, t);
                prox_test_result v = prox_shape_test(&a, &b), w = prox_shape_test(&b, &a);
                prox_distance_result d = prox_shape_distance(&a, &b);
                assert_int_equal(v.status, PROX_OK);
                assert_int_equal(w.status, PROX_OK);
                double S = scale_of(&a, &b);
                if (d.intersect || d.distance > 1e-9 * S) {
                    assert_int_equal(v.intersect, d.intersect);
                    assert_int_equal(w.intersect, d.intersect);
                }
            }
}

/* The sphere path answers the old pairs as the specialised solvers do. */
static void test_sphere_path_matches_specialised(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(14);
    for (int i = 0; i < 300; ++i) {
        int kind = i % 3; /* RCC, BOX, RPP */
        prox_shape a, b;
        random_pair(&g, kind == 0 ? PROX_SHAPE_RCC : (kind == 1 ? PROX_SHAPE_BOX : PROX_SHAPE_RPP), PROX_SHAPE_SPH, &a, &b);
        double tol = 1e-14 * scale_of(&a, &b);
        prox_distance_result d = prox_shape_distance(&a, &b), e;
        prox_signed_result s = prox_shape_signed_distance(&b, &a), f;
        if (kind == 0) {
            e = prox_rcc_sph_distance(&a.u.rcc, &b.u.sph);
            f = prox_rcc_sph_signed_distance(&a.u.rcc, &b.u.sph);
        } else {
            prox_box bx = kind == 1 ? a.u.box : prox_rpp_to_box(&a.u.rpp);
            e = prox_box_sph_distance(&bx, &b.u.sph);
            f = prox_box_sph_signed_distance(&bx, &b.u.sph);
        }
        assert_int_equal(d.intersect, e.intersect);
        check_near(d.distance, e.distance, tol);
        check_near(prox_v3_dist(d.p1, e.p1), 0.0, tol);
        check_near(prox_v3_dist(d.p2, e.p2), 0.0, tol);
        check_near(s.sd, f.sd, tol);
        check_near(prox_v3_dist(s.p1, f.p2), 0.0, tol); /* mirrored: the sphere is A here */
        check_near(prox_v3_dot(s.normal, f.normal), -1.0, 1e-12);
    }
}

/* Invalid shapes of each new kind are named by every query, in either position. */
static void test_invalid_new_kinds(void **state)
{
    (void)state;
    prox_shape bad[6];
    bad[0] = prox_shape_from_trc((prox_trc){prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1.0, 1.0});
    bad[1] = prox_shape_from_rec((prox_rec){prox_v3(0, 0, 0), prox_v3(0, 0, 1), prox_v3(1, 0, 0.5), prox_v3(0, 1, 0)});
    bad[2] = prox_shape_from_ell((prox_ell){prox_v3(0, 0, 0), prox_v3(0, 0, 1), -1.0});
    bad[3] = prox_shape_from_rhp((prox_rhp){prox_v3(0, 0, 0), prox_v3(0, 0, 1),
                                            {prox_v3(1, 0, 0.3), prox_v3(0.5, 0.8, 0), prox_v3(-0.5, 0.8, 0)}});
    bad[4] = prox_shape_from_wed((prox_wed){prox_v3(0, 0, 0), prox_v3(1, 0, 0), prox_v3(2, 0, 0), prox_v3(0, 0, 1)});
    prox_arb arb = {{{0}}, {0}};
    bad[5] = prox_shape_from_arb(arb);
    bad[5].u.arb.face[0] = 1293;
    test_rng g = test_rng_seed(15);
    for (int i = 0; i < 6; ++i) {
        prox_status want = prox_shape_validate(&bad[i]);
        assert_int_not_equal(want, PROX_OK);
        assert_string_not_equal(prox_status_str(want), prox_status_str(PROX_OK));
        for (int k = 0; k < NK; ++k) {
            prox_shape ok = tk_random_shape(&g, (prox_shape_kind)k, prox_v3(0.5, 0, 0), 1.0);
            const prox_shape *p[2][2] = {{&bad[i], &ok}, {&ok, &bad[i]}};
            for (int o = 0; o < 2; ++o) {
                const prox_shape *x = p[o][0], *y = p[o][1];
                assert_int_equal(prox_shape_distance(x, y).status, want);
                assert_int_equal(prox_shape_signed_distance(x, y).status, want);
                assert_int_equal(prox_shape_test(x, y).status, want);
                assert_int_equal(prox_shape_contains(x, y).status, want);
                assert_int_equal(prox_shape_relation(x, y, -1.0).status, want);
                assert_int_equal(prox_shape_reposition(x, y, 0.1).status, want);
            }
        }
    }
    prox_shape s = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), 1.0}), u = s;
    u.kind = PROX_SHAPE_KIND_COUNT_;
    assert_int_equal(prox_shape_distance(&s, &u).status, PROX_EINVAL_SHAPE_KIND);
    assert_int_equal(prox_shape_contains(&u, &s).status, PROX_EINVAL_SHAPE_KIND);
    assert_int_equal(prox_shape_signed_distance(NULL, &s).status, PROX_EINVAL_ARG);
}

/* The support-function signed distance of support.h answers every pair as the generic query does. */
static void test_support_signed_every_pair(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(17);
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < TRIALS; ++t) {
                prox_shape a, b;
                random_pair(&g, ka, kb, &a, &b);
                set_ctx(&a, &b, t);
                double S = scale_of(&a, &b);
                prox_signed_result s = prox_shape_signed_distance_support(&a, &b), r = prox_shape_signed_distance(&a, &b);
                check(s.status == PROX_OK);
                check_near(s.sd, r.sd, 1e-9 * S);
            }
}

/* Repositioning leaves every pair the margin apart (the moved B measured by the distance query). */
static void test_reposition_every_pair(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(16);
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb) {
            prox_shape a, b, b2;
            random_pair(&g, ka, kb, &a, &b);
            prox_reposition_result r = prox_shape_reposition(&a, &b, 0.25);
            assert_int_equal(r.status, PROX_OK);
            assert_int_equal(prox_shape_translated(&b, r.translation, &b2), PROX_OK);
            prox_distance_result d = prox_shape_distance(&a, &b2);
            double S = scale_of(&a, &b2);
            if (r.moved) check_near(d.distance, 0.25, 1e-9 * S);
            else check(d.distance >= 0.25 - 1e-12 * S);
        }
}

/* Two curved bodies (RCC, TRC, REC, ELL in any pair but RCC-RCC) that overlap: the distance query's
 * common point lies in both solids (the test's long-double membership, 1e-12 S), however it was
 * found: a centre inside the other body, the midpoint of the two closest points to the other's
 * centre (query.c's cheap look), or the engine when both miss. Pairs at random offsets (most
 * centres outside the other body), and pairs moved to overlap by only 1e-10 S along their normal,
 * where the cheap points rarely lie in both and the engine answers. */
static void test_curved_overlap_common_point(void **state)
{
    (void)state;
    static const prox_shape_kind kinds[] = {PROX_SHAPE_RCC, PROX_SHAPE_TRC, PROX_SHAPE_REC, PROX_SHAPE_ELL};
    test_rng g = test_rng_seed(13);
    int n_ov = 0, n_shallow = 0;
    for (int ia = 0; ia < 4; ++ia)
        for (int ib = 0; ib < 4; ++ib) {
            if (ia == 0 && ib == 0) continue; /* RCC-RCC: the cylinder pair's own solver */
            for (int t = 0; t < 60; ++t) {
                prox_shape a, b;
                random_pair(&g, kinds[ia], kinds[ib], &a, &b);
                set_ctx(&a, &b, t);
                prox_signed_result sd = prox_shape_signed_distance(&a, &b);
                assert_int_equal(sd.status, PROX_OK);
                if (t % 2 == 1) { /* B moved along the normal to overlap by 1e-10 S */
                    prox_shape b2;
                    double S0 = scale_of(&a, &b);
                    if (prox_shape_translated(&b, prox_v3_scale(sd.normal, -1e-10 * S0 - sd.sd), &b2) != PROX_OK) continue;
                    b = b2;
                    ++n_shallow;
                }
                double S = scale_of(&a, &b), tol = 1e-12 * S;
                prox_distance_result d = prox_shape_distance(&a, &b);
                assert_int_equal(d.status, PROX_OK);
                if (!d.intersect) continue;
                ++n_ov;
                tk_body A = tk_make(&a), B = tk_make(&b);
                check(d.certified);
                check(d.distance == 0.0);
                check(tk_inside(&A, L(d.p1), tol) && tk_inside(&B, L(d.p1), tol));
            }
        }
    check(n_ov > 300 && n_shallow > 200);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_distance_every_pair),   cmocka_unit_test(test_signed_every_pair),
        cmocka_unit_test(test_verdict_every_pair),    cmocka_unit_test(test_sphere_path_matches_specialised),
        cmocka_unit_test(test_invalid_new_kinds),     cmocka_unit_test(test_reposition_every_pair),
        cmocka_unit_test(test_support_signed_every_pair), cmocka_unit_test(test_curved_overlap_common_point),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
