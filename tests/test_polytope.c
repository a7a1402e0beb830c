/* The prepared polytope (core/polytope.h) of BOX, RPP, RHP, WED and ARB against the card definitions
 * written independently in test_poly_brute.h: facet numbering and planes, corners, support
 * function, membership, closest point (checked by the projection inequality), signed boundary
 * distance; and the validators of RHP, WED and ARB. */
#include "core/polytope.h"
#include "test_poly_brute.h"

static double scale_of(const tp_body *T, prox_vec3 c) { return (double)fmaxl(T->size, lnorm(L(c))); }

/* Every face's normal and plane match the card's plane with the same facet number; every corner lies
 * on three or more card planes and inside all of them. */
static void check_structure(const prox_shape *s)
{
    assert_int_equal(prox_shape_validate(s), PROX_OK);
    prox_polytope p;
    prox_vec3 c = prox_polytope_make(s, &p);
    tp_body T = tp_from_shape(s);
    double S = scale_of(&T, c);
    assert_int_equal(p.nf, T.nf);
    assert_int_equal(p.nv, T.nv);
    assert_true(p.ne > 0);
    assert_int_equal(p.nv - p.ne + p.nf, 2);
    for (int f = 0; f < p.nf; ++f) {
        int k = -1;
        for (int j = 0; j < T.nf; ++j)
            if (T.facet[j] == p.facet[f]) k = j;
        assert_true(k >= 0);
        assert_near((double)lnorm(lsub(L(p.n[f]), T.n[k])), 0.0, 1e-12);
        assert_near(p.d[f] + prox_v3_dot(p.n[f], c), (double)T.d[k], 1e-12 * S);
    }
    for (int i = 0; i < p.nv; ++i) {
        lv3 x = ladd(L(p.v[i]), L(c));
        int on = 0;
        for (int j = 0; j < T.nf; ++j) {
            ld r = ldot(T.n[j], x) - T.d[j];
            assert_true(r <= 1e-12L * S);
            on += fabsl(r) <= 1e-12L * S;
        }
        assert_true(on >= 3);
    }
    assert_near(p.size, (double)T.size, 1e-12 * S);
}

static void test_structure_random(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(11);
    for (int it = 0; it < 300; ++it) {
        double s = pow(10.0, test_range(&g, -3, 3));
        prox_vec3 o = prox_v3_scale(test_unit(&g), s * test_range(&g, 0, 100));
        prox_shape sh = tp_rand_kind(&g, it % TP_KINDS, o, s);
        check_structure(&sh);
    }
    for (int it = 0; it < 60; ++it) {
        prox_shape sh = tp_rand_degen(&g, it % TP_DEGEN_KINDS, prox_v3(1, 2, 3), 2.0);
        check_structure(&sh);
    }
}

/* The MCNP manual's own examples: RPP facets by coordinate, a HEX of the 9-entry form, a WED, an
 * ARB cube; facet planes checked against hand-written values. */
