/* Prepared solids (prox/solid.h): the verdict, distance and signed distance of two solids are the
 * generic shape queries' answers on the same shapes, field for field and bit for bit, on every
 * ordered pair of the ten macrobodies, on boxes too thin for their polytope (the support-function
 * route) and on each route's fallbacks; invalid and unknown shapes are refused with their
 * validator's status and no solid. */
#include "test_util.h"

#include "prox/solid.h"

#include <string.h>

#define NK PROX_SHAPE_KIND_COUNT_

static char ctx[160];

static int same_double(double x, double y) { return memcmp(&x, &y, sizeof x) == 0; }
static int same_vec(prox_vec3 x, prox_vec3 y) { return same_double(x.x, y.x) && same_double(x.y, y.y) && same_double(x.z, y.z); }

static void check_same_distance(prox_distance_result s, prox_distance_result d)
{
    int ok = s.status == d.status && s.intersect == d.intersect && same_double(s.distance, d.distance) &&
             same_vec(s.p1, d.p1) && same_vec(s.p2, d.p2) && same_double(s.certificate_gap, d.certificate_gap) &&
             s.certified == d.certified && s.a_in_b == d.a_in_b && s.b_in_a == d.b_in_a && s.method == d.method &&
             s.pair == d.pair && s.feature1 == d.feature1 && s.feature2 == d.feature2;
    if (!ok) fail_msg("%s: distance %.17g (status %d) from the solids, %.17g (status %d) from the shapes", ctx,
                      s.distance, s.status, d.distance, d.status);
}

static void check_same_signed(prox_signed_result s, prox_signed_result d)
{
    int ok = s.status == d.status && same_double(s.sd, d.sd) && same_vec(s.normal, d.normal) && same_vec(s.p1, d.p1) &&
             same_vec(s.p2, d.p2) && same_double(s.sd_lower, d.sd_lower) && same_double(s.sd_upper, d.sd_upper) &&
             s.certified == d.certified;
    if (!ok) fail_msg("%s: signed distance %.17g from the solids, %.17g from the shapes", ctx, s.sd, d.sd);
}

static void check_same_test(prox_test_result s, prox_test_result d)
{
    int ok = s.status == d.status && s.intersect == d.intersect && same_vec(s.direction, d.direction) &&
             same_double(s.value, d.value) && s.decided_by == d.decided_by;
    if (!ok) fail_msg("%s: verdict %d from the solids, %d from the shapes", ctx, s.intersect, d.intersect);
}

/* The three queries on a pair, from solids and from shapes. */
static void check_pair(const prox_shape *a, const prox_shape *b)
{
    prox_status sa, sb;
    prox_solid *A = prox_solid_new(a, &sa), *B = prox_solid_new(b, &sb);
    if (!A || !B) fail_msg("%s: solid refused (status %d, %d)", ctx, sa, sb);
    check_same_distance(prox_solid_distance(A, B), prox_shape_distance(a, b));
    check_same_signed(prox_solid_signed_distance(A, B), prox_shape_signed_distance(a, b));
    check_same_test(prox_solid_test(A, B), prox_shape_test(a, b));
    prox_solid_free(A);
    prox_solid_free(B);
}

/* Every ordered pair of kinds, centres 0 .. 1.5 times the larger size apart (overlapping, touching
 * and disjoint pairs all occur), each solid reused against several partners as a program would. */
static void test_every_pair_matches_shapes(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(20261129);
    int trials = 40;
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < trials; ++t) {
                prox_shape a = test_any_shape(&g, ka, prox_v3(0, 0, 0));
                double s = fmax(prox_shape_size(&a), 1.0);
                prox_shape b = test_any_shape(&g, kb, prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 1.5) * s));
                snprintf(ctx, sizeof ctx, "%s-%s trial %d", prox_shape_kind_name(a.kind), prox_shape_kind_name(b.kind), t);
                if (prox_shape_validate(&a) != PROX_OK || prox_shape_validate(&b) != PROX_OK) continue;
                check_pair(&a, &b);
            }
}

/* A box with two edges 1e-13 of its third: too thin for its polytope (query.c, poly_fits), it takes
 * the support-function route against polytopes and curved bodies alike; and one such edge, a plate,
 * which keeps its polytope. */
