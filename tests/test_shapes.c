/* Validators: every kind of bad input gets its own named status, and status strings exist. */
#include "test_util.h"
#include <string.h>

static void test_rcc_validate(void **state)
{
    (void)state;
    prox_rcc c = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1};
    assert_int_equal(prox_rcc_validate(&c), PROX_OK);
    c.radius = 0;
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_RADIUS);
    c.radius = -1;
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_RADIUS);
    c.radius = NAN;
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_NONFINITE);
    c.radius = 1;
    c.axis = prox_v3(0, 0, 0);
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_AXIS);
    c.axis = prox_v3(0, INFINITY, 0);
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_NONFINITE);
    c.axis = prox_v3(1.5e308, 1.5e308, 0); /* finite parts, length overflows */
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_RANGE);
    c.axis = prox_v3(0, 0, 1e-120); /* too short for the supported range */
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_RANGE);
    c.axis = prox_v3(0, 0, 1);
    c.base = prox_v3(2e100, 0, 0);
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_RANGE);
    c.base = prox_v3(0, 0, 0);
    c.radius = 1e-101;
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_RANGE);
    c.radius = 1;
    c.axis = prox_v3(0, 0, 1);
    c.base.x = NAN;
    assert_int_equal(prox_rcc_validate(&c), PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_rcc_validate(NULL), PROX_EINVAL_ARG);
}

static void test_box_validate(void **state)
{
    (void)state;
    prox_box b = {prox_v3(0, 0, 0), {prox_v3(1, 0, 0), prox_v3(0, 2, 0), prox_v3(0, 0, 3)}};
    assert_int_equal(prox_box_validate(&b), PROX_OK);
    b.edge[1] = prox_v3(0.1, 2, 0);
    assert_int_equal(prox_box_validate(&b), PROX_EINVAL_BOX_ORTHO);
    b.edge[1] = prox_v3(0, 0, 0);
    assert_int_equal(prox_box_validate(&b), PROX_EINVAL_BOX_EDGE);
    b.edge[1] = prox_v3(0, NAN, 0);
    assert_int_equal(prox_box_validate(&b), PROX_EINVAL_NONFINITE);
    /* Orthogonality is relative: a tiny box rotated by a tiny rounding is still a box. */
    prox_box t = {prox_v3(0, 0, 0), {prox_v3(1e-9, 1e-25, 0), prox_v3(-1e-25, 1e-9, 0), prox_v3(0, 0, 1e-9)}};
    assert_int_equal(prox_box_validate(&t), PROX_OK);
}

static void test_rpp_sph_validate(void **state)
{
    (void)state;
    prox_rpp r = {0, 1, 0, 1, 0, 1};
    assert_int_equal(prox_rpp_validate(&r), PROX_OK);
    r.ymax = -1;
    assert_int_equal(prox_rpp_validate(&r), PROX_EINVAL_RPP_BOUNDS);
    r.ymax = NAN;
    assert_int_equal(prox_rpp_validate(&r), PROX_EINVAL_NONFINITE);
    prox_sph s = {prox_v3(1, 2, 3), 1};
    assert_int_equal(prox_sph_validate(&s), PROX_OK);
    s.radius = 0;
    assert_int_equal(prox_sph_validate(&s), PROX_EINVAL_RADIUS);
    s.radius = 1e101;
    assert_int_equal(prox_sph_validate(&s), PROX_EINVAL_RANGE);
    s.radius = 0;
    prox_shape g = prox_shape_from_sph(s);
    assert_int_equal(prox_shape_validate(&g), PROX_EINVAL_RADIUS);
    g.kind = (prox_shape_kind)42;
    assert_int_equal(prox_shape_validate(&g), PROX_EINVAL_SHAPE_KIND);
}

static void test_status_strings(void **state)
{
    (void)state;
    for (int s = 0; s < PROX_STATUS_COUNT_; ++s) {
        const char *m = prox_status_str((prox_status)s);
        assert_non_null(m);
        assert_true(strcmp(m, "unknown status code") != 0);
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rcc_validate),
        cmocka_unit_test(test_box_validate),
        cmocka_unit_test(test_rpp_sph_validate),
        cmocka_unit_test(test_status_strings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
