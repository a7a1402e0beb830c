/* BOX-BOX hand-made cases (box_box.c): face-to-face, edge-to-edge, vertex-to-face distances, a box
 * wholly inside another and a cross of two bars (both missed by the TRX report's Sec. 3.1 edge-of-B
 * against faces-of-A test), exact depths and witnesses. Random pairs are in test_query.c. */
#include "test_util.h"
#include "prox/query.h"

static prox_box aabb(double x0, double x1, double y0, double y1, double z0, double z1)
{
    prox_rpp r = {x0, x1, y0, y1, z0, z1};
    return prox_rpp_to_box(&r);
}

static void test_face_to_face(void **st)
{
    (void)st;
    prox_box a = aabb(0, 1, 0, 1, 0, 1), b = aabb(1.25, 2, 0.5, 3, -1, 0.5);
    prox_distance_result d = prox_box_box_distance(&a, &b);
    assert_false(d.intersect);
    assert_near(d.distance, 0.25, 1e-15);
    assert_near(d.certificate_gap, 0.25, 1e-15);
    b = aabb(1, 2, 0.5, 3, -1, 0.5); /* touching */
    assert_true(prox_box_box_test(&a, &b).intersect);
    assert_near(prox_box_box_signed_distance(&a, &b).sd, 0.0, 1e-15);
}

/* Two edges crossing at right angles, one above the other: a rotated 45 deg about z and x. */
static void test_edge_to_edge(void **st)
{
    (void)st;
    prox_box a = aabb(-1, 1, -1, 1, -1, 1);
    double s = sqrt(0.5), gap = 0.125;
    prox_box b; /* rotated 45 deg about x: lowest edge along x at z = 1 + gap */
    b.edge[0] = prox_v3(2, 0, 0);
    b.edge[1] = prox_v3(0, s, s);
    b.edge[2] = prox_v3(0, -s, s);
    b.corner = prox_v3(-1, 0, 1 + gap);
    /* rotate b about z by 90 deg so its lowest edge runs along y, crossing a's top edge? keep along x:
     * a's top face is at z = 1: edge-to-face distance gap */
    prox_distance_result d = prox_box_box_distance(&a, &b);
    assert_near(d.distance, gap, 1e-15);
    /* now also rotate a by 45 deg about y: its top becomes an edge along y, crossing b's edge along x */
    prox_box a2;
    a2.edge[0] = prox_v3(s, 0, -s);
    a2.edge[1] = prox_v3(0, 1, 0);
    a2.edge[2] = prox_v3(s, 0, s);
    a2.corner = prox_v3(-s, -0.5, 0); /* top edge along y at x = 0, z = sqrt(1/2) */
    b.corner = prox_v3(-1, 0, s + gap);
    d = prox_box_box_distance(&a2, &b);
    assert_near(d.distance, gap, 1e-15);
    assert_near(d.p1.x, 0.0, 1e-15);
    assert_near(d.p2.y, 0.0, 1e-15);
    prox_signed_result sd = prox_box_box_signed_distance(&a2, &b);
    assert_near(sd.sd, gap, 1e-15);
    /* push b down by 3 gap: edge-edge penetration 2 gap, direction z */
    b.corner.z -= 3 * gap;
    sd = prox_box_box_signed_distance(&a2, &b);
    assert_near(sd.sd, -2 * gap, 1e-14);
    assert_near(sd.normal.z, 1.0, 1e-14);
    assert_near(prox_v3_dist(sd.p2, prox_v3_mad(sd.p1, sd.sd, sd.normal)), 0.0, 1e-14);
}

static void test_vertex_to_face(void **st)
{
    (void)st;
    prox_box a = aabb(0, 1, 0, 1, 0, 1);
    test_rng g = test_rng_seed(5);
    test_rot R = test_random_rot(&g);
    prox_box b;
    for (int k = 0; k < 3; ++k) b.edge[k] = test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2));
    /* place b's lowest vertex (in z) at (0.4, 0.6, 1.3) */
    int lo = 0;
    double best = INFINITY;
    for (int i = 0; i < 8; ++i) {
        double z = 0;
        for (int k = 0; k < 3; ++k) if (i >> k & 1) z += b.edge[k].z;
        if (z < best) best = z, lo = i;
    }
    prox_vec3 off = {0, 0, 0};
    for (int k = 0; k < 3; ++k) if (lo >> k & 1) off = prox_v3_add(off, b.edge[k]);
    b.corner = prox_v3_sub(prox_v3(0.4, 0.6, 1.3), off);
    prox_distance_result d = prox_box_box_distance(&a, &b);
    assert_near(d.distance, 0.3, 1e-15);
    assert_near(d.p2.x, 0.4, 1e-15);
    assert_near(d.p1.z, 1.0, 1e-15);
}

/* B wholly inside A and a cross of two bars: no edge of B crosses a face of A in either. */
static void test_inside_and_cross(void **st)
{
    (void)st;
    prox_box a = aabb(-2, 2, -2, 2, -2, 2), b = aabb(-0.5, 0.5, -0.25, 0.5, 0, 1);
    assert_true(prox_box_box_test(&a, &b).intersect);
    prox_distance_result d = prox_box_box_distance(&a, &b);
    assert_true(d.intersect);
    prox_shape A = prox_shape_from_box(a), B = prox_shape_from_box(b);
    prox_relation_result r = prox_shape_relation(&A, &B, -1);
    assert_int_equal(r.relation, PROX_REL_B_IN_A);
    assert_near(r.clearance, 1.0, 1e-15);
    /* exact depth: cheapest exit of b is +z: 2 - 0 = 2 (from z in [0,1] to above 2) */
    assert_near(prox_box_box_signed_distance(&a, &b).sd, -2.0, 1e-15);
    /* cross: a long bar along x, b a long bar along y, same z extent; A's edges pierce B's faces */
    prox_box x = aabb(-3, 3, -0.5, 0.5, 0, 1), y = aabb(-0.5, 0.5, -3, 3, 0.25, 0.75);
    d = prox_box_box_distance(&x, &y);
    assert_true(d.intersect);
    A = prox_shape_from_box(x), B = prox_shape_from_box(y);
    assert_int_equal(prox_shape_relation(&A, &B, -1).relation, PROX_REL_CROSSING);
    assert_near(prox_box_box_signed_distance(&x, &y).sd, -0.75, 1e-15); /* exit along z: 1 - 0.25 */
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_face_to_face), cmocka_unit_test(test_edge_to_edge),
                                       cmocka_unit_test(test_vertex_to_face), cmocka_unit_test(test_inside_and_cross)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
