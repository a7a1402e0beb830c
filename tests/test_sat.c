/* Tests of prox_rcc_sat (Eberly's separating axes with a certified minimisation of G over the
 * tangent plane): the verdict on the reference sets of tests/data (must equal sd <= 0
 * except within 1e-12 x scale of touching), validity of every reported separating direction
 * (checked with prox_rcc_support, independently of the SAT code), a dense-direction brute force,
 * seeded properties (symmetry, rigid motion, scale) and hand-made cases. */
#include "test_util.h"

#include <stdlib.h>

#include "prox/distance.h"
#include "prox/sat.h"
#include "../bench/stress_gen.h"

/* Gap between the projections along unit d, computed from the library's support function. */
static double support_gap(const prox_rcc *a, const prox_rcc *b, prox_vec3 d)
{
    return -prox_rcc_support(b, prox_v3_neg(d)) - prox_rcc_support(a, d);
}

/* Checks a reported verdict against a reference signed distance (NAN: no reference). */
static void check_verdict(const prox_rcc *a, const prox_rcc *b, double ref, int *ambiguous)
{
    double S = prox_rcc_pair_scale(a, b);
    prox_test_result r = prox_rcc_sat(a, b);
    assert_int_equal(r.status, PROX_OK);
    if (!r.intersect) {
        /* the direction must separate, with the reported gap, pointing from A towards B */
        assert_near(prox_v3_norm(r.direction), 1.0, 1e-12);
        double g = support_gap(a, b, r.direction);
        /* support_gap works in absolute coordinates: allow their rounding (far-away pairs) */
        double M = fmax(prox_v3_maxabs(a->base), prox_v3_maxabs(b->base)), tol = 1e-12 * S + 1e-15 * M;
        assert_true(g > -tol);
        assert_near(r.value, g, tol);
        assert_true(r.decided_by != PROX_SAT_NONE && r.decided_by != PROX_SAT_CERTIFIED);
    } else {
        assert_true(r.value <= 0.0);
    }
    if (isnan(ref)) return;
    int want = ref <= 0.0;
    if (r.intersect != want) {
        if (fabs(ref) <= 1e-12 * S) { (*ambiguous)++; return; }
        print_error("verdict %d, reference sd %.17g (scale %.3g)\n", r.intersect, ref, S);
        fail();
    }
}

static void check_set(const char *name, int expect_n)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.pairs", PROX_VALIDATION_DIR, name);
    FILE *fp = fopen(path, "r");
    snprintf(path, sizeof path, "%s/%s.ref", PROX_VALIDATION_DIR, name);
    FILE *fr = fopen(path, "r");
    assert_non_null(fp);
    assert_non_null(fr);
    prox_rcc a, b;
    int n = 0, amb = 0, by[PROX_SAT_CERTIFIED + 1] = {0};
    while (fscanf(fp, "%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &a.base.x, &a.base.y, &a.base.z,
                  &a.axis.x, &a.axis.y, &a.axis.z, &a.radius, &b.base.x, &b.base.y, &b.base.z, &b.axis.x, &b.axis.y,
                  &b.axis.z, &b.radius) == 14) {
        double ref[7];
        for (int i = 0; i < 7; ++i) assert_int_equal(fscanf(fr, "%lf", &ref[i]), 1);
        check_verdict(&a, &b, ref[0], &amb);
        by[prox_rcc_sat(&a, &b).decided_by]++;
        n++;
    }
    fclose(fp);
    fclose(fr);
    assert_int_equal(n, expect_n);
    printf("%s: %d pairs, %d within 1e-12 x scale of touching; decided by W0 %d W1 %d W0xW1 %d parallel %d "
           "perpW0 %d perpW1 %d other %d certified %d\n",
           name, n, amb, by[1], by[2], by[3], by[4], by[5], by[6], by[7], by[8]);
    assert_true(amb <= n / 50);
}

static void test_sat_paper_cases(void **state) { (void)state; check_set("paper_cases", 5); }
static void test_sat_agarwal_public(void **state) { (void)state; check_set("agarwal_public", 2000); }
static void test_sat_stress_public(void **state) { (void)state; check_set("stress_public", 1000); }

static prox_rcc random_rcc(test_rng *g, double spread)
{
    prox_rcc c;
    c.base = prox_v3(test_range(g, -spread, spread), test_range(g, -spread, spread), test_range(g, -spread, spread));
    c.axis = prox_v3_scale(test_unit(g), test_range(g, 0.1, 5.0));
    c.radius = test_range(g, 0.1, 2.0);
    return c;
}

/* Brute force: the best gap over a dense set of directions (a lower bound of the distance).
 * Whenever it is clearly positive the SAT must report separation. */