static prox_shape thin_box(test_rng *g, prox_vec3 c, int thin_edges)
{
    test_rot R = test_random_rot(g);
    double len[3] = {2.0, thin_edges >= 2 ? 2e-13 : 1.5, thin_edges >= 1 ? 2e-13 : 1.0};
    prox_box b;
    b.corner = c;
    for (int k = 0; k < 3; ++k) {
        b.edge[k] = prox_v3_scale(test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2)), len[k]);
        b.corner = prox_v3_mad(b.corner, -0.5, b.edge[k]);
    }
    return prox_shape_from_box(b);
}

static void test_thin_boxes_match_shapes(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(7);
    for (int thin = 1; thin <= 2; ++thin)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < 20; ++t) {
                prox_shape a = thin_box(&g, prox_v3(0, 0, 0), thin);
                prox_shape b = test_any_shape(&g, kb, prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 3.0)));
                snprintf(ctx, sizeof ctx, "box with %d thin edges-%s trial %d", thin, prox_shape_kind_name(b.kind), t);
                if (prox_shape_validate(&a) != PROX_OK || prox_shape_validate(&b) != PROX_OK) continue;
                check_pair(&a, &b);
                check_pair(&b, &a);
            }
}

/* Solids touching and nearly touching (a 1e-10 gap or overlap), where the routes' fast paths hand
 * over to the certified engine most often. */
static void test_near_contact_matches_shapes(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(11);
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < 6; ++t) {
                prox_shape a = test_any_shape(&g, ka, prox_v3(0, 0, 0));
                prox_shape b = test_any_shape(&g, kb, prox_v3_scale(test_unit(&g), 2.0 * prox_shape_size(&a)));
                if (prox_shape_validate(&a) != PROX_OK || prox_shape_validate(&b) != PROX_OK) continue;
                prox_signed_result s = prox_shape_signed_distance(&a, &b);
                assert_int_equal(s.status, PROX_OK);
                /* move B along the normal so that the pair stands (t % 3 - 1) 1e-10 apart */
                prox_vec3 move = prox_v3_scale(s.normal, (double)(t % 3 - 1) * 1e-10 - s.sd);
                prox_shape b2;
                if (prox_shape_translated(&b, move, &b2) != PROX_OK) continue;
                snprintf(ctx, sizeof ctx, "%s-%s near contact %d", prox_shape_kind_name(a.kind), prox_shape_kind_name(b.kind), t);
                check_pair(&a, &b2);
            }
}

/* Invalid shapes are refused with the validator's status (and never made); NULL is an argument
 * error; a query on a NULL solid reports it. */
static void test_invalid_shapes_refused(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(3);
    for (int k = 0; k < NK; ++k) {
        prox_shape s = test_any_shape(&g, k, prox_v3(0, 0, 0));
        prox_status st = PROX_OK;
        prox_solid *o = prox_solid_new(&s, &st);
        assert_non_null(o);
        assert_int_equal(st, PROX_OK);
        assert_memory_equal(prox_solid_shape(o), &s, sizeof s);
        prox_solid_free(o);
        /* a NaN in the first double of the shape's parameters */
        prox_shape bad = s;
        double *first = (double *)&bad.u;
        *first = NAN;
        st = PROX_OK;
        o = prox_solid_new(&bad, &st);
        assert_null(o);
        assert_int_equal(st, prox_shape_validate(&bad));
        assert_int_not_equal(st, PROX_OK);
    }
    prox_shape s = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), 1.0});
    prox_shape unknown = s;
    unknown.kind = (prox_shape_kind)NK;
    prox_status st = PROX_OK;
    assert_null(prox_solid_new(&unknown, &st));
    assert_int_equal(st, PROX_EINVAL_SHAPE_KIND);
    assert_null(prox_solid_new(NULL, &st));
    assert_int_equal(st, PROX_EINVAL_ARG);
    assert_null(prox_solid_new(NULL, NULL));
    prox_shape zero = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), 0.0});
    assert_null(prox_solid_new(&zero, &st));
    assert_int_equal(st, PROX_EINVAL_RADIUS);
    prox_solid *o = prox_solid_new(&s, NULL);
    assert_non_null(o);
    assert_int_equal(prox_solid_distance(o, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_solid_signed_distance(NULL, o).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_solid_test(NULL, NULL).status, PROX_EINVAL_ARG);
    assert_null(prox_solid_shape(NULL));
    prox_solid_free(o);
    prox_solid_free(NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_pair_matches_shapes),
        cmocka_unit_test(test_thin_boxes_match_shapes),
        cmocka_unit_test(test_near_contact_matches_shapes),
        cmocka_unit_test(test_invalid_shapes_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
