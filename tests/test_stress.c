/* Numerical stress of the cylinder-cylinder queries: the near-degenerate families
 * of bench/stress_gen.h (parallel / antiparallel / perpendicular axes within 1e-15..1e-3 rad, gaps
 * 0 and 1e-12..1e-3, rim-rim, rim-face, face-face, lateral contacts, nearly coaxial end circles,
 * r/h from 1e-6 to 1e6, size ratios 1e3..1e6, scenes scaled by 1e-8..1e8 and moved 1e3..1e8 from
 * the origin), each pair built with a known exact distance (support-function slab construction).
 * For every pair: the distance against the construction, symmetry, rigid-motion invariance, exact
 * binary scale invariance, |p1 - p2| = d, points on the surfaces, and the SAT verdict against the
 * distance sign. Tolerance: 1e-12 x S plus the rounding the input doubles carry (8 ulp of the largest
 * coordinate), S = max(|cA - cB|, hA, hB, rA, rB). The worst case of each family is printed as the
 * 14 numbers of the pair (validation-file order) so that a failure is a reproducer. */
#include <string.h>

#include "test_util.h"

#include "prox/sat.h"
#include "../bench/stress_gen.h"

#define PAIRS_PER_FAMILY 1500

/* Worst violation of one invariant over a family, with the pair that produced it. */
typedef struct worst {
    double err; /* relative to S */
    prox_rcc a, b;
} worst;

static void keep(worst *w, double err, const prox_rcc *a, const prox_rcc *b)
{
    if (!(err <= w->err)) w->err = err, w->a = *a, w->b = *b; /* NaN is kept as a failure */
}

static void print_pair(const char *what, const worst *w)
{
    printf("  %-10s %.3g  pair: %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
           what, w->err, w->a.base.x, w->a.base.y, w->a.base.z, w->a.axis.x, w->a.axis.y, w->a.axis.z, w->a.radius,
           w->b.base.x, w->b.base.y, w->b.base.z, w->b.axis.x, w->b.axis.y, w->b.axis.z, w->b.radius);
}

/* Allowed error of a pair relative to S: 1e-12 plus the input's own rounding. */
static double rel_tol(const prox_rcc *a, const prox_rcc *b, double S)
{
    return 1e-12 + 8.0 * sg_input_ulp(a, b) / S;
}

enum { W_DIST, W_SYM, W_MOTION, W_SCALE, W_WITNESS, W_SAT, W_COUNT };
static const char *const w_names[W_COUNT] = {"distance", "symmetry", "motion", "scale", "witness", "sat"};

/* Checks one pair; updates the worst violations (each as error / allowed error). */
static void check_pair(const sg_pair *p, sg_rng *r, worst *w)
{
    const prox_rcc *a = &p->a, *b = &p->b;
    double S = sg_pair_scale(a, b), tol = rel_tol(a, b, S);
    prox_distance_result d = prox_rcc_distance(a, b);
    if (d.status != PROX_OK || !isfinite(d.distance)) {
        keep(&w[W_DIST], INFINITY, a, b);
        return;
    }
    keep(&w[W_DIST], fabs(d.distance - p->d_ref) / S / tol, a, b);
    prox_distance_result e = prox_rcc_distance(b, a);
    keep(&w[W_SYM], fabs(e.distance - d.distance) / S / tol, a, b);
    /* witnesses: |p1 - p2| = d and, when apart, both points on their surfaces */
    double wit = fabs(prox_v3_dist(d.p1, d.p2) - d.distance);
    long double da = sg_point_rcc(a, d.p1), db = sg_point_rcc(b, d.p2);
    wit = fmax(wit, d.distance > 0 ? (double)fmaxl(fabsl(da), fabsl(db)) : (double)fmaxl(fmaxl(da, db), 0));
    keep(&w[W_WITNESS], wit / S / tol, a, b);
    /* rigid motion: rotate and translate both (the moved input carries its own rounding) */
    double q[4];
    sg_random_quat(r, q);
    prox_vec3 t = prox_v3_scale(sg_unit(r), S * sg_u(r));
    prox_rcc ma = sg_move(*a, q, t), mb = sg_move(*b, q, t);
    double mtol = rel_tol(&ma, &mb, S) + tol;
    keep(&w[W_MOTION], fabs(prox_rcc_distance(&ma, &mb).distance - d.distance) / S / mtol, a, b);
    /* exact binary scaling: every input double scales without rounding */
    double s = ldexp(1.0, (int)(sg_next(r) % 41) - 20);
    prox_rcc sa = sg_scale(*a, s), sb = sg_scale(*b, s);
    keep(&w[W_SCALE], fabs(prox_rcc_distance(&sa, &sb).distance - s * d.distance) / (s * S) / tol, a, b);
    /* SAT verdict against the (reference) distance sign, outside touching */
    prox_test_result v = prox_rcc_sat(a, b);
    int bad = v.status != PROX_OK || (p->d_ref > tol * S && v.intersect);
    keep(&w[W_SAT], bad ? INFINITY : 0.0, a, b);
}