static void test_card_examples(void **state)
{
    (void)state;
    prox_rpp r = {-1, 2, -3, 4, -5, 6};
    prox_shape s = prox_shape_from_rpp(r);
    prox_polytope p;
    prox_vec3 c = prox_polytope_make(&s, &p);
    const double want[6] = {2, 1, 4, 3, 6, 5}; /* n.x <= want: xmax, -xmin, ymax, -ymin, zmax, -zmin */
    for (int f = 0; f < 6; ++f) assert_near(p.d[f] + prox_v3_dot(p.n[f], c), want[p.facet[f] - 1], 1e-14);

    prox_rhp h;
    assert_int_equal(prox_rhp_regular(prox_v3(0, 0, -4), prox_v3(0, 0, 8), prox_v3(0, 2, 0), &h), PROX_OK);
    s = prox_shape_from_rhp(h);
    c = prox_polytope_make(&s, &p);
    assert_int_equal(p.nv, 12);
    assert_int_equal(p.ne, 18);
    for (int f = 0; f < 8; ++f) {
        prox_vec3 n = p.n[f];
        double d = p.d[f] + prox_v3_dot(n, c);
        switch (p.facet[f]) {
        case 1: assert_near(n.y, 1.0, 1e-15); assert_near(d, 2.0, 1e-14); break;
        case 2: assert_near(n.y, -1.0, 1e-15); assert_near(d, 2.0, 1e-14); break;
        case 3: assert_near(n.x, -sqrt(3) / 2, 1e-15); assert_near(n.y, 0.5, 1e-15); break; /* z x r turned +60 */
        case 7: assert_near(n.z, 1.0, 1e-15); assert_near(d, 4.0, 1e-14); break;
        case 8: assert_near(n.z, -1.0, 1e-15); assert_near(d, 4.0, 1e-14); break;
        default: assert_near(d, 2.0, 1e-14); break;
        }
    }
    prox_wed w = {prox_v3(0, 0, 0), prox_v3(3, 0, 0), prox_v3(0, 4, 0), prox_v3(0, 0, 5)};
    s = prox_shape_from_wed(w);
    c = prox_polytope_make(&s, &p);
    for (int f = 0; f < 5; ++f) {
        prox_vec3 n = p.n[f];
        double d = p.d[f] + prox_v3_dot(n, c);
        switch (p.facet[f]) {
        case 1: assert_near(n.x, 0.8, 1e-15); assert_near(n.y, 0.6, 1e-15); assert_near(d, 2.4, 1e-14); break;
        case 2: assert_near(n.x, -1.0, 1e-15); assert_near(d, 0.0, 1e-14); break; /* plane of v2, v3 */
        case 3: assert_near(n.y, -1.0, 1e-15); assert_near(d, 0.0, 1e-14); break; /* plane of v1, v3 */
        case 4: assert_near(n.z, 1.0, 1e-15); assert_near(d, 5.0, 1e-14); break;
        case 5: assert_near(n.z, -1.0, 1e-15); assert_near(d, 0.0, 1e-14); break;
        default: fail();
        }
    }
    prox_arb a = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                  {1234, 5678, 1265, 2376, 3487, 4158}};
    assert_int_equal(prox_arb_validate(&a), PROX_OK);
    s = prox_shape_from_arb(a);
    c = prox_polytope_make(&s, &p);
    const prox_vec3 nw[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
    for (int f = 0; f < 6; ++f) assert_near(prox_v3_dist(p.n[f], nw[p.facet[f] - 1]), 0.0, 1e-15);
}

/* hc, pc, contains, closest and boundary against the card's planes and corners. */
static void check_queries(const prox_shape *s, test_rng *g)
{
    prox_polytope p;
    prox_vec3 c = prox_polytope_make(s, &p);
    tp_body T = tp_from_shape(s);
    double S = (double)T.size;
    for (int it = 0; it < 40; ++it) {
        prox_vec3 d = test_unit(g);
        double h = prox_polytope_hc(&p, d);
        assert_near(h + prox_v3_dot(d, c), (double)tp_support(&T, L(d)), 1e-13 * fmax(S, prox_v3_norm(c)));
        assert_near(prox_v3_dot(d, prox_polytope_pc(&p, d)), h, 1e-14 * S);
        /* a point near the body, relative to c */
        prox_vec3 y = prox_v3_scale(test_unit(g), S * test_range(g, 0, 1.2));
        lv3 ya = ladd(L(y), L(c));
        ld res = tp_resid(&T, ya);
        if (fabsl(res) > 1e-9L * S) assert_int_equal(prox_polytope_contains(&p, y, 0.0), res < 0);
        prox_vec3 q = prox_polytope_closest(&p, y);
        lv3 qa = ladd(L(q), L(c));
        assert_true(tp_resid(&T, qa) <= 1e-13L * S);
        /* projection onto a convex set: (y - q).(v - q) <= 0 for every corner v */
        for (int i = 0; i < T.nv; ++i)
            assert_true(ldot(lsub(ya, qa), lsub(T.v[i], qa)) <= 1e-13L * S * S);
        prox_vec3 qb;
        double sd = prox_polytope_boundary(&p, y, &qb);
        lv3 qba = ladd(L(qb), L(c));
        assert_near((double)tp_resid(&T, qba), 0.0, 1e-13 * S);
        assert_near(fabs(sd), prox_v3_dist(qb, y), 1e-13 * S);
        if (res < -1e-9L * S) { /* inside: minus the distance to the nearest card plane */
            ld m = INFINITY;
            for (int f = 0; f < T.nf; ++f) m = fminl(m, T.d[f] - ldot(T.n[f], ya));
            assert_near(sd, (double)-m, 1e-13 * S);
        } else if (res > 1e-9L * S) {
            assert_near(sd, prox_v3_dist(q, y), 1e-13 * S);
        }
    }
}

