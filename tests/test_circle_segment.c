/* circle_segment.c: P(C, L) and prox_circle_line_stationary against independent long-double brute force:
 * dense sampling of the circle angle (segment parameter by clamped projection) with golden-section
 * refinement; every local extremum of the sampled line distance must be among the returned stationary
 * angles, and every returned angle must be stationary. */
#include "test_brute.h"
#include "core/circle.h"

/* Circle and segment in long double; the circle frame is the library's (angles are compared). */
typedef struct prob {
    lv3 c, u, v, n, a, d;
    ld r;
    int infinite; /* 1: distance to the infinite line (stationary test), squared */
} prob;
static lv3 cpt(const prob *P, ld th) { return ladd(P->c, lsc(ladd(lsc(P->u, cosl(th)), lsc(P->v, sinl(th))), P->r)); }
static ld pval(const void *ctx, ld th)
{
    const prob *P = ctx;
    lv3 x = cpt(P, th), q = lsub(x, P->a);
    ld dd = ldot(P->d, P->d), t = dd > 0 ? ldot(q, P->d) / dd : 0;
    if (!P->infinite) t = t < 0 ? 0 : (t > 1 ? 1 : t);
    lv3 e = lsub(q, lsc(P->d, t));
    return P->infinite ? ldot(e, e) : lnorm(e);
}
enum { NS = 512 };
static ld brute_min(const prob *P) { return tb_min_periodic(pval, P, NS); }

static prob make_prob(const prox_circle *c, const prox_segment *s, int infinite)
{
    prob P;
    prox_vec3 n = prox_v3_normalize(c->normal);
    prox_fcircle f = prox_fcircle_make(c->center, n, c->radius);
    P.c = L(f.c); P.u = L(f.u); P.v = L(f.v); P.n = L(f.n); P.r = c->radius;
    P.a = L(s->a); P.d = lsub(L(s->b), L(s->a));
    P.infinite = infinite;
    return P;
}

static prox_prim_result check(prox_circle c, prox_segment s)
{
    prox_prim_result res = prox_circle_segment(&c, &s);
    assert_int_equal(res.status, PROX_OK);
    double tol = 1e-12 * tb_seg_scale(&s, c.center, c.radius);
    prob P = make_prob(&c, &s, 0);
    assert_near(res.distance, (double)brute_min(&P), tol);
    assert_near(prox_v3_dist(res.p1, res.p2), res.distance, tol);
    /* p1 on the circle at angle s1[0]; p2 on the segment at t = s2[0] */
    assert_near((double)lnorm(lsub(L(res.p1), cpt(&P, res.s1[0]))), 0, 4 * tol);
    assert_true(res.s1[0] >= 0 && res.s1[0] < 2 * PROX_PI);
    assert_true(res.s2[0] >= 0 && res.s2[0] <= 1);
    assert_near(tb_seg_point_err(res.p2, P.a, P.d, res.s2[0]), 0, tol);
    return res;
}

static void test_circle_segment_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(707);
    for (int i = 0; i < 6000; ++i) {
        double s = tb_random_scale(&r);
        prox_vec3 o = tb_random_origin(&r, i, s);
        prox_circle c = tb_random_circle(&r, o, s);
        prox_segment sg = tb_random_segment(&r, o, 2 * s);
        prox_vec3 u, v;
        prox_circle_frame(&c, &u, &v);
        switch (i % 8) {
        case 1: sg.b = prox_v3_mad(sg.a, s * test_range(&r, -2, 2), c.normal); break; /* parallel to the axis */
        case 2: sg.b = sg.a; break;
        case 3: /* in the circle's plane */
            sg.a = prox_v3_add(c.center, prox_v3_add(prox_v3_scale(u, s * test_range(&r, -2, 2)), prox_v3_scale(v, s * test_range(&r, -2, 2))));
            sg.b = prox_v3_add(c.center, prox_v3_add(prox_v3_scale(u, s * test_range(&r, -2, 2)), prox_v3_scale(v, s * test_range(&r, -2, 2))));
            break;
        case 4: /* through the circle (piercing its rim) */
        {
            prox_vec3 x = prox_circle_point(&c, test_range(&r, 0, 6.28));
            prox_vec3 dir = test_unit(&r);
            sg.a = prox_v3_mad(x, -s * test_range(&r, 0.1, 1), dir);
            sg.b = prox_v3_mad(x, s * test_range(&r, 0.1, 1), dir);
            break;
        }
        case 5: /* through the centre */
            sg.b = prox_v3_mad(c.center, test_range(&r, 0.2, 1), prox_v3_sub(c.center, sg.a));
            break;
        default: break;
        }
        check(c, sg);
    }
}

