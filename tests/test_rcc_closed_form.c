/* PROX_METHOD_CLOSED_FORM (src/distance/rcc_closed_form.c): Agarwal's complete enumeration on its own.
 * Guards: the reference sets of tests/data (distance and points within 1e-12 S, every disjoint pair
 * certified, a common point for every overlapping pair); agreement with the fast method and
 * symmetry on seeded random pairs that are not in the sets (protocol A at varied scale, and the
 * near-degenerate stress families with their constructed exact distance); a rim-rim contact decided by
 * the GSL-rooted degree-8 polynomial; the degenerate contacts (coaxial rims, parallel axes, parallel
 * faces, perpendicular disk and side, nested, point contacts); a root-finder failure reported as
 * PROX_ENUMERIC; invalid input. */
#include "test_refsets.h"
#include <stdlib.h>
#include <string.h>

#include "core/poly.h"
#include "distance/rcc_methods.h"
#include "../bench/stress_gen.h"

/* Tolerance on points: 1e-12 S plus the rounding of the output coordinates (pairs far away). */
static double point_tol(const prox_distance_result *r, double S)
{
    return 1e-12 * S + 4.0 * fmax(prox_v3_maxabs(r->p1), prox_v3_maxabs(r->p2)) * 0x1p-52;
}

/* The answer is self-consistent: status OK, the method's tag, p1 in A and p2 in B, |p2 - p1| equal to
 * the distance; an intersecting answer has distance 0 and p1 = p2 in both solids. Returns 0 (after
 * printing) when not. */
static int answer_valid(const prox_rcc *a, const prox_rcc *b, const prox_distance_result *r, const char *what)
{
    double S = prox_rcc_pair_scale(a, b), pt = point_tol(r, S);
    int ok = r->status == PROX_OK && r->method == PROX_METHOD_CLOSED_FORM &&
             prox_rcc_contains_point(a, r->p1, pt) && prox_rcc_contains_point(b, r->p2, pt) &&
             fabs(prox_v3_dist(r->p1, r->p2) - r->distance) <= pt;
    if (r->intersect) ok = ok && r->distance == 0.0 && prox_v3_dist(r->p1, r->p2) == 0.0 && r->certified;
    if (!ok)
        print_error("%s: invalid answer (status %d, d %.17g, intersect %d, |p2-p1| %.17g, p1 in A %d, p2 in B %d)\n",
                    what, r->status, r->distance, r->intersect, prox_v3_dist(r->p1, r->p2),
                    prox_rcc_contains_point(a, r->p1, pt), prox_rcc_contains_point(b, r->p2, pt));
    return ok;
}

/* One reference set: every disjoint pair within 1e-12 S of the reference and certified, every
 * overlapping pair (sd <= 0) intersecting with a common point. */
static void check_reference_set(const char *name)
{
    double *P, *R;
    size_t n = load_set(name, &P, &R);
    size_t bad = 0, overlaps = 0, kinds[8] = {0};
    double worst = 0.0;
    for (size_t i = 0; i < n; ++i) {
        prox_rcc a = rcc_of(P + 14 * i), b = rcc_of(P + 14 * i + 7);
        double sd = R[7 * i], S = prox_rcc_pair_scale(&a, &b);
        prox_distance_result r = prox_rcc_closed_form(&a, &b);
        int ok = answer_valid(&a, &b, &r, name);
        double err = fabs(r.distance - fmax(sd, 0.0));
        worst = fmax(worst, err / S);
        if (sd > 0.0) {
            ok = ok && err <= 1e-12 * S && (r.certified || r.intersect);
        } else {
            ok = ok && r.intersect;
            ++overlaps;
        }
        kinds[r.pair]++;
        if (!ok && bad++ < 5)
            print_error("%s pair %zu: d %.17g ref sd %.17g err/S %.3g intersect %d certified %d gap %.17g\n", name,
                        i, r.distance, sd, err / S, r.intersect, r.certified, r.certificate_gap);
    }
    printf("# %s: %zu pairs, %zu overlapping, max |d - ref|/S %.3g, failures %zu; pairs SS %zu CS %zu CD %zu "
           "CC %zu overlap %zu\n",
           name, n, overlaps, worst, bad, kinds[PROX_PAIR_SS], kinds[PROX_PAIR_CS], kinds[PROX_PAIR_CD],
           kinds[PROX_PAIR_CC], kinds[PROX_PAIR_OVERLAP]);
    free(P);
    free(R);
    assert_int_equal(bad, 0);
}

