/* The lower bounds of the depth function phi(D) = hc_A(D) + hc_B(D) - D.Delta over the strata of two
 * cylinders that let the depth's enumeration (src/sat/rcc_depth.c) skip a stratum's solve.
 * - A rim-rim cell (sup_rim_lune_lb): on its lune of directions (D.al >= 0, D.be >= 0) phi must never
 *   fall below the bound. Random pairs of cylinders (radii and heights 0.5..10, centres up to 14
 *   apart, any axes, parallel and antiparallel ones among them), every cell, phi sampled over the
 *   lune and along its boundary arcs and corners.
 * - A ridge D.w = 0 (sup_ridge_shadow_lb): phi sampled around the ridge's great circle, for both
 *   cylinders of the same pairs, never below the bound.
 * Each bound must also be worth its cost: close to the sampled minimum on some strata (a bound a few
 * percent too high would exceed it there), and for the cells above the depth on most of the cells of
 * overlapping pairs, which is what makes the enumeration skip them. */
#include "test_util.h"

#include "core/body.h"
#include "sat/sat_internal.h"
#include "sat/sup_engine.h"

static prox_body random_cyl(test_rng *g, prox_vec3 c, prox_vec3 w)
{
    double r = test_range(g, 0.5, 10.0), h = test_range(g, 0.5, 10.0);
    prox_shape s = prox_shape_from_rcc((prox_rcc){prox_v3_mad(c, -0.5 * h, w), prox_v3_scale(w, h), r});
    return prox_body_make(&s);
}

static double phi(const prox_body *a, const prox_body *b, prox_vec3 d)
{
    return prox_cyl_hc(&a->cyl, d) + prox_cyl_hc(&b->cyl, d) - prox_v3_dot(d, prox_v3_sub(b->c, a->c));
}

/* Pair i of a family: random axes; with family >= 1 every tenth pair parallel or antiparallel, with
 * family 2 also every tenth from the fifth perpendicular (a needle shadow); A at the origin, B up to
 * 14 away. */
static void random_pair(test_rng *g, int i, int family, prox_body *a, prox_body *b)
{
    prox_vec3 wa = test_unit(g), wb = test_unit(g);
    if (family >= 1 && i % 10 == 0) wb = i % 20 == 0 ? wa : prox_v3_neg(wa);
    if (family == 2 && i % 10 == 5) wb = prox_v3_any_perp(wa);
    *a = random_cyl(g, prox_v3(0, 0, 0), wa);
    *b = random_cyl(g, prox_v3_scale(test_unit(g), test_range(g, 0.0, 14.0)), wb);
}

/* Cell k (A's rim at end +-1 by bit 0, B's by bit 1): the rims in absolute coordinates and the
 * lune's normals al = e_A w_A, be = -e_B w_B. */
static void cell_of(const prox_body *a, const prox_body *b, int k, prox_fcircle *ca, prox_fcircle *cb, prox_vec3 *al,
                    prox_vec3 *be)
{
    int ea = k & 1 ? 1 : -1, eb = k & 2 ? 1 : -1;
    *ca = prox_cyl_rim(&a->cyl, ea > 0), *cb = prox_cyl_rim(&b->cyl, eb > 0);
    ca->c = prox_v3_add(ca->c, a->c);
    cb->c = prox_v3_add(cb->c, b->c);
    *al = prox_v3_scale(a->cyl.w, (double)ea), *be = prox_v3_scale(b->cyl.w, (double)-eb);
}

/* The least phi found over the lune: random directions folded into it, the arcs D.al = 0 and
 * D.be = 0 and their ends. */
static double lune_min(test_rng *g, const prox_body *a, const prox_body *b, prox_vec3 al, prox_vec3 be)
{
    double m = INFINITY;
    for (int k = 0; k < 6000; ++k) {
        prox_vec3 d = test_unit(g);
        if (prox_v3_dot(d, al) < 0.0 && prox_v3_dot(d, be) < 0.0) d = prox_v3_neg(d);
        if (prox_v3_dot(d, al) >= 0.0 && prox_v3_dot(d, be) >= 0.0) m = fmin(m, phi(a, b, d));
        for (int e = 0; e < 2; ++e) { /* the arc D.u = 0, D.o >= 0 */
            prox_vec3 u = e ? be : al, o = e ? al : be, t = prox_v3_reject(d, u);
            double n = prox_v3_norm(t);
            if (!(n > 0.0)) continue;
            t = prox_v3_scale(t, 1.0 / n);
            if (prox_v3_dot(t, o) < 0.0) t = prox_v3_neg(t); /* -t lies on the same great circle */
            m = fmin(m, phi(a, b, t));
        }
    }
    prox_vec3 x = prox_v3_cross(al, be);
    if (prox_v3_norm(x) > 0.0) {
        x = prox_v3_normalize(x);
        m = fmin(m, fmin(phi(a, b, x), phi(a, b, prox_v3_neg(x))));
    }
    return m;
}

