/* Large seeded sweeps of the RCC-RCC distance against independent truths: the stress generator's
 * constructed exact distances (bench/stress_gen.h: a separating slab between support points) over
 * all its families, the certified separating-axis verdict (src/sat) on Agarwal's protocol, and the
 * containment flags against a brute-force maximisation.
 * Rare failures (1 in 1e4 pairs) were found only at this size: keep it large. */
#include "test_brute.h"
#include "prox/sat.h"
#include "prox/support.h"
#include "../bench/stress_gen.h"

static void test_rcc_random_constructed(void **state)
{
    (void)state;
    sg_rng r = sg_seed(20261122);
    const int n = 260000;
    int bad = 0;
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
        int fam = i % SG_NFAMILIES;
        sg_pair p = sg_make(&r, fam);
        prox_distance_result d = prox_rcc_distance(&p.a, &p.b);
        assert_int_equal(d.status, PROX_OK);
        double S = sg_pair_scale(&p.a, &p.b);
        double tol = 1e-12 * S + 8.0 * sg_input_ulp(&p.a, &p.b);
        double err = fabs(d.distance - (p.d_ref > 0.0 ? p.d_ref : 0.0));
        if (err / tol > worst) worst = err / tol;
        if (err > tol && bad++ < 5)
            print_error("family %s: d %.17g constructed %.17g (err %.3g S)\n", sg_family_names[fam], d.distance,
                        p.d_ref, err / S);
    }
    printf("# %d constructed pairs, worst error / tolerance %.3g, failures %d\n", n, worst, bad);
    assert_int_equal(bad, 0);
}

static void test_rcc_random_verdict(void **state)
{
    (void)state;
    sg_rng r = sg_seed(7);
    const int n = 100000;
    int bad = 0;
    for (int i = 0; i < n; ++i) {
        prox_rcc a = {prox_v3(0, 0, 0), prox_v3(0, 0, 5), 2};
        prox_vec3 o;
        do {
            o = prox_v3(50 * sg_u(&r) - 25, 50 * sg_u(&r) - 25, 50 * sg_u(&r) - 25);
        } while (prox_v3_norm(o) > 25);
        double rb = 20 * (1 - sg_u(&r)), hb = 50 * (1 - sg_u(&r));
        prox_rcc b = {o, prox_v3_scale(sg_unit(&r), hb), rb};
        prox_distance_result d = prox_rcc_distance(&a, &b);
        prox_test_result v = prox_rcc_sat(&a, &b);
        double S = prox_rcc_pair_scale(&a, &b);
        if ((d.distance == 0.0) != (v.intersect != 0) && d.distance > 1e-12 * S) ++bad;
    }
    printf("# %d protocol-A pairs, verdict mismatches %d\n", n, bad);
    assert_int_equal(bad, 0);
}

/* Brute-force containment of circle (c, n, r) in the solid cylinder k: the axial range is exact
 * (t_c +- r |n x w|); the largest distance from k's axis by tb_circle_line_max_dist (samples refined
 * by golden sections, test_brute.h).  *margin is how far the decision is from flipping (min over both tests). */
static int circle_inside_brute(prox_vec3 c, prox_vec3 n, double r, const prox_rcc *k, double *margin)
{
    double h = prox_v3_norm(k->axis);
    prox_vec3 w = prox_v3_scale(k->axis, 1.0 / h);
    double tc = prox_v3_dot(prox_v3_sub(c, k->base), w), half = r * prox_v3_norm(prox_v3_cross(n, w));
    double ax = fmin(tc - half, h - (tc + half)); /* >= 0 inside */
    double rmax = (double)tb_circle_line_max_dist(c, n, r, k->base, w);
    double rad = k->radius - rmax;
    *margin = fmin(fabs(ax), fabs(rad));
    return ax >= 0.0 && rad >= 0.0;
}