static void test_queries_random(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(12);
    for (int it = 0; it < 200; ++it) {
        double s = pow(10.0, test_range(&g, -2, 2));
        prox_shape sh = tp_rand_kind(&g, it % TP_KINDS, prox_v3_scale(test_unit(&g), 10 * s), s);
        check_queries(&sh, &g);
    }
    for (int it = 0; it < 30; ++it) {
        prox_shape sh = tp_rand_degen(&g, it % TP_DEGEN_KINDS, prox_v3(0, 0, 0), 1.0);
        check_queries(&sh, &g);
    }
}

static void test_rhp_validate(void **state)
{
    (void)state;
    prox_rhp h;
    assert_int_equal(prox_rhp_regular(prox_v3(1, 2, 3), prox_v3(0, 0, 2), prox_v3(1, 0, 0), &h), PROX_OK);
    assert_near(prox_v3_norm(h.r[1]), 1.0, 1e-15);
    assert_near(prox_v3_dot(h.r[0], h.r[1]), 0.5, 1e-15);
    assert_near(prox_v3_dot(h.r[0], h.r[2]), -0.5, 1e-15);
    assert_true(prox_v3_cross(h.r[0], h.r[1]).z > 0); /* s is r turned +60 about the height */
    assert_int_equal(prox_rhp_validate(&h), PROX_OK);
    assert_int_equal(prox_rhp_validate(NULL), PROX_EINVAL_ARG);
    prox_rhp b = h;
    b.r[1].z = 0.1; /* not perpendicular to the height */
    assert_int_equal(prox_rhp_validate(&b), PROX_EINVAL_RHP);
    b = h;
    b.r[1] = h.r[0]; /* s = r: two planes coincide */
    assert_int_equal(prox_rhp_validate(&b), PROX_EINVAL_RHP);
    b = h;
    b.r[1] = prox_v3_scale(h.r[1], 3.0); /* s's planes cut nothing: only four sides */
    assert_int_equal(prox_rhp_validate(&b), PROX_EINVAL_RHP);
    b = h;
    b.r[2] = prox_v3(0, 0, 0);
    assert_int_equal(prox_rhp_validate(&b), PROX_EINVAL_RHP);
    b = h;
    b.axis = prox_v3(0, 0, 0);
    assert_int_equal(prox_rhp_validate(&b), PROX_EINVAL_AXIS);
    b = h;
    b.base.x = NAN;
    assert_int_equal(prox_rhp_validate(&b), PROX_EINVAL_NONFINITE);
    b = h;
    b.base.x = 1e200;
    assert_int_equal(prox_rhp_validate(&b), PROX_EINVAL_RANGE);
    assert_int_equal(prox_rhp_regular(prox_v3(0, 0, 0), prox_v3(0, 0, 1), prox_v3(0, 0, 1), &b), PROX_EINVAL_RHP);
    /* a general hexagon (15 entries) */
    b = h;
    b.r[1] = prox_v3(0.3, 0.9, 0);
    assert_int_equal(prox_rhp_validate(&b), PROX_OK);
}

