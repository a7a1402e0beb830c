/* Point-to-primitive solvers (point_segment.c, point_circle.c, point_disk.c, point_cylsurf.c) against an
 * independent brute force in long double: dense sampling of the primitive's angle, the remaining
 * parameter by clamped projection, golden-section refinement of the best samples. */
#include "test_brute.h"

/* An orthonormal frame (e1, e2) of the plane orthogonal to unit n, built independently of the library. */
static void lframe(lv3 n, lv3 *e1, lv3 *e2)
{
    lv3 t = fabsl(n.x) < 0.6L ? (lv3){1, 0, 0} : (lv3){0, 1, 0};
    *e1 = lunit(lsub(t, lsc(n, ldot(t, n))));
    *e2 = lcross(n, *e1);
}

/* Brute-force min over theta of g(theta) = dist(x, segment(theta)), where segment(theta) is
 * [o + rr(cos e1 + sin e2), + len n] (len 0: a circle point; rr = 0 handled by the caller). */
typedef struct angfam {
    lv3 o, e1, e2, dir;
    ld rr;
    int radial; /* 1: the segment is radial, from o to o + rr(cos e1 + sin e2) */
} angfam;
typedef struct fam_query {
    const angfam *F;
    lv3 x;
} fam_query;
static ld fam_eval(const void *ctx, ld th)
{
    const fam_query *Q = ctx;
    const angfam *F = Q->F;
    lv3 rad = ladd(lsc(F->e1, cosl(th)), lsc(F->e2, sinl(th)));
    if (F->radial) return lseg_dist(Q->x, F->o, lsc(rad, F->rr));
    return lseg_dist(Q->x, ladd(F->o, lsc(rad, F->rr)), F->dir);
}
/* 128 samples of theta, every sampled local minimum refined by golden section. */
static ld fam_min(const angfam *F, lv3 x)
{
    fam_query Q = {F, x};
    return tb_min_periodic(fam_eval, &Q, 128);
}

/* Random geometry: a scale, an origin offset, and a point near the primitive. */
typedef struct scene {
    double scale;
    prox_vec3 origin;
} scene;
static scene random_scene(test_rng *r, int i)
{
    scene s;
    s.scale = pow(10.0, test_range(r, -3, 3));
    if (i % 10 == 0) s.scale = 1e6;
    if (i % 10 == 1) s.scale = 1e-6;
    s.origin = prox_v3(0, 0, 0);
    if (i % 7 == 0) s.origin = prox_v3_scale(test_unit(r), 1e8);
    else if (i % 3 == 0) s.origin = prox_v3_scale(test_unit(r), s.scale * test_range(r, 0, 10));
    return s;
}
static prox_vec3 rpt(test_rng *r, const scene *s, double spread)
{
    return prox_v3_mad(s->origin, s->scale * spread * test_range(r, 0, 1), test_unit(r));
}
static double tol_of(double scale) { return 1e-12 * scale; }
static double scale_of(prox_vec3 a, double s)
{
    double m = prox_v3_maxabs(a);
    return m > s ? m : s;
}

