/* Polytope-polytope distance and signed distance (distance/poly_internal.h) against independent
 * long-double checks on the card definitions (test_poly_brute.h):
 *  - disjoint: p1, p2 on the two boundaries, |p2 - p1| equal to the exhaustive long-double minimum
 *    over corner-solid and edge-edge pairs, and (above 1e-3 S, where the direction p2 - p1 is
 *    accurate to 1e-13) the support-function dual bound s(n) near n = (p2 - p1) / |p2 - p1| meeting it;
 *  - overlapping: the common point in both solids; the depth's witnesses p2 - p1 = sd n on the two
 *    boundaries, s(n) = sd (moving B by -sd n separates), and no direction of a dense sample of the
 *    sphere, refined locally, separates better (sd is the largest separation);
 *  - BOX pairs against the box-box solver; symmetry under exchange and translation; motion along
 *    the normal; hand-made RPP cases; touching contacts; near-degenerate bodies. */
#include "core/polytope.h"
#include "distance/poly_internal.h"
#include "test_poly_brute.h"

typedef struct pp_case {
    prox_shape sa, sb;
    prox_polytope a, b;
    prox_vec3 ca, cb;
    tp_body A, B;
    double S;
} pp_case;

static void pp_make(pp_case *c, const prox_shape *sa, const prox_shape *sb)
{
    c->sa = *sa;
    c->sb = *sb;
    assert_int_equal(prox_shape_validate(sa), PROX_OK);
    assert_int_equal(prox_shape_validate(sb), PROX_OK);
    c->ca = prox_polytope_make(sa, &c->a);
    c->cb = prox_polytope_make(sb, &c->b);
    c->A = tp_from_shape(sa);
    c->B = tp_from_shape(sb);
    c->S = fmax(prox_v3_dist(c->ca, c->cb), fmax(c->a.size, c->b.size));
}

/* Largest separation of B from A over a Fibonacci sample of the sphere, refined by a shrinking
 * pattern search about the best few directions. */
static ld brute_max_sep(const tp_body *A, const tp_body *B, int n)
{
    ld best = -INFINITY;
    lv3 top[4];
    ld topv[4] = {-INFINITY, -INFINITY, -INFINITY, -INFINITY};
    const ld ga = 3.14159265358979323846L * (3.0L - sqrtl(5.0L));
    for (int i = 0; i < n; ++i) {
        ld z = 1.0L - 2.0L * (i + 0.5L) / n, r = sqrtl(1.0L - z * z);
        lv3 d = {r * cosl(ga * i), r * sinl(ga * i), z};
        ld s = tp_sep(A, B, d);
        for (int k = 0; k < 4; ++k)
            if (s > topv[k]) {
                for (int m = 3; m > k; --m) topv[m] = topv[m - 1], top[m] = top[m - 1];
                topv[k] = s, top[k] = d;
                break;
            }
    }
    for (int k = 0; k < 4; ++k) {
        lv3 d = top[k];
        ld s = topv[k], step = 0.05L;
        for (int iter = 0; iter < 3000 && step > 1e-15L; ++iter) {
            lv3 e1 = lunit(lcross(d, fabsl(d.x) < 0.6L ? (lv3){1, 0, 0} : (lv3){0, 1, 0})), e2 = lcross(d, e1);
            int moved = 0;
            for (int j = 0; j < 8; ++j) {
                ld th = j * 3.14159265358979323846L / 4;
                lv3 t = lunit(ladd(d, lsc(ladd(lsc(e1, cosl(th)), lsc(e2, sinl(th))), step)));
                ld st = tp_sep(A, B, t);
                if (st > s) s = st, d = t, moved = 1;
            }
            if (!moved) step *= 0.5L;
        }
        best = fmaxl(best, s);
    }
    return best;
}

static lv3 labs3(prox_vec3 p) { return L(p); }

/* The separation along n0, raised by a shrinking pattern search about n0 (the computed direction
 * p2 - p1 of a tiny distance d carries a rounding of eps S / d, which tilts it off the maximum). */
static ld refine_sep(const tp_body *A, const tp_body *B, lv3 d)
{
    ld s = tp_sep(A, B, d), step = 1e-4L;
    for (int iter = 0; iter < 3000 && step > 1e-17L; ++iter) {
        lv3 e1 = lunit(lcross(d, fabsl(d.x) < 0.6L ? (lv3){1, 0, 0} : (lv3){0, 1, 0})), e2 = lcross(d, e1);
        int moved = 0;
        for (int j = 0; j < 8; ++j) {
            ld th = j * 3.14159265358979323846L / 4;
            lv3 t = lunit(ladd(d, lsc(ladd(lsc(e1, cosl(th)), lsc(e2, sinl(th))), step)));
            ld st = tp_sep(A, B, t);
            if (st > s) s = st, d = t, moved = 1;
        }
        if (!moved) step *= 0.5L;
    }
    return s;
}

