/* RCC-SPH (rcc_sph.c): exact distance, proximal points, signed distance and repositioning of a
 * cylinder and a sphere, against an independent brute force written here in long double: the signed
 * distance of the centre to the cylinder as the least distance to the three boundary pieces taken one
 * by one (lateral patch, base disk, top disk), never the axial/radial clamp that rcc_sph.c uses.
 * Hand-made cases: sphere touching the rim, on the end face, beside the side, inside the cylinder, the
 * cylinder inside the sphere, and the report's configurations (LA-UR-13-26757 Sec. 3.5, Figs. 16-22:
 * Configuration 1 beside the side; Configurations 2/3 beyond an end, Types 1-4). */
#include "test_brute_shapes.h"

/* Brute force: signed distance of x to the solid cylinder (negative inside) and the nearest boundary
 * point q, as the minimum over the lateral patch and the two end disks. */
static ld brute_signed(const void *solid, lv3 x, lv3 *q)
{
    const prox_rcc *c = solid;
    lv3 b = L(c->base), ax = L(c->axis);
    ld h = lnorm(ax), r = c->radius;
    lv3 w = {ax.x / h, ax.y / h, ax.z / h};
    ld t = ldot(lsub(x, b), w);
    lv3 rad = lmad(lsub(x, b), -t, w);
    ld rho = lnorm(rad);
    lv3 e = rho > 0 ? (lv3){rad.x / rho, rad.y / rho, rad.z / rho} : (lv3){0, 0, 0};
    if (!(rho > 0)) { /* on the axis: any radial direction */
        lv3 a = fabsl(w.x) < 0.5L ? (lv3){1, 0, 0} : (lv3){0, 1, 0};
        a = lmad(a, -ldot(a, w), w);
        e = (lv3){a.x / lnorm(a), a.y / lnorm(a), a.z / lnorm(a)};
    }
    int inside = t >= 0 && t <= h && rho <= r;
    /* lateral patch: the point at the clamped height on the radial line */
    ld tc = t < 0 ? 0 : (t > h ? h : t);
    ld best = sqrtl((t - tc) * (t - tc) + (rho - r) * (rho - r));
    *q = lmad(lmad(b, tc, w), r, e);
    for (int top = 0; top < 2; ++top) { /* disks: the point at the clamped radius in the end plane */
        ld z = top ? h : 0, rr = rho < r ? rho : r;
        ld d = sqrtl((t - z) * (t - z) + (rho - rr) * (rho - rr));
        if (d < best) best = d, *q = lmad(lmad(b, z, w), rr, e);
    }
    return inside ? -best : best;
}

/* One pair against the brute force (distance, points, certificate; signed distance, witnesses;
 * repositioning), in both argument orders of the generic entry point. */
static void check_pair(const prox_rcc *c, const prox_sph *s, int *n_dis, int *n_ov)
{
    tbs_solid A = {prox_shape_from_rcc(*c), c, brute_signed};
    double tol = 1e-12 * tbs_sph_pair_scale(&A, s);
    lv3 tmp;
    ld sd = tbs_check_sph_distance(&A, s, prox_rcc_sph_distance(c, s), n_dis, n_ov);
    prox_signed_result r = prox_rcc_sph_signed_distance(c, s);
    if (fabsl(brute_signed(c, L(r.p1), &tmp)) > tol)
        print_error("c %a %a %a ax %a %a %a r %a s %a %a %a R %a sd %g p1 %g %g %g\n", c->base.x, c->base.y, c->base.z, c->axis.x, c->axis.y, c->axis.z, c->radius, s->center.x, s->center.y, s->center.z, s->radius, (double)sd, r.p1.x, r.p1.y, r.p1.z);
    tbs_check_sph_signed(&A, s, r, sd);
    /* generic entry, sphere first: mirrored answer */
    prox_shape B = prox_shape_from_sph(*s);
    prox_signed_result m = prox_shape_signed_distance(&B, &A.shape);
    assert_near(m.sd, r.sd, 0.0);
    assert_near(prox_v3_dist(m.p1, r.p2), 0.0, 0.0);
    assert_near(m.normal.x, -r.normal.x, 0.0);
    tbs_check_sph_reposition(&A, s, sd);
}

