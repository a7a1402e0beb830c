/* Tests of prox_rcc_distance_support, the support method (PROX_METHOD_SUPPORT) alone: on the reference
 * sets of tests/data (paper_cases, agarwal_public, stress_public) every disjoint pair must have its
 * distance within 1e-12 S of the reference, witness points p1 in A and p2 in B (within 1e-12 S) with
 * |p2 - p1| = distance, and a certificate; every overlapping pair a common point of both solids.
 * Also: symmetry, containment flags against hand-made nesting, parallel contacts whose support sets
 * are faces or segments (the witnesses must come from the exact closest pair of those sets, not their
 * centres), and invalid input. */
#include "test_refsets.h"

#include <stdlib.h>

#include "prox/distance.h"
#include "prox/sat.h"
#include "sat/sat_internal.h"

/* Checks one answer against the reference signed distance sd; returns 1 when it fails (printed). */
static int check_answer(const char *name, size_t i, const prox_rcc *a, const prox_rcc *b, const prox_distance_result *r,
                        double sd)
{
    double S = prox_rcc_pair_scale(a, b), tol = 1e-12 * S;
    /* output coordinates are rounded doubles: allow their rounding (pairs far from the origin) */
    double big = fmax(prox_v3_maxabs(r->p1), prox_v3_maxabs(r->p2));
    double ptol = tol + 4.0 * big * 0x1p-52;
    int bad = 0;
    if (r->status != PROX_OK || r->method != PROX_METHOD_SUPPORT) {
        print_error("%s pair %zu: status %d method %d\n", name, i, r->status, r->method);
        return 1;
    }
    double e1 = cyl_sdf(a, r->p1), e2 = cyl_sdf(b, r->p2);
    if (r->intersect) {
        if (sd > tol) bad = 1; /* outside the touching band the verdict must be exact */
        if (r->distance != 0.0 || prox_v3_dist(r->p1, r->p2) != 0.0) bad = 1;
        if (!(e1 <= ptol && cyl_sdf(b, r->p1) <= ptol) || !r->certified) bad = 1;
        if (bad)
            print_error("%s pair %zu: overlap answer, ref sd %.17g, common point off A %.3g off B %.3g S, cert %d\n",
                        name, i, sd, e1 / S, cyl_sdf(b, r->p1) / S, r->certified);
        return bad;
    }
    double derr = fabs(r->distance - fmax(sd, 0.0));
    double pe = fabs(prox_v3_dist(r->p1, r->p2) - r->distance);
    if (sd < -tol || derr > tol || pe > ptol || e1 > ptol || e2 > ptol || !r->certified ||
        r->certificate_gap > r->distance + ptol || r->distance - r->certificate_gap > tol)
        bad = 1;
    if (bad)
        print_error("%s pair %zu: d %.17g ref %.17g err %.3g S, |p2-p1|-d %.3g S, p1 off A %.3g S, p2 off B %.3g S, "
                    "gap %.17g cert %d\n",
                    name, i, r->distance, sd, derr / S, pe / S, e1 / S, e2 / S, r->certificate_gap, r->certified);
    return bad;
}

/* Runs a reference set, both orders of each pair; fails on any bad answer. */
static void check_set(const char *name)
{
    double *P, *R;
    size_t n = load_set(name, &P, &R);
    int bad = 0, overlaps = 0, asym = 0;
    for (size_t i = 0; i < n; ++i) {
        prox_rcc a = rcc_of(P + 14 * i), b = rcc_of(P + 14 * i + 7);
        double sd = R[7 * i], S = prox_rcc_pair_scale(&a, &b);
        prox_distance_result r = prox_rcc_distance_support(&a, &b), q = prox_rcc_distance_support(&b, &a);
        bad += check_answer(name, i, &a, &b, &r, sd);
        bad += check_answer(name, i, &b, &a, &q, sd);
        overlaps += r.intersect;
        /* symmetry: the same verdict outside the touching band, the same distance */
        if ((fabs(sd) > 1e-12 * S && r.intersect != q.intersect) || fabs(r.distance - q.distance) > 1e-12 * S) {
            print_error("%s pair %zu: asymmetric: %d %.17g vs %d %.17g\n", name, i, r.intersect, r.distance,
                        q.intersect, q.distance);
            asym++;
        }
        /* containment agrees with the flags swapped */
        if (r.a_in_b != q.b_in_a || r.b_in_a != q.a_in_b) asym++;
    }
    printf("# %s: %zu pairs, %d overlapping, %d bad answers, %d asymmetric\n", name, n, overlaps, bad, asym);
    free(P);
    free(R);
    assert_int_equal(bad, 0);
    assert_int_equal(asym, 0);
}