/* A inside B iff both rims of A are (B convex, A the hull of its rims). */
static int rcc_inside_brute(const prox_rcc *a, const prox_rcc *b, double *margin)
{
    prox_vec3 n = prox_v3_normalize(a->axis);
    double m0, m1;
    int in0 = circle_inside_brute(a->base, n, a->radius, b, &m0);
    int in1 = circle_inside_brute(prox_v3_add(a->base, a->axis), n, a->radius, b, &m1);
    /* the margin that matters: the failing test's, or both when inside */
    *margin = in0 && in1 ? fmin(m0, m1) : (!in0 && !in1 ? fmax(m0, m1) : (!in0 ? m0 : m1));
    return in0 && in1;
}

/* Nesting flags checked against the brute force: pairs decided (brute-force margin above 1e-9 S),
 * of which nested, and mismatches. */
typedef struct nest_tally {
    int decided, inside, bad;
} nest_tally;

/* prox's nesting flags of (small, big), in both argument orders, against rcc_inside_brute where its
 * margin exceeds 1e-9 S; returns prox's result for (small, big) and, in *rev, for (big, small). */
static prox_distance_result check_nesting(int i, const prox_rcc *small, const prox_rcc *big, nest_tally *t,
                                     prox_distance_result *rev)
{
    double S = prox_rcc_pair_scale(small, big), m_ab, m_ba;
    int ab = rcc_inside_brute(small, big, &m_ab), ba = rcc_inside_brute(big, small, &m_ba);
    prox_distance_result d1 = prox_rcc_distance(small, big), d2 = prox_rcc_distance(big, small);
    assert_int_equal(d1.status, PROX_OK);
    assert_int_equal(d2.status, PROX_OK);
    if (m_ab > 1e-9 * S) {
        ++t->decided;
        t->inside += ab;
        if ((d1.a_in_b != ab || d2.b_in_a != ab) && t->bad++ < 5)
            print_error("pair %d: A in B brute %d, prox %d / %d (margin %.3g S)\n", i, ab, d1.a_in_b,
                        d2.b_in_a, m_ab / S);
    }
    if (m_ba > 1e-9 * S && (d1.b_in_a != ba || d2.a_in_b != ba) && t->bad++ < 5)
        print_error("pair %d: B in A brute %d, prox %d / %d\n", i, ba, d1.b_in_a, d2.a_in_b);
    *rev = d2;
    return d1;
}

/* Containment flags against the brute force, on a small cylinder placed where it is partly in, partly
 * out of a large one (centres inside, random tilts and sizes): both outcomes are common there. */
static void test_rcc_random_containment(void **state)
{
    (void)state;
    sg_rng r = sg_seed(1122);
    const int n = 4000;
    nest_tally t = {0, 0, 0};
    for (int i = 0; i < n; ++i) {
        double rb = 1.0 + 4.0 * sg_u(&r), hb = 2.0 + 8.0 * sg_u(&r);
        prox_rcc big = {prox_v3(0, 0, 0), prox_v3_scale(sg_unit(&r), hb), rb};
        double hb_ = prox_v3_norm(big.axis);
        prox_vec3 w = prox_v3_scale(big.axis, 1.0 / hb_);
        double ra = rb * (0.05 + 0.6 * sg_u(&r)), ha = hb * (0.05 + 0.6 * sg_u(&r));
        prox_vec3 ca = prox_v3_add(prox_v3_scale(w, hb * sg_u(&r)), prox_v3_scale(sg_perp(&r, w), rb * sg_u(&r)));
        prox_vec3 wa = sg_u(&r) < 0.3 ? sg_tilt(&r, w, sg_log(&r, 1e-6, 0.3)) : sg_unit(&r);
        prox_rcc small = {prox_v3_mad(ca, -0.5 * ha, wa), prox_v3_scale(wa, ha), ra};
        prox_distance_result d2, d1 = check_nesting(i, &small, &big, &t, &d2);
        if (d1.a_in_b) assert_true(d1.intersect && d1.distance == 0.0);
    }
    printf("# %d containment pairs, %d decided by the brute force (%d inside), mismatches %d\n", n,
           t.decided, t.inside, t.bad);
    assert_true(t.inside > t.decided / 10 && t.inside < t.decided - t.decided / 10); /* both outcomes */
    assert_int_equal(t.bad, 0);
}

