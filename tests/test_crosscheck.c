/* Tests of prox_rcc_crosscheck: the closed-form distance and the separating-axis / support-function
 * methods must agree on the reference sets and on seeded random pairs of Agarwal's protocol
 * (A fixed, B random: radius (0,20], height (0,50], base in the ball of radius 25), outside the
 * band |sd| <= 1e-12 x scale around touching. Disagreements are printed as 14-number reproducers. */
#include "test_util.h"

#include "prox/sat.h"

static int report(const prox_rcc *a, const prox_rcc *b, const prox_crosscheck_result *r, const char *what, int i)
{
    if (r->agree) return 0;
    printf("DISAGREE %s %d: verdicts dist %d sat %d, distance %.17g sd %.17g diff %.3g tol %.3g margin %.3g\n"
           "  %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
           what, i, r->intersect_distance, r->intersect_sat, r->distance, r->sd, r->distance_diff, r->tol, r->margin,
           a->base.x, a->base.y, a->base.z, a->axis.x, a->axis.y, a->axis.z, a->radius, b->base.x, b->base.y,
           b->base.z, b->axis.x, b->axis.y, b->axis.z, b->radius);
    return 1;
}

static int run_set(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.pairs", PROX_VALIDATION_DIR, name);
    FILE *fp = fopen(path, "r");
    assert_non_null(fp);
    prox_rcc a, b;
    int n = 0, bad = 0;
    while (fscanf(fp, "%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &a.base.x, &a.base.y, &a.base.z,
                  &a.axis.x, &a.axis.y, &a.axis.z, &a.radius, &b.base.x, &b.base.y, &b.base.z, &b.axis.x, &b.axis.y,
                  &b.axis.z, &b.radius) == 14) {
        prox_crosscheck_result r = prox_rcc_crosscheck(&a, &b);
        assert_int_equal(r.status, PROX_OK);
        bad += report(&a, &b, &r, name, n);
        n++;
    }
    fclose(fp);
    printf("%s: %d pairs, %d disagreements\n", name, n, bad);
    return bad;
}

static void test_crosscheck_paper_cases(void **state) { (void)state; assert_int_equal(run_set("paper_cases"), 0); }
static void test_crosscheck_agarwal_public(void **state) { (void)state; assert_int_equal(run_set("agarwal_public"), 0); }
static void test_crosscheck_stress_public(void **state) { (void)state; assert_int_equal(run_set("stress_public"), 0); }

static void test_crosscheck_random_protocol_a(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(4201);
    prox_rcc a = {{0, 0, 0}, {0, 0, 5}, 2};
    int bad = 0;
    for (int i = 0; i < 3000; ++i) {
        prox_rcc b;
        b.radius = 20.0 * (1.0 - test_uniform(&g));
        double h = 50.0 * (1.0 - test_uniform(&g));
        do b.base = prox_v3(test_range(&g, -25, 25), test_range(&g, -25, 25), test_range(&g, -25, 25));
        while (prox_v3_norm(b.base) > 25.0);
        b.axis = prox_v3_scale(test_unit(&g), h);
        prox_crosscheck_result r = prox_rcc_crosscheck(&a, &b);
        assert_int_equal(r.status, PROX_OK);
        bad += report(&a, &b, &r, "protocol-A", i);
    }
    assert_int_equal(bad, 0);
}

static void test_crosscheck_invalid(void **state)
{
    (void)state;
    prox_rcc a = {{0, 0, 0}, {0, 0, 5}, 2}, bad = {{0, 0, 0}, {0, 0, 5}, 0};
    assert_int_equal(prox_rcc_crosscheck(&a, &bad).status, PROX_EINVAL_RADIUS);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crosscheck_paper_cases),      cmocka_unit_test(test_crosscheck_agarwal_public),
        cmocka_unit_test(test_crosscheck_stress_public),    cmocka_unit_test(test_crosscheck_random_protocol_a),
        cmocka_unit_test(test_crosscheck_invalid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