/* The internal entry points the query layer composes: prox_sat_rcc_signed (both signs) and
 * prox_sat_rcc_depth (overlapping pairs) against the references: distances to 1e-12 S, depths to
 * 1e-9 S, witnesses in their solids and p2 - p1 = sd n. */
static void check_signed_set(const char *name)
{
    double *P, *R;
    size_t n = load_set(name, &P, &R);
    int bad = 0;
    for (size_t i = 0; i < n; ++i) {
        prox_rcc a = rcc_of(P + 14 * i), b = rcc_of(P + 14 * i + 7);
        double sd = R[7 * i], S = prox_rcc_pair_scale(&a, &b);
        prox_signed_result g = prox_sat_rcc_signed(&a, &b);
        assert_int_equal(g.status, PROX_OK);
        /* p2 - p1 = sd n: to 1e-9 S for disjoint pairs (the points are exact, the normal is the
         * search's direction); overlapping: witnesses of a depth whose normal sits on a kink are
         * consistent to 3.3e-7 S on face-lat stress pairs (docs/algorithms/sat.md, the known limit
         * test_signed_distance also allows) */
        int disjoint = sd > 1e-12 * S;
        double tol = disjoint ? 1e-12 * S : 1e-9 * S, ptol = 1e-9 * S, wtol = disjoint ? 1e-9 * S : 1e-5 * S;
        int ok = fabs(g.sd - sd) <= tol && cyl_sdf(&a, g.p1) <= ptol && cyl_sdf(&b, g.p2) <= ptol &&
                 prox_v3_dist(prox_v3_sub(g.p2, g.p1), prox_v3_scale(g.normal, g.sd)) <= wtol;
        if (sd < -1e-12 * S) { /* overlapping: the depth entry point gives the same depth */
            prox_signed_result d = prox_sat_rcc_depth(&a, &b);
            ok = ok && d.status == PROX_OK && fabs(d.sd - sd) <= 1e-9 * S;
        }
        if (!ok && bad++ < 5)
            print_error("%s pair %zu: sd %.17g ref %.17g, |p2 - p1 - sd n| %.3g S\n", name, i, g.sd, sd,
                        prox_v3_dist(prox_v3_sub(g.p2, g.p1), prox_v3_scale(g.normal, g.sd)) / S);
    }
    free(P);
    free(R);
    assert_int_equal(bad, 0);
}

static void test_support_signed_internal(void **state)
{
    (void)state;
    check_signed_set("agarwal_public");
    check_signed_set("stress_public");
    prox_rcc a = {{0, 0, 0}, {0, 0, 5}, 2}, r0 = {{0, 0, 0}, {0, 0, 5}, -1};
    assert_int_equal(prox_sat_rcc_signed(&a, &r0).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_sat_rcc_depth(&r0, &a).status, PROX_EINVAL_RADIUS);
}

static void test_support_paper_cases(void **state) { (void)state; check_set("paper_cases"); }
static void test_support_agarwal_public(void **state) { (void)state; check_set("agarwal_public"); }
static void test_support_stress_public(void **state) { (void)state; check_set("stress_public"); }

/* Checks a disjoint answer against a distance known in closed form. */
static void check_known(prox_rcc a, prox_rcc b, double d)
{
    prox_distance_result r = prox_rcc_distance_support(&a, &b);
    assert_int_equal(r.status, PROX_OK);
    assert_int_equal(r.intersect, 0);
    double S = prox_rcc_pair_scale(&a, &b);
    assert_near(r.distance, d, 1e-12 * S);
    assert_near(prox_v3_dist(r.p1, r.p2), d, 1e-12 * S);
    assert_true(cyl_sdf(&a, r.p1) <= 1e-12 * S);
    assert_true(cyl_sdf(&b, r.p2) <= 1e-12 * S);
    assert_int_equal(r.certified, 1);
}