/* A cylinder (axis wa, height ha, radius ra) whose axis crosses the common normal of its axis and
 * big's (unit axis w) at its fraction s / ha, L from big's axis at big's axial coordinate t: an
 * overlapping Case-1 pair with big when 0 <= t <= |big axis|, 0 <= s <= ha and L < the radii's sum. */
static prox_rcc case1_partner(const prox_rcc *big, prox_vec3 w, prox_vec3 wa, double t, double s,
                              double L, double ha, double ra)
{
    prox_vec3 nrm = prox_v3_normalize(prox_v3_cross(wa, w));
    prox_vec3 foot = prox_v3_mad(prox_v3_mad(big->base, t, w), L, nrm);
    return (prox_rcc){prox_v3_mad(foot, -s, wa), prox_v3_scale(wa, ha), ra};
}

/* Nesting flags of overlapping Case-1 pairs (the feet of the common perpendicular on both axes, the
 * pairs that end earliest) against the brute force.  The small cylinder's foot is put less than rb
 * from the big one's along the common normal, so its rims straddle the big cylinder's side as often
 * as they sit inside; the radii and tilts span the band where the quick bounds leave the decision to
 * the exact test.  Both argument orders. */
static void test_rcc_case1_nesting(void **state)
{
    (void)state;
    sg_rng r = sg_seed(2211);
    const int n = 5000;
    nest_tally tally = {0, 0, 0};
    int case1 = 0;
    for (int i = 0; i < n; ++i) {
        double rb = sg_log(&r, 0.1, 10.0), hb = sg_log(&r, 0.1, 10.0);
        prox_vec3 w = sg_unit(&r);
        prox_vec3 wa = sg_u(&r) < 0.2 ? sg_tilt(&r, w, sg_log(&r, 2e-3, 0.2)) : sg_unit(&r);
        double ra = rb * sg_log(&r, 0.02, 1.2), ha = hb * sg_log(&r, 0.02, 1.2);
        double t = hb * sg_u(&r), s = ha * sg_u(&r), L = rb * sg_u(&r);
        prox_rcc big = {prox_v3_scale(sg_unit(&r), 10.0 * sg_u(&r)), prox_v3_scale(w, hb), rb};
        prox_rcc small = case1_partner(&big, w, wa, t, s, L, ha, ra);
        prox_distance_result d2, d1 = check_nesting(i, &small, &big, &tally, &d2);
        assert_true(d1.intersect && d2.intersect && d1.distance == 0.0 && d2.distance == 0.0);
        case1 += d1.agarwal == PROX_CASE_1;
    }
    printf("# %d overlapping Case-1 constructions (%d classified Case 1), %d decided by the brute "
           "force (%d inside), mismatches %d\n",
           n, case1, tally.decided, tally.inside, tally.bad);
    assert_true(case1 > n * 9 / 10);
    int outcomes = tally.inside > tally.decided / 10 && tally.inside < tally.decided - tally.decided / 10;
    assert_true(outcomes); /* both outcomes exercised */
    assert_int_equal(tally.bad, 0);
}

/* Nesting flags of overlapping Case-1 pairs right at the radial boundary: the big cylinder's radius
 * is set to the small one's farthest rim distance from its axis (long double) times 1 +- delta,
 * delta log-uniform in [1e-8, 1e-2], with room to spare axially, so the answer flips with the sign
 * and the decision falls in or near the band between the quick accept and reject bounds of the
 * containment test, where only the exact farthest point decides. */
