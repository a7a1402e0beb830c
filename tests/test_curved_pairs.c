/* Coaxial solids of revolution (distance/curved_internal.h): RCC, TRC, ELL, SPH on one axis.
 * Independent checks through the 3D support functions of the core bodies: a disjoint answer is
 * proved by weak duality (the gap along the reported normal is a lower bound, |p2 - p1| an upper
 * one) and must equal the largest gap over directions sampled around the axis; an overlapping one
 * must equal the least overlap over those directions, with witnesses in the solids. Then hand cases,
 * the coaxiality test and the named statuses. */
#include "test_util.h"

#include <float.h>

#include "core/body.h"
#include "distance/curved_internal.h"

/* A random solid of revolution of kind k centred at c with axis direction w (sizes 10^-e .. 10^e). */
static prox_shape rev_shape(test_rng *g, int k, prox_vec3 c, prox_vec3 w, double e)
{
    double h = pow(10.0, test_range(g, -e, e)), r = pow(10.0, test_range(g, -e, e));
    if (test_uniform(g) < 0.5) w = prox_v3_neg(w);
    prox_vec3 ax = prox_v3_scale(w, h);
    if (k == 0) {
        prox_rcc x = {prox_v3_mad(c, -0.5, ax), ax, r};
        return prox_shape_from_rcc(x);
    }
    if (k == 1) {
        double r2 = test_uniform(g) < 0.25 ? 0.0 : pow(10.0, test_range(g, -e, e));
        prox_trc x = {prox_v3_mad(c, -0.5, ax), ax, r, r2};
        if (test_uniform(g) < 0.2) x.r1 = 0.0, x.r2 = r;
        return prox_shape_from_trc(x);
    }
    if (k == 2) {
        prox_ell x = {c, prox_v3_scale(w, 0.5 * h), r};
        return prox_shape_from_ell(x);
    }
    prox_sph x = {c, r};
    return prox_shape_from_sph(x);
}

/* h_A(n) + h_B(-n) along n = cos(th) w + sin(th) u: minus the gap (disjoint) or the overlap. */
static double overlap(const prox_body *a, const prox_body *b, prox_vec3 w, prox_vec3 u, double th)
{
    prox_vec3 n = prox_v3_mad(prox_v3_scale(w, cos(th)), sin(th), u);
    return prox_body_support(a, n) + prox_body_support(b, prox_v3_neg(n));
}

/* Least overlap over th in [0, pi]: dense samples, golden section around the best. */
static double min_overlap(const prox_body *a, const prox_body *b, prox_vec3 w, prox_vec3 u)
{
    enum { N = 4000 };
    double best = INFINITY;
    int ib = 0;
    for (int i = 0; i <= N; ++i) {
        double v = overlap(a, b, w, u, PROX_PI * i / N);
        if (v < best) best = v, ib = i;
    }
    double lo = PROX_PI * (ib > 0 ? ib - 1 : 0) / N, hi = PROX_PI * (ib < N ? ib + 1 : N) / N;
    const double gr = 0.6180339887498949;
    double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo);
    double f1 = overlap(a, b, w, u, x1), f2 = overlap(a, b, w, u, x2);
    for (int it = 0; it < 80; ++it) {
        if (f1 < f2)
            hi = x2, x2 = x1, f2 = f1, x1 = hi - gr * (hi - lo), f1 = overlap(a, b, w, u, x1);
        else
            lo = x1, x1 = x2, f1 = f2, x2 = lo + gr * (hi - lo), f2 = overlap(a, b, w, u, x2);
    }
    return fmin(best, fmin(f1, f2));
}

