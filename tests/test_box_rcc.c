/* BOX-RCC hand-made cases (box_rcc.c): the intersections the TRX report's Sec. 3.2 misses (slab
 * through the side with no edge crossing the surface, box inside, cylinder inside) and exact distances
 * of rim-to-face, corner-to-rim, edge-to-lateral contacts. Random pairs are in test_query.c. */
#include "test_util.h"
#include "prox/query.h"

static prox_box aabb(double x0, double x1, double y0, double y1, double z0, double z1)
{
    prox_rpp r = {x0, x1, y0, y1, z0, z1};
    return prox_rpp_to_box(&r);
}

/* A slab |x| <= 0.5, |y|,|z| <= 5 crossed by a cylinder along x (radius 1, x in [-10, 10]): no box edge
 * meets the cylinder and no rim meets the box, yet they intersect (report Sec. 3.2 says no). */
static void test_slab_through_side(void **st)
{
    (void)st;
    prox_box b = aabb(-0.5, 0.5, -5, 5, -5, 5);
    prox_rcc c = {{-10, 0, 0}, {20, 0, 0}, 1};
    assert_true(prox_box_rcc_test(&b, &c).intersect);
    prox_distance_result d = prox_box_rcc_distance(&b, &c);
    assert_true(d.intersect);
    assert_true(prox_rcc_contains_point(&c, d.p1, 1e-12));
    prox_signed_result s = prox_box_rcc_signed_distance(&b, &c);
    /* cheapest exit: sideways past the slab's edge at |y| = 5 plus the radius (along x it is 10.5) */
    assert_near(s.sd, -6.0, 1e-9);
}

/* Tiny box inside a big cylinder, and a thin cylinder inside a big box. */
static void test_nested(void **st)
{
    (void)st;
    prox_box tiny = aabb(0.1, 0.2, 0.1, 0.2, 1, 1.1);
    prox_rcc big = {{0, 0, 0}, {0, 0, 5}, 3};
    assert_true(prox_box_rcc_test(&tiny, &big).intersect);
    prox_shape A = prox_shape_from_box(tiny), B = prox_shape_from_rcc(big);
    assert_int_equal(prox_shape_relation(&A, &B, -1).relation, PROX_REL_A_IN_B);
    prox_box huge = aabb(-5, 5, -5, 5, -5, 5);
    prox_rcc rod = {{0, 0, -1}, {0.3, 0.2, 2}, 0.1};
    assert_true(prox_box_rcc_test(&huge, &rod).intersect);
    A = prox_shape_from_box(huge), B = prox_shape_from_rcc(rod);
    assert_int_equal(prox_shape_relation(&A, &B, -1).relation, PROX_REL_B_IN_A);
}

/* Rim against a face: cylinder tilted by 45 degrees above the face z = 0 of a big box. */
static void test_rim_to_face(void **st)
{
    (void)st;
    prox_box b = aabb(-5, 5, -5, 5, -1, 0);
    double c45 = sqrt(0.5), h = 2.0, r = 0.5, gap = 0.3;
    /* lowest rim point of the base circle: base centre z - r sin45 */
    prox_rcc c = {{0, 0, gap + r * c45}, {h * c45, 0, h * c45}, r};
    prox_distance_result d = prox_box_rcc_distance(&b, &c);
    assert_false(d.intersect);
    assert_near(d.distance, gap, 1e-15);
    assert_near(d.certificate_gap, gap, 1e-15);
    assert_near(d.p1.z, 0.0, 1e-15);
}

/* Box corner towards the rim: the corner on the line through a rim point along its outward bisector. */
static void test_corner_to_rim(void **st)
{
    (void)st;
    prox_rcc c = {{0, 0, 0}, {0, 0, 2}, 1};
    double g = 0.25, e = g * sqrt(0.5);
    /* rim point (1, 0, 2); outward bisector (1, 0, 1)/sqrt2; box corner at rim + g * bisector */
    prox_box b = aabb(1 + e, 3, -1, 1, 2 + e, 4);
    b.corner = prox_v3(1 + e, -1, 2 + e);
    prox_distance_result d = prox_box_rcc_distance(&b, &c);
    assert_false(d.intersect);
    /* the closest box point to the rim is the edge point (1+e, 0, 2+e) */
    assert_near(d.distance, g, 1e-15);
    assert_near(d.p2.x, 1.0, 1e-12);
    assert_near(d.p2.z, 2.0, 1e-12);
}