/* --- point-segment --- */
static void check_point_segment(prox_vec3 p, prox_segment sg)
{
    prox_prim_result res = prox_point_segment(p, &sg);
    assert_int_equal(res.status, PROX_OK);
    double sc = scale_of(p, scale_of(sg.a, scale_of(sg.b, prox_v3_dist(sg.a, sg.b)))), tol = tol_of(sc);
    ld bf = lseg_dist(L(p), L(sg.a), lsub(L(sg.b), L(sg.a)));
    /* golden section on t as the "brute force" cross-check of the clamped projection */
    assert_near(res.distance, (double)bf, tol);
    assert_near(prox_v3_dist(res.p1, res.p2), res.distance, tol);
    assert_true(res.s2[0] >= 0.0 && res.s2[0] <= 1.0);
    assert_near(tb_seg_point_err(res.p2, L(sg.a), lsub(L(sg.b), L(sg.a)), res.s2[0]), 0, tol);
    assert_true(res.p1.x == p.x && res.p1.y == p.y && res.p1.z == p.z);
}
static void test_point_segment_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(101);
    for (int i = 0; i < 4000; ++i) {
        scene s = random_scene(&r, i);
        prox_segment sg = {rpt(&r, &s, 1), rpt(&r, &s, 1)};
        if (i % 50 == 5) sg.b = sg.a; /* zero length */
        check_point_segment(rpt(&r, &s, 2), sg);
    }
}
static void test_point_segment_special(void **st)
{
    (void)st;
    prox_segment sg = {prox_v3(0, 0, 0), prox_v3(2, 0, 0)};
    prox_prim_result res = prox_point_segment(prox_v3(1, 3, 0), &sg);
    assert_near(res.distance, 3, 1e-15);
    assert_near(res.s2[0], 0.5, 1e-15);
    res = prox_point_segment(prox_v3(-3, 4, 0), &sg);
    assert_near(res.distance, 5, 1e-15);
    assert_near(res.s2[0], 0.0, 0);
    res = prox_point_segment(prox_v3(1, 0, 0), &sg); /* on the segment */
    assert_near(res.distance, 0, 0);
    prox_segment z = {prox_v3(1, 1, 1), prox_v3(1, 1, 1)};
    res = prox_point_segment(prox_v3(1, 1, 2), &z);
    assert_near(res.distance, 1, 0);
    prox_segment far = {prox_v3(1e8, 1e8, 1e8), prox_v3(1e8 + 1, 1e8, 1e8)};
    res = prox_point_segment(prox_v3(1e8 + 0.5, 1e8 + 1, 1e8), &far);
    assert_near(res.distance, 1, 1e-8);
    res = prox_point_segment(prox_v3(NAN, 0, 0), &sg);
    assert_int_equal(res.status, PROX_EINVAL_NONFINITE);
    res = prox_point_segment(prox_v3(0, 0, 0), NULL);
    assert_int_equal(res.status, PROX_EINVAL_ARG);
    prox_segment ov = {prox_v3(-1.5e308, 0, 0), prox_v3(1.5e308, 0, 0)};
    res = prox_point_segment(prox_v3(0, 0, 0), &ov);
    assert_int_equal(res.status, PROX_EINVAL_NONFINITE);
}

/* --- point-circle, point-disk --- */
static prox_circle random_circle(test_rng *r, const scene *s)
{
    prox_circle c = {rpt(r, s, 1), test_unit(r), s->scale * test_range(r, 0.05, 2)};
    return c;
}
static angfam circle_family(const prox_circle *c, int radial)
{
    angfam F;
    F.o = L(c->center);
    lv3 n = lunit(L(c->normal));
    lframe(n, &F.e1, &F.e2);
    F.dir = (lv3){0, 0, 0};
    F.rr = c->radius;
    F.radial = radial;
    return F;
}
/* Height of x over the plane of c and its distance from c's axis, in long double. */
static void plane_coords(prox_vec3 x, const prox_circle *c, ld *h, ld *rho)
{
    lv3 n = lunit(L(c->normal)), d = lsub(L(x), L(c->center));
    *h = ldot(d, n);
    *rho = lnorm(lsub(d, lsc(n, *h)));
}
static void check_on_circle(prox_vec3 x, const prox_circle *c, double tol)
{
    ld h, rho;
    plane_coords(x, c, &h, &rho);
    assert_near((double)h, 0, tol);
    assert_near((double)rho, c->radius, tol);
}
static void check_on_disk(prox_vec3 x, const prox_disk *c, double tol)
{
    ld h, rho;
    plane_coords(x, c, &h, &rho);
    assert_near((double)h, 0, tol);
    assert_true(rho <= c->radius + tol);
}
/* Checks shared by point-circle (radial 0) and point-disk (radial 1): status, distance against the
 * brute force, |p1 - p2| = distance. Returns the tolerance. */