/* Contacts whose support sets are faces or segments: the pair must come from the exact closest pair
 * of the two sets. A disk over an offset disk (their projections overlap only in part, so the disk
 * centres are not a valid pair); a disk against the side line of a lying cylinder; two side lines of
 * parallel cylinders of different lengths, offset along the axis; crossing side lines. */
static void test_support_face_contacts(void **state)
{
    (void)state;
    /* end disks facing each other, B shifted sideways by 3 (radii 2 and 1.5: they still overlap) */
    check_known((prox_rcc){{0, 0, 0}, {0, 0, 4}, 2}, (prox_rcc){{3, 0, 5}, {0, 0, 2}, 1.5}, 1.0);
    /* B's end disk above A's lying side line, off A's centre along its axis */
    check_known((prox_rcc){{0, 0, 0}, {10, 0, 0}, 1}, (prox_rcc){{8, 0.5, 1.75}, {0, 0, 3}, 0.5}, 0.75);
    /* parallel side by side, B shorter and offset along the axis (its segment overhangs A's end) */
    check_known((prox_rcc){{0, 0, 0}, {0, 0, 4}, 1}, (prox_rcc){{3, 0, 3}, {0, 0, 5}, 1.5}, 0.5);
    /* crossing side lines, axes perpendicular, gap 0.25 */
    check_known((prox_rcc){{0, 0, -3}, {0, 0, 6}, 1}, (prox_rcc){{-4, 2.25, 1}, {8, 0, 0}, 1}, 0.25);
    /* antiparallel axes, end disks facing */
    check_known((prox_rcc){{0, 0, 0}, {0, 0, 1}, 1}, (prox_rcc){{0.5, 0.5, 3}, {0, 0, -1}, 1}, 1.0);
}

/* Nesting: the flags, and a common point in both. */
static void test_support_nested(void **state)
{
    (void)state;
    prox_rcc big = {{0, 0, 0}, {0, 0, 10}, 5}, small = {{1, 1, 2}, {1, 0, 3}, 1}, cross = {{-8, 0, 5}, {16, 0, 0}, 1};
    prox_distance_result r = prox_rcc_distance_support(&small, &big);
    assert_int_equal(r.status, PROX_OK);
    assert_int_equal(r.intersect, 1);
    assert_int_equal(r.a_in_b, 1);
    assert_int_equal(r.b_in_a, 0);
    assert_true(prox_rcc_contains_point(&small, r.p1, 0.0) && prox_rcc_contains_point(&big, r.p1, 0.0));
    r = prox_rcc_distance_support(&big, &small);
    assert_int_equal(r.b_in_a, 1);
    assert_int_equal(r.a_in_b, 0);
    r = prox_rcc_distance_support(&big, &cross); /* crossing, neither inside */
    assert_int_equal(r.intersect, 1);
    assert_int_equal(r.a_in_b + r.b_in_a, 0);
    assert_int_equal(r.certified, 1);
    assert_true(prox_rcc_contains_point(&cross, r.p1, 1e-12) && prox_rcc_contains_point(&big, r.p1, 1e-12));
    /* identical cylinders: each lies in the other (closed sets) */
    r = prox_rcc_distance_support(&big, &big);
    assert_int_equal(r.a_in_b, 1);
    assert_int_equal(r.b_in_a, 1);
}

/* Seeded random pairs of Agarwal's protocol A against the fast method (prox_rcc_distance): both are
 * exact, so their distances agree to 1e-12 S outside the touching band, and so do the verdicts. */
