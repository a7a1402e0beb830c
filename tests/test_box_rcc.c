/* BOX-RCC hand-made cases (box_rcc.c): the intersections the TRX report's Sec. 3.2 misses (slab
 * through the side with no edge crossing the surface, box inside, cylinder inside) and exact distances
 * of rim-to-face, corner-to-rim, edge-to-lateral contacts. Random pairs are in test_query.c. */
#include "test_util.h"
#include "prox/support.h"
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


/* ---- Randomised exactness of the pruned distance against an independent long-double minimisation ---- */

typedef long double ld;

/* Distance of x (long double) to the solid cylinder c: clamp of the axial and radial offsets. */
static ld point_cyl_ld(const prox_rcc *c, const ld x[3])
{
    ld w[3] = {c->axis.x, c->axis.y, c->axis.z}, d[3] = {x[0] - c->base.x, x[1] - c->base.y, x[2] - c->base.z};
    ld h = sqrtl(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (int k = 0; k < 3; ++k) w[k] /= h;
    ld t = d[0] * w[0] + d[1] * w[1] + d[2] * w[2], rr = 0;
    for (int k = 0; k < 3; ++k) rr += (d[k] - t * w[k]) * (d[k] - t * w[k]);
    ld dt = t < 0 ? -t : (t > h ? t - h : 0), dr = sqrtl(rr) - c->radius;
    if (dr < 0) dr = 0;
    return sqrtl(dt * dt + dr * dr);
}

/* Point of face (k, sgn) of box b at face parameters (u, v) in [0,1]^2. */
static void face_point(const prox_box *b, int k, int sgn, ld u, ld v, ld x[3])
{
    int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    prox_vec3 e = b->edge[k], e1 = b->edge[k1], e2 = b->edge[k2];
    ld s = sgn > 0 ? 1 : 0;
    x[0] = b->corner.x + s * e.x + u * e1.x + v * e2.x;
    x[1] = b->corner.y + s * e.y + u * e1.y + v * e2.y;
    x[2] = b->corner.z + s * e.z + u * e1.z + v * e2.z;
}

#define GOLD 0.61803398874989484820L
/* min over v in [0,1] of dist(face(u, v), C): golden section (the distance to a convex set is convex). */
static ld face_inner(const prox_box *b, const prox_rcc *c, int k, int sgn, ld u)
{
    ld lo = 0, hi = 1, x[3];
    ld m1 = hi - GOLD * (hi - lo), m2 = lo + GOLD * (hi - lo);
    face_point(b, k, sgn, u, m1, x);
    ld f1 = point_cyl_ld(c, x);
    face_point(b, k, sgn, u, m2, x);
    ld f2 = point_cyl_ld(c, x);
    for (int it = 0; it < 80; ++it) {
        if (f1 <= f2) {
            hi = m2, m2 = m1, f2 = f1, m1 = hi - GOLD * (hi - lo);
            face_point(b, k, sgn, u, m1, x);
            f1 = point_cyl_ld(c, x);
        } else {
            lo = m1, m1 = m2, f1 = f2, m2 = lo + GOLD * (hi - lo);
            face_point(b, k, sgn, u, m2, x);
            f2 = point_cyl_ld(c, x);
        }
    }
    face_point(b, k, sgn, u, 0, x);
    ld e0 = point_cyl_ld(c, x);
    face_point(b, k, sgn, u, 1, x);
    return fminl(fminl(f1, f2), fminl(e0, point_cyl_ld(c, x)));
}

/* Distance of the box to the cylinder: the minimum over the 6 faces of a nested golden-section search
 * (partial minima of a convex function are convex), independent of the library's candidate set. */
static ld brute_box_rcc(const prox_box *b, const prox_rcc *c)
{
    ld best = INFINITY;
    for (int f = 0; f < 6; ++f) {
        int k = f / 2, sgn = (f & 1) ? 1 : -1;
        ld lo = 0, hi = 1, m1 = hi - GOLD * (hi - lo), m2 = lo + GOLD * (hi - lo);
        ld f1 = face_inner(b, c, k, sgn, m1), f2 = face_inner(b, c, k, sgn, m2);
        for (int it = 0; it < 80; ++it) {
            if (f1 <= f2) hi = m2, m2 = m1, f2 = f1, m1 = hi - GOLD * (hi - lo), f1 = face_inner(b, c, k, sgn, m1);
            else lo = m1, m1 = m2, f1 = f2, m2 = lo + GOLD * (hi - lo), f2 = face_inner(b, c, k, sgn, m2);
        }
        best = fminl(best, fminl(fminl(f1, f2), fminl(face_inner(b, c, k, sgn, 0), face_inner(b, c, k, sgn, 1))));
    }
    return best;
}

/* Distance of x from the box (0 inside), from its edge coordinates. */
static double off_box_rcc(const prox_box *b, prox_vec3 x)
{
    prox_vec3 d = prox_v3_sub(x, b->corner);
    double s2 = 0;
    for (int k = 0; k < 3; ++k) {
        double len = prox_v3_norm(b->edge[k]), t = prox_v3_dot(d, b->edge[k]) / len;
        double o = t < 0 ? -t : (t > len ? t - len : 0);
        s2 += o * o;
    }
    return sqrt(s2);
}

/* Seeded random disjoint pairs: random box (half sizes 1e-3 .. 5, some thin) and cylinder (r, h 1e-2 .. 10)
 * with the axis random, along a box axis (caps parallel to a face, side parallel to two faces) or at
 * 45 deg in a box plane; at random distances and moved to near-touching gaps (1e-9 .. 1e-1 x scale) along
 * their closest direction. The pruned prox_box_rcc_distance equals the brute-force minimum to 1e-12 x
 * scale; its points are that far apart and lie in their solids. */
static void test_random_pruned_exact(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(777);
    int checked = 0;
    for (int it = 0; it < 1200; ++it) {
        test_rot R = test_random_rot(&g);
        prox_box b;
        prox_vec3 ctr = prox_v3(test_range(&g, -3, 3), test_range(&g, -3, 3), test_range(&g, -3, 3)), cnr = ctr;
        for (int k = 0; k < 3; ++k) {
            double len = 2.0 * pow(10.0, test_range(&g, -3.0, 0.7));
            b.edge[k] = prox_v3_scale(test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2)), len);
            cnr = prox_v3_mad(cnr, -0.5, b.edge[k]);
        }
        b.corner = cnr;
        int kind = it % 4, ax = (int)(test_uniform(&g) * 3.0);
        prox_vec3 e = test_rot_apply(&R, prox_v3(ax == 0, ax == 1, ax == 2));
        prox_vec3 e1 = test_rot_apply(&R, prox_v3(ax == 2, ax == 0, ax == 1));
        prox_vec3 w = kind == 0 ? test_unit(&g) : (kind == 1 ? e : prox_v3_normalize(prox_v3_add(e, kind == 2 ? prox_v3_scale(e1, 1e-9) : e1)));
        double h = pow(10.0, test_range(&g, -2.0, 1.0)), r = pow(10.0, test_range(&g, -2.0, 1.0));
        prox_vec3 cc = prox_v3_mad(ctr, test_range(&g, 0.0, 15.0), test_unit(&g));
        prox_rcc c = {prox_v3_mad(cc, -0.5 * h, w), prox_v3_scale(w, h), r};
        prox_distance_result d = prox_box_rcc_distance(&b, &c);
        assert_int_equal(d.status, PROX_OK);
        if (d.intersect) continue;
        double scale = fmax(fmax(prox_v3_dist(ctr, cc), 2 * r), h);
        for (int k = 0; k < 3; ++k) scale = fmax(scale, prox_v3_norm(b.edge[k]));
        if ((it / 4) % 2) { /* move the cylinder along the closest direction to a small gap */
            double gap = pow(10.0, test_range(&g, -9.0, -1.0)) * scale;
            prox_vec3 n = prox_v3_scale(prox_v3_sub(d.p2, d.p1), 1.0 / d.distance);
            c.base = prox_v3_mad(c.base, gap - d.distance, n);
            d = prox_box_rcc_distance(&b, &c);
            assert_int_equal(d.status, PROX_OK);
            if (d.intersect) continue;
        }
        double tol = 1e-12 * scale;
        ld ref = brute_box_rcc(&b, &c);
        /* kind 2 (an end disk tilted 1e-9 from a box face) guards rim_face's lowest rim point: without
         * a second rejection against the axis it leaves the rim's plane and the distance misses by
         * 4.3e-10 x scale (it 158; docs/algorithms/box_speed.md). */
        assert_near(d.distance, (double)ref, tol);
        assert_near(prox_v3_dist(d.p1, d.p2), d.distance, tol);
        assert_true(off_box_rcc(&b, d.p1) <= tol);
        ld p2[3] = {d.p2.x, d.p2.y, d.p2.z};
        /* kind 2: a point of a rim tilted 1e-9 carries that tilt's rounding (it 802: 4e-12 x scale) */
        assert_true(point_cyl_ld(&c, p2) <= (kind == 2 ? 1e-9 * scale : tol));
        assert_true(d.certificate_gap <= d.distance + (kind == 2 ? 1e-9 * scale : tol));
        ++checked;
    }
    assert_true(checked > 800);
}

