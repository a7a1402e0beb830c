/* Containment A in B for the 9 ordered pairs (containment.c): seeded random pairs against a dense
 * sampling of A's extreme set (box vertices, rim circles, sphere surface) with point clearances
 * written here; the report's Set 1 cases (LA-UR-13-26757 Sec. 2) with the corrected conditions of
 * docs/errata-trx.md. */
#include "test_util.h"
#include "prox/query.h"

/* Point clearance in B (distance to the boundary inside, negative outside), brute-force side. */
static double clear_pt(const prox_shape *b, prox_vec3 x)
{
    if (b->kind == PROX_SHAPE_SPH) return b->u.sph.radius - prox_v3_dist(x, b->u.sph.center);
    if (b->kind == PROX_SHAPE_RCC) {
        double h = prox_v3_norm(b->u.rcc.axis);
        prox_vec3 w = prox_v3_scale(b->u.rcc.axis, 1 / h), d = prox_v3_sub(x, b->u.rcc.base);
        double t = prox_v3_dot(d, w), rho = prox_v3_norm(prox_v3_sub(d, prox_v3_scale(w, t)));
        return fmin(fmin(t, h - t), b->u.rcc.radius - rho);
    }
    double m = INFINITY;
    prox_vec3 d = prox_v3_sub(x, b->u.box.corner);
    for (int k = 0; k < 3; ++k) {
        double L = prox_v3_norm(b->u.box.edge[k]), t = prox_v3_dot(d, b->u.box.edge[k]) / L;
        m = fmin(m, fmin(t, L - t));
    }
    return m;
}

/* Min clearance of sampled points of A's extreme set. */
static double sampled(const prox_shape *a, const prox_shape *b)
{
    double m = INFINITY;
    if (a->kind == PROX_SHAPE_BOX) {
        for (int i = 0; i < 8; ++i) {
            prox_vec3 v = a->u.box.corner;
            for (int k = 0; k < 3; ++k) if (i >> k & 1) v = prox_v3_add(v, a->u.box.edge[k]);
            m = fmin(m, clear_pt(b, v));
        }
    } else if (a->kind == PROX_SHAPE_RCC) {
        prox_vec3 w = prox_v3_normalize(a->u.rcc.axis), u = prox_v3_any_perp(w), v = prox_v3_cross(w, u);
        for (int e = 0; e < 2; ++e)
            for (int i = 0; i < 20000; ++i) {
                double th = 2 * PROX_PI * i / 20000;
                prox_vec3 c = e ? prox_v3_add(a->u.rcc.base, a->u.rcc.axis) : a->u.rcc.base;
                c = prox_v3_add(c, prox_v3_add(prox_v3_scale(u, a->u.rcc.radius * cos(th)), prox_v3_scale(v, a->u.rcc.radius * sin(th))));
                m = fmin(m, clear_pt(b, c));
            }
    } else {
        for (int i = 0; i < 40000; ++i) {
            double z = 1 - (2.0 * i + 1) / 40000, r = sqrt(1 - z * z), th = 2.399963229728653 * i;
            prox_vec3 d = prox_v3(r * cos(th), r * sin(th), z);
            m = fmin(m, clear_pt(b, prox_v3_mad(a->u.sph.center, a->u.sph.radius, d)));
        }
        /* the face normals of a box / axis directions of a cylinder as exact samples */
        prox_vec3 dirs[6];
        int nd = 0;
        if (b->kind == PROX_SHAPE_BOX) for (int k = 0; k < 3; ++k) dirs[nd++] = prox_v3_normalize(b->u.box.edge[k]);
        if (b->kind == PROX_SHAPE_RCC) { /* the axis, and the radial direction of the centre */
            prox_vec3 w = prox_v3_normalize(b->u.rcc.axis), d = prox_v3_sub(a->u.sph.center, b->u.rcc.base);
            dirs[nd++] = w;
            prox_vec3 rad = prox_v3_sub(d, prox_v3_scale(w, prox_v3_dot(d, w)));
            if (prox_v3_norm(rad) > 0) dirs[nd++] = prox_v3_normalize(rad);
        }
        if (b->kind == PROX_SHAPE_SPH && prox_v3_dist(a->u.sph.center, b->u.sph.center) > 0)
            dirs[nd++] = prox_v3_normalize(prox_v3_sub(a->u.sph.center, b->u.sph.center));
        for (int k = 0; k < nd; ++k)
            for (int s = -1; s <= 1; s += 2)
                m = fmin(m, clear_pt(b, prox_v3_mad(a->u.sph.center, s * a->u.sph.radius, dirs[k])));
    }
    return m;
}

