/* Tests of prox_rcc_signed_distance and the generic support-function engine
 * (prox_shape_signed_distance_support): the reference sets of tests/data (depth to
 * 1e-9 x scale, distance to 1e-12 x scale, 1e-10 for the `far` family whose input carries that
 * rounding), witness validity, seeded properties (symmetry, rigid motion, scale), hand-made
 * cases, a long-double brute force on random pairs, and other shape kinds. */
#include "test_util.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "prox/query.h"
#include "prox/sat.h"
#include "prox/support.h"

typedef struct vset {
    int n;
    prox_rcc a[2100], b[2100];
    double ref[2100][7];
    int far[2100];
} vset;

static vset *load_set(const char *name)
{
    char path[1024];
    vset *s = calloc(1, sizeof *s);
    snprintf(path, sizeof path, "%s/%s.pairs", PROX_VALIDATION_DIR, name);
    FILE *fp = fopen(path, "r");
    snprintf(path, sizeof path, "%s/%s.ref", PROX_VALIDATION_DIR, name);
    FILE *fr = fopen(path, "r");
    snprintf(path, sizeof path, "%s/%s.meta", PROX_VALIDATION_DIR, name);
    FILE *fm = fopen(path, "r");
    assert_non_null(fp);
    assert_non_null(fr);
    prox_rcc *A = s->a, *B = s->b;
    while (s->n < 2100 &&
           fscanf(fp, "%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &A[s->n].base.x, &A[s->n].base.y,
                  &A[s->n].base.z, &A[s->n].axis.x, &A[s->n].axis.y, &A[s->n].axis.z, &A[s->n].radius, &B[s->n].base.x,
                  &B[s->n].base.y, &B[s->n].base.z, &B[s->n].axis.x, &B[s->n].axis.y, &B[s->n].axis.z,
                  &B[s->n].radius) == 14) {
        for (int i = 0; i < 7; ++i) assert_int_equal(fscanf(fr, "%lf", &s->ref[s->n][i]), 1);
        if (fm) {
            int idx;
            char fam[64], note[64];
            double c;
            if (fscanf(fm, "%d %63s %lf %63s", &idx, fam, &c, note) == 4) s->far[s->n] = strcmp(fam, "far") == 0;
        }
        s->n++;
    }
    fclose(fp);
    fclose(fr);
    if (fm) fclose(fm);
    return s;
}

/* Checks every pair of a set; returns the worst witness inconsistency |p2 - p1 - sd n| / S. */
static double check_set(const char *name, int expect_n)
{
    vset *s = load_set(name);
    assert_int_equal(s->n, expect_n);
    double worst_w = 0.0, worst_o = 0.0, worst_d = 0.0;
    for (int i = 0; i < s->n; ++i) {
        double S = prox_rcc_pair_scale(&s->a[i], &s->b[i]), ref = s->ref[i][0];
        prox_signed_result r = prox_rcc_signed_distance(&s->a[i], &s->b[i]);
        assert_int_equal(r.status, PROX_OK);
        double e = fabs(r.sd - ref) / S;
        if (ref <= 0.0) {
            if (e > worst_o) worst_o = e;
            if (e > 1e-9) print_error("%s pair %d: depth error %.3g x scale\n", name, i, e);
            assert_true(e <= 1e-9);
        } else {
            double tol = s->far[i] ? 1e-10 : 1e-12;
            if (e > worst_d) worst_d = e;
            if (e > tol) print_error("%s pair %d: distance error %.3g x scale\n", name, i, e);
            assert_true(e <= tol);
        }
        /* witnesses: p1 in A, p2 in B, unit normal, p2 - p1 = sd n */
        assert_true(prox_rcc_contains_point(&s->a[i], r.p1, 1e-9 * S));
        assert_true(prox_rcc_contains_point(&s->b[i], r.p2, 1e-9 * S));
        assert_near(prox_v3_norm(r.normal), 1.0, 1e-12);
        double w = prox_v3_dist(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd)) / S;
        if (w > worst_w) worst_w = w;
    }
    printf("%s: worst depth err %.3g, distance err %.3g, witness %.3g (x scale)\n", name, worst_o, worst_d, worst_w);
    free(s);
    return worst_w;
}