static double dense_gap(const prox_rcc *a, const prox_rcc *b)
{
    double best = -INFINITY;
    for (int i = 0; i < 120; ++i)
        for (int j = 0; j < 240; ++j) {
            double th = PROX_PI * (i + 0.5) / 120, ph = 2 * PROX_PI * j / 240;
            prox_vec3 d = prox_v3(sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
            double g = support_gap(a, b, d);
            if (g > best) best = g;
        }
    return best;
}

static void test_sat_dense_directions(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(4101);
    int sep = 0, inter = 0, amb = 0;
    for (int it = 0; it < 150; ++it) {
        prox_rcc a = random_rcc(&g, 3.0), b = random_rcc(&g, 3.0);
        double S = prox_rcc_pair_scale(&a, &b);
        double dg = dense_gap(&a, &b);
        prox_test_result r = prox_rcc_sat(&a, &b);
        /* the independent signed distance decides the expected verdict */
        double sd = prox_rcc_signed_distance(&a, &b).sd;
        check_verdict(&a, &b, sd, &amb);
        if (dg > 1e-9 * S) assert_int_equal(r.intersect, 0);
        if (r.intersect) inter++; else sep++;
    }
    assert_true(sep > 20 && inter > 20); /* both verdicts exercised */
}

static void test_sat_properties(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(4102);
    for (int it = 0; it < 2000; ++it) {
        prox_rcc a = random_rcc(&g, 3.0), b = random_rcc(&g, 3.0);
        double S = prox_rcc_pair_scale(&a, &b);
        double sd = prox_rcc_signed_distance(&a, &b).sd;
        if (fabs(sd) <= 1e-9 * S) continue; /* verdict legitimately unstable at touching */
        prox_test_result r = prox_rcc_sat(&a, &b);
        assert_int_equal(r.intersect, sd <= 0.0);
        assert_int_equal(prox_rcc_sat(&b, &a).intersect, r.intersect);
        test_rot R = test_random_rot(&g);
        prox_vec3 t = prox_v3(test_range(&g, -50, 50), test_range(&g, -50, 50), test_range(&g, -50, 50));
        prox_rcc a2 = {prox_v3_add(test_rot_apply(&R, a.base), t), test_rot_apply(&R, a.axis), a.radius};
        prox_rcc b2 = {prox_v3_add(test_rot_apply(&R, b.base), t), test_rot_apply(&R, b.axis), b.radius};
        assert_int_equal(prox_rcc_sat(&a2, &b2).intersect, r.intersect);
        prox_rcc a3 = {prox_v3_scale(a.base, 1024), prox_v3_scale(a.axis, 1024), a.radius * 1024};
        prox_rcc b3 = {prox_v3_scale(b.base, 1024), prox_v3_scale(b.axis, 1024), b.radius * 1024};
        assert_int_equal(prox_rcc_sat(&a3, &b3).intersect, r.intersect);
    }
}

static void test_sat_hand_made(void **state)
{
    (void)state;
    int amb = 0;
    prox_rcc a = {{0, 0, 0}, {0, 0, 2}, 1};
    /* parallel axes: radially apart, radially overlapping, apart in height */
    prox_rcc p1 = {{2.6, 0, 0.5}, {0, 0, 1}, 1.5}, p2 = {{2.4, 0, 0.5}, {0, 0, 1}, 1.5}, p3 = {{0.5, 0, 2.1}, {0, 0, 1}, 1};
    prox_test_result r = prox_rcc_sat(&a, &p1);
    assert_int_equal(r.intersect, 0);
    assert_int_equal(r.decided_by, PROX_SAT_PARALLEL);
    assert_near(r.value, 0.1, 1e-15);
    assert_near(r.direction.x, 1.0, 1e-15);
    assert_int_equal(prox_rcc_sat(&a, &p2).intersect, 1);
    r = prox_rcc_sat(&a, &p3);
    assert_int_equal(r.intersect, 0);
    assert_int_equal(r.decided_by, PROX_SAT_W0);
    /* antiparallel coaxial, overlapping and touching (touching counts as intersecting) */
    prox_rcc c1 = {{0, 0, 3}, {0, 0, -1.5}, 0.5}, c2 = {{0, 0, 3}, {0, 0, -1}, 0.5};
    assert_int_equal(prox_rcc_sat(&a, &c1).intersect, 1);
    assert_int_equal(prox_rcc_sat(&a, &c2).intersect, 1);
    /* perpendicular: crossing above the top (W0 separates), lateral crossing (W0 x W1) */
    prox_rcc q1 = {{-3, 0, 2.5}, {6, 0, 0}, 0.4}, q2 = {{-3, 1.5, 1}, {6, 0, 0}, 0.4}, q3 = {{-3, 1.4, 1}, {6, 0, 0}, 0.4};
    r = prox_rcc_sat(&a, &q1);
    assert_int_equal(r.intersect, 0);
    assert_near(r.value, 0.1, 1e-15);
    r = prox_rcc_sat(&a, &q2);
    assert_int_equal(r.intersect, 0);
    assert_int_equal(r.decided_by, PROX_SAT_W0xW1);
    assert_near(r.value, 0.1, 1e-15);
    assert_int_equal(prox_rcc_sat(&a, &q3).intersect, 1);
    /* rim against rim at 45 degrees: only "other" directions separate */
    prox_vec3 w = prox_v3_normalize(prox_v3(1, 1, 1));
    prox_rcc o = {prox_v3(1.9, 1.9, 2.9), prox_v3_scale(w, 2.0), 0.5};
    check_verdict(&a, &o, prox_rcc_signed_distance(&a, &o).sd, &amb);
    /* same centre */
    prox_rcc s = {{0, -1, 1}, {0, 2, 0}, 0.1};
    assert_int_equal(prox_rcc_sat(&a, &s).intersect, 1);
    /* invalid input */
    prox_rcc bad = {{0, 0, 0}, {0, 0, 1}, -1};
    assert_int_equal(prox_rcc_sat(&a, &bad).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_rcc_sat(NULL, &a).status, PROX_EINVAL_ARG);
    assert_int_equal(amb, 0);
}

/* Regression (stress family parallel-side): a sliver portal (two vertices 1e-6 apart on the lateral
 * segment) gave N.p0 / N.n above the true exit point t*, a false certified overlap (value -1.5e-11)
 * for a pair 4.48e-12 apart (scale ~4.2). The bound is now min over the portal of N.p_i / N.n. */
static void test_sat_sliver_portal_regression(void **state)
{
    (void)state;
    prox_rcc a = {{-1.8028444187267914, -0.62093184734003781, 0.75836459171793669},
                  {-1.1463873783739271, 0.68674488099258157, -0.20092110598857102}, 0.37366444355744322};
    prox_rcc b = {{-1.1362728725644018, 3.4579237431363969, 1.8074935273294432},
                  {3.0637226277367438, -1.8353271076341788, 0.53696206920929046}, 3.6705734616502945};
    prox_distance_result d = prox_rcc_distance(&a, &b);
    assert_int_equal(d.intersect, 0);
    assert_near(d.distance, 4.48e-12, 5e-14);
    prox_test_result r = prox_rcc_sat(&a, &b);
    assert_int_equal(r.intersect, 0);
    assert_true(r.value > 0.0 && r.value <= d.distance + 1e-15);
    assert_true(support_gap(&a, &b, r.direction) > 0.0);
    r = prox_rcc_sat(&b, &a);
    assert_int_equal(r.intersect, 0);
}

/* Soundness of the certificate on the near-touching stress families: a pair whose constructed
 * distance exceeds the input's rounding must never be certified overlapping, and a reported
 * separating direction must separate (support functions of the library, not the SAT's). */
static void test_sat_certificate_sound_stress(void **state)
{
    (void)state;
    int certified = 0, false_cert = 0, missed = 0, n = 0;
    for (int fam = 0; fam < SG_NFAMILIES; ++fam) {
        sg_rng r = sg_seed(7700 + (uint64_t)fam);
        for (int k = 0; k < 600; ++k) {
            sg_pair p = sg_make(&r, fam);
            double S = sg_pair_scale(&p.a, &p.b), tol = 1e-12 * S + 8.0 * sg_input_ulp(&p.a, &p.b);
            prox_test_result v = prox_rcc_sat(&p.a, &p.b);
            assert_int_equal(v.status, PROX_OK);
            n++;
            if (v.decided_by == PROX_SAT_CERTIFIED && v.value < 0.0) {
                certified++;
                if (p.d_ref > 8.0 * sg_input_ulp(&p.a, &p.b)) {
                    print_error("family %s pair %d: certified overlap %.3g, exact distance %.3g\n",
                                sg_family_names[fam], k, v.value, p.d_ref);
                    false_cert++;
                }
            }
            if (v.intersect && p.d_ref > tol) missed++;
            if (!v.intersect) assert_true(v.value <= p.d_ref + tol);
        }
    }
    printf("stress certificates: %d pairs, %d certified, %d false, %d separated pairs missed\n", n, certified,
           false_cert, missed);
    assert_int_equal(false_cert, 0);
    assert_int_equal(missed, 0);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sat_paper_cases),      cmocka_unit_test(test_sat_agarwal_public),
        cmocka_unit_test(test_sat_stress_public),    cmocka_unit_test(test_sat_dense_directions),
        cmocka_unit_test(test_sat_properties),       cmocka_unit_test(test_sat_hand_made),
        cmocka_unit_test(test_sat_sliver_portal_regression),
        cmocka_unit_test(test_sat_certificate_sound_stress),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