static void test_support_vs_fast_random(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(777);
    prox_rcc a = {{0, 0, 0}, {0, 0, 5}, 2};
    int bad = 0;
    for (int i = 0; i < 2000; ++i) {
        prox_rcc b;
        b.radius = 20.0 * (1.0 - test_uniform(&g));
        double h = 50.0 * (1.0 - test_uniform(&g));
        do b.base = prox_v3(test_range(&g, -25, 25), test_range(&g, -25, 25), test_range(&g, -25, 25));
        while (prox_v3_norm(b.base) > 25.0);
        b.axis = prox_v3_scale(test_unit(&g), h);
        prox_distance_result s = prox_rcc_distance_support(&a, &b), f = prox_rcc_distance(&a, &b);
        assert_int_equal(s.status, PROX_OK);
        double S = prox_rcc_pair_scale(&a, &b);
        if (fabs(s.distance - f.distance) > 1e-12 * S || s.intersect != f.intersect ||
            (s.intersect && (s.a_in_b != f.a_in_b || s.b_in_a != f.b_in_a))) {
            print_error("pair %d: support %d %.17g (in %d %d) fast %d %.17g (in %d %d)\n", i, s.intersect, s.distance,
                        s.a_in_b, s.b_in_a, f.intersect, f.distance, f.a_in_b, f.b_in_a);
            bad++;
        }
        bad += check_answer("protocol-A", (size_t)i, &a, &b, &s, f.intersect ? -1.0 : f.distance);
    }
    assert_int_equal(bad, 0);
}

/* Scale invariance at the ends of the supported range: every pair of agarwal_public and stress_public
 * scaled by 2^-299 and 2^299 (about 1e-90 and 1e90; a power of two scales the input exactly) must
 * give the same verdict and the distance scaled by the same factor. Guards the unit-scale
 * normalisation: the portal bound squares and multiplies coordinates and overflowed there (disjoint
 * pairs reported intersecting at 1e90, distances 10^4 times too large at 1e-90). */
static void check_scaled_set(const char *name)
{
    char pp[512];
    snprintf(pp, sizeof pp, "%s/%s.pairs", PROX_VALIDATION_DIR, name);
    double *P;
    size_t n = read_table(pp, 14, &P);
    const double scales[2] = {0x1p-299, 0x1p299};
    int bad = 0;
    for (size_t i = 0; i < n; ++i) {
        prox_rcc a = rcc_of(P + 14 * i), b = rcc_of(P + 14 * i + 7);
        prox_distance_result r0 = prox_rcc_distance_support(&a, &b);
        prox_test_result v0 = prox_rcc_sat(&a, &b);
        for (int k = 0; k < 2; ++k) {
            double c = scales[k];
            prox_rcc as = {prox_v3_scale(a.base, c), prox_v3_scale(a.axis, c), a.radius * c};
            prox_rcc bs = {prox_v3_scale(b.base, c), prox_v3_scale(b.axis, c), b.radius * c};
            prox_distance_result r = prox_rcc_distance_support(&as, &bs);
            prox_test_result v = prox_rcc_sat(&as, &bs);
            if (r.status == PROX_EINVAL_RANGE && v.status == PROX_EINVAL_RANGE) continue; /* sizes out of range */
            int ok = r.status == PROX_OK && v.status == PROX_OK && r.intersect == r0.intersect &&
                     v.intersect == v0.intersect && r.distance == r0.distance * c && r.certified == r0.certified;
            if (!ok && bad++ < 5)
                print_error("%s pair %zu x %g: %d %.17g (sat %d) vs %d %.17g (sat %d)\n", name, i, c, r.intersect,
                            r.distance / c, v.intersect, r0.intersect, r0.distance, v0.intersect);
        }
    }
    free(P);
    assert_int_equal(bad, 0);
}

static void test_support_extreme_scale(void **state)
{
    (void)state;
    check_scaled_set("agarwal_public");
    check_scaled_set("stress_public");
}

/* Pairs of the stress generator (bench/stress_gen.h) the support method once answered wrongly, 14
 * numbers each (A then B); each must agree with the fast method to 1e-12 S, disjoint ones certified:
 *  - end disks facing each other, B tilted by ~5e-11: both support sets near-faces; the middle of the
 *    overlap of the projected disks lifted onto the tilted disk was 4e-11 S too far (guards trying a
 *    near-face also as its extreme point);
 *  - a disk against a rim, pair scaled to 1e6: the same, 5e-5 S too far;
 *  - touching within rounding: the portal's trial direction had t_up < |Delta| but a gap of -1e-15
 *    computed the other way, and was reported as separating (guards "separated" only with a
 *    positive gap; the support distance was 8.5e-9 for a touching pair). */