static void test_signed_paper_cases(void **state)
{
    (void)state;
    assert_true(check_set("paper_cases", 5) <= 1e-9);
}
static void test_signed_agarwal_public(void **state)
{
    (void)state;
    /* Witness consistency |p2 - p1 - sd n| / S: disjoint pairs are exact (closed-form points);
     * overlapping pairs measured 1.0e-13 worst since the depth is enumerated by strata (rcc_depth.c;
     * was 1.7e-8 with the global search alone; docs/algorithms/sat.md). */
    assert_true(check_set("agarwal_public", 2000) <= 1e-9);
}
static void test_signed_stress_public(void **state)
{
    (void)state;
    /* measured 3.3e-7 (face-lat pairs, axes perpendicular within eps, depth ~1e-7);
     * was 7.8e-6; the 1e-9 goal is not met on these (docs/algorithms/sat.md) */
    assert_true(check_set("stress_public", 1000) <= 1e-5);
}

/* Independent primal brute force in long double for disjoint pairs: alternating projections
 * x <- closest point of A to y, y <- closest point of B to x converge to a closest pair of two
 * disjoint convex sets; |x - y| is an upper bound of the distance that tends to it. */
typedef struct ldcyl {
    long double b[3], w[3], h, r;
} ldcyl;
static ldcyl ld_make(const prox_rcc *c)
{
    ldcyl q;
    long double ax[3] = {c->axis.x, c->axis.y, c->axis.z};
    q.h = sqrtl(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
    for (int i = 0; i < 3; ++i) { q.w[i] = ax[i] / q.h; }
    q.b[0] = c->base.x; q.b[1] = c->base.y; q.b[2] = c->base.z;
    q.r = c->radius;
    return q;
}
static void ld_closest(const ldcyl *c, const long double x[3], long double out[3])
{
    long double d[3] = {x[0] - c->b[0], x[1] - c->b[1], x[2] - c->b[2]};
    long double t = d[0] * c->w[0] + d[1] * c->w[1] + d[2] * c->w[2], rad[3], rn = 0;
    for (int i = 0; i < 3; ++i) { rad[i] = d[i] - t * c->w[i]; rn += rad[i] * rad[i]; }
    rn = sqrtl(rn);
    long double tc = t < 0 ? 0 : (t > c->h ? c->h : t), f = rn > c->r ? c->r / rn : 1;
    for (int i = 0; i < 3; ++i) out[i] = c->b[i] + tc * c->w[i] + f * rad[i];
}
static long double brute_distance(const prox_rcc *a, const prox_rcc *b)
{
    ldcyl A = ld_make(a), B = ld_make(b);
    long double x[3] = {A.b[0], A.b[1], A.b[2]}, y[3];
    for (int it = 0; it < 200000; ++it) {
        ld_closest(&B, x, y);
        ld_closest(&A, y, x);
    }
    ld_closest(&B, x, y);
    return sqrtl((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) + (x[2] - y[2]) * (x[2] - y[2]));
}

static prox_rcc random_rcc(test_rng *g, double spread)
{
    prox_rcc c;
    c.base = prox_v3(test_range(g, -spread, spread), test_range(g, -spread, spread), test_range(g, -spread, spread));
    c.axis = prox_v3_scale(test_unit(g), test_range(g, 0.2, 4.0));
    c.radius = test_range(g, 0.2, 2.0);
    return c;
}

static void test_signed_brute_force(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(4001);
    int checked = 0;
    for (int it = 0; it < 60; ++it) {
        prox_rcc a = random_rcc(&g, 4.0), b = random_rcc(&g, 4.0);
        double S = prox_rcc_pair_scale(&a, &b);
        prox_signed_result r = prox_rcc_signed_distance(&a, &b);
        if (r.sd <= 1e-3 * S) continue; /* alternating projections only bound disjoint pairs */
        long double bf = brute_distance(&a, &b);
        /* the support-function value is a lower bound, the primal pair an upper bound */
        assert_true(r.sd <= (double)bf + 1e-13 * S);
        assert_near(r.sd, (double)bf, 1e-10 * S);
        checked++;
    }
    assert_true(checked >= 20);
}

/* Overlapping pairs: the strata enumeration of prox_rcc_signed_distance against the global
 * support-function search (prox_shape_signed_distance_support, sampling all strata + Newton), an
 * independent method; both values are upper bounds of the depth, and the witnesses must be
 * consistent to 1e-9 x scale. Deep-inside and protocol-A-like poses. */
static void test_signed_depth_vs_global(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(4003);
    int checked = 0;
    for (int it = 0; it < 400; ++it) {
        prox_rcc a = random_rcc(&g, it % 2 ? 1.0 : 3.0), b = random_rcc(&g, it % 2 ? 1.0 : 3.0);
        if (it % 4 == 3) { b.radius *= 0.1; b.axis = prox_v3_scale(b.axis, 0.1); } /* small B */
        double S = prox_rcc_pair_scale(&a, &b);
        prox_signed_result r = prox_rcc_signed_distance(&a, &b);
        if (!(r.sd < -1e-6 * S)) continue;
        prox_shape sa = prox_shape_from_rcc(a), sb = prox_shape_from_rcc(b);
        prox_signed_result q = prox_shape_signed_distance_support(&sa, &sb);
        if (fabs(r.sd - q.sd) > 1e-9 * S) print_error("pair %d: enum %.17g global %.17g\n", it, r.sd, q.sd);
        assert_near(r.sd, q.sd, 1e-9 * S);
        assert_true(prox_v3_dist(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd)) <= 1e-9 * S);
        assert_true(prox_rcc_contains_point(&a, r.p1, 1e-9 * S));
        assert_true(prox_rcc_contains_point(&b, r.p2, 1e-9 * S));
        checked++;
    }
    assert_true(checked >= 100);
}

