/* BOX-RCC fast paths against the methods they shortcut, on thousands of random pairs:
 *  - the distance (prox_box_rcc_distance: cheap common points, alternating projections with the
 *    feature pair they name and a duality certificate) against the complete enumeration without
 *    them (prox_box_rcc_distance_enum) and against the support-function method
 *    (prox_shape_signed_distance_support), which shares only the core (its value a lower bound,
 *    its witness pair an upper one);
 *  - the depth of overlapping pairs (the strata enumeration with its bounds that skip strata) against
 *    the support-function method.
 * Pairs: the benchmark's random mixture, touching and nearly touching pairs (a random pair slid along
 * its contact normal to a gap of 0 .. 1e-6 S), and near-degenerate poses: box faces parallel to the
 * axis, the axis parallel to a box edge, disks parallel to faces, all within 0 .. 1e-6 rad, and
 * rims grazing edges. Every answer must keep the witness contract: p1 on the box, p2 on the
 * cylinder, |p2 - p1| = distance; signed: p2 - p1 = sd n. */
#include <float.h>

#include "test_util.h"

/* The complete enumeration without the fast path (src/distance/box_rcc.c, internal). */
prox_distance_result prox_box_rcc_distance_enum(const prox_box *a, const prox_rcc *b);

#define DIST_TOL 1e-12  /* distances and points, relative to the pair scale S */
#define DEPTH_TOL 1e-9  /* depths, relative to S */
#define VERDICT_BAND 1e-11 /* pairs this close to touching (x S) may be reported either way */

/* Distance from x to the solid s (0 inside): a point as the smallest sphere. */
static double off_solid(const prox_shape *s, prox_vec3 x)
{
    prox_shape p = prox_shape_from_sph((prox_sph){x, PROX_MIN_SIZE});
    prox_distance_result r = prox_shape_distance(s, &p);
    assert_int_equal(r.status, PROX_OK);
    return r.distance;
}

/* Prints the pair (for a failing check) and fails. */
static void pair_fail(const prox_box *a, const prox_rcc *b, const char *what, double got, double want)
{
    print_error("%s: got %.17g want %.17g\nbox corner %.17g %.17g %.17g\n", what, got, want, a->corner.x, a->corner.y,
                a->corner.z);
    for (int k = 0; k < 3; ++k) print_error("  edge %.17g %.17g %.17g\n", a->edge[k].x, a->edge[k].y, a->edge[k].z);
    print_error("rcc base %.17g %.17g %.17g axis %.17g %.17g %.17g radius %.17g\n", b->base.x, b->base.y, b->base.z,
                b->axis.x, b->axis.y, b->axis.z, b->radius);
    fail();
}

/* Fails, printing the pair, unless |got - want| <= tol. */
#define CHECK_NEAR(what, got, want, tol)                                                   \
    do {                                                                                   \
        double g_ = (got), w_ = (want);                                                    \
        if (!(fabs(g_ - w_) <= (tol))) pair_fail(a, b, what, g_, w_);                      \
    } while (0)

/* Counts of what the checks met, so that a test that stopped covering a case is noticed. */
typedef struct fast_stats {
    int disjoint, overlap, touching, certified;
} fast_stats;

/* The distance of one pair against the enumeration and the support method, with the witness
 * contract; the signed distance of an overlapping pair against the support method. */