/* A needle (r 0.0034, h 596) whose top rim is 2.05e-8 from a long plate (864 x 10.8 x 2.1). Guards
 * the radial clip of the plate's long edges against the cylinder: solved with the discriminant
 * B^2 - A C it cancels to 1e-5 relative here and calls the pair touching, so the clip is measured
 * around the edge's closest approach. The gap is confirmed by the independent support-function
 * method. */
static void test_needle_beside_plate(void **st)
{
    (void)st;
    prox_rcc c = {{0, 0, 0}, {-35.833814265014752, -583.70178548520857, -115.85831320115065}, 0.0034320752276763866};
    prox_box b = {{-555.05371491268852, -584.09916867516915, 572.37096099408291},
                  {{518.7335007632613, -10.549043259054548, -688.4239470361905},
                   {-1.2297738680016161, 10.615748674979274, -1.0893155284963378},
                   {1.7134027987622187, 0.33044850359389893, 1.2860004656602289}}};
    prox_test_result t = prox_box_rcc_test(&b, &c);
    prox_distance_result d = prox_box_rcc_distance(&b, &c);
    prox_shape A = prox_shape_from_box(b), B = prox_shape_from_rcc(c);
    prox_signed_result s = prox_shape_signed_distance_support(&A, &B);
    assert_int_equal(t.status, PROX_OK);
    assert_false(t.intersect);
    assert_false(d.intersect);
    assert_near(d.distance, s.sd, 1e-12 * 862.0);
    assert_true(d.distance > 2e-8);
}