/* The distance answer, checked as in the file comment. Returns 1 when disjoint. */
static int check_distance(const pp_case *c, prox_distance_result d)
{
    double S = c->S;
    assert_int_equal(d.status, PROX_OK);
    if (d.intersect) {
        assert_true(d.distance == 0.0);
        assert_true(prox_v3_dist(d.p1, d.p2) == 0.0);
        assert_true(tp_resid(&c->A, labs3(d.p1)) <= 1e-12L * S);
        assert_true(tp_resid(&c->B, labs3(d.p1)) <= 1e-12L * S);
        assert_true(d.certified);
        return 0;
    }
    assert_near((double)tp_resid(&c->A, L(d.p1)), 0.0, 1e-12 * S);
    assert_near((double)tp_resid(&c->B, L(d.p2)), 0.0, 1e-12 * S);
    lv3 dd = lsub(L(d.p2), L(d.p1));
    ld len = lnorm(dd);
    assert_near(d.distance, (double)len, 1e-12 * S);
    assert_true(len > 0);
    ld ref = tp_distance(&c->A, &c->B); /* exhaustive, independent */
    assert_near(d.distance, (double)ref, 1e-12 * S);
    ld gap = refine_sep(&c->A, &c->B, lsc(dd, 1.0L / len));
    if (len > 1e-3L * S) assert_near((double)gap, (double)len, 1e-12 * S); /* the dual bound meets it */
    assert_true(d.certified);
    assert_true(d.certificate_gap <= ref + 1e-12L * S); /* a lower bound */
    assert_true(d.distance - d.certificate_gap <= 1e-12 * S);
    return 1;
}

static void check_signed(const pp_case *c, prox_signed_result r, prox_distance_result d)
{
    double S = c->S;
    assert_int_equal(r.status, PROX_OK);
    assert_near(prox_v3_norm(r.normal), 1.0, 1e-12);
    if (!d.intersect) {
        assert_near(r.sd, d.distance, 1e-12 * S);
        assert_true(r.sd > 0.0);
    } else {
        assert_true(r.sd <= 1e-12 * S);
    }
    lv3 res = lsub(lsub(L(r.p2), L(r.p1)), lsc(L(r.normal), r.sd));
    assert_near((double)lnorm(res), 0.0, (r.sd > 0 ? 1e-12 : 1e-9) * S);
    assert_near((double)tp_resid(&c->A, L(r.p1)), 0.0, 1e-9 * S);
    assert_near((double)tp_resid(&c->B, L(r.p2)), 0.0, 1e-9 * S);
    ld s_n = tp_sep(&c->A, &c->B, lunit(L(r.normal)));
    assert_near((double)s_n, r.sd, 1e-9 * S);
    if (r.sd <= 0.0) {
        ld bm = brute_max_sep(&c->A, &c->B, 3000);
        if (!(bm <= r.sd + 1e-9L * S)) {
            print_error("a direction separates better: %.17Lg > sd %.17g (S %g)\n", bm, r.sd, S);
            fail();
        }
    }
}

/* Both queries on the pair, then exchange and translation symmetry. Returns 1 when disjoint. */
static int check_pair(const prox_shape *sa, const prox_shape *sb)
{
    pp_case c;
    pp_make(&c, sa, sb);
    prox_distance_result d = prox_poly_distance(&c.a, c.ca, &c.b, c.cb);
    prox_signed_result r = prox_poly_signed(&c.a, c.ca, &c.b, c.cb);
    int dis = check_distance(&c, d);
    check_signed(&c, r, d);
    /* exchange: the same distance and signed distance, the normal reversed */
    prox_distance_result d2 = prox_poly_distance(&c.b, c.cb, &c.a, c.ca);
    prox_signed_result r2 = prox_poly_signed(&c.b, c.cb, &c.a, c.ca);
    assert_int_equal(d2.intersect, d.intersect);
    assert_near(d2.distance, d.distance, 1e-12 * c.S);
    assert_near(r2.sd, r.sd, (r.sd > 0 ? 1e-12 : 1e-9) * c.S);
    /* translation of both: the same answers, moved */
    prox_vec3 T = prox_v3(3.25 * c.S, -1.5 * c.S, 0.75 * c.S);
    prox_distance_result d3 = prox_poly_distance(&c.a, prox_v3_add(c.ca, T), &c.b, prox_v3_add(c.cb, T));
    prox_signed_result r3 = prox_poly_signed(&c.a, prox_v3_add(c.ca, T), &c.b, prox_v3_add(c.cb, T));
    assert_near(d3.distance, d.distance, 1e-12 * c.S);
    assert_near(r3.sd, r.sd, (r.sd > 0 ? 1e-12 : 1e-9) * c.S);
    /* motion: B moved along the normal by -sd + m clears A by m */
    double m = 0.01 * c.S;
    prox_vec3 cb4 = prox_v3_mad(c.cb, m - r.sd, r.normal);
    prox_distance_result d4 = prox_poly_distance(&c.a, c.ca, &c.b, cb4);
    assert_int_equal(d4.intersect, 0);
    if (r.sd <= 0.0) assert_near(d4.distance, m, 1e-9 * c.S);
    else assert_near(d4.distance, m, 1e-12 * c.S);
    return dis;
}