/* Deep overlaps of wide cylinders (radii up to 10, heights down to 0.5, centres within 3): the rim-rim
 * cells whose (farthest, farthest) pairs no bound excludes are solved by the far-point stationary
 * points (rcc_depth.c, dp_cells_far), so the enumeration settles every pair (its answer certified,
 * none left to the global search), and agrees with the global search to 1e-9 S. */
static void test_signed_deep_overlap_enumerated(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(4011);
    int checked = 0, uncertified = 0;
    for (int it = 0; it < 300; ++it) {
        prox_vec3 wa = test_unit(&g), wb = test_unit(&g), cb = prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 3.0));
        double ha = test_range(&g, 0.5, 10.0), hb = test_range(&g, 0.5, 10.0);
        prox_rcc a = {prox_v3_scale(wa, -0.5 * ha), prox_v3_scale(wa, ha), test_range(&g, 0.5, 10.0)};
        prox_rcc b = {prox_v3_mad(cb, -0.5 * hb, wb), prox_v3_scale(wb, hb), test_range(&g, 0.5, 10.0)};
        double S = prox_rcc_pair_scale(&a, &b);
        prox_signed_result r = prox_rcc_signed_distance(&a, &b);
        assert_int_equal(r.status, PROX_OK);
        if (!(r.sd < -1e-6 * S)) continue;
        prox_shape sa = prox_shape_from_rcc(a), sb = prox_shape_from_rcc(b);
        prox_signed_result q = prox_shape_signed_distance_support(&sa, &sb);
        if (fabs(r.sd - q.sd) > 1e-9 * S) print_error("pair %d: enum %.17g global %.17g\n", it, r.sd, q.sd);
        assert_near(r.sd, q.sd, 1e-9 * S);
        uncertified += !r.certified;
        checked++;
    }
    printf("# deep overlaps: %d checked, %d not certified\n", checked, uncertified);
    assert_true(checked >= 200);
    assert_int_equal(uncertified, 0);
}

/* An end disk pressed 2e-4 deep into a side line tilted under 1e-9 rad from it (stress_public pair
 * 607, under 24 random rigid motions): the side line's support set along the normal is the whole
 * line, whose far end sits the tilt times its length off the supporting plane. The witnesses must
 * still give p2 - p1 = sd normal to 1e-12 S (plus the rounding of the moved input) and lie in their
 * solids. */
static void test_signed_face_against_tilted_side(void **state)
{
    (void)state;
    const prox_rcc a0 = {prox_v3(-3.0733140026246022, -0.10889632572799132, 2.3779112806176173),
                         prox_v3(1.6307633128386183, -0.27444358094806948, -1.1361601242283492), 1.0307153374155913};
    const prox_rcc b0 = {prox_v3(-0.82384867017326735, -1.3985079585502382, 1.377982663849026),
                         prox_v3(0.40055983968650538, 0.51005644742162493, 0.45172908422611024), 0.56479687110367061};
    test_rng g = test_rng_seed(607);
    for (int k = 0; k < 25; ++k) {
        prox_rcc a = a0, b = b0;
        if (k > 0) {
            test_rot R = test_random_rot(&g);
            prox_vec3 t = prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 10.0));
            a.base = prox_v3_add(test_rot_apply(&R, a0.base), t), a.axis = test_rot_apply(&R, a0.axis);
            b.base = prox_v3_add(test_rot_apply(&R, b0.base), t), b.axis = test_rot_apply(&R, b0.axis);
        }
        prox_signed_result r = prox_rcc_signed_distance(&a, &b);
        double S = prox_rcc_pair_scale(&a, &b), tol = 1e-12 * S + 64.0 * DBL_EPSILON * 20.0;
        assert_int_equal(r.status, PROX_OK);
        assert_near(r.sd, -0.00020737898480452873, 1e-9 * S);
        double e = prox_v3_dist(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd));
        if (e > tol) print_error("motion %d: residual %.3g S\n", k, e / S);
        assert_true(e <= tol);
        assert_true(prox_rcc_contains_point(&a, r.p1, tol));
        assert_true(prox_rcc_contains_point(&b, r.p2, tol));
    }
}