static prox_shape rnd(test_rng *g, int kind, double size)
{
    prox_vec3 c = prox_v3(test_range(g, -0.5, 0.5), test_range(g, -0.5, 0.5), test_range(g, -0.5, 0.5));
    if (kind == 0) {
        test_rot R = test_random_rot(g);
        prox_box b;
        for (int k = 0; k < 3; ++k)
            b.edge[k] = prox_v3_scale(test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2)), size * test_range(g, 0.3, 1.0));
        b.corner = prox_v3_sub(c, prox_v3_scale(prox_v3_add(prox_v3_add(b.edge[0], b.edge[1]), b.edge[2]), 0.5));
        return prox_shape_from_box(b);
    }
    if (kind == 1) {
        prox_rcc r;
        r.axis = prox_v3_scale(test_unit(g), size * test_range(g, 0.3, 1.0));
        r.base = prox_v3_mad(c, -0.5, r.axis);
        r.radius = size * test_range(g, 0.15, 0.5);
        return prox_shape_from_rcc(r);
    }
    prox_sph s = {c, size * test_range(g, 0.15, 0.5)};
    return prox_shape_from_sph(s);
}

static void test_random_nine_pairs(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(2024);
    for (int ka = 0; ka < 3; ++ka)
        for (int kb = 0; kb < 3; ++kb) {
            int ins = 0, outs = 0;
            for (int i = 0; i < 300; ++i) {
                prox_shape a = rnd(&g, ka, test_range(&g, 0.3, 1.2)), b = rnd(&g, kb, 3.0);
                prox_contain_result r = prox_shape_contains(&a, &b);
                assert_int_equal(r.status, PROX_OK);
                double s = sampled(&a, &b), tol = (ka == 0) ? 1e-13 : 2e-7;
                assert_true(r.clearance <= s + 1e-13);  /* exact min <= any sample */
                assert_true(r.clearance >= s - tol);   /* and close to the dense sampling */
                if (fabs(r.clearance) > tol) assert_int_equal(r.inside, s > 0);
                ins += r.inside, outs += !r.inside;
            }
            print_message("%d in %d: %d inside, %d not\n", ka, kb, ins, outs);
            assert_true(ins > 10 && outs > 10);
        }
}

/* Long-double brute force for a rim (centre c, frame u, v, radius r) against cylinder B: the extremes of
 * the axial coordinate and the largest distance from B's axis, by 256 samples refined by golden
 * sections at every sampled local maximum (at most two: degree-2 trigonometric polynomials). */