/* Random pairs of every kind with each other: B's reference at 0.2 .. 1.5 sizes from A's. */
static void test_random_pairs(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(21);
    int ndis = 0, nov = 0;
    for (int it = 0; it < 400; ++it) {
        int ka = it % TP_KINDS, kb = (it / TP_KINDS + it) % TP_KINDS;
        double s = pow(10.0, test_range(&g, -3, 3));
        prox_vec3 o = prox_v3_scale(test_unit(&g), s * test_range(&g, 0, 10));
        prox_shape sa = tp_rand_kind(&g, ka, o, s);
        prox_vec3 ob = prox_v3_add(o, prox_v3_scale(test_unit(&g), s * test_range(&g, 0.2, 1.5)));
        prox_shape sb = tp_rand_kind(&g, kb, ob, s * test_range(&g, 0.3, 2));
        if (check_pair(&sa, &sb)) ++ndis;
        else ++nov;
    }
    assert_true(ndis > 60);
    assert_true(nov > 60);
}

/* Near-degenerate bodies against every kind. */
static void test_degenerate_pairs(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(22);
    for (int it = 0; it < 150; ++it) {
        prox_shape sa = tp_rand_degen(&g, it % TP_DEGEN_KINDS, prox_v3(0, 0, 0), 1.0);
        prox_vec3 ob = prox_v3_scale(test_unit(&g), test_range(&g, 0.1, 1.2));
        prox_shape sb = it % 2 ? tp_rand_kind(&g, (it / 2) % TP_KINDS, ob, test_range(&g, 0.3, 1.5))
                               : tp_rand_degen(&g, (it / 3) % TP_DEGEN_KINDS, ob, test_range(&g, 0.3, 1.5));
        check_pair(&sa, &sb);
    }
}

/* BOX pairs: the polytope solver and the box-box solver (a different method, with its own fast
 * path) give the same answers, and the box-box answers pass the same independent checks. Half the
 * pairs are moved to a gap of 1e-10 .. 1e-2 along their contact direction; some share a face
 * orientation (B's frame is A's turned about one axis). */
static void test_against_box_box(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(23);
    for (int it = 0; it < 400; ++it) {
        prox_shape sa = tp_rand_box(&g, prox_v3(0, 0, 0), 1.0);
        prox_shape sb = tp_rand_box(&g, prox_v3_scale(test_unit(&g), test_range(&g, 0, 1.5)), test_range(&g, 0.3, 2));
        if (it % 4 == 3) { /* B turned about A's third edge: parallel faces */
            prox_vec3 w = prox_v3_normalize(sa.u.box.edge[2]);
            double l[3];
            for (int k = 0; k < 3; ++k) l[k] = prox_v3_norm(sb.u.box.edge[k]);
            prox_vec3 e0 = prox_v3_normalize(sa.u.box.edge[0]), e1 = prox_v3_cross(w, e0);
            double th = test_range(&g, 0, 1);
            prox_vec3 u = prox_v3_add(prox_v3_scale(e0, cos(th)), prox_v3_scale(e1, sin(th)));
            sb.u.box.edge[0] = prox_v3_scale(u, l[0]);
            sb.u.box.edge[1] = prox_v3_scale(prox_v3_cross(w, u), l[1]);
            sb.u.box.edge[2] = prox_v3_scale(w, l[2]);
        }
        if (it % 2) { /* near touching */
            prox_signed_result q = prox_box_box_signed_distance(&sa.u.box, &sb.u.box);
            double gap = pow(10.0, test_range(&g, -10, -2));
            sb.u.box.corner = prox_v3_mad(sb.u.box.corner, gap - q.sd, q.normal);
        }
        pp_case c;
        pp_make(&c, &sa, &sb);
        prox_distance_result d = prox_poly_distance(&c.a, c.ca, &c.b, c.cb);
        prox_distance_result e = prox_box_box_distance(&sa.u.box, &sb.u.box);
        check_distance(&c, e);
        assert_int_equal(d.intersect, e.intersect);
        assert_near(d.distance, e.distance, 1e-12 * c.S);
        prox_signed_result r = prox_poly_signed(&c.a, c.ca, &c.b, c.cb);
        prox_signed_result q = prox_box_box_signed_distance(&sa.u.box, &sb.u.box);
        assert_near(r.sd, q.sd, 1e-9 * c.S);
    }
}