static void test_rcc_case1_nesting_boundary(void **state)
{
    (void)state;
    sg_rng r = sg_seed(4477);
    const int n = 4000;
    nest_tally tally = {0, 0, 0};
    int case1 = 0;
    for (int i = 0; i < n; ++i) {
        double ha = sg_log(&r, 0.1, 10.0), ra = ha * sg_log(&r, 0.05, 5.0);
        prox_vec3 w = sg_unit(&r);
        prox_vec3 wa = sg_u(&r) < 0.3 ? sg_tilt(&r, w, sg_log(&r, 2e-3, 0.3)) : sg_unit(&r);
        double hb = 4.0 * (ha + 2.0 * ra) * (1.0 + sg_u(&r)), t = hb * (0.4 + 0.2 * sg_u(&r));
        double s = ha * sg_u(&r), L = ra * sg_u(&r);
        prox_rcc big = {prox_v3_scale(sg_unit(&r), 10.0 * sg_u(&r)), prox_v3_scale(w, hb), 1.0};
        prox_rcc small = case1_partner(&big, w, wa, t, s, L, ha, ra);
        long double m0 = tb_circle_line_max_dist(small.base, wa, ra, big.base, w);
        long double m1 = tb_circle_line_max_dist(prox_v3_add(small.base, small.axis), wa, ra, big.base, w);
        double delta = sg_log(&r, 1e-8, 1e-2) * (sg_u(&r) < 0.5 ? -1.0 : 1.0);
        big.radius = (double)((m0 > m1 ? m0 : m1) * (1.0L + delta));
        prox_distance_result d2, d1 = check_nesting(i, &small, &big, &tally, &d2);
        assert_true(d1.intersect && d2.intersect);
        case1 += d1.agarwal == PROX_CASE_1 && d2.agarwal == PROX_CASE_1;
    }
    printf("# %d Case-1 pairs at the nesting boundary (%d classified Case 1), %d decided by the brute "
           "force (%d inside), mismatches %d\n",
           n, case1, tally.decided, tally.inside, tally.bad);
    assert_int_equal(case1, n);
    assert_true(tally.decided > n * 9 / 10);
    assert_true(tally.inside > tally.decided / 3 && tally.inside < tally.decided - tally.decided / 3);
    assert_int_equal(tally.bad, 0);
}

/* Case-1 pairs (nested, overlapping, disjoint) scaled by 2^-120 and 2^120, exact binary scalings
 * that take squared lengths and products of them far outside the range of doubles: distance, points
 * and nesting flags must scale exactly with the pair. */
static void test_rcc_case1_extreme_scale(void **state)
{
    (void)state;
    sg_rng r = sg_seed(977);
    int bad = 0;
    const double scales[2] = {0x1p-120, 0x1p120};
    for (int i = 0; i < 2000; ++i) {
        double rb = sg_log(&r, 0.1, 10.0), hb = sg_log(&r, 0.1, 10.0);
        prox_vec3 w = sg_unit(&r), wa = sg_unit(&r);
        double ra = rb * sg_log(&r, 0.02, 1.2), ha = hb * sg_log(&r, 0.02, 1.2);
        double t = hb * sg_u(&r), s = ha * sg_u(&r);
        double L = (rb + ra) * 1.5 * sg_u(&r); /* a third disjoint */
        prox_rcc b = {prox_v3_scale(sg_unit(&r), 10.0 * sg_u(&r)), prox_v3_scale(w, hb), rb};
        prox_rcc a = case1_partner(&b, w, wa, t, s, L, ha, ra);
        prox_distance_result d = prox_rcc_distance(&a, &b);
        for (int k = 0; k < 2; ++k) {
            double f = scales[k];
            prox_rcc as = sg_scale(a, f);
            prox_rcc bs = sg_scale(b, f);
            prox_distance_result e = prox_rcc_distance(&as, &bs);
            double S = prox_rcc_pair_scale(&a, &b);
            int ok = e.status == PROX_OK && fabs(e.distance / f - d.distance) <= 1e-12 * S &&
                     e.intersect == d.intersect && e.a_in_b == d.a_in_b && e.b_in_a == d.b_in_a;
            if (ok && d.distance > 0.0)
                ok = prox_v3_dist(prox_v3_scale(e.p1, 1.0 / f), d.p1) <= 1e-12 * S &&
                     prox_v3_dist(prox_v3_scale(e.p2, 1.0 / f), d.p2) <= 1e-12 * S;
            if (!ok && bad++ < 5)
                print_error("pair %d scale %g: d %.17g -> %.17g, flags %d%d%d -> %d%d%d\n", i, f,
                            d.distance, e.distance / f, d.intersect, d.a_in_b, d.b_in_a,
                            e.intersect, e.a_in_b, e.b_in_a);
        }
    }
    assert_int_equal(bad, 0);
}