static void test_cf_paper_cases(void **state)
{
    (void)state;
    check_reference_set("paper_cases");
}

static void test_cf_agarwal_public(void **state)
{
    (void)state;
    check_reference_set("agarwal_public");
}

static void test_cf_stress_public(void **state)
{
    (void)state;
    check_reference_set("stress_public");
}

/* A random pair of protocol A's kind (B around A, random orientation and sizes), then rotated,
 * scaled by 10^U(-6, 6) and translated up to 1e3 x that scale: varied scale and orientation. */
static void random_scaled_pair(test_rng *g, prox_rcc *a, prox_rcc *b)
{
    prox_rcc a0 = {prox_v3(0, 0, 0), prox_v3(0, 0, test_range(g, 0.5, 10)), test_range(g, 0.2, 4)};
    prox_vec3 o = prox_v3_scale(test_unit(g), test_range(g, 0, 20));
    prox_rcc b0 = {o, prox_v3_scale(test_unit(g), test_range(g, 0.5, 20)), test_range(g, 0.2, 8)};
    test_rot R = test_random_rot(g);
    double s = pow(10.0, test_range(g, -6, 6));
    prox_vec3 t = prox_v3_scale(test_unit(g), s * test_range(g, 0, 1e3));
    const prox_rcc *in[2] = {&a0, &b0};
    prox_rcc *out[2] = {a, b};
    for (int k = 0; k < 2; ++k)
        *out[k] = (prox_rcc){prox_v3_add(prox_v3_scale(test_rot_apply(&R, in[k]->base), s), t),
                             prox_v3_scale(test_rot_apply(&R, in[k]->axis), s), s * in[k]->radius};
}

/* Compares the closed form with the fast method on (a, b) and checks it against swapping A and B;
 * `ref` (>= 0 when known) is a constructed exact distance, `slack` the input's rounding. Returns 1
 * when everything agrees; worst[0] collects the largest disagreement with the fast method and the
 * swapped query, worst[1] with the constructed distance too (relative to S). */
static int agree(const prox_rcc *a, const prox_rcc *b, double ref, double slack, double worst[2])
{
    double S = prox_rcc_pair_scale(a, b), tol = 1e-12 * S + slack;
    prox_distance_result c = prox_rcc_closed_form(a, b), f = prox_rcc_distance(a, b), s = prox_rcc_closed_form(b, a);
    int ok = answer_valid(a, b, &c, "random") && answer_valid(b, a, &s, "random swapped") && f.status == PROX_OK;
    double e = fmax(fabs(c.distance - f.distance), fabs(c.distance - s.distance));
    worst[0] = fmax(worst[0], e / S);
    if (ref >= 0.0) e = fmax(e, fabs(c.distance - ref));
    worst[1] = fmax(worst[1], e / S);
    ok = ok && e <= tol;
    if (c.distance > tol) ok = ok && c.certified && !c.intersect && !s.intersect;
    if (c.intersect && s.intersect) ok = ok && c.a_in_b == s.b_in_a && c.b_in_a == s.a_in_b;
    if (c.intersect && f.intersect) ok = ok && c.a_in_b == f.a_in_b && c.b_in_a == f.b_in_a;
    if (!ok)
        print_error("closed form %.17g (intersect %d, in %d %d, cert %d, pair %d) fast %.17g (in %d %d) swapped "
                    "%.17g (pair %d) ref %.17g, S %.3g, err/S %.3g\n",
                    c.distance, c.intersect, c.a_in_b, c.b_in_a, c.certified, c.pair, f.distance, f.a_in_b,
                    f.b_in_a, s.distance, s.pair, ref, S, e / S);
    return ok;
}

