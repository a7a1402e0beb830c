/* A polytope (BOX, RPP, RHP, WED, ARB) against a curved body (RCC, TRC, REC, ELL): the public distance
 * and signed distance, which take the projections and feature pairs of src/distance/poly_body.c
 * (every such pair but BOX-RCC and RPP-RCC: box_rcc.c, with the engine behind the disjoint answers it
 * leaves uncertified, 30-40 % of the pairs 1e-10 .. 1e-3 S apart), against the full
 * support-function engine (prox_convex_distance_full: its local search and every candidate normal),
 * in both orders, on near pairs (disjoint and overlapping), pairs moved 1e-10 .. 1e-3 S apart along
 * the engine's normal, touching pairs, and near pairs 1e6 sizes from the origin.
 *
 * Every answer: the same verdict (outside the touching band), certified; a disjoint one within
 * 1e-12 S of the engine's distance, its witnesses in the solids with |p2 - p1| = distance, its lower
 * bound below the engine's distance; a common point in both solids. The signed distance of a
 * disjoint pair: sd = distance, a unit normal with p2 - p1 = sd normal, sd_lower <= sd <= sd_upper.
 * The fast path itself (prox_poly_body_fast, called on the same bodies) must settle most near
 * disjoint pairs, and whatever it settles must be right: a MEET point in both solids, a DISJOINT pair
 * within the bar of the engine's distance. */
#include "test_util.h"

#include <float.h>

#include "core/body.h"
#include "core/polytope.h"
#include "core/tol.h"
#include "distance/poly_internal.h"
#include "prox/query.h"
#include "sat/convex.h"

#define BAR 1e-12 /* the accuracy bar of distances and points, in units of S */

static const int k_poly[] = {PROX_SHAPE_BOX, PROX_SHAPE_RPP, PROX_SHAPE_RHP, PROX_SHAPE_WED, PROX_SHAPE_ARB};
static const int k_body[] = {PROX_SHAPE_RCC, PROX_SHAPE_TRC, PROX_SHAPE_REC, PROX_SHAPE_ELL};

typedef struct stats {
    int pairs, disjoint, fast_disjoint, overlapping, fast_meet;
    double err_d, err_w;
} stats;

/* The fast path on its own, the polytope and the body as the query builds them; its settled
 * answers checked against the engine's (g). */
static void check_fast(const prox_shape *ps, const prox_shape *bs, const prox_distance_result *g, double S, double tol,
                       stats *st)
{
    prox_polytope P;
    prox_vec3 cp;
    assert_int_equal(prox_polytope_checked(ps, &P, &cp), PROX_OK);
    prox_body body = prox_body_make(bs), poly = prox_body_of_polytope(&P, cp);
    prox_distance_result r = {0};
    double Sb = fmax(prox_v3_dist(cp, body.c), fmax(P.size, body.size));
    int v = prox_poly_body_fast(&P, cp, &body, Sb, &r);
    if (v == PROX_PB_MEET) {
        st->fast_meet++;
        assert_true(prox_body_contains(&poly, r.p1, tol) && prox_body_contains(&body, r.p1, tol));
        assert_true(g->intersect || g->distance <= tol); /* the engine sees a common point too */
    } else if (v == PROX_PB_DISJOINT) {
        st->fast_disjoint++;
        assert_false(g->intersect);
        if (!(fabs(r.distance - g->distance) <= tol)) {
            print_error("fast %.17g engine %.17g (diff/S %.3g)\n", r.distance, g->distance, fabs(r.distance - g->distance) / S);
            fail();
        }
        assert_true(r.distance - r.certificate_gap <= PROX_TOL_CERT * Sb * 1.0001);
    }
}