/* Touching pairs 1e6 from the origin, where differences of coordinates carry ~1e-10 of rounding.
 * Guards the rim-against-face candidate: its height can come out slightly negative, and dropping it
 * would let the next candidate win (0.011 and 0.148 apart). A height within that rounding is a
 * touching contact: the support-function method near the origin finds |sd| < 4e-11 for both. */
static void test_touching_far_from_origin(void **st)
{
    (void)st;
    const prox_box b[2] = {{{916109.97620175302, 286505.14515563642, -280459.11164191371},
                            {{-0.00037916083950382537, 0.0010441987651200932, 0.0012748385620487666},
                             {0.4753843038440112, -0.071029680297156964, 0.19956739916679028},
                             {0.13088291250199938, 0.29846756554945997, -0.20554272218834807}}},
                           {{-714013.22546030825, 537662.77404415852, -448446.04499862326},
                            {{-1.5733135714300404, -2.5795296766053895, 0.38166247329897629},
                             {0.015718964930393205, -0.0063498747364509559, 0.021881036551048349},
                             {-5.0662479012430763, 3.7913028812992087, 4.7397421612343491}}}};
    const prox_rcc c[2] = {{{916110.10641015461, 286505.27253558364, -280459.14107491384},
                            {0.023765397860766944, 0.017662451216641398, 0.0077974071680049955},
                            0.027585978914366639},
                           {{-714015.87258419069, 537663.99321619328, -448444.54791480157},
                            {-0.16456615419745924, -0.29981278433318009, 0.21842068945176263},
                            0.48489523963801806}};
    for (int i = 0; i < 2; ++i) {
        prox_distance_result d = prox_box_rcc_distance(&b[i], &c[i]);
        assert_int_equal(d.status, PROX_OK);
        assert_true(d.distance <= 1e-9); /* the coordinates' rounding is ~1e-10 */
        assert_true(d.certificate_gap <= d.distance + 1e-9);
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_slab_through_side), cmocka_unit_test(test_nested),
                                       cmocka_unit_test(test_rim_to_face), cmocka_unit_test(test_corner_to_rim),
                                       cmocka_unit_test(test_edge_to_side),
                                       cmocka_unit_test(test_edge_paths),
                                       cmocka_unit_test(test_random_pruned_exact),
                                       cmocka_unit_test(test_needle_beside_plate),
                                       cmocka_unit_test(test_touching_far_from_origin)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
