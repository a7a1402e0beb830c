/* The three cylinder-pair distance methods behind prox_rcc_distance_ex (fast, closed-form, support):
 * each on its own against the reference sets of tests/data (distance to 1e-12 S, witness points in
 * their solids and |p2 - p1| = distance, the verdict outside the touching band), the three against
 * each other on seeded random pairs none of them was tuned on, the method argument and names, and the
 * fast method's hand-over to the closed-form method when it cannot certify. The methods share only
 * the geometric core, so their agreement is an independent check of each. */
#include <stdlib.h>

#include "test_refsets.h"

#include "../bench/stress_gen.h"

static const prox_method methods[3] = {PROX_METHOD_FAST, PROX_METHOD_CLOSED_FORM, PROX_METHOD_SUPPORT};

/* Allowed absolute error of a pair: 1e-12 S plus the rounding the input doubles carry. */
static double pair_tol(const prox_rcc *a, const prox_rcc *b)
{
    return 1e-12 * sg_pair_scale(a, b) + 8.0 * sg_input_ulp(a, b);
}

/* The witnesses of r: p1 in A and p2 in B (long-double point distance, independent of the library),
 * |p2 - p1| = distance, a common point when intersecting. Returns the worst violation, absolute. */
static double witness_err(const prox_rcc *a, const prox_rcc *b, const prox_distance_result *r)
{
    double in1 = (double)sg_point_rcc(a, r->p1), in2 = (double)sg_point_rcc(b, r->p2);
    double e = fmax(fmax(in1, in2), 0.0);
    e = fmax(e, fabs(prox_v3_dist(r->p1, r->p2) - r->distance));
    if (r->intersect) e = fmax(e, fmax(r->distance, prox_v3_dist(r->p1, r->p2)));
    return e;
}

/* One method on one reference set: every pair within the bar. Returns the number of failures. */
static int check_set(const char *name, prox_method m)
{
    double *P, *R;
    size_t n = load_set(name, &P, &R);
    int bad = 0, handed = 0, unproved = 0;
    double worst_d = 0.0, worst_w = 0.0;
    for (size_t i = 0; i < n; ++i) {
        prox_rcc a = rcc_of(P + 14 * i), b = rcc_of(P + 14 * i + 7);
        double sd = R[7 * i], S = sg_pair_scale(&a, &b), tol = pair_tol(&a, &b);
        prox_distance_result r = prox_rcc_distance_ex(&a, &b, m);
        if (r.status != PROX_OK) {
            if (bad++ < 5) print_error("%s %s pair %zu: status %d\n", prox_method_name(m), name, i, r.status);
            continue;
        }
        handed += r.method != m;
        unproved += !r.certified;
        double derr = fabs(r.distance - fmax(sd, 0.0)), werr = witness_err(&a, &b, &r);
        /* output coordinates are rounded doubles: their rounding is allowed (pairs far from the origin) */
        double ptol = tol + 4.0 * 0x1p-52 * fmax(prox_v3_maxabs(r.p1), prox_v3_maxabs(r.p2));
        int verdict_ok = fabs(sd) <= tol || (r.intersect != 0) == (sd <= 0.0);
        worst_d = fmax(worst_d, derr / S);
        worst_w = fmax(worst_w, werr / S);
        if ((!(derr <= tol) || !(werr <= ptol) || !verdict_ok) && bad++ < 5)
            print_error("%s %s pair %zu: d %.17g ref %.17g (err %.3g S), witness err %.3g S, intersect %d\n",
                        prox_method_name(m), name, i, r.distance, sd, derr / S, werr / S, r.intersect);
    }
    printf("# %-11s %-14s %4zu pairs: worst |d - ref| %.3g S, worst witness %.3g S, failures %d "
           "(answered by another method %d, not certified %d)\n",
           prox_method_name(m), name, n, worst_d, worst_w, bad, handed, unproved);
    free(P);
    free(R);
    return bad;
}

static void test_methods_reference_sets(void **state)
{
    (void)state;
    static const char *const sets[3] = {"paper_cases", "agarwal_public", "stress_public"};
    int bad = 0;
    for (int k = 0; k < 3; ++k)
        for (int s = 0; s < 3; ++s) bad += check_set(sets[s], methods[k]);
    assert_int_equal(bad, 0);
}

/* A pair of Agarwal's protocol A (A fixed, r = 2, h = 5; B's centre within 25, radius up to 20,
 * height up to 50, random axis), or one of the stress generator's near-degenerate families. */