/* Axis-aligned RPPs by hand: the distance is the norm of the per-axis gaps; the depth of overlapping
 * ones the least per-axis overlap. */
static void test_rpp_by_hand(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(24);
    for (int it = 0; it < 200; ++it) {
        double lo[2][3], hi[2][3];
        for (int k = 0; k < 2; ++k)
            for (int j = 0; j < 3; ++j) lo[k][j] = test_range(&g, -1, 1), hi[k][j] = lo[k][j] + test_range(&g, 0.1, 1.5);
        prox_rpp ra = {lo[0][0], hi[0][0], lo[0][1], hi[0][1], lo[0][2], hi[0][2]};
        prox_rpp rb = {lo[1][0], hi[1][0], lo[1][1], hi[1][1], lo[1][2], hi[1][2]};
        prox_shape sa = prox_shape_from_rpp(ra), sb = prox_shape_from_rpp(rb);
        double gap2 = 0.0, ov = INFINITY;
        int apart = 0;
        for (int j = 0; j < 3; ++j) {
            double gj = fmax(lo[1][j] - hi[0][j], lo[0][j] - hi[1][j]);
            if (gj > 0) gap2 += gj * gj, apart = 1;
            ov = fmin(ov, -gj);
        }
        pp_case c;
        pp_make(&c, &sa, &sb);
        prox_signed_result r = prox_poly_signed(&c.a, c.ca, &c.b, c.cb);
        if (apart) assert_near(r.sd, sqrt(gap2), 1e-14 * c.S);
        else assert_near(r.sd, -ov, 1e-14 * c.S);
        check_pair(&sa, &sb);
    }
}

/* Touching: B moved along a face normal of A until its support value meets that face's plane: the
 * signed distance is at least 0 to within the touch tolerance, and the two queries agree. */
static void test_touching(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(25);
    for (int it = 0; it < 100; ++it) {
        prox_shape sa = tp_rand_kind(&g, it % TP_KINDS, prox_v3(0, 0, 0), 1.0);
        prox_shape sb = tp_rand_kind(&g, (it / 3) % TP_KINDS, prox_v3(0, 0, 0), 1.0);
        pp_case c;
        pp_make(&c, &sa, &sb);
        /* face contact: B moved along A's face normal f until its support meets A's face plane */
        int f = it % c.a.nf;
        prox_vec3 n = c.a.n[f];
        double t = (c.a.d[f] + prox_v3_dot(n, c.ca)) - (-prox_polytope_hc(&c.b, prox_v3_neg(n)) + prox_v3_dot(n, c.cb));
        prox_vec3 cb = prox_v3_mad(c.cb, t, n);
        prox_signed_result r = prox_poly_signed(&c.a, c.ca, &c.b, cb);
        assert_int_equal(r.status, PROX_OK);
        assert_true(r.sd >= -1e-12 * c.S); /* s(n) = 0: no overlap */
        prox_distance_result d = prox_poly_distance(&c.a, c.ca, &c.b, cb);
        if (d.intersect) assert_true(r.sd <= 1e-12 * c.S);
        else assert_near(d.distance, r.sd, 1e-12 * c.S);
    }
}

/* Extreme scales: the same pair scaled by 1e-90 and 1e90 (inside the supported range) gives the
 * same answers scaled. */
static void test_extreme_scales(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(26);
    for (int it = 0; it < 60; ++it) {
        double sc = it % 2 ? 1e90 : 1e-90;
        prox_vec3 o = prox_v3_scale(test_unit(&g), sc);
        prox_shape sa = tp_rand_kind(&g, it % TP_KINDS, o, sc);
        prox_shape sb = tp_rand_kind(&g, (it / 2) % TP_KINDS, prox_v3_add(o, prox_v3_scale(test_unit(&g), sc * test_range(&g, 0.2, 1.5))), sc);
        pp_case c;
        pp_make(&c, &sa, &sb);
        prox_distance_result d = prox_poly_distance(&c.a, c.ca, &c.b, c.cb);
        prox_signed_result r = prox_poly_signed(&c.a, c.ca, &c.b, c.cb);
        assert_true(isfinite(d.distance) && isfinite(r.sd) && prox_v3_isfinite(r.p1) && prox_v3_isfinite(r.p2));
        check_distance(&c, d);
        if (sa.kind == PROX_SHAPE_BOX && sb.kind == PROX_SHAPE_BOX) {
            prox_distance_result e = prox_box_box_distance(&sa.u.box, &sb.u.box);
            check_distance(&c, e);
        }
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rpp_by_hand),      cmocka_unit_test(test_random_pairs),
        cmocka_unit_test(test_degenerate_pairs), cmocka_unit_test(test_against_box_box),
        cmocka_unit_test(test_touching),         cmocka_unit_test(test_extreme_scales),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