static void test_random_pairs(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(606);
    int dis = 0, ov = 0;
    for (int i = 0; i < 6000; ++i) {
        double scale = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 1e-3 : 1e3);
        prox_vec3 off = i % 5 == 0 ? prox_v3(-1e3 * scale, 2e3 * scale, 7e2 * scale) : prox_v3(0, 0, 0);
        prox_rcc c;
        c.axis = prox_v3_scale(test_unit(&g), test_range(&g, i % 7 == 0 ? 0.01 : 0.2, 3.0) * scale);
        c.radius = test_range(&g, i % 9 == 0 ? 0.01 : 0.1, 1.5) * scale;
        c.base = prox_v3_add(off, prox_v3(test_range(&g, -1, 1) * scale, test_range(&g, -1, 1) * scale, test_range(&g, -1, 1) * scale));
        prox_sph s = {prox_v3_add(off, prox_v3(test_range(&g, -2.5, 2.5) * scale, test_range(&g, -2.5, 2.5) * scale, test_range(&g, -2.5, 2.5) * scale)),
                      test_range(&g, 0.05, i % 11 == 0 ? 4.0 : 1.2) * scale};
        if (i % 13 == 0) /* centre on the axis line */
            s.center = prox_v3_mad(c.base, test_range(&g, -1, 2), c.axis);
        check_pair(&c, &s, &dis, &ov);
    }
    print_message("rcc-sph: %d disjoint, %d overlapping (the rest within tol of touching)\n", dis, ov);
    assert_true(dis > 1000 && ov > 1000);
}

/* The test cylinder: axis z, base at the origin, height 2, radius 1, optionally rotated and moved. */
typedef struct scene {
    test_rot R;
    prox_vec3 off;
} scene;
static prox_vec3 place(const scene *sc, prox_vec3 x) { return prox_v3_add(test_rot_apply(&sc->R, x), sc->off); }
static prox_rcc cyl(const scene *sc)
{
    prox_rcc c = {place(sc, prox_v3(0, 0, 0)), test_rot_apply(&sc->R, prox_v3(0, 0, 2)), 1.0};
    return c;
}

/* Distance g from the feature point `foot` along the outward direction n (unit, local frame). */
static void expect_gap(const scene *sc, prox_vec3 foot, prox_vec3 n, double rad, double gap)
{
    prox_rcc c = cyl(sc);
    prox_sph s = {place(sc, prox_v3_mad(foot, rad + gap, n)), rad};
    prox_distance_result d = prox_rcc_sph_distance(&c, &s);
    assert_int_equal(d.status, PROX_OK);
    prox_shape A = prox_shape_from_rcc(c), B = prox_shape_from_sph(s);
    if (gap == 0.0) {
        assert_true(d.intersect);
        assert_int_equal(prox_shape_relation(&A, &B, -1).relation, PROX_REL_TOUCHING);
    } else {
        assert_false(d.intersect);
        assert_near(d.distance, gap, 4e-15);
        assert_near(prox_v3_dist(d.p1, place(sc, foot)), 0.0, 4e-15);
    }
    assert_near(prox_rcc_sph_signed_distance(&c, &s).sd, gap, 4e-15);
}

