/* BOX-SPH (box_sph.c): exact distance, proximal points, signed distance and repositioning of a box and
 * a sphere, against an independent brute force written here in long double: the signed distance of
 * the centre to the box from the box's 6 faces taken one by one (point-to-rectangle distance outside,
 * distance to the nearest face plane inside), never from the local-frame clamp that box_sph.c uses.
 * Hand-made cases: sphere touching an edge, touching a corner, inside the box, through a face (the last
 * two missed by the TRX report's edge-line test, LA-UR-13-26757 Sec. 3.3 / Fig. 9), box inside the
 * sphere, and the report's own edge-line figure (an edge line cutting the sphere). */
#include "test_brute_shapes.h"

/* Brute force: signed distance of x to the box (negative inside) and the nearest boundary point q.
 * Face f of 6: the corner (or corner + edge k) and the two other edges spanning it. */
static ld brute_signed(const void *solid, lv3 x, lv3 *q)
{
    const prox_box *b = solid;
    lv3 c0 = L(b->corner), e[3] = {L(b->edge[0]), L(b->edge[1]), L(b->edge[2])};
    int inside = 1;
    for (int k = 0; k < 3; ++k) {
        ld t = ldot(lsub(x, c0), e[k]) / ldot(e[k], e[k]);
        if (t < 0 || t > 1) inside = 0;
    }
    ld best = INFINITY;
    for (int f = 0; f < 6; ++f) {
        int k = f / 2, i = (k + 1) % 3, j = (k + 2) % 3;
        lv3 o = (f & 1) ? lmad(c0, 1, e[k]) : c0;
        ld s = ldot(lsub(x, o), e[i]) / ldot(e[i], e[i]), t = ldot(lsub(x, o), e[j]) / ldot(e[j], e[j]);
        if (!inside) { /* clamp onto the face rectangle */
            s = s < 0 ? 0 : (s > 1 ? 1 : s);
            t = t < 0 ? 0 : (t > 1 ? 1 : t);
        }
        lv3 p = lmad(lmad(o, s, e[i]), t, e[j]);
        ld d = lnorm(lsub(x, p));
        if (d < best) best = d, *q = p;
    }
    return inside ? -best : best;
}

static prox_box rand_box(test_rng *g, prox_vec3 c, double lo, double hi)
{
    test_rot R = test_random_rot(g);
    prox_box b;
    for (int k = 0; k < 3; ++k) b.edge[k] = prox_v3_scale(test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2)), test_range(g, lo, hi));
    b.corner = prox_v3_sub(c, prox_v3_scale(prox_v3_add(prox_v3_add(b.edge[0], b.edge[1]), b.edge[2]), 0.5));
    return b;
}

/* Checks one pair against the brute force: distance, points and certificate when disjoint, common
 * point when not; signed distance and its witnesses; repositioning to a margin. */
static void check_pair(const prox_box *b, const prox_sph *s, int *n_dis, int *n_ov)
{
    tbs_solid A = {prox_shape_from_box(*b), b, brute_signed};
    ld sd = tbs_check_sph_distance(&A, s, prox_box_sph_distance(b, s), n_dis, n_ov);
    tbs_check_sph_signed(&A, s, prox_box_sph_signed_distance(b, s), sd);
    tbs_check_sph_reposition(&A, s, sd);
}

static void test_random_pairs(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(505);
    int dis = 0, ov = 0;
    for (int i = 0; i < 6000; ++i) {
        /* mixed scales and offsets: unit scenes, thin boxes, big spheres, far from the origin */
        double scale = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 1e-3 : 1e3);
        prox_vec3 off = i % 5 == 0 ? prox_v3(1e3 * scale, -2e3 * scale, 5e2 * scale) : prox_v3(0, 0, 0);
        prox_vec3 cb = prox_v3_add(off, prox_v3(test_range(&g, -1, 1) * scale, test_range(&g, -1, 1) * scale, test_range(&g, -1, 1) * scale));
        prox_box b = rand_box(&g, cb, (i % 7 == 0 ? 0.01 : 0.2) * scale, 2.0 * scale);
        prox_sph s = {prox_v3_add(off, prox_v3(test_range(&g, -2, 2) * scale, test_range(&g, -2, 2) * scale, test_range(&g, -2, 2) * scale)),
                      test_range(&g, 0.05, i % 11 == 0 ? 4.0 : 1.2) * scale};
        check_pair(&b, &s, &dis, &ov);
    }
    print_message("box-sph: %d disjoint, %d overlapping (the rest within tol of touching)\n", dis, ov);
    assert_true(dis > 1000 && ov > 1000);
}