static void check_pair(const prox_shape *A, const prox_shape *B, prox_vec3 w, int i)
{
    prox_body a = prox_body_make(A), b = prox_body_make(B);
    /* tolerance: 1e-13 of the pair's scale, plus the rounding of the bodies' absolute positions
     * (a centre base + axis/2 carries ~1 ulp of its coordinates, which tiny bodies far from the
     * origin feel relative to their size) */
    double S = fmax(fmax(a.size, b.size), prox_v3_dist(a.c, b.c));
    S += 16.0 * DBL_EPSILON * (prox_v3_maxabs(a.c) + prox_v3_maxabs(b.c)) / 1e-13; /* 16 ulps, below */
    prox_vec3 u = prox_v3_any_perp(w);
    assert_true(prox_coaxial_pair(A, B));
    prox_signed_result s = prox_coaxial_signed_distance(A, B);
    prox_distance_result d = prox_coaxial_distance(A, B);
    assert_int_equal(s.status, PROX_OK);
    assert_int_equal(d.status, PROX_OK);
    double m = min_overlap(&a, &b, w, u);
    double along = prox_body_support(&a, s.normal) + prox_body_support(&b, prox_v3_neg(s.normal));
    /* attained along the normal, and no sampled direction does better (the samples may miss a sharp
     * minimum: one-sided) */
    int ok = -s.sd <= m + 1e-13 * S && fabs(s.sd + along) <= 1e-13 * S &&
             fabs(prox_v3_norm(s.normal) - 1.0) <= 1e-15 &&
             prox_v3_dist(prox_v3_sub(s.p2, s.p1), prox_v3_scale(s.normal, s.sd)) <= 1e-13 * S &&
             prox_body_contains(&a, s.p1, 1e-13 * S) && prox_body_contains(&b, s.p2, 1e-13 * S);
    if (!ok) {
        print_error("pair %d (%s %s): sd %.17g, least overlap %.17g, along normal %.17g, S %g, "
                    "|p2 - p1 - sd n| %.3g, in A %d, in B %d\n", i, prox_shape_kind_name(A->kind),
                    prox_shape_kind_name(B->kind), s.sd, -m, -along, S,
                    prox_v3_dist(prox_v3_sub(s.p2, s.p1), prox_v3_scale(s.normal, s.sd)),
                    prox_body_contains(&a, s.p1, 1e-13 * S), prox_body_contains(&b, s.p2, 1e-13 * S));
        fail();
    }
    if (d.intersect) {
        assert_true(s.sd <= 1e-13 * S);
        assert_true(d.certified);
        assert_true(prox_body_contains(&a, d.p1, 1e-14 * S) && prox_body_contains(&b, d.p1, 1e-14 * S));
    } else {
        assert_true(s.sd >= -1e-13 * S);
        assert_near(d.distance, s.sd, 1e-13 * S);
        assert_near(prox_v3_dist(d.p1, d.p2), d.distance, 1e-13 * S);
        if (!d.certified || !(d.certificate_gap <= d.distance + 1e-13 * S)) {
            print_error("pair %d (%s %s): distance %.17g gap %.17g S %g\n", i, prox_shape_kind_name(A->kind),
                        prox_shape_kind_name(B->kind), d.distance, d.certificate_gap, S);
            fail();
        }
    }
}

/* Random coaxial pairs of every kind combination, from far apart to nested; sizes within a factor
 * e of 1 (e = 1: ordinary bodies; e = 3: needles, disks and bodies 1e6 apart in size). */
static void random_pairs(int n, uint64_t seed, double e)
{
    test_rng g = test_rng_seed(seed);
    for (int i = 0; i < n; ++i) {
        int ka = i % 4, kb = (i / 4) % 4;
        if (ka == 3 && kb == 3) kb = 2;
        prox_vec3 w = test_unit(&g), o = prox_v3(test_range(&g, -9, 9), test_range(&g, -9, 9), test_range(&g, -9, 9));
        prox_shape A = rev_shape(&g, ka, o, w, e);
        double reach = prox_shape_size(&A);
        prox_shape B = rev_shape(&g, kb, prox_v3_mad(o, reach * test_range(&g, -1.5, 1.5), w), w, e);
        check_pair(&A, &B, w, i);
    }
}
static void test_random_pairs(void **state) { (void)state, random_pairs(600, 101, 1.0); }
static void test_extreme_pairs(void **state) { (void)state, random_pairs(300, 102, 3.0); }

/* Exact cases by hand. */
static void test_hand_cases(void **state)
{
    (void)state;
    prox_vec3 z = prox_v3(0, 0, 1);
    /* two RCCs stacked with a gap of 0.5: the whole disk overlap is optimal, the axis point given */
    prox_rcc c1 = {prox_v3(0, 0, 0), prox_v3(0, 0, 2), 1}, c2 = {prox_v3(0, 0, 2.5), prox_v3(0, 0, 1), 3};
    prox_shape A = prox_shape_from_rcc(c1), B = prox_shape_from_rcc(c2);
    prox_distance_result d = prox_coaxial_distance(&A, &B);
    assert_int_equal(d.intersect, 0);
    assert_near(d.distance, 0.5, 1e-15);
    assert_int_equal(d.point_set, 1);
    assert_near(d.p1.z, 2.0, 1e-15);
    assert_near(d.p2.z, 2.5, 1e-15);
    /* a cone whose apex points at a sphere on its axis: the apex is nearest */
    prox_trc t = {prox_v3(0, 0, 0), prox_v3(0, 0, 2), 1, 0};
    prox_sph s = {prox_v3(0, 0, 5), 1};
    A = prox_shape_from_trc(t), B = prox_shape_from_sph(s);
    d = prox_coaxial_distance(&A, &B);
    assert_near(d.distance, 2.0, 1e-15);
    assert_near(d.p1.z, 2.0, 1e-15);
    assert_int_equal(d.point_set, 0);
    /* a thin RCC nested in a wide one: the depth is the radial exit r1 + r2 = 3... or the axial one */
    prox_rcc in = {prox_v3(0, 0, -1), prox_v3(0, 0, 2), 0.5}, out = {prox_v3(0, 0, -10), prox_v3(0, 0, 20), 2};
    A = prox_shape_from_rcc(out), B = prox_shape_from_rcc(in);
    prox_signed_result r = prox_coaxial_signed_distance(&A, &B);
    assert_near(r.sd, -2.5, 1e-15); /* move the thin one sideways by r_out + r_in */
    assert_near(fabs(prox_v3_dot(r.normal, z)), 0.0, 1e-15);
    /* an ELL standing on an RCC: touching at the vertex */
    prox_ell e = {prox_v3(0, 0, 5), prox_v3(0, 0, 3), 1};
    prox_rcc base = {prox_v3(0, 0, 0), prox_v3(0, 0, 2), 4};
    A = prox_shape_from_ell(e), B = prox_shape_from_rcc(base);
    d = prox_coaxial_distance(&A, &B);
    assert_int_equal(d.intersect, 1);
    assert_near(d.p1.z, 2.0, 1e-15);
    /* two prolate ELLs end to end: vertex to vertex */
    prox_ell e2 = {prox_v3(0, 0, 10), prox_v3(0, 0, -1), 2};
    B = prox_shape_from_ell(e2);
    d = prox_coaxial_distance(&A, &B);
    assert_near(d.distance, 1.0, 1e-15);
}