static double check_round_common(const prox_prim_result *res, prox_vec3 p, const prox_circle *c, int radial)
{
    assert_int_equal(res->status, PROX_OK);
    double sc = scale_of(p, scale_of(c->center, c->radius)), tol = tol_of(sc);
    angfam F = circle_family(c, radial);
    assert_near(res->distance, (double)fam_min(&F, L(p)), tol);
    assert_near(prox_v3_dist(res->p1, res->p2), res->distance, tol);
    return tol;
}
static void check_point_circle(prox_vec3 p, prox_circle c)
{
    prox_prim_result res = prox_point_circle(p, &c);
    double tol = check_round_common(&res, p, &c, 0);
    check_on_circle(res.p2, &c, tol);
    prox_circle cu = c; /* prox_circle_point expects a unit normal */
    cu.normal = prox_v3_normalize(c.normal);
    assert_near(prox_v3_dist(prox_circle_point(&cu, res.s2[0]), res.p2), 0, 4 * tol);
    assert_true(res.s2[0] >= 0 && res.s2[0] < 2 * PROX_PI);
}
static void check_point_disk(prox_vec3 p, prox_disk c)
{
    prox_prim_result res = prox_point_disk(p, &c);
    double tol = check_round_common(&res, p, &c, 1);
    check_on_disk(res.p2, &c, tol);
    prox_vec3 u, v;
    prox_circle cu = c;
    cu.normal = prox_v3_normalize(c.normal);
    prox_circle_frame(&cu, &u, &v);
    prox_vec3 q = prox_v3_add(c.center, prox_v3_add(prox_v3_scale(u, res.s2[1] * cos(res.s2[0])),
                                                    prox_v3_scale(v, res.s2[1] * sin(res.s2[0]))));
    assert_near(prox_v3_dist(q, res.p2), 0, 4 * tol);
}
static void test_point_circle_disk_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(202);
    for (int i = 0; i < 2000; ++i) {
        scene s = random_scene(&r, i);
        prox_circle c = random_circle(&r, &s);
        prox_vec3 p = rpt(&r, &s, 3);
        if (i % 11 == 0) p = prox_v3_mad(c.center, test_range(&r, -1, 1) * s.scale, c.normal); /* on axis */
        if (i % 13 == 0) p = prox_v3_mad(prox_circle_point(&c, test_range(&r, 0, 6)), 1e-3 * s.scale, test_unit(&r));
        check_point_circle(p, c);
        check_point_disk(p, c);
    }
}
static void test_point_circle_disk_special(void **st)
{
    (void)st;
    prox_circle c = {prox_v3(0, 0, 0), prox_v3(0, 0, 2), 1}; /* non-unit normal is normalised */
    prox_prim_result res = prox_point_circle(prox_v3(0, 0, 1), &c);
    assert_int_equal(res.status, PROX_OK);
    assert_int_equal(res.set, 1);
    assert_near(res.distance, sqrt(2.0), 1e-15);
    res = prox_point_circle(prox_v3(3, 0, 0), &c);
    assert_int_equal(res.set, 0);
    assert_near(res.distance, 2, 1e-15);
    res = prox_point_disk(prox_v3(0.5, 0.2, -3), &c);
    assert_near(res.distance, 3, 1e-15);
    assert_near(res.p2.x, 0.5, 1e-15);
    res = prox_point_disk(prox_v3(0, 0, 0), &c);
    assert_near(res.distance, 0, 0);
    res = prox_point_disk(prox_v3(4, 0, 4), &c);
    assert_near(res.distance, 5, 1e-15);
    prox_circle big = {prox_v3(1e8, -1e8, 1e8), prox_v3(1, 1, 1), 1e6};
    check_point_circle(prox_v3(1e8, -1e8, 1e8 + 5e5), big);
    prox_circle tiny = {prox_v3(1e-6, 0, 0), prox_v3(0, 1, 0), 1e-6};
    check_point_circle(prox_v3(3e-6, 2e-6, 0), tiny);
    check_point_disk(prox_v3(3e-6, 2e-6, 0), tiny);
    prox_circle bad = c;
    bad.radius = 0;
    assert_int_equal(prox_point_circle(prox_v3(0, 0, 0), &bad).status, PROX_EINVAL_RADIUS);
    bad = c;
    bad.normal = prox_v3(0, 0, 0);
    assert_int_equal(prox_point_disk(prox_v3(0, 0, 0), &bad).status, PROX_EINVAL_AXIS);
    bad = c;
    bad.center.y = INFINITY;
    assert_int_equal(prox_point_disk(prox_v3(0, 0, 0), &bad).status, PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_point_circle(prox_v3(0, 0, 0), NULL).status, PROX_EINVAL_ARG);
}