/* ~2000 pairs not in the sets: 1000 of protocol A at varied scale, position and orientation, and 1000
 * from the stress generator's near-degenerate families (rim-rim, parallel and perpendicular axes,
 * faces, coaxial rims, extreme aspects and size ratios, far from the origin). */
static void test_cf_random_agreement(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(424242);
    int bad = 0;
    double worst[2] = {0.0, 0.0};
    for (int i = 0; i < 1000; ++i) {
        prox_rcc a, b;
        random_scaled_pair(&g, &a, &b);
        double ulp = 8.0 * fmax(prox_v3_maxabs(a.base), prox_v3_maxabs(b.base)) * 0x1p-52;
        if (!agree(&a, &b, -1.0, ulp, worst) && bad++ < 5) print_error("  protocol-A pair %d\n", i);
    }
    sg_rng r = sg_seed(20261125);
    for (int i = 0; i < 1000; ++i) {
        int fam = i % SG_NFAMILIES;
        sg_pair p = sg_make(&r, fam);
        double slack = 8.0 * sg_input_ulp(&p.a, &p.b);
        if (!agree(&p.a, &p.b, p.d_ref > 0.0 ? p.d_ref : 0.0, slack, worst) && bad++ < 10)
            print_error("  stress family %s, pair %d\n", sg_family_names[fam], i);
    }
    printf("# 2000 random pairs: worst |closed form - fast or swapped| / S %.3g, with the constructed distance "
           "%.3g (input rounding of far pairs), failures %d\n",
           worst[0], worst[1], bad);
    assert_int_equal(bad, 0);
}

/* Rotation of +z * len by the unit quaternion [q0, q1, q2, q3] (q0 scalar), as in Agarwal's Table 1. */
static prox_vec3 quat_axis(double q0, double q1, double q2, double q3, double len)
{
    return prox_v3(2 * (q1 * q3 + q0 * q2) * len, 2 * (q2 * q3 - q0 * q1) * len, (1 - 2 * (q1 * q1 + q2 * q2)) * len);
}

/* A rim-rim contact decided by the degree-8 polynomial: Agarwal's Fig. 8 (Case 3, P(C1b, C2t), 7.106 as
 * printed), and constructed rim-rim contacts with an exact distance (B placed so that its support
 * point along -n is `gap` beyond A's along a generic n: dist = gap exactly). The pair must be C-C and
 * certified; with GSL's QR failing (test hook) the same query reports PROX_ENUMERIC, so GSL's roots
 * are on the path that decided it. */
