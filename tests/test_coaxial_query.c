/* Coaxial solids of revolution through the generic queries: an RCC, a TRC, an ELL and a sphere on one
 * axis have a whole circle of optimal directions, so the query layer answers them from the meridian
 * sections (docs/algorithms/curved.md, "Coaxial pairs"). The expected values follow from the
 * configurations by hand; the support method (an independent search) must agree with them. */
#include "test_util.h"

#include "prox/prox.h"

static prox_shape rcc(void) { return prox_shape_from_rcc((prox_rcc){prox_v3(0, 0, 0), prox_v3(0, 0, 4), 1.0}); }

/* ELL of semi-axis 2 along z and equatorial radius 0.5, centred at height zc. */
static prox_shape ell(double zc) { return prox_shape_from_ell((prox_ell){prox_v3(0, 0, zc), prox_v3(0, 0, 2), 0.5}); }

static void check_signed(const prox_shape *a, const prox_shape *b, double want)
{
    prox_signed_result r = prox_shape_signed_distance(a, b), t = prox_shape_signed_distance(b, a);
    assert_int_equal(r.status, PROX_OK);
    assert_int_equal(t.status, PROX_OK);
    assert_near(r.sd, want, 1e-13);
    assert_near(t.sd, want, 1e-13);
    /* the witnesses agree with the answer */
    prox_vec3 d = prox_v3_sub(r.p2, r.p1);
    assert_near(prox_v3_norm(prox_v3_sub(d, prox_v3_scale(r.normal, r.sd))), 0, 1e-12);
    prox_signed_result s = prox_shape_signed_distance_support(a, b);
    assert_int_equal(s.status, PROX_OK);
    assert_near(s.sd, want, 1e-9);
}

static void test_apart_on_axis(void **state)
{
    (void)state;
    prox_shape a = rcc(), b = ell(10.0); /* ELL spans z in [8, 12], the RCC [0, 4] */
    check_signed(&a, &b, 4.0);
    prox_distance_result d = prox_shape_distance(&a, &b);
    assert_int_equal(d.status, PROX_OK);
    assert_int_equal(d.intersect, 0);
    assert_near(d.distance, 4.0, 1e-13);
    assert_near(d.p1.z, 4.0, 1e-13);
    assert_near(d.p2.z, 8.0, 1e-13);
}

static void test_overlap_on_axis(void **state)
{
    (void)state;
    /* ELL spans z in [3, 7]: lifting it by 1 clears the top cap; sideways it would need 1 + 0.433 */
    prox_shape a = rcc(), b = ell(5.0);
    check_signed(&a, &b, -1.0);
    prox_distance_result d = prox_shape_distance(&a, &b);
    assert_int_equal(d.intersect, 1);
}

static void test_cone_in_cylinder_axis(void **state)
{
    (void)state;
    /* a TRC (r1 2 at z = 6, r2 0.5 at z = 9) above the RCC: 2 apart along the axis */
    prox_shape a = rcc(), b = prox_shape_from_trc((prox_trc){prox_v3(0, 0, 6), prox_v3(0, 0, 3), 2.0, 0.5});
    check_signed(&a, &b, 2.0);
    /* a sphere of radius 1 centred at z = 4.5 dips 0.5 below the top cap: lifting by 0.5 clears it */
    prox_shape s = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 4.5), 1.0});
    check_signed(&a, &s, -0.5);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_apart_on_axis),
        cmocka_unit_test(test_overlap_on_axis),
        cmocka_unit_test(test_cone_in_cylinder_axis),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