static prox_vec3 rot_apply_pt(const test_rot *R, prox_vec3 p, prox_vec3 t) { return prox_v3_add(test_rot_apply(R, p), t); }

static void test_signed_properties(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(4002);
    for (int it = 0; it < 300; ++it) {
        prox_rcc a = random_rcc(&g, 3.0), b = random_rcc(&g, 3.0);
        double S = prox_rcc_pair_scale(&a, &b);
        prox_signed_result r = prox_rcc_signed_distance(&a, &b);
        /* symmetry: swapping A and B keeps sd and flips the normal */
        prox_signed_result q = prox_rcc_signed_distance(&b, &a);
        assert_near(q.sd, r.sd, 1e-11 * S);
        /* rigid motion */
        test_rot R = test_random_rot(&g);
        prox_vec3 t = prox_v3(test_range(&g, -5, 5), test_range(&g, -5, 5), test_range(&g, -5, 5));
        prox_rcc a2 = {rot_apply_pt(&R, a.base, t), test_rot_apply(&R, a.axis), a.radius};
        prox_rcc b2 = {rot_apply_pt(&R, b.base, t), test_rot_apply(&R, b.axis), b.radius};
        assert_near(prox_rcc_signed_distance(&a2, &b2).sd, r.sd, 1e-11 * S);
        /* scale by a power of two: exact */
        prox_rcc a3 = {prox_v3_scale(a.base, 0.125), prox_v3_scale(a.axis, 0.125), a.radius * 0.125};
        prox_rcc b3 = {prox_v3_scale(b.base, 0.125), prox_v3_scale(b.axis, 0.125), b.radius * 0.125};
        assert_near(prox_rcc_signed_distance(&a3, &b3).sd, r.sd * 0.125, 1e-12 * S);
        /* moving B by -sd n makes them touch */
        prox_rcc b4 = b;
        b4.base = prox_v3_mad(b.base, -r.sd, r.normal);
        assert_near(prox_rcc_signed_distance(&a, &b4).sd, 0.0, 1e-9 * S);
    }
}

static void test_signed_hand_made(void **state)
{
    (void)state;
    prox_rcc a = {{0, 0, 0}, {0, 0, 2}, 1};
    /* coaxial stacked with a gap of 0.5 */
    prox_rcc b = {{0, 0, 2.5}, {0, 0, 3}, 0.5};
    prox_signed_result r = prox_rcc_signed_distance(&a, &b);
    assert_near(r.sd, 0.5, 1e-15);
    assert_near(r.normal.z, 1.0, 1e-15);
    assert_near(r.p2.z - r.p1.z, 0.5, 1e-15);
    /* coaxial, B inside A: depth = min over escape routes: radial 1 - 0.25 + 0.25 = 1, axial ... */
    prox_rcc c = {{0, 0, 0.9}, {0, 0, 0.2}, 0.25};
    r = prox_rcc_signed_distance(&a, &c);
    assert_near(r.sd, -1.1, 1e-14); /* axial escape 2 - 0.9 = 1.1 beats sideways 1 + 0.25 */
    /* parallel side by side: axes 3 apart, radii 1 and 1.5 -> distance 0.5 */
    prox_rcc d = {{3, 0, -1}, {0, 0, 5}, 1.5};
    r = prox_rcc_signed_distance(&a, &d);
    assert_near(r.sd, 0.5, 1e-15);
    assert_near(r.normal.x, 1.0, 1e-15);
    /* perpendicular crossing laterals overlapping by 0.25 */
    prox_rcc e = {{-3, 1.75, 1}, {6, 0, 0}, 1};
    r = prox_rcc_signed_distance(&a, &e);
    assert_near(r.sd, -0.25, 1e-14);
    /* touching end to end */
    prox_rcc f = {{0.3, 0, 2}, {0, 0, 1}, 1};
    assert_near(prox_rcc_signed_distance(&a, &f).sd, 0.0, 1e-15);
    /* invalid input */
    prox_rcc bad = {{0, 0, 0}, {0, 0, 0}, 1};
    assert_int_equal(prox_rcc_signed_distance(&a, &bad).status, PROX_EINVAL_AXIS);
    bad.axis.z = NAN;
    assert_int_equal(prox_rcc_signed_distance(&bad, &a).status, PROX_EINVAL_NONFINITE);
}

