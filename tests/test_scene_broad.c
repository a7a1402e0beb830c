/* Tests of the scene broad phase (src/scene/broad.c) and of the bounding volumes of all ten kinds
 * (prox_shape_aabb, prox_shape_bounding_sphere in src/scene/scene.c).
 *
 * The broad phase must hand on exactly the pairs a brute-force loop over all pairs finds (boxes that
 * come within c on every axis), in (a, b) order, on any thread count: random boxes of mixed sizes,
 * a huge box over everything, duplicates, boxes 1e6 away, clusters, and n = 0, 1, 2. A scene query
 * must report what the naive all-pairs query reports. The bounding volumes of the ten kinds must hold
 * points of the solid sampled from the card's own definition (rims, ellipses, corners), and the box
 * must be tight to those samples. */
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"
#include "core/tol.h"
#include "prox/scene.h"
#include "scene/broad.h"

/* ---- the broad phase against brute force --------------------------------------------------------- */

/* Brute force: every pair i < j with lo_j <= hi_i + c and lo_i <= hi_j + c on all three axes. */
static prox_broad_pair *brute_pairs(const prox_aabb *b, size_t n, double c, size_t *np)
{
    size_t cap = 64, m = 0;
    prox_broad_pair *v = malloc(cap * sizeof *v);
    assert_non_null(v);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            const prox_aabb *x = &b[i], *y = &b[j];
            if (y->lo.x <= x->hi.x + c && x->lo.x <= y->hi.x + c && y->lo.y <= x->hi.y + c &&
                x->lo.y <= y->hi.y + c && y->lo.z <= x->hi.z + c && x->lo.z <= y->hi.z + c) {
                if (m == cap) {
                    cap *= 2;
                    v = realloc(v, cap * sizeof *v);
                    assert_non_null(v);
                }
                v[m++] = (prox_broad_pair){i, j};
            }
        }
    *np = m;
    return v;
}

/* The broad phase on 1, 2 and 3 threads must return the brute-force list, element for element. */
static size_t check_against_brute(const prox_aabb *b, size_t n, double c)
{
    size_t nb = 0;
    prox_broad_pair *ref = brute_pairs(b, n, c, &nb);
    for (int threads = 1; threads <= 3; ++threads) {
        prox_broad_pair *got = NULL;
        size_t ng = 0;
        assert_int_equal(prox_broad_pairs(b, sizeof *b, n, c, threads, &got, &ng), 0);
        if (ng != nb) print_error("n = %zu, c = %g, threads %d: %zu pairs, brute force %zu\n", n, c, threads, ng, nb);
        assert_int_equal(ng, nb);
        for (size_t k = 0; k < nb; ++k) {
            if (got[k].a != ref[k].a || got[k].b != ref[k].b)
                print_error("pair %zu: (%zu, %zu), brute force (%zu, %zu)\n", k, got[k].a, got[k].b, ref[k].a, ref[k].b);
            assert_true(got[k].a == ref[k].a && got[k].b == ref[k].b);
        }
        assert_true(ng > 0 || got == NULL);
        free(got);
    }
    free(ref);
    return nb;
}

/* A box of half-sizes h around c. */
static prox_aabb box_at(prox_vec3 c, prox_vec3 h)
{
    prox_aabb b = {prox_v3_sub(c, h), prox_v3_add(c, h)};
    return b;
}

/* n boxes in a cube of side L with half-sizes log-uniform over [smin, smax]. */
static void random_boxes(test_rng *g, prox_aabb *b, size_t n, double L, double smin, double smax)
{
    for (size_t i = 0; i < n; ++i) {
        prox_vec3 c = prox_v3(test_range(g, 0, L), test_range(g, 0, L), test_range(g, 0, L));
        prox_vec3 h = prox_v3(smin * pow(smax / smin, test_uniform(g)), smin * pow(smax / smin, test_uniform(g)),
                              smin * pow(smax / smin, test_uniform(g)));
        b[i] = box_at(c, h);
    }
}