/* Runs one family and fails when any invariant exceeds its tolerance (ratio > 1). */
static void run_family(int fam)
{
    sg_rng r = sg_seed(1000 + (uint64_t)fam);
    worst w[W_COUNT];
    memset(w, 0, sizeof w);
    for (int k = 0; k < PAIRS_PER_FAMILY; ++k) {
        sg_pair p = sg_make(&r, fam);
        check_pair(&p, &r, w);
    }
    printf("family %-14s worst error / tolerance:\n", sg_family_names[fam]);
    int ok = 1;
    for (int k = 0; k < W_COUNT; ++k) {
        print_pair(w_names[k], &w[k]);
        ok &= w[k].err <= 1.0;
    }
    if (!ok) fail_msg("family %s: an invariant exceeds its tolerance (reproducers above)", sg_family_names[fam]);
}

#define FAMILY_TEST(id)                                        \
    static void test_stress_##id(void **state)                 \
    {                                                          \
        (void)state;                                           \
        run_family(id);                                        \
    }
FAMILY_TEST(0)
FAMILY_TEST(1)
FAMILY_TEST(2)
FAMILY_TEST(3)
FAMILY_TEST(4)
FAMILY_TEST(5)
FAMILY_TEST(6)
FAMILY_TEST(7)
FAMILY_TEST(8)
FAMILY_TEST(9)
FAMILY_TEST(10)
FAMILY_TEST(11)
FAMILY_TEST(12)

/* The generator itself: its constructed distance must match an independent point-sampling bound
 * (no sample pair closer than d_ref, up to rounding), or every other check here would be void. */
static void test_stress_generator_is_sound(void **state)
{
    (void)state;
    sg_rng r = sg_seed(5);
    for (int k = 0; k < 13 * 20; ++k) {
        sg_pair p = sg_make(&r, k % SG_NFAMILIES);
        double S = sg_pair_scale(&p.a, &p.b), tol = rel_tol(&p.a, &p.b, S) * S;
        assert_true(p.d_ref >= 0);
        /* sampled points of A against the closed solid B: none deeper than the gap allows */
        for (int j = 0; j < 400; ++j) {
            double t = sg_u(&r), rho = sqrt(sg_u(&r)), ang = 2 * PROX_PI * sg_u(&r);
            prox_vec3 w = prox_v3_normalize(p.a.axis), u = prox_v3_any_perp(w), v = prox_v3_cross(w, u);
            prox_vec3 x = prox_v3_mad(p.a.base, t, p.a.axis);
            x = prox_v3_mad(x, p.a.radius * rho * cos(ang), u);
            x = prox_v3_mad(x, p.a.radius * rho * sin(ang), v);
            assert_true((double)sg_point_rcc(&p.b, x) >= p.d_ref - tol);
        }
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stress_generator_is_sound),
        cmocka_unit_test(test_stress_0),  cmocka_unit_test(test_stress_1),  cmocka_unit_test(test_stress_2),
        cmocka_unit_test(test_stress_3),  cmocka_unit_test(test_stress_4),  cmocka_unit_test(test_stress_5),
        cmocka_unit_test(test_stress_6),  cmocka_unit_test(test_stress_7),  cmocka_unit_test(test_stress_8),
        cmocka_unit_test(test_stress_9),  cmocka_unit_test(test_stress_10), cmocka_unit_test(test_stress_11),
        cmocka_unit_test(test_stress_12),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