static void check_pair(const prox_box *a, const prox_rcc *b, fast_stats *st)
{
    prox_shape sa = prox_shape_from_box(*a), sb = prox_shape_from_rcc(*b);
    /* S, plus the rounding of coordinates far from the origin (a point there is only known to
     * an ulp of its coordinates, whatever the method) */
    double far = fmax(prox_v3_norm(a->corner), prox_v3_norm(b->base));
    double S = prox_shape_pair_scale(&sa, &sb) + 64.0 * DBL_EPSILON * far / DIST_TOL;
    prox_distance_result f = prox_box_rcc_distance(a, b), e = prox_box_rcc_distance_enum(a, b);
    prox_signed_result u = prox_shape_signed_distance_support(&sa, &sb);
    assert_int_equal(f.status, PROX_OK);
    assert_int_equal(e.status, PROX_OK);
    assert_int_equal(u.status, PROX_OK);
    double ref = u.sd > 0.0 ? u.sd : 0.0;
    if (fabs(u.sd) > VERDICT_BAND * S) {
        CHECK_NEAR("verdict vs support", f.intersect, u.sd <= 0.0, 0.0);
        CHECK_NEAR("verdict vs enumeration", f.intersect, e.intersect, 0.0);
    } else {
        ++st->touching;
    }
    if (f.intersect) {
        ++st->overlap;
        CHECK_NEAR("common point off the box", off_solid(&sa, f.p1), 0.0, DIST_TOL * S);
        CHECK_NEAR("common point off the cylinder", off_solid(&sb, f.p1), 0.0, DIST_TOL * S);
    } else {
        ++st->disjoint;
        CHECK_NEAR("distance vs enumeration", f.distance, e.distance, DIST_TOL * S);
        /* the support method's value bounds the distance from below, its witness pair from above (on
         * exactly parallel contacts its value can be the looser of the two) */
        if (!(f.distance >= ref - DIST_TOL * S)) pair_fail(a, b, "distance below support's bound", f.distance, ref);
        if (u.sd > 0.0 && !(f.distance <= prox_v3_dist(u.p1, u.p2) + DIST_TOL * S))
            pair_fail(a, b, "distance above support's pair", f.distance, prox_v3_dist(u.p1, u.p2));
        CHECK_NEAR("|p2 - p1|", prox_v3_dist(f.p1, f.p2), f.distance, DIST_TOL * S);
        CHECK_NEAR("p1 off the box", off_solid(&sa, f.p1), 0.0, DIST_TOL * S);
        CHECK_NEAR("p2 off the cylinder", off_solid(&sb, f.p2), 0.0, DIST_TOL * S);
        if (!(f.certificate_gap <= f.distance + DIST_TOL * S)) pair_fail(a, b, "bound", f.certificate_gap, f.distance);
        if (f.certified) { /* proved: the bound within the certificate's slack */
            ++st->certified;
            CHECK_NEAR("certified gap", f.certificate_gap, f.distance, 1e-13 * S);
        }
    }
    prox_signed_result g = prox_shape_signed_distance(&sa, &sb);
    assert_int_equal(g.status, PROX_OK);
    /* the witness contract of the depth outside the touching band (inside it the witnesses of the
     * support engine, shared by every method, are off by up to ~1e-9 S: a separate open issue) */
    if (g.sd < -VERDICT_BAND * S) {
        CHECK_NEAR("depth vs support", g.sd, u.sd, DEPTH_TOL * S);
        CHECK_NEAR("|normal|", prox_v3_norm(g.normal), 1.0, 1e-12);
        prox_vec3 res = prox_v3_sub(prox_v3_sub(g.p2, g.p1), prox_v3_scale(g.normal, g.sd));
        CHECK_NEAR("p2 - p1 - sd n", prox_v3_norm(res), 0.0, DEPTH_TOL * S);
        CHECK_NEAR("signed p1 off the box", off_solid(&sa, g.p1), 0.0, DEPTH_TOL * S);
        CHECK_NEAR("signed p2 off the cylinder", off_solid(&sb, g.p2), 0.0, DEPTH_TOL * S);
    }
}

/* The box with unit edges e[k] and lengths len[k] centred at c. */
static prox_box make_box(prox_vec3 c, const prox_vec3 e[3], const double len[3])
{
    prox_box x;
    x.corner = c;
    for (int k = 0; k < 3; ++k) {
        x.edge[k] = prox_v3_scale(e[k], len[k]);
        x.corner = prox_v3_mad(x.corner, -0.5, x.edge[k]);
    }
    return x;
}

/* A random rotation's axes e and edge lengths in [0.5, 10]. */
static void random_frame(test_rng *g, prox_vec3 e[3], double len[3])
{
    test_rot R = test_random_rot(g);
    for (int k = 0; k < 3; ++k) {
        e[k] = test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2));
        len[k] = test_range(g, 0.5, 10);
    }
}

/* The benchmark's pair: sizes in [0.5, 10], centres 0 .. 14 apart, random rotations. */
static void random_pair(test_rng *g, prox_box *a, prox_rcc *b)
{
    prox_vec3 e[3];
    double len[3];
    random_frame(g, e, len);
    *a = make_box(prox_v3(0, 0, 0), e, len);
    prox_vec3 cb = prox_v3_scale(test_unit(g), test_range(g, 0, 14)), w = test_unit(g);
    double h = test_range(g, 0.5, 10);
    *b = (prox_rcc){prox_v3_mad(cb, -0.5 * h, w), prox_v3_scale(w, h), test_range(g, 0.5, 10)};
}

static void test_random_mixture(void **state)
{
    (void)state;
    test_init();
    test_rng g = test_rng_seed(20261125);
    fast_stats st = {0};
    for (int i = 0; i < 3000; ++i) {
        prox_box a;
        prox_rcc b;
        random_pair(&g, &a, &b);
        check_pair(&a, &b, &st);
    }
    assert_true(st.disjoint > 800 && st.overlap > 800);
    /* the fast path proves nearly every disjoint answer of the mixture (the fallback's less often) */
    assert_true(st.certified > 0.95 * st.disjoint);
}

/* A random disjoint pair slid along its contact normal to a gap of 0 .. 1e-6 S (the closest pair
 * stays where it was: moving B towards A along the normal shortens only that gap). */