static void test_wed_validate(void **state)
{
    (void)state;
    prox_wed w = {prox_v3(0, 0, 0), prox_v3(1, 0, 0), prox_v3(0, 1, 0), prox_v3(0, 0, 1)}, b;
    assert_int_equal(prox_wed_validate(&w), PROX_OK);
    assert_int_equal(prox_wed_validate(NULL), PROX_EINVAL_ARG);
    b = w, b.v3 = prox_v3(0.1, 0, 1);
    assert_int_equal(prox_wed_validate(&b), PROX_EINVAL_WED);
    b = w, b.v2 = prox_v3(2, 0, 0);
    assert_int_equal(prox_wed_validate(&b), PROX_EINVAL_WED);
    b = w, b.v2 = prox_v3(0, 0, 0);
    assert_int_equal(prox_wed_validate(&b), PROX_EINVAL_WED);
    b = w, b.v2 = prox_v3(1, 1e-6, 0); /* flat but valid */
    assert_int_equal(prox_wed_validate(&b), PROX_OK);
    b = w, b.v1.y = INFINITY;
    assert_int_equal(prox_wed_validate(&b), PROX_EINVAL_NONFINITE);
    b = w, b.v3 = prox_v3(0, 0, 1e-120);
    assert_int_equal(prox_wed_validate(&b), PROX_EINVAL_RANGE);
}

static void test_arb_validate(void **state)
{
    (void)state;
    const prox_arb cube = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                           {1234, 5678, 1265, 2376, 3487, 4158}};
    prox_arb a = cube;
    assert_int_equal(prox_arb_validate(&a), PROX_OK);
    assert_int_equal(prox_arb_validate(NULL), PROX_EINVAL_ARG);
    a.face[0] = 4321; /* either turn is accepted */
    assert_int_equal(prox_arb_validate(&a), PROX_OK);
    a = cube, a.face[1] = 5679; /* corner 9 does not exist */
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_ARB_FACE);
    a = cube, a.face[1] = 5668; /* repeated corner */
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_ARB_FACE);
    a = cube, a.face[1] = 5068; /* 0 among the first three */
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_ARB_FACE);
    a = cube, a.face[1] = 123; /* not four digits */
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_ARB_FACE);
    for (int f = 0; f < 6; ++f) { /* corners named in any order round a face: MCNP takes its plane */
        static const int swap[3][2] = {{1, 2}, {2, 3}, {0, 2}};
        for (int k = 0; k < 3; ++k) {
            a = cube;
            int d[4] = {a.face[f] / 1000, a.face[f] / 100 % 10, a.face[f] / 10 % 10, a.face[f] % 10};
            int t = d[swap[k][0]];
            d[swap[k][0]] = d[swap[k][1]], d[swap[k][1]] = t;
            a.face[f] = 1000 * d[0] + 100 * d[1] + 10 * d[2] + d[3];
            assert_int_equal(prox_arb_validate(&a), PROX_OK);
            prox_polytope p, q;
            prox_shape sa = prox_shape_from_arb(a), sc = prox_shape_from_arb(cube);
            prox_polytope_make(&sa, &p), prox_polytope_make(&sc, &q);
            assert_int_equal(p.nf, q.nf);
            assert_int_equal(p.ne, q.ne);
            for (int g = 0; g < p.nf; ++g) {
                assert_true(prox_v3_dist(p.n[g], q.n[g]) < 1e-15);
                assert_true(fabs(p.d[g] - q.d[g]) < 1e-15);
            }
        }
    }
    a = cube, a.corner[6].z = 1.01; /* face 5678 (and two sides) not planar */
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_ARB_PLANAR);
    a = cube, a.face[5] = 0; /* open surface */
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_ARB_CONVEX);
    a = cube, a.face[4] = a.face[5] = 0;
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_ARB_CONVEX);
    a = cube, a.corner[7] = a.corner[6]; /* two corners at one point */
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_ARB_FACE);
    a = cube, a.corner[2].x = NAN;
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_NONFINITE);
    a = cube, a.corner[2].x = -1e101;
    assert_int_equal(prox_arb_validate(&a), PROX_EINVAL_RANGE);
    /* a non-convex body with planar faces: a prism over a dented quadrilateral */
    prox_arb d = {{{-1, 0, 0}, {0, -1, 0}, {1, 0, 0}, {0, -0.5, 0}, {-1, 0, 1}, {0, -1, 1}, {1, 0, 1}, {0, -0.5, 1}},
                  {1234, 5678, 1265, 2376, 3487, 4158}};
    assert_int_equal(prox_arb_validate(&d), PROX_EINVAL_ARB_CONVEX);
    d.corner[3].y = d.corner[7].y = 0.5; /* the convex one */
    assert_int_equal(prox_arb_validate(&d), PROX_OK);
    /* a tetrahedron: three-corner faces end in 0, corners 5-8 unused (zero) */
    prox_arb t = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1230, 1240, 1340, 2340, 0, 0}};
    assert_int_equal(prox_arb_validate(&t), PROX_OK);
    t.face[3] = 0;
    assert_int_equal(prox_arb_validate(&t), PROX_EINVAL_ARB_CONVEX);
    /* the generic-shape path */
    prox_shape s = prox_shape_from_arb(cube);
    assert_int_equal(prox_shape_validate(&s), PROX_OK);
    assert_string_equal(prox_status_str(PROX_EINVAL_ARB_PLANAR) != NULL ? "ok" : "", "ok");
}