/* Case-1 pairs where the common perpendicular is short and the bases far apart (a small cylinder
 * beside a long one), against the independent support method to 1e-12 S, and against the pair
 * scaled by 2^-80.  An S-S normal taken from alternating rejections, whose residual along B's axis
 * is multiplied by |(bB - bA).wB|, puts the distance up to 1.2e-11 S off, too far or too near (114 of
 * these 20000 pairs); the first pair below is one from a broader draw, with its distance from a
 * 40-digit evaluation. */
static void test_rcc_case1_short_perpendicular(void **state)
{
    (void)state;
    const double f = 0x1p-80;
    const prox_rcc a0 = {prox_v3(-211.63087875421701, 38.10168802029176, -2.1881900526133413),
                         prox_v3(0.0019564173377379008, 0.0022268015435515471, 0.00041154130474214257),
                         0.0015693143744573345};
    const prox_rcc b0 = {prox_v3(5.719400264752875, -5.2312468099571454, -0.29317120783543998),
                         prox_v3(-227.13003164415474, 45.285832779171649, -1.9833439766186418),
                         0.0010691091868932758};
    prox_rcc as = sg_scale(a0, f);
    prox_rcc bs = sg_scale(b0, f);
    double S0 = prox_rcc_pair_scale(&a0, &b0);
    assert_near(prox_rcc_distance(&as, &bs).distance / f, 0.00069747178450311992, 1e-12 * S0);
    assert_near(prox_rcc_distance(&a0, &b0).distance, 0.00069747178450311992, 1e-12 * S0);
    sg_rng r = sg_seed(6161);
    int bad = 0, n = 20000;
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
        double ra = sg_log(&r, 1e-3, 1.0), ha = sg_log(&r, 1e-3, 1.0);
        double rb = sg_log(&r, 1e-3, 1.0), hb = sg_log(&r, 10.0, 1e3);
        prox_vec3 w = sg_unit(&r), wa = sg_unit(&r);
        double t = hb * sg_u(&r), s = ha * sg_u(&r), L = (ra + rb) * (1.0 + sg_log(&r, 1e-6, 1.0));
        prox_rcc b = {prox_v3_scale(sg_unit(&r), 10.0 * sg_u(&r)), prox_v3_scale(w, hb), rb};
        prox_rcc a = case1_partner(&b, w, wa, t, s, L, ha, ra);
        prox_distance_result d = prox_rcc_distance(&a, &b);
        prox_rcc a2 = sg_scale(a, f);
        prox_rcc b2 = sg_scale(b, f);
        prox_distance_result e = prox_rcc_distance(&a2, &b2);
        prox_distance_result g = prox_rcc_distance_ex(&a, &b, PROX_METHOD_SUPPORT);
        double S = prox_rcc_pair_scale(&a, &b);
        double err = fmax(fabs(e.distance / f - d.distance), fabs(g.distance - d.distance)) / S;
        worst = err > worst ? err : worst;
        if (!(err <= 1e-12) && bad++ < 5)
            print_error("pair %d: %.17g, scaled %.17g, support method %.17g (%.3g S)\n", i, d.distance,
                        e.distance / f, g.distance, err);
    }
    printf("# %d short-perpendicular Case-1 pairs against the support method and the scaled pair: worst "
           "%.3g S, failures %d\n",
           n, worst, bad);
    assert_int_equal(bad, 0);
}