static void test_broad_small_counts(void **state)
{
    (void)state;
    prox_aabb b[2] = {box_at(prox_v3(0, 0, 0), prox_v3(1, 1, 1)), box_at(prox_v3(2.5, 0, 0), prox_v3(1, 1, 1))};
    prox_broad_pair *got = (prox_broad_pair *)&got;
    size_t ng = 7;
    assert_int_equal(prox_broad_pairs(b, sizeof *b, 0, 0.0, 2, &got, &ng), 0); /* n = 0 */
    assert_null(got);
    assert_int_equal(ng, 0);
    assert_int_equal(prox_broad_pairs(b, sizeof *b, 1, 1e300, 2, &got, &ng), 0); /* n = 1 */
    assert_null(got);
    assert_int_equal(ng, 0);
    assert_int_equal(check_against_brute(b, 2, 0.0), 0);  /* 0.5 apart on x */
    assert_int_equal(check_against_brute(b, 2, 0.5), 1);  /* exactly at the threshold: kept */
    assert_int_equal(check_against_brute(b, 2, 0.49), 0); /* just short of it */
    b[1] = b[0];                                          /* a duplicate */
    assert_int_equal(check_against_brute(b, 2, 0.0), 1);
}

static void test_broad_mixed_sizes(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(101);
    enum { N = 3000 };
    prox_aabb *b = malloc(N * sizeof *b);
    assert_non_null(b);
    random_boxes(&g, b, N, 60.0, 0.01, 3.0);
    size_t found = 0;
    const double cs[] = {0.0, 0.3, 2.0};
    for (int k = 0; k < 3; ++k) found += check_against_brute(b, N, cs[k]);
    assert_true(found > N); /* the scene is not trivially empty */
    free(b);
}

/* One huge box over everything, one thin slab across the scene, duplicates and far-away boxes. */
static void test_broad_awkward_scene(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(202);
    enum { N = 2500 };
    prox_aabb *b = malloc(N * sizeof *b);
    assert_non_null(b);
    random_boxes(&g, b, N, 40.0, 0.05, 1.0);
    b[17] = box_at(prox_v3(20, 20, 20), prox_v3(1e4, 1e4, 1e4));  /* a huge body */
    b[N - 1] = box_at(prox_v3(20, 20, 20), prox_v3(30, 0.01, 30)); /* a thin slab */
    for (size_t i = 100; i < 400; ++i) b[i] = b[i % 7 + 1000];      /* piles of duplicates */
    for (size_t i = 500; i < 530; ++i)                               /* bodies 1e6 away, some touching */
        b[i] = box_at(prox_v3(1e6 + 0.5 * (double)(i % 10), -1e6, 1e6 * (double)(i % 2)), prox_v3(0.3, 0.3, 0.3));
    for (size_t i = 600; i < 900; ++i) /* a dense cluster: everything overlaps everything */
        b[i] = box_at(prox_v3(5 + 1e-3 * (double)i, 5, 5), prox_v3(0.5, 0.5, 0.5));
    size_t found = check_against_brute(b, N, 0.0);
    assert_true(found > 300 * 299 / 2 + N); /* the cluster alone, and the huge body with all */
    check_against_brute(b, N, 0.25);
    free(b);
}

/* All centres equal: the median split cannot separate them by position and must still halve. */
static void test_broad_all_equal(void **state)
{
    (void)state;
    enum { N = 700 };
    prox_aabb *b = malloc(N * sizeof *b);
    assert_non_null(b);
    for (size_t i = 0; i < N; ++i) b[i] = box_at(prox_v3(3, -2, 1), prox_v3(1, 1, 1));
    assert_int_equal(check_against_brute(b, N, 0.0), (size_t)N * (N - 1) / 2);
    for (size_t i = 0; i < N; ++i) b[i] = box_at(prox_v3(0, 0, 2.0 * (double)i), prox_v3(1, 1, 1)); /* a column */
    assert_int_equal(check_against_brute(b, N, 0.0), N - 1); /* neighbours touch */
    free(b);
}

/* ---- scenes: broad phase against the naive all-pairs query --------------------------------------- */

/* A random body of kind RCC, BOX, RPP or SPH at c with sizes log-uniform over [s, 10 s]. */
static prox_shape old_kind_body(test_rng *g, prox_vec3 c, double s)
{
    int kind = (int)(test_uniform(g) * 4);
    double a = s * pow(10.0, test_uniform(g)), r = s * pow(10.0, test_uniform(g));
    if (kind == 0) return prox_shape_from_sph((prox_sph){c, r});
    if (kind == 1) {
        prox_vec3 ax = prox_v3_scale(test_unit(g), a);
        return prox_shape_from_rcc((prox_rcc){prox_v3_mad(c, -0.5, ax), ax, r});
    }
    if (kind == 2) {
        test_rot R = test_random_rot(g);
        prox_box b = {c, {prox_v3(0, 0, 0), prox_v3(0, 0, 0), prox_v3(0, 0, 0)}};
        for (int k = 0; k < 3; ++k)
            b.edge[k] = prox_v3_scale(test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2)), s * pow(10.0, test_uniform(g)));
        return prox_shape_from_box(b);
    }
    return prox_shape_from_rpp((prox_rpp){c.x - a, c.x + r, c.y - r, c.y + a, c.z - a, c.z + a});
}