/* Local extrema of the squared line distance by sampling + golden refinement, matched to the
 * returned stationary angles; returned angles must have a tiny derivative. */
static void check_stationary(prox_circle c, prox_vec3 p, prox_vec3 w, int *checked)
{
    prox_vec3 n = prox_v3_normalize(c.normal);
    prox_fcircle f = prox_fcircle_make(c.center, n, c.radius);
    double th[4];
    int cnt = -1;
    int deg = prox_circle_line_stationary(&f, p, w, th, &cnt);
    assert_int_equal(deg, 0);
    assert_true(cnt >= 2 && cnt <= 4);
    prox_segment sg = {p, prox_v3_add(p, w)};
    prob P = make_prob(&c, &sg, 1);
    ld v[NS], step = 2 * (ld)PROX_PI / NS, ext[8];
    int ne = 0;
    for (int i = 0; i < NS; ++i) v[i] = pval(&P, i * step);
    for (int i = 0; i < NS && ne < 8; ++i) {
        ld a = v[(i + NS - 1) % NS], b = v[(i + 1) % NS];
        int mn = v[i] < a && v[i] <= b, mx = v[i] > a && v[i] >= b;
        if (mn || mx) tb_golden(pval, &P, (i - 1) * step, (i + 1) * step, mn ? 1 : -1, &ext[ne++]);
    }
    /* well-separated extrema only (near-double ones are ill-posed for the brute force) */
    for (int i = 0; i < ne; ++i)
        for (int j = 0; j < ne; ++j) {
            ld dd = fabsl(ext[i] - ext[j]);
            dd = fminl(dd, 2 * (ld)PROX_PI - dd);
            if (i != j && dd < 0.05L) return;
        }
    ld scale2 = P.r * P.r + ldot(lsub(P.c, P.a), lsub(P.c, P.a));
    for (int i = 0; i < ne; ++i) {
        int found = 0;
        for (int j = 0; j < cnt; ++j) {
            ld dd = fabsl(ext[i] - th[j]);
            dd = fmodl(dd, 2 * (ld)PROX_PI);
            dd = fminl(dd, 2 * (ld)PROX_PI - dd);
            if (dd < 1e-6L) found = 1;
        }
        if (!found) print_error("extremum %.17Lg not among %d returned angles\n", ext[i], cnt);
        assert_true(found);
    }
    for (int j = 0; j < cnt; ++j) { /* g'(th) ~ 0: central difference in long double */
        ld hgt = 1e-7L, der = (pval(&P, th[j] + hgt) - pval(&P, th[j] - hgt)) / (2 * hgt);
        assert_true(fabsl(der) <= 1e-6L * scale2);
    }
    ++*checked;
}

static void test_circle_line_stationary_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(808);
    int checked = 0;
    for (int i = 0; i < 6000; ++i) {
        double s = pow(10.0, test_range(&r, -3, 3));
        prox_circle c = {prox_v3_scale(test_unit(&r), s * test_range(&r, 0, 2)), test_unit(&r), s * test_range(&r, 0.1, 1.5)};
        prox_vec3 p = prox_v3_scale(test_unit(&r), s * test_range(&r, 0, 2)), w = test_unit(&r);
        if (i % 4 == 1) p = prox_v3_mad(c.center, s * test_range(&r, -0.5, 0.5), test_unit(&r)); /* near the centre */
        if (i % 4 == 2) w = prox_v3_normalize(prox_v3_mad(c.normal, 0.05, test_unit(&r)));       /* near the axis direction */
        check_stationary(c, p, w, &checked);
    }
    assert_true(checked > 3000);
}