static void check_pair(const prox_shape *sa, const prox_shape *sb, int poly_first, stats *st)
{
    assert_int_equal(prox_shape_validate(sa), PROX_OK);
    assert_int_equal(prox_shape_validate(sb), PROX_OK);
    prox_body a = prox_body_make(sa), b = prox_body_make(sb);
    double S = prox_shape_pair_scale(sa, sb);
    prox_convex_info gi;
    prox_distance_result f = prox_shape_distance(sa, sb), g = prox_convex_distance_full(&a, &b, &gi);
    assert_int_equal(f.status, PROX_OK);
    assert_int_equal(g.status, PROX_OK);
    st->pairs++;
    /* the bar, and the rounding of the input coordinates of a pair far from the origin */
    double tol = BAR * S + 16.0 * DBL_EPSILON * prox_v3_norm(f.p1);
    check_fast(poly_first ? sa : sb, poly_first ? sb : sa, &g, S, tol, st);
    if (f.intersect || g.intersect) {
        /* the same verdict outside the touching band */
        assert_true(f.intersect ? (g.intersect || g.distance <= tol) : f.distance <= tol);
        if (f.intersect) {
            st->overlapping++;
            assert_true(f.certified);
            assert_true(prox_body_contains(&a, f.p1, tol) && prox_body_contains(&b, f.p1, tol));
        }
        return;
    }
    st->disjoint++;
    if (!(f.certified && fabs(f.distance - g.distance) <= tol)) {
        print_error("kinds %d %d: certified %d distance %.17g engine %.17g (diff/S %.3g)\n", sa->kind, sb->kind, f.certified,
                    f.distance, g.distance, fabs(f.distance - g.distance) / S);
        fail();
    }
    assert_true(f.certificate_gap <= g.distance + PROX_TOL_CERT * S + tol);
    assert_true(prox_body_contains(&a, f.p1, tol));
    assert_true(prox_body_contains(&b, f.p2, tol));
    double ew = fabs(prox_v3_dist(f.p1, f.p2) - f.distance);
    assert_true(ew <= 2.0 * tol);
    st->err_d = fmax(st->err_d, fabs(f.distance - g.distance) / S);
    st->err_w = fmax(st->err_w, ew / S);
    /* the signed distance of the disjoint pair */
    prox_signed_result s = prox_shape_signed_distance(sa, sb);
    assert_int_equal(s.status, PROX_OK);
    assert_near(s.sd, f.distance, tol);
    assert_near(prox_v3_norm(s.normal), 1.0, 1e-12);
    assert_true(prox_v3_norm(prox_v3_sub(prox_v3_sub(s.p2, s.p1), prox_v3_scale(s.normal, s.sd))) <= 2.0 * tol);
    assert_true(s.sd_lower <= s.sd && s.sd <= s.sd_upper);
}

/* Families: 0 near (B 0.05 .. 2 sizes of A away), 1 close (moved 1e-10 .. 1e-3 S apart along the
 * engine's normal), 2 touching (moved into contact), 3 near pairs 1e6 sizes from the origin. */
static void make_pair(test_rng *g, int fam, int ka, int kb, prox_shape *a, prox_shape *b)
{
    prox_vec3 o = fam == 3 ? prox_v3_scale(test_unit(g), 1e6 * test_range(g, 1.0, 10.0)) : prox_v3(0, 0, 0);
    *a = test_any_shape(g, ka, o);
    double sz = prox_shape_size(a);
    *b = test_any_shape(g, kb, prox_v3_mad(o, sz * exp(test_range(g, log(0.05), log(2.0))), test_unit(g)));
    if (fam == 0 || fam == 3) return;
    prox_body ba = prox_body_make(a), bb = prox_body_make(b);
    prox_signed_result r = prox_convex_signed(&ba, &bb);
    double S = prox_shape_pair_scale(a, b), gap = fam == 1 ? S * exp(test_range(g, log(1e-10), log(1e-3))) : 0.0;
    *b = test_translate(b, prox_v3_scale(r.normal, gap - r.sd));
}

