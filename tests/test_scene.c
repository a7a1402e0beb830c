/* Tests of scenes, query modes and the batch API (src/scene/scene.c): bounding volumes against the
 * support functions, every query mode against a direct call of the exact solvers, the broad phase
 * against the naive all-pairs loop and against a brute-force loop over query.h, the nearest pair,
 * the batch API on 1 and 2 threads, and invalid input. */
#include <stdlib.h>
#include <string.h>

#include "test_util.h"
#include "prox/scene.h"
#include "prox/support.h"

/* A random body of a random kind around centre c with sizes in [0.2, 2]. */
static prox_shape random_body(test_rng *g, prox_vec3 c)
{
    int kind = (int)(test_uniform(g) * 4);
    if (kind == 0) {
        prox_sph s = {c, test_range(g, 0.2, 1.0)};
        return prox_shape_from_sph(s);
    }
    if (kind == 1) {
        prox_vec3 ax = prox_v3_scale(test_unit(g), test_range(g, 0.5, 3.0));
        prox_rcc r = {prox_v3_mad(c, -0.5, ax), ax, test_range(g, 0.2, 1.0)};
        return prox_shape_from_rcc(r);
    }
    if (kind == 2) {
        test_rot R = test_random_rot(g);
        prox_box b;
        prox_vec3 half = prox_v3(0, 0, 0);
        for (int i = 0; i < 3; ++i) {
            prox_vec3 e = prox_v3(R.m[0][i], R.m[1][i], R.m[2][i]);
            b.edge[i] = prox_v3_scale(e, test_range(g, 0.5, 2.0));
            half = prox_v3_mad(half, 0.5, b.edge[i]);
        }
        b.corner = prox_v3_sub(c, half);
        return prox_shape_from_box(b);
    }
    double hx = test_range(g, 0.2, 1), hy = test_range(g, 0.2, 1), hz = test_range(g, 0.2, 1);
    prox_rpp r = {c.x - hx, c.x + hx, c.y - hy, c.y + hy, c.z - hz, c.z + hz};
    return prox_shape_from_rpp(r);
}

/* A scene of n random bodies in a cube of side L. */
static prox_scene *random_scene(test_rng *g, size_t n, double L, prox_shape *copy)
{
    prox_scene *s = prox_scene_create();
    assert_non_null(s);
    for (size_t i = 0; i < n; ++i) {
        prox_shape b = random_body(g, prox_v3(test_range(g, 0, L), test_range(g, 0, L), test_range(g, 0, L)));
        assert_int_equal(prox_scene_add(s, &b), PROX_OK);
        if (copy) copy[i] = b;
    }
    return s;
}

static void test_scene_bounding_volumes(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(11);
    for (int k = 0; k < 400; ++k) {
        prox_shape s = random_body(&g, prox_v3(test_range(&g, -100, 100), test_range(&g, -100, 100), 0));
        prox_aabb b = prox_shape_aabb(&s);
        prox_sph bs = prox_shape_bounding_sphere(&s);
        const prox_vec3 axes[3] = {prox_v3(1, 0, 0), prox_v3(0, 1, 0), prox_v3(0, 0, 1)};
        /* tight: the box faces are the support values along +-axes */
        for (int i = 0; i < 3; ++i) {
            double hi = prox_shape_support(&s, axes[i]), lo = -prox_shape_support(&s, prox_v3_neg(axes[i]));
            double bhi = i == 0 ? b.hi.x : (i == 1 ? b.hi.y : b.hi.z), blo = i == 0 ? b.lo.x : (i == 1 ? b.lo.y : b.lo.z);
            assert_true(bhi >= hi - 1e-13 && blo <= lo + 1e-13); /* support values carry rounding too */
            assert_near(bhi, hi, 1e-12 * 100);
            assert_near(blo, lo, 1e-12 * 100);
        }
        /* contains: support points in random directions lie in both volumes */
        for (int j = 0; j < 20; ++j) {
            prox_vec3 p = prox_shape_support_point(&s, test_unit(&g));
            double out = fmax(fmax(fmax(b.lo.x - p.x, p.x - b.hi.x), fmax(b.lo.y - p.y, p.y - b.hi.y)),
                              fmax(b.lo.z - p.z, p.z - b.hi.z));
            if (out > 1e-13) print_error("kind %d sticks out by %g\n", s.kind, out), fail();
            if (!(prox_v3_dist(p, bs.center) <= bs.radius + 1e-14 * (prox_v3_maxabs(bs.center) + bs.radius))) print_error("kind %d dist %.17g radius %.17g\n", s.kind, prox_v3_dist(p, bs.center), bs.radius), fail();
        }
    }
}