/* The broad phase's candidates are the brute-force pairs of the bodies' boxes at the threshold plus
 * the documented slack; the report equals the naive one, pair for pair, on 1 and 2 threads. */
static void check_scene(prox_scene *sc, double clearance, prox_query_mode mode)
{
    size_t n = prox_scene_count(sc);
    prox_aabb *b = malloc((n ? n : 1) * sizeof *b);
    assert_non_null(b);
    double scale = 0.0;
    for (size_t i = 0; i < n; ++i) {
        b[i] = prox_shape_aabb(prox_scene_body(sc, i));
        scale = fmax(scale, fmax(prox_v3_maxabs(b[i].lo), prox_v3_maxabs(b[i].hi)));
    }
    size_t nb = 0;
    free(brute_pairs(b, n, clearance + 2 * PROX_TOL_BROAD * scale, &nb));
    free(b);
    prox_scene_report naive = prox_scene_pairs_naive(sc, clearance, mode);
    assert_int_equal(naive.status, PROX_OK);
    for (int threads = 1; threads <= 2; ++threads) {
        prox_scene_set_threads(sc, threads);
        prox_scene_report r = prox_scene_pairs(sc, clearance, mode);
        assert_int_equal(r.status, PROX_OK);
        assert_int_equal(r.stats.candidates, nb);
        assert_int_equal(r.npairs, naive.npairs);
        for (size_t k = 0; k < r.npairs; ++k) {
            const prox_scene_pair *p = &r.pairs[k], *q = &naive.pairs[k];
            assert_true(p->a == q->a && p->b == q->b);
            assert_int_equal(p->r.status, q->r.status);
            assert_int_equal(p->r.intersect, q->r.intersect);
            assert_int_equal(p->r.closer, q->r.closer);
            assert_true(p->r.distance == q->r.distance);
        }
        prox_scene_report_free(&r);
    }
    prox_scene_report_free(&naive);
}

static void test_scene_matches_naive(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(303);
    prox_scene *sc = prox_scene_create();
    assert_non_null(sc);
    for (size_t i = 0; i < 400; ++i) {
        prox_shape s = old_kind_body(&g, prox_v3(test_range(&g, 0, 30), test_range(&g, 0, 30), test_range(&g, 0, 30)), 0.1);
        assert_int_equal(prox_scene_add(sc, &s), PROX_OK);
        if (i % 50 == 0) assert_int_equal(prox_scene_add(sc, &s), PROX_OK); /* a duplicate */
    }
    prox_shape huge = prox_shape_from_sph((prox_sph){prox_v3(15, 15, 15), 1e3});
    prox_shape far = prox_shape_from_sph((prox_sph){prox_v3(1e6, 1e6, -1e6), 1.0});
    prox_shape far2 = prox_shape_from_rpp((prox_rpp){1e6 + 0.5, 1e6 + 2, 1e6 - 1, 1e6 + 1, -1e6 - 1, -1e6 + 1});
    assert_int_equal(prox_scene_add(sc, &huge), PROX_OK);
    assert_int_equal(prox_scene_add(sc, &far), PROX_OK);
    assert_int_equal(prox_scene_add(sc, &far2), PROX_OK);
    check_scene(sc, 0.0, PROX_MODE_VERDICT);
    check_scene(sc, 0.5, PROX_MODE_CLOSER);
    check_scene(sc, 0.2, PROX_MODE_DISTANCE);
    prox_scene_destroy(sc);
}

static void test_scene_tiny(void **state)
{
    (void)state;
    prox_scene *sc = prox_scene_create();
    assert_non_null(sc);
    check_scene(sc, 0.0, PROX_MODE_VERDICT); /* n = 0 */
    prox_shape a = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), 1});
    prox_shape b = prox_shape_from_sph((prox_sph){prox_v3(1.5, 0, 0), 1});
    assert_int_equal(prox_scene_add(sc, &a), PROX_OK);
    check_scene(sc, 0.0, PROX_MODE_VERDICT); /* n = 1 */
    assert_int_equal(prox_scene_add(sc, &b), PROX_OK);
    check_scene(sc, 0.0, PROX_MODE_VERDICT); /* n = 2 */
    prox_scene_report r = prox_scene_intersecting(sc, PROX_MODE_VERDICT);
    assert_int_equal(r.npairs, 1);
    prox_scene_report_free(&r);
    prox_scene_destroy(sc);
}

