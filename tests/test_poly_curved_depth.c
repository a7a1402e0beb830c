/* The penetration depth of a polytope (RHP, WED, ARB; BOX against a spheroid) overlapping a cylinder
 * (RCC) or a spheroid (ELL) by its strata (src/sat/poly_curved_depth.c), through the generic signed
 * distance in both orders: equal to the
 * support-function method's certified depth (prox_shape_signed_distance_support, an independent
 * search over directions) within 1e-12 S, certified, with witnesses p2 - p1 = sd n; deep, shallow
 * (1e-10 S) and thin or flat solids (sizes 0.05 .. 10); and the enumeration, not the global search,
 * settles nearly every pair (its fallback counter). */
#include "test_util.h"

#include "sat/sat_internal.h"

#include <math.h>

static double lu(test_rng *g, double lo, double hi) { return exp(test_range(g, log(lo), log(hi))); }

/* A random RHP, WED or ARB (a frustum of a rectangular pyramid) about the origin. */
static prox_shape random_poly(test_rng *g, int k)
{
    test_rot R = test_random_rot(g);
    prox_vec3 e0 = test_rot_apply(&R, prox_v3(1, 0, 0)), e1 = test_rot_apply(&R, prox_v3(0, 1, 0));
    prox_vec3 e2 = test_rot_apply(&R, prox_v3(0, 0, 1));
    if (k == 0) {
        double a = lu(g, 0.05, 10), b = lu(g, 0.05, 10), h = lu(g, 0.05, 10), s = test_range(g, 0.1, 1.0);
        static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
        static const int faces[6] = {1234, 5678, 1265, 2376, 3487, 4158};
        prox_arb x;
        for (int i = 0; i < 4; ++i) {
            x.corner[i] = prox_v3_add(prox_v3_add(prox_v3_scale(e0, sx[i] * a), prox_v3_scale(e1, sy[i] * b)), prox_v3_scale(e2, -h));
            x.corner[4 + i] =
                prox_v3_add(prox_v3_add(prox_v3_scale(e0, s * sx[i] * a), prox_v3_scale(e1, s * sy[i] * b)), prox_v3_scale(e2, h));
        }
        for (int f = 0; f < 6; ++f) x.face[f] = faces[f];
        return prox_shape_from_arb(x);
    }
    if (k == 1) {
        double a = lu(g, 0.05, 10), b = lu(g, 0.05, 10), h = lu(g, 0.05, 10), th = test_range(g, 0.3, 2.8);
        prox_vec3 v1 = prox_v3_scale(e0, a), v2 = prox_v3_add(prox_v3_scale(e0, b * cos(th)), prox_v3_scale(e1, b * sin(th)));
        prox_vec3 v3 = prox_v3_scale(e2, h);
        return prox_shape_from_wed((prox_wed){prox_v3_scale(prox_v3_add(prox_v3_add(v1, v2), v3), -1.0 / 3.0), v1, v2, v3});
    }
    double ap = lu(g, 0.05, 10), h = lu(g, 0.05, 10);
    prox_rhp x;
    assert_int_equal(prox_rhp_regular(prox_v3_scale(e2, -0.5 * h), prox_v3_scale(e2, h), prox_v3_scale(e0, ap), &x), PROX_OK);
    return prox_shape_from_rhp(x);
}

/* A random RCC (ell = 0) or ELL (prolate and oblate) centred at c. */
static prox_shape random_curved(test_rng *g, prox_vec3 c, int ell)
{
    prox_vec3 w = test_unit(g);
    double r = lu(g, 0.05, 10), h = lu(g, 0.05, 10);
    if (ell) return prox_shape_from_ell((prox_ell){c, prox_v3_scale(w, 0.5 * h), r});
    return prox_shape_from_rcc((prox_rcc){prox_v3_mad(c, -0.5 * h, w), prox_v3_scale(w, h), r});
}

/* A random box about the origin. */
static prox_shape random_box(test_rng *g)
{
    test_rot R = test_random_rot(g);
    prox_box b;
    b.corner = prox_v3(0, 0, 0);
    for (int k = 0; k < 3; ++k) {
        b.edge[k] = prox_v3_scale(test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2)), lu(g, 0.05, 10));
        b.corner = prox_v3_mad(b.corner, -0.5, b.edge[k]);
    }
    return prox_shape_from_box(b);
}

/* One overlapping pair in the order given: the depth, its proof and its witnesses. */
static void check_depth(const prox_shape *a, const prox_shape *b)
{
    prox_signed_result s = prox_shape_signed_distance(a, b), e = prox_shape_signed_distance_support(a, b);
    assert_int_equal(s.status, PROX_OK);
    assert_int_equal(e.status, PROX_OK);
    double S = prox_shape_pair_scale(a, b);
    if (!(fabs(s.sd - e.sd) <= 1e-12 * S))
        fail_msg("%s-%s: depth %.17g, the support method's %.17g (S %g)", prox_shape_kind_name(a->kind),
                 prox_shape_kind_name(b->kind), -s.sd, -e.sd, S);
    assert_true(s.certified);
    assert_true(s.sd_lower <= s.sd + 1e-12 * S && s.sd <= s.sd_upper + 1e-12 * S);
    assert_true(prox_v3_dist(prox_v3_sub(s.p2, s.p1), prox_v3_scale(s.normal, s.sd)) <= 1e-9 * S);
}

static void test_depth_matches_support_method(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(41);
    unsigned long long f0 = prox_sat_poly_depth_fallbacks();
    int n = 0, shallow = 0;
    for (int t = 0; n < 3000; ++t) {
        int ell = t % 2, k = (t / 2) % (ell ? 4 : 3); /* a box against the spheroid only: BOX-RCC has its own solver */
        prox_shape a = k == 3 ? random_box(&g) : random_poly(&g, k);
        prox_shape b = random_curved(&g, prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 8.0)), ell);
        if (prox_shape_validate(&a) != PROX_OK || prox_shape_validate(&b) != PROX_OK) continue;
        prox_signed_result s = prox_shape_signed_distance(&a, &b);
        if (s.status != PROX_OK || !(s.sd < 0.0)) continue;
        if (t % 4 == 3) { /* moved back along the normal to overlap by 1e-10 S */
            prox_shape b2;
            double S = prox_shape_pair_scale(&a, &b);
            if (prox_shape_translated(&b, prox_v3_scale(s.normal, -s.sd - 1e-10 * S), &b2) != PROX_OK) continue;
            b = b2;
            ++shallow;
        }
        check_depth(&a, &b);
        check_depth(&b, &a);
        ++n;
    }
    unsigned long long fallbacks = prox_sat_poly_depth_fallbacks() - f0;
    print_message("# %d overlapping pairs (%d 1e-10 S deep), both orders: %llu handed to the global search\n", n,
                  shallow, fallbacks);
    assert_true(shallow > 400);
    assert_true(fallbacks < 2 * (unsigned long long)n / 20); /* under 5 % of the 2n answers */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_depth_matches_support_method),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