/* Hand-made: two spheres 3 apart (radii 1 and 1.5: gap 0.5) and an overlapping pair. */
static void test_scene_modes_hand(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), 1.0});
    prox_shape b = prox_shape_from_sph((prox_sph){prox_v3(3, 0, 0), 1.5});
    prox_pair_result r = prox_pair_query(&a, &b, PROX_MODE_VERDICT, 0);
    assert_int_equal(r.status, PROX_OK);
    assert_int_equal(r.intersect, 0);
    assert_int_equal(r.decided_by, PROX_DECIDED_BOUNDS);
    r = prox_pair_query(&a, &b, PROX_MODE_CLOSER, 0.4);
    assert_int_equal(r.closer, 0);
    r = prox_pair_query(&a, &b, PROX_MODE_CLOSER, 0.6);
    assert_int_equal(r.closer, 1);
    assert_int_equal(r.decided_by, PROX_DECIDED_SUPPORT); /* upper bound 0.5 < 0.6: no exact query */
    r = prox_pair_query(&a, &b, PROX_MODE_DISTANCE, 0);
    assert_near(r.distance, 0.5, 1e-15);
    r = prox_pair_query(&a, &b, PROX_MODE_POINTS, 0);
    assert_near(r.p1.x, 1.0, 1e-15);
    assert_near(r.p2.x, 1.5, 1e-15);
    r = prox_pair_query(&a, &b, PROX_MODE_RELATION, 0);
    assert_int_equal(r.relation, PROX_REL_DISJOINT);
    assert_near(r.distance, 0.5, 1e-15);

    b.u.sph.center = prox_v3(2, 0, 0); /* depth 0.5 */
    r = prox_pair_query(&a, &b, PROX_MODE_SIGNED, 0);
    assert_near(r.signed_distance, -0.5, 1e-15);
    assert_near(r.depth, 0.5, 1e-15);
    assert_near(r.reposition.x, 0.5, 1e-15);
    r = prox_pair_query(&a, &b, PROX_MODE_RELATION, 0);
    assert_int_equal(r.relation, PROX_REL_CROSSING);
    assert_near(r.reposition.x, 0.5, 1e-15);
    assert_int_equal(r.intersect, 1);
    b.u.sph = (prox_sph){prox_v3(0.2, 0, 0), 0.3};
    r = prox_pair_query(&a, &b, PROX_MODE_RELATION, 0);
    assert_int_equal(r.relation, PROX_REL_B_IN_A);
    r = prox_pair_query(&a, &b, PROX_MODE_VERDICT, 0);
    assert_int_equal(r.intersect, 1);
}

/* Every mode on random pairs against direct calls of query.h. */
static void test_scene_modes_random(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(12);
    for (int k = 0; k < 300; ++k) {
        prox_shape a = random_body(&g, prox_v3(0, 0, 0));
        prox_shape b = random_body(&g, prox_v3_scale(test_unit(&g), test_range(&g, 0, 5)));
        prox_distance_result d = prox_shape_distance(&a, &b);
        prox_test_result t = prox_shape_test(&a, &b);
        assert_int_equal(d.status, PROX_OK);
        prox_pair_result r = prox_pair_query(&a, &b, PROX_MODE_VERDICT, 0);
        assert_int_equal(r.intersect, t.intersect);
        double thr = test_range(&g, 0, 2);
        if (fabs(d.distance - thr) > 1e-9) {
            r = prox_pair_query(&a, &b, PROX_MODE_CLOSER, thr);
            assert_int_equal(r.closer, d.distance <= thr);
        }
        r = prox_pair_query(&a, &b, PROX_MODE_POINTS, 0);
        assert_near(r.distance, d.distance, 0);
        assert_near(prox_v3_dist(r.p1, d.p1), 0, 0);
        r = prox_pair_query(&a, &b, PROX_MODE_SIGNED, 0);
        prox_signed_result s = prox_shape_signed_distance(&a, &b);
        assert_near(r.signed_distance, s.sd, 0);
        if (s.sd < 0) { /* moving b by the reposition leaves the pair touching */
            prox_shape moved = test_translate(&b, r.reposition);
            prox_signed_result s2 = prox_shape_signed_distance(&a, &moved);
            assert_near(s2.sd, 0, 1e-8 * 10);
        }
        r = prox_pair_query(&a, &b, PROX_MODE_RELATION, 0);
        prox_relation_result rel = prox_shape_relation(&a, &b, -1);
        assert_int_equal(r.relation, rel.relation);
    }
}

