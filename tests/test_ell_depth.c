/* The ellipsoid lower bound of the depth of two ellipsoids (src/sat/ell_depth.c): an ellipsoid inside
 * their Minkowski difference, touching it along a given direction. What it proves must hold: two
 * spheres (the bound is then the depth, rA + rB - |delta|, along any direction), and random
 * overlapping pairs of ellipsoids of revolution and spheres (aspects 1e-2..1e2, depths from shallow to
 * one body inside the other), whose depth the cover of the sphere proves (prox_convex_signed_full):
 * the bound may not exceed that depth, along its normal or any other direction. Along the normal it
 * must be the depth itself (within the 1e-10 S of a proof) for most pairs, and the signed query
 * must then prove every such pair without the cover. */
#include "test_util.h"

#include <float.h>

#include "core/body.h"
#include "core/tol.h"
#include "sat/convex.h"
#include "sat/ell_depth.h"

/* A random ellipsoid of revolution (or, one time in five, a sphere) about c: semi-axes log-uniform
 * within a factor 10^aspect of each other, the larger up to 5. */
static prox_shape random_ell(test_rng *g, prox_vec3 c, double aspect)
{
    double a = 5.0 * pow(10.0, test_range(g, -aspect, 0.0)), b = 5.0 * pow(10.0, test_range(g, -aspect, 0.0));
    if (test_uniform(g) < 0.2) return prox_shape_from_sph((prox_sph){c, a});
    return prox_shape_from_ell((prox_ell){c, prox_v3_scale(test_unit(g), a), b});
}

static void test_spheres_exact(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(71);
    for (int i = 0; i < 200; ++i) {
        double ra = test_range(&g, 0.1, 5.0), rb = test_range(&g, 0.1, 5.0);
        prox_vec3 d = prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 0.99) * (ra + rb));
        prox_shape a = prox_shape_from_sph((prox_sph){{0, 0, 0}, ra}), b = prox_shape_from_sph((prox_sph){d, rb});
        prox_body ba = prox_body_make(&a), bb = prox_body_make(&b);
        double S = prox_shape_pair_scale(&a, &b), depth = ra + rb - prox_v3_norm(d);
        double lb = prox_ell_depth_lower(&ba, &bb, d, test_unit(&g), S);
        if (!(lb <= depth + 1e-14 * S && lb >= depth - 1e-12 * S)) {
            print_error("spheres %g %g apart %g: bound %.17g depth %.17g\n", ra, rb, prox_v3_norm(d), lb, depth);
            fail();
        }
    }
}

static void run_pairs(double aspect, int count, uint64_t seed)
{
    test_rng g = test_rng_seed(seed);
    int pairs = 0, tight = 0, quick = 0;
    double worst = -INFINITY; /* the largest (bound - depth) / S seen */
    while (pairs < count) {
        prox_shape a = random_ell(&g, prox_v3(0, 0, 0), aspect);
        prox_shape b = random_ell(&g, prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 6.0)), aspect);
        prox_body ba = prox_body_make(&a), bb = prox_body_make(&b);
        prox_convex_info gi, fi;
        prox_signed_result full = prox_convex_signed_full(&ba, &bb, &gi);
        assert_int_equal(full.status, PROX_OK);
        if (!(full.sd < 0.0) || !gi.certified) continue;
        ++pairs;
        double S = prox_shape_pair_scale(&a, &b), depth = -full.sd;
        prox_vec3 delta = prox_v3_sub(bb.c, ba.c);
        /* a lower bound along any direction: never above the proved depth (the cover's best, which
         * is at least the depth) */
        for (int k = 0; k < 4; ++k) {
            prox_vec3 n = k == 0 ? full.normal : test_unit(&g);
            double lb = prox_ell_depth_lower(&ba, &bb, delta, n, S);
            worst = fmax(worst, (lb - depth) / S);
            if (!(lb <= depth + 1e-12 * S)) {
                print_error("pair %d: bound %.17g above the depth %.17g (%.3g S)\n", pairs, lb, depth, (lb - depth) / S);
                fail();
            }
            if (k == 0) tight += lb >= depth - PROX_TOL_DEPTH_CERT * S;
        }
        /* the signed query proves it without the cover, equal to the cover's within the bar */
        prox_signed_result f = prox_convex_signed_ex(&ba, &bb, &fi);
        quick += fi.global == 0;
        assert_true(fi.certified);
        assert_true(fabs(f.sd - full.sd) <= PROX_TOL_DEPTH_BAR * S);
        assert_true(fi.lower <= depth + PROX_TOL_DEPTH_BAR * S);
    }
    printf("aspect 1e%g: %d overlapping pairs, the bound along the normal proves %d, the query proves %d without the cover; "
           "max (bound - depth) / S %.2g\n",
           aspect, pairs, tight, quick, worst);
    assert_true(tight * 10 >= pairs * 9); /* 95 % measured on each set */
    assert_true(quick == pairs);
}

static void test_random_pairs(void **state)
{
    (void)state;
    run_pairs(1.0, 150, 72);
}

static void test_random_pairs_thin(void **state)
{
    (void)state;
    run_pairs(2.0, 150, 73);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spheres_exact),
        cmocka_unit_test(test_random_pairs),
        cmocka_unit_test(test_random_pairs_thin),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
