/* The proved enclosure of a signed distance (prox_signed_result.sd_lower, sd_upper, certified):
 * - on the reference sets of tests/data (cylinder pairs with quad-precision signed distances), the
 *   enclosure holds the reference, and a certified answer is within the accuracy bar of it (1e-12 S
 *   disjoint, 1e-9 S overlapping); most answers are certified;
 * - on random pairs of every ordered pair of the ten macrobodies, the enclosure is consistent with the
 *   test's own long-double geometry (test_kinds_brute.h): the lower bound never exceeds a sampled
 *   distance (disjoint) nor the gap of the test's support functions along the normal, the upper bound
 *   is never below minus a sampled depth (overlapping), and sd lies inside it. */
#include "test_kinds_brute.h"
#include "test_refsets.h"

#include "../bench/stress_gen.h"

#define NK PROX_SHAPE_KIND_COUNT_

/* The reference lies in [sd_lower, sd_upper] up to the rounding of the input doubles; a certified
 * answer is within the bar. Returns the failures; *cert counts the certified answers. */
static int check_ref_pair(const prox_rcc *a, const prox_rcc *b, double ref, prox_signed_result r, int *cert)
{
    double S = sg_pair_scale(a, b), in = 8.0 * sg_input_ulp(a, b) + 1e-15 * S;
    if (r.status != PROX_OK) return 1;
    int bad = !(r.sd_lower <= ref + in) || !(ref <= r.sd_upper + in) || !(r.sd_lower <= r.sd) || !(r.sd <= r.sd_upper);
    if (r.certified) {
        ++*cert;
        bad |= !(fabs(r.sd - ref) <= (ref > 0.0 ? 1e-12 : 1e-9) * S + in);
        bad |= !(r.sd_upper - r.sd_lower <= (r.sd > 0.0 ? 1e-12 : 1e-9) * S);
    }
    return bad;
}

static void test_reference_sets_enclosed(void **state)
{
    (void)state;
    static const char *const sets[3] = {"paper_cases", "agarwal_public", "stress_public"};
    for (int k = 0; k < 3; ++k) {
        double *P, *R;
        size_t n = load_set(sets[k], &P, &R);
        int bad = 0, cert = 0, cert_shape = 0, overl = 0;
        for (size_t i = 0; i < n; ++i) {
            prox_rcc a = rcc_of(P + 14 * i), b = rcc_of(P + 14 * i + 7);
            prox_shape sa = prox_shape_from_rcc(a), sb = prox_shape_from_rcc(b);
            double ref = R[7 * i];
            overl += ref <= 0.0;
            int e = check_ref_pair(&a, &b, ref, prox_rcc_signed_distance(&a, &b), &cert);
            e |= check_ref_pair(&a, &b, ref, prox_shape_signed_distance(&sa, &sb), &cert_shape);
            if (e && bad++ < 5) {
                prox_signed_result r = prox_rcc_signed_distance(&a, &b);
                print_error("%s pair %zu: ref %.17g sd %.17g in [%.17g, %.17g] certified %d\n", sets[k], i, ref, r.sd,
                            r.sd_lower, r.sd_upper, r.certified);
            }
        }
        printf("# %-14s %4zu pairs (%d overlapping): certified %d (generic query %d), failures %d\n", sets[k], n,
               overl, cert, cert_shape, bad);
        assert_int_equal(bad, 0);
        assert_int_equal(cert, cert_shape);
        if (k == 1) assert_true(cert >= (int)(0.95 * (double)n)); /* protocol A pairs: nearly all proved */
        free(P);
        free(R);
    }
}

static void test_every_kind_consistent(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(2027);
    int cert = 0, total = 0;
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < 3; ++t) {
                prox_shape a = tk_random_shape(&g, (prox_shape_kind)ka, prox_v3(0, 0, 0), 1.0);
                prox_shape b = tk_random_shape(&g, (prox_shape_kind)kb,
                                               prox_v3_scale(test_unit(&g), test_range(&g, 0.3, 3.5)), 1.0);
                snprintf(ctx, sizeof ctx, "%s-%s trial %d", prox_shape_kind_name(a.kind), prox_shape_kind_name(b.kind), t);
                double S = prox_shape_pair_scale(&a, &b), tol = 1e-12 * S;
                tk_body A = tk_make(&a), B = tk_make(&b);
                prox_signed_result r = prox_shape_signed_distance(&a, &b);
                assert_int_equal(r.status, PROX_OK);
                check(r.sd_lower <= r.sd && r.sd <= r.sd_upper);
                check(r.sd_lower <= (double)-tk_phi(&A, &B, L(r.normal)) + tol); /* the gap along the normal */
                if (r.sd > 0.0) check(r.sd_lower <= (double)tk_brute_distance(&A, &B, 60) + tol);
                else check(r.sd_upper >= (double)-tk_minimise(tk_phi, &A, &B, 300, NULL) - tol);
                if (r.certified) check(r.sd_upper - r.sd_lower <= (r.sd > 0.0 ? 1e-12 : 1e-9) * S);
                cert += r.certified, ++total;
            }
    printf("# every kind pair: %d of %d answers certified\n", cert, total);
    assert_true(cert >= total * 9 / 10);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reference_sets_enclosed),
        cmocka_unit_test(test_every_kind_consistent),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