static void run_family(int fam, int per_kind, uint64_t seed)
{
    static const char *const names[] = {"near", "close", "touching", "far-from-origin"};
    test_rng g = test_rng_seed(seed);
    stats st = {0};
    for (size_t i = 0; i < sizeof k_poly / sizeof k_poly[0]; ++i)
        for (size_t j = 0; j < sizeof k_body / sizeof k_body[0]; ++j)
            for (int n = 0; n < per_kind; ++n) {
                prox_shape a, b;
                int swap = n & 1;
                make_pair(&g, fam, swap ? k_body[j] : k_poly[i], swap ? k_poly[i] : k_body[j], &a, &b);
                check_pair(&a, &b, !swap, &st);
            }
    printf("%-16s pairs %5d disjoint %5d (fast path %5d) overlapping %5d (fast path %5d)  max |distance - engine|/S %.2g  "
           "max ||p2-p1| - distance|/S %.2g\n",
           names[fam], st.pairs, st.disjoint, st.fast_disjoint, st.overlapping, st.fast_meet, st.err_d, st.err_w);
    assert_true(st.disjoint > 0);
    /* the point of the fast path: it settles most near pairs, disjoint and overlapping; of the pairs
     * 1e-10 .. 1e-3 S apart the ones whose closest features are smooth enough that the pair's own
     * direction certifies it (a corner or a rim 1e-8 S away knows its normal only to eps S / 1e-8 S),
     * none of the touching ones (within the band, either verdict) */
    if (fam == 0) assert_true(st.fast_disjoint * 10 > st.disjoint * 9 && st.fast_meet * 10 > st.overlapping * 9);
    if (fam == 1) assert_true(st.fast_disjoint * 5 > st.disjoint);
}

static void test_near(void **state) { (void)state; run_family(0, 60, 501); }
static void test_close(void **state) { (void)state; run_family(1, 30, 502); }
static void test_touching(void **state) { (void)state; run_family(2, 20, 503); }
static void test_far_from_origin(void **state) { (void)state; run_family(3, 20, 504); }

/* A hand case: a unit cube's face 0.5 below an RCC's bottom disk (a face-disk contact, flat against
 * flat: the support points are the disk's centre and its foot on the face), and the same RCC tilted
 * so that its rim touches the face at one point. Distances in closed form. */
static void test_face_contacts(void **state)
{
    (void)state;
    prox_shape cube = prox_shape_from_box((prox_box){prox_v3(-1, -1, -1), {prox_v3(2, 0, 0), prox_v3(0, 2, 0), prox_v3(0, 0, 2)}});
    prox_rhp hx;
    assert_int_equal(prox_rhp_regular(prox_v3(0, 0, -1), prox_v3(0, 0, 2), prox_v3(1, 0, 0), &hx), PROX_OK);
    prox_shape hex = prox_shape_from_rhp(hx);
    prox_shape cyl = prox_shape_from_rcc((prox_rcc){prox_v3(0.2, 0.1, 1.5), prox_v3(0, 0, 3), 0.5});
    const prox_shape *polys[2] = {&cube, &hex};
    for (int k = 0; k < 2; ++k) {
        prox_distance_result d = prox_shape_distance(polys[k], &cyl);
        assert_int_equal(d.status, PROX_OK);
        assert_false(d.intersect);
        assert_true(d.certified);
        assert_near(d.distance, 0.5, 1e-15);
        assert_near(d.p1.z, 1.0, 1e-15);
        assert_near(d.p2.z, 1.5, 1e-15);
    }
    /* tilted by 30 degrees about x: the lowest rim point is 0.5 sin 30 below the base centre */
    double c = cos(PROX_PI / 6), s = sin(PROX_PI / 6);
    prox_shape tilt = prox_shape_from_rcc((prox_rcc){prox_v3(0.2, 0.1, 1.5), prox_v3(0, -3 * s, 3 * c), 0.5});
    prox_distance_result d = prox_shape_distance(&hex, &tilt);
    assert_int_equal(d.status, PROX_OK);
    assert_true(d.certified);
    assert_near(d.distance, 0.5 - 0.5 * s, 1e-15);
    prox_signed_result r = prox_shape_signed_distance(&tilt, &hex); /* the other order */
    assert_near(r.sd, 0.5 - 0.5 * s, 1e-15);
    assert_near(r.normal.z, -1.0, 1e-15);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_near),           cmocka_unit_test(test_close),      cmocka_unit_test(test_touching),
        cmocka_unit_test(test_far_from_origin), cmocka_unit_test(test_face_contacts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