/* The broad phase must report exactly what the naive loop reports, with the same numbers. */
static void compare_reports(const prox_scene_report *x, const prox_scene_report *y)
{
    assert_int_equal(x->status, PROX_OK);
    assert_int_equal(y->status, PROX_OK);
    assert_int_equal(x->npairs, y->npairs);
    for (size_t i = 0; i < x->npairs; ++i) {
        assert_int_equal(x->pairs[i].a, y->pairs[i].a);
        assert_int_equal(x->pairs[i].b, y->pairs[i].b);
        assert_int_equal(x->pairs[i].r.intersect, y->pairs[i].r.intersect);
        assert_near(x->pairs[i].r.distance, y->pairs[i].r.distance, 0);
        assert_near(x->pairs[i].r.signed_distance, y->pairs[i].r.signed_distance, 0);
        assert_int_equal(x->pairs[i].r.relation, y->pairs[i].r.relation);
    }
}

static void test_scene_broad_phase_matches_naive(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(13);
    enum { N = 250 };
    prox_shape *body = malloc(N * sizeof *body);
    prox_scene *s = random_scene(&g, N, 18.0, body);
    struct {
        prox_query_mode mode;
        double c;
    } q[] = {{PROX_MODE_VERDICT, 0}, {PROX_MODE_CLOSER, 0.7}, {PROX_MODE_POINTS, 0.3},
             {PROX_MODE_SIGNED, 0.2}, {PROX_MODE_RELATION, 0.5}, {PROX_MODE_CLOSER, INFINITY}};
    for (size_t k = 0; k < sizeof q / sizeof q[0]; ++k) {
        prox_scene_report fast = prox_scene_pairs(s, q[k].c, q[k].mode);
        prox_scene_report slow = prox_scene_pairs_naive(s, q[k].c, q[k].mode);
        compare_reports(&fast, &slow);
        assert_int_equal(fast.stats.naive_pairs, N * (N - 1) / 2);
        if (q[k].c < INFINITY) assert_true(fast.stats.candidates < fast.stats.naive_pairs / 10);
        assert_true(fast.stats.exact <= fast.stats.candidates);
        if (k == 0) assert_true(fast.npairs > 5); /* the scene is dense enough to have collisions */
        if (k == 5) assert_int_equal(fast.npairs, fast.stats.naive_pairs);
        prox_scene_report_free(&fast);
        prox_scene_report_free(&slow);
    }
    /* Independently of the ladder: brute force over query.h. */
    prox_scene_report ver = prox_scene_intersecting(s, PROX_MODE_VERDICT);
    prox_scene_report near = prox_scene_pairs(s, 0.7, PROX_MODE_CLOSER);
    size_t iv = 0, in = 0;
    for (size_t i = 0; i < N; ++i)
        for (size_t j = i + 1; j < N; ++j) {
            int hit = prox_shape_test(&body[i], &body[j]).intersect;
            int reported = iv < ver.npairs && ver.pairs[iv].a == i && ver.pairs[iv].b == j;
            assert_int_equal(hit, reported);
            iv += (size_t)reported;
            double d = prox_shape_distance(&body[i], &body[j]).distance;
            reported = in < near.npairs && near.pairs[in].a == i && near.pairs[in].b == j;
            if (fabs(d - 0.7) > 1e-9) assert_int_equal(d <= 0.7, reported);
            in += (size_t)reported;
        }
    assert_int_equal(iv, ver.npairs);
    assert_int_equal(in, near.npairs);
    prox_scene_report_free(&ver);
    prox_scene_report_free(&near);
    prox_scene_destroy(s);
    free(body);
}

static void test_scene_nearest(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(14);
    for (int trial = 0; trial < 4; ++trial) {
        enum { N = 120 };
        prox_shape body[N];
        prox_scene *s = random_scene(&g, N, trial < 2 ? 60.0 : 15.0, body); /* sparse, then dense */
        double best = INFINITY;
        size_t ba = 0, bb = 0;
        for (size_t i = 0; i < N; ++i)
            for (size_t j = i + 1; j < N; ++j) {
                double d = prox_shape_distance(&body[i], &body[j]).distance;
                if (d < best) best = d, ba = i, bb = j;
            }
        prox_scene_report r = prox_scene_nearest(s);
        assert_int_equal(r.status, PROX_OK);
        assert_int_equal(r.npairs, 1);
        assert_near(r.pairs[0].r.distance, best, 0);
        if (best > 0) {
            assert_int_equal(r.pairs[0].a, ba);
            assert_int_equal(r.pairs[0].b, bb);
        }
        if (trial < 2) assert_true(r.stats.exact < r.stats.naive_pairs / 20);
        prox_scene_report_free(&r);
        prox_scene_destroy(s);
    }
    prox_scene *e = prox_scene_create();
    prox_scene_report r = prox_scene_nearest(e);
    assert_int_equal(r.npairs, 0);
    prox_scene_destroy(e);
}