static void test_touching(void **state)
{
    (void)state;
    test_init();
    test_rng g = test_rng_seed(77);
    static const double gaps[] = {0.0, 1e-14, 1e-12, 1e-10, 1e-8, 1e-6};
    fast_stats st = {0};
    int made = 0;
    while (made < 1200) {
        prox_box a;
        prox_rcc b;
        random_pair(&g, &a, &b);
        prox_distance_result e = prox_box_rcc_distance_enum(&a, &b);
        if (e.intersect || !(e.distance > 1e-3)) continue;
        prox_shape sa = prox_shape_from_box(a), sb = prox_shape_from_rcc(b);
        double S = prox_shape_pair_scale(&sa, &sb), want = gaps[made % 6] * S;
        prox_vec3 n = prox_v3_scale(prox_v3_sub(e.p2, e.p1), 1.0 / e.distance);
        b.base = prox_v3_mad(b.base, want - e.distance, n);
        check_pair(&a, &b, &st);
        ++made;
    }
    assert_true(st.touching > 100);
}

/* A unit vector within angle eps of u (towards a random perpendicular). */
static prox_vec3 tilt(test_rng *g, prox_vec3 u, double eps)
{
    prox_vec3 p = test_unit(g);
    p = prox_v3_mad(p, -prox_v3_dot(p, u), u);
    double pn = prox_v3_norm(p);
    if (!(pn > 1e-6)) return u;
    p = prox_v3_scale(p, 1.0 / pn);
    prox_vec3 v = prox_v3_add(prox_v3_scale(u, cos(eps)), prox_v3_scale(p, sin(eps)));
    return prox_v3_scale(v, 1.0 / prox_v3_norm(v));
}

/* Near-degenerate poses: the axis within 0 .. 1e-6 rad of a box edge (faces parallel to the axis,
 * disks parallel to two faces) or of a face plane (a disk perpendicular to a face), and rims grazing
 * edges (a pair made to touch, then slid apart or together by tiny amounts). */
static void test_degenerate_poses(void **state)
{
    (void)state;
    test_init();
    test_rng g = test_rng_seed(4242);
    static const double eps[] = {0.0, 1e-15, 1e-12, 1e-9, 1e-6};
    fast_stats st = {0};
    for (int i = 0; i < 2500; ++i) {
        prox_vec3 e[3];
        double len[3];
        random_frame(&g, e, len);
        prox_box a = make_box(prox_v3(0, 0, 0), e, len);
        int k = i % 3, mode = (i / 3) % 3;
        prox_vec3 w;
        if (mode == 0) /* along an edge: faces parallel to the axis, disks parallel to a face */
            w = tilt(&g, e[k], eps[i % 5]);
        else if (mode == 1) /* parallel to a face, at 45 degrees to its edges: a disk perpendicular to it */
            w = tilt(&g, prox_v3_normalize(prox_v3_add(e[k], e[(k + 1) % 3])), eps[i % 5]);
        else /* oblique */
            w = tilt(&g, e[(k + 1) % 3], 0.3 * test_uniform(&g));
        if (test_uniform(&g) < 0.5) w = prox_v3_neg(w);
        double h = test_range(&g, 0.5, 10), r = test_range(&g, 0.5, 10);
        prox_vec3 cb = prox_v3_scale(test_unit(&g), test_range(&g, 0, 14));
        prox_rcc b = {prox_v3_mad(cb, -0.5 * h, w), prox_v3_scale(w, h), r};
        check_pair(&a, &b, &st);
        /* the same pose slid to touch within 1e-12 .. 1e-9 S (rims grazing edges and faces) */
        prox_distance_result d = prox_box_rcc_distance_enum(&a, &b);
        if (!d.intersect && d.distance > 1e-6) {
            prox_shape sa = prox_shape_from_box(a), sb = prox_shape_from_rcc(b);
            double S = prox_shape_pair_scale(&sa, &sb);
            prox_vec3 n = prox_v3_scale(prox_v3_sub(d.p2, d.p1), 1.0 / d.distance);
            prox_rcc t = b;
            t.base = prox_v3_mad(b.base, (i % 2 ? 1e-9 : -1e-12) * S - d.distance, n);
            check_pair(&a, &t, &st);
        }
    }
    assert_true(st.disjoint > 500 && st.overlap > 500);
}

/* Far from the origin: the fast path works relative to the box centre. */
static void test_far_from_origin(void **state)
{
    (void)state;
    test_init();
    test_rng g = test_rng_seed(9);
    fast_stats st = {0};
    for (int i = 0; i < 600; ++i) {
        prox_box a;
        prox_rcc b;
        random_pair(&g, &a, &b);
        prox_vec3 t = prox_v3_scale(test_unit(&g), 1e6);
        a.corner = prox_v3_add(a.corner, t);
        b.base = prox_v3_add(b.base, t);
        check_pair(&a, &b, &st);
    }
    assert_true(st.disjoint > 100 && st.overlap > 100);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_random_mixture), cmocka_unit_test(test_touching),
                                       cmocka_unit_test(test_degenerate_poses), cmocka_unit_test(test_far_from_origin)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