/* --- point-cylsurf --- */
static void check_point_cylsurf(prox_vec3 p, prox_cylsurf cs)
{
    prox_prim_result res = prox_point_cylsurf(p, &cs);
    assert_int_equal(res.status, PROX_OK);
    double sc = scale_of(p, scale_of(cs.base, fmax(cs.radius, cs.height))), tol = tol_of(sc);
    angfam F;
    F.o = L(cs.base);
    lv3 n = lunit(L(cs.dir));
    lframe(n, &F.e1, &F.e2);
    F.dir = lsc(n, cs.height);
    F.rr = cs.radius;
    F.radial = 0;
    assert_near(res.distance, (double)fam_min(&F, L(p)), tol);
    assert_near(prox_v3_dist(res.p1, res.p2), res.distance, tol);
    lv3 d = lsub(L(res.p2), L(cs.base));
    ld z = ldot(d, n);
    assert_true(z >= -tol && z <= cs.height + tol);
    assert_near((double)lnorm(lsub(d, lsc(n, z))), cs.radius, tol);
    assert_near(res.s2[0], (double)z, tol);
    prox_circle ring = {prox_v3_mad(cs.base, res.s2[0], prox_v3_normalize(cs.dir)), prox_v3_normalize(cs.dir), cs.radius};
    assert_near(prox_v3_dist(prox_circle_point(&ring, res.s2[1]), res.p2), 0, 4 * tol);
}
static void test_point_cylsurf_random(void **st)
{
    (void)st;
    test_rng r = test_rng_seed(303);
    for (int i = 0; i < 2000; ++i) {
        scene s = random_scene(&r, i);
        prox_cylsurf cs = {rpt(&r, &s, 1), test_unit(&r), s.scale * test_range(&r, 0, 3), s.scale * test_range(&r, 0.05, 2)};
        if (i % 17 == 0) cs.height = 0;
        prox_vec3 p = rpt(&r, &s, 3);
        if (i % 11 == 0) p = prox_v3_mad(cs.base, test_range(&r, -1, 4) * s.scale, cs.dir);
        check_point_cylsurf(p, cs);
    }
}
static void test_point_cylsurf_special(void **st)
{
    (void)st;
    prox_cylsurf cs = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 4, 1};
    prox_prim_result res = prox_point_cylsurf(prox_v3(0, 0, 2), &cs);
    assert_int_equal(res.set, 1);
    assert_near(res.distance, 1, 1e-15);
    res = prox_point_cylsurf(prox_v3(0, 0, 7), &cs);
    assert_int_equal(res.set, 1);
    assert_near(res.distance, sqrt(10.0), 1e-15);
    res = prox_point_cylsurf(prox_v3(0.5, 0, 2), &cs);
    assert_int_equal(res.set, 0);
    assert_near(res.distance, 0.5, 1e-15);
    assert_near(res.s2[0], 2, 1e-15);
    res = prox_point_cylsurf(prox_v3(3, 0, -4), &cs);
    assert_near(res.distance, sqrt(20.0), 1e-14);
    prox_cylsurf bad = cs;
    bad.height = -1;
    assert_int_equal(prox_point_cylsurf(prox_v3(0, 0, 0), &bad).status, PROX_EINVAL_ARG);
    bad = cs;
    bad.radius = -1;
    assert_int_equal(prox_point_cylsurf(prox_v3(0, 0, 0), &bad).status, PROX_EINVAL_RADIUS);
    bad = cs;
    bad.dir = prox_v3(0, 0, 0);
    assert_int_equal(prox_point_cylsurf(prox_v3(0, 0, 0), &bad).status, PROX_EINVAL_AXIS);
    check_point_cylsurf(prox_v3(1e8 + 3, 1e8, 1e8 + 2), (prox_cylsurf){prox_v3(1e8, 1e8, 1e8), prox_v3(0, 0, 1), 4, 1});
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_point_segment_random),     cmocka_unit_test(test_point_segment_special),
        cmocka_unit_test(test_point_circle_disk_random), cmocka_unit_test(test_point_circle_disk_special),
        cmocka_unit_test(test_point_cylsurf_random),     cmocka_unit_test(test_point_cylsurf_special),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