static void test_circle_line_stationary_special(void **st)
{
    (void)st;
    /* circle in the xy plane: frame u = x, v = y (prox_v3_any_perp of z). */
    prox_fcircle f = prox_fcircle_make(prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1);
    assert_near(f.u.x, 1, 0);
    double th[4];
    int n;
    /* line x = 5 along y: g = (cos th - 5)^2, stationary at 0 and pi exactly (pi: the x = inf root) */
    assert_int_equal(prox_circle_line_stationary(&f, prox_v3(5, 0, 0), prox_v3(0, 1, 0), th, &n), 0);
    assert_int_equal(n, 2);
    assert_near(th[0], 0, 1e-15);
    assert_near(th[1], PROX_PI, 1e-15);
    /* line x = 5 along z: g = (cos th - 5)^2 + sin^2 th: again 0 and pi */
    assert_int_equal(prox_circle_line_stationary(&f, prox_v3(5, 0, 3), prox_v3(0, 0, 1), th, &n), 0);
    assert_int_equal(n, 2);
    assert_near(th[1], PROX_PI, 1e-15);
    /* line through the centre in the plane, along x: g = sin^2: 0, pi/2, pi, 3pi/2 */
    assert_int_equal(prox_circle_line_stationary(&f, prox_v3(0, 0, 0), prox_v3(1, 0, 0), th, &n), 0);
    assert_int_equal(n, 4);
    for (int i = 0; i < 4; ++i) assert_near(th[i], i * PROX_PI / 2, 1e-14);
    /* the axis itself: degenerate */
    assert_int_equal(prox_circle_line_stationary(&f, prox_v3(0, 0, 7), prox_v3(0, 0, -1), th, &n), 1);
    assert_int_equal(n, 0);
}

static void test_circle_segment_special(void **st)
{
    (void)st;
    prox_circle c = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1};
    /* segment on the axis: a set, distance r at the centre */
    prox_prim_result res = check(c, (prox_segment){prox_v3(0, 0, -2), prox_v3(0, 0, 3)});
    assert_int_equal(res.set, 1);
    assert_near(res.distance, 1, 1e-15);
    assert_near(res.s2[0], 0.4, 1e-15);
    /* axis segment above the plane */
    res = check(c, (prox_segment){prox_v3(0, 0, 2), prox_v3(0, 0, 3)});
    assert_int_equal(res.set, 1);
    assert_near(res.distance, sqrt(5.0), 1e-15);
    /* parallel to the axis outside: distance 2 at th = 0 */
    res = check(c, (prox_segment){prox_v3(3, 0, -1), prox_v3(3, 0, 1)});
    assert_near(res.distance, 2, 1e-15);
    assert_near(res.s1[0], 0, 1e-15);
    /* piercing the rim */
    res = check(c, (prox_segment){prox_v3(0, -1, -1), prox_v3(0, -1, 1)});
    assert_near(res.distance, 0, 1e-15);
    /* chord through the disk: touches the circle at both ends */
    res = check(c, (prox_segment){prox_v3(-2, 0.5, 0), prox_v3(2, 0.5, 0)});
    assert_near(res.distance, 0, 1e-15);
    /* minimum at th = pi */
    res = check(c, (prox_segment){prox_v3(-4, -3, 1), prox_v3(-4, 3, 1)});
    assert_near(res.distance, sqrt(10.0), 1e-14);
    assert_near(res.s1[0], PROX_PI, 1e-12);
    /* tangent line in the plane */
    res = check(c, (prox_segment){prox_v3(1, -2, 0), prox_v3(1, 2, 0)});
    assert_near(res.distance, 0, 1e-15);
    /* scales and far away */
    check((prox_circle){prox_v3(1e6, 0, 0), prox_v3(1, 2, 3), 1e6}, (prox_segment){prox_v3(0, 3e6, 0), prox_v3(2e6, -1e6, 5e5)});
    check((prox_circle){prox_v3(1e-6, 0, 0), prox_v3(1, 2, 3), 1e-6}, (prox_segment){prox_v3(0, 3e-6, 0), prox_v3(2e-6, -1e-6, 5e-7)});
    check((prox_circle){prox_v3(1e8, 1e8, -1e8), prox_v3(1, 0, 1), 2}, (prox_segment){prox_v3(1e8 + 3, 1e8, -1e8), prox_v3(1e8, 1e8 + 4, -1e8 + 1)});
    /* invalid */
    prox_segment sg = {prox_v3(0, 0, 0), prox_v3(1, 0, 0)};
    prox_circle bad = c;
    bad.radius = 0;
    assert_int_equal(prox_circle_segment(&bad, &sg).status, PROX_EINVAL_RADIUS);
    bad = c;
    bad.normal = prox_v3(0, 0, 0);
    assert_int_equal(prox_circle_segment(&bad, &sg).status, PROX_EINVAL_AXIS);
    sg.b.z = INFINITY;
    assert_int_equal(prox_circle_segment(&c, &sg).status, PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_circle_segment(NULL, &sg).status, PROX_EINVAL_ARG);
}