/* ---- bounding volumes of the ten kinds ------------------------------------------------------------ */

/* Points of the solid from the card's definition (not from the core's representation). */
typedef struct samples {
    prox_vec3 p[4096];
    int n;
} samples;

static void add(samples *s, prox_vec3 x)
{
    if (s->n < 4096) s->p[s->n++] = x;
}

/* Two unit vectors completing the unit w to an orthonormal frame. */
static void frame(prox_vec3 w, prox_vec3 *u, prox_vec3 *v)
{
    *u = prox_v3_any_perp(w);
    *u = prox_v3_scale(*u, 1.0 / prox_v3_norm(*u));
    *v = prox_v3_cross(w, *u);
}

/* The circle of radius r about centre o in the plane normal to w, at m angles. */
static void circle(samples *s, prox_vec3 o, prox_vec3 w, double r, int m)
{
    prox_vec3 u, v;
    frame(w, &u, &v);
    for (int k = 0; k < m; ++k) {
        double t = 2 * PROX_PI * k / m;
        add(s, prox_v3_add(o, prox_v3_add(prox_v3_scale(u, r * cos(t)), prox_v3_scale(v, r * sin(t)))));
    }
}

/* Corners of the RHP: the intersections of neighbouring side lines r_i . y = |r_i|^2 (sides r0, r1,
 * r2, -r0, -r1, -r2 in turn), at the base and at the top. */
static void rhp_corners(samples *s, const prox_rhp *h)
{
    prox_vec3 side[6] = {h->r[0], h->r[1], h->r[2], prox_v3_neg(h->r[0]), prox_v3_neg(h->r[1]), prox_v3_neg(h->r[2])};
    for (int i = 0; i < 6; ++i) {
        prox_vec3 a = side[i], b = side[(i + 1) % 6];
        double aa = prox_v3_dot(a, a), ab = prox_v3_dot(a, b), bb = prox_v3_dot(b, b), det = aa * bb - ab * ab;
        double al = (aa * bb - ab * bb) / det, be = (aa * bb - ab * aa) / det; /* y = al a + be b */
        prox_vec3 y = prox_v3_add(prox_v3_scale(a, al), prox_v3_scale(b, be));
        add(s, prox_v3_add(h->base, y));
        add(s, prox_v3_add(prox_v3_add(h->base, h->axis), y));
    }
}