/* Extreme aspect ratios (radii and heights log-uniform over 1e-3 .. 1e3, the base of B up to 1e3
 * times A's size away): the verdict agrees with the certified SAT, disjoint distances with the
 * independent support-function method to 1e-12 S, and overlap witnesses lie in both solids. Guards the
 * common-point search on intersections too thin for projections to enter quickly (needles through
 * pancakes, crossing pancakes: 4 in these 1e5 pairs). */
static void test_rcc_random_extreme_aspect(void **state)
{
    (void)state;
    sg_rng r = sg_seed(31337);
    const int n = 100000;
    int verdict_bad = 0, witness_bad = 0, dist_bad = 0;
    for (int i = 0; i < n; ++i) {
        prox_rcc a = {prox_v3(0, 0, 0), prox_v3_scale(sg_unit(&r), sg_log(&r, 1e-3, 1e3)), sg_log(&r, 1e-3, 1e3)};
        double sa = fmax(prox_v3_norm(a.axis), a.radius);
        prox_rcc b = {prox_v3_scale(sg_unit(&r), sg_log(&r, 1e-3, 1e3) * sa), prox_v3_scale(sg_unit(&r), sg_log(&r, 1e-3, 1e3)),
                      sg_log(&r, 1e-3, 1e3)};
        prox_distance_result d = prox_rcc_distance(&a, &b);
        prox_test_result v = prox_rcc_sat(&a, &b);
        assert_int_equal(d.status, PROX_OK);
        assert_int_equal(v.status, PROX_OK);
        double S = prox_rcc_pair_scale(&a, &b);
        if ((d.distance == 0.0) != (v.intersect != 0) && d.distance > 1e-12 * S && verdict_bad++ < 5)
            print_error("pair %d: distance %.17g, SAT intersect %d\n", i, d.distance, v.intersect);
        if (d.distance == 0.0) {
            long double e1 = sg_point_rcc(&a, d.p1), e2 = sg_point_rcc(&b, d.p1);
            if ((e1 > 1e-12 * S || e2 > 1e-12 * S) && witness_bad++ < 5)
                print_error("pair %d: overlap witness outside by %Lg, %Lg\n", i, e1, e2);
        } else { /* every disjoint pair, to 1e-12 S (sweeps of 1.3e6 pairs: worst 1.1e-15 S) */
            prox_shape A = prox_shape_from_rcc(a), B = prox_shape_from_rcc(b);
            prox_signed_result s = prox_shape_signed_distance_support(&A, &B);
            if (!(fabs(s.sd - d.distance) <= 1e-12 * S) && dist_bad++ < 5)
                print_error("pair %d: distance %.17g, support method %.17g\n", i, d.distance, s.sd);
        }
    }
    printf("# %d extreme-aspect pairs: verdict mismatches %d, witnesses outside %d, distance disagreements %d\n", n,
           verdict_bad, witness_bad, dist_bad);
    assert_int_equal(verdict_bad, 0);
    assert_int_equal(witness_bad, 0);
    assert_int_equal(dist_bad, 0);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rcc_random_constructed),
        cmocka_unit_test(test_rcc_random_verdict),
        cmocka_unit_test(test_rcc_random_containment),
        cmocka_unit_test(test_rcc_case1_nesting),
        cmocka_unit_test(test_rcc_case1_nesting_boundary),
        cmocka_unit_test(test_rcc_case1_extreme_scale),
        cmocka_unit_test(test_rcc_case1_short_perpendicular),
        cmocka_unit_test(test_rcc_random_extreme_aspect),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