static void test_bound_below_phi(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(2029);
    int cells = 0, tight = 0;
    double worst = -INFINITY;
    for (int i = 0; i < 300; ++i) {
        prox_body a, b;
        random_pair(&g, i, 1, &a, &b);
        double S = fmax(prox_v3_dist(a.c, b.c), fmax(a.size, b.size));
        for (int k = 0; k < 4; ++k) {
            prox_fcircle ca, cb;
            prox_vec3 al, be;
            cell_of(&a, &b, k, &ca, &cb, &al, &be);
            double lb = sup_rim_lune_lb(&ca, al, &cb, be), m = lune_min(&g, &a, &b, al, be);
            if (m == INFINITY) continue; /* an empty lune: no direction to bound */
            ++cells;
            worst = fmax(worst, (lb - m) / S);
            if (lb > m + 1e-12 * S)
                print_error("pair %d cell %d: bound %.17g above phi %.17g on its lune\n", i, k, lb, m);
            if (lb > 0.0 && lb >= 0.97 * m) ++tight;
        }
    }
    print_message("# %d cells: bound - sampled minimum at most %.2e S; within 3 %% of it on %d\n", cells, worst, tight);
    assert_true(worst <= 1e-12);
    assert_true(tight >= 10);
}

/* phi around the ridge D.w = 0 of `lat` never falls below its bound; returns the least value found. */
static double ridge_min(const prox_body *lat, const prox_body *a, const prox_body *b)
{
    prox_vec3 e1 = prox_v3_any_perp(lat->cyl.w), e2 = prox_v3_cross(lat->cyl.w, e1);
    double m = INFINITY;
    for (int k = 0; k < 20000; ++k) {
        double t = 2.0 * PROX_PI * k / 20000.0;
        m = fmin(m, phi(a, b, prox_v3_add(prox_v3_scale(e1, cos(t)), prox_v3_scale(e2, sin(t)))));
    }
    return m;
}

static void test_ridge_bound_below_phi(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(2031);
    int ridges = 0, tight = 0;
    double worst = -INFINITY;
    for (int i = 0; i < 300; ++i) {
        prox_body a, b;
        random_pair(&g, i, 2, &a, &b);
        double S = fmax(prox_v3_dist(a.c, b.c), fmax(a.size, b.size));
        prox_vec3 delta = prox_v3_sub(b.c, a.c);
        for (int k = 0; k < 2; ++k) {
            const prox_body *lat = k ? &b : &a, *oth = k ? &a : &b;
            double lb = sup_ridge_shadow_lb(lat, oth, k ? prox_v3_neg(delta) : delta), m = ridge_min(lat, &a, &b);
            ++ridges;
            worst = fmax(worst, (lb - m) / S);
            if (lb > m + 1e-12 * S) print_error("pair %d ridge %d: bound %.17g above phi %.17g on it\n", i, k, lb, m);
            if (lb > 0.0 && lb >= 0.97 * m) ++tight;
        }
    }
    print_message("# %d ridges: bound - sampled minimum at most %.2e S; within 3 %% of it on %d\n", ridges, worst, tight);
    assert_true(worst <= 1e-12);
    assert_true(tight >= 10);
}

/* On overlapping pairs the bound is compared with the depth: a cell whose bound exceeds it holds no
 * minimiser, and the depth's enumeration skips it. Most cells of the bench-like pairs must be so. */
static void test_bound_skips_cells(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(2030);
    int cells = 0, skipped = 0;
    for (int i = 0; i < 2000; ++i) {
        prox_body a, b;
        random_pair(&g, i, 0, &a, &b);
        prox_signed_result r = {0};
        if (sup_rcc_depth_enum(&a, &b, &r) != 1) continue; /* disjoint, touching or undecided */
        for (int k = 0; k < 4; ++k) {
            prox_fcircle ca, cb;
            prox_vec3 al, be;
            cell_of(&a, &b, k, &ca, &cb, &al, &be);
            ++cells;
            skipped += sup_rim_lune_lb(&ca, al, &cb, be) > -r.sd;
        }
    }
    print_message("# overlapping pairs: the bound exceeds the depth on %d of %d cells\n", skipped, cells);
    assert_true(cells > 1000);
    assert_true(skipped > cells / 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bound_below_phi),
        cmocka_unit_test(test_bound_skips_cells),
        cmocka_unit_test(test_ridge_bound_below_phi),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