static const double k_regress[][14] = {
    {1.0694271880721575, -1.770500603009288, 1.2422611367303324, 0.67376991454095392, -2.3184768337663062,
     0.57500758119984119, 0.77375832825846769, 1.0694263027338877, -1.770497567581093, 1.2422603625218209,
     -0.58243551750095224, 2.0041904896594396, -0.49706113471531332, 0.7702904542426493},
    {-1016191.5532980484, -6428624.5346454885, 6616044.6612049798, -39130.176038095728, 272254.25055298512,
     -534014.01569820999, 635927.21998169634, -1830230.2818078131, -4597099.4311190676, 2156540.9069170235,
     276658.76432854234, -1924896.1268607443, 3775593.9854017091, 666100.24227288947},
    {-1.4711679724603006, -0.11195094842071773, -1.7202783427539154, 0.88792531479735382, -0.37458063772025207,
     0.2027371651589468, 4.7925322844183427, -5.1408125906939475, -7.9970550318902269, 0.072301329647784573,
     -0.46559271102273614, 0.48647223147162422, -0.42775205123028581, 4.1196976366183407},
};

static void test_support_regressions(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof k_regress / sizeof k_regress[0]; ++k) {
        prox_rcc a = rcc_of(k_regress[k]), b = rcc_of(k_regress[k] + 7);
        double S = prox_rcc_pair_scale(&a, &b);
        for (int swap = 0; swap < 2; ++swap) {
            const prox_rcc *x = swap ? &b : &a, *y = swap ? &a : &b;
            prox_distance_result s = prox_rcc_distance_support(x, y), f = prox_rcc_distance(x, y);
            prox_test_result v = prox_rcc_sat(x, y);
            assert_int_equal(s.status, PROX_OK);
            assert_near(s.distance, f.distance, 1e-12 * S);
            assert_true(v.intersect || v.value > 0.0); /* separated only with a positive gap */
            if (check_answer("regression", k, x, y, &s, f.intersect ? 0.0 : f.distance)) fail();
        }
    }
}

static void test_support_invalid(void **state)
{
    (void)state;
    prox_rcc a = {{0, 0, 0}, {0, 0, 5}, 2};
    prox_rcc r0 = {{0, 0, 0}, {0, 0, 5}, 0}, ax0 = {{0, 0, 0}, {0, 0, 0}, 1}, nan = {{NAN, 0, 0}, {0, 0, 5}, 1};
    prox_rcc tiny = {{0, 0, 0}, {0, 0, 5}, 1e-300};
    assert_int_equal(prox_rcc_distance_support(&a, &r0).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_rcc_distance_support(&r0, &a).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_rcc_distance_support(&a, &ax0).status, PROX_EINVAL_AXIS);
    assert_int_equal(prox_rcc_distance_support(&nan, &a).status, PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_rcc_distance_support(&a, &tiny).status, PROX_EINVAL_RANGE);
    assert_int_equal(prox_rcc_distance_support(NULL, &a).status, PROX_EINVAL_ARG);
    prox_distance_result r = prox_rcc_distance_support(&a, &r0); /* every other field zero */
    assert_int_equal(r.intersect, 0);
    assert_true(r.distance == 0.0 && r.certified == 0);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_support_paper_cases),    cmocka_unit_test(test_support_agarwal_public),
        cmocka_unit_test(test_support_stress_public),  cmocka_unit_test(test_support_face_contacts),
        cmocka_unit_test(test_support_nested),         cmocka_unit_test(test_support_vs_fast_random),
        cmocka_unit_test(test_support_invalid),        cmocka_unit_test(test_support_signed_internal),
        cmocka_unit_test(test_support_extreme_scale),  cmocka_unit_test(test_support_regressions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