/* Random valid cards of every kind pass the validators; the near-degenerate ones too. */
static void test_random_valid(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(13);
    for (int it = 0; it < 500; ++it) {
        prox_shape sh = tp_rand_kind(&g, it % TP_KINDS, prox_v3_scale(test_unit(&g), 5.0), 1.0);
        assert_int_equal(prox_shape_validate(&sh), PROX_OK);
    }
    for (int it = 0; it < 90; ++it) {
        prox_shape sh = tp_rand_degen(&g, it % TP_DEGEN_KINDS, prox_v3(0, 0, 0), 1.0);
        assert_int_equal(prox_shape_validate(&sh), PROX_OK);
    }
}

/* Random ARB cards (corners of a perturbed cube, face entries drawn from a set of right and wrong
 * ones): the validator answers every one without a crash, and every accepted one builds a closed
 * convex polytope that matches its card planes. */
static void test_arb_fuzz(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(14);
    static const int good[6] = {1234, 5678, 1265, 2376, 3487, 4158};
    static const int wrong[8] = {1324, 5668, 9123, 1200, 12345, 1230, 2370, 5670};
    int accepted = 0;
    for (int it = 0; it < 2000; ++it) {
        prox_arb a = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, {0}};
        double jit = it % 3 == 0 ? 0.0 : pow(10.0, test_range(&g, -14, -1));
        for (int i = 0; i < 8; ++i)
            a.corner[i] = prox_v3_add(a.corner[i], prox_v3_scale(test_unit(&g), jit * test_uniform(&g)));
        for (int f = 0; f < 6; ++f) {
            double u = test_uniform(&g);
            a.face[f] = u < 0.85 ? good[f] : (u < 0.95 ? wrong[(int)(8 * test_uniform(&g))] : 0);
        }
        prox_status st = prox_arb_validate(&a);
        assert_true(st == PROX_OK || st == PROX_EINVAL_ARB_FACE || st == PROX_EINVAL_ARB_PLANAR ||
                    st == PROX_EINVAL_ARB_CONVEX);
        if (st == PROX_OK) {
            prox_shape sh = prox_shape_from_arb(a);
            if (jit < 1e-13) { /* planar to rounding: the card planes through three corners hold */
                check_structure(&sh);
            } else { /* faces planar to PROX_TOL_ARB_PLANAR: a closed polytope with every corner inside */
                prox_polytope p;
                prox_polytope_make(&sh, &p);
                assert_int_equal(p.nv - p.ne + p.nf, 2);
                for (int f = 0; f < p.nf; ++f)
                    for (int i = 0; i < p.nv; ++i) assert_true(prox_v3_dot(p.n[f], p.v[i]) - p.d[f] <= 2e-9 * p.size);
            }
            ++accepted;
        }
    }
    assert_true(accepted > 200);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_card_examples),  cmocka_unit_test(test_structure_random),
        cmocka_unit_test(test_queries_random), cmocka_unit_test(test_rhp_validate),
        cmocka_unit_test(test_wed_validate),   cmocka_unit_test(test_arb_validate),
        cmocka_unit_test(test_random_valid),   cmocka_unit_test(test_arb_fuzz),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