/* Coaxiality: tilts and offsets beyond PROX_TOL_COAXIAL_REV are not coaxial; two spheres are not a
 * coaxial pair; invalid input gets its status. */
static void test_coaxial_test(void **state)
{
    (void)state;
    prox_trc t = {prox_v3(0, 0, 0), prox_v3(0, 0, 2), 1, 0.5};
    prox_ell e = {prox_v3(0, 0, 5), prox_v3(0, 0, 1), 2};
    prox_shape A = prox_shape_from_trc(t), B = prox_shape_from_ell(e);
    assert_true(prox_coaxial_pair(&A, &B));
    e.axis = prox_v3(1e-10, 0, 1);
    B = prox_shape_from_ell(e);
    assert_false(prox_coaxial_pair(&A, &B));
    assert_int_equal(prox_coaxial_signed_distance(&A, &B).status, PROX_EUNSUPPORTED);
    e.axis = prox_v3(0, 0, 1), e.center.x = 1e-9;
    B = prox_shape_from_ell(e);
    assert_false(prox_coaxial_pair(&A, &B));
    e.center.x = 1e-14; /* within the tolerance */
    B = prox_shape_from_ell(e);
    assert_true(prox_coaxial_pair(&A, &B));
    /* tiny bodies far out: an offset of 1e-2 of their size is not coaxial; the distance keeps its
     * relative precision (the sections are placed from the input points, not rounded centres) */
    prox_rcc far = {prox_v3(1e6, 0, 0), prox_v3(1e-6, 0, 0), 1e-6};
    prox_sph fs = {prox_v3(1e6 + 3e-6, 1e-8, 0), 1e-6};
    A = prox_shape_from_rcc(far), B = prox_shape_from_sph(fs);
    assert_false(prox_coaxial_pair(&A, &B));
    fs.center.y = 0.0;
    B = prox_shape_from_sph(fs);
    assert_true(prox_coaxial_pair(&A, &B));
    /* the distance to the input's precision: centre - top - radius, differences of nearby doubles */
    assert_near(prox_coaxial_distance(&A, &B).distance, (fs.center.x - 1e6) - 1e-6 - 1e-6, 1e-20);
    prox_sph s1 = {prox_v3(0, 0, 0), 1}, s2 = {prox_v3(3, 0, 0), 1};
    A = prox_shape_from_sph(s1), B = prox_shape_from_sph(s2);
    assert_false(prox_coaxial_pair(&A, &B));
    prox_sph s3 = {prox_v3(0, 0, 9), 1}; /* a sphere on the TRC's axis */
    A = prox_shape_from_trc(t), B = prox_shape_from_sph(s3);
    assert_true(prox_coaxial_pair(&A, &B));
    prox_box bx = {prox_v3(0, 0, 0), {prox_v3(1, 0, 0), prox_v3(0, 1, 0), prox_v3(0, 0, 1)}};
    B = prox_shape_from_box(bx);
    assert_false(prox_coaxial_pair(&A, &B));
    t.r1 = t.r2;
    A = prox_shape_from_trc(t), B = prox_shape_from_sph(s3);
    assert_int_equal(prox_coaxial_distance(&A, &B).status, PROX_EINVAL_TRC);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand_cases),
        cmocka_unit_test(test_coaxial_test),
        cmocka_unit_test(test_random_pairs),
        cmocka_unit_test(test_extreme_pairs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