/* Box edge parallel to the lateral surface and the edge against the side. */
static void test_edge_to_side(void **st)
{
    (void)st;
    prox_rcc c = {{0, 0, 0}, {0, 0, 4}, 1};
    /* box rotated 45 deg about z so an edge (vertical) faces the axis at distance 1.5 */
    prox_box b;
    double s = sqrt(0.5);
    b.corner = prox_v3(1.5, 0, 1);
    b.edge[0] = prox_v3(s, s, 0);
    b.edge[1] = prox_v3(s, -s, 0);
    b.edge[2] = prox_v3(0, 0, 1);
    prox_distance_result d = prox_box_rcc_distance(&b, &c);
    assert_near(d.distance, 0.5, 1e-15);
    assert_near(d.certificate_gap, 0.5, 1e-15);
    /* moved to touch: verdict flips exactly at contact */
    b.corner.x = 1.0 + 1e-9;
    assert_false(prox_box_rcc_test(&b, &c).intersect);
    b.corner.x = 1.0;
    assert_true(prox_box_rcc_test(&b, &c).intersect);
    b.corner.x = 1.0 - 1e-9;
    assert_true(prox_box_rcc_test(&b, &c).intersect);
}

/* The closed-form edge paths of box_rcc.c: an edge parallel to the axis beside the side (a set of
 * closest pairs, foot in range or straddling an end plane), wholly above the top (rim nearest), and an
 * edge passing over the top disk (cap interior nearest). Each also rotated and moved as a whole. */
static void test_edge_paths(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(41);
    double s = sqrt(0.5);
    struct {
        double z0, z1, ex, dist;
    } vert[] = {{0.5, 1.5, 1.5, 0.5}, {1.0, 3.0, 1.5, 0.5}, {-1.0, 3.0, 1.5, 0.5}, {2.5, 4.0, 1.5, sqrt(0.5)}};
    for (int rot = 0; rot < 2; ++rot) {
        test_rot R = test_random_rot(&g);
        prox_vec3 off = rot ? prox_v3(-3, 7, 2) : prox_v3(0, 0, 0);
        if (!rot) R = (test_rot){{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        prox_rcc c = {off, test_rot_apply(&R, prox_v3(0, 0, 2)), 1};
        for (size_t i = 0; i < sizeof vert / sizeof vert[0]; ++i) {
            prox_box b; /* rotated 45 deg about z: its vertical edge at (ex, 0) faces the axis */
            b.edge[0] = test_rot_apply(&R, prox_v3(s, s, 0));
            b.edge[1] = test_rot_apply(&R, prox_v3(s, -s, 0));
            b.edge[2] = test_rot_apply(&R, prox_v3(0, 0, vert[i].z1 - vert[i].z0));
            b.corner = prox_v3_add(off, test_rot_apply(&R, prox_v3(vert[i].ex, 0, vert[i].z0)));
            prox_distance_result d = prox_box_rcc_distance(&b, &c);
            assert_int_equal(d.status, PROX_OK);
            assert_false(d.intersect);
            assert_near(d.distance, vert[i].dist, 1e-14);
            assert_near(d.certificate_gap, d.distance, 1e-14);
            assert_near(prox_v3_dist(d.p1, d.p2), d.distance, 1e-14);
        }
        /* an edge along x at height 2.3 over the top disk, the box above it: cap interior, 0.3 */
        prox_box b;
        b.edge[0] = test_rot_apply(&R, prox_v3(4, 0, 0));
        b.edge[1] = test_rot_apply(&R, prox_v3(0, s, s));
        b.edge[2] = test_rot_apply(&R, prox_v3(0, -s, s));
        b.corner = prox_v3_add(off, test_rot_apply(&R, prox_v3(-2, 0.2, 2.3)));
        prox_distance_result d = prox_box_rcc_distance(&b, &c);
        assert_false(d.intersect);
        assert_near(d.distance, 0.3, 1e-14);
        assert_near(d.certificate_gap, 0.3, 1e-14);
        /* the closest pairs form a segment (edge parallel to the disk): p2 on it, p1 above p2 */
        prox_vec3 q = prox_v3_sub(d.p2, off), l;
        l.x = R.m[0][0] * q.x + R.m[1][0] * q.y + R.m[2][0] * q.z; /* R^T q: local coordinates */
        l.y = R.m[0][1] * q.x + R.m[1][1] * q.y + R.m[2][1] * q.z;
        l.z = R.m[0][2] * q.x + R.m[1][2] * q.y + R.m[2][2] * q.z;
        assert_near(l.y, 0.2, 1e-14);
        assert_near(l.z, 2.0, 1e-14);
        assert_true(fabs(l.x) <= sqrt(0.96) + 1e-14);
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_slab_through_side), cmocka_unit_test(test_nested),
                                       cmocka_unit_test(test_rim_to_face), cmocka_unit_test(test_corner_to_rim),
                                       cmocka_unit_test(test_edge_to_side),
                                       cmocka_unit_test(test_edge_paths)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