static sg_pair random_pair(sg_rng *r, int i)
{
    if (i % 2) return sg_make(r, (i / 2) % SG_NFAMILIES);
    sg_pair p;
    p.a = (prox_rcc){prox_v3(0, 0, 0), prox_v3(0, 0, 5), 2};
    prox_vec3 o;
    do {
        o = prox_v3(50 * sg_u(r) - 25, 50 * sg_u(r) - 25, 50 * sg_u(r) - 25);
    } while (prox_v3_norm(o) > 25);
    double rb = 20 * (1 - sg_u(r)), hb = 50 * (1 - sg_u(r));
    p.b = (prox_rcc){o, prox_v3_scale(sg_unit(r), hb), rb};
    p.d_ref = NAN;
    return p;
}

/* The three methods agree pairwise on seeded pairs outside the reference sets: status, distance to
 * the bar, the verdict outside the touching band; each answer's witnesses are checked too. */
static void test_methods_agree_random(void **state)
{
    (void)state;
    sg_rng rng = sg_seed(5150);
    const int n = 1000;
    int bad = 0, fallbacks = 0, intersecting = 0;
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
        sg_pair p = random_pair(&rng, i);
        double tol = pair_tol(&p.a, &p.b), S = sg_pair_scale(&p.a, &p.b);
        prox_distance_result r[3];
        for (int k = 0; k < 3; ++k) {
            r[k] = prox_rcc_distance_ex(&p.a, &p.b, methods[k]);
            assert_int_equal(r[k].status, PROX_OK);
            double ptol = tol + 4.0 * 0x1p-52 * fmax(prox_v3_maxabs(r[k].p1), prox_v3_maxabs(r[k].p2));
            double we = witness_err(&p.a, &p.b, &r[k]);
            if (!(we <= ptol) && bad++ < 5)
                print_error("pair %d, %s: witness error %.3g S\n", i, prox_method_name(methods[k]), we / S);
        }
        fallbacks += r[0].method == PROX_METHOD_CLOSED_FORM;
        intersecting += r[1].intersect;
        for (int k = 0; k < 3; ++k) {
            const prox_distance_result *x = &r[k], *y = &r[(k + 1) % 3];
            double diff = fabs(x->distance - y->distance);
            worst = fmax(worst, diff / S);
            int verdict_ok = x->intersect == y->intersect || fmax(x->distance, y->distance) <= tol;
            if ((!(diff <= tol) || !verdict_ok) && bad++ < 8)
                print_error("pair %d: %s d %.17g (intersect %d), %s d %.17g (intersect %d), constructed %.17g\n",
                            i, prox_method_name(methods[k]), x->distance, x->intersect,
                            prox_method_name(methods[(k + 1) % 3]), y->distance, y->intersect, p.d_ref);
        }
    }
    printf("# %d random pairs (%d intersecting): worst pairwise difference %.3g S, failures %d; "
           "the fast method handed %d to the closed form\n",
           n, intersecting, worst, bad, fallbacks);
    assert_true(intersecting > n / 10 && intersecting < n - n / 10); /* both verdicts exercised */
    assert_int_equal(bad, 0);
}

/* Every answer of each method says which method produced it, and whether it is proved. */
static void test_methods_result_fields(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(0, 0, 0), prox_v3(0, 0, 5), 2};
    prox_rcc b = {prox_v3(7, 0, 1), prox_v3(0, 3, 0), 1};       /* disjoint, Case 1: distance 4 */
    prox_rcc c = {prox_v3(0.5, 0, 1), prox_v3(0, 0, 2), 0.5};   /* nested in a */
    for (int k = 0; k < 3; ++k) {
        prox_distance_result r = prox_rcc_distance_ex(&a, &b, methods[k]);
        assert_int_equal(r.status, PROX_OK);
        assert_near(r.distance, 4.0, 1e-12 * 8.0);
        assert_int_equal(r.method, methods[k]);
        if (methods[k] != PROX_METHOD_SUPPORT) assert_true(r.certified); /* disjoint, certificate holds */
        prox_distance_result s = prox_rcc_distance_ex(&a, &c, methods[k]);
        assert_int_equal(s.status, PROX_OK);
        assert_true(s.intersect);
        assert_int_equal(s.method, methods[k]);
    }
    /* the default method proves what it answers, and reports the nesting */
    prox_distance_result f = prox_rcc_distance(&c, &a);
    assert_true(f.certified && f.a_in_b && !f.b_in_a);
    assert_int_equal(f.method, PROX_METHOD_FAST);
}