typedef long double ld;
static ld rim_eval(const prox_rcc *b, prox_vec3 c, prox_vec3 u, prox_vec3 v, double r, ld th, int what)
{
    ld h = sqrtl((ld)b->axis.x * b->axis.x + (ld)b->axis.y * b->axis.y + (ld)b->axis.z * b->axis.z);
    ld w[3] = {b->axis.x / h, b->axis.y / h, b->axis.z / h};
    ld x[3] = {c.x + r * (cosl(th) * u.x + sinl(th) * v.x) - (ld)b->base.x,
               c.y + r * (cosl(th) * u.y + sinl(th) * v.y) - (ld)b->base.y,
               c.z + r * (cosl(th) * u.z + sinl(th) * v.z) - (ld)b->base.z};
    ld t = x[0] * w[0] + x[1] * w[1] + x[2] * w[2];
    if (what == 0) return -t;        /* maximise -t: the lowest point */
    if (what == 1) return t;         /* the highest point */
    ld q[3] = {x[0] - t * w[0], x[1] - t * w[1], x[2] - t * w[2]};
    return sqrtl(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
}
static ld rim_max(const prox_rcc *b, prox_vec3 c, prox_vec3 u, prox_vec3 v, double r, int what)
{
    enum { N = 256 };
    ld best = -INFINITY;
    for (int i = 0; i < N; ++i) {
        ld th = 2 * 3.14159265358979323846L * i / N, f = rim_eval(b, c, u, v, r, th, what);
        ld fl = rim_eval(b, c, u, v, r, th - 2.4543692606170259e-2L, what), fr = rim_eval(b, c, u, v, r, th + 2.4543692606170259e-2L, what);
        if (f > best) best = f;
        if (f < fl || f < fr) continue;
        ld lo = th - 2.4543692606170259e-2L, hi = th + 2.4543692606170259e-2L, g = 0.6180339887498949L;
        for (int it = 0; it < 90; ++it) {
            ld x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
            ld f1 = rim_eval(b, c, u, v, r, x1, what), f2 = rim_eval(b, c, u, v, r, x2, what);
            if (f1 > f2) hi = x2; else lo = x1;
            if (f1 > best) best = f1;
            if (f2 > best) best = f2;
        }
    }
    return best;
}

/* RCC in RCC: the exact rim test (stationary angles) against the long-double brute force to 1e-12 x
 * scale, including rims nearly coaxial and axes nearly parallel. */
static void test_rcc_in_rcc_exact(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(77);
    double worst = 0.0;
    for (int i = 0; i < 400; ++i) {
        prox_shape a = rnd(&g, 1, test_range(&g, 0.3, 1.2)), b = rnd(&g, 1, 3.0);
        if (i % 4 == 1) a.u.rcc.axis = prox_v3_scale(b.u.rcc.axis, 0.3); /* parallel axes */
        if (i % 4 == 2) { /* nearly parallel, nearly coaxial */
            a.u.rcc.axis = prox_v3_add(prox_v3_scale(b.u.rcc.axis, 0.3), prox_v3(1e-7, -2e-7, 0));
            a.u.rcc.base = prox_v3_add(prox_v3_mad(b.u.rcc.base, 0.2, b.u.rcc.axis), prox_v3(3e-8, 0, 1e-8));
        }
        prox_contain_result r = prox_rcc_in_rcc(&a.u.rcc, &b.u.rcc);
        assert_int_equal(r.status, PROX_OK);
        const prox_rcc *A = &a.u.rcc, *B = &b.u.rcc;
        prox_vec3 w = prox_v3_normalize(A->axis), u = prox_v3_any_perp(w), v = prox_v3_cross(w, u);
        ld hB = prox_v3_norm(B->axis), c = INFINITY;
        for (int e = 0; e < 2; ++e) {
            prox_vec3 ctr = e ? prox_v3_add(A->base, A->axis) : A->base;
            ld lo = -rim_max(B, ctr, u, v, A->radius, 0), hi = rim_max(B, ctr, u, v, A->radius, 1);
            ld rho = rim_max(B, ctr, u, v, A->radius, 2);
            c = fminl(c, fminl(fminl(lo, hB - hi), B->radius - rho));
        }
        double S = prox_shape_pair_scale(&a, &b);
        assert_near(r.clearance, (double)c, 1e-12 * S);
        worst = fmax(worst, fabs(r.clearance - (double)c) / S);
    }
    print_message("rcc in rcc: max |clearance - brute| / scale = %.3g\n", worst);
}

/* Set 1 of the report in local orientation, with the corrected conditions (errata 2-11). */
static void test_report_set1(void **st)
{
    (void)st;
    prox_rpp box = {-1, 1, -2, 2, -3, 3};
    prox_shape B = prox_shape_from_rpp(box);
    /* 2.4 BOX in SPH: corner radius sqrt(1+4+9) = 3.742 (Eq. (11) would check sqrt(1+9) only) */
    prox_sph s1 = {{0, 0, 0}, 3.5}, s2 = {{0, 0, 0}, 3.75};
    prox_shape S1 = prox_shape_from_sph(s1), S2 = prox_shape_from_sph(s2);
    assert_false(prox_shape_contains(&B, &S1).inside);
    assert_true(prox_shape_contains(&B, &S2).inside);
    /* 2.5 SPH in BOX: x is limiting (Eq. (14) forgets x) */
    prox_sph s3 = {{0, 0, 0}, 1.5};
    prox_shape S3 = prox_shape_from_sph(s3);
    assert_false(prox_shape_contains(&S3, &B).inside);
    assert_near(prox_shape_contains(&S3, &B).clearance, -0.5, 1e-15);
    /* 2.2 BOX in RCC along x: corners (y,z) = (+-2, +-3) need R >= sqrt(13); ends must enclose x */
    prox_rcc c1 = {{-1.5, 0, 0}, {3, 0, 0}, 3.61}, c2 = {{-1.5, 0, 0}, {3, 0, 0}, 3.60};
    prox_shape C1 = prox_shape_from_rcc(c1), C2 = prox_shape_from_rcc(c2);
    assert_true(prox_shape_contains(&B, &C1).inside);
    assert_false(prox_shape_contains(&B, &C2).inside);
    /* 2.8 SPH in RCC: R_A <= R_B (Eq. (17) has it backwards) */
    prox_sph s4 = {{0, 0, 0}, 1.4};
    prox_shape S4 = prox_shape_from_sph(s4);
    assert_true(prox_shape_contains(&S4, &C1).inside);
    /* 2.7 RCC in SPH: (h/2)^2 + R^2 <= R_B^2 */
    prox_rcc c3 = {{0, 0, -3}, {0, 0, 6}, 4.0};
    prox_sph s5 = {{0, 0, 0}, 5.0}, s6 = {{0, 0, 0}, 4.99};
    prox_shape C3 = prox_shape_from_rcc(c3), S5 = prox_shape_from_sph(s5), S6 = prox_shape_from_sph(s6);
    assert_true(prox_shape_contains(&C3, &S5).inside);
    assert_near(prox_shape_contains(&C3, &S5).clearance, 0.0, 1e-14);
    assert_false(prox_shape_contains(&C3, &S6).inside);
    /* 2.9 SPH in SPH off-centre: d + R_A <= R_B */
    prox_sph s7 = {{1, 0, 0}, 3.9};
    prox_shape S7 = prox_shape_from_sph(s7);
    assert_false(prox_shape_contains(&S7, &S2).inside);
    /* 2.6 RCC in RCC, tilted: a thin rod fits only along the diagonal of a short wide cylinder */
    prox_rcc big = {{0, 0, 0}, {0, 0, 2}, 2}, rod = {{-1.3, 0, 0.3}, {2.6, 0, 1.4}, 0.05};
    prox_shape BIG = prox_shape_from_rcc(big), ROD = prox_shape_from_rcc(rod);
    assert_true(prox_shape_contains(&ROD, &BIG).inside);
    rod.axis = prox_v3(4.2, 0, 1.4);
    ROD = prox_shape_from_rcc(rod);
    assert_false(prox_shape_contains(&ROD, &BIG).inside);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_random_nine_pairs), cmocka_unit_test(test_report_set1),
                                       cmocka_unit_test(test_rcc_in_rcc_exact)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