static prox_box unit_cube(void)
{
    prox_rpp r = {0, 1, 0, 1, 0, 1};
    return prox_rpp_to_box(&r);
}

/* The sphere along the outward bisector of an edge / a corner at gap g: distance g, the edge point or
 * the corner closest; touching (g = 0) intersects. The whole scene is also rotated. */
static void test_edge_and_corner(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(3);
    for (int rot = 0; rot < 2; ++rot) {
        test_rot R = test_random_rot(&g);
        for (int corner = 0; corner < 2; ++corner)
            for (int k = 0; k < 3; ++k) {
                double gap = k == 0 ? 0.0 : (k == 1 ? 0.125 : 1e-9), rad = 0.375;
                prox_vec3 foot = corner ? prox_v3(1, 1, 1) : prox_v3(1, 0.25, 1); /* edge along y at x = z = 1 */
                prox_vec3 n = corner ? prox_v3_normalize(prox_v3(1, 1, 1)) : prox_v3_normalize(prox_v3(1, 0, 1));
                prox_box b = unit_cube();
                prox_sph s = {prox_v3_mad(foot, rad + gap, n), rad};
                if (rot) {
                    b.corner = test_rot_apply(&R, b.corner);
                    for (int e = 0; e < 3; ++e) b.edge[e] = test_rot_apply(&R, b.edge[e]);
                    s.center = test_rot_apply(&R, s.center);
                    foot = test_rot_apply(&R, foot);
                }
                prox_distance_result d = prox_box_sph_distance(&b, &s);
                assert_int_equal(d.status, PROX_OK);
                if (gap == 0.0) {
                    assert_true(d.intersect);
                    assert_true(prox_shape_relation(&(prox_shape){PROX_SHAPE_BOX, {.box = b}},
                                                    &(prox_shape){PROX_SHAPE_SPH, {.sph = s}}, -1)
                                    .relation == PROX_REL_TOUCHING);
                } else {
                    assert_false(d.intersect);
                    assert_near(d.distance, gap, 1e-15);
                    assert_near(prox_v3_dist(d.p1, foot), 0.0, 4e-16);
                }
                assert_near(prox_box_sph_signed_distance(&b, &s).sd, gap, 1e-15);
            }
    }
}

/* Sphere inside the box: intersecting though no edge line meets it (report Sec. 3.3 says no); the
 * depth is the distance of the centre to the nearest face plus the radius, witness on that face. */
static void test_sphere_inside(void **st)
{
    (void)st;
    prox_box b = unit_cube();
    prox_sph s = {{0.3, 0.5, 0.55}, 0.2};
    prox_distance_result d = prox_box_sph_distance(&b, &s);
    assert_true(d.intersect);
    prox_signed_result r = prox_box_sph_signed_distance(&b, &s);
    assert_near(r.sd, -0.5, 1e-15);
    assert_near(r.normal.x, -1.0, 0.0);
    assert_near(r.p1.x, 0.0, 0.0);
    assert_near(r.p2.x, 0.5, 1e-15);
    prox_shape A = prox_shape_from_box(b), B = prox_shape_from_sph(s);
    prox_relation_result rel = prox_shape_relation(&A, &B, -1);
    assert_int_equal(rel.relation, PROX_REL_B_IN_A);
    assert_near(rel.clearance, 0.1, 1e-15);
    /* centre exactly at the box centre: every face is as near; any of them is a valid exit */
    s.center = prox_v3(0.5, 0.5, 0.5);
    r = prox_box_sph_signed_distance(&b, &s);
    assert_near(r.sd, -0.7, 1e-15);
    assert_near(prox_v3_dist(r.p2, prox_v3_mad(r.p1, r.sd, r.normal)), 0.0, 1e-15);
}