static void test_methods_invalid(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(0, 0, 0), prox_v3(0, 0, 5), 2}, b = {prox_v3(7, 0, 1), prox_v3(0, 3, 0), 1};
    prox_method bad[3] = {PROX_METHOD_COUNT_, (prox_method)-1, (prox_method)1000};
    for (int i = 0; i < 3; ++i) {
        prox_distance_result r = prox_rcc_distance_ex(&a, &b, bad[i]);
        assert_int_equal(r.status, PROX_EINVAL_ARG);
        assert_true(r.distance == 0.0 && !r.intersect);
        assert_null(prox_method_name(bad[i]));
    }
    /* each method validates its input */
    prox_rcc z = {prox_v3(0, 0, 0), prox_v3(0, 0, 0), 1};
    for (int k = 0; k < 3; ++k) {
        assert_int_equal(prox_rcc_distance_ex(&a, &z, methods[k]).status, PROX_EINVAL_AXIS);
        assert_int_equal(prox_rcc_distance_ex(NULL, &b, methods[k]).status, PROX_EINVAL_ARG);
    }
}

static void test_methods_names(void **state)
{
    (void)state;
    static const char *const names[3] = {"fast", "closed-form", "support"};
    for (int k = 0; k < 3; ++k) {
        assert_string_equal(prox_method_name(methods[k]), names[k]);
        prox_method m = PROX_METHOD_COUNT_;
        assert_true(prox_method_parse(prox_method_name(methods[k]), &m));
        assert_int_equal(m, methods[k]);
    }
    prox_method m = PROX_METHOD_SUPPORT;
    assert_false(prox_method_parse("Fast", &m)); /* exact names only; *m untouched */
    assert_false(prox_method_parse("", &m));
    assert_false(prox_method_parse("closed_form", &m));
    assert_false(prox_method_parse(NULL, &m));
    assert_false(prox_method_parse("fast", NULL));
    assert_int_equal(m, PROX_METHOD_SUPPORT);
}

/* When the fast method cannot certify its best candidate (a lateral contact of nearly parallel axes
 * a few 1e-12 S apart, below the certificate's resolution along the poor S-S normal), it hands the
 * pair to the closed-form method: the answer then says method = CLOSED_FORM and is the closed-form
 * method's own. The first pair is one such; the sweep checks every hand-over of a stress family. */
static void test_methods_fast_fallback(void **state)
{
    (void)state;
    const prox_rcc a = {prox_v3(5.0259781492509088, 0.57609888758057037, 0.52442663650374044),
                        prox_v3(-1.877513110865848, 0.30280271551534366, 2.8722858752882989), 3.1911960996787445};
    const prox_rcc b = {prox_v3(-1.1201540764421671, 0.87912314043325779, 1.7808646856234627),
                        prox_v3(0.53370665337100753, -0.086075470031877765, -0.8164832903217849), 1.2667380241863011};
    prox_distance_result f = prox_rcc_distance(&a, &b), c = prox_rcc_distance_ex(&a, &b, PROX_METHOD_CLOSED_FORM);
    assert_int_equal(f.status, PROX_OK);
    assert_int_equal(f.method, PROX_METHOD_CLOSED_FORM);
    assert_true(f.distance == c.distance && f.intersect == c.intersect);
    prox_distance_result s = prox_rcc_distance_ex(&a, &b, PROX_METHOD_SUPPORT);
    assert_near(f.distance, s.distance, pair_tol(&a, &b));

    sg_rng rng = sg_seed(99);
    int handed = 0, bad = 0;
    for (int i = 0; i < 600; ++i) {
        sg_pair p = sg_make(&rng, 6); /* parallel-side */
        prox_distance_result x = prox_rcc_distance(&p.a, &p.b);
        assert_int_equal(x.status, PROX_OK);
        if (fabs(x.distance - fmax(p.d_ref, 0.0)) > pair_tol(&p.a, &p.b) && bad++ < 5)
            print_error("parallel-side pair %d: d %.17g constructed %.17g\n", i, x.distance, p.d_ref);
        if (x.method == PROX_METHOD_FAST) {
            if (!x.certified && bad++ < 5) print_error("parallel-side pair %d: fast answer not certified\n", i);
            continue;
        }
        ++handed;
        prox_distance_result y = prox_rcc_distance_ex(&p.a, &p.b, PROX_METHOD_CLOSED_FORM);
        if (!(x.method == PROX_METHOD_CLOSED_FORM && x.distance == y.distance && x.intersect == y.intersect) &&
            bad++ < 5)
            print_error("parallel-side pair %d: handed over, method %d, d %.17g vs closed form %.17g\n", i,
                        x.method, x.distance, y.distance);
    }
    printf("# 600 parallel-side pairs: %d handed to the closed form, failures %d\n", handed, bad);
    assert_true(handed > 0);
    assert_int_equal(bad, 0);
}

int main(void)
{
    test_init();
    assert_string_equal(sg_family_names[6], "parallel-side");
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_methods_reference_sets), cmocka_unit_test(test_methods_agree_random),
        cmocka_unit_test(test_methods_result_fields),  cmocka_unit_test(test_methods_invalid),
        cmocka_unit_test(test_methods_names),          cmocka_unit_test(test_methods_fast_fallback),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