/* A random valid shape of kind k around c (size about sz) and samples of its solid. */
static prox_shape sampled_shape(test_rng *g, int k, prox_vec3 c, double sz, samples *s)
{
    test_rot R = test_random_rot(g);
    prox_vec3 e0 = test_rot_apply(&R, prox_v3(1, 0, 0)), e1 = test_rot_apply(&R, prox_v3(0, 1, 0)),
              e2 = test_rot_apply(&R, prox_v3(0, 0, 1));
    double l0 = sz * test_range(g, 0.2, 1), l1 = sz * test_range(g, 0.2, 1), l2 = sz * test_range(g, 0.2, 1);
    prox_shape out;
    s->n = 0;
    switch (k) {
    case PROX_SHAPE_RCC: {
        prox_rcc x = {c, prox_v3_scale(e0, l0), l1};
        circle(s, c, e0, l1, 720), circle(s, prox_v3_add(c, x.axis), e0, l1, 720);
        return prox_shape_from_rcc(x);
    }
    case PROX_SHAPE_BOX: {
        prox_box x = {c, {prox_v3_scale(e0, l0), prox_v3_scale(e1, l1), prox_v3_scale(e2, l2)}};
        for (int m = 0; m < 8; ++m)
            add(s, prox_v3_add(c, prox_v3_add(prox_v3_scale(x.edge[0], m & 1),
                                              prox_v3_add(prox_v3_scale(x.edge[1], (m >> 1) & 1),
                                                          prox_v3_scale(x.edge[2], (m >> 2) & 1)))));
        return prox_shape_from_box(x);
    }
    case PROX_SHAPE_RPP: {
        prox_rpp x = {c.x, c.x + l0, c.y - l1, c.y, c.z - l2, c.z + l2};
        for (int m = 0; m < 8; ++m)
            add(s, prox_v3(m & 1 ? x.xmax : x.xmin, m & 2 ? x.ymax : x.ymin, m & 4 ? x.zmax : x.zmin));
        return prox_shape_from_rpp(x);
    }
    case PROX_SHAPE_SPH: {
        for (int m = 0; m < 2000; ++m) add(s, prox_v3_mad(c, l0, test_unit(g)));
        return prox_shape_from_sph((prox_sph){c, l0});
    }
    case PROX_SHAPE_TRC: {
        double r2 = test_uniform(g) < 0.3 ? 0.0 : l2; /* a pointed cone now and then */
        prox_trc x = {c, prox_v3_scale(e0, l0), l1, r2};
        circle(s, c, e0, l1, 720);
        if (r2 > 0) circle(s, prox_v3_add(c, x.axis), e0, r2, 720);
        else add(s, prox_v3_add(c, x.axis));
        out = prox_shape_from_trc(x);
        break;
    }
    case PROX_SHAPE_REC: {
        prox_rec x = {c, prox_v3_scale(e0, l0), prox_v3_scale(e1, fmax(l1, l2)), prox_v3_scale(e2, fmin(l1, l2))};
        for (int m = 0; m < 720; ++m) {
            double t = 2 * PROX_PI * m / 720;
            prox_vec3 y = prox_v3_add(prox_v3_scale(x.a1, cos(t)), prox_v3_scale(x.a2, sin(t)));
            add(s, prox_v3_add(c, y)), add(s, prox_v3_add(prox_v3_add(c, x.axis), y));
        }
        out = prox_shape_from_rec(x);
        break;
    }
    case PROX_SHAPE_ELL: {
        prox_ell x = {c, prox_v3_scale(e0, l0), l1};
        for (int m = 0; m < 3000; ++m) { /* the ellipsoid is the unit sphere stretched: l0 along e0, l1 across */
            prox_vec3 d = test_unit(g);
            add(s, prox_v3_add(c, prox_v3_add(prox_v3_scale(e0, l0 * d.x),
                                              prox_v3_add(prox_v3_scale(e1, l1 * d.y), prox_v3_scale(e2, l1 * d.z)))));
        }
        out = prox_shape_from_ell(x);
        break;
    }
    case PROX_SHAPE_RHP: {
        prox_rhp x;
        assert_int_equal(prox_rhp_regular(c, prox_v3_scale(e0, l0), prox_v3_scale(e1, l1), &x), PROX_OK);
        rhp_corners(s, &x);
        out = prox_shape_from_rhp(x);
        break;
    }
    case PROX_SHAPE_WED: {
        double t = test_range(g, 0.3, 2.8);
        prox_wed x = {c, prox_v3_scale(e1, l1), prox_v3_scale(prox_v3_add(prox_v3_scale(e1, cos(t)), prox_v3_scale(e2, sin(t))), l2),
                      prox_v3_scale(e0, l0)};
        prox_vec3 tri[3] = {c, prox_v3_add(c, x.v1), prox_v3_add(c, x.v2)};
        for (int m = 0; m < 3; ++m) add(s, tri[m]), add(s, prox_v3_add(tri[m], x.v3));
        out = prox_shape_from_wed(x);
        break;
    }
    default: { /* ARB: a cube through a random affine map (planar faces, convex), corners 1-8 */
        prox_arb x;
        memset(&x, 0, sizeof x);
        prox_vec3 col[3] = {prox_v3_scale(e0, l0), prox_v3_add(prox_v3_scale(e1, l1), prox_v3_scale(e0, 0.3 * l0)),
                            prox_v3_add(prox_v3_scale(e2, l2), prox_v3_scale(e1, -0.2 * l1))};
        for (int m = 0; m < 8; ++m) {
            x.corner[m] = prox_v3_add(c, prox_v3_add(prox_v3_scale(col[0], m & 1),
                                                     prox_v3_add(prox_v3_scale(col[1], (m >> 1) & 1),
                                                                 prox_v3_scale(col[2], (m >> 2) & 1))));
            add(s, x.corner[m]);
        }
        const int faces[6] = {1375, 2486, 1265, 3487, 1243, 5687};
        memcpy(x.face, faces, sizeof faces);
        out = prox_shape_from_arb(x);
        break;
    }
    }
    return out;
}