/* Sphere through the middle of a face, touching no edge (missed by the edge-line test); a centre on
 * the face itself; the box inside a big sphere. */
static void test_through_face_and_box_inside(void **st)
{
    (void)st;
    prox_rpp big = {-5, 5, -5, 5, -1, 0};
    prox_box b = prox_rpp_to_box(&big);
    prox_sph s = {{0.5, -0.25, 0.1}, 0.3};
    prox_distance_result d = prox_box_sph_distance(&b, &s);
    assert_true(d.intersect);
    assert_near(d.p1.z, 0.0, 0.0);
    prox_signed_result r = prox_box_sph_signed_distance(&b, &s);
    assert_near(r.sd, -0.2, 1e-15);
    assert_near(r.normal.z, 1.0, 0.0);
    s.center.z = 0.0; /* centre on the face */
    r = prox_box_sph_signed_distance(&b, &s);
    assert_near(r.sd, -0.3, 1e-15);
    assert_near(fabs(r.normal.z), 1.0, 0.0);
    /* unit cube inside a sphere of radius sqrt(3)/2 + 0.01 about its centre */
    prox_box c = unit_cube();
    prox_sph ball = {{0.5, 0.5, 0.5}, sqrt(0.75) + 0.01};
    prox_shape A = prox_shape_from_box(c), B = prox_shape_from_sph(ball);
    prox_relation_result rel = prox_shape_relation(&A, &B, -1);
    assert_int_equal(rel.relation, PROX_REL_A_IN_B);
    assert_near(rel.clearance, 0.01, 1e-15);
    assert_near(prox_box_sph_signed_distance(&c, &ball).sd, -(0.5 + sqrt(0.75) + 0.01), 1e-15);
}

/* The report's Fig. 9 situation: an edge line of the box cuts the sphere (Eq. (50) has real roots)
 * although the edge segment itself stays clear; the report's line test calls it a collision (erratum:
 * t must be in [0, 1]). The exact distance says disjoint. */
static void test_report_edge_line(void **st)
{
    (void)st;
    prox_box b = unit_cube();
    prox_sph s = {{2.0, 0.0, 0.0}, 0.5}; /* the x-axis edge line (y = z = 0) passes through the centre */
    prox_distance_result d = prox_box_sph_distance(&b, &s);
    assert_false(d.intersect);
    assert_near(d.distance, 0.5, 1e-15);
    assert_near(d.p1.x, 1.0, 0.0);
    /* the line roots of Eqs. (50)-(51) with coordinates relative to the centre (erratum 25): t = 1.5, 2.5 */
    double a = 1, bb = 2 * (1 * (0 - 2.0)), c = 4.0 - 0.25, disc = bb * bb - 4 * a * c;
    assert_true(disc > 0);
    assert_near((-bb - sqrt(disc)) / 2, 1.5, 1e-15);
}

/* Invalid input: named statuses, never a number. */
static void test_invalid(void **st)
{
    (void)st;
    prox_box b = unit_cube();
    prox_sph s = {{0, 0, 0}, 0.0};
    assert_int_equal(prox_box_sph_distance(&b, &s).status, PROX_EINVAL_RADIUS);
    s.radius = 1.0;
    s.center.y = INFINITY;
    assert_int_equal(prox_box_sph_signed_distance(&b, &s).status, PROX_EINVAL_NONFINITE);
    b.edge[1] = prox_v3(0.5, 1, 0);
    s.center.y = 0;
    assert_int_equal(prox_box_sph_distance(&b, &s).status, PROX_EINVAL_BOX_ORTHO);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_pairs),       cmocka_unit_test(test_edge_and_corner),
        cmocka_unit_test(test_sphere_inside),      cmocka_unit_test(test_through_face_and_box_inside),
        cmocka_unit_test(test_report_edge_line),   cmocka_unit_test(test_invalid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