/* Touching the rim (along its outward bisector), the end face, the side; gaps 0, 1e-9, 0.25. */
static void test_rim_face_side(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(8);
    for (int k = 0; k < 2; ++k) {
        scene sc = {test_random_rot(&g), k ? prox_v3(3, -1, 2) : prox_v3(0, 0, 0)};
        if (!k) sc.R = (test_rot){{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        double gaps[3] = {0.0, 1e-9, 0.25};
        for (int i = 0; i < 3; ++i) {
            double c = cos(0.7), s = sin(0.7);
            expect_gap(&sc, prox_v3(c, s, 2), prox_v3_normalize(prox_v3(c, s, 1)), 0.4, gaps[i]); /* top rim */
            expect_gap(&sc, prox_v3(c, s, 0), prox_v3_normalize(prox_v3(c, s, -1)), 0.4, gaps[i]); /* base rim */
            expect_gap(&sc, prox_v3(0.3, -0.2, 2), prox_v3(0, 0, 1), 0.6, gaps[i]);               /* end face */
            expect_gap(&sc, prox_v3(c, s, 1.2), prox_v3(c, s, 0), 0.6, gaps[i]);                   /* side */
        }
    }
}

/* Sphere inside the cylinder (nearest exit through the side), cylinder inside the sphere. */
static void test_nested(void **st)
{
    (void)st;
    prox_rcc c = {{0, 0, 0}, {0, 0, 2}, 1};
    prox_sph s = {{0.2, 0, 1.1}, 0.5};
    prox_signed_result r = prox_rcc_sph_signed_distance(&c, &s);
    assert_near(r.sd, -1.3, 1e-15); /* side at 0.8, base at 1.1, top at 0.9: side, plus R */
    assert_near(r.normal.x, 1.0, 0.0);
    assert_near(r.p1.x, 1.0, 1e-15);
    prox_shape A = prox_shape_from_rcc(c), B = prox_shape_from_sph(s);
    prox_relation_result rel = prox_shape_relation(&A, &B, -1);
    assert_int_equal(rel.relation, PROX_REL_B_IN_A);
    assert_near(rel.clearance, 0.3, 1e-15);
    assert_true(prox_rcc_sph_distance(&c, &s).intersect);
    /* centre on the axis, at mid-height: the side (distance 1) is nearer than the ends (distance 1.5) */
    prox_rcc tall = {{0, 0, -1.5}, {0, 0, 3}, 1};
    prox_sph mid = {{0, 0, 0}, 0.25};
    r = prox_rcc_sph_signed_distance(&tall, &mid);
    assert_near(r.sd, -1.25, 1e-15);
    assert_near(prox_v3_dot(r.normal, prox_v3(0, 0, 1)), 0.0, 1e-15);
    assert_near(prox_v3_dist(r.p2, prox_v3_mad(r.p1, r.sd, r.normal)), 0.0, 1e-15);
    /* the cylinder inside a sphere: (h/2)^2 + r^2 = 2 < R^2 */
    prox_sph ball = {{0, 0, 1}, 1.5};
    B = prox_shape_from_sph(ball);
    rel = prox_shape_relation(&A, &B, -1);
    assert_int_equal(rel.relation, PROX_REL_A_IN_B);
    assert_near(rel.clearance, 1.5 - sqrt(2.0), 1e-15);
    assert_near(prox_rcc_sph_signed_distance(&c, &ball).sd, -2.5, 1e-15); /* exit: R + 1 along the side */
}

/* The report's configurations for a cylinder along z from 0 to 2, radius 1 (Sec. 3.5). The sphere's
 * centre at axial d (negative: beyond the base, Configuration 2) and radial rho. */
static void test_report_configurations(void **st)
{
    (void)st;
    prox_rcc c = {{0, 0, 0}, {0, 0, 2}, 1};
    struct {
        double axial, rho, R, sd;
    } cases[] = {
        {1.0, 1.5, 0.3, 0.2},                          /* Config. 1: beside the side, clear */
        {1.0, 1.5, 0.7, -0.2},                         /* Config. 1: crossing the side */
        {-0.5, 0.4, 0.3, 0.2},                         /* Config. 2 Type 1: short of the end plane */
        {-0.5, 2.0, 0.8, sqrt(0.25 + 1.0) - 0.8},      /* Type 2: crosses the end plane outside the rim */
        {-0.3, 1.3, 0.5, sqrt(0.09 + 0.09) - 0.5},     /* Type 3: side-end (rim) intersection */
        {-0.3, 0.5, 0.5, -0.2},                        /* Type 4: end intersection */
        {2.4, 1.2, 0.3, sqrt(0.16 + 0.04) - 0.3},      /* Config. 3 beyond the top, rim nearest */
        {2.4, 0.0, 0.3, 0.1},                          /* Config. 3 on the axis */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        prox_sph s = {{cases[i].rho * cos(0.3), cases[i].rho * sin(0.3), cases[i].axial}, cases[i].R};
        prox_signed_result r = prox_rcc_sph_signed_distance(&c, &s);
        assert_int_equal(r.status, PROX_OK);
        assert_near(r.sd, cases[i].sd, 1e-15);
        prox_distance_result d = prox_rcc_sph_distance(&c, &s);
        assert_int_equal(d.intersect, cases[i].sd <= 0);
        if (!d.intersect) assert_near(d.distance, cases[i].sd, 1e-15);
    }
}

/* Invalid input: named statuses. */
static void test_invalid(void **st)
{
    (void)st;
    prox_rcc c = {{0, 0, 0}, {0, 0, 0}, 1};
    prox_sph s = {{0, 0, 0}, 1};
    assert_int_equal(prox_rcc_sph_distance(&c, &s).status, PROX_EINVAL_AXIS);
    c.axis.z = 1;
    s.radius = NAN;
    assert_int_equal(prox_rcc_sph_signed_distance(&c, &s).status, PROX_EINVAL_NONFINITE);
    s.radius = -1;
    assert_int_equal(prox_rcc_sph_distance(&c, &s).status, PROX_EINVAL_RADIUS);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_pairs), cmocka_unit_test(test_rim_face_side),
        cmocka_unit_test(test_nested),       cmocka_unit_test(test_report_configurations),
        cmocka_unit_test(test_invalid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