static void test_cf_rim_rim_gsl(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(0, 0, 0), prox_v3(0, 0, 12), 2};
    prox_rcc b = {prox_v3(-12, 12, -18), quat_axis(0.3, 0.4, -0.3, sqrt(33.0) / (5 * sqrt(2.0)), 18), 2.5};
    prox_distance_result r = prox_rcc_closed_form(&a, &b);
    assert_true(answer_valid(&a, &b, &r, "Fig. 8"));
    assert_int_equal(r.pair, PROX_PAIR_CC);
    assert_int_equal(r.feature1, PROX_FEAT_RIM_BASE); /* P(C1b, C2t), Sec. 4 */
    assert_int_equal(r.feature2, PROX_FEAT_RIM_TOP);
    assert_int_equal(r.agarwal, PROX_CASE_3);
    assert_true(r.certified);
    assert_near(r.distance, 7.106, 0.0005);
    assert_near(r.distance, prox_rcc_distance(&a, &b).distance, 1e-12 * prox_rcc_pair_scale(&a, &b));
    prox_poly_test_fail_qr(1);
    prox_distance_result e = prox_rcc_closed_form(&a, &b);
    prox_poly_test_fail_qr(0);
    assert_int_equal(e.status, PROX_ENUMERIC);

    test_rng g = test_rng_seed(88);
    for (int i = 0; i < 50; ++i) {
        prox_rcc A = {prox_v3(0, 0, 0), prox_v3_scale(test_unit(&g), test_range(&g, 0.5, 5)), test_range(&g, 0.3, 3)};
        prox_rcc B = {prox_v3(0, 0, 0), prox_v3_scale(test_unit(&g), test_range(&g, 0.5, 5)), test_range(&g, 0.3, 3)};
        prox_vec3 n = test_unit(&g);
        /* generic n: the support sets are single rim points (n at least 0.1 rad off axes and planes) */
        double ca = fabs(prox_v3_dot(n, prox_v3_normalize(A.axis)));
        double cb = fabs(prox_v3_dot(n, prox_v3_normalize(B.axis)));
        if (ca < 0.1 || ca > 0.99 || cb < 0.1 || cb > 0.99) continue;
        double gap = pow(10.0, test_range(&g, -6, 0));
        prox_vec3 pa = prox_rcc_support_point(&A, n), pb = prox_rcc_support_point(&B, prox_v3_neg(n));
        B.base = prox_v3_add(B.base, prox_v3_sub(prox_v3_mad(pa, gap, n), pb));
        prox_distance_result c = prox_rcc_closed_form(&A, &B);
        double S = prox_rcc_pair_scale(&A, &B);
        assert_true(answer_valid(&A, &B, &c, "constructed rim-rim"));
        assert_int_equal(c.pair, PROX_PAIR_CC);
        assert_true(c.certified);
        assert_near(c.distance, gap, 1e-12 * S);
    }
}

/* A root-finder failure on any rim pair is an error, never an answer from a partial enumeration. */
static void test_cf_enumeric(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(0, 0, 0), prox_v3(0, 0, 4), 1};
    prox_rcc b = {prox_v3(3, 0, 1), prox_v3(0, 0, 2), 1};
    prox_poly_test_fail_qr(1);
    prox_distance_result r = prox_rcc_closed_form(&a, &b);
    prox_poly_test_fail_qr(0);
    assert_int_equal(r.status, PROX_ENUMERIC);
    assert_true(r.distance == 0.0 && r.intersect == 0 && r.certified == 0);
    r = prox_rcc_closed_form(&a, &b);
    assert_int_equal(r.status, PROX_OK);
    assert_near(r.distance, 1.0, 1e-15);
}