static void test_support_generic_shapes(void **state)
{
    (void)state;
    /* sphere-sphere, sphere-box, box-box against closed forms */
    prox_shape s1 = prox_shape_from_sph((prox_sph){{0, 0, 0}, 1});
    prox_shape s2 = prox_shape_from_sph((prox_sph){{3, 4, 0}, 2});
    assert_near(prox_shape_signed_distance_support(&s1, &s2).sd, 2.0, 1e-14);
    prox_shape r1 = prox_shape_from_rpp((prox_rpp){-1, 1, -1, 1, -1, 1});
    prox_shape r2 = prox_shape_from_rpp((prox_rpp){1.5, 3, -0.5, 0.5, 0.7, 4});
    prox_signed_result r = prox_shape_signed_distance_support(&r1, &r2);
    assert_near(r.sd, 0.5, 1e-14);
    assert_near(r.normal.x, 1.0, 1e-14);
    prox_shape r3 = prox_shape_from_rpp((prox_rpp){0.8, 3, -0.5, 0.5, 0.7, 4}); /* overlap 0.2 in x, 0.3 in z */
    assert_near(prox_shape_signed_distance_support(&r1, &r3).sd, -0.2, 1e-14);
    prox_shape s3 = prox_shape_from_sph((prox_sph){{2.5, 0, 0}, 1});       /* sphere 0.5 from face */
    assert_near(prox_shape_signed_distance_support(&r1, &s3).sd, 0.5, 1e-14);
    prox_shape s4 = prox_shape_from_sph((prox_sph){{2, 2, 2}, 1});         /* corner: sqrt(3) - 1 */
    assert_near(prox_shape_signed_distance_support(&r1, &s4).sd, sqrt(3.0) - 1.0, 1e-14);
    /* cylinder vs box: cylinder standing on the box top, 0.25 above */
    prox_shape c1 = prox_shape_from_rcc((prox_rcc){{0.3, 0.2, 1.25}, {0, 0, 2}, 0.5});
    r = prox_shape_signed_distance_support(&r1, &c1);
    assert_near(r.sd, 0.25, 1e-14);
    assert_true(prox_v3_dist(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd)) <= 1e-12);
    /* support function matches the definition on a box corner */
    assert_near(prox_shape_support(&r1, prox_v3(1, -2, 3)), 6.0, 0);
    prox_vec3 p = prox_shape_support_point(&r1, prox_v3(1, -2, 3));
    assert_near(p.x, 1, 0);
    assert_near(p.y, -1, 0);
    assert_near(p.z, 1, 0);
    prox_shape badk = r1;
    badk.kind = PROX_SHAPE_KIND_COUNT_; /* the first value past the last kind */
    assert_int_equal(prox_shape_signed_distance_support(&r1, &badk).status, PROX_EINVAL_SHAPE_KIND);
}

/* The generic support-function method on near-touching DISJOINT pairs of every kind: a random pair
 * moved along its contact normal to a gap of 1e-12 .. 1e-2 x scale (translating along the normal
 * changes the distance by exactly the move).  There the cone of separating directions is too narrow
 * for the fixed samples; the method used to report such pairs as overlapping (RCC-RCC 3.5e-8 apart
 * as -0.029).  Its value is a lower bound (duality) and must reach the distance within 1e-11 x scale,
 * and never be <= 0 for a pair more than 1e-10 x scale apart. */
