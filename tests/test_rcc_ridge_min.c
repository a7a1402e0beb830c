/* The ridge of the cylinder-cylinder depth solved for its minimiser only (sup_ridge_shadow_min,
 * rcc_ridge_shadow.c): on the great circle D.w = 0 of one cylinder, the least phi(D) = hc_A(D) +
 * hc_B(D) - D.delta over its candidate directions (each with both signs) must equal the minimum of
 * phi over the circle, found here independently by a dense sampling of the angle refined by
 * golden-section search, and the one of every stationary direction (sup_ridge_shadow). */
#include "test_util.h"

#include "core/body.h"
#include "sat/sat_internal.h"
#include "sat/sup_engine.h"

/* phi at the unit direction d (A, B centrally symmetric bodies, delta = c_B - c_A). */
static double phi(const prox_body *a, const prox_body *b, prox_vec3 delta, prox_vec3 d)
{
    return prox_cyl_hc(&a->cyl, d) + prox_cyl_hc(&b->cyl, d) - prox_v3_dot(d, delta);
}

/* The least phi over the candidates (not unit), projected into the ridge plane, both signs. */
static double cand_min(const prox_body *a, const prox_body *b, prox_vec3 delta, prox_vec3 w, const prox_vec3 *c, int n)
{
    double m = INFINITY;
    for (int i = 0; i < n; ++i) {
        prox_vec3 v = prox_v3_reject(c[i], w);
        double len = prox_v3_norm(v);
        if (!(len > 0.0)) continue;
        v = prox_v3_scale(v, 1.0 / len);
        m = fmin(m, fmin(phi(a, b, delta, v), phi(a, b, delta, prox_v3_neg(v))));
    }
    return m;
}

/* phi on the ridge circle at angle t (frame e1, e2 of the plane normal to w). */
static double ridge_at(const prox_body *a, const prox_body *b, prox_vec3 delta, prox_vec3 e1, prox_vec3 e2, double t)
{
    return phi(a, b, delta, prox_v3_add(prox_v3_scale(e1, cos(t)), prox_v3_scale(e2, sin(t))));
}

/* The minimum of phi over the ridge circle: 4096 samples, then golden-section search in the two
 * sample intervals around each of the best samples (phi is smooth there or has a kink at a local
 * minimum, where the search still converges). */
static double brute_min(const prox_body *a, const prox_body *b, prox_vec3 delta, prox_vec3 w)
{
    enum { N = 4096 };
    prox_vec3 e1 = prox_v3_any_perp(w), e2 = prox_v3_cross(w, e1);
    double best = INFINITY, h = 2.0 * PROX_PI / N;
    for (int i = 0; i < N; ++i) {
        double f0 = ridge_at(a, b, delta, e1, e2, (i - 1) * h), f1 = ridge_at(a, b, delta, e1, e2, i * h),
               f2 = ridge_at(a, b, delta, e1, e2, (i + 1) * h);
        if (!(f1 <= f0 && f1 <= f2)) continue; /* not a sampled local minimum */
        double lo = (i - 1) * h, hi = (i + 1) * h, g = 0.5 * (sqrt(5.0) - 1.0);
        for (int it = 0; it < 80; ++it) {
            double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
            if (ridge_at(a, b, delta, e1, e2, x1) < ridge_at(a, b, delta, e1, e2, x2)) hi = x2;
            else lo = x1;
        }
        best = fmin(best, fmin(f1, ridge_at(a, b, delta, e1, e2, 0.5 * (lo + hi))));
    }
    return best;
}

static prox_body random_cyl(test_rng *g, prox_vec3 c)
{
    prox_vec3 w = test_unit(g);
    double h = test_range(g, 0.5, 10.0), r = test_range(g, 0.5, 10.0);
    prox_shape s = prox_shape_from_rcc((prox_rcc){prox_v3_mad(c, -0.5 * h, w), prox_v3_scale(w, h), r});
    return prox_body_make(&s);
}

static void test_ridge_minimum(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(20261125);
    int checked = 0;
    for (int k = 0; k < 300; ++k) {
        prox_body a = random_cyl(&g, prox_v3(0, 0, 0));
        prox_body b = random_cyl(&g, prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 14.0)));
        prox_vec3 delta = prox_v3_sub(b.c, a.c);
        double S = fmax(prox_v3_norm(delta), fmax(a.size, b.size));
        for (int side = 0; side < 2; ++side) {
            const prox_body *lat = side ? &b : &a, *oth = side ? &a : &b;
            prox_vec3 cmin[24], call[24];
            int nmin = sup_ridge_shadow_min(lat, oth, delta, cmin, 24), nall = sup_ridge_shadow(lat, oth, delta, call, 24);
            assert_true((nmin < 0) == (nall < 0));
            if (nmin < 0) continue; /* a degenerate shadow: the caller solves the rims' quartics */
            assert_true(nmin <= nall);
            double m = cand_min(&a, &b, delta, lat->cyl.w, cmin, nmin);
            assert_near(m, cand_min(&a, &b, delta, lat->cyl.w, call, nall), 1e-13 * S);
            double bf = brute_min(&a, &b, delta, lat->cyl.w);
            assert_true(m <= bf + 1e-13 * S); /* every ridge direction is an upper bound of the minimum */
            assert_near(m, bf, 1e-9 * S);
            ++checked;
        }
    }
    assert_true(checked > 500);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_ridge_minimum)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