/* Degenerate contacts: exact distances, valid points, the flags. */
static void test_cf_degenerate(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(0, 0, 0), prox_v3(0, 0, 4), 1};
    struct {
        prox_rcc b;
        double d;
        int point_set;
        prox_pair_kind pair;
    } T[] = {
        {{prox_v3(0, 0, 5), prox_v3(0, 0, 3), 1}, 1.0, 1, PROX_PAIR_CD},       /* coaxial stacked rims */
        {{prox_v3(0, 0, 5), prox_v3(0, 0, 3), 0.5}, 1.0, 1, PROX_PAIR_CD},     /* coaxial, narrower */
        {{prox_v3(0.5, 0, 5), prox_v3(0, 0, 3), 1}, 1.0, 1, PROX_PAIR_CD},     /* parallel faces, offset */
        {{prox_v3(3, 0, 1), prox_v3(0, 0, 2), 1}, 1.0, 1, PROX_PAIR_CS},       /* parallel sides */
        {{prox_v3(3, 0, 3), prox_v3(0, 0, -2), 1}, 1.0, 1, PROX_PAIR_CS},      /* antiparallel sides */
        {{prox_v3(3, -2, 2), prox_v3(0, 4, 0), 1}, 1.0, 0, PROX_PAIR_SS},      /* perpendicular sides */
        {{prox_v3(2, 0, 2), prox_v3(4, 0, 0), 1}, 1.0, 0, PROX_PAIR_CS},       /* B's disk against A's side */
        {{prox_v3(0, 0, 6), prox_v3(0, 0, 1), 3}, 2.0, 1, PROX_PAIR_CD},       /* wider coaxial above */
        {{prox_v3(2, 0, 4), prox_v3(0, 0, 3), 1}, 0.0, 0, PROX_PAIR_OVERLAP},  /* touching rims at a point */
        {{prox_v3(2, 0, 1), prox_v3(0, 0, 2), 1}, 0.0, 0, PROX_PAIR_OVERLAP},  /* touching sides along a line */
        {{prox_v3(0, 0, 4), prox_v3(0, 0, 3), 1}, 0.0, 0, PROX_PAIR_OVERLAP},  /* faces flush */
    };
    for (size_t k = 0; k < sizeof T / sizeof T[0]; ++k) {
        for (int swap = 0; swap < 2; ++swap) {
            const prox_rcc *x = swap ? &T[k].b : &a, *y = swap ? &a : &T[k].b;
            prox_distance_result r = prox_rcc_closed_form(x, y);
            if (!answer_valid(x, y, &r, "degenerate") || !(fabs(r.distance - T[k].d) <= 1e-15 * 8) ||
                r.pair != T[k].pair || (T[k].d > 0.0 && (r.point_set != T[k].point_set || !r.certified))) {
                print_error("case %zu swap %d: d %.17g (want %g) pair %d (want %d) point_set %d certified %d\n", k,
                            swap, r.distance, T[k].d, r.pair, T[k].pair, r.point_set, r.certified);
                fail();
            }
        }
    }
}

/* Overlap: nested pairs (Agarwal Fig. 2) with the inner centre, crossing pairs with a common point, a
 * needle through a thin disk that no candidate point reaches. */
static void test_cf_overlap(void **state)
{
    (void)state;
    prox_rcc big = {prox_v3(0, 0, 0), prox_v3(0, 0, 10), 5};
    prox_rcc small = {prox_v3(1, 0.5, 2), prox_v3(0.3, 0.2, 3), 1};
    prox_distance_result r = prox_rcc_closed_form(&big, &small);
    assert_true(answer_valid(&big, &small, &r, "nested"));
    assert_true(r.intersect && r.b_in_a && !r.a_in_b);
    r = prox_rcc_closed_form(&small, &big);
    assert_true(r.intersect && r.a_in_b && !r.b_in_a);
    prox_rcc inner = {prox_v3(0, 0, 1), prox_v3(0, 0, 8), 5}; /* same radius, coaxial: inside */
    r = prox_rcc_closed_form(&inner, &big);
    assert_true(r.intersect && r.a_in_b);
    prox_rcc out = {prox_v3(3, 0, 5), prox_v3(0, 0, 1), 2 + 1e-6}; /* sticks out by 1e-6 */
    r = prox_rcc_closed_form(&out, &big);
    assert_true(answer_valid(&out, &big, &r, "crossing"));
    assert_true(r.intersect && !r.a_in_b && !r.b_in_a);
    prox_rcc needle = {prox_v3(0.3, -0.2, -5), prox_v3(1e-3, 0, 10), 1e-4};
    prox_rcc disk = {prox_v3(-3, 0, -1e-6), prox_v3(1e-6, 0, 2e-6), 4};
    r = prox_rcc_closed_form(&needle, &disk);
    assert_true(answer_valid(&needle, &disk, &r, "needle through disk"));
    assert_true(r.intersect);
}

/* Sizes at the ends of the supported range (1e-100 .. 1e100): the degree-8 polynomial of a rim 1e-100
 * the size of its distance to the other rim cannot be formed in its own frame (its coefficients would
 * overflow); the pair is then solved from the other rim, or both rims stand as points. Never
 * PROX_ENUMERIC for valid input; the distance agrees with the fast method. */