static void test_support_near_touching(void **state)
{
    (void)state;
    test_rng r = test_rng_seed(4711);
    const char *kn[] = {"RCC", "BOX", "SPH"};
    int bad = 0, total = 0;
    for (int ka = 0; ka < 3; ++ka)
        for (int kb = 0; kb < 3; ++kb) {
            double worst = 0.0;
            int cnt = 0;
            for (int i = 0; i < 12000; ++i) {
                prox_shape a, b;
                test_extreme_pair(&r, ka, kb, &a, &b);
                prox_distance_result d = prox_shape_distance(&a, &b);
                if (d.status != PROX_OK || !(d.distance > 0.0)) continue;
                prox_vec3 nrm = prox_v3_scale(prox_v3_sub(d.p2, d.p1), 1.0 / d.distance);
                double S0 = prox_shape_pair_scale(&a, &b), g = pow(10.0, test_range(&r, -12, -2)) * S0;
                prox_shape b2;
                prox_vec3 move = prox_v3_scale(nrm, g - d.distance);
                assert_int_equal(prox_shape_translated(&b, move, &b2), PROX_OK);
                prox_distance_result e = prox_shape_distance(&a, &b2);
                prox_signed_result s = prox_shape_signed_distance_support(&a, &b2);
                assert_int_equal(s.status, PROX_OK);
                double S = prox_shape_pair_scale(&a, &b2), err = fabs(s.sd - e.distance) / S;
                worst = fmax(worst, err);
                ++cnt;
                int wrong = s.sd > e.distance + 1e-12 * S || err > 1e-11 ||
                            (e.distance > 1e-10 * S && !(s.sd > 0.0));
                if (wrong && bad++ < 5)
                    print_error("%s-%s pair %d: support %.17g, distance %.17g (scale %.3g)\n",
                                kn[ka], kn[kb], i, s.sd, e.distance, S);
            }
            total += cnt;
            printf("# %s-%s: %d near-touching pairs, worst |support - distance| %.2g x scale\n",
                   kn[ka], kn[kb], cnt, worst);
        }
    assert_true(total > 50000);
    assert_int_equal(bad, 0);
}

/* Two near-touching pairs the sweep above found at a rate of ~1e-5 (seed 7): a tiny disk against a
 * box edge, seen nearly edge-on, where phi along the edge's ridge is a bowl only 5.7e-9 deep over 0.3
 * rad (the ridge search stopped at a kink 4.5e-9 short), and a thin rod against a thin plate whose
 * separating direction only the overlapping branch's searches found (then left unrefined). */
static void test_support_flat_ridge(void **state)
{
    (void)state;
    prox_box box1 = {{0, 0, 0},
                     {{-89.030776290191099, 536.46955327234821, 43.60060747518979},
                      {29.598725864219961, 4.5543017254075426, 4.402537944096701},
                      {80.781178899354785, 62.827953192234084, -608.09411726876544}}};
    prox_rcc disk = {{-0.15545469407081924, 0.84681336559331299, 0.077607475527912584},
                     {-0.00093145888665782824, 3.8818281791486663e-05, -0.002258007945901841},
                     0.016851356630715124};
    prox_rcc rod = {{0, 0, 0}, {-51.064117825448328, -36.551792510787635, 0.30054299440663712},
                    0.0032084882685149323};
    prox_box plate = {{1.0224028190267602, -1.4137949182802143, 3.8293823635533499},
                      {{0.013752753824505163, 0.003021833216584606, -0.0025612808904325237},
                       {-10.317519091097846, 14.267583162396718, -38.566657717227692},
                       {-3.2713994980672161, 22.770278858354551, 9.298953947421122}}};
    prox_shape pairs[2][2] = {{prox_shape_from_box(box1), prox_shape_from_rcc(disk)},
                              {prox_shape_from_rcc(rod), prox_shape_from_box(plate)}};
    for (int k = 0; k < 2; ++k) {
        prox_distance_result d = prox_shape_distance(&pairs[k][0], &pairs[k][1]);
        prox_signed_result s = prox_shape_signed_distance_support(&pairs[k][0], &pairs[k][1]);
        double S = prox_shape_pair_scale(&pairs[k][0], &pairs[k][1]);
        assert_int_equal(d.status, PROX_OK);
        assert_int_equal(s.status, PROX_OK);
        assert_true(d.distance > 1e-9 && d.distance < 6e-9);
        assert_near(s.sd, d.distance, 1e-13 * S);
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_signed_paper_cases),   cmocka_unit_test(test_signed_agarwal_public),
        cmocka_unit_test(test_signed_stress_public), cmocka_unit_test(test_signed_brute_force),
        cmocka_unit_test(test_signed_depth_vs_global),
        cmocka_unit_test(test_signed_deep_overlap_enumerated),
        cmocka_unit_test(test_signed_face_against_tilted_side),
        cmocka_unit_test(test_signed_properties),    cmocka_unit_test(test_signed_hand_made),
        cmocka_unit_test(test_support_generic_shapes),
        cmocka_unit_test(test_support_near_touching),
        cmocka_unit_test(test_support_flat_ridge),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
