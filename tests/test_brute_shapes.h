/* Shared checks of the solid-against-sphere tests (test_box_sph.c, test_rcc_sph.c): the long-double
 * toolkit of test_brute.h plus lmad, and the assertions both tests make on one pair, written once
 * against the test's own brute-force signed distance of a point to the solid (passed in as `sdf`).
 * Nothing here computes a reference answer from the library: the reference is always `sdf`, written in
 * the test file; the library is called only as the query under test (and prox_shape_pair_scale for the
 * tolerance scale). */
#ifndef PROX_TEST_BRUTE_SHAPES_H
#define PROX_TEST_BRUTE_SHAPES_H

#include "test_brute.h"
#include "prox/query.h"

static inline lv3 lmad(lv3 a, ld s, lv3 b) { lv3 r = {a.x + s * b.x, a.y + s * b.y, a.z + s * b.z}; return r; }

/* Brute-force signed distance of x to a solid (negative inside) and its nearest boundary point *q. */
typedef ld (*tbs_signed_fn)(const void *solid, lv3 x, lv3 *q);

/* The solid A of a pair: as a generic shape, and as the test's own data for its brute force. */
typedef struct tbs_solid {
    prox_shape shape;
    const void *solid;
    tbs_signed_fn sdf;
} tbs_solid;

/* The pair's scale (tolerances are relative to it). */
static inline double tbs_sph_pair_scale(const tbs_solid *A, const prox_sph *s)
{
    prox_shape B = prox_shape_from_sph(*s);
    return prox_shape_pair_scale(&A->shape, &B);
}

/* Distance result d of A and sphere s against the brute force: distance, points and certificate when
 * disjoint, a common point when overlapping (counted in *n_dis / *n_ov). Returns the brute signed
 * distance sd of the pair. */
static inline ld tbs_check_sph_distance(const tbs_solid *A, const prox_sph *s, prox_distance_result d, int *n_dis,
                                        int *n_ov)
{
    double S = tbs_sph_pair_scale(A, s), tol = 1e-12 * S;
    lv3 q, tmp;
    ld sd = A->sdf(A->solid, L(s->center), &q) - s->radius;
    assert_int_equal(d.status, PROX_OK);
    if (sd > tol) {
        ++*n_dis;
        assert_false(d.intersect);
        assert_near(d.distance, (double)sd, tol);
        assert_near(prox_v3_dist(d.p1, d.p2), d.distance, tol);
        assert_true(A->sdf(A->solid, L(d.p1), &tmp) <= tol);                  /* p1 in A */
        assert_near(prox_v3_dist(d.p2, s->center), s->radius, tol);          /* p2 on the sphere */
        assert_near(prox_v3_dist(d.p1, prox_v3(q.x, q.y, q.z)), 0.0, 4 * tol); /* unique closest point */
        assert_near(d.certificate_gap, d.distance, tol);
    } else if (sd < -tol) {
        ++*n_ov;
        assert_true(d.intersect);
        assert_true(A->sdf(A->solid, L(d.p1), &tmp) <= tol);
        assert_true(prox_v3_dist(d.p1, s->center) <= s->radius + tol);
    }
    return sd;
}

/* Signed result r of A and sphere s against the brute signed distance sd: value, unit normal,
 * p2 = p1 + sd n, p1 on A's boundary, p2 on the sphere. */
static inline void tbs_check_sph_signed(const tbs_solid *A, const prox_sph *s, prox_signed_result r, ld sd)
{
    double S = tbs_sph_pair_scale(A, s), tol = 1e-12 * S;
    lv3 tmp;
    assert_int_equal(r.status, PROX_OK);
    assert_near(r.sd, (double)sd, sd < 0 ? 1e-9 * S : tol);
    assert_near(prox_v3_norm(r.normal), 1.0, 1e-14);
    assert_near(prox_v3_dist(r.p2, prox_v3_mad(r.p1, r.sd, r.normal)), 0.0, 4 * tol);
    assert_near((double)A->sdf(A->solid, L(r.p1), &tmp), 0.0, tol); /* p1 on A's boundary */
    assert_near(prox_v3_dist(r.p2, s->center), s->radius, tol);
}

/* Repositioning the sphere away from A leaves exactly the margin 0.05 x scale (or nothing moves). */
static inline void tbs_check_sph_reposition(const tbs_solid *A, const prox_sph *s, ld sd)
{
    double S = tbs_sph_pair_scale(A, s);
    lv3 tmp;
    prox_shape B = prox_shape_from_sph(*s);
    double margin = 0.05 * S;
    prox_reposition_result rp = prox_shape_reposition(&A->shape, &B, margin);
    assert_int_equal(rp.status, PROX_OK);
    prox_shape B2 = test_translate(&B, rp.translation);
    ld after = A->sdf(A->solid, L(B2.u.sph.center), &tmp) - s->radius;
    assert_near((double)after, rp.moved ? margin : (double)sd, 1e-9 * S);
}

#endif