static void test_cf_extreme_scale(void **state)
{
    (void)state;
    struct {
        prox_rcc a, b;
        double d;
    } T[] = {
        {{prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1}, {prox_v3(3, 0, 0), prox_v3(0, 1e-100, 1e-100), 1e-100}, 2.0},
        {{prox_v3(0, 0, 0), prox_v3(0, 0, 1e-80), 1e-80}, {prox_v3(1e80, 0, 0), prox_v3(0, 1e80, 1e80), 1e79}, 9e79},
        {{prox_v3(0, 0, 0), prox_v3(1e-90, 0, 0), 1e-90}, {prox_v3(0, 1e90, 0), prox_v3(0, 0, 1e-90), 1e-90}, 1e90},
        {{prox_v3(5, 5, 5), prox_v3(0, 0, 1e-100), 1e-100}, {prox_v3(5, 6, 5), prox_v3(1e-100, 0, 0), 1e-100}, 1.0},
    };
    for (size_t k = 0; k < sizeof T / sizeof T[0]; ++k) {
        for (int swap = 0; swap < 2; ++swap) {
            const prox_rcc *x = swap ? &T[k].b : &T[k].a, *y = swap ? &T[k].a : &T[k].b;
            double S = prox_rcc_pair_scale(x, y);
            prox_distance_result r = prox_rcc_closed_form(x, y);
            if (!answer_valid(x, y, &r, "extreme scale") || !(fabs(r.distance - T[k].d) <= 1e-12 * S) ||
                !(fabs(r.distance - prox_rcc_distance(x, y).distance) <= 1e-12 * S) || !r.certified) {
                print_error("case %zu swap %d: status %d d %.17g (want %.17g) certified %d\n", k, swap, r.status,
                            r.distance, T[k].d, r.certified);
                fail();
            }
        }
    }
}

/* Invalid input: the validators' statuses, whichever cylinder is bad, and nothing else filled in. */
static void test_cf_bad_input(void **state)
{
    (void)state;
    prox_rcc ok = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1};
    struct {
        prox_rcc c;
        prox_status st;
    } T[] = {
        {{prox_v3(NAN, 0, 0), prox_v3(0, 0, 1), 1}, PROX_EINVAL_NONFINITE},
        {{prox_v3(0, 0, 0), prox_v3(0, INFINITY, 1), 1}, PROX_EINVAL_NONFINITE},
        {{prox_v3(0, 0, 0), prox_v3(0, 0, 1), 0}, PROX_EINVAL_RADIUS},
        {{prox_v3(0, 0, 0), prox_v3(0, 0, 1), -1}, PROX_EINVAL_RADIUS},
        {{prox_v3(0, 0, 0), prox_v3(0, 0, 0), 1}, PROX_EINVAL_AXIS},
        {{prox_v3(1e300, 0, 0), prox_v3(0, 0, 1), 1}, PROX_EINVAL_RANGE},
        {{prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1e-300}, PROX_EINVAL_RANGE},
    };
    for (size_t k = 0; k < sizeof T / sizeof T[0]; ++k) {
        prox_distance_result r = prox_rcc_closed_form(&T[k].c, &ok);
        assert_int_equal(r.status, T[k].st);
        assert_true(r.distance == 0.0 && !r.intersect && !r.certified && r.method == 0);
        assert_int_equal(prox_rcc_closed_form(&ok, &T[k].c).status, T[k].st);
    }
    assert_int_equal(prox_rcc_closed_form(NULL, &ok).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_rcc_closed_form(&ok, NULL).status, PROX_EINVAL_ARG);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cf_paper_cases),     cmocka_unit_test(test_cf_agarwal_public),
        cmocka_unit_test(test_cf_stress_public),   cmocka_unit_test(test_cf_random_agreement),
        cmocka_unit_test(test_cf_rim_rim_gsl),     cmocka_unit_test(test_cf_enumeric),
        cmocka_unit_test(test_cf_degenerate),      cmocka_unit_test(test_cf_overlap),
        cmocka_unit_test(test_cf_extreme_scale),   cmocka_unit_test(test_cf_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