/* Largest distance of a circle from a line (prox_circle_line_max_dist, the ellipse's farthest point)
 * against tb_circle_line_max_dist (samples refined by golden sections in long double), over random, parallel (circle plane
 * normal to the line), nearly parallel, edge-on, nearly edge-on and centre-near-the-line
 * configurations, to 1e-12 of max(r, centre distance). */
static void test_circle_line_max_dist(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(99);
    double worst = 0.0;
    for (int i = 0; i < 6000; ++i) {
        prox_vec3 w = test_unit(&g), n = test_unit(&g), q = prox_v3_normalize(prox_v3_cross(w, test_unit(&g)));
        double tilt = pow(10.0, test_range(&g, -12.0, -2.0));
        int k = i % 6;
        if (k == 1) n = w;
        if (k == 2) n = prox_v3_normalize(prox_v3_add(w, prox_v3_scale(q, tilt)));
        if (k == 3) n = q;
        if (k == 4) n = prox_v3_normalize(prox_v3_add(q, prox_v3_scale(w, tilt)));
        double r = pow(10.0, test_range(&g, -3.0, 1.0));
        prox_vec3 p = prox_v3(test_range(&g, -2, 2), test_range(&g, -2, 2), test_range(&g, -2, 2));
        prox_vec3 off = prox_v3_scale(test_unit(&g), k == 5 ? tilt : test_range(&g, 0.0, 3.0));
        prox_vec3 c = prox_v3_add(p, prox_v3_add(off, prox_v3_scale(w, test_range(&g, -2.5, 2.5))));
        prox_fcircle C = prox_fcircle_make(c, n, r);
        double got = prox_circle_line_max_dist(C.c, C.n, C.r, p, w);
        ld ref = tb_circle_line_max_dist(c, n, r, p, w);
        double S = fmax(r, prox_v3_dist(c, p));
        worst = fmax(worst, fabs(got - (double)ref) / S);
        assert_near(got, (double)ref, 1e-12 * S);
    }
    print_message("circle-line max distance: worst |error| / scale %.3g\n", worst);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_circle_segment_random),
        cmocka_unit_test(test_circle_segment_special),
        cmocka_unit_test(test_circle_line_stationary_random),
        cmocka_unit_test(test_circle_line_stationary_special),
        cmocka_unit_test(test_circle_line_max_dist),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