/* Field-by-field equality (struct padding is unspecified). */
static void same_result(const prox_pair_result *x, const prox_pair_result *y)
{
    assert_int_equal(x->status, y->status);
    assert_int_equal(x->decided_by, y->decided_by);
    assert_int_equal(x->intersect, y->intersect);
    assert_int_equal(x->closer, y->closer);
    assert_true(x->distance == y->distance && x->signed_distance == y->signed_distance && x->depth == y->depth);
    assert_true(x->p1.x == y->p1.x && x->p2.z == y->p2.z && x->reposition.y == y->reposition.y);
}

static void test_scene_batch(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(15);
    enum { N = 2000 };
    prox_shape *a = malloc(N * sizeof *a), *b = malloc(N * sizeof *b);
    prox_pair_result *r1 = malloc(N * sizeof *r1), *r2 = malloc(N * sizeof *r2);
    for (size_t i = 0; i < N; ++i) {
        a[i] = random_body(&g, prox_v3(0, 0, 0));
        b[i] = random_body(&g, prox_v3_scale(test_unit(&g), test_range(&g, 0, 4)));
    }
    b[7].u.sph.radius = NAN; /* one bad pair: its own status, the rest unaffected */
    b[7].kind = PROX_SHAPE_SPH;
    for (int mode = PROX_MODE_VERDICT; mode <= PROX_MODE_SIGNED; ++mode) {
        assert_int_equal(prox_batch_query(a, b, N, (prox_query_mode)mode, 0.5, 1, r1), PROX_OK);
        assert_int_equal(prox_batch_query(a, b, N, (prox_query_mode)mode, 0.5, 2, r2), PROX_OK);
        for (size_t i = 0; i < N; ++i) {
            prox_pair_result one = prox_pair_query(&a[i], &b[i], (prox_query_mode)mode, 0.5);
            same_result(&r1[i], &one);
            same_result(&r2[i], &one);
        }
        assert_int_equal(r1[7].status, PROX_EINVAL_NONFINITE);
    }
    assert_int_equal(prox_batch_query(NULL, b, N, PROX_MODE_VERDICT, 0, 1, r1), PROX_EINVAL_ARG);
    assert_int_equal(prox_batch_query(NULL, NULL, 0, PROX_MODE_VERDICT, 0, 1, NULL), PROX_OK);
    free(a), free(b), free(r1), free(r2);
}

static void test_scene_invalid(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), 1.0});
    prox_shape bad = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), -1.0});
    assert_int_equal(prox_pair_query(&a, &bad, PROX_MODE_VERDICT, 0).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_pair_query(&a, &a, PROX_MODE_CLOSER, NAN).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_pair_query(&a, &a, PROX_MODE_CLOSER, -1).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_pair_query(&a, &a, (prox_query_mode)99, 0).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_pair_query(NULL, &a, PROX_MODE_VERDICT, 0).status, PROX_EINVAL_ARG);
    prox_scene *s = prox_scene_create();
    assert_int_equal(prox_scene_add(s, &bad), PROX_EINVAL_RADIUS);
    assert_int_equal(prox_scene_count(s), 0);
    assert_int_equal(prox_scene_add(s, &a), PROX_OK);
    assert_null(prox_scene_body(s, 1));
    prox_scene_report r = prox_scene_pairs(s, -2, PROX_MODE_VERDICT);
    assert_int_equal(r.status, PROX_EINVAL_ARG);
    r = prox_scene_pairs(s, 0, PROX_MODE_VERDICT);
    assert_int_equal(r.status, PROX_OK);
    assert_int_equal(r.npairs, 0);
    prox_scene_destroy(s);
    assert_int_equal(prox_scene_pairs(NULL, 0, PROX_MODE_VERDICT).status, PROX_EINVAL_ARG);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scene_bounding_volumes),
        cmocka_unit_test(test_scene_modes_hand),
        cmocka_unit_test(test_scene_modes_random),
        cmocka_unit_test(test_scene_broad_phase_matches_naive),
        cmocka_unit_test(test_scene_nearest),
        cmocka_unit_test(test_scene_batch),
        cmocka_unit_test(test_scene_invalid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