/* Every sample lies in the box and in the sphere; the box is tight to the samples (to `slack` of
 * the size: sampled curves miss the extreme by up to the sampling step), and so is the sphere to 2x. */
static void check_volumes(const prox_shape *sh, const samples *s, double sz, double slack)
{
    prox_status st = prox_shape_validate(sh);
    if (st != PROX_OK) print_error("%s (size %g): %s\n", prox_shape_kind_name(sh->kind), sz, prox_status_str(st));
    assert_int_equal(st, PROX_OK);
    prox_aabb b = prox_shape_aabb(sh);
    prox_sph sp = prox_shape_bounding_sphere(sh);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, far = 0.0;
    for (int i = 0; i < s->n; ++i) {
        prox_vec3 x = s->p[i];
        double e = 4 * DBL_EPSILON * prox_v3_maxabs(x); /* the sample's own rounding */
        int in = b.lo.x - e <= x.x && x.x <= b.hi.x + e && b.lo.y - e <= x.y && x.y <= b.hi.y + e && b.lo.z - e <= x.z &&
                 x.z <= b.hi.z + e;
        if (!in)
            print_error("%s: sample %d (%.17g %.17g %.17g) outside the box (size %g)\n", prox_shape_kind_name(sh->kind), i,
                        x.x, x.y, x.z, sz);
        assert_true(in);
        if (!(prox_v3_dist(x, sp.center) <= sp.radius + e))
            print_error("%s: sample %d at %.17g from the centre, radius %.17g (size %g)\n", prox_shape_kind_name(sh->kind),
                        i, prox_v3_dist(x, sp.center), sp.radius, sz);
        assert_true(prox_v3_dist(x, sp.center) <= sp.radius + e);
        lo[0] = fmin(lo[0], x.x), lo[1] = fmin(lo[1], x.y), lo[2] = fmin(lo[2], x.z);
        hi[0] = fmax(hi[0], x.x), hi[1] = fmax(hi[1], x.y), hi[2] = fmax(hi[2], x.z);
        far = fmax(far, prox_v3_dist(x, sp.center));
    }
    double tol = slack * sz;
    assert_near(b.lo.x, lo[0], tol);
    assert_near(b.lo.y, lo[1], tol);
    assert_near(b.lo.z, lo[2], tol);
    assert_near(b.hi.x, hi[0], tol);
    assert_near(b.hi.y, hi[1], tol);
    assert_near(b.hi.z, hi[2], tol);
    /* the reference point need not be the centre of the smallest sphere: within 2x of the farthest sample */
    assert_true(sp.radius <= 2.0 * far + tol);
}

static void test_bounding_volumes_all_kinds(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(404);
    static samples s;
    for (int k = 0; k < PROX_SHAPE_KIND_COUNT_; ++k)
        for (int rep = 0; rep < 60; ++rep) {
            /* far bodies (1e6 away) no smaller than 10: a card's corners are planar to its digits */
            double sz = rep % 3 == 0 ? pow(10.0, test_range(&g, 1, 3)) : pow(10.0, test_range(&g, -3, 3));
            double off = rep % 3 == 0 ? 1e6 : (rep % 3 == 1 ? 0.0 : 10 * sz);
            prox_vec3 c = prox_v3_scale(test_unit(&g), off);
            prox_shape sh = sampled_shape(&g, k, c, sz, &s);
            /* polytopes: exact corners (rounding only); curves: 720 steps miss by 1 - cos(pi / 720) */
            int curved = k == PROX_SHAPE_RCC || k == PROX_SHAPE_SPH || k == PROX_SHAPE_TRC || k == PROX_SHAPE_REC ||
                         k == PROX_SHAPE_ELL;
            double slack = curved ? (k == PROX_SHAPE_SPH || k == PROX_SHAPE_ELL ? 0.2 : 2e-5) : 0.0;
            slack += 1e-12 * (1.0 + off / sz);
            check_volumes(&sh, &s, sz, slack);
        }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_broad_small_counts),     cmocka_unit_test(test_broad_mixed_sizes),
        cmocka_unit_test(test_broad_awkward_scene),    cmocka_unit_test(test_broad_all_equal),
        cmocka_unit_test(test_scene_matches_naive),    cmocka_unit_test(test_scene_tiny),
        cmocka_unit_test(test_bounding_volumes_all_kinds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
